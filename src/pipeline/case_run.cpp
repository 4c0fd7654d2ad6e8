#include "pipeline/case_run.hpp"

#include <fmt/format.h>

#include "analyses/point_the_bit.hpp"
#include "analyses/tendency_sensitivity.hpp"
#include "analyses/transient_start_places.hpp"
#include "core/error.hpp"
#include "core/profile.hpp"
#include "pipeline/summary.hpp"

namespace drillflex::pipeline {

using units::Quantity;

const char* AnalysisName(Analysis analysis) {
  switch (analysis) {
    case Analysis::Static: return "static";
    case Analysis::Modes: return "modes";
    case Analysis::Buckling: return "buckling";
    case Analysis::Vibration: return "vibration";
    case Analysis::Transient: return "transient";
    case Analysis::Tendency: return "tendency";
  }
  return "unknown";
}

AnalysisRequest AnalysisRequest::Only(Analysis analysis) {
  AnalysisRequest request;
  switch (analysis) {
    case Analysis::Static: request.static_analysis = true; break;
    case Analysis::Modes: request.modes = true; break;
    case Analysis::Buckling: request.buckling = true; break;
    case Analysis::Vibration: request.vibration = true; break;
    case Analysis::Transient: request.transient = true; break;
    case Analysis::Tendency: request.tendency = true; break;
  }
  return request;
}

bool AnalysisRequest::Has(Analysis analysis) const {
  switch (analysis) {
    case Analysis::Static: return static_analysis;
    case Analysis::Modes: return modes;
    case Analysis::Buckling: return buckling;
    case Analysis::Vibration: return vibration;
    case Analysis::Transient: return transient;
    case Analysis::Tendency: return tendency;
  }
  return false;
}

AnalysisRequest CaseAnalyses(const io::Case& c) {
  const auto& a = c.analyses;
  const AnalysisRequest request{a.static_analysis.has_value(), a.modes.has_value(), a.buckling.has_value(),
                                a.vibration.has_value(),       a.transient.has_value(), a.tendency.has_value()};
  if (!request.Any()) {
    throw InputError({c.file, 0, 0}, "analyses",
                     a.roadmap ? "the case lists only a roadmap: run it with `drillflex roadmap`"
                               : "the case lists no analyses to run");
  }
  return request;
}

CaseModel BuildCaseModel(const io::Case& c) {
  const profile::Scope scope("pipeline: build the model");
  model::ModelInput input = c.input;
  // A transient's initial loads are a load group of the case's model, off but in its start
  // (analyses::TransientStartPositions).
  if (c.analyses.transient) input.initial_loads = c.analyses.transient->initial_loads;
  auto cache = std::make_unique<cms::ReductionCache>();
  model::BuiltModel built = BuildModel(input, *cache);
  return CaseModel{std::move(input), std::move(cache), std::move(built)};
}

model::BuiltModel BuildModel(const model::ModelInput& input, cms::ReductionCache& cache) {
  return model::BuildSystemModel(input, cache);
}

analyses::TendencyResult RunCaseTendency(const io::Case& c, CaseModel& case_model, const RunObserver& observer) {
  const analyses::ModelFactory build = [&case_model](const model::ModelInput& input) {
    return BuildModel(input, *case_model.cache);
  };
  const analyses::TendencySettings settings = c.analyses.tendency.value_or(analyses::TendencySettings{});
  const analyses::StaticSettings statics = CaseStaticSettings(c, observer);
  try {
    analyses::TendencyResult result = analyses::RunTendency(case_model.input, build, statics, settings);
    if (settings.rss) {
      // The natural tendency and full steer, each from the case's steady curvature (the case's own steer is one of them).
      analyses::SteeringRates steering;
      steering.steer = settings.rss->steer;
      const auto at_steer = [&](double steer) {
        if (steer == settings.rss->steer) return result.curvature;
        analyses::TendencySettings varied = settings;
        varied.rss->steer = steer;
        return analyses::RunTendency(case_model.input, build, statics, varied, result.curvature).curvature;
      };
      steering.natural = at_steer(0.0);
      steering.full = at_steer(1.0);
      result.steering = steering;
    }
    if (settings.sensitivities) {
      result.sensitivities = analyses::ComputeTendencySensitivities(case_model.input, build, statics, settings, result);
    }
    return result;
  } catch (const InputError& e) {  // the string the tendency cannot take: name the case file
    if (!e.location().file.empty()) throw;
    throw InputError({c.file, e.location().line, e.location().column}, e.key_path(), e.message());
  }
}

analyses::StaticSettings CaseStaticSettings(const io::Case& c, const RunObserver& observer) {
  analyses::StaticSettings settings = c.analyses.static_analysis.value_or(analyses::StaticSettings{});
  if (observer.log) settings.log = observer.log;
  return settings;
}

TransientSetup PrepareTransient(const io::Case& c, CaseModel& case_model, const analyses::StaticResult* equilibrium,
                                const RunOptions& options) {
  const model::ModelInput& input = case_model.input;
  analyses::TransientSettings settings = c.analyses.transient.value_or(analyses::TransientSettings{});
  settings.state_frames = options.keep_transient_shapes ? settings.vtk_frames.value_or(kDefaultVtkFrames) : 0;
  // The equilibrium already solved, when the start is that equilibrium at rest (not with a rotating
  // string's prescribed friction, nor with initial loads).
  const bool reuse_equilibrium = equilibrium && settings.start == analyses::TransientStart::Equilibrium &&
                                 settings.initial_loads.empty() && !input.static_sliding;
  VecX start = reuse_equilibrium ? equilibrium->q
                                 : analyses::TransientStartPositions(input, case_model.built, settings,
                                                                     CaseStaticSettings(c, options.observer));
  // The model in motion: with the drives, the friction following the motion (same coordinates), a
  // bottom contact where the bit rests at the start. The fluid moves with the bodies, its annulus
  // terms at TransientFluidFrequency.
  const double fluid_frequency = analyses::TransientFluidFrequency(input, case_model.built, start, settings);
  if (fluid_frequency > 0.0 && options.observer.note) {
    options.observer.note(
        fmt::format("transient: the annulus fluid's C_m and C_v at {:.4g} Hz", fluid_frequency / (2.0 * kPi)));
  }
  model::ModelInput moving_input = analyses::TransientModelInput(input, settings, fluid_frequency);
  moving_input = analyses::PlaceBottomAtStart(std::move(moving_input), case_model.built, start);
  moving_input = analyses::PlaceBlockAtStart(std::move(moving_input), case_model.built, start);
  model::BuiltModel moving = BuildModel(moving_input, *case_model.cache);
  return TransientSetup{std::move(settings), fluid_frequency, std::move(start), std::move(moving)};
}

analyses::StaticResult RunCaseStatic(const io::Case& c, CaseModel& case_model, const RunObserver& observer) {
  return analyses::RunStaticInWell(case_model.input, case_model.built, CaseStaticSettings(c, observer));
}

analyses::ModesResult RunCaseModes(const io::Case& c, const CaseModel& case_model, const VecX& equilibrium) {
  const model::LateralFluid fluid = model::MakeLateralFluid(case_model.input, case_model.built.system);
  const analyses::ModesSettings settings = c.analyses.modes.value_or(analyses::ModesSettings{});
  return settings.gyroscopic
             ? analyses::ComputeGyroscopicModes(case_model.built.system, equilibrium, settings, &fluid)
             : analyses::RunModes(case_model.built, equilibrium, settings, &fluid);
}

analyses::VibrationResult RunCaseVibration(const io::Case& c, const CaseModel& case_model, const VecX& equilibrium,
                                           const analyses::VibrationSettings& settings) {
  const model::LateralFluid fluid = model::MakeLateralFluid(case_model.input, case_model.built.system);
  try {
    return analyses::RunVibration(case_model.built, case_model.input, fluid, equilibrium, settings);
  } catch (const InputError& e) {  // an excitation the string cannot take: name the case file
    if (!e.location().file.empty()) throw;
    throw InputError({c.file, e.location().line, e.location().column}, e.key_path(), e.message());
  }
}

analyses::VibrationSettings CaseVibrationSettings(const io::Case& c) {
  analyses::VibrationSettings settings = c.analyses.vibration.value_or(analyses::VibrationSettings{});
  if (settings.excitations.empty()) settings.excitations = analyses::DefaultExcitations(c.input.string);
  return settings;
}

namespace {

void Finished(const RunObserver& observer, Analysis analysis, const CaseResults& results) {
  if (observer.finished) observer.finished(analysis, results);
}

// Runs one analysis's `solve`. With RunOptions::keep_finished a solver's failure is kept in
// results.failures (false returned) instead of ending the run.
template <class Solve>
bool Attempt(Analysis analysis, const RunOptions& options, CaseResults& results, Solve&& solve) {
  if (!options.keep_finished) {
    solve();
    return true;
  }
  try {
    solve();
    return true;
  } catch (const SolverError& error) {
    // The solvers name their analysis first ("buckling: ..."): the failure names it already.
    std::string message = error.what();
    const std::string prefix = std::string(AnalysisName(analysis)) + ": ";
    if (message.starts_with(prefix)) message.erase(0, prefix.size());
    results.failures.push_back({analysis, std::move(message)});
    return false;
  }
}

void NotRun(Analysis analysis, Analysis failed, CaseResults& results) {
  results.failures.push_back(
      {analysis, fmt::format("not run: it starts from the {} equilibrium, which failed", AnalysisName(failed))});
}

void RunModes(const io::Case& c, const RunOptions& options, const VecX& equilibrium, CaseResults& results) {
  results.modes = RunCaseModes(c, results.model, equilibrium);
  const analyses::ModesSettings settings = c.analyses.modes.value_or(analyses::ModesSettings{});
  if (settings.campbell) {
    const model::LateralFluid fluid = model::MakeLateralFluid(results.model.input, results.model.built.system);
    results.campbell = analyses::ComputeCampbell(results.model.built.system, equilibrium, settings, &fluid);
  }
  Finished(options.observer, Analysis::Modes, results);
}

void RunVibration(const io::Case& c, const RunOptions& options, const VecX& equilibrium, CaseResults& results) {
  const analyses::VibrationSettings settings = CaseVibrationSettings(c);
  const bool defaults = !c.analyses.vibration || c.analyses.vibration->excitations.empty();
  if (defaults && options.observer.note) {
    const analyses::Excitation& imbalance = settings.excitations.front();
    options.observer.note(fmt::format(
        "vibration: the case gives no excitations: an imbalance of {} at {} from the bit at 1× and the bit at 3× "
        "({} lateral, {} axial, {} torsional; docs/case-format.md)",
        Show(c, imbalance.imbalance, Quantity::Imbalance), Show(c, imbalance.at, Quantity::Length),
        Show(c, analyses::kDefaultBitLateral, Quantity::Force), Show(c, analyses::kDefaultBitAxial, Quantity::Force),
        Show(c, analyses::kDefaultBitTorsional, Quantity::Moment)));
  }
  results.vibration = RunCaseVibration(c, results.model, equilibrium, settings);
  Finished(options.observer, Analysis::Vibration, results);
}

}  // namespace

namespace {

// The transient from the static equilibrium when one was solved (else from its own start).
void RunCaseTransient(const io::Case& c, const RunOptions& options, CaseResults& results) {
  const RunObserver& observer = options.observer;
  results.transient_setup =
      PrepareTransient(c, results.model, results.static_result ? &*results.static_result : nullptr, options);
  const TransientSetup& setup = *results.transient_setup;
  analyses::TransientProgress progress;
  if (observer.progress) {
    progress = [&observer](double time, double duration) { observer.progress(Analysis::Transient, time, duration); };
  }
  // The string's limits at every output sample, whether or not VTK frames are kept (issue 37).
  analyses::LimitsRecorder limits(c.input, setup.moving, c.limits.design_factor);
  const analyses::TransientSampleObserver read_limits = [&limits](double time, const VecX& q, const VecX&) {
    limits.Read(time, q);
  };
  results.transient = analyses::RunTransient(setup.moving, setup.start, setup.settings, progress, read_limits);
  results.transient_limits = limits.envelope();
  Finished(observer, Analysis::Transient, results);
}

// What an analysis would refuse only after the static solve it starts from, refused before anything is
// solved (issue 33): a motor excitation without a speed or a motor. (The reader refuses what the case
// alone shows wrong: gyroscopic modes of an axial kind, a Campbell diagram without them.)
void CheckBeforeSolving(const io::Case& c, const AnalysisRequest& request) {
  if (request.tendency) {
    if (const auto problem = analyses::TendencyInputProblem(c.input)) {
      throw InputError({c.file, 0, 0}, problem->first, problem->second);
    }
    const std::optional<analyses::RssSettings> rss = c.analyses.tendency ? c.analyses.tendency->rss : std::nullopt;
    if (rss && rss->type == analyses::RssType::Point) {
      if (const auto problem = analyses::PointTheBitProblem(c.input, *rss)) {
        throw InputError({c.file, rss->source_line, 0}, problem->first, problem->second);
      }
    }
  }
  if (request.vibration) {
    const analyses::VibrationSettings settings = CaseVibrationSettings(c);
    for (Index i = 0; i < std::ssize(settings.excitations); ++i) {
      if (settings.excitations[i].type != analyses::ExcitationType::Motor) continue;
      try {
        analyses::MotorSpeed(settings.excitations[i], c.input, i);
      } catch (const InputError& e) {
        if (!e.location().file.empty()) throw;
        throw InputError({c.file, e.location().line, e.location().column}, e.key_path(), e.message());
      }
    }
  }
}

}  // namespace

CaseResults RunCase(const io::Case& c, const AnalysisRequest& request, const RunOptions& options) {
  const RunObserver& observer = options.observer;
  CheckBeforeSolving(c, request);
  if (request.static_analysis && !c.well && c.input.supports.empty()) {
    throw InputError({c.file, 0, 0}, "supports",
                     "the string has no well and no supports: nothing holds it (add 'supports')");
  }
  CaseResults results{.requested = request, .model = BuildCaseModel(c)};
  const model::ModelInput& input = results.model.input;
  const model::BuiltModel& built = results.model.built;
  if (observer.note) {
    observer.note(fmt::format("model: {} bodies, {} coordinates", built.system.bodies().size(),
                              built.system.num_velocities()));
    if (c.input.operation.hook_load && input.well && input.supports.empty()) {
      observer.note(fmt::format("operation: WOB {} from the hook load {} (the string's buoyed weight along the hole "
                                "less it; the pipe above the model, to the surface, weighs {})",
                                Show(c, input.operation.weight_on_bit, Quantity::WeightOnBit),
                                Show(c, *c.input.operation.hook_load, Quantity::Force),
                                Show(c, model::StringAboveWeight(input), Quantity::Force)));
    }
  }
  VecX equilibrium = built.system.ReferencePositions();
  bool static_failed = false;
  if (request.static_analysis || request.modes || request.vibration) {
    static_failed = !Attempt(Analysis::Static, options, results, [&] {
      results.static_result = RunCaseStatic(c, results.model, observer);
      equilibrium = results.static_result->q;
      Finished(observer, Analysis::Static, results);
    });
  }
  for (const Analysis linear : {Analysis::Modes, Analysis::Vibration}) {
    if (!request.Has(linear)) continue;
    if (static_failed) {
      NotRun(linear, Analysis::Static, results);
      continue;
    }
    Attempt(linear, options, results, [&] {
      if (linear == Analysis::Modes) RunModes(c, options, equilibrium, results);
      else RunVibration(c, options, equilibrium, results);
    });
  }
  if (request.buckling) {
    Attempt(Analysis::Buckling, options, results, [&] {
      results.buckling = analyses::RunBuckling(input, built, c.analyses.buckling.value_or(analyses::BucklingSettings{}),
                                               CaseStaticSettings(c, observer));
      Finished(observer, Analysis::Buckling, results);
    });
  }
  if (request.tendency) {
    Attempt(Analysis::Tendency, options, results, [&] {
      results.tendency = RunCaseTendency(c, results.model, observer);
      Finished(observer, Analysis::Tendency, results);
    });
  }
  if (request.transient && static_failed) {
    NotRun(Analysis::Transient, Analysis::Static, results);
  } else if (request.transient) {
    Attempt(Analysis::Transient, options, results, [&] { RunCaseTransient(c, options, results); });
  }
  return results;
}

}  // namespace drillflex::pipeline
