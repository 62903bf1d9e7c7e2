// SPDX-License-Identifier: MIT
#include "checkpoint.hpp"

#include <algorithm>
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

// what every refusal of a checkpoint field adds
constexpr const char* kDamaged = " (the checkpoint was damaged or edited: cannot resume)";

// NaN (no successful run) as null
nlohmann::ordered_json number_or_null(double v) {
  return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
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

CandidateStats stats_from_state(const StateReader& r) {
  constexpr double kInf = StateReader::kInf;
  CandidateStats s;
  s.fitness = r.number_or_null("fitness", 0.0, kInf);
  if (std::isnan(s.fitness)) s.fitness = kInf;
  s.success_rate = r.number("success_rate", 0.0, 1.0);
  s.mean_ticks = r.number("mean_ticks", 0.0, kInf);
  s.mean_path_ratio = r.number_or_null("mean_path_ratio", 0.0, kInf);
  s.mean_robots = r.number("mean_robots", 0.0, kInf);
  s.mean_robots_fraction = r.number("mean_robots_fraction", 0.0, 1.0);
  s.runs = static_cast<int>(r.integer("runs", 0, std::numeric_limits<std::int32_t>::max()));
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
    if (r.capped_runs > 0 || r.reruns > 0) {  // capping only: other checkpoints stay as they were
      history.back()["capping"] = {{"candidates", r.capped_candidates},
                                   {"capped_runs", r.capped_runs},
                                   {"reruns", r.reruns},
                                   {"ticks_capped", r.ticks_capped},
                                   {"ticks_rerun", r.ticks_rerun}};
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
  // every field is read strictly (StateReader) and checked against the rest of the checkpoint
  const StateReader r(j, "");
  if (r.text("format") != kFormat) r.fail("format", "not a swarmpath evolve checkpoint");
  if (const std::int64_t v = r.integer("version", 0, 1000); v != kVersion) {
    r.fail("version", "checkpoint version " + std::to_string(v) + " (this build reads " +
                          std::to_string(kVersion) + ")");
  }
  constexpr double kInf = StateReader::kInf;
  constexpr std::int64_t kBig = std::int64_t{1} << 53;
  constexpr std::int64_t kInt = std::numeric_limits<std::int32_t>::max();
  RunState s;
  s.config_hash = r.text("config_hash");
  s.generation = r.integer("generation", 0, kBig);
  s.evaluations = r.integer("evaluations", 0, kBig);
  s.runs = r.integer("runs", 0, kBig);
  s.seconds = r.number("seconds", 0.0, kInf);
  (void)r.object("optimizer");
  s.optimizer = r.at("optimizer");
  for (const StateReader& h : r.objects("history")) {
    GenerationRecord g;
    const auto i = static_cast<std::int64_t>(s.history.size());
    g.generation = h.integer("generation", 0, kBig);
    if (g.generation != i)
      h.fail("generation", "must be " + std::to_string(i) + " (the rows count generations)");
    g.best = h.number("best", -kInf, kInf);
    g.mean = h.number("mean", -kInf, kInf);
    // the mean of a generation's fitness values is never below their best (up to its last bits)
    if (g.mean < g.best - 1e-9 * std::max(1.0, std::fabs(g.best))) {
      h.fail("mean", "must be at least the generation's best (" + number_text(g.best) + "), got " +
                         number_text(g.mean));
    }
    g.std = h.number("std", 0.0, kInf);
    g.best_so_far = h.number("best_so_far", -kInf, kInf);
    const double lowest = i == 0 ? g.best : std::min(s.history.back().best_so_far, g.best);
    if (g.best_so_far != lowest) {
      h.fail("best_so_far", "must be the lowest best so far (" + number_text(lowest) + "), got " +
                                number_text(g.best_so_far));
    }
    g.best_success_rate = h.number("best_success_rate", 0.0, 1.0);
    g.evaluations = h.integer("evaluations", 1, kBig);
    if (i > 0 && g.evaluations <= s.history.back().evaluations) {
      h.fail("evaluations", "must grow from generation to generation (the count of all candidates so far)");
    }
    g.seconds = h.number("seconds", i == 0 ? 0.0 : s.history.back().seconds, kInf);
    g.hypervolume = h.number("hypervolume", 0.0, kInf);
    g.front_size = static_cast<int>(h.integer("front_size", 0, kInt));
    g.feasible = static_cast<int>(h.integer("feasible", 0, kInt));
    g.front_min = h.numbers("front_min", StateReader::kAny, -kInf, kInf);
    // the tuned values came later: checkpoints without them still resume
    for (auto [key, v] : {std::pair{"tuned_best", &g.tuned_best},
                          {"tuned_mean", &g.tuned_mean},
                          {"tuned_min", &g.tuned_min},
                          {"tuned_max", &g.tuned_max}}) {
      if (h.has(key)) *v = h.numbers(key, StateReader::kAny, -kInf, kInf);
    }
    if (h.has("validation_runs")) {
      g.validation_runs = static_cast<int>(h.integer("validation_runs", 1, kInt));
      g.validation_fitness = h.number_or_null("validation_fitness", 0.0, kInf);
      if (std::isnan(g.validation_fitness)) g.validation_fitness = kInf;
      g.validation_success_rate = h.number("validation_success_rate", 0.0, 1.0);
    }
    if (h.has("capping")) {
      const StateReader k = h.object("capping");
      g.capped_candidates = static_cast<int>(k.integer("candidates", 0, kInt));
      g.capped_runs = k.integer("capped_runs", 0, kBig);
      g.reruns = k.integer("reruns", 0, kBig);
      g.ticks_capped = k.integer("ticks_capped", 0, kBig);
      g.ticks_rerun = k.integer("ticks_rerun", 0, kBig);
    }
    s.history.push_back(g);
  }
  if (static_cast<std::size_t>(s.generation) != s.history.size()) {
    r.fail("generation", "is " + std::to_string(s.generation) + " but the history holds " +
                             std::to_string(s.history.size()) + " generations");
  }
  const std::int64_t counted = s.history.empty() ? 0 : s.history.back().evaluations;
  if (s.evaluations != counted) {
    r.fail("evaluations",
           "is " + std::to_string(s.evaluations) + " but the history counts " + std::to_string(counted));
  }
  if (!s.history.empty() && s.seconds != s.history.back().seconds) {
    r.fail("seconds", "is " + number_text(s.seconds) + " but the history's last row says " +
                          number_text(s.history.back().seconds));
  }
  for (const StateReader& e : r.objects("elites")) {
    Elite el;
    el.x = e.numbers("x", StateReader::kAny, 0.0, 1.0);
    el.values = e.numbers("values", StateReader::kAny, -kInf, kInf);
    el.generation = e.integer("generation", 0, std::max<std::int64_t>(0, s.generation - 1));
    el.candidate = static_cast<int>(e.integer("candidate", 0, kInt));
    el.stats = stats_from_state(e.object("stats"));
    s.elites.push_back(std::move(el));
  }
  return s;
}

RunState read_checkpoint(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw sim::ConfigError(path, 0, "", "cannot resume: no checkpoint here (run without --resume to start)");
  try {
    return checkpoint_from_json(nlohmann::json::parse(in));
  } catch (const nlohmann::json::exception& e) {
    throw sim::ConfigError(path, 0, "", std::string("cannot resume: not JSON: ") + e.what());
  } catch (const StateError& e) {
    throw sim::ConfigError(path, 0, e.field(), e.message() + kDamaged);
  }
}

std::string elite_origin(const Elite& e, bool short_form) {
  const std::string g = std::to_string(e.generation);
  if (e.candidate == kDistributionMean) {
    return short_form ? "mean after gen " + g : "the distribution mean after generation " + g;
  }
  const std::string k = std::to_string(e.candidate);
  return short_form ? "gen " + g + " #" + k : "generation " + g + ", candidate " + k;
}

}  // namespace swarmpath::evolve
