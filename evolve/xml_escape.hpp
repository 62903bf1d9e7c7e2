// SPDX-License-Identifier: MIT
// Escaping text for XML and SVG output (the ARGoS export, the fitness and arena pictures).
#pragma once

#include <string>
#include <string_view>

namespace swarmpath::evolve {

/// s with <, >, & and " replaced by their entities.
inline std::string xml_escape(std::string_view s) {
  std::string out;
  for (const char ch : s) {
    switch (ch) {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += ch;
    }
  }
  return out;
}

}  // namespace swarmpath::evolve
