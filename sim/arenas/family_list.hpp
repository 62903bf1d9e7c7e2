// SPDX-License-Identifier: MIT
// The families, one per file; registry.cpp lists them.
#pragma once

#include "family.hpp"
#include "sim/scenario_writer.hpp"

namespace swarmpath::sim::arenas {

const Family& open_family();
const Family& clutter_family();
const Family& wall_gap_family();
const Family& u_trap_family();
const Family& corridor_family();
const Family& serpentine_family();
const Family& rooms_family();
const Family& mixed_family();

/// "`a` (x) must be <= `b` (y)" when a > b, else "" (with key = a): the min/max rule of a range.
std::string ordered(const ParamValues& p, std::string_view a, std::string_view b, std::string& key);

}  // namespace swarmpath::sim::arenas
