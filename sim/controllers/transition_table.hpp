// SPDX-License-Identifier: MIT
// What the controllers' transition tables share: a row's number as the memory records it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace swarmpath::sim {

/// Index + 1 of the row called `row` (e.g. "#9a", "T10") in `table`, as a memory's last_row stores it;
/// 0: none.
template <typename Row>
std::uint8_t row_number(std::span<const Row> table, std::string_view row) {
  for (std::size_t i = 0; i < table.size(); ++i) {
    if (table[i].row == row) return static_cast<std::uint8_t>(i + 1);
  }
  return 0;
}

}  // namespace swarmpath::sim
