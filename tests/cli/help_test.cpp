// `mssph --help`, `mssph run --help` and `mssph info`: they work and say what the program does.
#include "backend_factory/backend_factory.hpp"
#include "cli/commands.hpp"
#include "cli_fixture.hpp"
#include "util/build_info.hpp"

namespace mssph::test {
namespace {

void expect_mentions(const std::string& text, const std::vector<std::string>& phrases) {
  for (const std::string& p : phrases) EXPECT_NE(text.find(p), std::string::npos) << "\"" << p << "\" in\n" << text;
}

// The exit codes of errors.hpp, as documented in both help texts.
const std::vector<std::string> kExitCodes{"Exit codes: 0 ", "1 other error", "2 bad input", "3 simulation failure",
                                          "130, 143",       "129",           "SIGHUP"};

using Help = Cli;

TEST_F(Help, TopLevelListsCommandsAndExitCodes) {
  const ProcessResult r = mssph({"--help"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  expect_mentions(r.out, {"run ", "info ", "mssph run --help"});
  expect_mentions(r.out, kExitCodes);
}

TEST_F(Help, RunListsEveryOptionAndDocumentsOutputAndOverrides) {
  const ProcessResult r = mssph({"run", "--help"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  // Every option the command registers, taken from the same registration code.
  CLI::App app;
  int exit_code = 0;
  cli::add_run_command(app, exit_code);
  for (const CLI::Option* option : app.get_subcommand("run")->get_options()) {
    expect_mentions(r.out, {option->get_name()});
  }
  expect_mentions(r.out,
                  {"results/runs/<scene>_<backend>.h5", "--set PATH=VALUE", "flush_interval", ".xdmf", "\"completed\"",
                   "\"failed:", "\"interrupted: <signal>", "--force", "--dry-run", "--threads", ".partial"});
  expect_mentions(r.out, kExitCodes);
}

TEST_F(Help, InfoNamesVersionAndBackends) {
  const ProcessResult r = mssph({"info"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  expect_mentions(r.out, {"mssph " + build_info().version, build_info().git_commit});
  expect_mentions(r.out, available_backends());
  expect_mentions(r.out, {"GPU"});  // a line per device, or why none is used
}

TEST_F(Help, NoSubcommandIsBadInput) {
  const ProcessResult r = mssph({});
  EXPECT_EQ(r.exit_code, 2);
  expect_mentions(r.err, {"subcommand", "--help"});
}

}  // namespace
}  // namespace mssph::test
