// The WITSML readers: the sample documents of both versions read alike, units from each value's
// `uom`, and every bad document rejected with its file, line, element and what was expected.
#include "io/witsml.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "core/error.hpp"
#include "core/types.hpp"

namespace drillflex::io {
namespace witsml_reader_test {

using ::testing::HasSubstr;

constexpr double kFt = 0.3048;
constexpr double kIn = 0.0254;

const std::string kSamples = DRILLFLEX_SOURCE_DIR "/examples/witsml/";

// A 1.4.1.1 document of one object around `body`.
std::string Document1411(const std::string& objects, const std::string& body) {
  return "<?xml version=\"1.0\"?>\n<" + objects + "s xmlns=\"http://www.witsml.org/schemas/1series\" version=\"1.4.1.1\">\n<" +
         objects + " uid=\"o1\"><name>test</name>\n" + body + "</" + objects + ">\n</" + objects + "s>\n";
}

std::string Station(const std::string& md, const std::string& incl, const std::string& azi,
                    const std::string& md_uom = "ft") {
  return "<trajectoryStation uid=\"s" + md + "\"><md uom=\"" + md_uom + "\">" + md + "</md><incl uom=\"dega\">" + incl +
         "</incl><azi uom=\"dega\">" + azi + "</azi></trajectoryStation>\n";
}

std::string Component(int sequence, const std::string& type, const std::string& fields) {
  return "<tubularComponent uid=\"c" + std::to_string(sequence) + "\"><typeTubularComp>" + type +
         "</typeTubularComp><sequence>" + std::to_string(sequence) + "</sequence>" + fields + "</tubularComponent>\n";
}

const std::string kCollar = "<id uom=\"in\">2.8125</id><od uom=\"in\">6.75</od><len uom=\"ft\">30</len>";

// The InputError a bad document throws.
InputError ErrorOf(const std::string& text) {
  try {
    ReadWitsml(text, "bad.xml");
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return InputError({}, "", "");
}

TEST(WitsmlReader, TheSamplesOfBothVersionsReadAlike) {
  for (const char* version : {"1.4.1.1", "2.0"}) {
    SCOPED_TRACE(version);
    const auto trajectory = ReadWitsmlFile(kSamples + version + "/trajectory.xml");
    const auto geometry = ReadWitsmlFile(kSamples + version + "/wbgeometry.xml");
    const auto tubular = ReadWitsmlFile(kSamples + version + "/tubular.xml");
    EXPECT_EQ(trajectory.version, version);
    ASSERT_EQ(trajectory.trajectories.size(), 1u);
    const auto survey = SurveyOf(trajectory.trajectories[0]);
    ASSERT_EQ(survey.size(), 19u);
    EXPECT_DOUBLE_EQ(survey[2].md, 5100 * kFt);
    EXPECT_DOUBLE_EQ(survey[2].inclination, 3 * kDegree);
    EXPECT_DOUBLE_EQ(survey[2].azimuth, 45 * kDegree);
    ASSERT_EQ(geometry.geometries.size(), 1u);
    const auto hole = HoleOf(geometry.geometries[0]);
    ASSERT_EQ(hole.size(), 2u);
    EXPECT_DOUBLE_EQ(*hole[0].to_md, 4500 * kFt);
    EXPECT_DOUBLE_EQ(hole[0].diameter, 8.835 * kIn);
    EXPECT_FALSE(hole[1].to_md);
    EXPECT_DOUBLE_EQ(hole[1].diameter, 8.5 * kIn);
    EXPECT_TRUE(hole[0].cased);   // typeHoleCasing casing
    EXPECT_FALSE(hole[1].cased);  // open hole
    ASSERT_EQ(tubular.tubulars.size(), 1u);
    const auto& components = tubular.tubulars[0].components;
    ASSERT_EQ(components.size(), 8u);
    const model::Component stabilizer = ComponentOf(components[1]);
    EXPECT_EQ(stabilizer.type, model::ComponentType::Stabilizer);
    EXPECT_DOUBLE_EQ(*stabilizer.blade_diameter, 8.4375 * kIn);
    EXPECT_DOUBLE_EQ(*stabilizer.blade_length, 1.5 * kFt);
    EXPECT_EQ(ComponentOf(components[3]).material, "nonmag");  // MWD, non-magnetic steel
    const model::Component pipe = ComponentOf(components[7]);
    EXPECT_EQ(pipe.type, model::ComponentType::Pipe);
    EXPECT_EQ(pipe.count, 30);  // len 900 ft of lenJointAv 30 ft joints
    EXPECT_DOUBLE_EQ(pipe.length, 30 * kFt);
    EXPECT_DOUBLE_EQ(*pipe.joint_diameter, 6.625 * kIn);
    EXPECT_DOUBLE_EQ(*pipe.joint_length, 1.5 * kFt);
    // wtPerLen and grade are read but not mapped: a warning each, never silence.
    EXPECT_THAT(tubular.warnings.at(0), HasSubstr("tPerLen> 100 lbm/ft not mapped"));  // wtPerLen, 2.0 WtPerLen
    EXPECT_THAT(tubular.warnings.back(), HasSubstr("not mapped"));
  }
}

TEST(WitsmlReader, UnitsComeFromEachValuesUom) {
  const auto document = ReadWitsml(
      Document1411("trajectory", Station("0", "0", "0", "m") + Station("1000", "0.5", "1", "ftUS") +
                                     "<trajectoryStation><md uom=\"km\">0.5</md><incl uom=\"rad\">1</incl>"
                                     "<azi uom=\"dega\">370</azi></trajectoryStation>"),
      "units.xml");
  const auto survey = SurveyOf(document.trajectories[0]);
  EXPECT_DOUBLE_EQ(survey[1].md, 1000 * 1200.0 / 3937.0);  // US survey feet
  EXPECT_DOUBLE_EQ(survey[2].md, 500.0);
  EXPECT_DOUBLE_EQ(survey[2].inclination, 1.0);
  EXPECT_NEAR(survey[2].azimuth, 10 * kDegree, 1e-12);  // 370 deg, taken round
  const auto tubular = ReadWitsml(
      Document1411("tubular", Component(1, "drill collar",
                                        "<id uom=\"mm\">71.4</id><od uom=\"cm\">17.145</od><len uom=\"m\">9.144</len>"
                                        "<wtPerLen uom=\"kg/m\">145</wtPerLen>")),
      "si.xml");
  const model::Component collar = ComponentOf(tubular.tubulars[0].components[0]);
  EXPECT_DOUBLE_EQ(collar.inner_diameter, 0.0714);
  EXPECT_DOUBLE_EQ(collar.outer_diameter, 0.17145);
  EXPECT_DOUBLE_EQ(collar.length, 9.144);
}

TEST(WitsmlReader, SeveralObjectsInOneDocument) {
  const std::string text =
      "<trajectorys xmlns=\"http://www.witsml.org/schemas/1series\" version=\"1.4.1.1\">"
      "<trajectory uid=\"a\"><name>A</name>" + Station("0", "0", "0") + Station("100", "1", "0") + "</trajectory>"
      "<trajectory uid=\"b\"><name>B</name>" + Station("0", "0", "0") + Station("200", "2", "0") + "</trajectory>"
      "</trajectorys>";
  const auto document = ReadWitsml(text, "two.xml");
  ASSERT_EQ(document.trajectories.size(), 2u);
  EXPECT_EQ(document.trajectories[1].name, "B");
}

TEST(WitsmlReader, OverlappingCasingsGiveTheNarrowest) {
  const auto section = [](const std::string& type, const std::string& top, const std::string& bottom,
                          const std::string& inside) {
    return "<wbGeometrySection><typeHoleCasing>" + type + "</typeHoleCasing><mdTop uom=\"ft\">" + top +
           "</mdTop><mdBottom uom=\"ft\">" + bottom + "</mdBottom><diaDrift uom=\"in\">" + inside +
           "</diaDrift><idSection uom=\"in\">" + inside + "</idSection></wbGeometrySection>\n";
  };
  // 13-3/8 in surface casing to 2000 ft, the 9-5/8 in intermediate casing from the surface to 6000 ft
  // inside it, a 7 in liner from 5500 ft to 9000 ft, open hole below: the innermost pipe holds.
  const auto document = ReadWitsml(
      Document1411("wbGeometry", section("casing", "0", "2000", "12.259") + section("casing", "0", "6000", "8.679") +
                                     section("liner", "5500", "9000", "6.059") +
                                     section("open hole", "9000", "10000", "6")),
      "nested.xml");
  const auto hole = HoleOf(document.geometries[0]);
  ASSERT_EQ(hole.size(), 3u);
  EXPECT_DOUBLE_EQ(*hole[0].to_md, 5500 * kFt);
  EXPECT_DOUBLE_EQ(hole[0].diameter, 8.679 * kIn);
  EXPECT_DOUBLE_EQ(*hole[1].to_md, 9000 * kFt);
  EXPECT_DOUBLE_EQ(hole[1].diameter, 6.059 * kIn);
  EXPECT_DOUBLE_EQ(hole[2].diameter, 6 * kIn);
}

TEST(WitsmlReader, MotorBendIsPlacedFromTheBit) {
  const auto document = ReadWitsml(
      Document1411("tubular",
                   Component(1, "bit PDC fixed cutter", "<id uom=\"in\">0</id><od uom=\"in\">8.5</od><len uom=\"ft\">1</len>") +
                       Component(2, "motor steerable",
                                 "<id uom=\"in\">3</id><od uom=\"in\">6.75</od><len uom=\"ft\">25</len>"
                                 "<motor><lobesRotor>5</lobesRotor></motor>"
                                 "<bend><angle uom=\"dega\">1.5</angle><distBendBot uom=\"ft\">6</distBendBot></bend>")),
      "motor.xml");
  const model::Component motor = ComponentOf(document.tubulars[0].components[1]);
  EXPECT_EQ(motor.type, model::ComponentType::Motor);
  EXPECT_DOUBLE_EQ(*motor.bend_angle, 1.5 * kDegree);
  EXPECT_DOUBLE_EQ(*motor.bend_to_bit, 7 * kFt);  // 1 ft of bit below, the bend 6 ft up the motor
  EXPECT_EQ(*motor.lobes, 5);
}

TEST(WitsmlReader, AnUnmappedTypeIsASubWithAWarning) {
  const auto document = ReadWitsml(Document1411("tubular", Component(1, "whipstock", kCollar)), "w.xml");
  EXPECT_EQ(document.tubulars[0].components[0].type, model::ComponentType::Sub);
  ASSERT_FALSE(document.warnings.empty());
  EXPECT_THAT(document.warnings[0], HasSubstr("'whipstock' has no drillflex type"));
}

// Each bad document: the file, the line, the element's path and what was expected.
struct Bad {
  const char* what;
  std::string text;
  int line;
  const char* element;  // a part of the key path
  const char* message;  // a part of the message
};

void ExpectBad(const Bad& bad) {
  SCOPED_TRACE(bad.what);
  const InputError error = ErrorOf(bad.text);
  EXPECT_EQ(error.location().file, "bad.xml");
  EXPECT_EQ(error.location().line, bad.line) << error.what();
  EXPECT_THAT(error.key_path(), HasSubstr(bad.element)) << error.what();
  EXPECT_THAT(error.message(), HasSubstr(bad.message)) << error.what();
  EXPECT_THAT(std::string(error.what()), HasSubstr("bad.xml:" + std::to_string(bad.line)));
}

TEST(WitsmlReader, ASurveyWhoseMdGoesBackwards) {
  ExpectBad({"an MD going backwards",
             Document1411("trajectory", Station("0", "0", "0") + Station("5000", "1", "0") + Station("4900", "2", "0")), 6,
             "trajectoryStation[uid=s4900]/md", "must strictly increase"});
}

TEST(WitsmlReader, AComponentWithoutOd) {
  ExpectBad({"a component without OD",
             Document1411("tubular", Component(1, "drill collar", "<id uom=\"in\">2.8125</id><len uom=\"ft\">30</len>")), 4,
             "tubularComponent[uid=c1]", "expected a <od> element"});
}

TEST(WitsmlReader, ATubularWhoseSequenceNumbersSkip) {
  ExpectBad({"sequence numbers that skip",
             Document1411("tubular", Component(1, "drill collar", kCollar) + Component(2, "drill collar", kCollar) +
                                         Component(4, "drill collar", kCollar)),
             6, "tubularComponent[uid=c4]/sequence", "skip from 2 to 4"});
}

TEST(WitsmlReader, ANamespaceOrVersionItDoesNotRead) {
  ExpectBad({"a namespace it does not read",
             "<trajectorys xmlns=\"http://www.witsml.org/schemas/131\" version=\"1.3.1.1\"/>", 1, "trajectorys",
             "namespace 'http://www.witsml.org/schemas/131' is not read"});
  ExpectBad({"a version it does not read",
             "<tubulars xmlns=\"http://www.witsml.org/schemas/1series\" version=\"1.4.1.0\">\n</tubulars>", 1, "tubulars",
             "version '1.4.1.0' is not read"});
}

TEST(WitsmlReader, OtherBadDocumentsNameFileLineElementAndExpectation) {
  const std::vector<Bad> cases = {
      {"a sequence number twice",
       Document1411("tubular", Component(1, "drill collar", kCollar) + Component(1, "jar", kCollar)), 5,
       "sequence", "appears twice"},
      {"a 2.0 object of another schema version",
       "<Trajectory xmlns=\"http://www.energistics.org/energyml/data/witsmlv2\" schemaVersion=\"2.1\"/>", 1,
       "Trajectory", "schemaVersion '2.1' is not read"},
      {"an unknown unit symbol",
       Document1411("trajectory", Station("0", "0", "0") + Station("100", "1", "0", "fathom")), 5,
       "trajectoryStation[uid=s100]/md", "unknown unit of measure uom=\"fathom\""},
      {"a unit of the wrong kind",
       Document1411("tubular", Component(1, "drill collar", "<id uom=\"in\">2</id><od uom=\"dega\">6</od><len uom=\"ft\">30</len>")),
       4, "tubularComponent[uid=c1]/od", "uom=\"dega\" is an angle, but a diameter"},
      {"a value without uom",
       Document1411("tubular", Component(1, "drill collar", "<id uom=\"in\">2</id><od>6</od><len uom=\"ft\">30</len>")), 4,
       "/od", "no 'uom' attribute"},
      {"a number that is not one",
       Document1411("trajectory", Station("0", "0", "0") + Station("1O0", "1", "0")), 5, "/md", "got '1O0'"},
      {"an inclination beyond 180 deg", Document1411("trajectory", Station("0", "0", "0") + Station("100", "181", "0")), 5,
       "/incl", "between 0 and 180"},
      {"an ID as large as the OD",
       Document1411("tubular", Component(1, "drill collar", "<id uom=\"in\">6.75</id><od uom=\"in\">6.75</od><len uom=\"ft\">30</len>")),
       4, "/id", "between 0 and the outside diameter"},
      {"a gap between hole sections",
       Document1411("wbGeometry",
                    "<wbGeometrySection><typeHoleCasing>casing</typeHoleCasing><mdTop uom=\"ft\">0</mdTop><mdBottom "
                    "uom=\"ft\">100</mdBottom><idSection uom=\"in\">9</idSection></wbGeometrySection>\n"
                    "<wbGeometrySection><typeHoleCasing>open hole</typeHoleCasing><mdTop uom=\"ft\">200</mdTop><mdBottom "
                    "uom=\"ft\">300</mdBottom><idSection uom=\"in\">8</idSection></wbGeometrySection>\n"),
       3, "wbGeometry[uid=o1]", "no section covers the MD from 100 ft to 200 ft"},
      {"malformed XML", "<trajectorys>\n<trajectory>\n</trajectorys>\n", 3, "", "not well-formed XML"},
  };
  for (const Bad& bad : cases) ExpectBad(bad);
}

}  // namespace witsml_reader_test
}  // namespace drillflex::io
