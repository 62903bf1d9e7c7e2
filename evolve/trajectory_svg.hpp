// SPDX-License-Identifier: MIT
// One tuned parameter over the generations, as a small SVG chart: the best candidate's value, the
// population's mean and its min-max band, the base value and the value finally reported.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace swarmpath::evolve {

struct Trajectory {
  std::string name;
  double lo = 0.0, hi = 1.0;  ///< the gene's range
  double base = 0.0;          ///< the base params' value (NaN: unknown)
  double reported = 0.0;      ///< the value of the genome the run reports (NaN: none)
  std::vector<double> best;   ///< per generation: the best candidate's value (empty: none, e.g. NSGA-II)
  std::vector<double> mean, min, max;  ///< per generation, over the valid candidates
};

/// A 360 x 230 chart of one trajectory.
void write_trajectory_svg(std::ostream& out, const Trajectory& t);

}  // namespace swarmpath::evolve
