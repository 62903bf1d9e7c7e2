// SPDX-License-Identifier: MIT
// What the controllers' transition tables share: a row's number as the memory records it, and
// each state's rows in table order.
#pragma once

#include <array>
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

/// The indices of each state's rows, in table order: a step scans only the current state's rows,
/// and the first of them whose guard holds is the row a scan of the whole table would fire.
template <std::size_t Rows, std::size_t States>
struct RowsByState {
  std::array<std::uint8_t, Rows> rows{};
  std::array<std::uint8_t, States + 1> begin{};

  constexpr std::span<const std::uint8_t> of(std::size_t state) const {
    return {rows.data() + begin[state], rows.data() + begin[state + 1]};
  }
};

template <std::size_t States, typename Row, std::size_t Rows>
constexpr RowsByState<Rows, States> rows_by_state(const std::array<Row, Rows>& table) {
  static_assert(Rows < 256);
  RowsByState<Rows, States> r;
  std::size_t k = 0;
  for (std::size_t s = 0; s < States; ++s) {
    r.begin[s] = static_cast<std::uint8_t>(k);
    for (std::size_t i = 0; i < Rows; ++i) {
      if (static_cast<std::size_t>(table[i].from) == s) r.rows[k++] = static_cast<std::uint8_t>(i);
    }
  }
  r.begin[States] = static_cast<std::uint8_t>(k);
  return r;
}

}  // namespace swarmpath::sim
