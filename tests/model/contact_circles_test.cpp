// The wall-contact circles (model/contact_circles.hpp):
//  * a uniform collar: interior nodes stand for one node spacing, the end nodes for half of one,
//    the lengths adding up to the string between the end nodes;
//  * drill pipe with tool joints: one circle of the joint OD per joint, at the connection, standing
//    for the joint's length (half at the string's ends), whatever the mesh; the body's circles for
//    the rest of their spans; the body circles' stiffness per metre the same on every mesh;
//  * a stabilizer: one blade circle at the middle of the blades, standing for the blade length.
#include "model/contact_circles.hpp"

#include <gtest/gtest.h>

#include <numeric>

#include "core/error.hpp"
#include "model/builder.hpp"

namespace drillflex::model {
namespace contact_circles_test {

constexpr double kPipeOd = 0.127, kJointOd = 0.1683;

StringConfig PipeWithJoints() {
  Component pipe;
  pipe.type = ComponentType::Pipe;
  pipe.outer_diameter = kPipeOd;
  pipe.inner_diameter = 0.1086;
  pipe.length = kDefaultJointSpacing;
  pipe.count = 4;
  pipe.joint_diameter = kJointOd;
  pipe.joint_length = kDefaultJointLength;
  StringConfig string;
  string.components.push_back(pipe);
  return string;
}

std::vector<double> Nodes(double length, int intervals) {
  std::vector<double> s;
  for (int i = 0; i <= intervals; ++i) s.push_back(length * i / intervals);
  return s;
}

TEST(ContactCircles, UniformCollarSplitsTheSpacing) {
  Component collar;
  collar.outer_diameter = 0.1714;
  collar.length = 9.144;
  StringConfig string;
  string.components.push_back(collar);
  const std::vector<double> s = Nodes(9.144, 30);
  const std::vector<ContactCircle> circles = ContactCircles(string, s);
  const double spacing = 9.144 / 30;
  EXPECT_NEAR(circles.front().length, 0.5 * spacing, 1e-12);
  EXPECT_NEAR(circles.back().length, 0.5 * spacing, 1e-12);
  double sum = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    EXPECT_EQ(circles[i].diameter, 0.1714);
    if (i > 0 && i + 1 < s.size()) {
      EXPECT_NEAR(circles[i].length, spacing, 1e-12);
    }
    sum += circles[i].length;
  }
  EXPECT_NEAR(sum, 9.144, 1e-12);
}

TEST(ContactCircles, ToolJointsArePointContactsOfTheirOwnLengthOnEveryMesh) {
  const StringConfig string = PipeWithJoints();
  const double length = 4 * kDefaultJointSpacing;
  for (int per_joint : {10, 20, 40, 7}) {
    const std::vector<double> s = Nodes(length, 4 * per_joint);
    const std::vector<ContactCircle> circles = ContactCircles(string, s);
    int joints = 0;
    double body_length = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (circles[i].diameter == kJointOd) {
        ++joints;
        // At a connection (s = j × 9.144 m), standing for the joint (half of it at the ends).
        EXPECT_NEAR(std::remainder(s[i], kDefaultJointSpacing), 0.0, 1e-9) << per_joint;
        const bool end = i == 0 || i + 1 == s.size();
        EXPECT_NEAR(circles[i].length, (end ? 0.5 : 1.0) * kDefaultJointLength, 1e-12) << per_joint;
      } else {
        EXPECT_EQ(circles[i].diameter, kPipeOd);
        body_length += circles[i].length;
      }
    }
    EXPECT_EQ(joints, 5) << per_joint << " nodes a joint";
    // The body circles stand for the pipe body, L − 4 joint lengths, but for the parts of the
    // joint nodes' spans beside the joints (a node spacing less a joint, at most, per joint) and
    // the 1/16 floors of the nodes inside a joint.
    const double spacing = kDefaultJointSpacing / per_joint;
    const double uncovered = 4 * std::max(spacing - kDefaultJointLength, 0.0);
    EXPECT_LE(body_length, length - 4 * kDefaultJointLength + 8 * spacing / 16 + 1e-9) << per_joint;
    EXPECT_GE(body_length, length - 4 * kDefaultJointLength - uncovered - 1e-9) << per_joint;
  }
}

TEST(ContactCircles, BodyStiffnessPerMetreDoesNotDependOnTheMesh) {
  const StringConfig string = PipeWithJoints();
  const double length = 4 * kDefaultJointSpacing;
  for (int intervals : {40, 80, 160}) {
    const std::vector<double> s = Nodes(length, intervals);
    const std::vector<ContactCircle> circles = ContactCircles(string, s);
    // A body node well away from the joints stands for exactly its node spacing.
    const int quarter = intervals / 8;  // s = 4.572 m, mid-way between joints
    EXPECT_NEAR(circles[quarter].length, length / intervals, 1e-12) << intervals;
  }
}

TEST(ContactCircles, StabilizerBladesAreOnePointContactAtTheirMiddle) {
  Component stabilizer;
  stabilizer.type = ComponentType::Stabilizer;
  stabilizer.outer_diameter = 0.1714;
  stabilizer.length = 1.524;
  stabilizer.blade_diameter = 0.2143;
  stabilizer.blade_length = 0.4572;
  StringConfig string;
  string.components.push_back(stabilizer);
  for (int intervals : {10, 20, 33}) {
    const std::vector<double> s = Nodes(1.524, intervals);
    const std::vector<ContactCircle> circles = ContactCircles(string, s);
    int blades = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (circles[i].diameter != 0.2143) continue;
      ++blades;
      EXPECT_LE(std::abs(s[i] - 0.762), 0.5 * 1.524 / intervals + 1e-12) << intervals;
      EXPECT_NEAR(circles[i].length, 0.4572, 1e-12) << intervals;
    }
    EXPECT_EQ(blades, 1) << intervals;
  }
}

TEST(ContactCircles, RefusesUnorderedPositions) {
  const StringConfig string = PipeWithJoints();
  EXPECT_THROW(ContactCircles(string, {0.0, 2.0, 1.0}), LogicError);
}

}  // namespace contact_circles_test
}  // namespace drillflex::model
