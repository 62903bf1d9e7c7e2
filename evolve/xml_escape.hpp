// SPDX-License-Identifier: MIT
// Escaping text for XML and SVG output (the ARGoS export, the fitness and arena pictures).
#pragma once

#include <string>
#include <string_view>

namespace swarmpath::evolve {

/// s with <, >, & and " replaced by their entities and control characters by U+FFFD.
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
        // XML 1.0 has no C0 control characters but tab, line feed and carriage return, not even as
        // references, and DEL is one too: the replacement character U+FFFD stands for them
        if ((static_cast<unsigned char>(ch) < 0x20 && ch != '\t' && ch != '\n' && ch != '\r') || ch == 0x7f) {
          out += "\uFFFD";
        } else {
          out += ch;
        }
    }
  }
  return out;
}

}  // namespace swarmpath::evolve
