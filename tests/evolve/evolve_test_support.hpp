// SPDX-License-Identifier: MIT
// Helpers shared by the evolve tests: source paths, scratch folders, a tiny evolve config (one
// small arena, 8 robots, short runs) and fakes for the objective and the optimiser.
#pragma once

#include <atomic>
#include <filesystem>
#include <fstream>
#include <functional>
#include <mutex>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

#include "evolve/evolve_config.hpp"
#include "evolve/objective.hpp"
#include "evolve/optim/optimizer.hpp"

namespace swarmpath::evolve::testing {

inline std::string source(const std::string& rel) { return std::string(SWARMPATH_SOURCE_DIR) + "/" + rel; }

/// A fresh, empty folder for the running test.
inline std::filesystem::path scratch(const std::string& name) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const auto dir = std::filesystem::temp_directory_path() /
                   ("swarmpath_evolve_test_" + std::to_string(::getpid())) /
                   (std::string(info->test_suite_name()) + "." + info->name()) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void write_text(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

/// A tiny config: short_chain at 8 robots, 3000 ticks, 2 seeds; three tuned parameters.
inline std::string tiny_config(const std::string& optimizer = "random", int generations = 2,
                               const std::string& extra_tune = "") {
  return "name = \"tiny\"\n"
         "params = \"" +
         source("genomes/paper.toml") +
         "\"\n"
         "mode = \"pf\"\n"
         "seed = 7\n"
         "\n[tune]\n"
         "w_away = {}\n"
         "p_turn = { lo = 0.002, hi = 0.2, log = true }\n"
         "T_explore0 = { lo = 200, hi = 2000, step = 50 }\n" +
         extra_tune +
         "\n[evaluation]\n"
         "scenarios = [\"" +
         source("tests/data/short_chain.toml") +
         "\"]\n"
         "robots = [8]\n"
         "seeds = 2\n"
         "max_ticks = 3000\n"
         "\n[optimizer]\n"
         "name = \"" +
         optimizer +
         "\"\n"
         "population = 4\n"
         "\n[budget]\n"
         "generations = " +
         std::to_string(generations) +
         "\n"
         "\n[reevaluate]\n"
         "top_k = 2\n"
         "seeds = 2\n";
}

inline EvolveConfig tiny(const std::string& optimizer = "random", int generations = 2) {
  return parse_evolve_config(tiny_config(optimizer, generations), "tiny.toml", "");
}

/// An objective whose score is a function of (params, case), recording every call.
class FakeObjective final : public CaseObjective {
 public:
  using Score = std::function<double(const sim::Params&, const EvalCase&)>;

  FakeObjective(std::vector<EvalSetting> settings, Score score)
      : settings_(std::move(settings)), score_(std::move(score)) {}

  const std::vector<EvalSetting>& settings() const override { return settings_; }

  RunScore evaluate(const sim::Params& p, const EvalCase& c) const override {
    RunScore s;
    s.fitness = score_(p, c);
    s.success = true;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      calls_.push_back({p, c});
    }
    return s;
  }

  RunScore penalty(const EvalCase&) const override {
    ++penalties_;
    RunScore s;
    s.fitness = 100.0;
    return s;
  }

  struct Call {
    sim::Params params;
    EvalCase c;
  };

  std::vector<Call> calls() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return calls_;
  }

  int penalties() const { return penalties_; }

 private:
  std::vector<EvalSetting> settings_;
  Score score_;
  mutable std::mutex mutex_;
  mutable std::vector<Call> calls_;
  mutable std::atomic<int> penalties_{0};
};

/// An optimiser that proposes the same fixed batch every generation.
class FixedOptimizer final : public Optimizer {
 public:
  explicit FixedOptimizer(std::vector<Vector> batch) : batch_(std::move(batch)) {}

  std::string name() const override { return "fixed"; }

  std::vector<Vector> ask() override { return batch_; }

  void tell(const std::vector<Vector>& xs, const std::vector<double>& f) override {
    for (std::size_t i = 0; i < xs.size(); ++i) {
      if (f[i] < best_f_) {
        best_f_ = f[i];
        best_x_ = xs[i];
      }
    }
    ++told_;
  }

  Vector best_x() const override { return best_x_; }

  double best_f() const override { return best_f_; }

  nlohmann::json state() const override { return {{"told", told_}}; }

  void restore(const nlohmann::json& s) override { told_ = s.at("told").get<int>(); }

 private:
  std::vector<Vector> batch_;
  Vector best_x_;
  double best_f_ = 1e300;
  int told_ = 0;
};

}  // namespace swarmpath::evolve::testing
