// Scene files a hostile user could give `mssph run`: a value nested 100000 deep, a file of
// hundreds of thousands of objects, /dev/zero, a file over the size limit, a FIFO and a pipe.
// Each is refused with exit code 2 (or read, for the FIFO and the pipe) within seconds, with no
// crash and without reading the file twice.
#include "cli_fixture.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <thread>

namespace mssph::test {
namespace {

using namespace std::chrono_literals;

class InputBounds : public Cli {
 protected:
  // A file among the test's inputs, outside the working directory (which must stay empty).
  std::string input(const std::string& name, const std::string& text) const {
    const std::string path = (inputs_ / name).string();
    std::ofstream(path) << text;
    return path;
  }
  std::string input_path(const std::string& name) const { return (inputs_ / name).string(); }

  // The base scene with `value` (JSON text) at `key` of `object` (a member of the root, or the
  // root itself when empty).
  static std::string base_with(const std::string& object, const std::string& key, const std::string& value) {
    nlohmann::json scene = read_json(kCorpusBase);
    nlohmann::json& target = object.empty() ? scene : scene[object];
    target[key] = "@VALUE@";
    std::string text = scene.dump();
    text.replace(text.find("\"@VALUE@\""), 9, value);
    return text;
  }

  TempDir inputs_;
};

std::string nested_arrays(std::size_t depth) { return std::string(depth, '[') + std::string(depth, ']'); }

// Describing the value in the error message serialised it whole, recursively: SIGSEGV.
TEST_F(InputBounds, AValueNestedDeepWhereAStringOrNumberIsExpectedIsRefusedWithoutACrash) {
  const std::string deep = nested_arrays(100000);
  for (const auto& [object, key] :
       std::vector<std::pair<std::string, std::string>>{{"", "name"}, {"simulation", "dt"}, {"", "unknown_section"}}) {
    SCOPED_TRACE(key);
    const std::string scene = input("deep.json", base_with(object, key, deep));
    const ProcessResult r = mssph({"run", scene, "-q", "--out", work("o.h5")});
    EXPECT_EQ(r.exit_code, 2) << "signal " << r.signal << "\n" << r.err;
    EXPECT_NE(r.err.find("deep.json: /" + (object.empty() ? key : object + "/" + key) + "/0/0/"), std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("nested more than 64 levels"), std::string::npos) << r.err;
    EXPECT_LT(r.err.size(), 2000u) << "the message describes the value briefly";
    EXPECT_TRUE(work_entries().empty());
  }
}

// The duplicate-key check scanned the parent container at every object's end: 200,000 objects
// took 50 s, a million keyframes never finished loading.
TEST_F(InputBounds, TwoHundredThousandObjectsLoadInSeconds) {
  std::string objects = "[";
  for (int i = 0; i < 200000; ++i) objects += (i ? ",{\"a\":" : "{\"a\":") + std::to_string(i) + "}";
  objects += "]";
  const std::string scene = input("bulk.json", base_with("", "bulk", objects));
  const auto began = std::chrono::steady_clock::now();
  const ProcessResult r = start({"run", scene, "-q", "--out", work("o.h5")})->wait(30s);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  ASSERT_FALSE(r.timed_out) << "still loading after 30 s";
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("bulk.json: /bulk: unknown key 'bulk'"), std::string::npos) << r.err;
  EXPECT_LT(seconds, 10.0) << "loading is linear in the file's size";
}

TEST_F(InputBounds, DevZeroIsRefusedAtTheSizeLimit) {
  const ProcessResult r = start({"run", "/dev/zero", "-q", "--out", work("o.h5")})->wait(30s);
  ASSERT_FALSE(r.timed_out);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("/dev/zero: more than 64 MiB; a scene file may have at most 64 MiB"), std::string::npos)
      << r.err;
  EXPECT_TRUE(work_entries().empty());
}

TEST_F(InputBounds, AFileOverTheSizeLimitIsRefusedUnread) {
  const std::string big = input_path("big.json");
  std::ofstream(big).close();
  std::filesystem::resize_file(big, (std::uintmax_t{64} << 20) + 1);  // sparse: nothing to write
  const ProcessResult r = mssph({"run", big, "-q", "--out", work("o.h5")});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("big.json: 67108865 bytes; a scene file may have at most 64 MiB"), std::string::npos) << r.err;
}

// The scene was read twice (to parse it, then to record it): from a FIFO the second read waited
// for a writer that never came.
TEST_F(InputBounds, AFifoIsReadOnce) {
  const std::string fifo = input_path("scene.fifo");
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  const std::string text = read_file(kCorpusBase);
  std::thread writer([&] {
    // Non-blocking: fails with ENXIO until mssph has opened the FIFO for reading.
    const auto deadline = std::chrono::steady_clock::now() + 30s;
    int fd = -1;
    while (fd < 0 && std::chrono::steady_clock::now() < deadline) {
      fd = open(fifo.c_str(), O_WRONLY | O_NONBLOCK);
      if (fd < 0) std::this_thread::sleep_for(5ms);
    }
    if (fd < 0) return;
    fcntl(fd, F_SETFL, 0);
    for (std::size_t done = 0; done < text.size();) {
      const ssize_t n = write(fd, text.data() + done, text.size() - done);
      if (n <= 0) break;
      done += static_cast<std::size_t>(n);
    }
    close(fd);
  });
  const ProcessResult r = start({"run", fifo, "--dry-run", "--backend", "cpu", "--out", work("o.h5")})->wait(30s);
  writer.join();
  ASSERT_FALSE(r.timed_out) << "waiting for a second writer";
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("particles: 227"), std::string::npos) << r.out;
}

// `cat scene.json | mssph run /dev/stdin`: the log records the text that was parsed.
TEST_F(InputBounds, APipedSceneIsRecordedInTheLog) {
  const std::string command = "cat '" + kCorpusBase + "' | '" MSSPH_BINARY "' run /dev/stdin -q --backend cpu " +
                              "--threads 1 --out '" + work("piped.h5") + "'";
  const ProcessResult r = run_process({"/bin/sh", "-c", command}, work_.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const h5::Handle log = open_read_only(work("piped.h5"));
  EXPECT_EQ(h5::read_string_attribute(log.id(), "config_file"), read_file(kCorpusBase));
  EXPECT_EQ(h5::read_string_attribute(log.id(), "config_path"), "/dev/stdin");
}

}  // namespace
}  // namespace mssph::test
