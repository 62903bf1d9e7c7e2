// SPDX-License-Identifier: MIT
#include "genome.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

namespace swarmpath::evolve {

namespace {

constexpr double kGridEps = 1e-9;  // grid-index slack against round-off, in steps

// the grid of a gene: origin + k * unit for k in [0, kmax]; unit 0 means continuous
struct Grid {
  double origin = 0.0;
  double unit = 0.0;
  double kmax = 0.0;
};

Grid grid_of(const Gene& g) {
  Grid grid;
  if (g.integer) {
    grid.origin = std::ceil(g.lo);
    grid.unit = std::max(1.0, std::round(g.step));
  } else {
    grid.origin = g.lo;
    grid.unit = g.step;
  }
  if (grid.unit > 0.0) grid.kmax = std::floor((g.hi - grid.origin) / grid.unit + kGridEps);
  return grid;
}

double at(const Grid& grid, double k) { return canonical(grid.origin + k * grid.unit); }

enum class Snap { kNearest, kDown, kUp };

// the grid index of v (unclamped)
double index_of(const Grid& grid, double v, Snap snap) {
  const double k = (v - grid.origin) / grid.unit;
  switch (snap) {
    case Snap::kNearest:
      return std::round(k);
    case Snap::kDown:
      return std::floor(k + kGridEps);
    case Snap::kUp:
      return std::ceil(k - kGridEps);
  }
  return std::round(k);
}

const Gene* gene_named(const Genome& g, std::string_view name) {
  for (const Gene& gene : g.genes) {
    if (gene.info->name == name) return &gene;
  }
  return nullptr;
}

// the largest value of `gene` that is <= limit (< limit when strict), or NaN when none lies in bounds
double highest_below(const Gene& gene, double limit, bool strict) {
  const Grid grid = grid_of(gene);
  double v = 0.0;
  if (grid.unit > 0.0) {
    double k = index_of(grid, limit, Snap::kDown);
    if (strict && at(grid, k) >= limit) k -= 1.0;
    if (k > grid.kmax) k = grid.kmax;
    if (k < 0.0) return std::numeric_limits<double>::quiet_NaN();
    v = at(grid, k);
  } else {
    v = canonical(std::min(gene.hi, strict ? limit - gene.info->step : limit));
  }
  return v >= gene.lo && v <= gene.hi ? v : std::numeric_limits<double>::quiet_NaN();
}

// the smallest value of `gene` that is >= limit (> limit when strict), or NaN
double lowest_above(const Gene& gene, double limit, bool strict) {
  const Grid grid = grid_of(gene);
  double v = 0.0;
  if (grid.unit > 0.0) {
    double k = index_of(grid, limit, Snap::kUp);
    if (strict && at(grid, k) <= limit) k += 1.0;
    if (k < 0.0) k = 0.0;
    if (k > grid.kmax) return std::numeric_limits<double>::quiet_NaN();
    v = at(grid, k);
  } else {
    v = canonical(std::max(gene.lo, strict ? limit + gene.info->step : limit));
  }
  return v >= gene.lo && v <= gene.hi ? v : std::numeric_limits<double>::quiet_NaN();
}

// SPEC §7's cross constraints as `lower <= upper` (or <), in the order they are repaired
struct Order {
  std::string_view lower;
  std::string_view upper;
  bool strict;
};

constexpr Order kOrders[] = {
    {"theta_soft", "theta_hard", false},
    {"theta_none", "theta_soft", false},
    {"R_keep", "R_vis", false},
    {"d_sub", "R_vis", true},
    {"T_explore0", "T_explore_max", false},
};

// repairs one pair; returns true when something moved
bool repair(const Genome& g, const Order& o, sim::Params& p) {
  const sim::ParamInfo& li = *sim::find_param(o.lower);
  const sim::ParamInfo& ui = *sim::find_param(o.upper);
  const double a = sim::get_value(p, li);
  const double b = sim::get_value(p, ui);
  if (o.strict ? a < b : a <= b) return false;
  if (const Gene* lg = gene_named(g, o.lower)) {
    if (const double v = highest_below(*lg, b, o.strict); !std::isnan(v)) {
      sim::set_value(p, li, v);
      return true;
    }
  }
  if (const Gene* ug = gene_named(g, o.upper)) {
    if (const double v = lowest_above(*ug, a, o.strict); !std::isnan(v)) {
      sim::set_value(p, ui, v);
      return true;
    }
  }
  return false;
}

}  // namespace

double canonical(double v) {
  if (!std::isfinite(v)) return v;
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 12);
  double out = v;
  std::from_chars(buf, res.ptr, out);
  return out;
}

bool Gene::binary() const {
  return info->type == sim::ParamType::kBool || info->type == sim::ParamType::kChoice;
}

Bounds Genome::bounds() const { return {Vector(genes.size(), 0.0), Vector(genes.size(), 1.0)}; }

Gene default_gene(const sim::ParamInfo& info) {
  Gene g;
  g.info = &info;
  g.lo = info.lo;
  g.hi = info.hi;
  g.integer = info.type == sim::ParamType::kInteger;
  return g;
}

namespace {

// a value of a numeric gene (in any units between its bounds) on the gene's grid
double snap_to_grid(const Gene& g, double raw) {
  const Grid grid = grid_of(g);
  if (grid.unit > 0.0) return at(grid, std::clamp(index_of(grid, raw, Snap::kNearest), 0.0, grid.kmax));
  return canonical(std::clamp(raw, g.lo, g.hi));
}

// repairs the cross constraints of d.params and records what is left
void repair_all(const Genome& g, Decoded& d) {
  // a repair may break an earlier pair (raising theta_soft for theta_none, say): a few passes
  for (int pass = 0; pass < 3; ++pass) {
    bool moved = false;
    for (const Order& o : kOrders) moved = repair(g, o, d.params) || moved;
    if (!moved) break;
    d.repaired = true;
  }
  d.violation = sim::check_params(d.params);
}

}  // namespace

double gene_value(const Gene& g, double x) {
  x = std::clamp(x, 0.0, 1.0);
  if (g.binary()) return x >= 0.5 ? 1.0 : 0.0;
  return snap_to_grid(g, g.log ? g.lo * std::pow(g.hi / g.lo, x) : g.lo + x * (g.hi - g.lo));
}

double gene_coordinate(const Gene& g, double v) {
  if (g.binary()) return v != 0.0 ? 0.75 : 0.25;
  v = std::clamp(v, g.lo, g.hi);
  const double x = g.log ? std::log(v / g.lo) / std::log(g.hi / g.lo) : (v - g.lo) / (g.hi - g.lo);
  return std::clamp(x, 0.0, 1.0);
}

Decoded decode(const Genome& g, std::span<const double> x) {
  Decoded d;
  d.params = g.base;
  for (std::size_t i = 0; i < g.genes.size(); ++i) {
    sim::set_value(d.params, *g.genes[i].info, gene_value(g.genes[i], i < x.size() ? x[i] : 0.5));
  }
  repair_all(g, d);
  return d;
}

Decoded decode_values(const Genome& g, std::span<const double> values) {
  Decoded d;
  d.params = g.base;
  std::string not_finite;
  for (std::size_t i = 0; i < g.genes.size() && i < values.size(); ++i) {
    const Gene& gene = g.genes[i];
    if (!std::isfinite(values[i]) && not_finite.empty())
      not_finite = std::string(gene.info->name) + " is not a number";
    const double v = gene.binary() ? (values[i] != 0.0 ? 1.0 : 0.0) : snap_to_grid(gene, values[i]);
    sim::set_value(d.params, *gene.info, v);
  }
  repair_all(g, d);
  if (!not_finite.empty()) d.violation = not_finite;  // never repaired into a value
  return d;
}

Vector encode(const Genome& g, const sim::Params& p) {
  Vector x(g.genes.size());
  for (std::size_t i = 0; i < g.genes.size(); ++i) {
    x[i] = gene_coordinate(g.genes[i], sim::get_value(p, *g.genes[i].info));
  }
  return x;
}

std::vector<std::pair<std::string, std::string>> tuned_values(const Genome& g, const sim::Params& p) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const Gene& gene : g.genes)
    out.emplace_back(std::string(gene.info->name), sim::format_value(p, *gene.info));
  return out;
}

std::vector<double> tuned_numbers(const Genome& g, const sim::Params& p) {
  std::vector<double> v;
  v.reserve(g.genes.size());
  for (const Gene& gene : g.genes) v.push_back(sim::get_value(p, *gene.info));
  return v;
}

}  // namespace swarmpath::evolve
