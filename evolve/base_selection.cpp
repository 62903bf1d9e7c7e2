// SPDX-License-Identifier: MIT
#include "base_selection.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "evolve/racing.hpp"

namespace swarmpath::evolve {

std::string_view keep_base_test_name(KeepBaseTest t) {
  return t == KeepBaseTest::kSignedRank ? "signed-rank" : "t";
}

std::optional<KeepBaseTest> parse_keep_base_test(std::string_view name) {
  for (const KeepBaseTest t : {KeepBaseTest::kPairedT, KeepBaseTest::kSignedRank}) {
    if (name == keep_base_test_name(t)) return t;
  }
  return std::nullopt;
}

double signed_rank_p_value(std::span<const double> d, double* w_plus) {
  std::vector<double> size;
  std::vector<bool> won;
  for (const double v : d) {
    if (v == 0.0) continue;
    size.push_back(std::abs(v));
    won.push_back(v > 0.0);
  }
  const std::size_t n = size.size();
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return size[a] < size[b]; });
  // doubled ranks are whole numbers even where tied sizes share their mean rank
  std::vector<std::size_t> rank2(n);
  for (std::size_t i = 0; i < n;) {
    std::size_t j = i;
    while (j < n && size[order[j]] == size[order[i]]) ++j;
    for (std::size_t k = i; k < j; ++k) rank2[order[k]] = i + j + 1;  // 2 x the mean of ranks i+1 .. j
    i = j;
  }
  std::size_t observed = 0, total = 0;
  for (std::size_t i = 0; i < n; ++i) {
    total += rank2[i];
    if (won[i]) observed += rank2[i];
  }
  if (w_plus != nullptr) *w_plus = 0.5 * static_cast<double>(observed);
  if (n == 0) return 1.0;
  if (n > kExactSignedRankPairs) {  // the normal approximation, ties in the variance, continuity corrected
    double var = 0.0;
    for (const std::size_t r : rank2) var += static_cast<double>(r * r) / 16.0;  // (r / 2)^2 / 4
    const double z =
        (0.5 * static_cast<double>(observed) - 0.25 * static_cast<double>(total) - 0.5) / std::sqrt(var);
    return 0.5 * std::erfc(z / std::sqrt(2.0));
  }
  // P(sum of doubled ranks with a + sign = s), each sign + or - with probability 1/2
  std::vector<double> prob(total + 1, 0.0);
  prob[0] = 1.0;
  std::size_t reach = 0;
  for (std::size_t i = 0; i < n; ++i) {
    reach += rank2[i];
    for (std::size_t s = reach + 1; s-- > 0;)
      prob[s] = 0.5 * prob[s] + (s >= rank2[i] ? 0.5 * prob[s - rank2[i]] : 0.0);
  }
  double p = 0.0;
  for (std::size_t s = observed; s <= total; ++s) p += prob[s];
  return std::min(p, 1.0);
}

BaseSelection select_against_base(std::span<const double> finalist, std::span<const double> base,
                                  int finalists, double level, KeepBaseTest test) {
  if (finalist.size() != base.size())
    throw std::invalid_argument("the finalist and the base ran other cases");
  BaseSelection s;
  s.on = true;
  s.finalists = finalists;
  s.level = level;
  s.threshold = level / static_cast<double>(std::max(finalists, 1));
  s.pairs = static_cast<int>(base.size());
  std::vector<double> d(base.size());
  for (std::size_t k = 0; k < d.size(); ++k) d[k] = base[k] - finalist[k];
  const double n = static_cast<double>(d.size());
  if (!d.empty()) {
    for (const double v : d) s.mean_difference += v;
    s.mean_difference /= n;
  }
  if (d.size() >= 2) {
    double ss = 0.0;
    for (const double v : d) ss += (v - s.mean_difference) * (v - s.mean_difference);
    s.sd_difference = std::sqrt(ss / (n - 1.0));
    if (s.sd_difference > 0.0) s.t = s.mean_difference / (s.sd_difference / std::sqrt(n));
  }
  s.test = test;
  s.p_value = test == KeepBaseTest::kSignedRank ? signed_rank_p_value(d, &s.w_plus) : paired_t_p_value(d);
  s.base_kept = !(s.p_value < s.threshold);
  return s;
}

}  // namespace swarmpath::evolve
