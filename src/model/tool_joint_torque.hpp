// The torsional strength and recommended make-up torque of a rotary-shouldered tool joint from its
// connection's thread data and the joint's OD and pin ID (issue 37): API RP 7G's (16th ed., 1998,
// Appendix A, the "Farr equation"; Farr 1957) T = S A (P/(2π) + R_t f / cos θ + R_s f). SI throughout:
// the standard writes it in in, psi and ft·lbf (T = S A/12 (...)), the /12 only its inch-to-foot.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

namespace drillflex::model {

// A rotary-shouldered connection's thread data (API Spec 7-2, the numbered connections' table), m.
struct RotaryConnection {
  const char* name;         // "NC50"
  double pitch_diameter;    // C, the thread's pitch diameter at the gauge point (5/8 in from the shoulder)
  double taper;             // tpr, the change of diameter per length (2 in/ft: 1/6)
  double lead;              // P, the advance per turn (4 threads per inch: 0.25 in)
  double thread_height;     // H, the sharp-V thread's height
  double root_truncation;   // S_rs, the pin thread's root truncation
  double pin_length;        // L_pc, the pin's length
  double counterbore;       // Q_c, the box's counterbore diameter
};

// The numbered connections NC26, NC31, NC38, NC40, NC46 and NC50 (V-0.038R thread, 4 threads per inch,
// taper 2 in/ft): docs/case-format.md lists their data and where it was taken from.
const std::vector<RotaryConnection>& RotaryConnections();

// A numbered connection's common name: the older style cut on the same thread (API Spec 7-2's
// interchangeability of the numbered connections): the internal-flush (IF) connections 2-3/8 IF (NC26),
// 2-7/8 IF (NC31), 3-1/2 IF (NC38), 4 IF (NC46), 4-1/2 IF (NC50), and 4 FH (NC40).
struct ConnectionAlias {
  const char* name;      // "4-1/2 IF"
  const char* numbered;  // "NC50"
};
const std::vector<ConnectionAlias>& RotaryConnectionAliases();

// The connection named `name`, a numbered connection or its common name (case-insensitive, spaces and
// dashes ignored: "nc 50", "4-1/2 IF", "4 1/2 if"), or none.
std::optional<RotaryConnection> FindRotaryConnection(std::string_view name);

// RP 7G's tool-joint steel: a minimum yield of 120 ksi whatever the pipe's grade; the recommended
// make-up torque stresses the weaker of pin and box to 60 % of it (72 ksi); the thread compound's
// friction coefficient 0.08; half the thread's included angle 30°.
inline constexpr double kToolJointYield = 120.0 * 1000.0 * 4.4482216152605 / (0.0254 * 0.0254);  // Pa
inline constexpr double kMakeupStressFraction = 0.6;
inline constexpr double kThreadCompoundFriction = 0.08;

struct ConnectionStrength {
  double pin_area = 0.0;         // A_p, m²
  double box_area = 0.0;         // A_b, m²
  bool pin_weaker = true;        // A_p < A_b: the pin sets the strength
  double torsional_yield = 0.0;  // N·m, the weaker member at the joint's yield
  double makeup_torque = 0.0;    // N·m, the weaker member at 60 % of it
};

// The pin's thread root diameter C − B at its critical section, 3/4 in from the shoulder (1/8 in past the
// gauge point; RP 7G A.8 as its 2003 addendum puts the section): B = 2 (H/2 − S_rs) + tpr · 1/8 in, m. A pin
// bore must be smaller.
double PinThreadRoot(const RotaryConnection& connection);

// RP 7G's torsional strength of `connection` on a tool joint of outside diameter `joint_od` and pin
// bore `pin_id` (m), its steel's yield `joint_yield` (Pa):
//   A_p = π/4 ((C − B)² − ID²)   the pin 3/4 in from the shoulder, B = 2 (H/2 − S_rs) + tpr · 1/8 in
//   A_b = π/4 (OD² − (Q_c − E)²) the box, E = tpr · 3/8 in
//   R_t = (C + (C − tpr (L_pc − 5/8 in)))/4   the thread's mean radius over the pin
//   R_s = (OD + Q_c)/4                        the shoulder's mean radius
//   T = S min(A_p, A_b) (P/(2π) + R_t f / cos θ + R_s f)
// with S the joint's yield for the torsional strength and 60 % of it for the make-up torque. Throws
// LogicError for a joint OD not above the counterbore or a pin ID not below C − B.
ConnectionStrength ConnectionTorsionalStrength(const RotaryConnection& connection, double joint_od, double pin_id,
                                               double joint_yield = kToolJointYield);

}  // namespace drillflex::model
