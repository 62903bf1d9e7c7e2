// SPDX-License-Identifier: MIT
// mixed: each arena is drawn from one of the other families (uniformly, with that family's default
// parameters and this family's arena size and robots), then sprinkled with clutter that keeps a
// wide gap from every wall so that no passage closes.
#include "draw_support.hpp"
#include "family_list.hpp"
#include "registry.hpp"

namespace swarmpath::sim::arenas {

namespace {

// clang-format off
constexpr FamilyParam kParams[] = {
    {"clutter", 0.03, 0.0, 0.15, false, "", "share of the floor covered by extra clutter"},
};

// clang-format on

bool draw(const ParamValues& p, Rng& rng, Draft& d) {
  const Family* choices[] = {&open_family(),     &clutter_family(),    &wall_gap_family(), &u_trap_family(),
                             &corridor_family(), &serpentine_family(), &rooms_family()};
  const Family& f = *choices[rng.below(std::size(choices))];
  // the drawn family's defaults, with this family's common parameters
  std::vector<FamilyParam> params = all_params(f);
  std::vector<double> values;
  for (const FamilyParam& q : params) {
    const bool common = q.name == "width" || q.name == "height" || q.name == "robots";
    values.push_back(common ? p(q.name) : q.fallback);
  }
  const ParamValues sub(std::move(params), std::move(values));
  std::string key;
  if (f.check != nullptr && !f.check(sub, key).empty()) return false;  // e.g. rooms in a narrow arena
  if (!f.draw(sub, rng, d)) return false;
  scatter_clutter(d, rng, {p("clutter"), 0.2, 0.5, 0.4, 0.8, 0});
  d.note = "mixed: drew " + std::string(f.name) + " (its defaults) plus clutter";
  return true;
}

}  // namespace

const Family& mixed_family() {
  static const Family f{"mixed", "one of the other families at its defaults, drawn at random, plus clutter",
                        kParams, draw, nullptr};
  return f;
}

}  // namespace swarmpath::sim::arenas
