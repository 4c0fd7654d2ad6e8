#include "model/tool_joint_torque.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace drillflex::model {
namespace {

constexpr double kInch = 0.0254;       // m
constexpr double kPi = 3.14159265358979323846;
// The V-0.038R thread (4 threads per inch, taper 2 in/ft): a 60° thread of sharp-V height H = 0.216005 in
// on the taper and a 0.038 in root radius, whose truncation (the radius's depth below the sharp V's root,
// r (1/sin 30° − 1)) is the radius itself.
constexpr double kTaper2InPerFoot = 2.0 / 12.0;
constexpr double kLead4Tpi = 0.25 * kInch;
constexpr double kHeightV038R = 0.216005 * kInch;
constexpr double kTruncationV038R = 0.038 * kInch;

RotaryConnection Numbered(const char* name, double pitch_diameter_in, double pin_length_in, double counterbore_in) {
  return {name,          pitch_diameter_in * kInch, kTaper2InPerFoot,   kLead4Tpi, kHeightV038R, kTruncationV038R,
          pin_length_in * kInch, counterbore_in * kInch};
}

std::string Squeezed(std::string_view text) {
  std::string out;
  for (const char c : text) {
    if (c != '-' && c != ' ') out.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
  }
  return out;
}

}  // namespace

const std::vector<RotaryConnection>& RotaryConnections() {
  // C (gauge-point pitch diameter), L_pc (pin length), Q_c (counterbore), inches (API Spec 7-2).
  static const std::vector<RotaryConnection> connections = {
      Numbered("NC26", 2.668, 3.0, 2.9375),  Numbered("NC31", 3.183, 3.5, 3.453125),
      Numbered("NC38", 3.808, 4.0, 4.078125), Numbered("NC40", 4.072, 4.5, 4.34375),
      Numbered("NC46", 4.626, 4.5, 4.90625), Numbered("NC50", 5.0417, 4.5, 5.3125)};
  return connections;
}

const std::vector<ConnectionAlias>& RotaryConnectionAliases() {
  static const std::vector<ConnectionAlias> aliases = {{"2-3/8 IF", "NC26"}, {"2-7/8 IF", "NC31"}, {"3-1/2 IF", "NC38"},
                                                       {"4 FH", "NC40"},     {"4 IF", "NC46"},     {"4-1/2 IF", "NC50"}};
  return aliases;
}

std::optional<RotaryConnection> FindRotaryConnection(std::string_view name) {
  std::string wanted = Squeezed(name);
  for (const ConnectionAlias& alias : RotaryConnectionAliases()) {
    if (Squeezed(alias.name) == wanted) wanted = alias.numbered;
  }
  for (const RotaryConnection& connection : RotaryConnections()) {
    if (Squeezed(connection.name) == wanted) return connection;
  }
  return std::nullopt;
}

double PinThreadRoot(const RotaryConnection& connection) {
  return connection.pitch_diameter - 2.0 * (0.5 * connection.thread_height - connection.root_truncation) -
         connection.taper * 0.125 * kInch;
}

ConnectionStrength ConnectionTorsionalStrength(const RotaryConnection& connection, double joint_od, double pin_id,
                                               double joint_yield) {
  const double c = connection.pitch_diameter;
  const double taper = connection.taper;
  const double e = taper * 0.375 * kInch;
  const double pin_root = PinThreadRoot(connection);
  if (!(pin_id < pin_root)) throw LogicError("ConnectionTorsionalStrength: the pin ID reaches the thread root");
  if (!(joint_od > connection.counterbore - e)) throw LogicError("ConnectionTorsionalStrength: the OD is inside the box's thread");
  ConnectionStrength strength;
  strength.pin_area = 0.25 * kPi * (pin_root * pin_root - pin_id * pin_id);
  const double box_inner = connection.counterbore - e;
  strength.box_area = 0.25 * kPi * (joint_od * joint_od - box_inner * box_inner);
  strength.pin_weaker = strength.pin_area <= strength.box_area;
  const double area = std::min(strength.pin_area, strength.box_area);
  const double thread_radius = 0.25 * (c + (c - taper * (connection.pin_length - 0.625 * kInch)));
  const double shoulder_radius = 0.25 * (joint_od + connection.counterbore);
  const double f = kThreadCompoundFriction;
  const double half_angle = kPi / 6.0;  // 30°
  // The torque per unit of axial pre-load: the thread's lead, then the friction on the flanks and the shoulder.
  const double arm = connection.lead / (2.0 * kPi) + thread_radius * f / std::cos(half_angle) + shoulder_radius * f;
  strength.torsional_yield = joint_yield * area * arm;
  strength.makeup_torque = kMakeupStressFraction * strength.torsional_yield;
  return strength;
}

}  // namespace drillflex::model
