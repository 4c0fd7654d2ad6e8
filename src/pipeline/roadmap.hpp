// The torque-and-drag roadmap: at each bit depth from a start to the case's bit MD, for each friction
// factor, the hook loads pulling out (pick-up), running in (slack-off) and rotating off bottom, and
// the surface torque off and on bottom, each a static run of the stiff-string model (contacts, tool
// joints, buckling where it occurs) with the string's top component lengthened to the surface.
#pragma once

#include <string>
#include <vector>

#include "io/case.hpp"

namespace drillflex::pipeline {

struct RoadmapSettings {
  double from_md = 0.0;              // m: the first bit depth (> the string below its top component)
  double step = 0.0;                 // m (> 0); the case's bit MD is always the last depth
  std::vector<double> friction;      // the friction factors (axial and around the string alike)
  double rotary_speed = 0.0;         // rad/s off and on bottom; 0: the case's rpm, else 60 rpm
  double trip_speed = 0.3048;        // m/s, pulling out and running in (only its sign counts: the
                                     // friction is Coulomb, far above its regularization velocity)
};

// One depth and friction factor. Hook loads in N (tension at the surface), torques in N·m; NaN with
// a `message` when a run failed.
struct RoadmapPoint {
  double bit_md = 0.0;
  double friction = 0.0;
  double pick_up = 0.0;
  double slack_off = 0.0;
  double rotating = 0.0;
  double off_bottom_torque = 0.0;
  double on_bottom_torque = 0.0;  // at the case's WOB and TOB
  std::string message;
};

// The case at `bit_md`: its well's bit MD moved there and the string's top component repeated as
// often as fits below the surface (what is left to the surface counts as the pipe above the model).
// Throws InputError (file, "string") when the components below the top one do not fit.
io::Case CaseAtDepth(const io::Case& c, double bit_md);

// The roadmap, depths from the start down to the case's bit MD, each friction factor at each depth.
std::vector<RoadmapPoint> RunRoadmap(const io::Case& c, const RoadmapSettings& settings);

}  // namespace drillflex::pipeline
