// SPDX-License-Identifier: MIT
#include "atomic_write.hpp"

#include <atomic>
#include <cerrno>
#include <fcntl.h>
#include <filesystem>
#include <sstream>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>
#include <utility>

namespace swarmpath::evolve {

namespace {

namespace fs = std::filesystem;

std::string reason(int error) { return std::error_code(error, std::generic_category()).message(); }

// an open file descriptor that is closed (unchecked) unless release()d
class Fd {
 public:
  explicit Fd(int fd) : fd_(fd) {}

  ~Fd() {
    if (fd_ >= 0) ::close(fd_);
  }

  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;

  int get() const { return fd_; }

  int release() { return std::exchange(fd_, -1); }

 private:
  int fd_;
};

void write_all(int fd, std::string_view text, const std::string& path) {
  while (!text.empty()) {
    const ssize_t n = ::write(fd, text.data(), text.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      throw WriteError(path, reason(errno));
    }
    text.remove_prefix(static_cast<std::size_t>(n));
  }
}

void close_checked(Fd& fd, const std::string& path) {
  if (::close(fd.release()) != 0 && errno != EINTR) throw WriteError(path, reason(errno));
}

// devices, pipes and sockets (and anything under /dev or /proc) are written in place
void write_in_place(const std::string& path, std::string_view text) {
  Fd fd(::open(path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC));
  if (fd.get() < 0) throw WriteError(path, reason(errno));
  write_all(fd.get(), text, path);
  close_checked(fd, path);
}

std::string temporary_name(const fs::path& target) {
  static std::atomic<unsigned> counter{0};
  return target.string() + "." + std::to_string(::getpid()) + "-" + std::to_string(counter++) + ".tmp";
}

// the rename is durable once the folder's entry is on the disk (best effort: not every file
// system can sync a folder)
void sync_folder(const fs::path& folder) {
  const int fd = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  (void)::fsync(fd);
  ::close(fd);
}

}  // namespace

bool is_temporary_of(std::string_view file_name, std::string_view name) {
  if (file_name.size() <= name.size() + 5 || file_name.substr(0, name.size()) != name) return false;
  if (file_name[name.size()] != '.' || !file_name.ends_with(".tmp")) return false;
  const std::string_view middle = file_name.substr(name.size() + 1, file_name.size() - name.size() - 5);
  return !middle.empty() && middle.find_first_not_of("0123456789-") == std::string_view::npos;
}

void write_file_atomic(const std::string& path, std::string_view text) {
  if (path.empty()) throw WriteError(path, "no file name");

  struct stat st {};

  const bool exists = ::stat(path.c_str(), &st) == 0;
  if (exists && S_ISDIR(st.st_mode)) throw WriteError(path, "it is a folder");
  if ((exists && !S_ISREG(st.st_mode)) || path.starts_with("/dev/") || path.starts_with("/proc/")) {
    write_in_place(path, text);
    return;
  }
  // a symbolic link stays a link: its target is replaced
  fs::path target(path);
  if (exists) {
    std::error_code ec;
    if (fs::is_symlink(target, ec)) target = fs::canonical(target, ec);
    if (ec) throw WriteError(path, ec.message());
  }

  const std::string tmp = temporary_name(target);
  Fd fd(::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666));
  if (fd.get() < 0) throw WriteError(path, reason(errno));
  try {
    write_all(fd.get(), text, path);
    if (::fsync(fd.get()) != 0) throw WriteError(path, reason(errno));
    close_checked(fd, path);
    if (::rename(tmp.c_str(), target.c_str()) != 0) throw WriteError(path, reason(errno));
  } catch (...) {
    ::unlink(tmp.c_str());
    throw;
  }
  sync_folder(target.parent_path());
}

void write_file_atomic(const std::string& path, const std::function<void(std::ostream&)>& write) {
  std::ostringstream text;
  write(text);
  write_file_atomic(path, text.str());
}

}  // namespace swarmpath::evolve
