// SPDX-License-Identifier: MIT
// The multi-objective runner (optimizer = "nsga2"): bit-identical at 1 and 2 threads, exact
// resume, the front it reports is feasible and non-dominated, re-evaluation on fresh seeds marks
// the points that noise had flattered, and the files hold what the run found.
#include "evolve/pareto_runner.hpp"

#include <cmath>
#include <filesystem>
#include <mutex>
#include <sstream>

#include <gtest/gtest.h>

#include "evolve/optim/hypervolume.hpp"
#include "evolve/optim/nsga2.hpp"
#include "evolve/pareto_report.hpp"
#include "evolve/seeds.hpp"
#include "evolve_test_support.hpp"

namespace swarmpath::evolve {
namespace {

using testing::read_text;
using testing::scratch;

namespace fs = std::filesystem;

EvolveConfig tiny_pareto(int generations, const std::string& objectives = "") {
  const std::string text = objectives.empty() ? testing::tiny_pareto_config(generations)
                                              : testing::tiny_pareto_config(generations, objectives);
  return parse_evolve_config(text, "tiny.toml", "");
}

ParetoResult run(const EvolveConfig& c, const CaseObjective& f, const fs::path& dir, int threads,
                 std::optional<int> generations = {}, bool resume = false) {
  return run_pareto(c, f, testing::test_options(dir, threads, generations, resume));
}

void expect_same_files(const fs::path& a, const fs::path& b, std::size_t front) {
  for (const char* name : {"log.csv", "checkpoint.json", "hypervolume.svg", "pareto.csv", "pareto.svg"}) {
    const std::string ta = read_text(a / name);
    EXPECT_FALSE(ta.empty()) << name;
    EXPECT_EQ(ta, read_text(b / name)) << name;
  }
  for (std::size_t i = 0; i < front; ++i) {
    const std::string name = "front/" + front_file_name(i);
    EXPECT_EQ(read_text(a / name), read_text(b / name)) << name;
  }
  EXPECT_EQ(testing::run_json_text(a), testing::run_json_text(b));
}

// A fake with a known trade-off: w_away = a in [0, 2] gives ticks 1000 (1 + a) and robots used
// 1 - a / 2, so every candidate is on the true front in (ticks, robots); success everywhere.
// `noise` adds a seed-dependent term to the ticks.
class TradeOff final : public CaseObjective {
 public:
  explicit TradeOff(double noise = 0.0) : noise_(noise) {}

  const std::vector<EvalSetting>& settings() const override { return settings_; }

  CaseSimulation simulation(const EvalCase& c) const override { return testing::one_tick(c); }

  RunScore score(const sim::Params& p, const EvalCase& c, const sim::Metrics&) const override {
    RunScore s;
    s.success = true;
    s.ticks = 1000.0 * (1.0 + p.w_away) + noise_ * static_cast<double>(c.seed % 1000);
    s.path_ratio = 1.0 + 0.01 * p.p_turn;
    s.robots_fraction = 1.0 - p.w_away / 2.0;
    s.robots_used = 8.0 * s.robots_fraction;
    const std::lock_guard<std::mutex> lock(mutex_);
    ++calls_;
    return s;
  }

  RunScore penalty(const EvalCase&) const override {
    RunScore s;
    s.ticks = 3000.0;
    return s;
  }

  int calls() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return calls_;
  }

 private:
  std::vector<EvalSetting> settings_ = {{"s", 8, false}};
  double noise_;
  mutable std::mutex mutex_;
  mutable int calls_ = 0;
};

TEST(ParetoRunner, BitIdenticalAtOneAndTwoThreadsOnTheSimulator) {
  const EvolveConfig c = tiny_pareto(2);
  const SwarmObjective f(c);
  const fs::path one = scratch("t1"), two = scratch("t2");
  const ParetoResult r1 = run(c, f, one, 1);
  const ParetoResult r2 = run(c, f, two, 2);
  expect_same_files(one, two, r1.front.size());
  EXPECT_EQ(r1.state.generation, 2);
  EXPECT_EQ(r1.state.evaluations, 16);  // 2 generations x population 8
  ASSERT_FALSE(r1.front.empty());
  // the log's last hypervolume is the final front's, recomputed here from its objectives
  std::vector<Vector> front;
  for (const FrontPoint& p : r1.front) front.push_back(p.objectives);
  EXPECT_EQ(r1.hypervolume, hypervolume(front, c.multi.reference));
  EXPECT_EQ(r1.state.history.back().hypervolume, r1.hypervolume);
  EXPECT_EQ(r1.state.history.back().front_size, static_cast<int>(r1.front.size()));
}

TEST(ParetoRunner, ResumeContinuesExactly) {
  const EvolveConfig c = tiny_pareto(4);
  const TradeOff f(50.0);
  const fs::path straight = scratch("straight"), split = scratch("split");
  const ParetoResult whole = run(c, f, straight, 2);
  run(c, f, split, 2, 2);
  EXPECT_EQ(read_checkpoint((split / "checkpoint.json").string()).generation, 2);
  const ParetoResult resumed = run(c, f, split, 1, 4, /*resume=*/true);
  expect_same_files(straight, split, whole.front.size());
  EXPECT_EQ(resumed.front.size(), whole.front.size());
}

TEST(ParetoRunner, FrontIsFeasibleNonDominatedAndSpread) {
  const EvolveConfig c =
      tiny_pareto(6, "use = [\"ticks\", \"robots\"]\nmin_success = 0.5\nreference = [3000, 1.0]\n");
  const TradeOff f;
  const ParetoResult r = run(c, f, scratch("run"), 2);
  ASSERT_GE(r.front.size(), 4u);  // every candidate lies on the true front: the population spreads on it
  for (const FrontPoint& p : r.front) {
    EXPECT_GE(p.elite.stats.success_rate, 0.5);
    for (const FrontPoint& q : r.front) EXPECT_FALSE(dominates(q.objectives, p.objectives));
    // the objectives are those of the fake at the decoded params
    EXPECT_DOUBLE_EQ(p.objectives[0], 1000.0 * (1.0 + p.params.w_away));
    EXPECT_DOUBLE_EQ(p.objectives[1], 1.0 - p.params.w_away / 2.0);
    // noise-free: re-evaluation agrees, and nothing is dominated after it
    EXPECT_EQ(p.reevaluated_objectives, p.objectives);
    EXPECT_FALSE(p.dominated_after_reevaluation);
    EXPECT_EQ(p.intervals[0].half_width, 0.0);
  }
  // sorted by the first objective
  for (std::size_t i = 1; i < r.front.size(); ++i)
    EXPECT_LE(r.front[i - 1].objectives[0], r.front[i].objectives[0]);
  // the true front spans w_away in [0, 2]: NSGA-II's boundary points get there
  EXPECT_LT(r.front.front().params.w_away, 0.2);
  EXPECT_GT(r.front.back().params.w_away, 1.8);
  // the true front bounds 1000 with the reference point (the triangle between the line from
  // (1000, 1) to (3000, 0) and the corner (3000, 1)); k points on it hold at most k / (k + 1) of
  // it (evenly spread inside), so a population of 8 at most 8/9
  EXPECT_GT(r.hypervolume, 0.8 * 1000.0);
  EXPECT_LE(r.hypervolume, 1000.0 * 8.0 / 9.0 + 1e-9);
}

TEST(ParetoRunner, ReevaluationMarksPointsThatNoiseFlattered) {
  // ticks = 1000 (1 + a) + 400 * (seed mod 1000): the generation's luck differs from the fresh seeds'
  const EvolveConfig c =
      tiny_pareto(3, "use = [\"ticks\", \"robots\"]\nmin_success = 0.5\nreference = [500000, 1.0]\n");
  const TradeOff f(400.0);
  const ParetoResult r = run(c, f, scratch("run"), 2);
  ASSERT_FALSE(r.front.empty());
  // the same fresh cases for every point: the noise term is common, so the re-evaluated ticks keep
  // the order of w_away, and exactly the points that fresh seeds reveal as dominated are marked
  for (const FrontPoint& p : r.front) {
    bool dominated = false;
    for (const FrontPoint& q : r.front) {
      if (&p != &q && dominates(q.reevaluated_objectives, p.reevaluated_objectives)) dominated = true;
    }
    EXPECT_EQ(p.dominated_after_reevaluation, dominated);
    EXPECT_EQ(p.dominates_base, dominates(p.reevaluated_objectives, r.base.reevaluated_objectives));
    EXPECT_NE(p.reevaluated_objectives[0], p.objectives[0]);  // fresh seeds, other noise
    EXPECT_GT(p.intervals[0].half_width, 0.0);
    EXPECT_EQ(p.intervals[0].n, 2);  // 1 setting x 2 fresh seeds
    // paired on the same seeds, the common noise cancels: the difference to the base is exact
    ASSERT_EQ(p.versus_base.size(), 2u);
    EXPECT_NEAR(p.versus_base[0].mean, 1000.0 * (p.params.w_away - r.base.params.w_away), 1e-6);
    EXPECT_NEAR(p.versus_base[0].half_width, 0.0, 1e-6);
    EXPECT_EQ(p.versus_base[1].n, 2);
  }
  // the base params ran on the same fresh cases
  EXPECT_EQ(r.base.reevaluated.runs, 2);
  EXPECT_EQ(r.reevaluation_cases.size(), 2u);
}

TEST(ParetoRunner, FilesHoldTheFront) {
  const EvolveConfig c = tiny_pareto(3);
  const TradeOff f(10.0);
  const fs::path dir = scratch("run");
  // a stale front file from an earlier, larger run must not survive
  fs::create_directories(dir / "front");
  testing::write_text(dir / "front" / "099.toml", "stale");
  const ParetoResult r = run(c, f, dir, 2);
  EXPECT_FALSE(fs::exists(dir / "front" / "099.toml"));
  // one params file per point, reading back to the point's params
  for (std::size_t i = 0; i < r.front.size(); ++i) {
    const sim::Params p = sim::load_params((dir / "front" / front_file_name(i)).string());
    EXPECT_EQ(p.w_away, r.front[i].params.w_away);
    EXPECT_EQ(p.p_turn, r.front[i].params.p_turn);
    EXPECT_EQ(p.t_explore0, r.front[i].params.t_explore0);
  }
  EXPECT_FALSE(fs::exists(dir / "front" / front_file_name(r.front.size())));
  // pareto.csv: a header, one row per point, one for the base params
  std::istringstream csv(read_text(dir / "pareto.csv"));
  std::string line;
  std::vector<std::string> lines;
  while (std::getline(csv, line)) lines.push_back(line);
  ASSERT_EQ(lines.size(), r.front.size() + 2);
  EXPECT_EQ(
      lines[0].rfind("point,generation,candidate,T_explore0,w_away,p_turn,gen_path,gen_ticks,gen_robots,", 0),
      0u);
  EXPECT_NE(lines[0].find("ticks_mean,ticks_ci95_low,ticks_ci95_high,ticks_n"), std::string::npos);
  EXPECT_EQ(lines[1].rfind("000,", 0), 0u);
  EXPECT_EQ(lines.back().rfind("base,", 0), 0u);
  // log.csv: one row per generation with the hypervolume
  const std::string log = read_text(dir / "log.csv");
  EXPECT_EQ(
      log.rfind("generation,hypervolume,front_size,feasible,best_success_rate,min_path,min_ticks,min_robots,",
                0),
      0u);
  EXPECT_EQ(std::count(log.begin(), log.end(), '\n'), 4);
  // pareto.svg: three projections of three objectives, the base params marked
  const std::string svg = read_text(dir / "pareto.svg");
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("default.toml"), std::string::npos);
  EXPECT_NE(svg.find(">ticks to form</text>"), std::string::npos);
  EXPECT_NE(svg.find(">robots used / N</text>"), std::string::npos);
  EXPECT_NE(svg.find(">path / A*</text>"), std::string::npos);
  // run.json: the front with its intervals and flags
  const nlohmann::json j = nlohmann::json::parse(read_text(dir / "run.json"));
  EXPECT_EQ(j.at("front").size(), r.front.size());
  EXPECT_TRUE(j.at("front")[0].at("reevaluated_objectives").at("ticks").contains("ci95_low"));
  EXPECT_EQ(j.at("config").at("objectives").at("use")[1], "ticks");
}

TEST(ParetoRunner, NothingFeasibleIsAClearError) {
  const EvolveConfig c = tiny_pareto(1);

  class Fails final : public CaseObjective {
   public:
    const std::vector<EvalSetting>& settings() const override { return settings_; }

    CaseSimulation simulation(const EvalCase& k) const override { return testing::one_tick(k); }

    RunScore score(const sim::Params&, const EvalCase&, const sim::Metrics&) const override {
      RunScore s;
      s.ticks = 3000.0;
      return s;
    }

    RunScore penalty(const EvalCase& k) const override { return score({}, k, {}); }

   private:
    std::vector<EvalSetting> settings_ = {{"s", 8, false}};
  } f;

  try {
    run(c, f, scratch("run"), 1);
    ADD_FAILURE() << "reported a front of infeasible points";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("min_success"), std::string::npos) << e.what();
  }
}

TEST(ParetoRunner, ResumingWithOtherObjectivesIsRefused) {
  const EvolveConfig c = tiny_pareto(1);
  const TradeOff f;
  const fs::path dir = scratch("run");
  run(c, f, dir, 1);
  const EvolveConfig other =
      tiny_pareto(2, "use = [\"path\", \"ticks\"]\nmin_success = 0.5\nreference = [2.0, 3000]\n");
  EXPECT_THROW(run(other, f, dir, 1, 2, true), sim::ConfigError);
}

}  // namespace
}  // namespace swarmpath::evolve
