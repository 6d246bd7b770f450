#pragma once
// Output files written whole at once: a device recording, an XDMF sidecar, a validation report.
// The bytes go into a temporary file next to the output, <path>.tmp-XXXXXX, created exclusively
// (O_EXCL | O_NOFOLLOW under a name no file has), so that neither an existing file nor the target
// of a link is ever written, and that no temporary can be another run's locked <out>.partial.
// The temporary is then renamed to <path> by the rules of io/output_claim.hpp: without --force
// nothing is replaced, with it only a regular file that no run holds locked.
#include <sys/types.h>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace mssph {

// Bytes a temporary file adds to its output's name: ".tmp-" and six random characters.
inline constexpr std::size_t kTemporarySuffixBytes = 11;

// The checks before a run writes `path` (`option` names it in the message): throws InputError
// when its name is too long, what is there may not be replaced (check_replaceable), or another
// run is writing it (holds <path>.partial locked).
void check_output_file(const std::string& option, const std::string& path, bool replace);

// What OutputFile::write throws when the file was written whole but may not take its name: it
// lies at kept_at() instead, and the message says why and where.
class OutputKeptAside : public std::runtime_error {
 public:
  OutputKeptAside(const std::string& message, std::string kept_at)
      : std::runtime_error(message), kept_at_(std::move(kept_at)) {}
  const std::string& kept_at() const { return kept_at_; }

 private:
  std::string kept_at_;
};

class OutputFile {
 public:
  // `durable`: each write is synced to disk before it is renamed into place (a sidecar rewritten
  // at every snapshot is not).
  OutputFile(std::string path, bool replace, bool durable = true);

  const std::string& path() const { return path_; }

  // Writes `bytes` as the whole file, creating missing parent directories. The first write
  // replaces an existing file only with `replace`; a later one replaces only the file this object
  // wrote last. Throws std::runtime_error naming the file and the system's reason ("No space left
  // on device"), or OutputKeptAside when the file may not be replaced: the new one is then kept at
  // its temporary name.
  void write(std::string_view bytes);

  // Removes the file this object wrote last, if it is still the one at path(); nothing else.
  void remove_written() noexcept;

 private:
  std::string path_;
  bool replace_ = false;
  bool durable_ = true;
  bool written_ = false;
  dev_t device_ = 0;
  ino_t inode_ = 0;
};

}  // namespace mssph
