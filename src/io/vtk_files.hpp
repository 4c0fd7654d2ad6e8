// VTK XML PolyData files of a static result, for ParaView (case-format.md "Additions to the contract":
// "string.vtp: one point per entry of static.nodes, in that order, point data in SI"). Written as
// text by hand (no VTK library): ASCII, <VTKFile type="PolyData" version="1.0">, Float64 values at
// full precision (shortest round trip), a non-finite value written as 0 (VTK's ASCII reader does not
// reliably take "nan" or "inf"; the file then says how many in a comment), never "-0".
//
//  * string.vtp: the stations at their deformed places (global frame: x north, y east, z down), one
//    polyline from the bit up; point data named after static.csv's columns, in SI (m, N, N·m, Pa,
//    rad): s, md, displacement and rotation (3 components, string frame), lateral_offset,
//    axial_force, torque, shear_force, bending_moment, bending_stress, von_mises_stress; in a well
//    hole_offset, offset_high_side_angle, clearance, hole_diameter; and outer_radius (the body's)
//    and contact_radius (the model's wall-contact circle: blade, tool joint or body) for ParaView's
//    Tube filter (the active scalars: outer_radius; Tube with Vary Radius "By Absolute Scalar" draws
//    the string at its size).
//  * well.vtp (a case with a well): the hole's axis over the string's MD range as one polyline, with
//    md, hole_diameter, hole_radius (the active scalars: the Tube filter as above draws the hole),
//    inclination and azimuth (rad).
//  * contacts.vtp (when wall contacts carry force): one vertex per contact at the point where the
//    string touches the wall, with s, md, component (index in the string), normal_force,
//    friction_force (N), normal (unit: the direction of the wall's normal force on the string, from
//    the wall toward the hole axis) and normal_force_vector (N: normal_force × normal).
#pragma once

#include "analyses/static_analysis.hpp"
#include "io/case.hpp"
#include "io/result_files.hpp"
#include "model/builder.hpp"

namespace drillflex::io {

// Adds string.vtp, and well.vtp and contacts.vtp when there is something to draw. `built` is the
// model `result` was solved on: the well drawn is its wellbore (the case's when it has no wall
// contacts).
void AddStaticVtk(const Case& c, const model::BuiltModel& built, const analyses::StaticResult& result,
                  ResultFiles& files);

}  // namespace drillflex::io
