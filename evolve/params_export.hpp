// SPDX-License-Identifier: MIT
// A Params as other tools take it: JSON (name -> value, with units) and the attribute block of
// an ARGoS controller's <params> element (SPEC §7 names as attribute names).
#pragma once

#include <iosfwd>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "sim/params.hpp"

namespace swarmpath::evolve {

/// A parameter's value as JSON: a number, a boolean, or a choice's name.
nlohmann::ordered_json param_value_json(const sim::Params& p, const sim::ParamInfo& info);

/// name -> value for every parameter, in SPEC §7 order.
nlohmann::ordered_json params_values_json(const sim::Params& p);

/// name -> {value, unit, row, meaning} for every parameter, in SPEC §7 order.
nlohmann::ordered_json params_export_json(const sim::Params& p);

/// Which controller a Params runs: {"name": "default" | "paper-literal" | "custom", "additions_on": k,
/// "additions": total, "additions_off": [names]} (sim/additions.hpp).
nlohmann::ordered_json controller_json(const sim::Params& p);

/// The same in words, e.g. "default controller (41 of 41 additions beyond SPEC on)".
std::string controller_text(const sim::Params& p);

/// `<params name="value" ... />`, one attribute a line, preceded by an XML comment.
void write_argos_params(std::ostream& out, const sim::Params& p, std::string_view source);

}  // namespace swarmpath::evolve
