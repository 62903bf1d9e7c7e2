// SPDX-License-Identifier: MIT
// Wall-clock stopwatch for progress lines and logs; never an input to a simulation or a seed.
#pragma once

#include <chrono>

namespace swarmpath::evolve {

class Stopwatch {
 public:
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace swarmpath::evolve
