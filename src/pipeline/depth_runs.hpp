// The torque-and-drag runs of the string at one bit depth (the roadmap's, pipeline/roadmap_runs.hpp,
// and the calibration's, pipeline/calibration.hpp), as a continuation: the depth's model is built once
// (the string continued as the case at that depth has it, the default well supports) and every run is
// the same model under another parameter block (model/load_parameters.hpp):
//
//   at rest, off bottom        the bit free, no WOB, no friction: the energy's minimum from the
//                              string resting on the wall (the one cold solve of a depth);
//   pick-up, slack-off         the axial friction of a prescribed trip, each from the same run before
//                              (another friction), the first from the string at rest;
//   rotating, off bottom       the friction around the string, from the same run before, the first
//                              continued in the friction from rest;
//   on bottom                  the bit held at the hole centre with a WOB and torque on bit, from the
//                              same run before, the first from the string resting on the wall.
//
// Each warm run is Newton from its neighbour with the factorization kept while it contracts
// (analyses/static_solve.hpp, strategy 1), falling back to the whole chain where that fails. The
// surface reading adds the pipe above the stiff model, to the surface, by the soft string.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "analyses/analysis_settings.hpp"
#include "analyses/soft_string.hpp"
#include "analyses/static_analysis.hpp"
#include "io/case.hpp"
#include "pipeline/case_run.hpp"

namespace drillflex::pipeline {

// The wall friction of a run: the open hole's coefficient (along and around the string alike) and the
// cased hole's (none: each cased section's own, model/hole_friction.hpp).
struct HoleFrictionFactors {
  double open_hole = 0.0;
  std::optional<double> cased_hole;
};

enum class TdRun { kPickUp, kSlackOff, kRotatingOffBottom, kOnBottom };
const char* TdRunName(TdRun run);  // "pulling out", "running in", "rotating off bottom", "on bottom"

// What a run holds besides the friction.
struct TdRunLoads {
  double trip_speed = 0.3048;   // m/s, pulling out and running in
  double rotary_speed = 0.0;    // rad/s, rotating off and on bottom
  std::optional<double> weight_on_bit;  // N on bottom; none: the case's
  std::optional<double> torque_on_bit;  // N·m on bottom; none: the case's
};

// The tension and torque at the surface.
struct SurfaceReading {
  double hook_load = 0.0;       // N
  double surface_torque = 0.0;  // N·m, clockwise looking down-hole
};

// The same reading by the soft string (Johancsik, analyses/soft_string.hpp, Johancsik's N = L without
// the rotating string's climb, as the soft roadmap has it) of `at_depth`, the string continued to the
// surface (pipeline::CaseAtDepth), in elements of at most a joint; the trip and rotary speeds do not
// enter (Coulomb friction).
SurfaceReading SoftSurfaceReading(const model::ModelInput& at_depth, TdRun run, const HoleFrictionFactors& friction,
                                  const TdRunLoads& loads);

class DepthRuns {
 public:
  // `at`: the case at the depth (pipeline::StiffCaseAtDepth), its supports cleared (the rig's: the
  // hook at the top, the bit at the hole's centre on bottom). `log`, when set, takes the solvers'
  // progress lines, each prefixed with the depth and the run.
  DepthRuns(const io::Case& at, const std::function<void(const std::string&)>& log = nullptr);
  DepthRuns(const DepthRuns&) = delete;  // the static settings' log holds `this`
  DepthRuns& operator=(const DepthRuns&) = delete;

  // At rest off bottom (no friction): the start of the first runs. SolverError when it fails.
  void SolveAtRest();
  // One run, from the same run before (or from rest). SolverError when it fails; a warning (a
  // sliding string answered at rest: its friction found no static balance) goes to notes().
  SurfaceReading Run(TdRun run, const HoleFrictionFactors& friction, const TdRunLoads& loads);

  // The stations of the last `run` solved, from the bit up, as a static's (s from the bit, MD, axial force,
  // torque, bending moment): the stiff model's (analyses::StaticNodeResults), then the pipe above it to
  // the surface by the soft string that carries the model's top there (s from the bit, no bending moment).
  // LogicError before that run.
  std::vector<analyses::StaticNodeResult> Stations(TdRun run) const;

  // The warnings of the runs since the last ClearNotes().
  const std::vector<std::string>& notes() const { return notes_; }
  void ClearNotes() { notes_.clear(); }
  double bit_md() const { return model_.input.bit_md; }

 private:
  VecX Solve(const model::LoadParameters& parameters, const VecX* start, const char* run);
  VecX FromRest(const model::LoadParameters& parameters);
  VecX OnBottomCold(const model::LoadParameters& parameters);
  SurfaceReading ReadSurface(const VecX& q, const model::LoadParameters& parameters, TdRun run,
                             const HoleFrictionFactors& friction) const;
  // The model's top (the hook's reaction: tension and torque) and the soft string above it, if any.
  struct Above {
    SurfaceReading at_top;
    std::optional<analyses::SoftStringResult> soft;
  };
  Above CarryToSurface(const VecX& q, const model::LoadParameters& parameters, TdRun run,
                       const HoleFrictionFactors& friction) const;
  void Label(const HoleFrictionFactors& friction, const char* run);

  CaseModel model_;
  std::optional<model::ModelInput> above_;  // the pipe above the model, by the soft string
  analyses::StaticSettings static_settings_;
  std::optional<VecX> rest_, pick_up_, slack_off_, rotating_, on_bottom_;
  // What each run (TdRun's order) was last solved under, for its Stations.
  struct Solved {
    model::LoadParameters parameters;
    HoleFrictionFactors friction;
  };
  std::array<std::optional<Solved>, 4> solved_;
  std::string on_bottom_failure_;  // why the first on-bottom run failed at this depth
  std::vector<std::string> notes_;
  std::string on_bottom_at_rest_;  // the warning of an on-bottom run answered at rest
  std::optional<TdRunLoads> on_bottom_loads_;  // of the last on-bottom run solved
  std::function<void(const std::string&)> log_;
  std::string prefix_;  // of the log's lines: the depth, friction and run
};

}  // namespace drillflex::pipeline
