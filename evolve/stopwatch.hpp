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

/// A run's wall time across resumes: the seconds its checkpoint had recorded plus this process's.
class RunClock {
 public:
  /// `before`: the checkpoint's seconds; `record`: false makes every recorded time 0 (files that
  /// are bit-identical from run to run)
  RunClock(double before, bool record) : before_(before), record_(record) {}

  /// For the wall-time budget, always the real value.
  double elapsed() const { return before_ + watch_.seconds(); }

  /// For log.csv, checkpoint.json and run.json.
  double recorded() const { return record_ ? elapsed() : 0.0; }

 private:
  Stopwatch watch_;
  double before_;
  bool record_;
};

}  // namespace swarmpath::evolve
