// SPDX-License-Identifier: MIT
#include "checkpoint.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "sim/config_error.hpp"

namespace swarmpath::evolve {

namespace {

constexpr const char* kFormat = "swarmpath evolve checkpoint";
constexpr int kVersion = 2;  // 2: stats and history carry the multi-objective fields

// NaN (no successful run) as null
nlohmann::ordered_json number_or_null(double v) {
  return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
}

double number_from(const nlohmann::json& j, const char* key) {
  const nlohmann::json& v = j.at(key);
  if (v.is_null()) return std::numeric_limits<double>::quiet_NaN();
  return v.get<double>();
}

}  // namespace

nlohmann::ordered_json stats_json(const CandidateStats& s) {
  nlohmann::ordered_json j;
  j["fitness"] = number_or_null(s.fitness);
  j["success_rate"] = s.success_rate;
  j["mean_ticks"] = s.mean_ticks;
  j["mean_path_ratio"] = number_or_null(s.mean_path_ratio);
  j["mean_robots"] = s.mean_robots;
  j["mean_robots_fraction"] = s.mean_robots_fraction;
  j["runs"] = s.runs;
  return j;
}

CandidateStats stats_from_json(const nlohmann::json& j) {
  CandidateStats s;
  s.fitness = number_from(j, "fitness");
  if (std::isnan(s.fitness)) s.fitness = std::numeric_limits<double>::infinity();
  s.success_rate = j.at("success_rate").get<double>();
  s.mean_ticks = j.at("mean_ticks").get<double>();
  s.mean_path_ratio = number_from(j, "mean_path_ratio");
  s.mean_robots = j.at("mean_robots").get<double>();
  s.mean_robots_fraction = j.at("mean_robots_fraction").get<double>();
  s.runs = j.at("runs").get<int>();
  return s;
}

nlohmann::ordered_json checkpoint_json(const RunState& s) {
  nlohmann::ordered_json j;
  j["format"] = kFormat;
  j["version"] = kVersion;
  j["config_hash"] = s.config_hash;
  j["generation"] = s.generation;
  j["evaluations"] = s.evaluations;
  j["runs"] = s.runs;
  j["seconds"] = s.seconds;
  j["optimizer"] = s.optimizer;
  nlohmann::ordered_json history = nlohmann::ordered_json::array();
  for (const GenerationRecord& r : s.history) {
    history.push_back({{"generation", r.generation},
                       {"best", r.best},
                       {"mean", r.mean},
                       {"std", r.std},
                       {"best_so_far", r.best_so_far},
                       {"best_success_rate", r.best_success_rate},
                       {"evaluations", r.evaluations},
                       {"seconds", r.seconds},
                       {"hypervolume", r.hypervolume},
                       {"front_size", r.front_size},
                       {"feasible", r.feasible},
                       {"front_min", r.front_min},
                       {"tuned_best", r.tuned_best},
                       {"tuned_mean", r.tuned_mean},
                       {"tuned_min", r.tuned_min},
                       {"tuned_max", r.tuned_max}});
    if (r.validation_runs > 0) {
      history.back()["validation_runs"] = r.validation_runs;
      history.back()["validation_fitness"] = r.validation_fitness;
      history.back()["validation_success_rate"] = r.validation_success_rate;
    }
  }
  j["history"] = history;
  nlohmann::ordered_json elites = nlohmann::ordered_json::array();
  for (const Elite& e : s.elites) {
    elites.push_back({{"x", e.x},
                      {"values", e.values},
                      {"generation", e.generation},
                      {"candidate", e.candidate},
                      {"stats", stats_json(e.stats)}});
  }
  j["elites"] = elites;
  return j;
}

RunState checkpoint_from_json(const nlohmann::json& j) {
  try {
    if (j.at("format").get<std::string>() != kFormat)
      throw std::runtime_error("not a swarmpath evolve checkpoint");
    if (j.at("version").get<int>() != kVersion) {
      throw std::runtime_error("checkpoint version " + j.at("version").dump() + " (this build reads " +
                               std::to_string(kVersion) + ")");
    }
    RunState s;
    s.config_hash = j.at("config_hash").get<std::string>();
    s.generation = j.at("generation").get<std::int64_t>();
    s.evaluations = j.at("evaluations").get<std::int64_t>();
    s.runs = j.at("runs").get<std::int64_t>();
    s.seconds = j.at("seconds").get<double>();
    s.optimizer = j.at("optimizer");
    for (const nlohmann::json& r : j.at("history")) {
      GenerationRecord g;
      g.generation = r.at("generation").get<std::int64_t>();
      g.best = r.at("best").get<double>();
      g.mean = r.at("mean").get<double>();
      g.std = r.at("std").get<double>();
      g.best_so_far = r.at("best_so_far").get<double>();
      g.best_success_rate = r.at("best_success_rate").get<double>();
      g.evaluations = r.at("evaluations").get<std::int64_t>();
      g.seconds = r.at("seconds").get<double>();
      g.hypervolume = r.at("hypervolume").get<double>();
      g.front_size = r.at("front_size").get<int>();
      g.feasible = r.at("feasible").get<int>();
      g.front_min = r.at("front_min").get<Vector>();
      // the tuned values came later: checkpoints without them still resume
      for (auto [key, v] : {std::pair{"tuned_best", &g.tuned_best},
                            {"tuned_mean", &g.tuned_mean},
                            {"tuned_min", &g.tuned_min},
                            {"tuned_max", &g.tuned_max}}) {
        if (r.contains(key)) *v = r.at(key).get<Vector>();
      }
      if (r.contains("validation_runs")) {
        g.validation_runs = r.at("validation_runs").get<int>();
        g.validation_fitness = r.at("validation_fitness").get<double>();
        g.validation_success_rate = r.at("validation_success_rate").get<double>();
      }
      s.history.push_back(g);
    }
    for (const nlohmann::json& e : j.at("elites")) {
      Elite el;
      el.x = e.at("x").get<Vector>();
      el.values = e.at("values").get<std::vector<double>>();
      el.generation = e.at("generation").get<std::int64_t>();
      el.candidate = e.at("candidate").get<int>();
      el.stats = stats_from_json(e.at("stats"));
      s.elites.push_back(std::move(el));
    }
    if (s.generation < 0 || static_cast<std::size_t>(s.generation) != s.history.size()) {
      throw std::runtime_error("generation count and history disagree");
    }
    return s;
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(std::string("malformed checkpoint: ") + e.what());
  }
}

RunState read_checkpoint(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw sim::ConfigError(path, 0, "", "cannot resume: no checkpoint here (run without --resume to start)");
  try {
    return checkpoint_from_json(nlohmann::json::parse(in));
  } catch (const nlohmann::json::exception& e) {
    throw sim::ConfigError(path, 0, "", std::string("cannot resume: not JSON: ") + e.what());
  } catch (const std::runtime_error& e) {
    throw sim::ConfigError(path, 0, "", std::string("cannot resume: ") + e.what());
  }
}

}  // namespace swarmpath::evolve
