// SPDX-License-Identifier: MIT
#include "genome_manifest.hpp"

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "evolve/evolve_config.hpp"
#include "evolve/report.hpp"
#include "sim/config_error.hpp"
#include "sim/params.hpp"
#include "sim/toml_reader.hpp"

namespace swarmpath::evolve {

namespace {

nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw sim::ConfigError(path, 0, "", "cannot read");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw sim::ConfigError(path, 0, "", std::string("not JSON: ") + e.what());
  }
}

std::string file_in(const sim::TableReader& t, const std::string& key, const std::string& dir) {
  const std::string written = t.string(key);
  const std::optional<std::string> p = resolve_path(written, dir);
  if (!p) t.fail(key, "\"" + written + "\" not found (paths are taken from the manifest's folder)");
  return *p;
}

}  // namespace

GenomeManifest load_genome_manifest(const std::string& path) {
  const sim::TomlDoc doc = sim::TomlDoc::parse_file(path);
  const std::string dir = std::filesystem::path(path).parent_path().string();
  const sim::TableReader root(doc, doc.root(), "");
  GenomeManifest m;
  m.file = path;
  m.against = file_in(root, "against", dir);
  for (const sim::TableReader& t : root.table_array("genome")) {
    ShippedGenome g;
    g.params = file_in(t, "params", dir);
    g.config = file_in(t, "config", dir);
    g.run = file_in(t, "run", dir);
    if (t.has("front_point")) {
      const std::int64_t k = t.integer("front_point");
      if (k < 0 || k > 100000) t.fail("front_point", "must be >= 0");
      g.front_point = static_cast<int>(k);
    } else {
      t.allow("front_point");
    }
    t.finish();
    m.genomes.push_back(g);
  }
  root.finish();
  return m;
}

std::string genome_mismatch(const ShippedGenome& g) {
  const nlohmann::json j = read_json(g.run);
  nlohmann::json tuned;
  if (g.front_point) {
    if (!j.contains("front") || *g.front_point >= static_cast<int>(j["front"].size())) {
      return g.run + " has no front point " + std::to_string(*g.front_point);
    }
    tuned = j["front"][static_cast<std::size_t>(*g.front_point)]["tuned"];
  } else {
    if (!j.contains("best") || j["best"].is_null()) return g.run + " names no best candidate";
    tuned = j["best"]["tuned"];
  }
  const sim::Params p = sim::load_params(g.params);
  for (const auto& [name, value] : tuned.items()) {
    const sim::ParamInfo* info = sim::find_param(name);
    if (info == nullptr) return g.run + " tuned an unknown parameter " + name;
    const double ours = sim::get_value(p, *info);
    double theirs = 0.0;
    if (value.is_boolean()) {
      theirs = value.get<bool>() ? 1.0 : 0.0;
    } else if (value.is_string()) {
      theirs = value.get<std::string>() == info->choices[1] ? 1.0 : 0.0;  // a choice: its second name is 1
    } else {
      theirs = value.get<double>();
    }
    if (ours != theirs) {
      return g.params + ": " + name + " = " + exact(ours) + ", but its run chose " + exact(theirs) + " (" +
             g.run + ")";
    }
  }
  return {};
}

std::string recorded_config_hash(const ShippedGenome& g) { return read_json(g.run).value("config_hash", ""); }

}  // namespace swarmpath::evolve
