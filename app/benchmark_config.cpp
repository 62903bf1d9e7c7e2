// SPDX-License-Identifier: MIT
#include "benchmark_config.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

#include "experiment.hpp"
#include "sim/config_error.hpp"
#include "sim/scenario.hpp"
#include "sim/scenario_writer.hpp"
#include "sim/toml_reader.hpp"

namespace swarmpath::app {

namespace {

using sim::TableReader;

std::int64_t int_in(const TableReader& t, std::string_view key, std::int64_t fallback, std::int64_t lo,
                    std::int64_t hi) {
  const std::int64_t v = t.has(key) ? t.integer(key) : (t.allow(key), fallback);
  if (v < lo || v > hi) {
    t.fail(key, "must lie in [" + std::to_string(lo) + ", " + std::to_string(hi) + "] (got " +
                    std::to_string(v) + ")");
  }
  return v;
}

BenchmarkFamily read_family(const TableReader& t, int most_robots, bool screen) {
  BenchmarkFamily f;
  f.spec = sim::arenas::read_spec(t, "family", "params");
  f.label = std::string(f.spec.family->name);
  if (t.has("label")) {
    f.label = t.string("label");
    if (f.label.empty() || f.label == "paper" || f.label == "all families" || f.label == "paper arenas")
      t.fail("label", "a family's rows need a name, and not \"paper\", \"all families\" or \"paper arenas\"");
  } else {
    t.allow("label");
  }
  if (const auto params = t.table("params"); params && params->has("robots")) {
    params->fail("robots", "the benchmark's robots = [...] sets the robot counts of every arena");
  }
  const std::vector<sim::arenas::FamilyParam> params = sim::arenas::all_params(*f.spec.family);
  for (std::size_t i = 0; i < params.size(); ++i) {
    if (params[i].name == "robots") f.spec.values[i] = most_robots;
  }
  std::set<std::uint64_t> seen;
  for (const double s : t.numbers("seeds")) {
    const bool benchmark_seed = sim::arenas::is_benchmark_seed(static_cast<std::uint64_t>(std::max(0.0, s)));
    if (screen && (s != std::floor(s) || s < 0))
      t.fail("seeds", "arena seeds are whole numbers >= 0 (got " + sim::toml_number(s) + ")");
    if (s != std::floor(s) || (!screen && !benchmark_seed)) {
      t.fail("seeds", "benchmark arenas take seeds in [" + std::to_string(sim::arenas::kBenchmarkSeedLo) +
                          ", " + std::to_string(sim::arenas::kBenchmarkSeedHi - 1) +
                          "], which no screen or tuning run draws (got " + sim::toml_number(s) + ")");
    }
    if (screen && benchmark_seed) {
      t.fail("seeds", "a screen's arenas take seeds outside the benchmarks' range [" +
                          std::to_string(sim::arenas::kBenchmarkSeedLo) + ", " +
                          std::to_string(sim::arenas::kBenchmarkSeedHi - 1) +
                          "]: choose on a screen, measure on a benchmark (got " + sim::toml_number(s) + ")");
    }
    const auto seed = static_cast<std::uint64_t>(s);
    if (!seen.insert(seed).second) t.fail("seeds", "seed " + std::to_string(seed) + " named twice");
    f.seeds.push_back(seed);
  }
  if (f.seeds.empty()) t.fail("seeds", "give at least one arena seed");
  t.finish();
  return f;
}

BenchmarkConfig parse(const sim::TomlDoc& doc, const std::string& base_dir) {
  BenchmarkConfig c;
  c.file = doc.name();
  const TableReader root(doc, doc.root(), "");
  c.name = root.string("name");
  if (c.name.empty()) root.fail("name", "must not be empty");
  c.version = static_cast<int>(int_in(root, "version", 1, 1, 1000000));
  if (root.has("purpose")) {
    const std::string purpose = root.string("purpose");
    if (purpose != "benchmark" && purpose != "screen")
      root.fail("purpose", "must be \"benchmark\" or \"screen\" (got \"" + purpose + "\")");
    c.screen = purpose == "screen";
  } else {
    root.allow("purpose");
  }
  const std::int64_t generator = root.integer("generator_version");
  if (generator != sim::arenas::kGeneratorVersion) {
    root.fail(
        "generator_version",
        "this benchmark's arenas were drawn by arena generator " + std::to_string(generator) +
            "; this build draws with version " + std::to_string(sim::arenas::kGeneratorVersion) +
            ", whose arenas differ: make a new version of the benchmark rather than compare across them");
  }
  for (const double n : root.numbers("robots")) {
    if (n != std::floor(n) || n < 1 || n > 120)
      root.fail("robots", "robot counts must be whole numbers in [1, 120]");
    c.robots.push_back(static_cast<int>(n));
  }
  if (c.robots.empty()) root.fail("robots", "give at least one robot count");
  c.seeds = static_cast<int>(int_in(root, "seeds", 1, 1, 10000));
  c.seed_base = static_cast<std::uint64_t>(int_in(root, "seed_base", 1, 0, 1'000'000'000));
  c.max_ticks = int_in(root, "max_ticks", 36000, 1, sim::kMaxTicks);
  if (root.has("paper")) {
    namespace fs = std::filesystem;
    const std::string written = root.string("paper");
    std::error_code ec;
    const fs::path p = fs::path(written).is_absolute() ? fs::path(written) : fs::path(base_dir) / written;
    if (!fs::exists(p, ec))
      root.fail("paper", "\"" + written + "\" not found (looked in " + p.string() + ")");
    c.paper = scenario_files({p.lexically_normal().string()});
  } else {
    root.allow("paper");
  }
  const int most = *std::max_element(c.robots.begin(), c.robots.end());
  for (const TableReader& f : root.table_array("family"))
    c.families.push_back(read_family(f, most, c.screen));
  if (c.families.empty()) root.fail("family", "a benchmark needs at least one [[family]] of arenas");
  root.finish();
  return c;
}

}  // namespace

std::size_t BenchmarkConfig::arenas() const {
  std::size_t n = 0;
  for (const BenchmarkFamily& f : families) n += f.seeds.size();
  return n;
}

BenchmarkConfig load_benchmark_config(const std::string& path) {
  const sim::TomlDoc doc = sim::TomlDoc::parse_file(path);
  return parse(doc, std::filesystem::path(path).parent_path().string());
}

BenchmarkConfig parse_benchmark_config(std::string_view text, const std::string& name,
                                       const std::string& base_dir) {
  const sim::TomlDoc doc = sim::TomlDoc::parse_string(text, name);
  return parse(doc, base_dir);
}

std::vector<sim::arenas::GeneratedArena> draw_benchmark_arenas(
    const std::vector<const BenchmarkFamily*>& families, int threads) {
  std::vector<std::pair<const BenchmarkFamily*, std::uint64_t>> todo;
  for (const BenchmarkFamily* f : families) {
    for (const std::uint64_t s : f->seeds) todo.emplace_back(f, s);
  }
  std::vector<sim::arenas::GeneratedArena> out(todo.size());
  std::vector<std::string> errors(todo.size());
  const auto n = static_cast<std::int64_t>(todo.size());
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (std::int64_t i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    try {
      out[k] = sim::arenas::generate_arena(todo[k].first->spec, todo[k].second);
    } catch (const std::exception& e) {
      errors[k] = e.what();
    }
  }
  for (const std::string& e : errors) {
    if (!e.empty()) throw std::runtime_error("drawing a benchmark arena failed: " + e);
  }
  return out;
}

}  // namespace swarmpath::app
