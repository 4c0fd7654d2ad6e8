// V7 of validation.md in time (v7_hook_load.hpp): 1000 ft of the V7 pipe pulled out and run in at
// 0.5 ft/s; Johancsik's hook loads computed for that length, w_b L (cos I ± μ sin I) = 11,839 and
// 4,684 lbf, within 3 %. The 10,000 ft string of validation.md (118,388 and 46,841 lbf) is
// hook_load_10000_ft_test.cpp.
#include "v7_hook_load.hpp"

namespace drillflex::validation {
namespace hook_load_test {

// validation.md's figures, rounded down to the pound (46,841.6 is written 46,841).
TEST(V7HookLoad, ReferencesAreValidationMdsOver10000Ft) {
  EXPECT_NEAR(V7CaseBuoyedWeight(), kV7BuoyedWeight, 1e-4 * kV7BuoyedWeight);
  EXPECT_NEAR(JohancsikHookLoad(10000.0, 0.0), 82615.0, 1.0);
  EXPECT_NEAR(JohancsikHookLoad(10000.0, 1.0), 118388.0, 1.0);
  EXPECT_NEAR(JohancsikHookLoad(10000.0, -1.0), 46841.0, 1.0);
}

TEST(V7HookLoad, PullingOut1000FtWithin3Percent) {
  CheckSlidingHookLoad("v7-hook-load/pulling-out-1000-ft.yaml", 1000.0, 1.0, 1.25);
}

TEST(V7HookLoad, RunningIn1000FtWithin3Percent) {
  CheckSlidingHookLoad("v7-hook-load/running-in-1000-ft.yaml", 1000.0, -1.0, 1.25);
}

}  // namespace hook_load_test
}  // namespace drillflex::validation
