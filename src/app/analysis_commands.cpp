// `drillflex static|modes|buckling|vibration|transient|run CASE [-o DIR]`: build the model of a case, run the
// analyses, print a summary in the case's units and write the results atomically.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <optional>

#include <fmt/format.h>

#include "analyses/bit_bottom_start.hpp"
#include "analyses/bit_tendency.hpp"
#include "analyses/buckling_analysis.hpp"
#include "analyses/gyroscopic_modes.hpp"
#include "analyses/modes_analysis.hpp"
#include "analyses/static_analysis.hpp"
#include "analyses/transient_analysis.hpp"
#include "analyses/vibration_analysis.hpp"
#include "app/commands.hpp"
#include "cms/reduction_cache.hpp"
#include "core/error.hpp"
#include "io/analysis_results.hpp"
#include "io/model_input.hpp"
#include "io/report_html.hpp"
#include "io/vtk_files.hpp"

namespace drillflex::app {
namespace {

using units::Quantity;

// Frames of the string's shape a transient keeps for transient.pvd by default: about 0.5 MB each for
// the bundled example's 1 015 stations (docs/case-format.md `vtk_frames`).
constexpr int kDefaultVtkFrames = 50;

struct Requested {
  bool static_analysis = false, modes = false, buckling = false, vibration = false, transient = false;
};

// A value in the case's units with its unit; never "-0" (a zero's sign says nothing to an engineer).
std::string Show(const io::Case& c, double si, Quantity quantity, int digits = 5) {
  const double value = units::FromSI(si, quantity, c.units);
  const std::string text = fmt::format("{:.{}g}", value + 0.0, digits);
  return (text == "-0" ? std::string("0") : text) + " " + std::string(units::DefaultUnit(quantity, c.units));
}

void PrintStatic(const io::Case& c, const analyses::StaticResult& result) {
  std::cout << fmt::format("static: converged ({}) in {} iterations (|R| = {:.3g} N){}\n", result.method,
                           result.iterations, result.residual_norm, result.stable ? ", stable" : "");
  for (const std::string& warning : result.warnings) std::cout << "  warning: " << warning << "\n";
  // Where along the string: s from the bit, and the MD with a well.
  auto where = [&](double s, double md) {
    return c.well ? fmt::format("{} from the bit (MD {})", Show(c, s, Quantity::Length), Show(c, md, Quantity::Length))
                  : fmt::format("{} from the bit", Show(c, s, Quantity::Length));
  };
  const analyses::StaticNodeResult* widest = nullptr;
  const analyses::StaticNodeResult* stressed = nullptr;
  const analyses::StaticNodeResult* tightest = nullptr;  // smallest clearance of a node with a wall contact
  for (const auto& node : result.nodes) {
    if (!widest || node.lateral_offset > widest->lateral_offset) widest = &node;
    if (!stressed || node.von_mises_stress > stressed->von_mises_stress) stressed = &node;
    if (node.wall_contact && (!tightest || node.clearance < tightest->clearance)) tightest = &node;
  }
  auto md_of = [&](const analyses::StaticNodeResult& node) {
    return node.has_wall ? node.md : io::StationMd(c, node.s);
  };
  if (widest) {
    std::cout << fmt::format("  largest lateral displacement {} at {}\n",
                             Show(c, widest->lateral_offset, Quantity::Diameter), where(widest->s, md_of(*widest)));
    std::cout << fmt::format("  peak von Mises stress {} at {} (bending {}, axial force {})\n",
                             Show(c, stressed->von_mises_stress, Quantity::Stress),
                             where(stressed->s, md_of(*stressed)),
                             Show(c, stressed->bending_stress, Quantity::Stress),
                             Show(c, stressed->axial_force, Quantity::Force));
  }
  if (c.well) {
    if (result.contacts.empty()) {
      std::cout << "  no wall contact carries force\n";
    } else {
      const auto largest =
          std::max_element(result.contacts.begin(), result.contacts.end(),
                           [](const auto& a, const auto& b) { return a.normal_force < b.normal_force; });
      std::cout << fmt::format("  {} wall contacts carry force; the largest {} at {} ({})\n", result.contacts.size(),
                               Show(c, largest->normal_force, Quantity::Force), where(largest->s, largest->md),
                               c.string.components.at(largest->component).name);
    }
  }
  if (tightest) {
    std::cout << fmt::format("  smallest clearance to the wall {} at {}{}\n",
                             Show(c, tightest->clearance, Quantity::Diameter), where(tightest->s, tightest->md),
                             tightest->clearance < 0.0 ? " (negative: into the wall, normal force / contact stiffness)"
                                                       : "");
  }
  if (result.bit) {
    const auto& bit = *result.bit;
    const analyses::BitTendency tendency = analyses::ClassifyBitTendency(bit);
    std::cout << fmt::format("  bit: side force {}: {} (build force {}), walk {} (walk force {}); tilt {:.4g} deg; "
                             "a tendency needs more than {}\n",
                             Show(c, bit.side_force, Quantity::Force), analyses::TendencyName(tendency.inclination),
                             Show(c, bit.build_force, Quantity::Force), analyses::TendencyName(tendency.azimuth),
                             Show(c, bit.walk_force, Quantity::Force), bit.tilt / kDegree,
                             Show(c, tendency.threshold, Quantity::Force, 3));
  }
  // Reactions in the string frame at the support: x along the string (up-hole), and in a well y to
  // the right and z to the high side (docs/case-format.md "Frames and signs").
  const char* lateral_y = c.well ? "right" : "y";
  const char* lateral_z = c.well ? "high side" : "z";
  for (const auto& reaction : result.reactions) {
    const double string_length = io::StringLength(c);
    const std::string name = reaction.s <= 1e-9                          ? " (the bit)"
                             : std::abs(reaction.s - string_length) < 1e-6 ? " (the top)"
                                                                           : "";
    std::cout << fmt::format("  support at {}{}: force along the string (up-hole) {}, {} {}, {} {}\n",
                             Show(c, reaction.s, Quantity::Length), name, Show(c, reaction.force.x(), Quantity::Force),
                             lateral_y, Show(c, reaction.force.y(), Quantity::Force), lateral_z,
                             Show(c, reaction.force.z(), Quantity::Force));
  }
}

void PrintModes(const analyses::ModesResult& result) {
  std::cout << fmt::format("modes: {} computed", result.modes.size());
  if (result.gyroscopic) {
    std::cout << fmt::format(" spinning at {:.5g} rpm (gyroscopic, on {} undamped modes)", result.rotary_speed * 30.0 / kPi,
                             result.basis_size);
  }
  if (result.near_zero_modes > 0) {
    std::cout << fmt::format("; {} near zero (below {} Hz: no critical speed)", result.near_zero_modes,
                             analyses::kNearZeroFrequencyHz);
  }
  if (result.negative_stiffness_modes > 0) {
    std::cout << fmt::format("; {} with ω² < 0 (negative stiffness: not vibration modes)", result.negative_stiffness_modes);
  }
  std::cout << "\n";
  std::cout << fmt::format("  {:>4} {:>12} {:>9}  {:<10} {:>6} {:>6} {:>6}\n", "#", "f (Hz)", "damping", "kind", "axial",
                           "tors", "lat");
  for (std::size_t m = 0; m < result.modes.size(); ++m) {
    const auto& mode = result.modes[m];
    std::cout << fmt::format("  {:>4} {:>12.6g} {:>9.3g}  {:<10} {:>6.3f} {:>6.3f} {:>6.3f}{}\n", m + 1,
                             mode.frequency_hz, mode.damping_ratio, analyses::ModeKindName(mode.kind), mode.axial_fraction, mode.torsional_fraction,
                             mode.lateral_fraction,
                             result.gyroscopic         ? fmt::format("  {} whirl ({:+.2f})", analyses::WhirlName(mode.whirl),
                                                                     mode.whirl_index)
                             : mode.rigid_body         ? "  (rigid body)"
                             : mode.negative_stiffness ? fmt::format("  (ω² = {:.4g} rad²/s² < 0: negative stiffness)",
                                                                     mode.eigenvalue)
                             : mode.near_zero          ? "  (near zero: barely resisted)"
                                                       : "");
  }
}

// The Campbell diagram's extent and where its branches cross 1× (an imbalance meets them there).
void PrintCampbell(const analyses::CampbellResult& result) {
  if (result.points.empty()) return;
  std::cout << fmt::format("Campbell diagram: {} speeds, {:.5g} to {:.5g} rpm (campbell.csv)\n", result.points.size(),
                           result.points.front().rotary_speed * 30.0 / kPi, result.points.back().rotary_speed * 30.0 / kPi);
  if (result.synchronous.empty()) {
    std::cout << "  no branch crosses 1x in that range\n";
    return;
  }
  for (const analyses::CampbellCrossing& crossing : result.synchronous) {
    std::cout << fmt::format("  mode {} crosses 1x at {:.5g} rpm ({:.4g} Hz, {} whirl)\n", crossing.branch + 1,
                             crossing.rotary_speed * 30.0 / kPi, crossing.frequency_hz, analyses::WhirlName(crossing.whirl));
  }
}

void PrintCriticalRpm(const io::Case& c, const analyses::ModesResult& result) {
  const io::RuleOfThumbRpm rule = io::CalcRuleOfThumbCriticalRpm(c);
  if (const analyses::ModeResult* mode = analyses::FirstLateralMode(result)) {
    std::cout << fmt::format("  critical RPM of the first lateral mode {:.5g} rpm; rule of thumb 33055 sqrt(OD²+ID²)/L² "
                             "{:.5g} rpm (span {}, ±15 %)\n",
                             60.0 * mode->frequency_hz, rule.rpm * 30.0 / kPi, Show(c, rule.span, Quantity::Length));
    return;
  }
  std::cout << fmt::format("  rule-of-thumb critical RPM 33055 sqrt(OD²+ID²)/L² {:.5g} rpm (span {})\n",
                           rule.rpm * 30.0 / kPi, Show(c, rule.span, Quantity::Length));
}

// "bit 3×", "imbalance 1×", "motor 5 lobes": what drives a critical RPM.
std::string ExcitationName(const io::Case& c, int index) {
  if (!c.analyses.vibration || index < 0 || index >= static_cast<int>(c.analyses.vibration->excitations.size())) return "?";
  return analyses::ExcitationName(c.analyses.vibration->excitations[static_cast<std::size_t>(index)]);
}

// The critical RPMs most severe first (at most kListed; the rest by RPM on one line).
void PrintCriticalSpeeds(const io::Case& c, const analyses::VibrationResult& result) {
  constexpr std::size_t kListed = 8;
  if (result.critical_speeds.empty()) {
    std::cout << "  critical RPMs: none in the sweep\n";
    return;
  }
  const bool ratio = !result.max_clearance_ratio.empty();
  std::cout << fmt::format("  critical RPMs, most severe first ({}):\n",
                           ratio ? "lateral amplitude / radial clearance" : "lateral amplitude");
  for (std::size_t k = 0; k < result.critical_speeds.size() && k < kListed; ++k) {
    const analyses::CriticalSpeed& critical = result.critical_speeds[k];
    const std::string severity = ratio ? fmt::format("{:.3g} of the clearance, ", critical.severity) : "";
    std::cout << fmt::format("    {}: {}largest amplitude {}, bending {}; {} at {:.3g} Hz\n",
                             Show(c, critical.rpm, Quantity::RotarySpeed), severity,
                             Show(c, critical.displacement, Quantity::Diameter),
                             Show(c, critical.bending_stress, Quantity::Stress), ExcitationName(c, critical.excitation),
                             critical.frequency / (2.0 * kPi));
  }
  if (result.critical_speeds.size() > kListed) {
    std::vector<double> rest;
    for (std::size_t k = kListed; k < result.critical_speeds.size(); ++k) rest.push_back(result.critical_speeds[k].rpm);
    std::sort(rest.begin(), rest.end());
    std::string list;
    for (const double rpm : rest) list += (list.empty() ? "" : ", ") + Show(c, rpm, Quantity::RotarySpeed);
    std::cout << fmt::format("    {} milder peaks: {}\n", rest.size(), list);
  }
}

void PrintVibration(const io::Case& c, const analyses::VibrationResult& result) {
  std::cout << fmt::format("vibration: {} rotary speeds, {} to {}; {} wall contacts closed at equilibrium\n",
                           result.rpm.size(), Show(c, result.rpm.front(), Quantity::RotarySpeed),
                           Show(c, result.rpm.back(), Quantity::RotarySpeed), result.closed_contacts);
  if (result.method == analyses::VibrationMethod::Reduced) {
    std::cout << fmt::format("  solved on a reduced basis of {} vectors (method: direct for the full system)\n",
                             result.basis_size);
  } else {
    std::cout << "  solved on the full system (a sparse LU per frequency)"
              << (result.method_note.empty() ? "" : ": " + result.method_note) << "\n";
  }
  const auto peak = std::max_element(result.max_lateral_displacement.begin(), result.max_lateral_displacement.end());
  const std::size_t i = static_cast<std::size_t>(peak - result.max_lateral_displacement.begin());
  std::cout << fmt::format("  largest lateral displacement amplitude {} at {} ({} from the bit)\n",
                           Show(c, *peak, Quantity::Diameter), Show(c, result.rpm[i], Quantity::RotarySpeed),
                           Show(c, result.s_max_displacement[i], Quantity::Length));
  PrintCriticalSpeeds(c, result);
  std::string windows;
  for (const auto& w : result.safe_windows) {
    windows += (windows.empty() ? "" : ", ") + fmt::format("{} to {}", Show(c, w.from, Quantity::RotarySpeed),
                                                           Show(c, w.to, Quantity::RotarySpeed));
  }
  std::cout << fmt::format("  safe windows (displacement below {:.3g} of the clearance, bending-stress amplitude "
                           "below {}): {}\n",
                           result.clearance_fraction, Show(c, result.stress_limit, Quantity::Stress),
                           windows.empty() ? "none" : windows);
  std::string quiet;
  for (const auto& w : result.quietest_windows) {
    quiet += (quiet.empty() ? "" : ", ") + fmt::format("{} to {}", Show(c, w.from, Quantity::RotarySpeed),
                                                       Show(c, w.to, Quantity::RotarySpeed));
  }
  std::cout << fmt::format("  quietest ranges (within {}× of the sweep's least {}): {}\n", analyses::kQuietFactor,
                           result.max_clearance_ratio.empty() ? "amplitude" : "clearance ratio", quiet);
}

void PrintBuckling(const io::Case& c, const analyses::BucklingResult& result) {
  const std::string scaled = result.scaled_wob ? "the WOB" : "every load";
  const std::string how = result.about_equilibrium ? "the lowest lateral frequency about the equilibrium reaches 0"
                                                   : "eigenproblem";
  std::cout << fmt::format("buckling: {} × {:.6g} buckles the string, largest compression {} ({})\n", scaled,
                           result.load_factor, Show(c, result.critical_load, Quantity::Force, 6), how);
  if (result.critical_wob > 0.0) {
    std::cout << fmt::format("  critical WOB {}\n", Show(c, result.critical_wob, Quantity::Force, 6));
  }
  if (result.sinusoidal.computed) {
    const analyses::SinusoidalBucklingScreen& screen = result.sinusoidal;
    const std::string where = fmt::format("MD {}", Show(c, screen.md, Quantity::Length));
    if (screen.sinusoidal_load == 0.0) {
      std::cout << fmt::format("  Dawson-Paslay: at {} the hole is vertical and the string compressed ({}): no weight "
                               "holds it to the wall (Lubinski's case)\n",
                               where, Show(c, screen.compression, Quantity::Force));
    } else if (screen.load_factor < 1.0) {
      std::cout << fmt::format("  Dawson-Paslay: the compression {} at {} is {:.3g} times the sinusoidal buckling load "
                               "{} (helical {}): the string lies buckled there at the case's loads\n",
                               Show(c, screen.compression, Quantity::Force), where, screen.compression / screen.sinusoidal_load,
                               Show(c, screen.sinusoidal_load, Quantity::Force), Show(c, screen.helical_load, Quantity::Force));
    } else {
      std::cout << fmt::format("  Dawson-Paslay: sinusoidal buckling first at {} × {:.4g}, at {} (compression "
                               "{} against {} now)\n",
                               scaled, screen.load_factor, where, Show(c, screen.compression, Quantity::Force),
                               Show(c, screen.sinusoidal_load, Quantity::Force));
    }
  }
  if (!result.about_equilibrium && result.frequency_method_converged) {
    std::cout << fmt::format("  from the lowest frequency against load: multiplier {:.6g}, compression {}\n",
                             result.frequency_load_factor, Show(c, result.frequency_critical_load, Quantity::Force, 6));
  } else if (!result.frequency_method_converged) {
    std::cout << "  warning: the frequency extrapolation did not settle (samples in buckling.csv)\n";
  }
}

// A one-line progress bar with the time left on standard error, drawn only when it is a terminal
// (none in pipes, files and tests), redrawn at most five times a second.
class ProgressBar {
 public:
  ProgressBar() : enabled_(isatty(STDERR_FILENO) == 1), start_(Clock::now()), last_(start_) {}
  ~ProgressBar() {
    if (drawn_) std::fputc('\n', stderr);
  }
  void Update(double time, double duration) {
    if (!enabled_) return;
    const auto now = Clock::now();
    if (drawn_ && now - last_ < std::chrono::milliseconds(200) && time < duration) return;
    last_ = now;
    drawn_ = true;
    const double fraction = std::clamp(time / duration, 0.0, 1.0);
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const int width = 30, filled = static_cast<int>(fraction * width);
    const std::string left =
        fraction > 0.0 ? fmt::format("{:.0f} s left", elapsed * (1.0 - fraction) / fraction) : std::string("...");
    std::fprintf(stderr, "\r  [%s%s] %3.0f %%  t = %.4g of %.4g s, %s   ", std::string(filled, '#').c_str(),
                 std::string(width - filled, '.').c_str(), 100.0 * fraction, time, duration, left.c_str());
    std::fflush(stderr);
  }

 private:
  using Clock = std::chrono::steady_clock;
  bool enabled_ = false;
  bool drawn_ = false;
  Clock::time_point start_, last_;
};

// `driven`: a top drive, a block or a bit-rock law does work on the string; `block`: a block drive
// holds the top (its force is the hook load).
void PrintTransient(const io::Case& c, const analyses::TransientResult& result, bool driven, bool block) {
  const auto& stats = result.statistics;
  std::cout << fmt::format("transient: {} s in {} steps ({} rejected), {} Newton iterations, {} factorizations; "
                           "steps {:.3g} to {:.3g} s\n",
                           result.samples.back().time, stats.steps, stats.error_rejections + stats.newton_failures,
                           stats.newton_iterations, stats.factorizations, stats.smallest_step, stats.largest_step);
  // The energy's change says something only about a string left to itself: a driven one gains the
  // drives' work, which is not summed, so no balance is printed for it.
  if (!driven) {
    std::cout << fmt::format("  energy: largest change {:.3g} of the largest kinetic energy (damping, friction and the "
                             "integrator's dissipation, rho_infinity {:.3g})\n",
                             result.energy_drift, result.rho_infinity);
  }
  const auto& last = result.samples.back();
  // The tension at the top of the modelled string is the rig's hook load only with a block drive
  // holding it; negative, the string above pushes the top down.
  const std::string top = last.hook_load < 0.0 ? fmt::format("compression at the top of the modelled string {}",
                                                              Show(c, -last.hook_load, Quantity::Force))
                                               : fmt::format("{} {}", block ? "hook load" : "tension at the top of the modelled string",
                                                             Show(c, last.hook_load, Quantity::Force));
  std::cout << fmt::format("  at the end: surface {}, bit {}, {}, WOB {}\n", Show(c, last.surface_speed, Quantity::RotarySpeed),
                           Show(c, last.bit_speed, Quantity::RotarySpeed), top,
                           Show(c, last.weight_on_bit, Quantity::WeightOnBit));
}

int RunAnalyses(const CommandOptions& options, Requested requested, const char* command) {
  const auto start = std::chrono::steady_clock::now();
  const io::Case c = io::ReadCase(options.case_path);
  if (requested.static_analysis && !c.well && c.supports.empty()) {
    throw InputError({c.file, 0, 0}, "supports",
                     "the string has no well and no supports: nothing holds it (add 'supports')");
  }
  cms::ReductionCache cache;
  const model::ModelInput input = io::MakeModelInput(c);
  const model::BuiltModel built = model::BuildSystemModel(input, cache);
  std::cout << fmt::format("model: {} bodies, {} coordinates\n", built.system.bodies().size(),
                           built.system.num_velocities());
  io::ResultFiles files(options.output_directory.empty() ? io::DefaultOutputDirectory(c) : options.output_directory);
  io::AddCaseHeader(c, built, files);
  io::AddOperation(c, input, files);
  if (c.operation.hook_load && input.trajectory && input.supports.empty()) {
    std::cout << fmt::format("operation: WOB {} from the hook load {} (the string's buoyed weight along the hole less "
                             "it; the pipe above the model, to the surface, weighs {})\n",
                             Show(c, input.operation.weight_on_bit, Quantity::WeightOnBit),
                             Show(c, *c.operation.hook_load, Quantity::Force),
                             Show(c, model::StringAboveWeight(input), Quantity::Force));
  }
  const bool report = c.output.report && !options.no_report, vtk = c.output.vtk && !options.no_report;
  io::ReportData report_data;

  VecX equilibrium = built.system.ReferencePositions();
  if (requested.static_analysis || requested.modes || requested.vibration) {
    analyses::StaticSettings settings = c.analyses.static_analysis.value_or(analyses::StaticSettings{});
    if (options.verbose) settings.log = [](const std::string& line) { std::cerr << line << '\n'; };
    const auto result = analyses::RunStaticInWell(input, built, cache, settings);
    equilibrium = result.q;
    // The modes and the vibration write the equilibrium they start from too (not printed): the
    // report and string.vtp draw it.
    if (requested.static_analysis) PrintStatic(c, result);
    {
      io::AddStaticResults(c, result, files);
      if (report) report_data.AddStatic(c, input, result);
      if (vtk) io::AddStaticVtk(c, built, result, files);
    }
  }
  if (requested.modes) {
    const model::LateralFluid fluid = model::MakeLateralFluid(input, built.system);
    const analyses::ModesSettings settings = c.analyses.modes.value_or(analyses::ModesSettings{});
    const auto result = settings.gyroscopic
                            ? analyses::ComputeGyroscopicModes(built.system, equilibrium, settings, &fluid)
                            : analyses::RunModes(built, equilibrium, settings, &fluid);
    PrintModes(result);
    PrintCriticalRpm(c, result);
    io::AddModesResults(c, result, files);
    if (report) report_data.AddModes(c, result);
    if (settings.campbell) {
      const analyses::CampbellResult campbell = analyses::ComputeCampbell(built.system, equilibrium, settings, &fluid);
      PrintCampbell(campbell);
      io::AddCampbellResults(c, campbell, files);
    }
  }
  if (requested.vibration) {
    const model::LateralFluid fluid = model::MakeLateralFluid(input, built.system);
    analyses::VibrationResult result;
    try {
      result = analyses::RunVibration(built, input, fluid, equilibrium,
                                      c.analyses.vibration.value_or(analyses::VibrationSettings{}));
    } catch (const InputError& e) {  // an excitation the string cannot take: name the case file
      if (!e.location().file.empty()) throw;
      throw InputError({c.file, e.location().line, e.location().column}, e.key_path(), e.message());
    }
    PrintVibration(c, result);
    io::AddVibrationResults(c, result, files);
    if (report) report_data.AddExcitations(c);
  }
  if (requested.buckling) {
    analyses::StaticSettings static_settings = c.analyses.static_analysis.value_or(analyses::StaticSettings{});
    if (options.verbose) static_settings.log = [](const std::string& line) { std::cerr << line << '\n'; };
    const auto result =
        analyses::RunBuckling(input, built, c.analyses.buckling.value_or(analyses::BucklingSettings{}), static_settings);
    PrintBuckling(c, result);
    io::AddBucklingResults(c, result, files);
  }
  if (requested.transient) {
    analyses::TransientSettings settings = c.analyses.transient.value_or(analyses::TransientSettings{});
    // The string's shape at kDefaultVtkFrames output samples for ParaView (transient.pvd), unless the
    // case says how many; none without VTK output.
    settings.state_frames = vtk ? settings.vtk_frames.value_or(kDefaultVtkFrames) : 0;
    // The equilibrium already solved for the other analyses, when the start is that equilibrium.
    // (That one is at rest: not with a rotating string's prescribed friction.)
    const bool reuse_equilibrium = (requested.static_analysis || requested.modes || requested.vibration) &&
                                   settings.start == analyses::TransientStart::Equilibrium &&
                                   settings.initial_loads.empty() && !input.static_sliding;
    analyses::StaticSettings static_settings = c.analyses.static_analysis.value_or(analyses::StaticSettings{});
    if (options.verbose) static_settings.log = [](const std::string& line) { std::cerr << line << '\n'; };
    const VecX start_q = reuse_equilibrium
                             ? equilibrium
                             : analyses::TransientStartPositions(input, built, cache, settings, static_settings);
    // The model in motion: with the drives, the friction following the motion (same coordinates),
    // a bottom contact where the bit rests at the start. The fluid moves with the bodies, its annulus
    // terms at TransientFluidFrequency.
    const double fluid_frequency = analyses::TransientFluidFrequency(input, built, start_q, settings);
    if (fluid_frequency > 0.0) {
      std::cout << fmt::format("transient: the annulus fluid's C_m and C_v at {:.4g} Hz\n", fluid_frequency / (2.0 * kPi));
    }
    const model::BuiltModel moving = model::BuildSystemModel(
        analyses::PlaceBottomAtStart(analyses::TransientModelInput(input, settings, fluid_frequency), built, start_q),
        cache);
    analyses::TransientResult result;
    {
      ProgressBar bar;
      result = analyses::RunTransient(moving, start_q, settings,
                                      [&bar](double time, double duration) { bar.Update(time, duration); });
    }
    const bool block = settings.block.has_value();
    const bool driven = block || settings.top_drive.has_value() || settings.bit_rock.has_value() || c.operation.rpm != 0.0;
    PrintTransient(c, result, driven, block);
    io::AddTransientResults(c, result, files);
    if (report) report_data.AddTransient(c, input, result);
    if (vtk) io::AddTransientVtk(c, moving, result, files);
  }
  if (report) {
    const double solved = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    files.Add("report.html", io::ComposeReportHtml(files.json(), report_data, {command, solved}));
  }
  files.Commit();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << fmt::format("results written to {} ({:.3g} s){}\n", files.directory(), seconds,
                           report ? fmt::format("; the report: {}/report.html", files.directory()) : "");
  return kExitOk;
}

}  // namespace

int RunStaticCommand(const CommandOptions& options) { return RunAnalyses(options, {.static_analysis = true}, "static"); }
int RunModesCommand(const CommandOptions& options) { return RunAnalyses(options, {.modes = true}, "modes"); }
int RunBucklingCommand(const CommandOptions& options) { return RunAnalyses(options, {.buckling = true}, "buckling"); }
int RunVibrationCommand(const CommandOptions& options) { return RunAnalyses(options, {.vibration = true}, "vibration"); }
int RunTransientCommand(const CommandOptions& options) { return RunAnalyses(options, {.transient = true}, "transient"); }

int RunCaseCommand(const CommandOptions& options) {
  const io::Case c = io::ReadCase(options.case_path);
  const auto& a = c.analyses;
  if (!a.static_analysis && !a.modes && !a.buckling && !a.vibration && !a.transient) {
    throw InputError({c.file, 0, 0}, "analyses", "the case lists no analyses to run");
  }
  return RunAnalyses(options, {a.static_analysis.has_value(), a.modes.has_value(), a.buckling.has_value(),
                               a.vibration.has_value(), a.transient.has_value()},
                     "run");
}

}  // namespace drillflex::app
