// What the builder says about input it cannot model.
#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "model_test_support.hpp"

namespace drillflex::model {
namespace builder_input_test {

// A section the reduction cannot take (found by fuzz/case_file: the reduction's LogicError ended the
// program: an od of 1e-9 m, a modulus of 1e-300 Pa with a density of 1e300 kg/m3) is an InputError
// naming the component and its line.
TEST(BuildSystemModel, ASectionTooThinToReduceIsAnInputError) {
  for (const double od : {1e-9, 0.0762}) {
    ModelInput input = testing::RodInput(1, 4, 2);
    input.string.components[0].outer_diameter = od;
    input.string.components[0].source_line = 7;
    if (od > 1e-3) input.materials["rod"] = fe::Material{"rod", 1e-300, 0.3, 1e300};
    cms::ReductionCache cache;
    try {
      BuildSystemModel(input, cache);
      FAIL() << "built a rod " << od << " m across of modulus " << input.materials["rod"].youngs_modulus << " Pa, "
             << input.materials["rod"].density << " kg/m3";
    } catch (const InputError& error) {
      EXPECT_EQ(error.key_path(), "string[0]");
      EXPECT_EQ(error.location().line, 7);
      EXPECT_NE(std::string(error.what()).find("cannot be modelled"), std::string::npos) << error.what();
    }
  }
}

// A string that is a bit alone, in a well: no node touches the wall (found by fuzz/case_file:
// ContactCircles' LogicError for no contact nodes ended the program).
TEST(BuildSystemModel, ABitAloneInAWellHasNoWallContact) {
  ModelInput input = testing::RodInput(2, 4, 2);
  input.string.components[0].type = ComponentType::Bit;
  input.well =
      model::MakeWellbore(well::Trajectory(std::vector<well::SurveyStation>{{0.0, 0.0, 0.0}, {100.0, 0.0, 0.0}}),
                          std::vector<well::HoleSection>{well::HoleSection{std::nullopt, 0.3, std::nullopt}});
  input.bit_md = 100.0;
  cms::ReductionCache cache;
  EXPECT_TRUE(BuildSystemModel(input, cache).contacts.empty());
}

}  // namespace builder_input_test
}  // namespace drillflex::model
