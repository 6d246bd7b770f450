#include "config/input_file.hpp"

#include "util/errors.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace mssph {
namespace {

class OpenFile {
 public:
  explicit OpenFile(int fd) : fd_(fd) {}
  ~OpenFile() { ::close(fd_); }
  OpenFile(const OpenFile&) = delete;
  OpenFile& operator=(const OpenFile&) = delete;
  int fd() const { return fd_; }

 private:
  int fd_;
};

std::string limit_text() { return std::to_string(kMaxInputFileBytes >> 20) + " MiB"; }

// Waits until `fd` has data or its end (a FIFO: until a writer has written or come and gone).
void wait_readable(int fd) {
  pollfd request{fd, POLLIN, 0};
  while (::poll(&request, 1, -1) < 0 && errno == EINTR) {
  }
}

}  // namespace

std::string read_input_file(const std::string& path, const std::string& what) {
  // Non-blocking: opening a FIFO for reading would otherwise wait for a writer, and a signal
  // handler installed with SA_RESTART would restart that wait for ever.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) {
    // A missing file says so by itself; any other reason (permissions, a loop of links) is named.
    throw InputError(path + ": cannot open " + what +
                     (errno == ENOENT ? "" : " (" + std::string(std::strerror(errno)) + ")"));
  }
  const OpenFile file(fd);
  struct stat info {};
  if (::fstat(fd, &info) != 0) throw InputError(path + ": cannot read " + what + " (" + std::strerror(errno) + ")");
  // Anything but a directory or a block device (a disk: gigabytes that are no input file).
  if (S_ISDIR(info.st_mode) || S_ISBLK(info.st_mode)) {
    throw InputError(path + ": " + (S_ISDIR(info.st_mode) ? "a directory" : "a block device") + ", not a " + what);
  }
  if (S_ISREG(info.st_mode) && static_cast<std::size_t>(info.st_size) > kMaxInputFileBytes) {
    throw InputError(path + ": " + std::to_string(info.st_size) + " bytes; a " + what + " may have at most " +
                     limit_text());
  }
  std::string text;
  char chunk[1 << 16];
  while (true) {
    // A FIFO with no writer yet reads as empty: wait until one has written or come and gone.
    wait_readable(fd);
    const ssize_t n = ::read(fd, chunk, sizeof chunk);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) continue;
      throw InputError(path + ": cannot read " + what + " (" + std::strerror(errno) + ")");
    }
    if (text.size() + static_cast<std::size_t>(n) > kMaxInputFileBytes) {
      throw InputError(path + ": more than " + limit_text() + "; a " + what + " may have at most " + limit_text());
    }
    text.append(chunk, static_cast<std::size_t>(n));
  }
  return text;
}

}  // namespace mssph
