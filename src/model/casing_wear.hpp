// Casing wear by a rotating string (issue 37): White & Dawson's (1987, "Casing wear: laboratory
// measurements and field predictions", SPE Drilling Engineering 2(1), SPE 14325) wear-factor model, the
// volume of casing worn per length proportional to the work of the friction on it, and the depth of the
// crescent groove a tool joint cuts to wear that volume. SI throughout.
#pragma once

namespace drillflex::model {

// The volume worn per length of casing, m³/m: WF · (F_n/L) · π D_tj N t, with WF the wear factor (1/Pa:
// the volume worn per friction work over the friction factor, the industry's 1e-10 in²/lbf = 1e-10 1/psi),
// F_n/L the string's side force per length on the casing (N/m), D_tj the tool joint's OD (m), N the rotary
// speed (rad/s: π D N t with N in rev/s) and t the rotating time (s). The sliding distance is the tool
// joint's surface's; the side force per length is the string's, so that the volume is the average over the
// casing as the joints pass along it drilling ahead (White & Dawson).
double WornVolumePerLength(double wear_factor, double side_force_per_length, double joint_diameter,
                           double rotary_speed, double time);

// The area (m²) of a groove of depth h (m) cut by a circle of radius r (the tool joint) into the circle of
// radius R > r (the casing's bore): the part of the joint's circle outside the bore's, its centre
// d = R − r + h from the bore's. With the lens of the two circles
//   lens = r² acos((d² + r² − R²)/(2 d r)) + R² acos((d² + R² − r²)/(2 d R))
//          − ½ √((−d + r + R)(d + r − R)(d − r + R)(d + r + R)),
// the groove is π r² − lens (0 at h = 0).
double GrooveArea(double bore_radius, double joint_radius, double depth);
// The depth of the groove of `area` (m²): GrooveArea's inverse (it grows with the depth), by bisection
// to 1e-12 m; 2 r when the area is the joint's whole circle or more.
double GrooveDepth(double bore_radius, double joint_radius, double area);

}  // namespace drillflex::model
