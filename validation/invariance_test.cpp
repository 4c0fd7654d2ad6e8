// Issue 4 acceptance: invariance of the static solution in a well (validation/v4-invariance/).
// A stabilized rotary BHA (near-bit stabilizer, 2 collars, string stabilizer, 9 collars; the bit the lower
// end of the near-bit stabilizer, held at the hole centre) under
// 20 klbf WOB in a straight 8-1/2 in hole inclined 30°, bit at 6500 ft, 10 ppg mud.
// Reference (symmetry, no computed number): in a straight hole the azimuth only turns the whole
// problem about the vertical (gravity), so the azimuth-0° and azimuth-137° cases must give the same
// bit side/build/walk force, tilt, and contacts (force, MD, high-side angle); the same case written in
// SI gives the same results after the change of units (1 ft = 0.3048 m, 1 lbf = 4.4482216152605 N).
// Tolerance 0.5 % (1 lbf absolute for contact forces near zero; build and walk within 0.5 % of the side
// force, see below; 0.01 ft on contact MDs): the stiff penalty supports' round-off at 2000 m depth is
// about 0.3 % of the bit side force.
#include <cmath>
#include <cstdio>
#include <string>

#include "field_units.hpp"
#include "validation_support.hpp"

namespace drillflex::validation {
namespace invariance_test {

struct Scale {
  double length = 1.0;  // output length to ft
  double force = 1.0;   // output force to lbf
};
constexpr Scale kField{};
constexpr Scale kSI{1.0 / kMetresPerFoot, 1.0 / kNewtonsPerPoundForce};

// Forces equal within 0.5 % or 1 lbf, whichever is larger.
void ExpectSameForce(double a_lbf, double b_lbf, const std::string& what) {
  EXPECT_LE(std::abs(a_lbf - b_lbf), std::max(1.0, 0.005 * std::max(std::abs(a_lbf), std::abs(b_lbf))))
      << what << ": " << a_lbf << " against " << b_lbf << " lbf";
}

double WorstRelative(double a, double b, double worst) {
  const double scale = std::max(std::abs(a), std::abs(b));
  return scale > 0.0 ? std::max(worst, std::abs(a - b) / scale) : worst;
}

// Compares the bit and the contacts of two results (each with its own output units).
void ExpectSameStatics(const nlohmann::json& a, Scale sa, const nlohmann::json& b, Scale sb, const char* label) {
  ASSERT_TRUE(a.contains("static") && b.contains("static"));
  const auto& bit_a = a["static"]["bit"];
  const auto& bit_b = b["static"]["bit"];
  double worst = 0.0;
  // Build and walk are the components of one lateral force vector, and their round-off is a fraction of
  // its magnitude: at azimuth 137° the walk comes out 0.9 lbf of a 2144 lbf side force here (0 at
  // azimuth 0, where the east components vanish exactly); with a 1 ft full-gauge bit added below the
  // stabilizer, 0.14 / 0.98 / 5.1 lbf with the bit at 500 / 2000 / 6500 ft, 0.08 % of its side force.
  // So the components are compared within 0.5 % of the side force (at least 1 lbf).
  const double side_a = bit_a["side_force"].get<double>() * sa.force;
  const double side_b = bit_b["side_force"].get<double>() * sb.force;
  ExpectSameForce(side_a, side_b, std::string(label) + " bit side_force");
  worst = WorstRelative(side_a, side_b, worst);
  const double vector_tolerance = std::max(1.0, 0.005 * std::max(side_a, side_b));
  for (const char* key : {"build_force", "walk_force"}) {
    const double fa = bit_a[key].get<double>() * sa.force, fb = bit_b[key].get<double>() * sb.force;
    EXPECT_LE(std::abs(fa - fb), vector_tolerance) << label << " bit " << key << ": " << fa << " against " << fb;
    if (std::string(key) == "build_force") worst = WorstRelative(fa, fb, worst);
  }
  const double tilt_a = bit_a["tilt"].get<double>(), tilt_b = bit_b["tilt"].get<double>();
  EXPECT_LE(std::abs(tilt_a - tilt_b), 0.005 * std::max(std::abs(tilt_a), std::abs(tilt_b)))
      << label << " bit tilt " << tilt_a << " against " << tilt_b << " deg";
  worst = WorstRelative(tilt_a, tilt_b, worst);

  // Every contact that carries more than 1 lbf in one result has its twin in the other at the same MD.
  const auto& ca = a["static"]["contacts"];
  const auto& cb = b["static"]["contacts"];
  EXPECT_FALSE(ca.empty());
  double worst_contact = 0.0, worst_md = 0.0;
  auto match = [&](const nlohmann::json& from, Scale sf, const nlohmann::json& to, Scale st) {
    for (const auto& contact : from) {
      const double force = contact["normal_force"].get<double>() * sf.force;
      const double md = contact["md"].get<double>() * sf.length;
      const nlohmann::json* twin = nullptr;
      for (const auto& other : to) {
        if (std::abs(other["md"].get<double>() * st.length - md) <= 0.01) twin = &other;
      }
      if (twin == nullptr) {
        EXPECT_LE(force, 1.0) << label << ": no twin for the contact at MD " << md << " ft, " << force << " lbf";
        continue;
      }
      const double other_force = (*twin)["normal_force"].get<double>() * st.force;
      ExpectSameForce(force, other_force, std::string(label) + " contact at MD " + std::to_string(md));
      EXPECT_NEAR(contact["high_side_angle"].get<double>(), (*twin)["high_side_angle"].get<double>(), 0.1)
          << label << " contact at MD " << md;
      if (std::max(force, other_force) > 100.0) worst_contact = WorstRelative(force, other_force, worst_contact);
      worst_md = std::max(worst_md, std::abs((*twin)["md"].get<double>() * st.length - md));
    }
  };
  match(ca, sa, cb, sb);
  match(cb, sb, ca, sa);
  std::printf("%s: bit side %.3f / %.3f lbf, build %.3f / %.3f, walk %.4f / %.4f, tilt %.6f / %.6f deg; "
              "%zu / %zu contacts; worst relative difference: bit %.4f %%, contacts over 100 lbf %.4f %%, "
              "contact MD %.2e ft\n",
              label, bit_a["side_force"].get<double>() * sa.force, bit_b["side_force"].get<double>() * sb.force,
              bit_a["build_force"].get<double>() * sa.force, bit_b["build_force"].get<double>() * sb.force,
              bit_a["walk_force"].get<double>() * sa.force, bit_b["walk_force"].get<double>() * sb.force, tilt_a,
              tilt_b, ca.size(), cb.size(), 100.0 * worst, 100.0 * worst_contact, worst_md);
}

// One test runs the three cases once (separate tests would share the azimuth-0 output directory).
TEST(V4Invariance, AzimuthAndUnitsDoNotChangeTheStaticsOfAStraightHole) {
  const auto north = RunCase("static", "v4-invariance/bha-30-deg-az-0.yaml");
  const auto turned = RunCase("static", "v4-invariance/bha-30-deg-az-137.yaml");
  const auto si = RunCase("static", "v4-invariance/bha-30-deg-si.yaml");
  ASSERT_EQ(si.value("units", ""), "SI");
  {
    SCOPED_TRACE("azimuth");
    ExpectSameStatics(north, kField, turned, kField, "azimuth 0 / 137 deg");
  }
  {
    SCOPED_TRACE("units");
    ExpectSameStatics(north, kField, si, kSI, "field / SI");
  }
}

}  // namespace invariance_test
}  // namespace drillflex::validation
