// SPDX-License-Identifier: MIT
#include "robustness.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace swarmpath::app {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Sums {
  int runs = 0;
  int successes = 0;
  double ticks = 0;
  double ratio = 0;
  double failures = 0;
  double chain_failures = 0;
  double allocated = 0;
  int allocating = 0;

  void add(const Sums& o) {
    runs += o.runs;
    successes += o.successes;
    ticks += o.ticks;
    ratio += o.ratio;
    failures += o.failures;
    chain_failures += o.chain_failures;
    allocated += o.allocated;
    allocating += o.allocating;
  }

  void add(const sim::Metrics& m, double astar8_tu) {
    ++runs;
    failures += m.failures;
    chain_failures += m.chain_failures;
    if (m.allocated >= 0) {
      allocated += m.allocated;
      ++allocating;
    }
    if (!m.success) return;
    ++successes;
    ticks += static_cast<double>(m.ticks_to_form);
    ratio += m.path_length_tu / astar8_tu;
  }

  RobustnessCell cell(sim::Mode mode, const std::string& scenario, std::size_t fail, std::size_t loss) const {
    RobustnessCell c;
    c.mode = mode;
    c.scenario = scenario;
    c.fail = fail;
    c.loss = loss;
    c.runs = runs;
    c.successes = successes;
    c.success_pct = runs > 0 ? 100.0 * successes / runs : kNaN;
    c.ticks_to_form = successes > 0 ? ticks / successes : kNaN;
    c.ratio_to_astar = successes > 0 ? ratio / successes : kNaN;
    c.failures = runs > 0 ? failures / runs : kNaN;
    c.chain_failures = runs > 0 ? chain_failures / runs : kNaN;
    c.allocated = allocating > 0 ? allocated / allocating : kNaN;
    return c;
  }
};

}  // namespace

std::vector<Variant> make_variants(std::size_t scenarios, const RobustnessGrid& g) {
  std::vector<Variant> out;
  for (std::size_t s = 0; s < scenarios; ++s) {
    for (std::size_t f = 0; f < g.fail_fractions.size(); ++f) {
      for (std::size_t l = 0; l < g.packet_losses.size(); ++l) out.push_back({s, f, l});
    }
  }
  return out;
}

std::vector<sim::Scenario> variant_scenarios(const std::vector<sim::Scenario>& base,
                                             const std::vector<Variant>& variants, const RobustnessGrid& g) {
  std::vector<sim::Scenario> out;
  out.reserve(variants.size());
  for (const Variant& v : variants) {
    sim::FaultModel f = base[v.scenario].faults;
    f.fail_fraction = g.fail_fractions[v.fail];
    f.packet_loss = g.packet_losses[v.loss];
    out.push_back(sim::with_faults(base[v.scenario], f, "--fail-fractions / --packet-loss"));
  }
  return out;
}

bool uses_radio(sim::Mode m, const RobustnessGrid& g) {
  return m == sim::Mode::kTaskAllocation || g.pf_radio;
}

std::vector<GridCase> robustness_cases(const std::vector<Variant>& variants, const std::vector<int>& robots,
                                       const std::vector<sim::Mode>& modes, int seeds,
                                       std::uint64_t seed_base, bool pf_radio) {
  const RobustnessGrid radio{{}, {}, pf_radio};
  std::vector<GridCase> grid;
  for (std::size_t v = 0; v < variants.size(); ++v) {
    for (const int n : robots) {
      for (const sim::Mode mode : modes) {
        if (!uses_radio(mode, radio) && variants[v].loss > 0) continue;  // stands for every loss
        for (int k = 0; k < seeds; ++k)
          grid.push_back({v, n, mode, seed_base + static_cast<std::uint64_t>(k)});
      }
    }
  }
  return grid;
}

const RobustnessCell& RobustnessReport::at(sim::Mode mode, std::size_t fail, std::size_t loss) const {
  for (const RobustnessCell& c : overall) {
    if (c.mode == mode && c.fail == fail && c.loss == loss) return c;
  }
  throw std::out_of_range("no robustness cell for this mode and condition");
}

const RobustnessCell& RobustnessReport::at(const std::string& group, sim::Mode mode, std::size_t fail,
                                           std::size_t loss) const {
  for (const RobustnessCell& c : per_group) {
    if (c.scenario == group && c.mode == mode && c.fail == fail && c.loss == loss) return c;
  }
  throw std::out_of_range("no robustness cell for this group, mode and condition");
}

RobustnessReport summarise_robustness(const std::vector<sim::Scenario>& base,
                                      const std::vector<double>& astar8_tu,
                                      const std::vector<Variant>& variants, const RobustnessGrid& g,
                                      const std::vector<sim::Mode>& modes, const std::vector<GridRun>& runs,
                                      const std::vector<std::string>& group_of) {
  if (!group_of.empty() && group_of.size() != base.size())
    throw std::invalid_argument("summarise_robustness: one group per scenario");
  RobustnessReport r;
  r.grid = g;
  r.modes = modes;
  for (const sim::Scenario& s : base) r.scenarios.push_back(s.name);
  const std::size_t nf = g.fail_fractions.size(), nl = g.packet_losses.size();
  // sums[mode][scenario][fail][loss], flattened
  const auto index = [&](std::size_t m, std::size_t s, std::size_t f, std::size_t l) {
    return ((m * base.size() + s) * nf + f) * nl + l;
  };
  std::vector<Sums> sums(modes.size() * base.size() * nf * nl);
  for (const GridRun& run : runs) {
    const Variant& v = variants[run.c.scenario];
    for (std::size_t m = 0; m < modes.size(); ++m) {
      if (modes[m] != run.c.mode) continue;
      // a run of a mode without radio stands for every packet loss
      const bool radio = uses_radio(run.c.mode, g);
      for (std::size_t l = 0; l < nl; ++l) {
        if (radio ? l == v.loss : v.loss == 0)
          sums[index(m, v.scenario, v.fail, l)].add(run.m, astar8_tu[v.scenario]);
      }
    }
  }
  for (std::size_t m = 0; m < modes.size(); ++m) {
    for (std::size_t f = 0; f < nf; ++f) {
      for (std::size_t l = 0; l < nl; ++l) {
        Sums all;
        for (std::size_t s = 0; s < base.size(); ++s) all.add(sums[index(m, s, f, l)]);
        r.overall.push_back(all.cell(modes[m], "", f, l));
      }
    }
  }
  for (std::size_t s = 0; s < base.size(); ++s) {
    for (std::size_t m = 0; m < modes.size(); ++m) {
      for (std::size_t f = 0; f < nf; ++f) {
        for (std::size_t l = 0; l < nl; ++l)
          r.per_scenario.push_back(sums[index(m, s, f, l)].cell(modes[m], base[s].name, f, l));
      }
    }
  }
  for (const std::string& name : group_of) {
    if (std::find(r.groups.begin(), r.groups.end(), name) == r.groups.end()) r.groups.push_back(name);
  }
  if (r.groups.size() < 2) return r;
  for (const std::string& name : r.groups) {
    for (std::size_t m = 0; m < modes.size(); ++m) {
      for (std::size_t f = 0; f < nf; ++f) {
        for (std::size_t l = 0; l < nl; ++l) {
          Sums group;
          for (std::size_t s = 0; s < base.size(); ++s) {
            if (group_of[s] == name) group.add(sums[index(m, s, f, l)]);
          }
          r.per_group.push_back(group.cell(modes[m], name, f, l));
        }
      }
    }
  }
  return r;
}

}  // namespace swarmpath::app
