// Values of a case set by key path (io::ParseCaseWithValues, io::WithValues): what the Python module's
// Case.with_values and the sweep command change a case with. Each set value is read as the case's own
// (units, checks), and every key path that cannot be set is an InputError naming it.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "io/case.hpp"

namespace drillflex::io {
namespace case_values_test {

using ::testing::HasSubstr;

constexpr double kFt = 0.3048;
constexpr double kKlbf = 4448.2216152605;

const char* kCase = R"(name: values
units: field
string:
  - {type: bit, od: 8.5, length: 1.0}
  - {type: stabilizer, od: 6.75, id: 2.8125, length: 5, blade_od: 8.375}
  - {type: collar, od: 6.75, id: 2.8125, length: 30, count: 3}
model:
  contact: {stiffness: 1e8 N/m, friction: 0.25}
operation: {wob: 25, rpm: 120}
analyses:
  static:
  transient: {duration: 10 s, output_interval: 0.01 s}
)";

Case Set(std::vector<CaseValue> values) { return ParseCaseWithValues(kCase, "case.yaml", ".", values); }

InputError SetError(std::vector<CaseValue> values) {
  try {
    Set(std::move(values));
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "no InputError";
  return InputError({}, "", "");
}

TEST(CaseValues, SetsScalarsInTheCasesUnitSyntax) {
  const Case c = Set({{"operation.wob", "30 klbf"},
                      {"string[2].length", "40 ft"},
                      {"model.contact.friction", "0.3"},
                      {"analyses.transient.duration", "2 s"},
                      {"operation.rpm", "90"}});
  EXPECT_NEAR(c.input.operation.weight_on_bit, 30 * kKlbf, 1e-6);
  EXPECT_NEAR(c.input.string.components[2].length, 40 * kFt, 1e-12);
  EXPECT_EQ(c.input.string.components[2].count, 3);
  EXPECT_NEAR(c.input.settings.contact.friction, 0.3, 1e-15);
  ASSERT_TRUE(c.analyses.transient);
  EXPECT_NEAR(c.analyses.transient->duration, 2.0, 1e-15);
  EXPECT_NEAR(c.input.operation.rotary_speed, 90 * kPi / 30, 1e-12);
  // A bare number is in the case's units (klbf for a WOB in field units).
  EXPECT_NEAR(Set({{"operation.wob", "12"}}).input.operation.weight_on_bit, 12 * kKlbf, 1e-6);
}

TEST(CaseValues, NoValuesReadsTheCaseAsParseCase) {
  const Case plain = ParseCase(kCase, "case.yaml");
  const Case same = Set({});
  EXPECT_EQ(same.text, kCase);
  EXPECT_EQ(plain.text, kCase);
  EXPECT_EQ(same.input.operation.weight_on_bit, plain.input.operation.weight_on_bit);
  EXPECT_EQ(same.input.string.components.size(), plain.input.string.components.size());
}

TEST(CaseValues, WithValuesRereadsACaseFromItsText) {
  const Case c = ParseCase(kCase, "dir/case.yaml", "dir");
  const Case changed = WithValues(c, {{"operation.wob", "30 klbf"}});
  EXPECT_NEAR(changed.input.operation.weight_on_bit, 30 * kKlbf, 1e-6);
  EXPECT_NEAR(c.input.operation.weight_on_bit, 25 * kKlbf, 1e-6);
  EXPECT_EQ(changed.file, "dir/case.yaml");
  EXPECT_EQ(changed.directory, "dir");
  EXPECT_EQ(changed.text, kCase);  // the file's text; the values are applied on each read
}

TEST(CaseValues, AddsAKeyTheCaseLeavesOutAndAFlowValue) {
  const Case c = Set({{"operation.torque_on_bit", "5000"},
                      {"analyses.static.max_iterations", "30"},
                      {"string[1]", "{type: collar, od: 6.75, id: 2.8125, length: 4}"}});
  EXPECT_NEAR(c.input.operation.torque_on_bit, 5000 * 1.3558179483314004, 1e-6);
  EXPECT_EQ(c.input.string.components[1].type, model::ComponentType::Collar);
  EXPECT_NEAR(c.input.string.components[1].length, 4 * kFt, 1e-12);
}

// A map on the way that the case leaves out is created (a dry case given a mud: 12 ppg is
// 12 × 119.826427 kg/m³), and the reader checks it as any other.
TEST(CaseValues, CreatesAMapTheCaseLeavesOut) {
  const Case c = Set({{"fluid.density", "12"}});
  ASSERT_TRUE(c.input.fluid.has_value());
  EXPECT_NEAR(c.input.fluid->density, 12 * 119.826427, 1e-3);
  EXPECT_FALSE(Set({}).input.fluid.has_value());
}

TEST(CaseValues, LaterValuesApplyToTheTreeTheEarlierLeft) {
  const Case c = Set({{"string[1]", "{type: collar, od: 6.75, id: 2.8125, length: 4}"}, {"string[1].length", "6"}});
  EXPECT_NEAR(c.input.string.components[1].length, 6 * kFt, 1e-12);
}

struct RejectedValue {
  const char* label;
  CaseValue value;
  int line;                // of the error's location (0: none)
  const char* message;     // a part of it
  const char* key = nullptr;  // the key the error names when not the value's (a section the reader refuses)
};

class CaseValuesRejects : public ::testing::TestWithParam<RejectedValue> {};

TEST_P(CaseValuesRejects, NamingTheKeyAndWhere) {
  const RejectedValue& rejected = GetParam();
  const InputError error = SetError({rejected.value});
  EXPECT_EQ(error.key_path(), rejected.key ? rejected.key : rejected.value.key) << error.what();
  EXPECT_EQ(error.location().file, "case.yaml");
  EXPECT_EQ(error.location().line, rejected.line) << error.what();
  EXPECT_THAT(error.what(), HasSubstr(rejected.message));
}

INSTANTIATE_TEST_SUITE_P(
    Values, CaseValuesRejects,
    ::testing::Values(
        RejectedValue{"misspelled_section", {"fluidd.density", "10"}, 1, "unknown key 'fluidd'", "fluidd"},
        RejectedValue{"index_out_of_range", {"string[3].length", "10"}, 4, "'string' has 3 items ([0] to [2]): no item [3]"},
        RejectedValue{"index_into_a_map", {"operation[0]", "1"}, 9, "'operation' is not a list"},
        RejectedValue{"key_into_a_scalar", {"operation.wob.value", "1"}, 9, "'operation.wob' is not a map"},
        RejectedValue{"key_into_a_list", {"string.length", "1"}, 4, "'string' is not a map"},
        RejectedValue{"empty_key", {"operation..wob", "1"}, 0, "not a key path"},
        RejectedValue{"unclosed_index", {"string[1.length", "1"}, 0, "not a key path"},
        RejectedValue{"negative_index", {"string[-1].length", "1"}, 0, "not a key path"},
        RejectedValue{"trailing_dot", {"operation.", "1"}, 0, "not a key path"},
        RejectedValue{"not_yaml", {"operation.wob", "{30"}, 0, "the value '{30' is not YAML"},
        // The reader's own errors, at the place of the value set (or of the map it joins).
        RejectedValue{"wrong_unit", {"operation.wob", "30 ft"}, 9, "is a length, but a weight on bit (force) is expected"},
        RejectedValue{"misspelled_key", {"operation.wobb", "30"}, 9, "unknown key 'wobb' (did you mean 'wob'?)"},
        RejectedValue{"negative_length", {"string[2].length", "-3 ft"}, 6, "greater than zero"}),
    [](const auto& info) { return std::string(info.param.label); });

}  // namespace case_values_test
}  // namespace drillflex::io
