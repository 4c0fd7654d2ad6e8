// The transient's limits in results.json (pipeline/transient_limits.hpp) through RunCase, with no VTK
// output (no frames kept): a collar (3 in × 1.181 in) clamped at its lower end, held at its equilibrium
// under 200 kN of tension and 5 kN·m of torque at its top, rated 500 MPa (design factor 1.25) with a
// make-up torque of 20 kN·m. By hand (Python): A = π/4 (0.0762² − 0.03²) = 3.853509e-3 m²,
// J = π/32 (0.0762⁴ − 0.03⁴) = 3.230416e-6 m⁴, σ = 51.90075 MPa, τ = T (D/2)/J = 58.97074 MPa,
// σ_vm = √(σ² + 3τ²) = 114.5702 MPa: 0.2864255 of 400 MPa, the closest; the torque 0.25. The model's
// section torque reads up to 1/cos φ of the load's, φ the relative twist of the two bodies' frames (the
// couplings measure it by sin φ: tests/analyses/internal_forces_test.cpp), φ = (T/cos φ) L_b/(G J) =
// 0.048732 rad with L_b = 2.54 m and G = E/2.6, 1/cos φ − 1 = 1.1886e-3: so the torque utilisation in
// [0.25, 0.2502972] and the von Mises one in [0.2864255, 0.2866961] (σ_vm with τ/cos φ), 1e-6 for round-off.
#include <gtest/gtest.h>

#include "io/case.hpp"
#include "pipeline/case_files.hpp"
#include "pipeline/case_run.hpp"

namespace drillflex::pipeline {
namespace transient_limits_test {

TEST(TransientLimits, EverySampleReadWithoutVtkAgainstTheHandComputation) {
  const io::Case c = io::ReadCase(DRILLFLEX_SOURCE_DIR "/tests/cases/held-collar.yaml");
  const CaseResults results = RunCase(c, AnalysisRequest::Only(Analysis::Transient));
  ASSERT_TRUE(results.transient);
  EXPECT_TRUE(results.transient->frame_q.empty());  // no VTK frames asked for
  FileOptions options;
  options.vtk = false;
  const io::ResultFiles files = ComposeResultFiles(c, results, options);
  const auto& limits = files.json()["transient"]["limits"];
  EXPECT_EQ(limits["samples"], 6);
  EXPECT_EQ(limits["history"]["time"].size(), 6u);
  EXPECT_EQ(limits["history"]["closest"], "yield");
  const auto within = [](double value, double low, double high) {
    EXPECT_GE(value, low * (1.0 - 1e-6));
    EXPECT_LE(value, high * (1.0 + 1e-6));
  };
  within(limits["summary"]["yield"]["utilisation"].get<double>(), 0.2864255, 0.2866961);
  within(limits["summary"]["makeup_torque"]["utilisation"].get<double>(), 0.25, 0.2502972);
  EXPECT_EQ(limits["summary"]["closest"]["limit"], "yield");
  for (const auto& u : limits["history"]["yield"]) within(u.get<double>(), 0.2864255, 0.2866961);
  EXPECT_FALSE(limits["history"].contains("helical_buckling"));  // no well: not screened
  const auto& stations = limits["nodes"];
  ASSERT_GT(stations["s"].size(), 2u);
  EXPECT_EQ(stations["yield_time"].size(), stations["s"].size());
  EXPECT_EQ(stations["helical_buckling_utilisation"][0], 0.0);
}

}  // namespace transient_limits_test
}  // namespace drillflex::pipeline
