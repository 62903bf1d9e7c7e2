// SPDX-License-Identifier: MIT
// The robustness experiment: every (scenario, robots, mode, seed) case under each failure
// fraction and packet loss, and what it measures: success, time to form and path / A* against
// both, per mode (with and without task allocation), over all scenarios and per scenario.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "experiment.hpp"
#include "sim/scenario.hpp"

namespace swarmpath::app {

/// The sweep: failure fractions x packet losses, on top of each scenario's own fault model.
struct RobustnessGrid {
  std::vector<double> fail_fractions{0.0, 0.05, 0.1, 0.2};
  std::vector<double> packet_losses{0.0, 0.1, 0.3};
  bool pf_radio = false;  ///< path formation listens to the medium too (share_sighting > 0)
};

/// Whether runs of mode `m` depend on the packet loss: task allocation's always, path
/// formation's only with share_sighting (g.pf_radio).
bool uses_radio(sim::Mode m, const RobustnessGrid& g);

/// One scenario under one condition (what run_grid simulates).
struct Variant {
  std::size_t scenario = 0;  ///< index into the base scenarios
  std::size_t fail = 0;      ///< index into fail_fractions
  std::size_t loss = 0;      ///< index into packet_losses
};

/// The variants, scenario-major, then failure fraction, then packet loss; each scenario's fault
/// model with the condition's fail_fraction and packet_loss.
std::vector<Variant> make_variants(std::size_t scenarios, const RobustnessGrid& g);
std::vector<sim::Scenario> variant_scenarios(const std::vector<sim::Scenario>& base,
                                             const std::vector<Variant>& variants, const RobustnessGrid& g);

/// Every (variant, robots, mode, seed), the same seeds in every variant (paired runs). Path
/// formation without share_sighting never listens to the medium (its runs are bit-identical under
/// any packet loss), so it is run at the first packet loss only and stands for the others; with
/// it (pf_radio) it is run at every packet loss.
std::vector<GridCase> robustness_cases(const std::vector<Variant>& variants, const std::vector<int>& robots,
                                       const std::vector<sim::Mode>& modes, int seeds,
                                       std::uint64_t seed_base, bool pf_radio = false);

/// Means over the runs of one (mode, failure fraction, packet loss), over all scenarios or one.
struct RobustnessCell {
  sim::Mode mode = sim::Mode::kPathFormation;
  std::string scenario;  ///< empty: every scenario; else a scenario's name, or a group's
  std::size_t fail = 0;
  std::size_t loss = 0;
  int runs = 0;
  int successes = 0;
  double success_pct = 0;     ///< 100 successes / runs
  double ticks_to_form = 0;   ///< mean T_form over the successful runs (NaN: none)
  double ratio_to_astar = 0;  ///< mean path / A* (8-connected) over the successful runs
  double failures = 0;        ///< mean robots failed per run (before the run ended)
  double chain_failures = 0;  ///< mean robots failed while holding a chain link
  double allocated = 0;       ///< task allocation: mean robots allocated (NaN otherwise)
};

struct RobustnessReport {
  RobustnessGrid grid;
  std::vector<sim::Mode> modes;
  std::vector<std::string> scenarios;
  std::vector<RobustnessCell> overall;       ///< mode-major, then fail, then loss
  std::vector<RobustnessCell> per_scenario;  ///< scenario-major, then mode, fail, loss
  std::vector<std::string> groups;           ///< the scenarios' groups, first seen first (paper, benchmark)
  std::vector<RobustnessCell> per_group;     ///< group-major, then mode, fail, loss (two groups or more)

  /// The cell of (mode, fail, loss) over every scenario, or over one group's.
  const RobustnessCell& at(sim::Mode mode, std::size_t fail, std::size_t loss) const;
  const RobustnessCell& at(const std::string& group, sim::Mode mode, std::size_t fail,
                           std::size_t loss) const;
};

/// Aggregates the runs (in robustness_cases order, any subset of modes); astar8_tu per base
/// scenario; group_of (empty, or one name per base scenario) also sums them by group.
RobustnessReport summarise_robustness(const std::vector<sim::Scenario>& base,
                                      const std::vector<double>& astar8_tu,
                                      const std::vector<Variant>& variants, const RobustnessGrid& g,
                                      const std::vector<sim::Mode>& modes, const std::vector<GridRun>& runs,
                                      const std::vector<std::string>& group_of = {});

}  // namespace swarmpath::app
