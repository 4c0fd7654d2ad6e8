// Casing wear over a run (issue 37; model/casing_wear.hpp, White & Dawson SPE 14325): the soft string
// (analyses/soft_string.hpp, Johancsik) rotating on bottom at the case's WOB and torque on bit, the
// case's friction (model.contact, each cased section its own), gives the side force per length on the
// casing at each depth of the run; the casing's worn volume per length adds up over the run's rotating
// time, and the groove a tool joint cuts to wear it, the remaining wall where the section gives its wall.
// The string runs to the surface (pipeline/roadmap.hpp CaseAtDepth): the stiff model of a static covers
// the BHA, rarely the casing.
#pragma once

#include <vector>

#include "analyses/soft_string.hpp"
#include "io/case.hpp"
#include "io/result_files.hpp"

namespace drillflex::pipeline {

// One MD of casing (every kWearStep from the surface to the deepest cased MD the string reaches).
struct CasingWearStation {
  double md = 0.0;                     // m
  double side_force_per_length = 0.0;  // N/m, the largest over the run's depths
  double worn_area = 0.0;              // m², the volume worn per length
  double joint_diameter = 0.0;         // m, the contact diameter of the component that wore it last
  double bore_diameter = 0.0;          // m, the casing's
  double groove_depth = 0.0;           // m
  double wall = 0.0;                   // m, the section's wall (0: not given)
  double remaining_wall = 0.0;         // m, wall − groove (0 without a wall)
  double wear_utilisation = 0.0;       // groove / wall (0 without a wall)
};

struct CasingWear {
  std::vector<CasingWearStation> stations;
  double rotating_time = 0.0;  // s over the run
  int depths = 0;              // the run's depths (1: rotating at the bit MD)
};

inline constexpr double kWearStep = 3.048;  // m (10 ft) between the casing's stations

// The run of `c.limits.wear` (required). Throws as pipeline::CaseAtDepth.
CasingWear ComputeCasingWear(const io::Case& c);

// The parts of a run (ComputeCasingWear; the roadmap's, pipeline/roadmap.hpp RoadmapCasingWear):
// the casing's stations of `c`'s well, nothing worn yet;
std::vector<CasingWearStation> CasingWearStations(const io::Case& c);
// the wear of the string of `at` (the case at a depth, pipeline::CaseAtDepth) rotating on bottom at its
// WOB and torque on bit for `time` (s) at the wear's rpm, its friction `friction`'s (its motion, WOB and
// TOB set here), added to `stations` of `c`;
void AddRotatingWear(const io::Case& c, const model::ModelInput& at, analyses::SoftStringOperation friction,
                     double time, std::vector<CasingWearStation>& stations);
// and each station's groove, remaining wall and utilisation from its worn area.
void FinishCasingWear(std::vector<CasingWearStation>& stations);

// results.json `static.casing_wear` and casing_wear.csv (the case's output units) when the case asks for
// wear (c.limits.wear), nothing otherwise.
void AddCasingWearResults(const io::Case& c, io::ResultFiles& files);

}  // namespace drillflex::pipeline
