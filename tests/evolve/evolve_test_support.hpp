// SPDX-License-Identifier: MIT
// What the evolve tests share: source paths, scratch folders, a tiny evolve config (one
// small arena, 8 robots, short runs) and fakes for the objective and the optimiser.
#pragma once

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <functional>
#include <mutex>
#include <optional>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

#include "evolve/evolve_config.hpp"
#include "evolve/objective.hpp"
#include "evolve/optim/optimizer.hpp"
#include "evolve/runner.hpp"
#include "sim/config_error.hpp"
#include "sim/scenario.hpp"

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

/// Options for a test run into `dir`: no wall time (files compare bit for bit), no callbacks.
inline RunOptions test_options(const std::filesystem::path& dir, int threads,
                               std::optional<int> generations = {}, bool resume = false) {
  RunOptions o;
  o.out_dir = dir.string();
  o.threads = threads;
  o.generations = generations;
  o.resume = resume;
  o.wall_time = false;
  return o;
}

/// run.json without what may differ between equal runs (the thread count).
inline std::string run_json_text(const std::filesystem::path& dir) {
  nlohmann::json j = nlohmann::json::parse(read_text(dir / "run.json"));
  j.erase("threads");
  return j.dump(1);
}

/// Runs `c` into three folders: at 1 thread, at 2 threads, and 1 generation at 2 threads resumed
/// to `generations` at 1 thread; expects the same files in all three; returns the first's run.json.
inline nlohmann::json expect_same_at_threads_and_resume(const EvolveConfig& c, const CaseObjective& f,
                                                        int generations) {
  const std::filesystem::path one = scratch("t1"), two = scratch("t2"), split = scratch("split");
  run_evolution(c, f, test_options(one, 1));
  run_evolution(c, f, test_options(two, 2));
  run_evolution(c, f, test_options(split, 2, 1));
  run_evolution(c, f, test_options(split, 1, generations, /*resume=*/true));
  for (const char* name : {"log.csv", "best.toml", "checkpoint.json"}) {
    EXPECT_EQ(read_text(one / name), read_text(two / name)) << name;
    EXPECT_EQ(read_text(one / name), read_text(split / name)) << name;
  }
  EXPECT_EQ(run_json_text(one), run_json_text(two));
  EXPECT_EQ(run_json_text(one), run_json_text(split));
  return nlohmann::json::parse(read_text(one / "run.json"));
}

/// A tiny config: short_chain at 8 robots, 3000 ticks, 2 seeds; three tuned parameters.
inline std::string tiny_config(const std::string& optimizer = "random", int generations = 2,
                               const std::string& extra_tune = "") {
  return "name = \"tiny\"\n"
         "params = \"" +
         source("genomes/default.toml") +
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

/// The tiny config with NSGA-II over path, ticks and robots (success >= 0.5), population 8.
inline std::string tiny_pareto_config(int generations = 2, const std::string& objectives =
                                                               "use = [\"path\", \"ticks\", \"robots\"]\n"
                                                               "min_success = 0.5\n"
                                                               "reference = [2.0, 3000, 1.0]\n") {
  std::string text = tiny_config("nsga2", generations);
  const std::string population = "population = 4\n", top_k = "top_k = 2\n";
  text.replace(text.find(population), population.size(), "population = 8\n");
  text.erase(text.find(top_k), top_k.size());
  return text + "\n[objectives]\n" + objectives;
}

inline EvolveConfig tiny(const std::string& optimizer = "random", int generations = 2) {
  return parse_evolve_config(tiny_config(optimizer, generations), "tiny.toml", "");
}

// the 1-based line of the first occurrence of `needle` in `text`
inline int line_of(const std::string& text, const std::string& needle) {
  const auto pos = text.find(needle);
  EXPECT_NE(pos, std::string::npos) << needle;
  return 1 +
         static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(pos), '\n'));
}

inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  return text.replace(pos, from.size(), to);
}

// parses `text` and expects a ConfigError at the line of `marker` with `key`
inline void expect_error(const std::string& text, const std::string& marker, const std::string& key,
                         const std::string& words) {
  try {
    (void)parse_evolve_config(text, "bad.toml", "");
    ADD_FAILURE() << "no error for " << key;
  } catch (const sim::ConfigError& e) {
    EXPECT_EQ(e.file(), "bad.toml");
    EXPECT_EQ(e.line(), line_of(text, marker)) << e.what();
    EXPECT_EQ(e.key(), key) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).rfind("bad.toml:" + std::to_string(e.line()) + ": " + key + ": ", 0), 0u)
        << e.what();
  }
}

/// The simulation a fake objective names: one robot for one tick (its Metrics are ignored).
inline CaseSimulation one_tick(const EvalCase& c) {
  static const auto scenario = std::make_shared<const sim::Scenario>(
      sim::parse_scenario("name = \"one_tick\"\nclass = \"open\"\nnest = [-1.0, 0.0]\ngoal = [1.0, "
                          "0.0]\n[arena]\nsize = [4.0, 4.0]\n"
                          "[deployment]\nsize = [1.0, 1.0]\nrobots = 1\n[simulation]\nmax_ticks = 1\n",
                          "one_tick.toml"));
  return {scenario, sim::Mode::kPathFormation, c.seed};
}

/// An objective whose score is a function of (params, case), recording every call.
class FakeObjective final : public CaseObjective {
 public:
  using Score = std::function<double(const sim::Params&, const EvalCase&)>;

  FakeObjective(std::vector<EvalSetting> settings, Score score)
      : settings_(std::move(settings)), score_(std::move(score)) {}

  const std::vector<EvalSetting>& settings() const override { return settings_; }

  CaseSimulation simulation(const EvalCase& c) const override { return one_tick(c); }

  RunScore score(const sim::Params& p, const EvalCase& c, const sim::Metrics&) const override {
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
