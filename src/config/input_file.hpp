#pragma once
// Reading a whole input file (a scene, a sweep, a benchmark result) once and with a bound, so that
// what the path names cannot make mssph allocate without limit (/dev/zero, a file of gigabytes) or
// wait for ever where it cannot be interrupted (a FIFO nobody writes to).
#include <cstddef>
#include <string>

namespace mssph {

// The largest input file read: mssph's scenes, sweeps and benchmark results are kilobytes, and
// 64 MiB holds a million trajectory keyframes.
inline constexpr std::size_t kMaxInputFileBytes = std::size_t{64} << 20;

// The bytes of `path`: a regular file up to kMaxInputFileBytes (a larger one is refused before
// anything is read), or a pipe, FIFO, socket or terminal read to its end up to the same bound
// (/dev/stdin under `cat scene.json | mssph run /dev/stdin`). A directory or a block device is
// refused. Opening never waits for a FIFO's writer; reading waits for its data, and a
// signal with a handler that ends the process (see src/run/interrupt.hpp) ends that wait.
// `what` names the file's role in errors ("scene file"). Throws InputError.
std::string read_input_file(const std::string& path, const std::string& what);

}  // namespace mssph
