// SPDX-License-Identifier: MIT
// The behaviours swarmpath adds to SPEC's rules ("additions"), each with the params settings that
// switch it off and the SPEC rule it changes, and the paper-literal params: SPEC §7's defaults with
// every addition off, which run exactly the rules of SPEC §2 (genomes/paper-literal.toml).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string_view>

#include "params.hpp"

namespace swarmpath::sim {

/// One params key and a value for it.
struct Setting {
  std::string_view key;
  double value = 0;
};

/// Where an addition can act: every run, or only runs with task allocation.
enum class AdditionScope : std::uint8_t { kBoth, kTaskAllocation };

/// A behaviour beyond SPEC §2's rules.
struct Addition {
  std::string_view name;                  ///< the ablation's name for it: its main params key
  std::string_view title;                 ///< what it does, in a few words
  std::string_view rule;                  ///< the SPEC rule it changes
  AdditionScope scope;                    ///< the runs it can change
  std::array<Setting, 2> off;             ///< what switches it off (key empty: no second setting)
  std::array<std::string_view, 3> needs;  ///< additions it acts only beside (empty: none)
};

/// Every addition, in the order of SPEC §2 (sensing, exploring, going home, forming, aligning,
/// task allocation).
std::span<const Addition> additions();

/// Whether `a` is on in the default controller (Params{}, genomes/default.toml); false for an
/// addition under trial, registered so that the ablation can measure it (run with --params that
/// switch it on).
bool in_default(const Addition& a);

/// The addition called `name`, or nullptr.
const Addition* find_addition(std::string_view name);

/// Switches `a` off in `p` (its keys take their off values).
void switch_off(Params& p, const Addition& a);

/// Switches `a` on in `p`, and the additions it needs, recursively: their keys take the code's
/// defaults (Params{}); an addition under trial (not in_default) takes its key's upper bound.
void switch_on(Params& p, const Addition& a);

/// Whether `a` is on in `p`: some key of it differs from its off value.
bool is_on(const Params& p, const Addition& a);

/// SPEC §7's default of a row, where the code's default departs from it (v_max, the three deltas);
/// nullptr when the code's default is SPEC's.
const Setting* spec_default(std::string_view key);

/// SPEC's controller: every SPEC §7 row at SPEC's default (v_max 10 cm/s, delta 5 / 15 / 20) and
/// every addition off.
Params paper_literal();

/// Which controller `p` is: "default" (every key at the code's default, genomes/default.toml),
/// "paper-literal" (paper_literal(), genomes/paper-literal.toml) or "custom".
std::string_view controller_name(const Params& p);

/// How many additions are on in `p`.
int additions_on(const Params& p);

}  // namespace swarmpath::sim
