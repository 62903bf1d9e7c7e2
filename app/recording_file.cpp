// SPDX-License-Identifier: MIT
#include "recording_file.hpp"

#include <fstream>
#include <iterator>
#include <sstream>

#include "evolve/atomic_write.hpp"
#include "evolve/report.hpp"
#include "sim/config_error.hpp"

namespace swarmpath::app {

void complete_recording(sim::Recording& r, const sim::Scenario& s) {
  const evolve::BuildInfo b = evolve::build_info();
  r.generator = "swarmpath " + b.version + " (git " + b.git_commit + ")";
  std::ifstream f(s.file);
  if (f) r.scenario_toml.assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
}

void write_recording_file(const std::string& path, const sim::Recording& r) {
  evolve::write_file_atomic(path, sim::encode_recording(r));
}

std::string read_file_bytes(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw sim::ConfigError(path, 0, "", "cannot open the file");
  std::ostringstream s;
  s << f.rdbuf();
  if (f.bad()) throw sim::ConfigError(path, 0, "", "cannot read the file");
  return s.str();
}

sim::Recording read_recording_file(const std::string& path) {
  return sim::decode_recording(read_file_bytes(path), path);
}

std::int64_t record_every(const sim::Scenario& s, std::int64_t ticks) {
  if (ticks == 0) return s.sim.ticks_per_second;
  if (ticks < 1 || ticks > s.sim.max_ticks)
    throw sim::ConfigError("--record-every", 0, "", "must lie in [1, max_ticks] ticks (10 ticks = 1 s)");
  return ticks;
}

}  // namespace swarmpath::app
