#pragma once
// What kind of file a stat(2) result describes, as messages name it ("a directory", "a FIFO"):
// for refusing paths that must be regular files, as inputs and as outputs.
#include <sys/stat.h>

#include <string>

namespace mssph {

// "a directory", "a symbolic link", "a device", "a FIFO", "a socket", or "a regular file".
std::string file_kind(const struct stat& st);

}  // namespace mssph
