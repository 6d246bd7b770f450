#include "io/output_claim.hpp"

#include "util/errors.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <utility>

namespace mssph {
namespace fs = std::filesystem;

namespace {

std::string what_is(const struct stat& st) {
  if (S_ISDIR(st.st_mode)) return "a directory";
  if (S_ISLNK(st.st_mode)) return "a symbolic link";
  if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) return "a device";
  if (S_ISFIFO(st.st_mode)) return "a FIFO";
  if (S_ISSOCK(st.st_mode)) return "a socket";
  return "not a regular file";
}

// Renames without replacing an existing `to` (Linux renameat2; link + unlink where the file
// system lacks it). False when `to` exists.
bool rename_no_replace(const std::string& from, const std::string& to) {
  if (renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0) return true;
  if (errno == EEXIST) return false;
  if (errno != EINVAL && errno != ENOSYS) {
    throw std::runtime_error("cannot rename " + from + " to " + to + ": " + std::strerror(errno));
  }
  if (link(from.c_str(), to.c_str()) != 0) {
    if (errno == EEXIST) return false;
    throw std::runtime_error("cannot link " + from + " to " + to + ": " + std::strerror(errno));
  }
  unlink(from.c_str());
  return true;
}

void sync_directory_of(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  const int dir = open(parent.empty() ? "." : parent.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir < 0) return;  // durability of the rename only; the file itself is synced
  fsync(dir);
  close(dir);
}

}  // namespace

void check_replaceable(const std::string& option, const std::string& path, bool replace) {
  struct stat st {};
  if (lstat(path.c_str(), &st) != 0) return;  // nothing there (or unreachable: creating it will say)
  const std::string head = option + " " + path + ": ";
  if (!S_ISREG(st.st_mode)) {
    throw InputError(head + "is " + what_is(st) + "; mssph writes only regular files" +
                     (S_ISLNK(st.st_mode) ? " and does not follow links (give the link's target)" : "") +
                     ", and never replaces anything else, even with --force");
  }
  if (!replace) throw InputError(head + "exists; pass --force to replace it, or choose another name");
}

bool same_file(const std::string& a, const std::string& b) {
  std::error_code error;
  if (fs::exists(a, error) && fs::exists(b, error)) return fs::equivalent(a, b, error);
  return fs::weakly_canonical(a, error) == fs::weakly_canonical(b, error);
}

bool held_by_another_run(const std::string& path) {
  const int existing = open((path + ".partial").c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK);
  const bool busy = existing >= 0 && flock(existing, LOCK_SH | LOCK_NB) != 0 && errno == EWOULDBLOCK;
  if (existing >= 0) close(existing);
  return busy;
}

void check_claimable(const std::string& path, bool replace) {
  const std::string partial = path + ".partial";
  check_replaceable("--out", path, replace);
  struct stat st {};
  if (lstat(partial.c_str(), &st) != 0) return;
  if (!S_ISREG(st.st_mode)) {
    throw InputError("--out " + path + ": " + partial + " (where the run would write) is " + what_is(st));
  }
  if (held_by_another_run(path))
    throw InputError("--out " + path + ": another run is writing it (it holds " + partial + ")");
  if (!replace) {
    throw InputError("--out " + path + ": " + partial +
                     " is the log of an earlier run that did not finish; pass --force to replace it, or move it away");
  }
}

OutputClaim::OutputClaim(const std::string& path, bool replace) : path_(path), replace_(replace) {
  const std::string partial = partial_path();
  check_claimable(path, replace);
  struct stat st {};
  const fs::path parent = fs::path(path).parent_path();
  if (!parent.empty()) {
    std::error_code error;
    fs::create_directories(parent, error);
    if (error) throw InputError("--out " + path + ": cannot create " + parent.string() + ": " + error.message());
  }
  fd_ = open(partial.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd_ < 0) throw InputError("--out " + path + ": cannot create " + partial + ": " + std::strerror(errno));
  // The lock, then a check that the name still leads to the locked file: another run may have
  // published (renamed) it between our open and our lock.
  struct stat locked {};
  const bool got_lock = flock(fd_, LOCK_EX | LOCK_NB) == 0;
  if (!got_lock || fstat(fd_, &locked) != 0 || lstat(partial.c_str(), &st) != 0 || locked.st_ino != st.st_ino ||
      locked.st_dev != st.st_dev) {
    close(fd_);
    fd_ = -1;
    throw InputError("--out " + path + ": another run is writing it (it holds " + partial + ")");
  }
  if (ftruncate(fd_, 0) != 0) {
    const std::string why = std::strerror(errno);
    release();
    throw InputError("--out " + path + ": cannot empty " + partial + ": " + why);
  }
}

OutputClaim OutputClaim::resume(const std::string& path) {
  OutputClaim claim;
  claim.path_ = path;
  const std::string partial = claim.partial_path();
  struct stat st {};
  if (lstat(partial.c_str(), &st) != 0) throw InputError("--restart " + partial + ": no such file");
  if (!S_ISREG(st.st_mode)) throw InputError("--restart " + partial + ": is " + what_is(st));
  if (lstat(path.c_str(), &st) == 0) {
    throw InputError("--restart " + partial + ": " + path + " exists, where the finished log would go; move it away");
  }
  claim.fd_ = open(partial.c_str(), O_RDWR | O_NOFOLLOW | O_CLOEXEC);
  if (claim.fd_ < 0) throw InputError("--restart " + partial + ": cannot open: " + std::strerror(errno));
  claim.keep_partial_ = true;
  if (flock(claim.fd_, LOCK_EX | LOCK_NB) != 0) {
    throw InputError("--restart " + partial + ": another run is writing it");
  }
  return claim;
}

OutputClaim::~OutputClaim() { release(); }

OutputClaim::OutputClaim(OutputClaim&& other) noexcept
    : path_(std::move(other.path_)),
      fd_(std::exchange(other.fd_, -1)),
      replace_(other.replace_),
      keep_partial_(other.keep_partial_),
      published_(other.published_) {}

OutputClaim& OutputClaim::operator=(OutputClaim&& other) noexcept {
  if (this != &other) {
    release();
    path_ = std::move(other.path_);
    fd_ = std::exchange(other.fd_, -1);
    replace_ = other.replace_;
    keep_partial_ = other.keep_partial_;
    published_ = other.published_;
  }
  return *this;
}

void OutputClaim::release() noexcept {
  if (fd_ < 0) return;
  // Still locked, so the partial file is this run's own: an unpublished, unkept one goes.
  if (!published_ && !keep_partial_) unlink(partial_path().c_str());
  close(fd_);
  fd_ = -1;
}

int OutputClaim::reserve(long long bytes) {
  if (fd_ < 0) return 0;
  struct stat st {};
  if (fstat(fd_, &st) != 0) return 0;
  // fallocate(KEEP_SIZE) ignores the file size limit, which a later write would meet.
  struct rlimit limit {};
  if (getrlimit(RLIMIT_FSIZE, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY &&
      static_cast<unsigned long long>(st.st_size) + static_cast<unsigned long long>(bytes) > limit.rlim_cur) {
    return EFBIG;
  }
  if (fallocate(fd_, FALLOC_FL_KEEP_SIZE, st.st_size, bytes) == 0) return 0;
  return errno == ENOSPC || errno == EFBIG ? errno : 0;
}

void OutputClaim::publish() {
  if (fd_ < 0) throw std::logic_error("publish() of an output that is not claimed: " + path_);
  if (fsync(fd_) != 0) {
    throw std::runtime_error("cannot sync " + partial_path() + " to disk: " + std::strerror(errno));
  }
  if (replace_) {
    if (std::rename(partial_path().c_str(), path_.c_str()) != 0) {
      throw std::runtime_error("cannot rename " + partial_path() + " to " + path_ + ": " + std::strerror(errno));
    }
  } else if (!rename_no_replace(partial_path(), path_)) {
    keep_partial_ = true;
    throw std::runtime_error(path_ + " appeared while the run was writing; its finished log is kept at " +
                             partial_path() + " (pass --force to replace files)");
  }
  published_ = true;
  sync_directory_of(path_);
  release();
}

}  // namespace mssph
