// SPDX-License-Identifier: MIT
// Recordings on disk (.swrec, sim/recording.hpp): written and read whole, with the scenario file's
// text and the program's version put in.
#pragma once

#include <cstdint>
#include <string>

#include "sim/recorder.hpp"
#include "sim/recording.hpp"

namespace swarmpath::app {

/// Adds what only the command line knows: the program's version and the scenario file's text.
void complete_recording(sim::Recording& r, const sim::Scenario& s);

/// Writes `r` to `path` (atomically); throws evolve::WriteError when the file cannot be written.
void write_recording_file(const std::string& path, const sim::Recording& r);

/// A whole file's bytes; throws ConfigError when it cannot be read.
std::string read_file_bytes(const std::string& path);

/// Reads and checks a recording; throws ConfigError naming the file and what is wrong.
sim::Recording read_recording_file(const std::string& path);

/// --record-every in ticks: `text` ticks, or the scenario's one second when empty.
std::int64_t record_every(const sim::Scenario& s, std::int64_t ticks);

}  // namespace swarmpath::app
