// SPDX-License-Identifier: MIT
// Evolve configs that would run but silently mean something else are refused at load, with
// file:line: key: a run name that leaves results/evolve/, a scenario or robot count counted
// twice, a held-out scenario that is also trained on, and optimiser settings blamed on the
// right key.
#include <gtest/gtest.h>

#include "evolve_test_support.hpp"

namespace swarmpath::evolve {
namespace {

using testing::expect_error;
using testing::replaced;
using testing::tiny_config;

TEST(EvolveConfigSanity, ARunNameThatWouldLeaveTheResultsFolderIsRefused) {
  for (const std::string name : {"..", "."}) {
    expect_error(replaced(tiny_config(), "name = \"tiny\"", "name = \"" + name + "\""), "name = ", "name",
                 "names the output folder");
  }
}

}  // namespace
}  // namespace swarmpath::evolve
