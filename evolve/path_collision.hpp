// SPDX-License-Identifier: MIT
// Inputs are never overwritten: before a command runs, every file it will write is checked
// against every file it reads (and against its other outputs), by file identity (hard and
// symbolic links, "./" and ".." included), and its folder must exist. Devices (/dev/null,
// /dev/stdout) are not files and may be named more than once.
#pragma once

#include <string>
#include <vector>

namespace swarmpath::evolve {

/// A file a command reads or writes, and the option or config key that named it ("--svg").
struct NamedPath {
  std::string what;
  std::string path;
};

/// True when a and b name the same file: the same inode when both exist, else the same absolute,
/// normalised path (symbolic links resolved as far as they exist).
bool same_file(const std::string& a, const std::string& b);

/// Throws sim::ConfigError (exit 2) naming the options when an output is also an input, when two
/// outputs name one file, when an output is a folder, or when an output's folder does not exist.
/// Empty paths are skipped.
void check_output_paths(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs);

}  // namespace swarmpath::evolve
