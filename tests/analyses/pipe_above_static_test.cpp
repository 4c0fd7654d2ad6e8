// What the pipe above the model holds the top with (model/string_above.hpp, StaticResult::pipe_above),
// on a string at rest in a kick-off: the tension it takes at rest is the modelled string's axial
// balance, so it equals the hook's axial reaction at the equilibrium (a string at rest carries no
// friction; measured −35 846 against −35 837 N: the balance takes the weight along the hole's axis,
// Σ w ΔTVD, the string lies on the wall as chords; within 0.1 %); the top lies where the pipe above lies (on the low
// side of a straight hole at the top), so its sideways hold is small against the string's weight; and
// with the top free (model.top: free) there is none.
#include <gtest/gtest.h>

#include <cstdio>

#include "analyses/static_analysis.hpp"
#include "cms/reduction_cache.hpp"
#include "well_cases.hpp"

namespace drillflex::analyses {
namespace pipe_above_static_test {

TEST(PipeAboveStatic, TheTensionItTakesIsTheHooksReactionAtRest) {
  model::ModelInput input = testing::KickOffToTheSouth(10);
  cms::ReductionCache cache;
  const model::BuiltModel built = model::BuildSystemModel(input, cache);
  const StaticResult result = RunStaticInWell(input, built, StaticSettings{});
  ASSERT_TRUE(result.converged);
  ASSERT_TRUE(result.pipe_above.has_value());
  const PipeAboveReaction& pipe = *result.pipe_above;
  ASSERT_EQ(result.reactions.size(), 2u);
  const SupportReaction& hook = result.reactions.back();
  std::printf("[ measure  ] tension at rest %.3f N, hook reaction %.3f N, sideways hold %.3f N, residual %.3g N\n",
              pipe.tension, hook.force.x(), pipe.force.tail<2>().norm(), result.residual_norm);
  EXPECT_NEAR(pipe.tension, hook.force.x(), 1e-3 * std::abs(hook.force.x()));
  EXPECT_FALSE(pipe.buckled);
  EXPECT_NEAR(pipe.s, result.nodes.back().s, 1e-9);
  // The sideways hold: a fraction of the weight of a metre of the pipe above (w ≈ 190 N/m).
  EXPECT_LT(pipe.force.tail<2>().norm(), 0.2 * 190.0);

  input.settings.top = model::TopCondition::Free;
  const model::BuiltModel free = model::BuildSystemModel(input, cache);
  EXPECT_FALSE(RunStaticInWell(input, free, StaticSettings{}).pipe_above.has_value());
}

}  // namespace pipe_above_static_test
}  // namespace drillflex::analyses
