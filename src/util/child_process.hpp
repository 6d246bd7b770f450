#pragma once
// Running another program to completion: a Python script, or this program under Valgrind. The
// child inherits the environment; what this process printed is flushed first, so it appears
// before what the child prints.
#include <string>
#include <vector>

namespace mssph {

// Runs argv[0] (a path, or a name looked up on PATH) with the arguments, its stdout and stderr
// passed through, and returns its exit code: 127 when it could not be started, 128 + N when
// killed by signal N. With `captured_stdout`, its stdout is returned there instead of printed.
int run_program(const std::vector<std::string>& argv, std::string* captured_stdout = nullptr);

}  // namespace mssph
