// SPDX-License-Identifier: MIT
#include "run_folder.hpp"

#include <algorithm>
#include <filesystem>

#include "evolve/atomic_write.hpp"
#include "evolve/checkpoint.hpp"
#include "evolve/folder_lock.hpp"
#include "evolve/path_collision.hpp"
#include "sim/config_error.hpp"

namespace swarmpath::evolve {

namespace {

namespace fs = std::filesystem;

std::string utc_stamp() { return utc_time_text("%Y-%m-%dT%H-%M-%SZ"); }

// what the earlier run in the folder got to, for the message
std::string earlier_run(const fs::path& folder, const std::vector<std::string>& present) {
  std::string files;
  for (const std::string& f : present) files += (files.empty() ? "" : ", ") + f;
  const fs::path ck = folder / "checkpoint.json";
  if (stopped_before_first_checkpoint(folder.string()))
    return "the files of a run stopped in its first generation, before its first checkpoint (" + files + ")";
  if (!fs::exists(ck)) return "files of an earlier run (" + files + ")";
  try {
    const RunState s = read_checkpoint(ck.string());
    return "a run stopped after generation " + std::to_string(s.generation) + " (" +
           std::to_string(s.evaluations) + " evaluations, config hash " + s.config_hash + "; " + files + ")";
  } catch (const std::exception&) {
    return "a run whose checkpoint.json does not read back (" + files + ")";
  }
}

// the temporary files of a kill between write and rename, and the old front of a kill mid-swap
void remove_leftovers(const fs::path& folder) {
  std::error_code ec;
  std::vector<fs::path> stale;
  for (const auto& e : fs::directory_iterator(folder, ec)) {
    const std::string name = e.path().filename().string();
    for (const std::string& f : run_file_names()) {
      if (is_temporary_of(name, f) || name == f + ".old") stale.push_back(e.path());
    }
  }
  for (const fs::path& p : stale) fs::remove_all(p, ec);
}

}  // namespace

const std::vector<std::string>& run_file_names() {
  static const std::vector<std::string> names = {"checkpoint.json", "log.csv",    "fitness.svg",
                                                 "hypervolume.svg", "best.toml",  "run.json",
                                                 "pareto.csv",      "pareto.svg", "front"};
  return names;
}

bool stopped_before_first_checkpoint(const std::string& folder) {
  const fs::path dir(folder);
  for (const char* f : {"checkpoint.json", "run.json", "best.toml", "pareto.csv", "front"}) {
    if (fs::exists(dir / f)) return false;
  }
  for (const char* f : {"log.csv", "fitness.svg", "hypervolume.svg"}) {
    if (fs::exists(dir / f)) return true;
  }
  return false;
}

void check_run_inputs(const EvolveConfig& c, const std::string& folder) {
  std::vector<NamedPath> inputs = {{"--config", c.file}, {"params", c.params_file}};
  for (const ScenarioRef& s : c.evaluation.scenarios) inputs.push_back({"evaluation.scenarios", s.path});
  for (const ScenarioRef& s : c.reevaluate.held_out) inputs.push_back({"reevaluate.held_out", s.path});
  for (const NamedPath& in : inputs) {
    if (in.path.empty()) continue;
    for (const std::string& name : run_file_names()) {
      const fs::path out = fs::path(folder) / name;
      // an input inside front/ would be replaced as well
      const bool inside = name == "front" && fs::path(in.path).parent_path() != fs::path() &&
                          same_file(fs::path(in.path).parent_path().string(), out.string());
      if (same_file(out.string(), in.path) || inside) {
        throw sim::ConfigError("--out", 0, "",
                               "the run would write " + out.string() + ", which is the " + in.what +
                                   " input (" + in.path + "); choose another output folder");
      }
    }
  }
}

void prepare_run_folder(const std::string& folder, bool resume, bool force,
                        const std::function<void(const std::string&)>& note) {
  const fs::path dir(folder);
  remove_leftovers(dir);
  if (resume) return;
  std::vector<std::string> present;
  for (const std::string& f : run_file_names()) {
    if (fs::exists(dir / f)) present.push_back(f);
  }
  const bool earlier = std::any_of(present.begin(), present.end(), [](const std::string& f) {
    return f == "checkpoint.json" || f == "log.csv" || f == "run.json" || f == "best.toml";
  });
  if (!earlier) return;
  if (!force) {
    throw sim::ConfigError(folder, 0, "",
                           "this folder holds " + earlier_run(dir, present) +
                               ": --resume continues it, --force starts afresh (its files move to " +
                               (dir / "replaced").string() + "/), or choose another output folder");
  }
  fs::path keep = dir / "replaced" / utc_stamp();
  for (int k = 2; fs::exists(keep); ++k) keep = dir / "replaced" / (utc_stamp() + "-" + std::to_string(k));
  fs::create_directories(keep);
  for (const std::string& f : present) fs::rename(dir / f, keep / f);
  if (note) note("starting afresh: the earlier run's files are now in " + keep.string() + "/");
}

}  // namespace swarmpath::evolve
