#pragma once
// The Python side of the file-format checks (h5py and the standard library's XML parser),
// run with MSSPH_PYTHON: what a user's analysis script or ParaView's reader would see.
#include "child_process.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace mssph::test {

// h5py's view of a file (tests/io/h5py_summary.py); fails the calling test when h5py cannot
// read it.
nlohmann::json h5py_summary(const std::string& h5_path);

// tests/io/check_xdmf.py on a sidecar: exit code 0 and "grids N" on stdout when it is valid.
ProcessResult check_xdmf(const std::string& xdmf_path);

}  // namespace mssph::test
