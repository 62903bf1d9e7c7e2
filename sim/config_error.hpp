// SPDX-License-Identifier: MIT
// The one error type for bad input files: it names the file, the line and the key.
#pragma once

#include <stdexcept>
#include <string>

namespace swarmpath::sim {

/// Thrown for any invalid input (scenario, params, config). what() reads
/// "file:line: key: message"; the CLI prints it and exits with code 2.
class ConfigError : public std::runtime_error {
 public:
  ConfigError(std::string file, int line, std::string key, const std::string& message)
      : std::runtime_error(format(file, line, key, message)),
        file_(std::move(file)),
        line_(line),
        key_(std::move(key)) {}

  const std::string& file() const { return file_; }

  int line() const { return line_; }

  const std::string& key() const { return key_; }

 private:
  static std::string format(const std::string& file, int line, const std::string& key,
                            const std::string& message) {
    std::string s = file;
    if (line > 0) s += ":" + std::to_string(line);
    s += ": ";
    if (!key.empty()) s += key + ": ";
    return s + message;
  }

  std::string file_;
  int line_;
  std::string key_;
};

}  // namespace swarmpath::sim
