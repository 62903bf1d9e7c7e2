// SPDX-License-Identifier: MIT
#include "base_selection.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "evolve/racing.hpp"

namespace swarmpath::evolve {

BaseSelection select_against_base(std::span<const double> finalist, std::span<const double> base,
                                  int finalists, double level) {
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
  s.p_value = paired_t_p_value(d);
  s.base_kept = !(s.p_value < s.threshold);
  return s;
}

}  // namespace swarmpath::evolve
