// SPDX-License-Identifier: MIT
#include "evolve/optim/nlopt_adapter.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <nlopt.hpp>

namespace swarmpath::evolve {
namespace {

struct AlgorithmInfo {
  const char* name;
  nlopt::algorithm id;
  bool takes_population;
};

constexpr AlgorithmInfo kAlgorithms[] = {
    {"esch", nlopt::GN_ESCH, true},
    {"crs2", nlopt::GN_CRS2_LM, true},
    {"isres", nlopt::GN_ISRES, true},
    {"direct", nlopt::GN_DIRECT_L, false},
    {"bobyqa", nlopt::LN_BOBYQA, false},
    {"sbplx", nlopt::LN_SBPLX, false},
    {"neldermead", nlopt::LN_NELDERMEAD, false},
};

const AlgorithmInfo& algorithm_info(const std::string& name) {
  for (const auto& a : kAlgorithms) {
    if (name == a.name) return a;
  }
  std::string known;
  for (const auto& a : kAlgorithms) known += (known.empty() ? "" : ", ") + std::string(a.name);
  throw std::invalid_argument("unknown NLopt algorithm '" + name + "' (known: " + known + ")");
}

std::string result_name(nlopt::result r) {
  switch (r) {
    case nlopt::SUCCESS:
      return "success";
    case nlopt::STOPVAL_REACHED:
      return "stopval_reached";
    case nlopt::FTOL_REACHED:
      return "ftol_reached";
    case nlopt::XTOL_REACHED:
      return "xtol_reached";
    case nlopt::MAXEVAL_REACHED:
      return "maxeval_reached";
    case nlopt::MAXTIME_REACHED:
      return "maxtime_reached";
    default:
      return "result " + std::to_string(static_cast<int>(r));
  }
}

/// What the objective callback sees: the history to answer from, and what it found.
struct ReplayCursor {
  const std::vector<NloptAdapter::Told>* history = nullptr;
  std::size_t calls = 0;
  bool diverged = false;  ///< NLopt asked for another x than the history holds
  Vector requested;       ///< the x of call history.size() + 1
};

double replay_objective(const std::vector<double>& x, std::vector<double>& /*grad*/, void* data) {
  auto& cursor = *static_cast<ReplayCursor*>(data);
  // some algorithms (CRS2, DIRECT) finish a batch of calls before they notice the forced stop
  if (cursor.diverged || !cursor.requested.empty()) throw nlopt::forced_stop();
  if (cursor.calls < cursor.history->size()) {
    const auto& told = (*cursor.history)[cursor.calls];
    if (x != told.x) {
      cursor.diverged = true;
      throw nlopt::forced_stop();
    }
    ++cursor.calls;
    return told.f;
  }
  cursor.requested = x;
  throw nlopt::forced_stop();
}

}  // namespace

std::vector<std::string> NloptAdapter::algorithms() {
  std::vector<std::string> names;
  for (const auto& a : kAlgorithms) names.emplace_back(a.name);
  return names;
}

NloptAdapter::NloptAdapter(const OptimizerSettings& s, const Bounds& b, const Vector& x0, std::uint64_t seed)
    : box_(b), x0_unit_(box_.to_unit(x0)), seed_(seed) {
  const std::string prefix = "nlopt:";
  if (s.name.rfind(prefix, 0) != 0) {
    throw std::invalid_argument("not an NLopt optimizer name: '" + s.name + "'");
  }
  algorithm_ = s.name.substr(prefix.size());
  const AlgorithmInfo& info = algorithm_info(algorithm_);
  const std::size_t n = b.dim();
  if (s.population < 0 || s.population == 1) {
    throw SettingError("population", name() + ": population must be >= 2 (or 0 for NLopt's default), got " +
                                         std::to_string(s.population));
  }
  if (info.id == nlopt::GN_CRS2_LM && s.population > 0 && static_cast<std::size_t>(s.population) < n + 1) {
    throw SettingError("population", name() + ": population must be >= n + 1 = " + std::to_string(n + 1) +
                                         ", got " + std::to_string(s.population));
  }
  // local and DIRECT algorithms have no population: the setting is ignored for them
  population_ = info.takes_population ? static_cast<unsigned>(s.population) : 0u;
  if (s.max_evaluations < 0) {
    throw SettingError("max_evaluations",
                       name() + ": max_evaluations must be >= 0, got " + std::to_string(s.max_evaluations));
  }
  max_evaluations_ =
      static_cast<unsigned>(s.max_evaluations > 0 ? s.max_evaluations : 200 * static_cast<int>(n + 1));
  if (!(s.xtol_rel >= 0.0 && std::isfinite(s.xtol_rel))) {
    throw SettingError("xtol_rel", name() + ": xtol_rel must be >= 0, got " + std::to_string(s.xtol_rel));
  }
  xtol_rel_ = s.xtol_rel;
  if (!(s.sigma0 > 0.0 && s.sigma0 <= 1.0)) {
    throw SettingError(
        "sigma0", name() + ": sigma0 (the initial step) must be in (0, 1], got " + std::to_string(s.sigma0));
  }
  initial_step_ = s.sigma0;
  replay();
}

void NloptAdapter::replay() {
  const AlgorithmInfo& info = algorithm_info(algorithm_);
  const unsigned n = static_cast<unsigned>(box_.dim());
  ReplayCursor cursor;
  cursor.history = &history_;
  nlopt::opt opt(info.id, n);
  opt.set_lower_bounds(std::vector<double>(n, 0.0));
  opt.set_upper_bounds(std::vector<double>(n, 1.0));
  opt.set_min_objective(replay_objective, &cursor);
  opt.set_maxeval(static_cast<int>(max_evaluations_));
  opt.set_xtol_rel(xtol_rel_);
  if (info.id == nlopt::LN_BOBYQA || info.id == nlopt::LN_SBPLX || info.id == nlopt::LN_NELDERMEAD) {
    opt.set_initial_step(initial_step_);
  }
  if (population_ > 0) opt.set_population(population_);

  Vector x = x0_unit_;
  double f = 0.0;
  next_unit_.clear();
  done_ = false;
  result_.clear();
  try {
    nlopt::srand(seed_);  // NLopt's own generator (ESCH, CRS2, ISRES): reseeded before every run
    result_ = result_name(opt.optimize(x, f));
    done_ = true;
  } catch (const nlopt::forced_stop&) {
    if (cursor.diverged) {
      throw std::logic_error(name() + ": replay diverged at evaluation " + std::to_string(cursor.calls + 1) +
                             " of " + std::to_string(history_.size()) + " (NLopt is not deterministic here)");
    }
    if (cursor.requested.empty())
      throw std::logic_error(name() + ": NLopt stopped without asking for a point");
    next_unit_ = cursor.requested;
  } catch (const nlopt::roundoff_limited&) {
    result_ = "roundoff_limited";
    done_ = true;
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(name() + ": NLopt rejected the settings (" + e.what() + ")");
  } catch (const std::runtime_error& e) {
    result_ = std::string("failure: ") + e.what();
    done_ = true;
  }
}

std::vector<Vector> NloptAdapter::ask() {
  if (done_) throw std::logic_error(name() + ": ask() after done() (" + result_ + ")");
  asked_ = true;
  return {box_.from_unit(next_unit_)};
}

void NloptAdapter::tell(const std::vector<Vector>& candidates, const std::vector<double>& fitness) {
  std::vector<Vector> asked;
  if (asked_) asked.push_back(box_.from_unit(next_unit_));
  const std::vector<double> f = checked_fitness(asked, candidates, fitness);
  best_.update(candidates, f);
  history_.push_back({next_unit_, f[0]});
  asked_ = false;
  replay();
}

nlohmann::json NloptAdapter::state() const {
  auto j = state_header(name(), box_.dim());
  j["seed"] = seed_;
  auto history = nlohmann::json::array();
  for (const auto& t : history_) history.push_back({{"x", vector_to_json(t.x)}, {"f", number_to_json(t.f)}});
  j["history"] = std::move(history);
  j["asked"] = asked_;
  j["best"] = best_.to_json();
  return j;
}

void NloptAdapter::restore(const nlohmann::json& state) {
  // every field is checked before anything changes (StateError names the field)
  const StateReader r(state, "");
  const std::size_t n = box_.dim();
  r.header(name(), n);
  const std::uint64_t seed = r.word("seed");
  const Bounds unit{Vector(n, 0.0), Vector(n, 1.0)};
  std::vector<Told> history;
  for (const StateReader& t : r.objects("history")) {
    history.push_back({t.point("x", unit), t.extended("f", -StateReader::kInf, StateReader::kInf)});
  }
  const BestSoFar best = BestSoFar::from_state(r, box_.bounds());
  const bool asked = r.boolean("asked");
  seed_ = seed;
  history_ = std::move(history);
  best_ = best;
  replay();
  asked_ = asked && !done_;
}

}  // namespace swarmpath::evolve
