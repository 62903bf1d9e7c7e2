// SPDX-License-Identifier: MIT
#include "irace_import.hpp"

#include <charconv>
#include <fstream>
#include <sstream>

#include "evolve/report.hpp"
#include "sim/config_error.hpp"

namespace swarmpath::evolve {

namespace {

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) {
    if (cell.size() >= 2 && cell.front() == '"' && cell.back() == '"') cell = cell.substr(1, cell.size() - 2);
    out.push_back(cell);
  }
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

bool parse_number(const std::string& text, double& v) {
  const char* end = text.data() + text.size();
  const auto r = std::from_chars(text.data(), end, v);
  return r.ec == std::errc() && r.ptr == end;
}

}  // namespace

std::vector<IraceElite> read_irace_elites(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw sim::ConfigError(path, 0, "", "cannot be read");
  std::string line;
  if (!std::getline(in, line)) throw sim::ConfigError(path, 1, "", "empty: no header line");
  const std::vector<std::string> header = split_csv(line);
  const auto column = [&](const std::string& name) -> std::size_t {
    for (std::size_t k = 0; k < header.size(); ++k) {
      if (header[k] == name) return k;
    }
    throw sim::ConfigError(path, 1, name, "column missing from the header");
  };
  const std::size_t rank = column("rank"), id = column("id"), cost = column("mean_cost"),
                    runs = column("runs"), experiments = column("experiments"),
                    version = column("irace_version"), seed = column("irace_seed");
  std::vector<IraceElite> elites;
  int n = 1;
  while (std::getline(in, line)) {
    ++n;
    if (line.empty()) continue;
    const std::vector<std::string> cells = split_csv(line);
    if (cells.size() != header.size()) {
      throw sim::ConfigError(
          path, n, "",
          std::to_string(cells.size()) + " cells, the header has " + std::to_string(header.size()));
    }
    const auto number = [&](std::size_t k) {
      double v = 0.0;
      if (!parse_number(cells[k], v))
        throw sim::ConfigError(path, n, header[k], "not a number: \"" + cells[k] + "\"");
      return v;
    };
    IraceElite e;
    e.rank = static_cast<int>(number(rank));
    e.id = cells[id];
    e.mean_cost = number(cost);
    e.runs = static_cast<std::int64_t>(number(runs));
    e.experiments = static_cast<std::int64_t>(number(experiments));
    e.irace_version = cells[version];
    e.irace_seed = cells[seed];
    for (std::size_t k = 0; k < header.size(); ++k) {
      if (k == rank || k == id || k == cost || k == runs || k == experiments || k == version || k == seed)
        continue;
      e.values.emplace_back(header[k], cells[k]);
    }
    elites.push_back(std::move(e));
  }
  if (elites.empty()) throw sim::ConfigError(path, n, "", "no elite configuration in it");
  return elites;
}

Decoded irace_elite_candidate(const Genome& g, const IraceElite& e, const std::string& file) {
  std::vector<double> values(g.genes.size());
  std::vector<bool> seen(g.genes.size(), false);
  for (const auto& [name, text] : e.values) {
    std::size_t i = 0;
    while (i < g.genes.size() && g.genes[i].info->name != name) ++i;
    if (i == g.genes.size()) {
      throw sim::ConfigError(file, 0, name, "irace tuned a parameter that the evolve config does not tune");
    }
    const sim::ParamInfo& info = *g.genes[i].info;
    double v = 0.0;
    if (info.type == sim::ParamType::kBool) {
      if (text != "true" && text != "false" && text != "TRUE" && text != "FALSE")
        throw sim::ConfigError(file, 0, name, "expected true or false, got \"" + text + "\"");
      v = (text == "true" || text == "TRUE") ? 1.0 : 0.0;
    } else if (info.type == sim::ParamType::kChoice) {
      if (text != info.choices[0] && text != info.choices[1]) {
        throw sim::ConfigError(file, 0, name,
                               "expected " + std::string(info.choices[0]) + " or " +
                                   std::string(info.choices[1]) + ", got \"" + text + "\"");
      }
      v = text == info.choices[1] ? 1.0 : 0.0;
    } else if (!parse_number(text, v)) {
      throw sim::ConfigError(file, 0, name, "not a number: \"" + text + "\"");
    }
    values[i] = v;
    seen[i] = true;
  }
  for (std::size_t i = 0; i < g.genes.size(); ++i) {
    if (!seen[i])
      throw sim::ConfigError(file, 0, std::string(g.genes[i].info->name), "missing from irace's elites");
  }
  return decode_values(g, values);
}

std::string irace_params_toml(const EvolveConfig& c, const IraceManifest& m, const IraceElite& e,
                              const Decoded& d, const std::string& dir) {
  const BuildInfo b = build_info();
  std::ostringstream h;
  h << "# irace " << e.irace_version << ": elite " << e.rank << " (configuration " << e.id << ", mean cost "
    << exact(e.mean_cost) << " over " << e.runs << " instance runs; " << e.experiments
    << " experiments in all, irace seed " << e.irace_seed << ") of the scenario in " << dir << ",\n";
  h << "# written from the evolve config " << m.config << " (hash " << m.config_hash << ", budget "
    << m.max_experiments << " experiments); imported by swarmpath " << b.version << ", git " << b.git_commit
    << ".\n";
  h << "# Mode " << sim::to_string(c.mode) << "; tuned:";
  for (const auto& [name, value] : e.values) h << ' ' << name << " = " << value;
  h << (d.repaired ? " (cross constraints repaired)" : "") << "; the others as in "
    << (c.params_written.empty() ? "the paper's defaults" : c.params_written) << ".\n\n";
  std::ostringstream out;
  sim::write_params_toml(out, d.params, h.str());
  return out.str();
}

}  // namespace swarmpath::evolve
