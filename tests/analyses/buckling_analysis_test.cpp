// Buckling and frequency under axial load (validation.md V2) on the V1 rod with E = 207 GPa,
// ρ = 7850 kg/m³ (Euler–Bernoulli inertia), 8 bodies × 10 elements × (6 + 6) = 144 coordinates:
//  * Euler loads π²EI/(KL)² within 1 % by the linearized eigenproblem and by f² → 0;
//  * pinned-pinned f(P) = f₀ sqrt(1 − P/P_cr) at P/P_cr = 0.5 and −1 within 0.5 %;
//  * the cantilever's dead-load frequency ratios (exact, not the sqrt law) within 1 %;
//  * Greenhill's self-weight column w L³/EI = 7.8373 within 2 %.
#include <gtest/gtest.h>

#include <cmath>

#include "analyses/buckling_analysis.hpp"
#include "analyses/modes_analysis.hpp"
#include "analyses/static_analysis.hpp"
#include "analyses_test_support.hpp"
#include "cms/reduction_cache.hpp"
#include "field_parts.hpp"

namespace drillflex::analyses {
namespace {

using model::kRx;
using model::kRy;
using model::kRz;
using model::kX;
using model::kY;
using model::kZ;
using testing::kRodLength;

constexpr double kE = 207e9, kRho = 7850.0;
constexpr int kBodies = 8;
const double kEI = kE * testing::RodSecondMoment();

double EulerLoad(double effective_length_factor) {
  return kPi * kPi * kEI / std::pow(effective_length_factor * kRodLength, 2);
}

model::ModelInput Rod(std::vector<model::Support> supports, std::vector<model::Load> loads) {
  model::ModelInput input = testing::RodInput(kBodies, kE, kRho);
  input.supports = std::move(supports);
  input.loads = std::move(loads);
  return input;
}

std::vector<model::Support> PinnedPinned() {
  return {testing::SupportAt(0.0, {kX, kY, kZ, kRx}), testing::SupportAt(kRodLength, {kY, kZ})};
}
std::vector<model::Support> ClampedFree() { return {testing::ClampAt(0.0)}; }
std::vector<model::Support> ClampedClamped() {
  return {testing::ClampAt(0.0), testing::SupportAt(kRodLength, {kY, kZ, kRy, kRz})};
}
std::vector<model::Support> ClampedPinned() {
  return {testing::ClampAt(0.0), testing::SupportAt(kRodLength, {kY, kZ})};
}

struct EulerCase {
  const char* name;
  std::vector<model::Support> (*supports)();
  double effective_length_factor;
};

// A compressive tip force of 1 kN; both methods give the multiplier of it.
TEST(BucklingAnalysis, EulerLoadsByBothMethods) {
  const EulerCase cases[] = {{"pinned-pinned", PinnedPinned, 1.0},
                             {"clamped-free", ClampedFree, 2.0},
                             {"clamped-clamped", ClampedClamped, 0.5},
                             {"clamped-pinned", ClampedPinned, 0.6992}};
  const double reference = 1000.0;
  for (const EulerCase& c : cases) {
    cms::ReductionCache cache;
    const model::ModelInput input = Rod(c.supports(), {testing::PointLoad(kRodLength, Vec3(-reference, 0, 0))});
    const model::BuiltModel built = model::BuildSystemModel(input, cache);
    const BucklingResult result = RunBuckling(input, built, BucklingSettings{});
    const double exact = EulerLoad(c.effective_length_factor);
    const double eigen_error = result.critical_load / exact - 1.0;
    const double frequency_error = result.frequency_critical_load / exact - 1.0;
    std::printf("%-16s P_cr %.1f N: eigenproblem %+.4f %%, frequency method %+.4f %% (%zu points)\n", c.name, exact,
                100 * eigen_error, 100 * frequency_error, result.frequency_table.size());
    // Compression to the residual's round-off floor (~1e-3 N, stiff springs).
    EXPECT_NEAR(result.reference_compression, reference, 1e-5 * reference) << c.name;
    EXPECT_NEAR(result.load_factor * result.reference_compression, result.critical_load, 1e-9 * exact) << c.name;
    EXPECT_LT(std::abs(eigen_error), 1e-2) << c.name;
    EXPECT_TRUE(result.frequency_method_converged) << c.name;
    EXPECT_LT(std::abs(frequency_error), 1e-2) << c.name;
  }
}

// The buckled mode of a pinned-pinned column is a half sine: zero at the pins, 1 at mid-span.
TEST(BucklingAnalysis, PinnedPinnedModeIsAHalfSine) {
  cms::ReductionCache cache;
  const model::ModelInput input = Rod(PinnedPinned(), {testing::PointLoad(kRodLength, Vec3(-1000, 0, 0))});
  const model::BuiltModel built = model::BuildSystemModel(input, cache);
  BucklingSettings settings;
  settings.frequency_method = false;
  const BucklingResult result = RunBuckling(input, built, settings);
  ASSERT_EQ(result.s.size(), result.mode_displacement.size());
  for (std::size_t i = 0; i < result.s.size(); ++i) {
    const double lateral = result.mode_displacement[i].tail<2>().norm();
    EXPECT_NEAR(lateral, std::sin(kPi * result.s[i] / kRodLength), 1e-2) << "s = " << result.s[i];
  }
}

// Frequencies of the statically loaded string through RunStatic + RunModes.
double LowestFrequency(std::vector<model::Support> supports, double compression) {
  cms::ReductionCache cache;
  const model::BuiltModel built =
      model::BuildSystemModel(Rod(std::move(supports), {testing::PointLoad(kRodLength, Vec3(-compression, 0, 0))}), cache);
  const StaticResult equilibrium = RunStatic(built, StaticSettings{});
  ModesSettings settings;
  settings.count = 1;
  settings.kind = ModeKind::Lateral;
  return RunModes(built, equilibrium.q, settings).modes.at(0).frequency_hz;
}

// validation.md V2 (computed): f₀ = 5.9544 Hz, 4.2104 Hz at P/P_cr = 0.5, 8.4208 Hz at −1.
TEST(BucklingAnalysis, PinnedPinnedFrequencyUnderAxialLoad) {
  const double pcr = EulerLoad(1.0);
  const struct {
    double ratio, hz;
  } points[] = {{0.0, 5.9544}, {0.5, 4.2104}, {-1.0, 8.4208}};
  for (const auto& point : points) {
    const double hz = LowestFrequency(PinnedPinned(), point.ratio * pcr);
    std::printf("pinned-pinned P/Pcr %+.2f: %.4f Hz, reference %.4f Hz, error %+.4f %%\n", point.ratio, hz, point.hz,
                100 * (hz / point.hz - 1));
    EXPECT_NEAR(hz / point.hz, 1.0, 5e-3) << "P/Pcr = " << point.ratio;
  }
}

// validation.md V2 (computed): f/f₀ of a cantilever under a dead tip load; f₀ the Euler–Bernoulli
// cantilever frequency 1.8751041² / (2π L²) sqrt(EI/(ρA)).
TEST(BucklingAnalysis, CantileverFrequencyUnderDeadTipLoad) {
  const double pcr = EulerLoad(2.0);
  const double f0 = 1.8751041 * 1.8751041 / (2 * kPi * kRodLength * kRodLength) *
                    std::sqrt(kEI / (kRho * testing::RodArea()));
  const struct {
    double ratio, frequency_ratio;
  } points[] = {{0.25, 0.874143}, {0.5, 0.720862}, {0.75, 0.515158}, {-1.0, 1.36938}};
  for (const auto& point : points) {
    const double ratio = LowestFrequency(ClampedFree(), point.ratio * pcr) / f0;
    std::printf("cantilever P/Pcr %+.2f: f/f0 %.6f, reference %.6f, error %+.4f %%\n", point.ratio, ratio,
                point.frequency_ratio, 100 * (ratio / point.frequency_ratio - 1));
    EXPECT_NEAR(ratio / point.frequency_ratio, 1.0, 1e-2) << "P/Pcr = " << point.ratio;
  }
}

// Greenhill: a column clamped at its base (s = 0), free at the top, under a distributed axial
// load w toward the base buckles at w L³/EI = 7.8373 (Timoshenko & Gere, Theory of Elastic
// Stability, §2.10).
TEST(BucklingAnalysis, GreenhillSelfWeightColumn) {
  const double w = 1000.0;  // N/m, the reference load
  cms::ReductionCache cache;
  const model::ModelInput input = Rod(ClampedFree(), {testing::DistributedLoad(0.0, kRodLength, Vec3(-w, 0, 0))});
  const model::BuiltModel built = model::BuildSystemModel(input, cache);
  const BucklingResult result = RunBuckling(input, built, BucklingSettings{});
  const double exact = 7.8373 * kEI / std::pow(kRodLength, 3);
  const double eigen_error = result.load_factor * w / exact - 1.0;
  const double frequency_error = result.frequency_load_factor * w / exact - 1.0;
  std::printf("Greenhill: eigenproblem %+.4f %%, frequency method %+.4f %%\n", 100 * eigen_error,
              100 * frequency_error);
  EXPECT_LT(std::abs(eigen_error), 2e-2);
  EXPECT_LT(std::abs(frequency_error), 2e-2);
  // The largest compression is at the base: w L less the base node's own share w h/2.
  const double h = kRodLength / (10 * kBodies);
  EXPECT_NEAR(result.reference_compression, w * (kRodLength - h / 2), 1e-6 * w * kRodLength);
}

}  // namespace
}  // namespace drillflex::analyses

namespace drillflex::analyses {
namespace {

// Dawson & Paslay's check beside the eigenproblem in a well: 300 ft of 4-3/4 in collars (no tool
// joints) lying in a straight 8-1/2 in hole at 60°, dry, under 40 klbf WOB. The compression is
// largest at the bit, F ≈ WOB, and F_sin = 2 √(EI w sin θ / r) by hand (w = ρ g A, r the radial
// clearance), so the WOB × F_sin / WOB (the default: the WOB scaled alone, F growing with it) or
// every load × (F_sin / WOB)² (F ∝ λ, F_sin ∝ √λ) reach it first there.
TEST(BucklingInWell, DawsonPaslayLoadFactorMatchesTheHandFormula) {
  model::ModelInput input;
  const double od = 4.75 * testing::kIn, id = 2.25 * testing::kIn;
  input.string.components = {testing::Part(model::ComponentType::Collar, 4.75, 2.25, 30.0, 10)};
  input.materials["steel"] = fe::Material{"steel", 2.1e11, 0.3, 7850.0};
  input.gravity = 9.81;
  const double inclination = 60.0 * kDegree;
  input.trajectory.emplace(std::vector<well::SurveyStation>{{0.0, inclination, 0.0}, {2000.0, inclination, 0.0}});
  input.hole = {well::HoleSection{{}, 8.5 * testing::kIn, {}}};
  input.bit_md = 1500.0;
  const double wob = 40000.0 * testing::kLbf;
  input.operation.weight_on_bit = wob;
  cms::ReductionCache cache;
  const model::BuiltModel built = model::BuildSystemModel(input, cache);
  BucklingSettings every_load;
  every_load.scale = BucklingScale::AllLoads;
  const BucklingResult result = RunBuckling(input, built, every_load);
  ASSERT_TRUE(result.sinusoidal.computed);
  EXPECT_FALSE(result.scaled_wob);
  const double area = kPi / 4.0 * (od * od - id * id);
  const double inertia = kPi / 64.0 * (std::pow(od, 4) - std::pow(id, 4));
  const double weight = 7850.0 * 9.81 * area;
  const double clearance = 0.5 * (8.5 * testing::kIn - od);
  const double sinusoidal = 2.0 * std::sqrt(2.1e11 * inertia * weight * std::sin(inclination) / clearance);
  EXPECT_NEAR(result.sinusoidal.sinusoidal_load, sinusoidal, 0.01 * sinusoidal);
  EXPECT_NEAR(result.sinusoidal.helical_load, 2.0 * std::sqrt(2.0) * sinusoidal, 0.01 * sinusoidal);
  EXPECT_LT(result.sinusoidal.s, 1.0);  // at the bit
  const double expected = (sinusoidal / wob) * (sinusoidal / wob);
  EXPECT_NEAR(result.sinusoidal.load_factor, expected, 0.02 * expected);
  const BucklingResult by_wob = RunBuckling(input, built, BucklingSettings{});
  ASSERT_TRUE(by_wob.scaled_wob);
  EXPECT_NEAR(by_wob.sinusoidal.load_factor, sinusoidal / wob, 0.02 * sinusoidal / wob);
  std::printf("[ measure  ] 60° hole: critical WOB %.0f N by the lateral frequency (the top free), Dawson-Paslay %.0f N\n",
              by_wob.critical_wob, sinusoidal);
}

}  // namespace
}  // namespace drillflex::analyses
