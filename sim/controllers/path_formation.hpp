// SPDX-License-Identifier: MIT
// The path-formation controller (paper, "Subgoal Formation" and "Path formation strategies";
// SPEC §2.3): explorers find the goal or a RED subgoal, back off toward the nest and stop as the
// next subgoal 70 cm away, until a subgoal sees the nest; then optimisation 1 straightens the
// chain nest -> goal and optimisation 2 goal -> nest. This file holds the transition table and the
// step; each state's guards and behaviour live with their responsibility: exploring.hpp (rows
// #1-#4), forming.hpp (#5-#8), alignment.hpp (#10-#13), chain_links.hpp (#9, #14-#17).
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "pf_memory.hpp"
#include "pf_perception.hpp"
#include "sim/params.hpp"
#include "sim/percept.hpp"

namespace swarmpath::sim {

struct RobotMemory;

using PfGuard = bool (*)(const PfContext&);
using PfAction = void (*)(const PfContext&, PfMemory&);

/// One row of SPEC §2.3's transition table.
struct PfTransition {
  PfState from;
  PfGuard when;
  PfState to;
  PfAction act;            ///< what the transition does besides changing state (may be null)
  std::string_view row;    ///< SPEC §2.3 row, e.g. "#9a"
  std::string_view label;  ///< the paper's Table 2 label, where one exists
};

/// The table, in SPEC §2.3's order; the first row of the current state whose guard holds fires.
std::span<const PfTransition> pf_transitions();

/// Index + 1 of the table row called `row` (e.g. "#9a"), as PfMemory::last_row stores it; 0: none.
std::uint8_t pf_row_number(std::string_view row);

/// Applies the first matching row (if any); returns it or nullptr.
const PfTransition* pf_transition(const PfContext& c, PfMemory& m);

/// One control step: perceive, the forming leg, transition via the table, then the state's behaviour.
Command path_formation_step(const Percept& in, const Params& p, RobotMemory& mem);

/// Sets up the memory of a robot starting to explore (T_explore = T_explore0), in `role`.
void pf_init(PfMemory& m, const Params& p, PfRole role = PfRole::kSwarm);

/// The command of state `s` driving `v_cm_s` (robot frame, cm/s) through the wheel mapping, its LED on.
Command pf_drive(const Params& p, RobotMemory& mem, Vec2 v_cm_s, PfState s);

/// Standing still with the LED of state `s`.
Command pf_stop(PfState s);

}  // namespace swarmpath::sim
