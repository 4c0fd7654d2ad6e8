// V7 of validation.md in time (v7_hook_load.hpp), its own string: 10,000 ft of the V7 pipe pulled out
// and run in at 0.5 ft/s, hook loads 118,388 and 46,841 lbf (Johancsik) within 3 %. 167
// bodies, ~8 s each in the assertion build (16–21 s before 2026-12-03): label `validation` (slow-validation
// before; hook_load_test.cpp is the 1000 ft variant).
#include "v7_hook_load.hpp"

namespace drillflex::validation {
namespace hook_load_10000_ft_test {

TEST(V7HookLoad, PullingOut10000FtWithin3Percent) {
  CheckSlidingHookLoad("v7-hook-load/pulling-out.yaml", 10000.0, 1.0, 4.5);
}

TEST(V7HookLoad, RunningIn10000FtWithin3Percent) {
  CheckSlidingHookLoad("v7-hook-load/running-in.yaml", 10000.0, -1.0, 4.5);
}

}  // namespace hook_load_10000_ft_test
}  // namespace drillflex::validation
