// Field units in SI, exactly, for the tests that check a formula as its source writes it (in, lbf, psi).
#pragma once

namespace drillflex::model::test {

inline constexpr double kInch = 0.0254;                          // m
inline constexpr double kPoundForce = 4.4482216152605;           // N
inline constexpr double kPsi = kPoundForce / (kInch * kInch);    // Pa
inline constexpr double kFootPound = kPoundForce * 0.3048;       // N·m
inline constexpr double kPi = 3.14159265358979323846;

}  // namespace drillflex::model::test
