// SPDX-License-Identifier: MIT
// What `swarmpath robustness` writes: markdown tables (success, time, path / A*, failures against
// failure fraction and packet loss, with and without task allocation), JSON with every run and
// cell, and an SVG of the three measures against the failure fraction.
#pragma once

#include <iosfwd>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "robustness.hpp"

namespace swarmpath::app {

/// The drop in success (points) from no failures to 10 % failing at no packet loss, per mode, over
/// every scenario or one group's; nullopt where the grid lacks 0 or 0.1 (or 0 packet loss).
std::optional<double> success_drop_at_10pct(const RobustnessReport& r, sim::Mode mode,
                                            const std::string& group = "");

void write_robustness_markdown(std::ostream& out, const RobustnessReport& r);

nlohmann::ordered_json robustness_json(const RobustnessReport& r, const std::vector<sim::Scenario>& variants,
                                       const std::vector<GridRun>& runs,
                                       const std::vector<Variant>& variant_of,
                                       const std::vector<double>& astar8_tu);

void write_robustness_svg(std::ostream& out, const RobustnessReport& r, const std::string& subtitle);

}  // namespace swarmpath::app
