// SPDX-License-Identifier: MIT
#include "report.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <iomanip>
#include <limits>
#include <ostream>
#include <sstream>

#include "evolve/build_info.hpp"
#include "evolve/params_export.hpp"
#include "evolve/seeds.hpp"
#include "evolve/xml_escape.hpp"
#include "sim/hash.hpp"

namespace swarmpath::evolve {

namespace {

// 1, 2 or 5 times a power of ten, about range / 5
double nice_step(double range) {
  if (!(range > 0.0)) return 1.0;
  const double raw = range / 5.0;
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 5.0}) {
    if (m * p >= raw) return m * p;
  }
  return 10.0 * p;
}

std::string short_text(double v) {
  std::ostringstream o;
  o << std::setprecision(4) << v;
  return o.str();
}

nlohmann::ordered_json finalist_json(const EvolveConfig& c, const Finalist& f, std::size_t rank) {
  nlohmann::ordered_json j;
  j["rank"] = rank;
  j["generation"] = f.elite.generation;
  j["candidate"] = f.elite.candidate;
  j["generation_stats"] = stats_json(f.elite.stats);
  j["reevaluated"] = stats_json(f.reevaluated);
  j["held_out"] = f.held_out.runs > 0 ? stats_json(f.held_out) : nlohmann::ordered_json(nullptr);
  nlohmann::ordered_json tuned;
  for (const Gene& g : c.genome.genes) tuned[std::string(g.info->name)] = param_value_json(f.params, *g.info);
  j["tuned"] = tuned;
  j["x"] = f.elite.x;
  return j;
}

}  // namespace

BuildInfo build_info() {
  BuildInfo b;
  b.version = build::kVersion;
  b.git_commit = build::kGitCommit;
#if defined(__clang__)
  b.compiler = std::string("clang ") + __clang_version__;
#elif defined(__GNUC__)
  b.compiler = std::string("g++ ") + __VERSION__;
#else
  b.compiler = "unknown";
#endif
  b.box2d = build::kBox2dVersion;
  b.build_type = build::kBuildType;
  return b;
}

std::string exact(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

void write_log_csv(std::ostream& out, const std::vector<GenerationRecord>& history) {
  out << "generation,best,mean,std,best_so_far,best_success_rate,evaluations,seconds\n";
  for (const GenerationRecord& r : history) {
    out << r.generation << ',' << exact(r.best) << ',' << exact(r.mean) << ',' << exact(r.std) << ','
        << exact(r.best_so_far) << ',' << exact(r.best_success_rate) << ',' << r.evaluations << ','
        << exact(r.seconds) << '\n';
  }
}

void write_fitness_svg(std::ostream& out, const std::string& title,
                       const std::vector<GenerationRecord>& history) {
  const double width = 720.0, height = 420.0;
  const double left = 72.0, right = 24.0, top = 44.0, bottom = 52.0;
  const double pw = width - left - right, ph = height - top - bottom;
  const std::size_t n = history.size();
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const GenerationRecord& r : history) {
    lo = std::min({lo, r.best, r.mean, r.best_so_far});
    hi = std::max({hi, r.best, r.mean, r.best_so_far});
  }
  if (n == 0) lo = 0.0, hi = 1.0;
  if (hi - lo < 1e-9) lo -= 0.5, hi += 0.5;
  const double ystep = nice_step(hi - lo);
  lo = std::floor(lo / ystep) * ystep;
  hi = std::ceil(hi / ystep) * ystep;
  const double gmax = n > 1 ? static_cast<double>(n - 1) : 1.0;
  const auto px = [&](double g) { return left + pw * g / gmax; };
  const auto py = [&](double f) { return top + ph * (hi - f) / (hi - lo); };

  out << std::fixed << std::setprecision(2);
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << ' ' << height << "\" font-family=\"sans-serif\">\n";
  out << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  out << "<text x=\"6\" y=\"20\" font-size=\"15\" font-weight=\"bold\">" << xml_escape(title) << "</text>\n";
  out << "<text x=\"6\" y=\"36\" font-size=\"12\">fitness per generation (lower is better)</text>\n";
  // grid and axes
  out << "<g stroke=\"#e4e4dc\" stroke-width=\"1\">\n";
  for (double f = lo; f <= hi + 0.5 * ystep; f += ystep) {
    out << "<line x1=\"" << left << "\" y1=\"" << py(f) << "\" x2=\"" << left + pw << "\" y2=\"" << py(f)
        << "\"/>\n";
  }
  out << "</g>\n<g font-size=\"11\" text-anchor=\"end\">\n";
  for (double f = lo; f <= hi + 0.5 * ystep; f += ystep) {
    out << "<text x=\"" << left - 6 << "\" y=\"" << py(f) + 4 << "\">" << short_text(f) << "</text>\n";
  }
  out << "</g>\n<g font-size=\"11\" text-anchor=\"middle\">\n";
  const double gstep = std::max(1.0, nice_step(gmax));
  for (double g = 0; g <= gmax + 1e-9; g += gstep) {
    out << "<text x=\"" << px(g) << "\" y=\"" << top + ph + 16 << "\">" << short_text(g) << "</text>\n";
  }
  out << "</g>\n";
  out << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << pw << "\" height=\"" << ph
      << "\" fill=\"none\" stroke=\"#999\"/>\n";
  out << "<text x=\"" << left + pw / 2 << "\" y=\"" << height - 12
      << "\" font-size=\"12\" text-anchor=\"middle\">generation</text>\n";
  out << "<text x=\"16\" y=\"" << top + ph / 2
      << "\" font-size=\"12\" text-anchor=\"middle\" transform=\"rotate(-90 16 " << top + ph / 2
      << ")\">fitness</text>\n";

  // the three series
  struct Series {
    const char* label;
    const char* color;
    double GenerationRecord::*field;
  };

  const Series series[] = {{"mean", "#7a9cc6", &GenerationRecord::mean},
                           {"best of generation", "#e07000", &GenerationRecord::best},
                           {"best so far", "#00a651", &GenerationRecord::best_so_far}};
  for (const Series& s : series) {
    if (n == 0) break;
    out << "<polyline fill=\"none\" stroke=\"" << s.color << "\" stroke-width=\"2\" points=\"";
    for (std::size_t i = 0; i < n; ++i)
      out << px(static_cast<double>(i)) << ',' << py(history[i].*s.field) << ' ';
    out << "\"/>\n";
    for (std::size_t i = 0; i < n; ++i) {
      out << "<circle cx=\"" << px(static_cast<double>(i)) << "\" cy=\"" << py(history[i].*s.field)
          << "\" r=\"2.5\" fill=\"" << s.color << "\"/>\n";
    }
  }
  // legend
  double ly = top + 16;
  for (const Series& s : series) {
    out << "<line x1=\"" << left + pw - 150 << "\" y1=\"" << ly - 4 << "\" x2=\"" << left + pw - 124
        << "\" y2=\"" << ly - 4 << "\" stroke=\"" << s.color << "\" stroke-width=\"3\"/><text x=\""
        << left + pw - 118 << "\" y=\"" << ly << "\" font-size=\"12\">" << s.label << "</text>\n";
    ly += 16;
  }
  out << "</svg>\n";
}

std::string best_toml(const EvolveConfig& c, const RunResult& r) {
  const Finalist& f = r.finalists.at(r.best);
  const BuildInfo b = build_info();
  std::ostringstream h;
  h << "# swarmpath evolve: the best candidate of run \"" << c.name << "\" (config " << c.file << ", hash "
    << config_hash(c) << ", swarmpath " << b.version << ", git " << b.git_commit << ").\n";
  h << "# Found in generation " << f.elite.generation << " (candidate " << f.elite.candidate
    << ", generation mean fitness " << short_text(f.elite.stats.fitness) << "); chosen among "
    << r.finalists.size() << " finalists by its fitness on fresh seeds: " << short_text(f.reevaluated.fitness)
    << " over " << f.reevaluated.runs << " runs, success rate " << short_text(f.reevaluated.success_rate)
    << ".\n";
  h << "# The base params on the same fresh seeds: fitness " << short_text(r.base.reevaluated.fitness)
    << ", success rate " << short_text(r.base.reevaluated.success_rate) << ".\n";
  if (f.held_out.runs > 0) {
    h << "# Held-out scenarios: fitness " << short_text(f.held_out.fitness) << " over " << f.held_out.runs
      << " runs, success rate " << short_text(f.held_out.success_rate) << ".\n";
  }
  h << "# Mode " << sim::to_string(c.mode) << "; tuned:";
  for (const Gene& g : c.genome.genes) h << ' ' << g.info->name;
  h << "; the others as in " << (c.params_written.empty() ? "the paper's defaults" : c.params_written)
    << ".\n\n";
  std::ostringstream out;
  sim::write_params_toml(out, f.params, h.str());
  return out.str();
}

nlohmann::ordered_json run_json(const EvolveConfig& c, const RunResult& r, int threads) {
  const BuildInfo b = build_info();
  nlohmann::ordered_json j;
  j["tool"] = "swarmpath evolve";
  j["versions"] = {{"swarmpath", b.version},
                   {"git_commit", b.git_commit},
                   {"compiler", b.compiler},
                   {"box2d", b.box2d},
                   {"build_type", b.build_type}};
  j["config_hash"] = config_hash(c);
  j["config"] = config_json(c);
  // the seeds of every generation (the same for every candidate of it) and of the re-evaluation
  nlohmann::ordered_json seeds;
  seeds["master"] = c.seed;
  seeds["optimizer"] = optimizer_seed(c.seed);
  seeds["derivation"] =
      "generation g, case i: mix_seed(master, 0x67656e, fixed_seeds ? 0 : g, i); re-evaluation case i: "
      "mix_seed(master, 0x72656576, i); optimiser: mix_seed(master, 0x6f7074). Cases are setting-major "
      "(scenario, then robot count, then replicate); the candidate index is not an input (common random "
      "numbers).";
  nlohmann::ordered_json cases = nlohmann::ordered_json::array();
  for (const EvalCase& k : r.cases) {
    const EvalSetting& st = r.settings.at(k.setting);
    cases.push_back({{"scenario", st.scenario}, {"robots", st.robots}, {"replicate", k.replicate}});
  }
  seeds["cases"] = cases;
  nlohmann::ordered_json gens = nlohmann::ordered_json::array();
  for (std::int64_t g = 0; g < r.state.generation; ++g) {
    nlohmann::ordered_json row = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < r.cases.size(); ++i) {
      row.push_back(generation_seed(c.seed, g, i, c.evaluation.fixed_seeds));
    }
    gens.push_back(row);
  }
  seeds["generations"] = gens;
  nlohmann::ordered_json reev = nlohmann::ordered_json::array();
  for (const EvalCase& k : r.reevaluation_cases) {
    const EvalSetting& st = r.settings.at(k.setting);
    reev.push_back({{"scenario", st.scenario},
                    {"robots", st.robots},
                    {"held_out", st.held_out},
                    {"replicate", k.replicate},
                    {"seed", k.seed}});
  }
  seeds["reevaluation"] = reev;
  j["seeds"] = seeds;
  j["threads"] = threads;
  j["generations"] = r.state.generation;
  j["evaluations"] = r.state.evaluations;
  j["runs"] = r.state.runs;
  j["wall_seconds"] = r.seconds;
  j["stop_reason"] = r.stop_reason;
  nlohmann::ordered_json finalists = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < r.finalists.size(); ++i)
    finalists.push_back(finalist_json(c, r.finalists[i], i));
  j["finalists"] = finalists;
  j["base_reevaluated"] = stats_json(r.base.reevaluated);
  j["base_held_out"] =
      r.base.held_out.runs > 0 ? stats_json(r.base.held_out) : nlohmann::ordered_json(nullptr);
  j["best"] =
      r.finalists.empty() ? nlohmann::ordered_json(nullptr) : finalist_json(c, r.finalists[r.best], r.best);
  if (!r.finalists.empty()) j["best"]["params"] = params_values_json(r.finalists[r.best].params);
  return j;
}

}  // namespace swarmpath::evolve
