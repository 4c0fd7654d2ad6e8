// core/profile: scopes record their calls and wall time only while profiling is on, nested scopes
// each their inclusive time, and the report lists the longest first.
#include "core/profile.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace drillflex::profile {
namespace profile_test {

TEST(Profile, RecordsScopesOnlyWhileOnAndNestsInclusively) {
  Reset();
  Enable(false);
  { const Scope ignored("off"); }
  EXPECT_TRUE(Report().empty());
  Enable(true);
  for (int i = 0; i < 3; ++i) {
    const Scope outer("outer");
    const Scope inner("inner");
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  { const Scope outer("outer"); }
  Enable(false);
  const std::vector<Entry> report = Report();
  ASSERT_EQ(report.size(), 2u);
  EXPECT_EQ(report[0].name, "outer");  // inclusive: at least the inner scope's time
  EXPECT_EQ(report[0].calls, 4);
  EXPECT_EQ(report[1].name, "inner");
  EXPECT_EQ(report[1].calls, 3);
  EXPECT_GE(report[1].seconds, 0.006);
  EXPECT_GE(report[0].seconds, report[1].seconds);
  EXPECT_NE(FormatReport(1.0).find("outer"), std::string::npos);
  Reset();
  EXPECT_TRUE(Report().empty());
}

}  // namespace profile_test
}  // namespace drillflex::profile
