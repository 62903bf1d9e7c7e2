// SPDX-License-Identifier: MIT
// What the LED colours of SPEC §2.2 mean to the controllers.
#pragma once

#include "sim/led.hpp"

namespace swarmpath::sim {

/// A path-formation colour (SPEC §2.6 T7): a robot forming a subgoal, in the chain, aligning, done or
/// broken off (WHITE, RED, MAGENTA, BLUE, PURPLE, BROWN, ORANGE).
constexpr bool is_path_colour(Led c) {
  switch (c) {
    case Led::kWhite:
    case Led::kRed:
    case Led::kMagenta:
    case Led::kBlue:
    case Led::kPurple:
    case Led::kBrown:
    case Led::kOrange:
      return true;
    default:
      return false;
  }
}

/// Paper label e (SPEC §2.3): the path robots an explorer keeps clear of, every one but a RED subgoal
/// (which it may attach to, row #1).
constexpr bool repels_explorers(Led c) { return is_path_colour(c) && c != Led::kRed; }

}  // namespace swarmpath::sim
