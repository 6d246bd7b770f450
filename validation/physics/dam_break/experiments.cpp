#include "experiments.hpp"

namespace mssph::validation {

const DamBreakExperiment& martin_moyce_1952() {
  static const DamBreakExperiment experiment{
      "Martin and Moyce 1952",
      {0.41, 0.84, 1.19, 1.43, 1.63, 1.83, 1.98, 2.20, 2.32, 2.51, 2.65, 2.83, 2.98, 3.11, 3.33},
      {1.11, 1.22, 1.44, 1.67, 1.89, 2.11, 2.33, 2.56, 2.78, 3.00, 3.22, 3.44, 3.67, 3.89, 4.11},
      {0.56, 0.77, 0.93, 1.08, 1.28, 1.46, 1.66, 1.84, 2.00, 2.21, 2.45, 2.70, 3.06, 3.44, 4.20, 5.25, 7.40},
      {0.94, 0.89, 0.83, 0.78, 0.72, 0.67, 0.61, 0.56, 0.50, 0.44, 0.39, 0.33, 0.28, 0.22, 0.17, 0.11, 0.06}};
  return experiment;
}

const DamBreakExperiment& koshizuka_oka_1996() {
  static const DamBreakExperiment experiment{"Koshizuka and Oka 1996",
                                             {0.0, 0.381, 0.769, 1.153, 1.537, 1.935, 2.323, 2.719, 3.096},
                                             {1.000, 1.111, 1.252, 1.505, 1.892, 2.241, 2.615, 3.003, 3.624},
                                             {},
                                             {}};
  return experiment;
}

}  // namespace mssph::validation
