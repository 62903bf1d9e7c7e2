// SPDX-License-Identifier: MIT
// LED colours (SPEC §2.2): exact RGB as ARGoS's CColor constants. BLACK means the LEDs are off
// and the robot is invisible to cameras.
#pragma once

#include <cstdint>
#include <string_view>

namespace swarmpath::sim {

enum class Led : std::uint8_t {
  kBlack,    ///< LEDs off: resting
  kGreen,    ///< exploring
  kGray50,   ///< return to nest
  kWhite,    ///< subgoal forming [P]
  kRed,      ///< subgoal [P]
  kMagenta,  ///< optimisation 1, aligning
  kBlue,     ///< nest beacon and sub-nest [P]
  kPurple,   ///< optimisation 2, aligning
  kBrown,    ///< path done
  kOrange,   ///< recovery
  kCyan,     ///< goal founder
  kGray80,   ///< decision maker
  kYellow,   ///< goal beacon
};

inline constexpr int kLedCount = 13;

struct Rgb {
  std::uint8_t r, g, b;
};

constexpr Rgb rgb(Led c) {
  switch (c) {
    case Led::kBlack:
      return {0, 0, 0};
    case Led::kGreen:
      return {0, 255, 0};
    case Led::kGray50:
      return {127, 127, 127};
    case Led::kWhite:
      return {255, 255, 255};
    case Led::kRed:
      return {255, 0, 0};
    case Led::kMagenta:
      return {255, 0, 255};
    case Led::kBlue:
      return {0, 0, 255};
    case Led::kPurple:
      return {160, 32, 240};
    case Led::kBrown:
      return {165, 42, 42};
    case Led::kOrange:
      return {255, 140, 0};
    case Led::kCyan:
      return {0, 255, 255};
    case Led::kGray80:
      return {204, 204, 204};
    case Led::kYellow:
      return {255, 255, 0};
  }
  return {0, 0, 0};
}

constexpr std::string_view name(Led c) {
  switch (c) {
    case Led::kBlack:
      return "black";
    case Led::kGreen:
      return "green";
    case Led::kGray50:
      return "gray50";
    case Led::kWhite:
      return "white";
    case Led::kRed:
      return "red";
    case Led::kMagenta:
      return "magenta";
    case Led::kBlue:
      return "blue";
    case Led::kPurple:
      return "purple";
    case Led::kBrown:
      return "brown";
    case Led::kOrange:
      return "orange";
    case Led::kCyan:
      return "cyan";
    case Led::kGray80:
      return "gray80";
    case Led::kYellow:
      return "yellow";
  }
  return "?";
}

}  // namespace swarmpath::sim
