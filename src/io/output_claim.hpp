#pragma once
// An exclusive claim on an output file for the length of one run. A run writes its file under
// <path>.partial, which it creates exclusively and holds an flock(2) on, and moves it to <path>
// only once the file is whole (publish()): so <path> holds a finished file or nothing, and two
// runs given the same path cannot both write it (the second is refused while the first holds the
// lock).
//
// Nothing already on disk is replaced unless `replace` is set (--force), and even then only a
// regular file: devices, directories, FIFOs and symbolic links are never replaced, nor is a file
// another run holds locked (its unfinished log). Files written whole at once (a recording, a
// sidecar, a report) follow the same rules through io/output_file.hpp.
#include <cstddef>
#include <string>

namespace mssph {

class OutputClaim {
 public:
  OutputClaim() = default;
  // Claims `path`: checks what is there now, creates missing parent directories and creates and
  // locks <path>.partial (a leftover one, which only `replace` allows, is removed first). Throws
  // InputError saying what is in the way; a refused claim leaves no directory behind.
  OutputClaim(const std::string& path, bool replace);
  // Claims `path` to continue the unfinished log at <path>.partial (`mssph run --restart`): locks
  // it as it is, keeping its contents, and keeps it when the claim ends unpublished. Throws
  // InputError when there is no such regular file, another run holds it, or a log already lies
  // at `path`.
  static OutputClaim resume(const std::string& path);
  ~OutputClaim();
  OutputClaim(OutputClaim&& other) noexcept;
  OutputClaim& operator=(OutputClaim&& other) noexcept;
  OutputClaim(const OutputClaim&) = delete;
  OutputClaim& operator=(const OutputClaim&) = delete;

  const std::string& path() const { return path_; }
  std::string partial_path() const { return path_ + ".partial"; }
  bool held() const { return fd_ >= 0; }
  // Whether existing files may be replaced (--force); never for a resumed claim.
  bool replaces() const { return replace_; }

  // Keeps <path>.partial on disk when the claim ends unpublished (a failed or interrupted run's
  // file); without it an unpublished claim removes the file it created.
  void keep_partial() { keep_partial_ = true; }

  // Makes sure `bytes` more than the partial file's current size are allocated on disk (Linux
  // fallocate, without changing the file's size), so that writes up to there cannot fail for
  // lack of space. Returns 0, or the errno that says why not: ENOSPC (the file system is full)
  // or EFBIG (the file would pass the process's file size limit). 0 too where the file system
  // cannot say (no fallocate).
  int reserve(long long bytes);

  // Makes the partial file durable (fsync) and renames it to `path` (see rename_into_place). When
  // that is refused, std::runtime_error says why and the finished file stays at its partial name;
  // when <path>.partial no longer names the locked file (another program renamed something over
  // it), it says so and nothing is renamed.
  void publish();

 private:
  void release() noexcept;

  std::string path_;
  int fd_ = -1;
  bool replace_ = false;
  bool keep_partial_ = false;
  bool published_ = false;
};

// Throws InputError "<option> <path>: ..." when `path` names something that may not be replaced:
// a directory, device, FIFO, socket or symbolic link, a file another run holds locked, or
// (without `replace`) any existing file. `option` names the command-line option in the message,
// e.g. "--out".
void check_replaceable(const std::string& option, const std::string& path, bool replace);

// Throws InputError "<option> <path>: ..." when a file system could not hold `path` with
// `suffix_bytes` appended to its name (a temporary file's): a component longer than NAME_MAX.
void check_file_name(const std::string& option, const std::string& path, std::size_t suffix_bytes);

// The checks OutputClaim's constructor makes, without creating anything: for a run to refuse a
// path before it spends time building its particles.
void check_claimable(const std::string& path, bool replace);

// Whether another process holds an flock(2) on the regular file at `path` (a run writing it).
bool locked_by_another_run(const std::string& path);

// Renames the whole file `from` to `to`. Without `replace` an existing `to` is never replaced;
// with it, only a regular file that no run holds locked is, and that file is locked (shared)
// while it goes, so that no run can claim it meanwhile. Returns "" once `from` lies at `to`, else why
// not, as words that follow the name `to` ("appeared while the run was writing"). Throws
// std::runtime_error when the system refuses the rename itself.
std::string rename_into_place(const std::string& from, const std::string& to, bool replace);

// Makes a rename into the directory of `path` durable (fsync of the directory), as far as the
// system allows.
void sync_parent_directory(const std::string& path);

// Whether two paths name the same file: the same inode when both exist, else the same
// absolute, normalized path.
bool same_file(const std::string& a, const std::string& b);

}  // namespace mssph
