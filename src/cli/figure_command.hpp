#pragma once
// `mssph figure 2|3|tss`: the paper's figures (and the one-world scene) from one command each.
// Each figure runs what it needs through the ordinary run machinery, writes HDF5 files, and hands
// them to a plotting script under scripts/figures/ that reads only those files.
#include <string>
#include <vector>

namespace mssph::cli {

struct Figure2Options {
  std::string backend = "auto";
  std::vector<std::string> media{"fluid", "deformable", "rigid"};
  std::vector<long long> sizes{2000, 5000, 10000, 15000, 20000, 25000, 30000};  // the paper's range
  long long max_particles = 0;  // > the largest size: extend on a 1-2-5 log scale up to it
  std::string geometry = "paper";
  double min_seconds = 0.5;  // timed steps per size, at least [s]
  std::string out = "results/runs/figure2";
  bool force = false;  // replace an earlier figure2.h5
};

struct Figure3Options {
  std::string backend = "auto";
  std::string resolution = "paper";  // coarse (4 cm), paper (2 cm), fine (1 cm)
  std::string out = "results/runs/figure3";
  std::string configs;  // where sphere_drop_{rigid,deformable,fluid}.json are
  std::vector<std::string> overrides;
  bool quiet = false;
  bool force = false;  // replace earlier run logs in `out`
};

struct FigureTssOptions {
  std::string backend = "auto";
  std::string out = "results/runs/figure_tss";
  std::string scene;
  std::vector<std::string> overrides;
  bool quiet = false;
  bool force = false;  // replace an earlier run log in `out`
};

// Each returns the process exit code: 0 when the figure was made (and its checks passed), 1 when
// a check failed or a run did not complete; bad input throws InputError.
int make_figure2(const Figure2Options& options, const std::string& command_line);
int make_figure3(const Figure3Options& options);
int make_figure_tss(const FigureTssOptions& options);

}  // namespace mssph::cli
