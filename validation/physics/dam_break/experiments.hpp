#pragma once
// Measured collapses of water columns of width a and height 2a, non-dimensional: the surge front
// Z = x / a at time T = t sqrt(2 g / a), and the column's height at the wall over 2a at
// tau = t sqrt(g / a).
#include <string>
#include <vector>

namespace mssph::validation {

struct DamBreakExperiment {
  std::string source;
  std::vector<double> front_time;   // T
  std::vector<double> front;        // Z
  std::vector<double> height_time;  // tau; empty where the source gives no heights
  std::vector<double> height;       // H / 2a
};

// Martin and Moyce 1952, Phil. Trans. R. Soc. A 244, 312-324, tables 2 and 6 (n^2 = 2,
// a = 2.25 in), as transcribed in the Ocellaris project (scripts/plot_dam_break.py).
const DamBreakExperiment& martin_moyce_1952();

// Koshizuka and Oka 1996, Nucl. Sci. Eng. 123, 421-434 (a = 14.6 cm in a tank 4a long), the
// front as digitised in PySPH (pysph/examples/db_exp_data.py).
const DamBreakExperiment& koshizuka_oka_1996();

}  // namespace mssph::validation
