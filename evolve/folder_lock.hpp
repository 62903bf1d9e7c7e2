// SPDX-License-Identifier: MIT
// An exclusive lock on an output folder, so that two runs never write into one folder: flock(2)
// on FOLDER/.lock, held while the object lives and released by the kernel when the process ends
// (kill -9 included, so a lock is never stale). The lock file says who holds it: pid, host,
// start time and what runs, so that a second run can say whom it waits for.
#pragma once

#include <string>

namespace swarmpath::evolve {

class FolderLock {
 public:
  /// The lock file inside a locked folder.
  static constexpr const char* kFileName = ".lock";

  /// Creates `folder` if needed and locks it; `what` describes the holder ("evolve of
  /// configs/evolve/default.toml"). Throws sim::ConfigError (exit 2) naming the holder when another
  /// process holds the lock, or naming the folder when it is a file or cannot be created or locked.
  FolderLock(const std::string& folder, const std::string& what);
  ~FolderLock();

  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;
  FolderLock(FolderLock&& other) noexcept;
  FolderLock& operator=(FolderLock&&) = delete;

  const std::string& folder() const { return folder_; }

 private:
  std::string folder_;
  int fd_ = -1;
};

/// The wall-clock time in UTC as strftime's `format` writes it (for messages and folder names, never
/// for results).
std::string utc_time_text(const char* format);

/// "pid 1234 on host h since 2025-11-26T15:42:39Z: WHAT": the holder line written into the lock.
std::string lock_holder_line(const std::string& what);

/// The folder an output folder option names must be a folder (or not exist yet): throws
/// sim::ConfigError naming `option` when `folder` is a file or something else.
void check_output_folder(const std::string& option, const std::string& folder);

}  // namespace swarmpath::evolve
