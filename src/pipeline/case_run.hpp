// One pipeline from a case to its results: read case → model input → built model → static
// equilibrium → modes, vibration, buckling, transient. The command line, the benches, the tests and
// the Python module all run a case through here, so no analysis is set up twice in the tree.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "analyses/buckling_analysis.hpp"
#include "analyses/gyroscopic_modes.hpp"
#include "analyses/modes_analysis.hpp"
#include "analyses/static_analysis.hpp"
#include "analyses/tendency_analysis.hpp"
#include "analyses/limits_envelope.hpp"
#include "analyses/transient_analysis.hpp"
#include "analyses/vibration_analysis.hpp"
#include "cms/reduction_cache.hpp"
#include "io/case.hpp"
#include "model/builder.hpp"

namespace drillflex::pipeline {

enum class Analysis { Static, Modes, Buckling, Vibration, Transient, Tendency };

// "static", "modes", "buckling", "vibration", "transient", "tendency": the command line's and the case's names.
const char* AnalysisName(Analysis analysis);

// Which analyses a run makes.
struct AnalysisRequest {
  bool static_analysis = false;
  bool modes = false;
  bool buckling = false;
  bool vibration = false;
  bool transient = false;
  bool tendency = false;

  static AnalysisRequest Only(Analysis analysis);
  bool Has(Analysis analysis) const;
  bool Any() const { return static_analysis || modes || buckling || vibration || transient || tendency; }
};

// The analyses the case lists under `analyses`; InputError naming the file and `analyses` when it
// lists none.
AnalysisRequest CaseAnalyses(const io::Case& c);

struct CaseResults;

// What a caller hears while a case runs; every member may be empty.
struct RunObserver {
  // The solvers' own lines (the static solver's iterations: the command line's --verbose).
  std::function<void(const std::string& line)> log;
  // What the run decided on the way, one line each: the model's size, the WOB a hook load leaves,
  // the frequency the transient's annulus fluid is taken at.
  std::function<void(const std::string& line)> note;
  // The running analysis's progress: `done` of `total` (the transient's simulated time and its
  // duration, s).
  std::function<void(Analysis analysis, double done, double total)> progress;
  // An analysis has finished: its result is in `results` (the static one also before the modes and
  // the vibration that start from it).
  std::function<void(Analysis analysis, const CaseResults& results)> finished;
};

struct RunOptions {
  // An analysis whose solver fails (SolverError) is named in CaseResults::failures and the run goes
  // on: the analyses that do not start from it still run and keep their results (`drillflex run
  // --keep-finished`, Python's run). False: the first failure ends the run (it throws). Bad input
  // (InputError) ends it either way.
  bool keep_finished = false;
  // Keep the transient's string shapes at its VTK frames (`vtk_frames`, default kDefaultVtkFrames),
  // for transient.pvd; without it none are kept.
  bool keep_transient_shapes = false;
  RunObserver observer;
};

// Frames of the string's shape a transient keeps for transient.pvd by default: about 0.5 MB each for
// the bundled example's 1 015 stations (docs/case-format.md `vtk_frames`).
inline constexpr int kDefaultVtkFrames = 50;

// The case's model: what the builder was given, the model it built, and the reductions it made (kept
// for the transient's and the buckling's own builds of the same bodies).
struct CaseModel {
  model::ModelInput input;
  std::unique_ptr<cms::ReductionCache> cache;
  model::BuiltModel built;
};

// The case's model: its model input (io::Case::input) built by BuildModel.
CaseModel BuildCaseModel(const io::Case& c);

// A model of `input` (the case's, or one an analysis varies: the transient's in motion, a tendency's in
// its own hole) with the reductions of `cache`: the one place model::BuildSystemModel is called.
model::BuiltModel BuildModel(const model::ModelInput& input, cms::ReductionCache& cache);

// The case's directional tendency (analyses/tendency_analysis.hpp) with its settings, and its
// sensitivities when they ask for them (analyses/tendency_sensitivity.hpp).
analyses::TendencyResult RunCaseTendency(const io::Case& c, CaseModel& case_model, const RunObserver& observer = {});

// The static settings of the case, with the observer's log.
analyses::StaticSettings CaseStaticSettings(const io::Case& c, const RunObserver& observer);

// The stages RunCase chains, for callers that time or vary one of them (the benches, the tests).
// The static equilibrium of the case's model (RunStaticInWell with the case's static settings).
analyses::StaticResult RunCaseStatic(const io::Case& c, CaseModel& case_model, const RunObserver& observer = {});
// The modes about `equilibrium` (gyroscopic when the case's modes ask for it), with the fluid.
analyses::ModesResult RunCaseModes(const io::Case& c, const CaseModel& case_model, const VecX& equilibrium);
// The case's vibration settings; without excitations, analyses::DefaultExcitations of its string.
analyses::VibrationSettings CaseVibrationSettings(const io::Case& c);
// The forced response about `equilibrium` under `settings` (the case's own by default in RunCase); an
// excitation the string cannot take is an InputError naming the case file.
analyses::VibrationResult RunCaseVibration(const io::Case& c, const CaseModel& case_model, const VecX& equilibrium,
                                           const analyses::VibrationSettings& settings);

// The transient as it runs: its settings, the model in motion (the drives, the friction following the
// motion, the bottom contact where the bit rests at the start, the fluid moving with the bodies), its
// start, and the frequency of the annulus fluid's C_m and C_v.
struct TransientSetup {
  analyses::TransientSettings settings;
  double fluid_frequency = 0.0;  // rad/s; 0: no frequency-dependent fluid
  VecX start;                    // positions at t = 0
  model::BuiltModel moving;
};

// The transient's setup. `equilibrium`: the case's static equilibrium when one was solved (the start
// when the transient starts from it at rest), else null.
TransientSetup PrepareTransient(const io::Case& c, CaseModel& case_model, const analyses::StaticResult* equilibrium,
                                const RunOptions& options);

// Everything a run computed. `static_result` is there when the static ran or the modes or the
// vibration started from it.
// An analysis of a run that kept what finished (RunOptions::keep_finished) and did not: its solver
// failed, or it was not run because it starts from one that failed.
struct AnalysisFailure {
  Analysis analysis = Analysis::Static;
  std::string message;  // the solver's account of where and why, or why it was not run
};

struct CaseResults {
  AnalysisRequest requested;
  CaseModel model;
  std::optional<analyses::StaticResult> static_result{};
  std::optional<analyses::ModesResult> modes{};
  std::optional<analyses::CampbellResult> campbell{};
  std::optional<analyses::VibrationResult> vibration{};
  std::optional<analyses::BucklingResult> buckling{};
  std::optional<TransientSetup> transient_setup{};
  std::optional<analyses::TransientResult> transient{};
  // The string's limits at every sample of the transient (analyses/limits_envelope.hpp).
  std::optional<analyses::LimitsEnvelope> transient_limits{};
  std::optional<analyses::TendencyResult> tendency{};
  std::vector<AnalysisFailure> failures{};  // in the order the analyses run (RunOptions::keep_finished)
};

// Runs the requested analyses of a case. Throws InputError (a case the analyses cannot take, named by
// file and key) and SolverError (a solver that did not converge, with where and why).
CaseResults RunCase(const io::Case& c, const AnalysisRequest& request, const RunOptions& options = {});

}  // namespace drillflex::pipeline
