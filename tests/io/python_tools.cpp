#include "python_tools.hpp"

#include <gtest/gtest.h>

namespace mssph::test {

nlohmann::json h5py_summary(const std::string& h5_path) {
  const ProcessResult r = run_process({MSSPH_PYTHON, MSSPH_SOURCE_DIR "/tests/io/h5py_summary.py", h5_path});
  EXPECT_EQ(r.exit_code, 0) << "h5py could not read " << h5_path << ":\n" << r.err;
  return r.exit_code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json::object();
}

ProcessResult check_xdmf(const std::string& xdmf_path) {
  return run_process({MSSPH_PYTHON, MSSPH_SOURCE_DIR "/tests/io/check_xdmf.py", xdmf_path});
}

}  // namespace mssph::test
