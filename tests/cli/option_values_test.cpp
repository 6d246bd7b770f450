// Option values that CLI11 let through although they make no sense: a checkpoint interval of nan
// (never elapses) or inf (refused with a 310-digit bound), validate's --seed 0 (taken as "fresh")
// and -1 (wrapped to 2^64 - 1), and validate's --out naming a file (exit 1, "filesystem error").
#include "cli_fixture.hpp"

#include <fstream>

namespace mssph::test {
namespace {

using OptionValues = Cli;

TEST_F(OptionValues, ACheckpointIntervalIsAPositiveFiniteNumber) {
  for (const char* value : {"nan", "inf", "0", "1s"}) {
    const std::string expected = std::string("--checkpoint-interval: expected a positive finite number, got ") + value;
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"run", kCorpusBase, "-q", "--out", work("o.h5")},
          std::vector<std::string>{"sweep", data_file("sweeps/tiny_product.json"), "--out", work("sweep")}}) {
      std::vector<std::string> with_value = args;
      with_value.insert(with_value.end(), {"--checkpoint-interval", value});
      const ProcessResult r = mssph(with_value);
      EXPECT_EQ(r.exit_code, 2) << args.front() << " " << value << "\n" << r.err;
      EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
      EXPECT_LT(r.err.size(), 200u) << "no 310-digit bound:\n" << r.err;
      EXPECT_TRUE(work_entries().empty());
    }
  }
}

TEST_F(OptionValues, ValidateSeedZeroIsASeedAndOnlyUnsignedIntegersAreSeeds) {
  const ProcessResult zero = mssph({"validate", "--quick", "--suite", "selftest", "--seed", "0", "--out", work("v")});
  EXPECT_EQ(zero.exit_code, 1) << "the self-test's expectation is wrong on purpose\n" << zero.err;
  EXPECT_NE(zero.err.find(", seed 0\n"), std::string::npos) << zero.err;
  EXPECT_EQ(read_json(work("v/report.json"))["run"]["seed"], 0);
  for (const char* seed : {"-1", "1.5", "18446744073709551616", "seven"}) {
    const ProcessResult r = mssph({"validate", "--quick", "--suite", "selftest", "--seed", seed, "--out", work("w")});
    EXPECT_EQ(r.exit_code, 2) << seed << "\n" << r.err;
    EXPECT_NE(r.err.find(std::string("--seed ") + seed + ": expected an integer from 0 to 18446744073709551615"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(std::filesystem::exists(work("w"))) << seed;
  }
}

TEST_F(OptionValues, ValidateOutThatIsAFileIsBadInput) {
  std::ofstream(work("report")) << "precious";
  const ProcessResult r = mssph({"validate", "--quick", "--suite", "selftest", "--out", work("report")});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--out " + work("report") + ": not a directory"), std::string::npos) << r.err;
  EXPECT_EQ(read_file(work("report")), "precious");
}

}  // namespace
}  // namespace mssph::test
