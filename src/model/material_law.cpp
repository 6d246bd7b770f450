#include "model/material_law.hpp"

namespace mssph {

double lame_mu(const Material& m) { return m.young_modulus / (2.0 * (1.0 + m.poisson_ratio)); }
double lame_lambda(const Material& m) {
  return m.young_modulus * m.poisson_ratio / ((1.0 + m.poisson_ratio) * (1.0 - 2.0 * m.poisson_ratio));
}

}  // namespace mssph
