// SPDX-License-Identifier: MIT
// Writing an output file so that nothing is lost: the text goes to a temporary file in the same
// folder, is flushed to the disk and checked at close, and only then renamed over the target, so
// a full disk, a kill or a crash leaves the previous file as it was. Devices and pipes
// (/dev/stdout, /dev/null, /dev/full) are written in place, with the same checks.
#pragma once

#include <functional>
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <string_view>

namespace swarmpath::evolve {

/// A failed write: what() reads "cannot write PATH: REASON".
class WriteError : public std::runtime_error {
 public:
  WriteError(std::string path, const std::string& reason)
      : std::runtime_error("cannot write " + path + ": " + reason), path_(std::move(path)) {}

  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

/// Replaces `path` with `text` as above. Throws WriteError naming `path` when any step fails
/// (then the previous file is unchanged and no temporary file is left behind).
void write_file_atomic(const std::string& path, std::string_view text);

/// The same with the text a writer produces (the writer runs before anything touches the disk).
void write_file_atomic(const std::string& path, const std::function<void(std::ostream&)>& write);

/// True for the temporary files write_file_atomic makes for `name` ("log.csv.1234-0.tmp"), which a
/// kill between write and rename can leave behind.
bool is_temporary_of(std::string_view file_name, std::string_view name);

}  // namespace swarmpath::evolve
