#include "io/output_claim.hpp"

#include "util/errors.hpp"
#include "util/file_kind.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <utility>
#include <vector>

namespace mssph {
namespace fs = std::filesystem;

namespace {

// Bytes a claim adds to its output's name: ".partial".
constexpr std::size_t kPartialSuffixBytes = 8;
// The longest name of one file or folder (Linux file systems).
constexpr std::size_t kNameMax = NAME_MAX;

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

// Removes directories a claim created, deepest first; one that is no longer empty stays.
void remove_directories(const std::vector<fs::path>& created) noexcept {
  for (auto it = created.rbegin(); it != created.rend(); ++it) rmdir(it->c_str());
}

// Creates the missing directories above `path`, shallowest first, and returns those it created,
// so that a claim refused after them can remove them again.
std::vector<fs::path> create_parents(const std::string& option, const std::string& path) {
  std::vector<fs::path> missing;
  std::error_code error;
  for (fs::path p = fs::path(path).parent_path(); !p.empty() && !fs::exists(fs::symlink_status(p, error));
       p = p.parent_path()) {
    missing.push_back(p);
  }
  std::vector<fs::path> created;
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    if (mkdir(it->c_str(), 0777) == 0) {
      created.push_back(*it);
    } else if (errno != EEXIST) {
      const std::string why = std::strerror(errno);
      remove_directories(created);
      throw InputError(option + " " + path + ": cannot create " + it->string() + ": " + why);
    }
  }
  return created;
}

// Whether the file descriptor `fd` is the file `path` names now.
bool names_file(const std::string& path, int fd) {
  struct stat open_file {};
  struct stat named {};
  return fstat(fd, &open_file) == 0 && lstat(path.c_str(), &named) == 0 && open_file.st_ino == named.st_ino &&
         open_file.st_dev == named.st_dev;
}

}  // namespace

bool locked_by_another_run(const std::string& path) {
  const int fd = open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return false;
  struct stat st {};
  const bool busy =
      fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && flock(fd, LOCK_SH | LOCK_NB) != 0 && errno == EWOULDBLOCK;
  close(fd);
  return busy;
}

void check_replaceable(const std::string& option, const std::string& path, bool replace) {
  struct stat st {};
  if (lstat(path.c_str(), &st) != 0) return;  // nothing there (or unreachable: creating it will say)
  const std::string head = option + " " + path + ": ";
  if (!S_ISREG(st.st_mode)) {
    throw InputError(head + "is " + file_kind(st) + "; mssph writes only regular files" +
                     (S_ISLNK(st.st_mode) ? " and does not follow links (give the link's target)" : "") +
                     ", and never replaces anything else, even with --force");
  }
  if (locked_by_another_run(path)) {
    throw InputError(head + "another run is writing it (it holds the file locked); never replaced, even with --force");
  }
  if (!replace) throw InputError(head + "exists; pass --force to replace it, or choose another name");
}

void check_file_name(const std::string& option, const std::string& path, std::size_t suffix_bytes) {
  const fs::path p(path);
  const std::string head = option + " " + path + ": ";
  for (const fs::path& part : p.parent_path()) {
    if (part.native().size() > kNameMax) {
      throw InputError(head + "a folder name there is " + std::to_string(part.native().size()) +
                       " bytes, more than the " + std::to_string(kNameMax) + " bytes a file name may have");
    }
  }
  const std::size_t name = p.filename().native().size();
  if (name + suffix_bytes > kNameMax) {
    throw InputError(head + "its file name is " + std::to_string(name) + " bytes; with the " +
                     std::to_string(suffix_bytes) + " bytes mssph adds to name its temporary file, that passes the " +
                     std::to_string(kNameMax) + " bytes a file name may have");
  }
}

std::string rename_into_place(const std::string& from, const std::string& to, bool replace) {
  if (!replace) return rename_no_replace(from, to) ? "" : "appeared while the run was writing";
  const int there = open(to.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (there < 0 && errno == ELOOP) return "is now a symbolic link, which mssph never replaces";
  if (there >= 0) {
    struct stat st {};
    std::string refused;
    if (fstat(there, &st) != 0 || !S_ISREG(st.st_mode)) {
      refused = "is now " + file_kind(st) + ", which mssph never replaces";
    } else if (flock(there, LOCK_SH | LOCK_NB) != 0) {
      // A writer holds it (a claim's exclusive lock); readers, which share theirs, keep the file
      // they opened.
      refused = "is being written by another run, which holds it locked";
    }
    if (!refused.empty()) {
      close(there);
      return refused;
    }
  }
  const bool moved = std::rename(from.c_str(), to.c_str()) == 0;
  const int error = errno;
  if (there >= 0) close(there);  // the lock goes with it, on the replaced file
  if (!moved) throw std::runtime_error("cannot rename " + from + " to " + to + ": " + std::strerror(error));
  return "";
}

void sync_parent_directory(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  const int dir = open(parent.empty() ? "." : parent.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir < 0) return;  // durability of the rename only; the file itself is synced
  fsync(dir);
  close(dir);
}

bool same_file(const std::string& a, const std::string& b) {
  std::error_code error;
  if (fs::exists(a, error) && fs::exists(b, error)) return fs::equivalent(a, b, error);
  return fs::weakly_canonical(a, error) == fs::weakly_canonical(b, error);
}

void check_claimable(const std::string& path, bool replace) {
  const std::string partial = path + ".partial";
  check_file_name("--out", path, kPartialSuffixBytes);
  check_replaceable("--out", path, replace);
  struct stat st {};
  if (lstat(partial.c_str(), &st) != 0) return;
  if (!S_ISREG(st.st_mode)) {
    throw InputError("--out " + path + ": " + partial + " (where the run would write) is " + file_kind(st));
  }
  if (locked_by_another_run(partial)) {
    throw InputError("--out " + path + ": another run is writing it (it holds " + partial + ")");
  }
  if (!replace) {
    throw InputError("--out " + path + ": " + partial +
                     " is the log of an earlier run that did not finish; pass --force to replace it, or move it away");
  }
}

OutputClaim::OutputClaim(const std::string& path, bool replace) : path_(path), replace_(replace) {
  const std::string partial = partial_path();
  check_claimable(path, replace);
  const std::vector<fs::path> created = create_parents("--out", path);
  const auto refuse = [&](const std::string& why) {
    if (fd_ >= 0) close(fd_);
    fd_ = -1;
    remove_directories(created);
    throw InputError("--out " + path + ": " + why);
  };
  const std::string busy = "another run is writing it (it holds " + partial + ")";
  // A leftover partial file (check_claimable let it through: `replace` is set) is removed, not
  // emptied, while a shared lock on it shows that no run is writing it: any other name of the
  // file (a hard link) keeps its contents.
  const int leftover = open(partial.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (leftover >= 0) {
    const bool locked = flock(leftover, LOCK_SH | LOCK_NB) == 0;
    if (locked) unlink(partial.c_str());
    close(leftover);
    if (!locked) refuse(busy);
  }
  fd_ = open(partial.c_str(), O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd_ < 0) refuse(errno == EEXIST ? busy : "cannot create " + partial + ": " + std::strerror(errno));
  // The lock, then a check that the name still leads to the locked file: another run may have
  // taken the new file for a leftover of its own between our open and our lock.
  if (flock(fd_, LOCK_EX | LOCK_NB) != 0 || !names_file(partial, fd_)) refuse(busy);
}

OutputClaim OutputClaim::resume(const std::string& path) {
  OutputClaim claim;
  claim.path_ = path;
  const std::string partial = claim.partial_path();
  struct stat st {};
  if (lstat(partial.c_str(), &st) != 0) throw InputError("--restart " + partial + ": no such file");
  if (!S_ISREG(st.st_mode)) throw InputError("--restart " + partial + ": is " + file_kind(st));
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
  if (!names_file(partial_path(), fd_)) {
    keep_partial_ = true;  // what lies at the name now is not this run's to remove
    throw std::runtime_error(partial_path() + " was replaced by another program during the run: this run's log is " +
                             "lost, and " + path_ + " is not written");
  }
  const std::string refused = rename_into_place(partial_path(), path_, replace_);
  if (!refused.empty()) {
    keep_partial_ = true;
    throw std::runtime_error(path_ + " " + refused + "; its finished log is kept at " + partial_path() +
                             (replace_ ? "" : " (pass --force to replace files)"));
  }
  published_ = true;
  sync_parent_directory(path_);
  release();
}

}  // namespace mssph
