// SPDX-License-Identifier: MIT
#include "folder_lock.hpp"

#include <cerrno>
#include <chrono>
#include <ctime>
#include <fcntl.h>
#include <filesystem>
#include <sys/file.h>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>
#include <utility>

#include "sim/config_error.hpp"

namespace swarmpath::evolve {

namespace {

namespace fs = std::filesystem;

std::string reason(int error) { return std::error_code(error, std::generic_category()).message(); }

std::string read_holder(int fd) {
  std::string text;
  char buf[512];
  ssize_t n = 0;
  off_t at = 0;
  while ((n = ::pread(fd, buf, sizeof buf, at)) > 0 && text.size() < 4096) {
    text.append(buf, static_cast<std::size_t>(n));
    at += n;
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  return text.empty() ? "a process that has not yet written its name" : text;
}

}  // namespace

std::string utc_time_text(const char* format) {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[64];
  return std::string(buf, std::strftime(buf, sizeof buf, format, &tm));
}

std::string lock_holder_line(const std::string& what) {
  char host[256] = "unknown";
  if (::gethostname(host, sizeof host) != 0) host[0] = '\0';
  host[sizeof host - 1] = '\0';
  return "pid " + std::to_string(::getpid()) + " on host " + host + " since " +
         utc_time_text("%Y-%m-%dT%H:%M:%SZ") + ": " + what;
}

void check_output_folder(const std::string& option, const std::string& folder) {
  std::error_code ec;
  const fs::file_status s = fs::status(folder, ec);
  if (!fs::exists(s) || fs::is_directory(s)) return;
  throw sim::ConfigError(option, 0, "",
                         folder + " is " + (fs::is_regular_file(s) ? "a file" : "not a folder") +
                             ": give a folder (it is created when missing)");
}

FolderLock::FolderLock(const std::string& folder, const std::string& what) : folder_(folder) {
  check_output_folder(folder, folder);
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec) throw sim::ConfigError(folder, 0, "", "cannot create the output folder: " + ec.message());
  const std::string path = (fs::path(folder) / kFileName).string();
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
  if (fd_ < 0) throw sim::ConfigError(path, 0, "", "cannot open the folder's lock file: " + reason(errno));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    const std::string holder = error == EWOULDBLOCK ? read_holder(fd_) : "";
    ::close(fd_);
    fd_ = -1;
    if (error == EWOULDBLOCK) {
      throw sim::ConfigError(folder, 0, "",
                             "another run is writing into this folder (" + holder +
                                 "); wait for it to end, or choose another output folder");
    }
    throw sim::ConfigError(path, 0, "", "cannot lock the output folder: " + reason(error));
  }
  // the holder's line, for whoever finds the folder locked
  const std::string line = lock_holder_line(what) + "\n";
  if (::ftruncate(fd_, 0) == 0) (void)!::pwrite(fd_, line.data(), line.size(), 0);
}

FolderLock::FolderLock(FolderLock&& other) noexcept
    : folder_(std::move(other.folder_)), fd_(std::exchange(other.fd_, -1)) {}

FolderLock::~FolderLock() {
  if (fd_ < 0) return;
  (void)!::ftruncate(fd_, 0);  // no holder any more; the kernel drops the lock at close
  ::close(fd_);
}

}  // namespace swarmpath::evolve
