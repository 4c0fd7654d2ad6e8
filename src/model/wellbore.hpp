// The hole the string lies in: the well path and the hole diameter along it. A model's input holds
// it once (model/model_input.hpp `well`, a shared_ptr to const); the builder, the wall contacts, the
// analyses and the VTK writer share that one object, none keeps a copy of its own.
#pragma once

#include <memory>
#include <vector>

#include "well/hole.hpp"
#include "well/trajectory.hpp"

namespace drillflex::model {

struct Wellbore {
  well::Trajectory trajectory;
  well::HoleProfile hole;  // empty: no hole (no wall contact)
};

// A wellbore shared read-only: `trajectory` with the hole `sections` (the io's and the tests' way in).
inline std::shared_ptr<const Wellbore> MakeWellbore(well::Trajectory trajectory,
                                                    std::vector<well::HoleSection> sections = {}) {
  return std::make_shared<const Wellbore>(Wellbore{std::move(trajectory), well::HoleProfile(std::move(sections))});
}

}  // namespace drillflex::model
