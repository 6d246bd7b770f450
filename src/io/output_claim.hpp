#pragma once
// An exclusive claim on an output file for the length of one run. A run writes its file under
// <path>.partial, which it holds an flock(2) on, and moves it to <path> only once the file is
// whole (publish()): so <path> holds a finished file or nothing, and two runs given the same
// path cannot both write it (the second is refused while the first holds the lock).
//
// Nothing already on disk is replaced unless `replace` is set (--force), and even then only a
// regular file: devices, directories, FIFOs and symbolic links are never replaced, nor is the
// file another run is writing.
#include <string>

namespace mssph {

class OutputClaim {
 public:
  OutputClaim() = default;
  // Claims `path`: checks what is there now, creates and locks <path>.partial (emptied), and
  // creates missing parent directories. Throws InputError saying what is in the way.
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

  // Keeps <path>.partial on disk when the claim ends unpublished (a failed or interrupted run's
  // file); without it an unpublished claim removes the file it created.
  void keep_partial() { keep_partial_ = true; }

  // Makes sure `bytes` more than the partial file's current size are allocated on disk (Linux
  // fallocate, without changing the file's size), so that writes up to there cannot fail for
  // lack of space. Returns 0, or the errno that says why not: ENOSPC (the file system is full)
  // or EFBIG (the file would pass the process's file size limit). 0 too where the file system
  // cannot say (no fallocate).
  int reserve(long long bytes);

  // Makes the partial file durable (fsync) and renames it to `path`. Without `replace`, a file
  // that appeared at `path` during the run is not replaced: std::runtime_error says so and the
  // finished file stays at its partial name.
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
// a directory, device, FIFO, socket or symbolic link, or (without `replace`) any existing file.
// `option` names the command-line option in the message, e.g. "--out".
void check_replaceable(const std::string& option, const std::string& path, bool replace);

// The checks OutputClaim's constructor makes, without creating anything: for a run to refuse a
// path before it spends time building its particles.
void check_claimable(const std::string& path, bool replace);

// Whether another process holds the claim on `path` (the lock on <path>.partial): a run writing it.
bool held_by_another_run(const std::string& path);

// Whether two paths name the same file: the same inode when both exist, else the same
// absolute, normalized path.
bool same_file(const std::string& a, const std::string& b);

}  // namespace mssph
