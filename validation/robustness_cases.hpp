// Randomized static cases for the robustness test (issue 4): a well from the surface with a
// kick-off, a build and a build-and-turn section at one dog-leg severity and a hold; a bit, 1–3
// stabilizers among collars and HWDP or drill pipe above; a random WOB and torque on bit. Field
// units. Case i is drawn from its own std::mt19937 seeded with kRobustnessSeed + i, so any case can
// be regenerated alone. The uniform draws are written out here (not std::uniform_*_distribution,
// whose algorithms the standard leaves to the library) so the cases are the same everywhere.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>

namespace drillflex::validation {

inline constexpr std::uint32_t kRobustnessSeed = 20250404;
inline constexpr double kRadiansPerDegree = 0.017453292519943295;

// Uniform on [a, b): a + (b − a)·u with u = (32-bit draw) / 2³².
inline double Uniform(std::mt19937& random, double a, double b) {
  return a + (b - a) * (static_cast<double>(random()) / 4294967296.0);
}

// Uniform integer on [low, high] (modulo of a 32-bit draw; the bias is below 1e-9).
inline int UniformInt(std::mt19937& random, int low, int high) {
  return low + static_cast<int>(random() % static_cast<std::uint32_t>(high - low + 1));
}

struct Station {
  double md_ft, inclination_deg, azimuth_deg;
};

// Dog-leg angle between two survey stations (minimum curvature):
// cos β = cos I₁ cos I₂ + sin I₁ sin I₂ cos(A₂ − A₁).
inline double DoglegDeg(const Station& a, const Station& b) {
  const double i1 = a.inclination_deg * kRadiansPerDegree, i2 = b.inclination_deg * kRadiansPerDegree;
  const double da = (b.azimuth_deg - a.azimuth_deg) * kRadiansPerDegree;
  const double c = std::cos(i1) * std::cos(i2) + std::sin(i1) * std::sin(i2) * std::cos(da);
  return std::acos(std::clamp(c, -1.0, 1.0)) / kRadiansPerDegree;
}

struct PipeSize {
  const char* name;
  double od, id, joint_od, joint_id;  // in
};

struct StringItem {
  std::string yaml;  // one `string:` entry
};

struct RobustnessCase {
  int index = 0;
  // Drawn parameters.
  double kop_ft = 0, dls_deg_per_100ft = 0, build_inclination_deg = 0, final_inclination_deg = 0;
  double start_azimuth_deg = 0, turn_deg = 0, hold_ft = 0, bit_md_ft = 0;
  double hole_in = 0, clearance_in = 0, collar_od_in = 0, collar_id_in = 0, blade_under_gauge_in = 0;
  double bha_length_ft = 0, pipe_length_m = 0, wob_klbf = 0, torque_ftlbf = 0, mud_ppg = 0;
  int stabilizers = 0;
  bool near_bit_stabilizer = false, hwdp = false;
  std::vector<double> stabilizer_at_ft;  // bottom of each stabilizer, from the bit
  // Derived.
  std::vector<Station> survey;
  double max_dls_deg_per_100ft = 0;  // the largest β/ΔMD of the survey, °/100 ft
  double string_length_ft = 0;
  std::vector<StringItem> string;
};

// Appends stations from the last one to (inclination, azimuth) in steps of at most 2° of
// inclination or azimuth change, each step's MD length β·100/DLS (at least 1 ft) so that every
// step has the case's dog-leg severity.
inline void AppendCurve(std::vector<Station>& survey, double inclination_deg, double azimuth_deg, double dls) {
  const Station start = survey.back();
  const double span = std::max(std::abs(inclination_deg - start.inclination_deg), std::abs(azimuth_deg - start.azimuth_deg));
  const int steps = std::max(1, static_cast<int>(std::ceil(span / 2.0)));
  for (int k = 1; k <= steps; ++k) {
    const double t = static_cast<double>(k) / steps;
    Station next{0.0, start.inclination_deg + t * (inclination_deg - start.inclination_deg),
                 start.azimuth_deg + t * (azimuth_deg - start.azimuth_deg)};
    next.md_ft = survey.back().md_ft + std::max(DoglegDeg(survey.back(), next) * 100.0 / dls, 1.0);
    survey.push_back(next);
  }
}

// The pipe above the BHA, by hole size (API drill pipe and HWDP dimensions).
inline PipeSize PipeFor(double hole_in, bool hwdp) {
  if (hole_in < 7.5) return hwdp ? PipeSize{"3-1/2 in HWDP", 3.5, 2.0625, 4.75, 2.125} : PipeSize{"3-1/2 in drill pipe", 3.5, 2.764, 4.75, 2.125};
  if (hole_in < 11.0) return hwdp ? PipeSize{"5 in HWDP", 5.0, 3.0, 6.5, 3.0} : PipeSize{"5 in drill pipe", 5.0, 4.276, 6.625, 3.25};
  return hwdp ? PipeSize{"5-1/2 in HWDP", 5.5, 3.375, 7.0, 3.375} : PipeSize{"5-1/2 in drill pipe", 5.5, 4.778, 7.0, 4.0};
}

inline void DrawWell(std::mt19937& random, RobustnessCase& c) {
  c.kop_ft = Uniform(random, 1500.0, 4000.0);
  c.dls_deg_per_100ft = Uniform(random, 0.5, 10.0);
  c.final_inclination_deg = Uniform(random, 0.0, 100.0);
  c.build_inclination_deg = c.final_inclination_deg * Uniform(random, 0.3, 1.0);  // end of the pure build
  c.start_azimuth_deg = Uniform(random, 0.0, 360.0);
  c.turn_deg = Uniform(random, -90.0, 90.0);  // azimuth change of the build-and-turn section
  c.hold_ft = Uniform(random, 0.0, 1000.0);
  c.survey = {{0.0, 0.0, 0.0}, {c.kop_ft, 0.0, c.start_azimuth_deg}};
  AppendCurve(c.survey, c.build_inclination_deg, c.start_azimuth_deg, c.dls_deg_per_100ft);
  AppendCurve(c.survey, c.final_inclination_deg, c.start_azimuth_deg + c.turn_deg, c.dls_deg_per_100ft);
  const double curve_end = c.survey.back().md_ft;
  if (c.hold_ft > 1.0) {
    Station hold = c.survey.back();
    hold.md_ft += c.hold_ft;
    c.survey.push_back(hold);
  }
  // The bit from a quarter of the way into the curve to the end of the hold.
  c.bit_md_ft = Uniform(random, c.kop_ft + 0.25 * (curve_end - c.kop_ft), c.survey.back().md_ft);
  for (std::size_t k = 1; k < c.survey.size(); ++k) {
    const double dls = DoglegDeg(c.survey[k - 1], c.survey[k]) * 100.0 / (c.survey[k].md_ft - c.survey[k - 1].md_ft);
    c.max_dls_deg_per_100ft = std::max(c.max_dls_deg_per_100ft, dls);
  }
}

// Hole from the standard bit sizes; radial collar clearance log-uniform from 0.25 in to a quarter
// of the hole diameter (collar OD from hole − 0.5 in down to half the hole), so tight clearances
// are drawn as often per factor of clearance as wide ones.
inline void DrawHoleAndCollars(std::mt19937& random, RobustnessCase& c) {
  static constexpr double kHoles[] = {6.125, 8.5, 8.75, 9.875, 12.25, 14.75, 17.5};
  c.hole_in = kHoles[UniformInt(random, 0, 6)];
  c.clearance_in = 0.25 * std::pow(c.hole_in, Uniform(random, 0.0, 1.0));
  c.collar_od_in = c.hole_in - 2.0 * c.clearance_in;
  c.collar_id_in = c.collar_od_in * Uniform(random, 0.3, 0.45);
  c.blade_under_gauge_in = Uniform(random, 0.0625, 0.25);
}

inline std::string CollarYaml(const RobustnessCase& c, double length_ft) {
  return fmt::format("{{type: collar, od: {:.4f}, id: {:.4f}, length: {:.3f}}}", c.collar_od_in, c.collar_id_in,
                     length_ft);
}

// Bit (1 ft) + 1–3 stabilizers (5 ft, 1.5 ft blades) at random positions among collars, the
// BHA 60–150 ft long; half the cases have a near-bit stabilizer. The collar lengths between are
// shares (weights uniform on [0.2, 1]) of what the bit and stabilizers leave.
inline void DrawBha(std::mt19937& random, RobustnessCase& c) {
  constexpr double kBitFt = 1.0, kStabilizerFt = 5.0;
  c.bha_length_ft = Uniform(random, 60.0, 150.0);
  c.stabilizers = UniformInt(random, 1, 3);
  c.near_bit_stabilizer = Uniform(random, 0.0, 1.0) < 0.5;
  std::vector<double> weights(c.stabilizers + 1);
  for (double& w : weights) w = Uniform(random, 0.2, 1.0);
  if (c.near_bit_stabilizer) weights[0] = 0.0;
  double total = 0.0;
  for (double w : weights) total += w;
  const double collars_ft = c.bha_length_ft - kBitFt - kStabilizerFt * c.stabilizers;
  c.string.push_back({fmt::format("{{type: bit, od: {:.4f}, length: {:.1f}}}", c.hole_in, kBitFt)});
  double s = kBitFt;
  for (int k = 0; k <= c.stabilizers; ++k) {
    const double gap = collars_ft * weights[k] / total;
    if (gap > 0.0) c.string.push_back({CollarYaml(c, gap)});
    s += gap;
    if (k == c.stabilizers) break;
    c.stabilizer_at_ft.push_back(s);
    c.string.push_back({fmt::format("{{type: stabilizer, od: {:.4f}, id: {:.4f}, length: {:.1f}, blade_od: {:.4f}, "
                                    "blade_length: 1.5}}",
                                    c.collar_od_in, c.collar_id_in, kStabilizerFt, c.hole_in - c.blade_under_gauge_in)});
    s += kStabilizerFt;
  }
}

inline void DrawPipeAndOperation(std::mt19937& random, RobustnessCase& c) {
  c.hwdp = Uniform(random, 0.0, 1.0) < 0.5;
  c.pipe_length_m = Uniform(random, 100.0, 300.0);
  const PipeSize pipe = PipeFor(c.hole_in, c.hwdp);
  c.string.push_back({fmt::format("{{type: {}, name: \"{}\", od: {}, id: {}, length: \"{:.2f} m\", joint_od: {}, "
                                  "joint_id: {}}}",
                                  c.hwdp ? "hwdp" : "pipe", pipe.name, pipe.od, pipe.id, c.pipe_length_m,
                                  pipe.joint_od, pipe.joint_id)});
  c.string_length_ft = c.bha_length_ft + c.pipe_length_m / 0.3048;
  c.wob_klbf = Uniform(random, 0.0, 50.0);
  c.torque_ftlbf = Uniform(random, 0.0, 10000.0);
  c.mud_ppg = Uniform(random, 8.5, 14.0);
}

inline RobustnessCase MakeRobustnessCase(int index) {
  std::mt19937 random(kRobustnessSeed + static_cast<std::uint32_t>(index));
  RobustnessCase c;
  c.index = index;
  DrawWell(random, c);
  DrawHoleAndCollars(random, c);
  DrawBha(random, c);
  DrawPipeAndOperation(random, c);
  return c;
}

// The survey rows, the hole, the bit MD, the fluid and the string of a case file, after its `survey:`
// line (both generators write them so).
inline std::string WellAndStringYaml(const std::vector<Station>& survey, double hole_in, double bit_md_ft,
                                     double mud_ppg, const std::vector<std::string>& string) {
  std::string text;
  for (const Station& s : survey) {
    text.append(fmt::format("    - [{:.4f}, {:.4f}, {:.4f}]\n", s.md_ft, s.inclination_deg, s.azimuth_deg));
  }
  text.append(fmt::format("  hole: {}\n  bit_md: {:.3f}\n\nfluid: {{density: {:.3f}, viscosity: 20}}\n\nstring:\n",
                          hole_in, bit_md_ft, mud_ppg));
  for (const std::string& item : string) text.append("  - ").append(item).append("\n");
  return text;
}

inline std::string ToYaml(const RobustnessCase& c) {
  std::string text = fmt::format(
      "# Robustness case {} (validation/robustness_test.cpp): seed {} + {}. Inclination {:.2f} deg, DLS {:.2f} "
      "deg/100 ft,\n# radial collar clearance {:.3f} in, WOB {:.2f} klbf, {} stabilizer(s), {:.1f} ft BHA.\n"
      "name: robustness-{:03d}\nunits: field\n\nwell:\n  survey:\n",
      c.index, kRobustnessSeed, c.index, c.final_inclination_deg, c.dls_deg_per_100ft, c.clearance_in, c.wob_klbf,
      c.stabilizers, c.bha_length_ft, c.index);
  std::vector<std::string> items;
  for (const StringItem& item : c.string) items.push_back(item.yaml);
  text.append(WellAndStringYaml(c.survey, c.hole_in, c.bit_md_ft, c.mud_ppg, items));
  text.append(fmt::format("\noperation: {{wob: {:.3f}, rpm: 0, torque_on_bit: {:.1f}}}\n\nanalyses:\n  static: {{}}\n",
                          c.wob_klbf, c.torque_ftlbf));
  return text;
}

}  // namespace drillflex::validation
