#include "io/output_file.hpp"

#include "io/output_claim.hpp"
#include "util/errors.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <utility>

namespace mssph {
namespace {

// A new file next to `path` under a name no file has: O_EXCL refuses an existing name, a link
// included, so another name is drawn.
std::pair<std::string, int> create_temporary(const std::string& path) {
  static constexpr char kLetters[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
  std::random_device random;
  std::uniform_int_distribution<std::size_t> letter(0, sizeof kLetters - 2);
  for (int attempt = 0; attempt < 100; ++attempt) {
    std::string name = path + ".tmp-";
    for (int k = 0; k < 6; ++k) name += kLetters[letter(random)];
    const int fd = open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd >= 0) return {name, fd};
    if (errno != EEXIST) throw std::runtime_error("cannot create " + name + ": " + std::strerror(errno));
  }
  throw std::runtime_error("cannot create a temporary file next to " + path + ": every name drawn exists");
}

// 0, or the errno of the write that failed.
int write_all(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return errno;
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  return 0;
}

}  // namespace

void check_output_file(const std::string& option, const std::string& path, bool replace) {
  check_file_name(option, path, kTemporarySuffixBytes);
  check_replaceable(option, path, replace);
  const std::string partial = path + ".partial";
  if (locked_by_another_run(partial)) {
    throw InputError(option + " " + path + ": another run is writing it (it holds " + partial + ")");
  }
}

OutputFile::OutputFile(std::string path, bool replace, bool durable)
    : path_(std::move(path)), replace_(replace), durable_(durable) {}

void OutputFile::write(std::string_view bytes) {
  const std::filesystem::path parent = std::filesystem::path(path_).parent_path();
  if (!parent.empty()) {
    std::error_code error;
    std::filesystem::create_directories(parent, error);
    if (error) throw std::runtime_error("cannot create " + parent.string() + " for " + path_ + ": " + error.message());
  }
  const auto [temporary, fd] = create_temporary(path_);
  int error = write_all(fd, bytes);
  if (error == 0 && durable_ && fsync(fd) != 0) error = errno;
  struct stat written {};
  if (error == 0 && fstat(fd, &written) != 0) error = errno;
  if (close(fd) != 0 && error == 0) error = errno;
  if (error != 0) {
    unlink(temporary.c_str());
    throw std::runtime_error((error == ENOSPC ? "disk full writing " : "cannot write ") + path_ + " (into " +
                             temporary + ", removed): " + std::strerror(error));
  }
  std::string refused;
  struct stat there {};
  if (!written_ || lstat(path_.c_str(), &there) != 0) {
    // A first write, or the file written before was removed meanwhile: nothing of this run's is there.
    refused = rename_into_place(temporary, path_, replace_ && !written_);
  } else if (there.st_dev != device_ || there.st_ino != inode_) {
    refused = "is no longer the file this run wrote there";
  } else if (std::rename(temporary.c_str(), path_.c_str()) != 0) {
    throw std::runtime_error("cannot rename " + temporary + " to " + path_ + ": " + std::strerror(errno));
  }
  if (!refused.empty()) {
    throw OutputKeptAside(path_ + " " + refused + "; its new contents are kept at " + temporary +
                              (replace_ || written_ ? "" : " (pass --force to replace files)"),
                          temporary);
  }
  written_ = true;
  device_ = written.st_dev;
  inode_ = written.st_ino;
  if (durable_) sync_parent_directory(path_);
}

void OutputFile::remove_written() noexcept {
  struct stat there {};
  if (!written_ || lstat(path_.c_str(), &there) != 0) return;
  if (there.st_dev == device_ && there.st_ino == inode_) unlink(path_.c_str());
  written_ = false;
}

}  // namespace mssph
