// SPDX-License-Identifier: MIT
// What `swarmpath table` writes: JSON (runs, cases, environments, summary, the paper's figures),
// one CSV line per run, and the paper's table in markdown with the paper's numbers beside ours.
#pragma once

#include <iosfwd>
#include <vector>

#include <nlohmann/json.hpp>

#include "table_report.hpp"

namespace swarmpath::app {

/// {"mode", "table_unit_cm", "runs": [...], "cases": [...], "environments": [...], "summary": {...},
/// "paper": {...}} for one mode.
nlohmann::ordered_json table_json(const std::vector<sim::Scenario>& scenarios,
                                  const std::vector<double>& astar8_tu, const std::vector<GridRun>& runs,
                                  const TableReport& report);

/// The same for `--mode both`: runs and cases of both modes, environments with "pf" and "ta"
/// columns, and the summary with every headline figure of SPEC §5.2.
nlohmann::ordered_json comparison_json(const std::vector<sim::Scenario>& scenarios,
                                       const std::vector<double>& astar8_tu, const std::vector<GridRun>& runs,
                                       const Comparison& c);

/// A CSV field (RFC 4180): quoted, with quotes doubled, when it holds a comma, a quote or a line break.
std::string csv_field(const std::string& text);

/// Text for a markdown table cell: '|' escaped.
std::string markdown_text(const std::string& text);

/// One line per run (any mode).
void write_runs_csv(std::ostream& out, const std::vector<sim::Scenario>& scenarios,
                    const std::vector<double>& astar8_tu, const std::vector<GridRun>& runs);

/// The paper's table for one mode, our figures beside the paper's.
void write_markdown(std::ostream& out, const TableReport& report);

/// The paper's whole table (time, A*, path without/with TA, resource reduction) and its claims.
void write_markdown(std::ostream& out, const Comparison& c);

}  // namespace swarmpath::app
