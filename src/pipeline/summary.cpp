#include "pipeline/summary.hpp"

#include <algorithm>
#include <array>

#include <cmath>

#include <fmt/format.h>

#include "analyses/bit_tendency.hpp"
#include "analyses/string_limits.hpp"
#include "io/analysis_results.hpp"

namespace drillflex::pipeline {

using units::Quantity;

namespace {

// "bit 3×", "imbalance 1×", "motor 5 lobes": what drives a critical RPM.
std::string ExcitationName(const io::Case& c, Index index) {
  if (!c.analyses.vibration || index < 0 || index >= std::ssize(c.analyses.vibration->excitations)) return "?";
  return analyses::ExcitationName(c.analyses.vibration->excitations[index]);
}

// The critical RPMs most severe first (at most kListed; the rest by RPM on one line).
void WriteCriticalSpeeds(std::ostream& out, const io::Case& c, const analyses::VibrationResult& result) {
  constexpr std::size_t kListed = 8;
  if (result.critical_speeds.empty()) {
    out << "  critical RPMs: none in the sweep\n";
    return;
  }
  const bool ratio = !result.max_clearance_ratio.empty();
  out << fmt::format("  critical RPMs, most severe first ({}):\n",
                           ratio ? "lateral amplitude / radial clearance" : "lateral amplitude");
  for (std::size_t k = 0; k < result.critical_speeds.size() && k < kListed; ++k) {
    const analyses::CriticalSpeed& critical = result.critical_speeds[k];
    const std::string severity = ratio ? fmt::format("{:.3g} of the clearance, ", critical.severity) : "";
    out << fmt::format("    {}: {}largest amplitude {}, bending {}; {} at {:.3g} Hz\n",
                             Show(c, critical.rotary_speed, Quantity::RotarySpeed), severity,
                             Show(c, critical.displacement, Quantity::Diameter),
                             Show(c, critical.bending_stress, Quantity::Stress), ExcitationName(c, critical.excitation),
                             critical.frequency / (2.0 * kPi));
  }
  if (result.critical_speeds.size() > kListed) {
    std::vector<double> rest;
    for (std::size_t k = kListed; k < result.critical_speeds.size(); ++k) rest.push_back(result.critical_speeds[k].rotary_speed);
    std::sort(rest.begin(), rest.end());
    std::string list;
    for (const double rpm : rest) list += (list.empty() ? "" : ", ") + Show(c, rpm, Quantity::RotarySpeed);
    out << fmt::format("    {} milder peaks: {}\n", rest.size(), list);
  }
}

// The string's limits (analyses/string_limits.hpp): each limit's largest utilisation and where, the
// closest, the buckled zones and the assumptions.
template <typename Where>
void WriteStaticLimits(std::ostream& out, const io::Case& c, const analyses::StaticResult& result, const Where& where) {
  const analyses::StringLimits limits = analyses::ComputeStringLimits(c.input, result.nodes, c.limits.design_factor);
  auto line = [&](const char* label, const analyses::LimitUtilisation& limit) {
    if (limit.component < 0) return fmt::format("{} -", label);
    return fmt::format("{} {:.3g} at {} ({})", label, limit.utilisation, where(limit.s, limit.md),
                       c.input.string.components.at(limit.component).name);
  };
  out << fmt::format("  limits (design factor {:.3g}), utilisation = load / limit:\n", limits.design_factor);
  out << "    " << line("yield (von Mises / (yield / design factor))", limits.yield) << "\n";
  out << "    " << line("make-up torque", limits.makeup_torque) << "\n";
  out << "    " << line("helical buckling (compression / F_hel)", limits.helical_buckling) << "\n";
  if (std::isfinite(limits.fatigue.utilisation)) {
    out << "    " << line("fatigue (bending stress / RP 7G endurance limit)", limits.fatigue) << "\n";
  }
  if (limits.closest.component >= 0) {
    out << fmt::format("    closest: {} {:.3g}{}\n", limits.closest.limit, limits.closest.utilisation,
                       limits.closest.utilisation >= 1.0 ? "  ** BEYOND THE LIMIT **" : "");
  }
  for (const analyses::BuckledZone& zone : limits.zones) {
    out << fmt::format("    buckled {}: MD {} to {}\n", analyses::BucklingStateName(zone.state),
                       Show(c, zone.md_from, Quantity::Length), Show(c, zone.md_to, Quantity::Length));
  }
  for (const std::string& note : limits.notes) out << "    note: " << note << "\n";
}

}  // namespace

std::string Show(const io::Case& c, double si, Quantity quantity, int digits) {
  const double value = units::FromSI(si, quantity, c.units);
  const std::string text = fmt::format("{:.{}g}", value + 0.0, digits);
  return (text == "-0" ? std::string("0") : text) + " " + std::string(units::DefaultUnit(quantity, c.units));
}

void WriteStatic(std::ostream& out, const io::Case& c, const analyses::StaticResult& result) {
  out << fmt::format("static: converged ({}) in {} iterations (|R| = {:.3g} N){}\n", result.method,
                           result.iterations, result.residual_norm, result.stable ? ", stable" : "");
  for (const std::string& warning : result.warnings) out << "  warning: " << warning << "\n";
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
    out << fmt::format("  largest lateral displacement {} at {}\n",
                             Show(c, widest->lateral_offset, Quantity::Diameter), where(widest->s, md_of(*widest)));
    out << fmt::format("  peak von Mises stress {} at {} (bending {}, axial force {})\n",
                             Show(c, stressed->von_mises_stress, Quantity::Stress),
                             where(stressed->s, md_of(*stressed)),
                             Show(c, stressed->bending_stress, Quantity::Stress),
                             Show(c, stressed->axial_force, Quantity::Force));
  }
  WriteStaticLimits(out, c, result, where);
  if (c.well) {
    if (result.contacts.empty()) {
      out << "  no wall contact carries force\n";
    } else {
      const auto largest =
          std::max_element(result.contacts.begin(), result.contacts.end(),
                           [](const auto& a, const auto& b) { return a.normal_force < b.normal_force; });
      out << fmt::format("  {} wall contacts carry force; the largest {} at {} ({})\n", result.contacts.size(),
                               Show(c, largest->normal_force, Quantity::Force), where(largest->s, largest->md),
                               c.input.string.components.at(largest->component).name);
    }
  }
  if (tightest) {
    out << fmt::format("  smallest clearance to the wall {} at {}{}\n",
                             Show(c, tightest->clearance, Quantity::Diameter), where(tightest->s, tightest->md),
                             tightest->clearance < 0.0 ? " (negative: into the wall, normal force / contact stiffness)"
                                                       : "");
  }
  if (result.bit) {
    const auto& bit = *result.bit;
    const analyses::BitTendency tendency = analyses::ClassifyBitTendency(bit);
    out << fmt::format("  bit: side force {}: {} (build force {}), walk {} (walk force {}); tilt {:.4g} deg; "
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
    out << fmt::format("  support at {}{}: force along the string (up-hole) {}, {} {}, {} {}\n",
                             Show(c, reaction.s, Quantity::Length), name, Show(c, reaction.force.x(), Quantity::Force),
                             lateral_y, Show(c, reaction.force.y(), Quantity::Force), lateral_z,
                             Show(c, reaction.force.z(), Quantity::Force));
  }
  if (result.mwd) {
    const analyses::MwdSag& mwd = *result.mwd;
    out << fmt::format("  MWD sensor at {} from the bit: its axis at {} inclination, the hole at {}: sag {} (subtract it "
                       "from the survey's inclination)\n",
                       Show(c, mwd.s, Quantity::Length), Show(c, mwd.axis_inclination, Quantity::Angle, 6),
                       Show(c, mwd.hole_inclination, Quantity::Angle, 6), Show(c, mwd.sag, Quantity::Angle, 3));
  }
  if (result.pipe_above) {
    const analyses::PipeAboveReaction& pipe = *result.pipe_above;
    if (pipe.buckled) {
      out << fmt::format("  the pipe above the top: compressed beyond its sinusoidal load ({} of tension at rest): "
                         "it lies buckled and holds nothing\n",
                         Show(c, pipe.tension, Quantity::Force));
    } else {
      out << fmt::format("  the pipe above the top ({} of tension at rest) holds it with {} {}, {} {}; moment {} {}, "
                         "{} {}\n",
                         Show(c, pipe.tension, Quantity::Force), lateral_y, Show(c, pipe.force.y(), Quantity::Force),
                         lateral_z, Show(c, pipe.force.z(), Quantity::Force), lateral_y,
                         Show(c, pipe.moment.y(), Quantity::Moment), lateral_z, Show(c, pipe.moment.z(), Quantity::Moment));
    }
  }
}

void WriteModes(std::ostream& out, const analyses::ModesResult& result) {
  out << fmt::format("modes: {} computed", result.modes.size());
  if (result.gyroscopic) {
    out << fmt::format(" spinning at {:.5g} rpm (gyroscopic, on {} undamped modes)", result.rotary_speed * 30.0 / kPi,
                             result.basis_size);
  }
  if (result.near_zero_modes > 0) {
    out << fmt::format("; {} near zero (below {} Hz: no critical speed)", result.near_zero_modes,
                             analyses::kNearZeroFrequencyHz);
  }
  if (result.negative_stiffness_modes > 0) {
    out << fmt::format("; {} with ω² < 0 (negative stiffness: not vibration modes)", result.negative_stiffness_modes);
  }
  out << "\n";
  out << fmt::format("  {:>4} {:>12} {:>9}  {:<10} {:>6} {:>6} {:>6}\n", "#", "f (Hz)", "damping", "kind", "axial",
                           "tors", "lat");
  for (std::size_t m = 0; m < result.modes.size(); ++m) {
    const auto& mode = result.modes[m];
    out << fmt::format("  {:>4} {:>12.6g} {:>9.3g}  {:<10} {:>6.3f} {:>6.3f} {:>6.3f}{}\n", m + 1,
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
void WriteCampbell(std::ostream& out, const analyses::CampbellResult& result) {
  if (result.points.empty()) return;
  out << fmt::format("Campbell diagram: {} speeds, {:.5g} to {:.5g} rpm (campbell.csv)\n", result.points.size(),
                           result.points.front().rotary_speed * 30.0 / kPi, result.points.back().rotary_speed * 30.0 / kPi);
  if (result.synchronous.empty()) {
    out << "  no branch crosses 1x in that range\n";
    return;
  }
  for (const analyses::CampbellCrossing& crossing : result.synchronous) {
    out << fmt::format("  mode {} crosses 1x at {:.5g} rpm ({:.4g} Hz, {} whirl)\n", crossing.branch + 1,
                             crossing.rotary_speed * 30.0 / kPi, crossing.frequency_hz, analyses::WhirlName(crossing.whirl));
  }
}

void WriteCriticalRpm(std::ostream& out, const io::Case& c, const analyses::ModesResult& result) {
  const io::RuleOfThumbSpeed rule = io::ComputeRuleOfThumbCriticalSpeed(c);
  if (const analyses::ModeResult* mode = analyses::FirstLateralMode(result)) {
    out << fmt::format("  critical RPM of the first lateral mode {:.5g} rpm; rule of thumb 33055 sqrt(OD²+ID²)/L² "
                             "{:.5g} rpm (span {}, ±15 %)\n",
                             60.0 * mode->frequency_hz, rule.rotary_speed * 30.0 / kPi, Show(c, rule.span, Quantity::Length));
    return;
  }
  out << fmt::format("  rule-of-thumb critical RPM 33055 sqrt(OD²+ID²)/L² {:.5g} rpm (span {})\n",
                           rule.rotary_speed * 30.0 / kPi, Show(c, rule.span, Quantity::Length));
}



void WriteVibration(std::ostream& out, const io::Case& c, const analyses::VibrationResult& result) {
  out << fmt::format("vibration: {} rotary speeds, {} to {}; {} wall contacts closed at equilibrium\n",
                           result.rotary_speeds.size(), Show(c, result.rotary_speeds.front(), Quantity::RotarySpeed),
                           Show(c, result.rotary_speeds.back(), Quantity::RotarySpeed), result.closed_contacts);
  if (result.method == analyses::VibrationMethod::Reduced) {
    out << fmt::format("  solved on a reduced basis of {} vectors (method: direct for the full system)\n",
                             result.basis_size);
  } else {
    out << "  solved on the full system (a sparse LU per frequency)"
              << (result.method_note.empty() ? "" : ": " + result.method_note) << "\n";
  }
  const auto peak = std::max_element(result.max_lateral_displacement.begin(), result.max_lateral_displacement.end());
  const Index i = peak - result.max_lateral_displacement.begin();
  out << fmt::format("  largest lateral displacement amplitude {} at {} ({} from the bit)\n",
                           Show(c, *peak, Quantity::Diameter), Show(c, result.rotary_speeds[i], Quantity::RotarySpeed),
                           Show(c, result.s_max_displacement[i], Quantity::Length));
  WriteCriticalSpeeds(out, c, result);
  std::string windows;
  for (const auto& w : result.safe_windows) {
    windows += (windows.empty() ? "" : ", ") + fmt::format("{} to {}", Show(c, w.from, Quantity::RotarySpeed),
                                                           Show(c, w.to, Quantity::RotarySpeed));
  }
  out << fmt::format("  safe windows (displacement below {:.3g} of the clearance, bending-stress amplitude "
                           "below {}): {}\n",
                           result.clearance_fraction, Show(c, result.stress_limit, Quantity::Stress),
                           windows.empty() ? "none" : windows);
  std::string quiet;
  for (const auto& w : result.quietest_windows) {
    quiet += (quiet.empty() ? "" : ", ") + fmt::format("{} to {}", Show(c, w.from, Quantity::RotarySpeed),
                                                       Show(c, w.to, Quantity::RotarySpeed));
  }
  out << fmt::format("  quietest ranges (within {}× of the sweep's least {}): {}\n", analyses::kQuietFactor,
                           result.max_clearance_ratio.empty() ? "amplitude" : "clearance ratio", quiet);
}

void WriteBuckling(std::ostream& out, const io::Case& c, const analyses::BucklingResult& result) {
  const std::string scaled = result.scaled_wob ? "the WOB" : "every load";
  const std::string how = result.about_equilibrium ? "the lowest lateral frequency about the equilibrium reaches 0"
                                                   : "eigenproblem";
  if (result.lower_bound) {
    const auto& table = result.frequency_table;
    out << fmt::format("buckling: no onset up to {} × {:g} (largest compression {}): the lowest lateral frequency rises "
                       "with the load, {:.4g} Hz at × 1 to {:.4g} Hz at × {:g}, every equilibrium stable ({})\n",
                       scaled, result.load_factor, Show(c, result.critical_load, Quantity::Force, 6),
                       table.front().frequency_hz, table.back().frequency_hz, result.load_factor,
                       result.critical_load > 0.0 ? "the compression presses the string onto the wall"
                                                  : "the loads put no part of the string in compression");
    if (result.critical_wob > 0.0) {
      out << fmt::format("  no buckling below a WOB of {}\n", Show(c, result.critical_wob, Quantity::Force, 6));
    }
  } else {
    out << fmt::format("buckling: {} × {:.6g} buckles the string, largest compression {} ({})\n", scaled,
                       result.load_factor, Show(c, result.critical_load, Quantity::Force, 6), how);
    if (result.critical_wob > 0.0) out << fmt::format("  critical WOB {}\n", Show(c, result.critical_wob, Quantity::Force, 6));
    if (result.onset_above_model) {
      out << "  the pipe above the modelled string buckles first: its compression at the model's top reaches "
             "Dawson-Paslay's sinusoidal load there, the modelled string standing\n";
    }
    if (result.buckled_at_case_loads) {
      out << fmt::format("  the string lies buckled at the case's loads: the onset was searched below them, from {} × "
                         "{:.3g}\n",
                         scaled, result.frequency_table.empty() ? 0.0 : result.frequency_table.front().load_factor);
    }
  }
  if (result.sinusoidal.computed) {
    const analyses::SinusoidalBucklingScreen& screen = result.sinusoidal;
    const std::string where = fmt::format("MD {}", Show(c, screen.md, Quantity::Length));
    if (screen.sinusoidal_load == 0.0) {
      out << fmt::format("  Dawson-Paslay: at {} the hole is vertical and the string compressed ({}): no weight "
                               "holds it to the wall (Lubinski's case)\n",
                               where, Show(c, screen.compression, Quantity::Force));
    } else if (screen.load_factor < 1.0) {
      out << fmt::format("  Dawson-Paslay: the compression {} at {} is {:.3g} times the sinusoidal buckling load "
                               "{} (helical {}): the string lies buckled there at the case's loads\n",
                               Show(c, screen.compression, Quantity::Force), where, screen.compression / screen.sinusoidal_load,
                               Show(c, screen.sinusoidal_load, Quantity::Force), Show(c, screen.helical_load, Quantity::Force));
    } else {
      out << fmt::format("  Dawson-Paslay: sinusoidal buckling first at {} × {:.4g}, at {} (compression "
                               "{} against {} now)\n",
                               scaled, screen.load_factor, where, Show(c, screen.compression, Quantity::Force),
                               Show(c, screen.sinusoidal_load, Quantity::Force));
    }
  }
  if (!result.about_equilibrium && result.frequency_method_converged) {
    out << fmt::format("  from the lowest frequency against load: multiplier {:.6g}, compression {}\n",
                             result.frequency_load_factor, Show(c, result.frequency_critical_load, Quantity::Force, 6));
  } else if (!result.frequency_method_converged && !result.lower_bound) {
    out << "  warning: the frequency extrapolation did not settle (samples in buckling.csv)\n";
  }
}

void WriteTransient(std::ostream& out, const io::Case& c, const analyses::TransientResult& result, bool driven, bool block) {
  const auto& stats = result.statistics;
  out << fmt::format("transient: {} s in {} steps ({} rejected), {} Newton iterations, {} factorizations; "
                           "steps {:.3g} to {:.3g} s\n",
                           result.samples.back().time, stats.steps, stats.error_rejections + stats.newton_failures,
                           stats.newton_iterations, stats.factorizations, stats.smallest_step, stats.largest_step);
  // The energy's change says something only about a string left to itself: a driven one gains the
  // drives' work, which is not summed, so no balance is printed for it.
  if (!driven) {
    out << fmt::format("  energy: largest change {:.3g} of the largest kinetic energy (damping, friction and the "
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
  out << fmt::format("  at the end: surface {}, bit {}, {}, WOB {}\n", Show(c, last.surface_speed, Quantity::RotarySpeed),
                           Show(c, last.bit_speed, Quantity::RotarySpeed), top,
                           Show(c, last.weight_on_bit, Quantity::WeightOnBit));
}

void WriteTendency(std::ostream& out, const io::Case& c, const analyses::TendencyResult& result) {
  const analyses::TendencyPoint& steady = result.trace.at(result.steady_index);
  const bool point = c.analyses.tendency && c.analyses.tendency->rss &&
                     c.analyses.tendency->rss->type == analyses::RssType::Point;
  out << fmt::format("tendency: builds {} and turns {} (dogleg {}) at inclination {}, azimuth {}; steerability {:g}, "
                     "WOB {} ({} statics)\n",
                     Show(c, result.build_rate, Quantity::DoglegSeverity, 4),
                     Show(c, result.turn_rate, Quantity::DoglegSeverity, 4),
                     Show(c, result.dogleg_severity, Quantity::DoglegSeverity, 4),
                     Show(c, result.inclination, Quantity::Angle, 4), Show(c, result.azimuth, Quantity::Angle, 4),
                     result.steerability, Show(c, result.weight_on_bit, Quantity::WeightOnBit), result.statics);
  if (result.toolfaces > 1) {
    out << fmt::format("  the bent motor rotating: the bit's deviation averaged over its bend at {} toolfaces\n",
                       result.toolfaces);
  }
  out << fmt::format("  bit at the steady curvature: side force {} (build {}, walk {}), tilt {} toward the high side, "
                     "{} toward the right\n",
                     Show(c, steady.bit.side_force, Quantity::Force), Show(c, steady.bit.build_force, Quantity::Force),
                     Show(c, steady.bit.walk_force, Quantity::Force), Show(c, steady.bit.tilt, Quantity::Angle, 4),
                     Show(c, steady.bit.tilt_right, Quantity::Angle, 4));
  if (result.steering) {
    const analyses::SteeringRates& steering = *result.steering;
    out << fmt::format("  {}-the-bit rotary steerable at {:g} % steer: natural tendency {} build, {} right; full steer {} build, {} "
                       "right; per unit of steer {} build, {} right (curvatures)\n",
                       point ? "point" : "push", 100.0 * steering.steer, Show(c, steering.natural.build, Quantity::DoglegSeverity, 4),
                       Show(c, steering.natural.right, Quantity::DoglegSeverity, 4),
                       Show(c, steering.full.build, Quantity::DoglegSeverity, 4),
                       Show(c, steering.full.right, Quantity::DoglegSeverity, 4),
                       Show(c, steering.full.build - steering.natural.build, Quantity::DoglegSeverity, 4),
                       Show(c, steering.full.right - steering.natural.right, Quantity::DoglegSeverity, 4));
  }
  if (result.three_point) {
    const analyses::ThreePointYield& yield = *result.three_point;
    // A point-the-bit system's bend is its fulcrum (the yield at full steer).
    const char* bend = point ? "the fulcrum" : "the bend";
    const std::string pad = yield.pad < yield.bend ? fmt::format("the pad at {}, ", Show(c, yield.pad, Quantity::Length, 4)) : "";
    out << fmt::format("  three-point geometric yield {} toward toolface {} (bit, {}{} at {}, the blades at {}; "
                       "rigid, no clearance{})\n",
                       Show(c, yield.curvature, Quantity::DoglegSeverity, 4), Show(c, yield.toolface, Quantity::Angle, 4),
                       pad, bend, Show(c, yield.bend, Quantity::Length, 4), Show(c, yield.stabilizer, Quantity::Length, 4),
                       point ? "; full steer" : "");
  }
}

void WriteTransientLimits(std::ostream& out, const io::Case& c, const analyses::LimitsEnvelope& envelope) {
  if (envelope.times.empty()) return;
  out << fmt::format("  limits over {} samples (design factor {:.3g}), the largest utilisation = load / limit:\n",
                     envelope.times.size(), envelope.design_factor);
  constexpr std::array<const char*, analyses::kEnvelopeLimits> kWords{"yield", "make-up torque", "helical buckling",
                                                                      "fatigue"};
  for (std::size_t k = 0; k < analyses::kEnvelopeLimits; ++k) {
    const analyses::LimitUtilisation& limit = envelope.summary[k];
    if (limit.limit.empty()) continue;
    const std::string md = c.well ? fmt::format(" (MD {})", Show(c, limit.md, Quantity::Length)) : "";
    out << fmt::format("    {} {:.3g} at {} from the bit{} ({}), t = {}{}\n", kWords[k], limit.utilisation,
                       Show(c, limit.s, Quantity::Length), md,
                       c.input.string.components.at(limit.component).name,
                       Show(c, envelope.summary_time[k], Quantity::Time, 4),
                       limit.utilisation >= 1.0 ? "  ** BEYOND THE LIMIT **" : "");
  }
  const std::size_t closest = envelope.closest();
  if (closest < analyses::kEnvelopeLimits) {
    out << fmt::format("    closest: {} {:.3g}\n", kWords[closest], envelope.summary[closest].utilisation);
  }
}

void WriteSummary(std::ostream& out, const io::Case& c, Analysis analysis, const CaseResults& results) {
  switch (analysis) {
    case Analysis::Static:
      if (results.static_result) WriteStatic(out, c, *results.static_result);
      return;
    case Analysis::Modes:
      if (!results.modes) return;
      WriteModes(out, *results.modes);
      WriteCriticalRpm(out, c, *results.modes);
      if (results.campbell) WriteCampbell(out, *results.campbell);
      return;
    case Analysis::Vibration:
      if (results.vibration) WriteVibration(out, c, *results.vibration);
      return;
    case Analysis::Buckling:
      if (results.buckling) WriteBuckling(out, c, *results.buckling);
      return;
    case Analysis::Transient:
      if (results.transient && results.transient_setup) {
        const analyses::TransientSettings& settings = results.transient_setup->settings;
        const bool block = settings.block.has_value();
        const bool driven =
            block || settings.top_drive.has_value() || settings.bit_rock.has_value() || c.input.operation.rotary_speed != 0.0;
        WriteTransient(out, c, *results.transient, driven, block);
        if (results.transient_limits) WriteTransientLimits(out, c, *results.transient_limits);
      }
      return;
    case Analysis::Tendency:
      if (results.tendency) WriteTendency(out, c, *results.tendency);
      return;
  }
}

}  // namespace drillflex::pipeline
