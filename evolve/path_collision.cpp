// SPDX-License-Identifier: MIT
#include "path_collision.hpp"

#include <filesystem>
#include <system_error>

#include "sim/config_error.hpp"

namespace swarmpath::evolve {

namespace {

namespace fs = std::filesystem;

bool is_device(const std::string& path) {
  std::error_code ec;
  const fs::file_status s = fs::status(path, ec);
  return fs::exists(s) && !fs::is_regular_file(s) && !fs::is_directory(s);
}

fs::path normal(const std::string& path) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
  return ec ? fs::absolute(path).lexically_normal() : p;
}

}  // namespace

bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  if (fs::exists(a, ec) && fs::exists(b, ec)) return fs::equivalent(a, b, ec) && !ec;
  return normal(a) == normal(b);
}

void check_output_paths(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs) {
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const NamedPath& out = outputs[i];
    if (out.path.empty() || is_device(out.path)) continue;
    std::error_code ec;
    if (fs::is_directory(out.path, ec)) {
      throw sim::ConfigError(out.what, 0, "", out.path + " is a folder: give a file name");
    }
    const fs::path folder = normal(out.path).parent_path();
    if (!fs::is_directory(folder, ec)) {
      throw sim::ConfigError(out.what, 0, "",
                             "cannot write " + out.path + ": its folder " + folder.string() +
                                 " does not exist (create it first)");
    }
    for (const NamedPath& in : inputs) {
      if (!in.path.empty() && same_file(out.path, in.path)) {
        throw sim::ConfigError(out.what, 0, "",
                               out.path + " is also the " + in.what + " input (" + in.path +
                                   "): writing it would replace that file; choose another output file");
      }
    }
    for (std::size_t k = 0; k < i; ++k) {
      if (!outputs[k].path.empty() && same_file(out.path, outputs[k].path)) {
        throw sim::ConfigError(out.what, 0, "",
                               out.path + " is also the " + outputs[k].what +
                                   " output: one file cannot hold both; choose another file");
      }
    }
  }
}

}  // namespace swarmpath::evolve
