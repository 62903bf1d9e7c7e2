// SPDX-License-Identifier: MIT
// A checkpoint is not trusted: every field is checked on resume (type, range, length, and
// agreement with the config and with the rest of the checkpoint), and a field that does not read
// back is exit 2 naming the checkpoint file and the field, before anything runs or is written.
#include <filesystem>
#include <functional>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/cli.hpp"
#include "evolve_test_support.hpp"
#include "tests/app/cli_support.hpp"

namespace swarmpath::evolve {
namespace {

namespace fs = std::filesystem;
using app::cli_support::cli;
using testing::read_text;
using testing::scratch;
using testing::write_text;

struct Tampering {
  std::string field;  ///< the field the message must name
  std::string words;  ///< and what it must say
  std::function<void(nlohmann::json&)> change;
};

// a run of `config` stopped after two generations, in dir/good
fs::path two_generations(const fs::path& dir, const std::string& config) {
  write_text(dir / "run.toml", config);
  const auto r = cli({"evolve", "--config", (dir / "run.toml").string(), "--out", (dir / "good").string(),
                      "--threads", "2", "--generations", "2", "--no-wall-time"});
  EXPECT_EQ(r.code, 0) << r.err;
  return dir / "good";
}

// each tampering on a copy of the run: the resume exits 2 naming the file and the field, and
// leaves the folder as it was
void expect_refused(const fs::path& dir, const fs::path& good, const std::vector<Tampering>& cases) {
  int k = 0;
  for (const Tampering& t : cases) {
    const fs::path copy = dir / ("tampered" + std::to_string(k++));
    fs::copy(good, copy, fs::copy_options::recursive);
    nlohmann::json j = nlohmann::json::parse(read_text(copy / "checkpoint.json"));
    t.change(j);
    const std::string text = j.dump(1);
    write_text(copy / "checkpoint.json", text);
    const std::string log = read_text(copy / "log.csv");
    const auto r = cli({"evolve", "--config", (dir / "run.toml").string(), "--out", copy.string(),
                        "--threads", "2", "--generations", "3", "--resume", "--no-wall-time"});
    EXPECT_EQ(r.code, app::kExitBadInput) << t.field << "\n" << r.err;
    const std::string where = (copy / "checkpoint.json").string() + ": " + t.field + ": ";
    EXPECT_NE(r.err.find(where), std::string::npos) << where << "\n" << r.err;
    EXPECT_NE(r.err.find(t.words), std::string::npos) << t.field << ": " << t.words << "\n" << r.err;
    EXPECT_EQ(read_text(copy / "checkpoint.json"), text) << t.field;
    EXPECT_EQ(read_text(copy / "log.csv"), log) << t.field;
  }
}

TEST(CheckpointIntegrity, EveryRunFieldIsCheckedOnResume) {
  const fs::path dir = scratch("run");
  const fs::path good = two_generations(dir, testing::tiny_config("cmaes", 3));
  expect_refused(
      dir, good,
      {
          {"format", "not a swarmpath evolve checkpoint",
           [](nlohmann::json& j) { j["format"] = "something else"; }},
          {"version", "this build reads 2", [](nlohmann::json& j) { j["version"] = 1; }},
          {"generation", "expected an integer", [](nlohmann::json& j) { j["generation"] = 1.5; }},
          {"generation", "history", [](nlohmann::json& j) { j["generation"] = 5; }},
          {"evaluations", "history",
           [](nlohmann::json& j) { j["evaluations"] = j["evaluations"].get<int>() + 1; }},
          {"runs", "must lie in", [](nlohmann::json& j) { j["runs"] = -1; }},
          {"runs", "cases", [](nlohmann::json& j) { j["runs"] = j["runs"].get<int>() + 1; }},
          {"seconds", "must lie in", [](nlohmann::json& j) { j["seconds"] = -1.0; }},
          {"history[0].generation", "must be 0",
           [](nlohmann::json& j) { j["history"][0]["generation"] = 1; }},
          {"history[1].best_so_far", "lowest best",
           [](nlohmann::json& j) {
             j["history"][1]["best_so_far"] = j["history"][1]["best"].get<double>() + 1.0;
           }},
          {"history[0].mean", "at least the generation's best",
           [](nlohmann::json& j) { j["history"][0]["mean"] = j["history"][0]["best"].get<double>() - 1.0; }},
          {"history[0].tuned_best", "expected 3 numbers",
           [](nlohmann::json& j) { j["history"][0]["tuned_best"].push_back(0.5); }},
          {"history[1].tuned_max", "expected 3 numbers",
           [](nlohmann::json& j) { j["history"][1]["tuned_max"].erase(0); }},
          {"history[0].front_size", "must be 0",
           [](nlohmann::json& j) { j["history"][0]["front_size"] = 50; }},
          {"history[1].hypervolume", "must be 0",
           [](nlohmann::json& j) { j["history"][1]["hypervolume"] = 2.5; }},
          {"history[0].best_success_rate", "must lie in [0, 1]",
           [](nlohmann::json& j) { j["history"][0]["best_success_rate"] = 2.0; }},
          {"history[1].evaluations", "grow",
           [](nlohmann::json& j) { j["history"][1]["evaluations"] = j["history"][0]["evaluations"]; }},
          {"elites", "at most 2", [](nlohmann::json& j) { j["elites"].push_back(j["elites"][0]); }},
          {"elites[0].x", "must lie in [0, 1]", [](nlohmann::json& j) { j["elites"][0]["x"][0] = 1.5; }},
          {"elites[0].x", "expected 3 numbers", [](nlohmann::json& j) { j["elites"][0]["x"].erase(2); }},
          {"elites[0].values", "not what its x decodes to",
           [](nlohmann::json& j) {
             j["elites"][0]["values"][1] = j["elites"][0]["values"][1].get<double>() * 2.0;
           }},
          {"elites[0].stats.fitness", "must lie in",
           [](nlohmann::json& j) { j["elites"][0]["stats"]["fitness"] = -100; }},
          {"elites[0].stats.runs", "cases", [](nlohmann::json& j) { j["elites"][0]["stats"]["runs"] = 7; }},
          {"elites[0].generation", "must lie in [0, 1]",
           [](nlohmann::json& j) { j["elites"][0]["generation"] = 7; }},
          {"elites[0].stats.success_rate", "must lie in [0, 1]",
           [](nlohmann::json& j) { j["elites"][0]["stats"]["success_rate"] = -0.5; }},
          {"elites[1]", "order", [](nlohmann::json& j) { std::swap(j["elites"][0], j["elites"][1]); }},
      });
}

TEST(CheckpointIntegrity, EveryCmaesStateFieldIsCheckedOnResume) {
  const fs::path dir = scratch("run");
  const fs::path good = two_generations(dir, testing::tiny_config("cmaes", 3));
  expect_refused(
      dir, good,
      {
          {"optimizer.sigma", "must lie in", [](nlohmann::json& j) { j["optimizer"]["sigma"] = 0; }},
          {"optimizer.sigma", "must lie in", [](nlohmann::json& j) { j["optimizer"]["sigma"] = -1; }},
          {"optimizer.lambda", "must lie in", [](nlohmann::json& j) { j["optimizer"]["lambda"] = -5; }},
          {"optimizer.lambda", "population 4", [](nlohmann::json& j) { j["optimizer"]["lambda"] = 1000; }},
          {"optimizer.mean", "expected 3 numbers",
           [](nlohmann::json& j) { j["optimizer"]["mean"].push_back(0.5); }},
          {"optimizer.cov", "symmetric", [](nlohmann::json& j) { j["optimizer"]["cov"][0][1] = 5.0; }},
          {"optimizer.cov", "positive definite",
           [](nlohmann::json& j) {
             for (auto& row : j["optimizer"]["cov"])
               for (auto& v : row) v = 0.0;
           }},
          {"optimizer.rng", "all zero",
           [](nlohmann::json& j) {
             j["optimizer"]["rng"] = {0, 0, 0, 0};
           }},
          {"optimizer.generation", "expected an integer",
           [](nlohmann::json& j) { j["optimizer"]["generation"] = "two"; }},
          {"optimizer.optimizer", "'ga', not 'cmaes'",
           [](nlohmann::json& j) { j["optimizer"]["optimizer"] = "ga"; }},
          {"optimizer.restarts", "must lie in [0, 0]",
           [](nlohmann::json& j) { j["optimizer"]["restarts"] = 3; }},
      });
}

TEST(CheckpointIntegrity, GaAndNsga2StatesAreCheckedOnResume) {
  const fs::path ga_dir = scratch("ga");
  const fs::path ga = two_generations(ga_dir, testing::tiny_config("ga", 3));
  expect_refused(
      ga_dir, ga,
      {
          {"optimizer.population", "expected 4",
           [](nlohmann::json& j) { j["optimizer"]["population"].erase(0); }},
          {"optimizer.population[1]", "must lie in [0, 1]",
           [](nlohmann::json& j) { j["optimizer"]["population"][1][0] = -0.25; }},
          {"optimizer.fitness", "expected 4", [](nlohmann::json& j) { j["optimizer"]["fitness"].erase(0); }},
      });
  const fs::path nsga_dir = scratch("nsga2");
  const fs::path nsga = two_generations(nsga_dir, testing::tiny_pareto_config(3));
  expect_refused(nsga_dir, nsga,
                 {
                     {"optimizer.objectives[0]", "expected 3 numbers",
                      [](nlohmann::json& j) { j["optimizer"]["objectives"][0].erase(0); }},
                     {"optimizer.violation", "must lie in",
                      [](nlohmann::json& j) { j["optimizer"]["violation"][0] = -1; }},
                     {"elites", "expected 8", [](nlohmann::json& j) { j["elites"].erase(0); }},
                     {"history[0].front_min", "expected 3 numbers",
                      [](nlohmann::json& j) { j["history"][0]["front_min"] = {1.0}; }},
                 });
}

TEST(CheckpointIntegrity, AnotherConfigOrABrokenFileNamesTheCheckpoint) {
  const fs::path dir = scratch("run");
  const fs::path good = two_generations(dir, testing::tiny_config("cmaes", 3));
  expect_refused(dir, good,
                 {{"config_hash", "different config", [](nlohmann::json& j) { j["config_hash"] = "0"; }}});
  const fs::path broken = dir / "broken";
  fs::copy(good, broken, fs::copy_options::recursive);
  const std::string text = read_text(broken / "checkpoint.json");
  write_text(broken / "checkpoint.json", text.substr(0, text.size() / 2));
  const auto r =
      cli({"evolve", "--config", (dir / "run.toml").string(), "--out", broken.string(), "--resume"});
  EXPECT_EQ(r.code, app::kExitBadInput) << r.err;
  EXPECT_NE(r.err.find((broken / "checkpoint.json").string() + ": cannot resume: not JSON"),
            std::string::npos)
      << r.err;
}

// every value of a checkpoint, one at a time: a string where a number, list or null was is always refused
// (exit 2 naming the checkpoint), and a negative or huge number is refused or resumes, never exit 1, a crash
// or std::bad_alloc
void each_leaf(const nlohmann::json& j, const nlohmann::json::json_pointer& at,
               std::vector<nlohmann::json::json_pointer>& out) {
  if (j.is_object()) {
    for (const auto& [key, v] : j.items()) each_leaf(v, at / key, out);
  } else if (j.is_array() && !j.empty()) {
    for (std::size_t i = 0; i < j.size(); ++i) each_leaf(j[i], at / i, out);
  } else {
    out.push_back(at);
  }
}

TEST(CheckpointIntegrity, NoTamperedValueResumesIntoACrash) {
  const fs::path dir = scratch("leaves");
  const fs::path good = two_generations(dir, testing::tiny_config("cmaes", 3));
  const nlohmann::json original = nlohmann::json::parse(read_text(good / "checkpoint.json"));
  std::vector<nlohmann::json::json_pointer> leaves;
  each_leaf(original, nlohmann::json::json_pointer(), leaves);
  ASSERT_GT(leaves.size(), 50u);
  const fs::path copy = dir / "tampered";
  int refused = 0;
  for (const nlohmann::json::json_pointer& leaf : leaves) {
    for (const nlohmann::json& bad : {nlohmann::json("x"), nlohmann::json(-5), nlohmann::json(1e18)}) {
      if (original.at(leaf) == bad) continue;
      fs::remove_all(copy);
      fs::copy(good, copy, fs::copy_options::recursive);
      nlohmann::json j = original;
      j.at(leaf) = bad;
      write_text(copy / "checkpoint.json", j.dump());
      // the resume asks for no more generations: an accepted checkpoint only finishes the run
      const auto r = cli({"evolve", "--config", (dir / "run.toml").string(), "--out", copy.string(),
                          "--threads", "1", "--generations", "2", "--resume", "--no-wall-time"});
      const std::string what = leaf.to_string() + " = " + bad.dump() + "\n" + r.err;
      if (bad.is_string() && !original.at(leaf).is_string()) {  // a type changed
        EXPECT_EQ(r.code, app::kExitBadInput) << what;
      } else {
        EXPECT_TRUE(r.code == app::kExitOk || r.code == app::kExitBadInput) << what;
      }
      if (r.code == app::kExitBadInput) {
        ++refused;
        EXPECT_NE(r.err.find((copy / "checkpoint.json").string() + ": "), std::string::npos) << what;
      }
    }
  }
  EXPECT_GT(refused, static_cast<int>(leaves.size()));  // every string and most numbers
}

}  // namespace
}  // namespace swarmpath::evolve
