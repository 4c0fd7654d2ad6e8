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
//  * transient.pvd and string_0000.vtp, string_0001.vtp, ... (a transient run that kept frames of the
//    string's state, TransientSettings::state_frames): a ParaView collection (<VTKFile
//    type="Collection">: one <DataSet timestep="t" part="0" file="string_NNNN.vtp"/> per frame, t in
//    s) of string.vtp files of the same form, one per kept frame, the stations at their places at
//    that time. Their forces are a static evaluation of the frame's positions q (as the transient's
//    samples read WOB and TOB: the elastic section forces, the couplings' without their damping);
//    the inertia and damping forces at that instant are not in them. Their place in the hole
//    (hole_offset, clearance, ...) and lateral_offset are exact.
#pragma once

#include "analyses/static_analysis.hpp"
#include "analyses/transient_analysis.hpp"
#include "io/case.hpp"
#include "io/result_files.hpp"
#include "model/builder.hpp"

namespace drillflex::io {

// Adds string.vtp, and well.vtp and contacts.vtp when there is something to draw. `built` is the
// model `result` was solved on: the well drawn is its wellbore (the case's when it has no wall
// contacts).
void AddStaticVtk(const Case& c, const model::BuiltModel& built, const analyses::StaticResult& result,
                  ResultFiles& files);

// Adds transient.pvd and one string_NNNN.vtp per frame of `result` (frame_times, frame_q; nothing
// when it kept none). `built` is the model the transient integrated (TransientModelInput's). Costs
// a static evaluation of the whole string per frame and its text, held in `files` until Commit: for
// bench/cases/rotary-bha-rotating.yaml (about 1 000 stations in a well) 4 ms and 0.52 MB a frame.
// Throws LogicError when frame_times and frame_q differ in length or a frame's q is not the
// model's size.
void AddTransientVtk(const Case& c, const model::BuiltModel& built, const analyses::TransientResult& result,
                     ResultFiles& files);

}  // namespace drillflex::io
