// Strings in wells shared by the analyses' tests.
#pragma once

#include <vector>

#include "fe/material.hpp"
#include "field_parts.hpp"
#include "model/builder.hpp"

namespace drillflex::analyses::testing {

// A packed BHA (bit, stabilizer, three collars) under 20 klbf WOB below `pipe_joints` joints of
// 5 in drill pipe with tool joints, in 10.5 ppg mud: the well vertical to 2000 ft, then 6°/100 ft
// toward the south while turning to 225°, held at 30° (the bodies' high-side frames turn by π at
// the kick-off), bit at 2700 ft.
inline model::ModelInput KickOffToTheSouth(int pipe_joints = 30) {
  model::ModelInput input;
  model::Component stabilizer = Part(model::ComponentType::Stabilizer, 6.75, 2.8125, 5.0);
  stabilizer.blade_diameter = 8.375 * kIn;
  stabilizer.blade_length = 1.5 * kFt;
  model::Component pipe = Part(model::ComponentType::Pipe, 5.0, 4.276, 30.0, pipe_joints);
  pipe.joint_diameter = 6.625 * kIn;
  pipe.joint_inner_diameter = 3.25 * kIn;
  input.string.components = {Part(model::ComponentType::Bit, 8.5, 2.0, 1.0), stabilizer,
                             Part(model::ComponentType::Collar, 6.75, 2.8125, 30.0, 3), pipe};
  input.materials["steel"] = fe::Material{"steel", 2.1e11, 0.3, 7850.0};
  input.gravity = 9.81;
  input.fluid = model::FluidConfig{1258.0, 0.02, {}, -1.0};
  // Vertical to 2000 ft, then 6°/100 ft toward the south while turning to 225°, held at 30°.
  input.well = model::MakeWellbore(
      well::Trajectory(std::vector<well::SurveyStation>{{0.0, 0.0, 0.0},
                                                        {2000.0 * kFt, 0.0, 180.0 * kDegree},
                                                        {2500.0 * kFt, 30.0 * kDegree, 225.0 * kDegree},
                                                        {4000.0 * kFt, 30.0 * kDegree, 225.0 * kDegree}}),
      std::vector<well::HoleSection>{well::HoleSection{{}, 8.5 * kIn, {}}});
  input.bit_md = 2700.0 * kFt;  // with 30 joints 1008 ft of string: the top is 308 ft up the vertical hole
  input.operation.weight_on_bit = 20000.0 * kLbf;
  return input;
}

}  // namespace drillflex::analyses::testing
