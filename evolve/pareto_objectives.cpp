// SPDX-License-Identifier: MIT
#include "pareto_objectives.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace swarmpath::evolve {

std::string_view objective_name(ObjectiveKind k) {
  switch (k) {
    case ObjectiveKind::kPathRatio:
      return "path";
    case ObjectiveKind::kTicks:
      return "ticks";
    case ObjectiveKind::kRobotsFraction:
      return "robots";
  }
  return "?";
}

std::optional<ObjectiveKind> parse_objective(std::string_view name) {
  for (const ObjectiveKind k :
       {ObjectiveKind::kPathRatio, ObjectiveKind::kTicks, ObjectiveKind::kRobotsFraction}) {
    if (objective_name(k) == name) return k;
  }
  return std::nullopt;
}

Vector objective_values(const CandidateStats& s, const std::vector<ObjectiveKind>& kinds,
                        double fail_path_ratio) {
  Vector v;
  v.reserve(kinds.size());
  for (const ObjectiveKind k : kinds) {
    switch (k) {
      case ObjectiveKind::kPathRatio:
        v.push_back(std::isfinite(s.mean_path_ratio) ? s.mean_path_ratio : fail_path_ratio);
        break;
      case ObjectiveKind::kTicks:
        v.push_back(s.mean_ticks);
        break;
      case ObjectiveKind::kRobotsFraction:
        v.push_back(s.mean_robots_fraction);
        break;
    }
  }
  return v;
}

double success_violation(const CandidateStats& s, double min_success, bool penalised) {
  return std::max(0.0, min_success - s.success_rate) + (penalised ? 1.0 : 0.0);
}

double t_quantile_975(int df) {
  static constexpr std::array<double, 30> kTable = {
      12.706205, 4.302653, 3.182446, 2.776445, 2.570582, 2.446912, 2.364624, 2.306004, 2.262157, 2.228139,
      2.200985,  2.178813, 2.160369, 2.144787, 2.131450, 2.119905, 2.109816, 2.100922, 2.093024, 2.085963,
      2.079614,  2.073873, 2.068658, 2.063899, 2.059539, 2.055529, 2.051831, 2.048407, 2.045230, 2.042272};
  if (df < 1) return std::numeric_limits<double>::infinity();
  if (df <= 30) return kTable[static_cast<std::size_t>(df - 1)];
  // Cornish-Fisher expansion of t about the normal quantile z (Abramowitz & Stegun 26.7.5)
  const double z = 1.959963984540054, v = static_cast<double>(df);
  const double z2 = z * z, z3 = z2 * z, z5 = z3 * z2, z7 = z5 * z2, z9 = z7 * z2;
  return z + (z3 + z) / (4.0 * v) + (5.0 * z5 + 16.0 * z3 + 3.0 * z) / (96.0 * v * v) +
         (3.0 * z7 + 19.0 * z5 + 17.0 * z3 - 15.0 * z) / (384.0 * v * v * v) +
         (79.0 * z9 + 776.0 * z7 + 1482.0 * z5 - 1920.0 * z3 - 945.0 * z) / (92160.0 * v * v * v * v);
}

// mean and t interval of the values, summed in index order
Interval mean_interval(const std::vector<double>& x) {
  Interval r;
  r.n = static_cast<int>(x.size());
  if (x.empty()) {
    r.mean = std::numeric_limits<double>::quiet_NaN();
    r.half_width = std::numeric_limits<double>::infinity();
    return r;
  }
  double sum = 0.0;
  for (const double v : x) sum += v;
  const double n = static_cast<double>(x.size());
  r.mean = sum / n;
  if (x.size() < 2) {
    r.half_width = std::numeric_limits<double>::infinity();
    return r;
  }
  double sq = 0.0;
  for (const double v : x) sq += (v - r.mean) * (v - r.mean);
  const double sd = std::sqrt(sq / (n - 1.0));
  r.half_width = t_quantile_975(r.n - 1) * sd / std::sqrt(n);
  return r;
}

namespace {

// the value of one objective in one run; nullopt where it is not defined (the path of a failure)
std::optional<double> run_value(const RunScore& r, ObjectiveKind k) {
  switch (k) {
    case ObjectiveKind::kPathRatio:
      if (r.success && std::isfinite(r.path_ratio)) return r.path_ratio;
      return std::nullopt;
    case ObjectiveKind::kTicks:
      return r.ticks;
    case ObjectiveKind::kRobotsFraction:
      return r.robots_fraction;
  }
  return std::nullopt;
}

}  // namespace

std::vector<Interval> objective_intervals(std::span<const RunScore> runs,
                                          const std::vector<ObjectiveKind>& kinds, double fail_path_ratio) {
  std::vector<Interval> out;
  for (const ObjectiveKind k : kinds) {
    std::vector<double> x;
    for (const RunScore& r : runs) {
      if (const std::optional<double> v = run_value(r, k)) x.push_back(*v);
    }
    Interval i = mean_interval(x);
    if (k == ObjectiveKind::kPathRatio && x.empty()) i.mean = fail_path_ratio;  // as objective_values
    out.push_back(i);
  }
  return out;
}

std::vector<Interval> paired_differences(std::span<const RunScore> a, std::span<const RunScore> b,
                                         const std::vector<ObjectiveKind>& kinds) {
  if (a.size() != b.size()) {
    throw std::invalid_argument("paired_differences: " + std::to_string(a.size()) + " runs against " +
                                std::to_string(b.size()));
  }
  std::vector<Interval> out;
  for (const ObjectiveKind k : kinds) {
    std::vector<double> d;
    for (std::size_t i = 0; i < a.size(); ++i) {
      const std::optional<double> va = run_value(a[i], k), vb = run_value(b[i], k);
      if (va && vb) d.push_back(*va - *vb);
    }
    out.push_back(mean_interval(d));
  }
  return out;
}

}  // namespace swarmpath::evolve
