// SPDX-License-Identifier: MIT
// restore() trusts nothing: a saved state whose fields have the wrong type, range or length is
// refused with a StateError naming the field, for every optimiser.
#include <gtest/gtest.h>

#include "evolve/optim/state_reader.hpp"
#include "optim_test_support.hpp"

namespace swarmpath::evolve {
namespace {

class StateValidation : public testing::TestWithParam<std::string> {};

// the state after two generations
nlohmann::json state_after_two(const std::string& name) {
  auto opt = make_optimizer(test::settings_named(name), test::test_box(), test::far_start(), 5);
  (void)test::candidates_of(*opt, test::sphere, 2);
  return opt->state();
}

void expect_field(const std::string& name, const nlohmann::json& state, const std::string& field) {
  auto fresh = make_optimizer(test::settings_named(name), test::test_box(), test::far_start(), 5);
  try {
    fresh->restore(state);
    ADD_FAILURE() << name << ": accepted a state with a bad " << field;
  } catch (const StateError& e) {
    EXPECT_EQ(e.field(), field) << e.what();
  }
}

TEST_P(StateValidation, TheRestoredStateIsTheSavedOne) {
  const nlohmann::json s = state_after_two(GetParam());
  auto fresh = make_optimizer(test::settings_named(GetParam()), test::test_box(), test::far_start(), 9);
  fresh->restore(s);
  EXPECT_EQ(fresh->state(), s);
}

TEST_P(StateValidation, AWrongDimensionOrBestPointIsRefused) {
  nlohmann::json s = state_after_two(GetParam());
  s["dim"] = 2;
  expect_field(GetParam(), s, "dim");
  s = state_after_two(GetParam());
  s["dim"] = -1;
  expect_field(GetParam(), s, "dim");
  s = state_after_two(GetParam());
  if (s.contains("best")) {
    s["best"]["x"].push_back(1.0);
    expect_field(GetParam(), s, "best.x");
  }
  s = state_after_two(GetParam());
  if (s.contains("rng")) {
    s["rng"] = {0, 0, 0, 0};
    expect_field(GetParam(), s, "rng");
    s["rng"] = {1, 2, 3};
    expect_field(GetParam(), s, "rng");
  }
  s = state_after_two(GetParam());
  if (s.contains("asked") && s["asked"].is_array()) {
    s["asked"] = {{100.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0}};
    // the GA's pending batch pairs with its unit coordinates: one point where none is pending
    expect_field(GetParam(), s, GetParam() == "ga" ? "asked" : "asked[0]");
  }
  s = state_after_two(GetParam());
  if (s.contains("history")) {  // NLopt: the points told so far
    s["history"][0]["x"][0] = 2.0;
    expect_field(GetParam(), s, "history[0].x");
  }
}

INSTANTIATE_TEST_SUITE_P(Optim, StateValidation, testing::ValuesIn(optimizer_names()),
                         [](const testing::TestParamInfo<std::string>& param_info) {
                           return test::param_name(param_info.param);
                         });

}  // namespace
}  // namespace swarmpath::evolve
