// The survey CSV reader on text (io/survey_csv.hpp), as well.survey_file reads it.
#include "io/survey_csv.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "core/types.hpp"

namespace drillflex::io {
namespace survey_csv_test {

using ::testing::HasSubstr;

constexpr double kFt = 0.3048;

std::string ErrorOf(std::string_view text, units::System system = units::System::SI) {
  try {
    ParseSurveyCsv(text, "survey.csv", system);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(SurveyCsv, HeaderCommentsBlankLinesUnitsAndCarriageReturns) {
  const auto stations = ParseSurveyCsv(
      "MD (ft), Inc (deg), Azi (deg)\r\n# tie-in\r\n\r\n0,0,0\r\n1000, 2.5 ,-90\r\n600 m,10 deg,1 rad\r\n",
      "survey.csv", units::System::Field);
  ASSERT_EQ(stations.size(), 3u);
  EXPECT_NEAR(stations[1].md, 1000 * kFt, 1e-12);
  EXPECT_NEAR(stations[1].inclination, 2.5 * kDegree, 1e-15);
  EXPECT_NEAR(stations[1].azimuth, 1.5 * kPi, 1e-12);  // -90 deg brought into [0, 360)
  EXPECT_NEAR(stations[2].md, 600.0, 1e-12);
  EXPECT_NEAR(stations[2].azimuth, 1.0, 1e-15);
}

TEST(SurveyCsv, ACommaEndingALineOpensNoColumnAsBefore) {
  // The reader cut lines with std::getline(line, cell, ','), which drops an empty last cell.
  EXPECT_EQ(ParseSurveyCsv("0,0,0,\n100,1,2,\n", "survey.csv", units::System::SI).size(), 2u);
  EXPECT_THAT(ErrorOf("0,0,0\n100,1,2,,\n"), HasSubstr("survey.csv:2:"));
  EXPECT_THAT(ErrorOf("0,0,0\n100,1,2,,\n"), HasSubstr("expected 3 columns"));
  EXPECT_TRUE(ParseSurveyCsv("", "survey.csv", units::System::SI).empty());
}

TEST(SurveyCsv, ErrorsNameTheLineAndTheKey) {
  try {
    ParseSurveyCsv("md,inc,azi\n0,0,0\n100,0,0\n90,5,0\n", "survey.csv", units::System::SI);
    FAIL() << "accepted a survey whose MD goes backwards";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location().line, 4);
    EXPECT_EQ(error.key_path(), "well.survey_file");
    EXPECT_THAT(error.what(), HasSubstr("strictly increase"));
  }
  EXPECT_THAT(ErrorOf("0,0,0\n100,200,0\n"), HasSubstr("between 0 and 180"));
  EXPECT_THAT(ErrorOf("0,0,0\n100,5 ppg,0\n"), HasSubstr("survey.csv:2:"));
  EXPECT_THAT(ErrorOf("md\n"), HasSubstr("expected 3 columns"));
}

}  // namespace survey_csv_test
}  // namespace drillflex::io
