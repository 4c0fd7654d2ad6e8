// The second generator of randomized static cases (issue 19): the BHAs a directional driller runs,
// with distributions of their own. Each case draws
//   - a well: vertical (0–2°, straight), build and hold, build and drop, or a turn at constant
//     inclination (a quarter each), DLS 1–8°/100 ft, kick-off 1000–4000 ft;
//   - a hole from the standard bit sizes, 6-1/8 to 17-1/2 in, and collars of the size run in it;
//   - a BHA: a steerable mud motor with a bent housing (0.5–2.5°, any toolface, the bend 4–8 ft
//     above the bit, a sleeve stabilizer on the motor half the time), a packed, a pendulum or a
//     slick BHA (a quarter each), an MWD and collars, 100–300 m of HWDP or drill pipe above;
//   - mud 8.6–16 ppg, WOB 0–45 klbf, rotating at 40–180 rpm with torque on bit, or not (half each).
// Field units. Case i is drawn from its own std::mt19937 seeded with kBhaSeed + i (the draws written
// out as in validation/robustness_cases.hpp, so the cases are the same everywhere).
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "robustness_cases.hpp"

namespace drillflex::validation {

inline constexpr std::uint32_t kBhaSeed = 20261204;

enum class WellShape { kVertical, kBuildAndHold, kBuildAndDrop, kTurn };
enum class BhaKind { kMotor, kPacked, kPendulum, kSlick };

inline const char* WellShapeName(WellShape shape) {
  switch (shape) {
    case WellShape::kVertical: return "vertical";
    case WellShape::kBuildAndHold: return "build-hold";
    case WellShape::kBuildAndDrop: return "build-drop";
    case WellShape::kTurn: return "turn";
  }
  return "?";
}

inline const char* BhaKindName(BhaKind kind) {
  switch (kind) {
    case BhaKind::kMotor: return "motor";
    case BhaKind::kPacked: return "packed";
    case BhaKind::kPendulum: return "pendulum";
    case BhaKind::kSlick: return "slick";
  }
  return "?";
}

struct BhaCase {
  int index = 0;
  WellShape shape = WellShape::kVertical;
  BhaKind kind = BhaKind::kSlick;
  double inclination_deg = 0.0;  // at the bit
  double dls_deg_per_100ft = 0.0, hole_in = 0.0, collar_od_in = 0.0, collar_id_in = 0.0;
  double bend_deg = 0.0, toolface_deg = 0.0;
  double wob_klbf = 0.0, rpm = 0.0, torque_ftlbf = 0.0, mud_ppg = 0.0;
  double bit_md_ft = 0.0, bha_length_ft = 0.0, string_length_ft = 0.0;
  std::vector<Station> survey;
  std::vector<std::string> string;  // `string:` entries
};

// Collars run in each standard hole size (OD, in): drilling practice's usual pairs.
inline double CollarFor(double hole_in) {
  if (hole_in < 7.0) return 4.75;
  if (hole_in < 9.0) return 6.5;
  if (hole_in < 11.0) return 7.0;
  if (hole_in < 13.0) return 8.0;
  if (hole_in < 16.0) return 9.5;
  return 11.0;
}

inline void DrawBhaWell(std::mt19937& random, BhaCase& c) {
  c.shape = static_cast<WellShape>(UniformInt(random, 0, 3));
  const double kop = Uniform(random, 1000.0, 4000.0);
  c.dls_deg_per_100ft = Uniform(random, 1.0, 8.0);
  const double azimuth = Uniform(random, 0.0, 360.0);
  c.survey = {{0.0, 0.0, 0.0}};
  switch (c.shape) {
    case WellShape::kVertical: {
      // A nearly vertical hole: a straight line at 0–2° from the surface.
      c.inclination_deg = Uniform(random, 0.0, 2.0);
      c.survey.push_back({kop + 3000.0, c.inclination_deg, azimuth});
      c.survey[0].inclination_deg = c.inclination_deg;
      c.survey[0].azimuth_deg = azimuth;
      c.bit_md_ft = kop + Uniform(random, 1500.0, 2800.0);
      return;
    }
    case WellShape::kBuildAndHold: {
      c.survey.push_back({kop, 0.0, azimuth});
      c.inclination_deg = Uniform(random, 5.0, 95.0);
      AppendCurve(c.survey, c.inclination_deg, azimuth, c.dls_deg_per_100ft);
      break;
    }
    case WellShape::kBuildAndDrop: {
      c.survey.push_back({kop, 0.0, azimuth});
      const double top = Uniform(random, 20.0, 60.0);
      AppendCurve(c.survey, top, azimuth, c.dls_deg_per_100ft);
      Station hold = c.survey.back();
      hold.md_ft += Uniform(random, 200.0, 1000.0);
      c.survey.push_back(hold);
      c.inclination_deg = top * Uniform(random, 0.0, 0.7);
      AppendCurve(c.survey, c.inclination_deg, azimuth, c.dls_deg_per_100ft);
      break;
    }
    case WellShape::kTurn: {
      c.survey.push_back({kop, 0.0, azimuth});
      c.inclination_deg = Uniform(random, 20.0, 90.0);
      AppendCurve(c.survey, c.inclination_deg, azimuth, 4.0);
      AppendCurve(c.survey, c.inclination_deg, azimuth + Uniform(random, -90.0, 90.0), c.dls_deg_per_100ft);
      break;
    }
  }
  const double curve_end = c.survey.back().md_ft;
  Station hold = c.survey.back();
  hold.md_ft += 1000.0;
  c.survey.push_back(hold);
  // The bit in the last curve or up to 800 ft into the hold after it.
  c.bit_md_ft = Uniform(random, 0.5 * (kop + curve_end), curve_end + 800.0);
}

inline std::string BhaCollar(const BhaCase& c, double length_ft, const char* type = "collar") {
  return fmt::format("{{type: {}, od: {:.4f}, id: {:.4f}, length: {:.3f}}}", type, c.collar_od_in, c.collar_id_in,
                     length_ft);
}

inline std::string BhaStabilizer(const BhaCase& c, double blade_od_in) {
  return fmt::format("{{type: stabilizer, od: {:.4f}, id: {:.4f}, length: 5.0, blade_od: {:.4f}, blade_length: 1.5}}",
                     c.collar_od_in, c.collar_id_in, blade_od_in);
}

inline void DrawBhaString(std::mt19937& random, BhaCase& c) {
  static constexpr double kHoles[] = {6.125, 8.5, 8.75, 9.875, 12.25, 14.75, 17.5};
  c.hole_in = kHoles[UniformInt(random, 0, 6)];
  c.collar_od_in = CollarFor(c.hole_in);
  c.collar_id_in = c.collar_od_in * Uniform(random, 0.3, 0.42);
  c.kind = static_cast<BhaKind>(UniformInt(random, 0, 3));
  const double under_gauge = Uniform(random, 0.0625, 0.25);
  const double blade = c.hole_in - under_gauge;
  c.string.push_back(fmt::format("{{type: bit, od: {:.4f}, length: 1.0}}", c.hole_in));
  double length = 1.0;
  switch (c.kind) {
    case BhaKind::kMotor: {
      const double motor_ft = Uniform(random, 20.0, 30.0);
      c.bend_deg = Uniform(random, 0.5, 2.5);
      c.toolface_deg = Uniform(random, 0.0, 360.0);
      const double bend_ft = Uniform(random, 4.0, 8.0);
      const bool sleeve = Uniform(random, 0.0, 1.0) < 0.5;
      std::string motor = fmt::format("{{type: motor, od: {:.4f}, id: {:.4f}, length: {:.3f}, bend: {:.3f}, "
                                      "bend_to_bit: {:.3f}, toolface: {:.2f}",
                                      c.collar_od_in, 0.4 * c.collar_od_in, motor_ft, c.bend_deg, bend_ft,
                                      c.toolface_deg);
      if (sleeve) motor += fmt::format(", blade_od: {:.4f}, blade_length: 1.5", blade - 0.125);
      c.string.push_back(motor + "}");
      length += motor_ft;
      c.string.push_back(BhaStabilizer(c, blade));
      length += 5.0;
      break;
    }
    case BhaKind::kPacked: {
      c.string.push_back(BhaStabilizer(c, blade));
      const double first = Uniform(random, 8.0, 15.0);
      c.string.push_back(BhaCollar(c, first));
      c.string.push_back(BhaStabilizer(c, blade));
      const double second = Uniform(random, 20.0, 30.0);
      c.string.push_back(BhaCollar(c, second));
      c.string.push_back(BhaStabilizer(c, blade));
      length += 15.0 + first + second;
      break;
    }
    case BhaKind::kPendulum: {
      const double below = Uniform(random, 30.0, 90.0);
      c.string.push_back(BhaCollar(c, below));
      c.string.push_back(BhaStabilizer(c, blade));
      length += below + 5.0;
      break;
    }
    case BhaKind::kSlick:
      break;
  }
  c.string.push_back(BhaCollar(c, 30.0, "mwd"));
  const double collars = Uniform(random, 30.0, 120.0);
  c.string.push_back(BhaCollar(c, collars));
  length += 30.0 + collars;
  c.bha_length_ft = length;
  const bool hwdp = Uniform(random, 0.0, 1.0) < 0.5;
  const PipeSize pipe = PipeFor(c.hole_in, hwdp);
  const double pipe_m = Uniform(random, 100.0, 300.0);
  c.string.push_back(fmt::format("{{type: {}, name: \"{}\", od: {}, id: {}, length: \"{:.2f} m\", joint_od: {}, "
                                 "joint_id: {}}}",
                                 hwdp ? "hwdp" : "pipe", pipe.name, pipe.od, pipe.id, pipe_m, pipe.joint_od,
                                 pipe.joint_id));
  c.string_length_ft = length + pipe_m / 0.3048;
}

inline void DrawBhaOperation(std::mt19937& random, BhaCase& c) {
  c.mud_ppg = Uniform(random, 8.6, 16.0);
  c.wob_klbf = Uniform(random, 0.0, 45.0);
  const bool rotating = Uniform(random, 0.0, 1.0) < 0.5;
  c.rpm = rotating ? Uniform(random, 40.0, 180.0) : 0.0;
  // Torque on bit up to ~1.2 ft·lbf per lbf of WOB per inch of bit (a PDC bit's specific torque).
  c.torque_ftlbf = rotating ? Uniform(random, 0.0, 1.0) * 1.2 * c.wob_klbf * c.hole_in * 1000.0 / 12.0 : 0.0;
}

inline BhaCase MakeBhaCase(int index) {
  std::mt19937 random(kBhaSeed + static_cast<std::uint32_t>(index));
  BhaCase c;
  c.index = index;
  DrawBhaWell(random, c);
  DrawBhaString(random, c);
  DrawBhaOperation(random, c);
  // The string stays below the surface.
  if (c.bit_md_ft < c.string_length_ft + 300.0) c.bit_md_ft = c.string_length_ft + 300.0;
  if (c.survey.back().md_ft < c.bit_md_ft + 100.0) {
    Station end = c.survey.back();
    end.md_ft = c.bit_md_ft + 100.0;
    c.survey.push_back(end);
  }
  return c;
}

inline std::string ToYaml(const BhaCase& c) {
  std::string text = fmt::format(
      "# Robustness case B{} (validation/robustness_test.cpp, second generator): seed {} + {}. {} well, {} BHA,\n"
      "# {:.2f} deg at the bit, DLS {:.2f} deg/100 ft, {} in hole, WOB {:.2f} klbf, {:.0f} rpm{}.\n"
      "name: robustness-b{:03d}\nunits: field\n\nwell:\n  survey:\n",
      c.index, kBhaSeed, c.index, WellShapeName(c.shape), BhaKindName(c.kind), c.inclination_deg,
      c.dls_deg_per_100ft, c.hole_in, c.wob_klbf, c.rpm,
      c.kind == BhaKind::kMotor ? fmt::format(", bend {:.2f} deg at toolface {:.0f} deg", c.bend_deg, c.toolface_deg)
                                : std::string(),
      c.index);
  text.append(WellAndStringYaml(c.survey, c.hole_in, c.bit_md_ft, c.mud_ppg, c.string));
  text.append(fmt::format("\noperation: {{wob: {:.3f}, rpm: {:.1f}, torque_on_bit: {:.1f}}}\n\nanalyses:\n  static: {{}}\n",
                          c.wob_klbf, c.rpm, c.torque_ftlbf));
  return text;
}

}  // namespace drillflex::validation
