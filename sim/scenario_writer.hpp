// SPDX-License-Identifier: MIT
// Writes a Scenario as the TOML that load_scenario reads: every value explicit and printed so
// that it reads back to the very same double, so parse(write(s)) == s field by field.
#pragma once

#include <string>
#include <string_view>

#include "scenario.hpp"

namespace swarmpath::sim {

/// The scenario file of `s`, after `header` (comment lines, each starting with '#'; may be empty).
std::string write_scenario_toml(const Scenario& s, std::string_view header = {});

/// The shortest decimal text that reads back to `v` (a TOML float or integer).
std::string toml_number(double v);

/// A yaw in degrees whose deg2rad is exactly `yaw_rad` when one lies within a few ulps of
/// rad2deg(yaw_rad) (always so for a yaw the loader produced), else rad2deg(yaw_rad).
double yaw_degrees_exact(double yaw_rad);

}  // namespace swarmpath::sim
