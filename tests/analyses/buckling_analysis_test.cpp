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
namespace buckling_analysis_test {

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

}  // namespace buckling_analysis_test
}  // namespace drillflex::analyses

namespace drillflex::analyses {
namespace buckling_analysis_test {

// 300 ft of 4-3/4 in collars (no tool joints) lying in a straight 8-1/2 in hole at `inclination`,
// dry, under a WOB; Dawson & Paslay's F_sin = 2 √(EI w sin θ / r) by hand (w = ρ g A, r the radial
// clearance).
struct CollarsInAStraightHole {
  model::ModelInput input;
  double sinusoidal = 0.0;  // F_sin, N
  double weight = 0.0;      // w, N/m
  double bending_rigidity = 0.0;  // EI, N·m²
};

CollarsInAStraightHole Collars(double inclination, double wob, model::TopCondition top) {
  CollarsInAStraightHole collars;
  model::ModelInput& input = collars.input;
  const double od = 4.75 * testing::kIn, id = 2.25 * testing::kIn;
  input.string.components = {testing::Part(model::ComponentType::Collar, 4.75, 2.25, 30.0, 10)};
  input.materials["steel"] = fe::Material{"steel", 2.1e11, 0.3, 7850.0};
  input.gravity = 9.81;
  input.well = model::MakeWellbore(
      well::Trajectory(std::vector<well::SurveyStation>{{0.0, inclination, 0.0}, {2000.0, inclination, 0.0}}),
      std::vector<well::HoleSection>{well::HoleSection{{}, 8.5 * testing::kIn, {}}});
  input.bit_md = 1500.0;
  input.operation.weight_on_bit = wob;
  input.settings.top = top;
  const double area = kPi / 4.0 * (od * od - id * id);
  collars.bending_rigidity = 2.1e11 * kPi / 64.0 * (std::pow(od, 4) - std::pow(id, 4));
  collars.weight = 7850.0 * 9.81 * area;
  const double clearance = 0.5 * (8.5 * testing::kIn - od);
  collars.sinusoidal = 2.0 * std::sqrt(collars.bending_rigidity * collars.weight * std::sin(inclination) / clearance);
  return collars;
}

// Dawson & Paslay's check beside the eigenproblem in a well, at 60° under 40 klbf WOB. The
// compression is largest at the bit, F ≈ WOB, so the WOB × F_sin / WOB (the default: the WOB scaled
// alone, F growing with it) or every load × (F_sin / WOB)² (F ∝ λ, F_sin ∝ √λ) reach it first there.
TEST(BucklingInWell, DawsonPaslayLoadFactorMatchesTheHandFormula) {
  const double wob = 40000.0 * testing::kLbf;
  const CollarsInAStraightHole collars = Collars(60.0 * kDegree, wob, model::TopCondition::StringAbove);
  cms::ReductionCache cache;
  const model::BuiltModel built = model::BuildSystemModel(collars.input, cache);
  BucklingSettings every_load;
  every_load.scale = BucklingScale::AllLoads;
  const BucklingResult result = RunBuckling(collars.input, built, every_load);
  ASSERT_TRUE(result.sinusoidal.computed);
  EXPECT_FALSE(result.scaled_wob);
  const double sinusoidal = collars.sinusoidal;
  EXPECT_NEAR(result.sinusoidal.sinusoidal_load, sinusoidal, 0.01 * sinusoidal);
  EXPECT_NEAR(result.sinusoidal.helical_load, 2.0 * std::sqrt(2.0) * sinusoidal, 0.01 * sinusoidal);
  EXPECT_LT(result.sinusoidal.s, 1.0);  // at the bit
  const double expected = (sinusoidal / wob) * (sinusoidal / wob);
  EXPECT_NEAR(result.sinusoidal.load_factor, expected, 0.02 * expected);
  const BucklingResult by_wob = RunBuckling(collars.input, built, BucklingSettings{});
  ASSERT_TRUE(by_wob.scaled_wob);
  EXPECT_NEAR(by_wob.sinusoidal.load_factor, sinusoidal / wob, 0.02 * sinusoidal / wob);
}

// The string above the model (issue 33, item 3; model/string_above.hpp): the modelled collars joined
// to a semi-infinite pipe lying on the low side buckle where a long pipe does. In a horizontal hole
// the compression is the WOB all along: the onset is Dawson–Paslay's F_sin (within 3 %: the bit end
// held at the hole centre, the frequency route's extrapolation). At 60° the compression falls by
// w cos θ a metre up the string, so the bit must carry more: the envelope of the sinusoid obeys
// 4 EI A'' + (F(x) − F_sin) A = 0 near the onset (the beam on its foundation expanded about the
// critical wavenumber), an Airy equation of length ℓ = (4 EI / (w cos θ))^⅓ with A = 0 at the held
// bit: F(0) = F_sin + 2.338 w cos θ ℓ (Ai's first zero), 7 % above F_sin here; within 10 % of F_sin
// (the bound) and 3 % of that. In the horizontal hole the pipe above, compressed as much as
// the collars, reaches F_sin with them: the onset is the pipe above's (BucklingResult::
// onset_above_model). The free top (model.top: free) buckles far below it at 60°, near Hetényi's
// free end of a beam on a foundation (F_sin / 2 under a uniform compression).
TEST(BucklingInWell, TheStringAboveTheModelBringsTheOnsetToDawsonPaslay) {
  const double wob = 40000.0 * testing::kLbf;
  for (const double degrees : {90.0, 60.0}) {
    const double inclination = degrees * kDegree;
    const CollarsInAStraightHole collars = Collars(inclination, wob, model::TopCondition::StringAbove);
    cms::ReductionCache cache;
    const model::BuiltModel built = model::BuildSystemModel(collars.input, cache);
    ASSERT_TRUE(built.string_above.has_value());
    const BucklingResult result = RunBuckling(collars.input, built, BucklingSettings{});
    ASSERT_TRUE(result.scaled_wob);
    const double sinusoidal = collars.sinusoidal;
    const double gradient = collars.weight * std::cos(inclination);  // N/m
    double expected = sinusoidal;
    if (gradient > 1e-6 * collars.weight) {
      expected += 2.33811 * gradient * std::cbrt(4.0 * collars.bending_rigidity / gradient);
    }
    std::printf("[ measure  ] %.0f° hole: critical WOB %.0f N, Dawson-Paslay %.0f N (%+.2f %%), with the "
                "compression's fall %.0f N (%+.2f %%)\n",
                degrees, result.critical_wob, sinusoidal, 100.0 * (result.critical_wob / sinusoidal - 1.0), expected,
                100.0 * (result.critical_wob / expected - 1.0));
    EXPECT_NEAR(result.critical_wob, sinusoidal, 0.10 * sinusoidal) << degrees;
    EXPECT_NEAR(result.critical_wob, expected, 0.03 * expected) << degrees;
    EXPECT_FALSE(result.buckled_at_case_loads);
    EXPECT_EQ(result.onset_above_model, degrees == 90.0) << degrees;

    if (degrees != 60.0) continue;
    // The free top at 60°: far below Dawson–Paslay (0.59 of it before the pipe above was modelled).
    const CollarsInAStraightHole free = Collars(inclination, wob, model::TopCondition::Free);
    const model::BuiltModel free_built = model::BuildSystemModel(free.input, cache);
    EXPECT_EQ(free_built.string_above.has_value(), false);
    const BucklingResult free_result = RunBuckling(free.input, free_built, BucklingSettings{});
    std::printf("[ measure  ] %.0f° hole, the top free: critical WOB %.0f N (%.3f of F_sin)\n", degrees,
                free_result.critical_wob, free_result.critical_wob / sinusoidal);
    EXPECT_LT(free_result.critical_wob, 0.75 * sinusoidal) << degrees;
  }
}

// A string buckled at the case's loads (the WOB twice its onset): the frequency about its
// equilibrium rises with the load (the post-buckled string pressed onto the wall), so the onset is
// searched below the loads, on a fresh path of equilibria from a fraction of them, and found where
// the search from below the onset finds it (within 1 %).
TEST(BucklingInWell, AStringBuckledAtItsLoadsHasItsOnsetFoundBelowThem) {
  const double wob = 40000.0 * testing::kLbf;
  const CollarsInAStraightHole below = Collars(60.0 * kDegree, wob, model::TopCondition::StringAbove);
  cms::ReductionCache cache;
  const BucklingResult reference =
      RunBuckling(below.input, model::BuildSystemModel(below.input, cache), BucklingSettings{});
  ASSERT_GT(reference.load_factor, 1.0);
  const CollarsInAStraightHole above =
      Collars(60.0 * kDegree, 2.0 * reference.critical_wob, model::TopCondition::StringAbove);
  const model::BuiltModel built = model::BuildSystemModel(above.input, cache);
  const BucklingResult result = RunBuckling(above.input, built, BucklingSettings{});
  std::printf("[ measure  ] WOB 2 x the onset: critical WOB %.0f N against %.0f N from below (%+.3f %%), x %.4f\n",
              result.critical_wob, reference.critical_wob, 100.0 * (result.critical_wob / reference.critical_wob - 1.0),
              result.load_factor);
  EXPECT_TRUE(result.buckled_at_case_loads);
  EXPECT_LT(result.load_factor, 1.0);
  EXPECT_NEAR(result.critical_wob, reference.critical_wob, 0.01 * reference.critical_wob);
}

}  // namespace buckling_analysis_test
}  // namespace drillflex::analyses
