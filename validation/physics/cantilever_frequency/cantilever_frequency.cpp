#include "cantilever_frequency.hpp"

#include "backend_factory/backend_factory.hpp"
#include "model/scene_builder.hpp"
#include "physics/cantilever/cantilever.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

namespace mssph::validation {

double oscillation_frequency(const std::vector<double>& time, const std::vector<double>& signal) {
  if (signal.size() < 2) return 0.0;
  const double level = std::accumulate(signal.begin(), signal.end(), 0.0) / static_cast<double>(signal.size());
  std::vector<double> crossings;
  for (std::size_t k = 1; k < signal.size(); ++k) {
    const double a = signal[k - 1] - level;
    const double b = signal[k] - level;
    if (a < 0.0 && b >= 0.0) crossings.push_back(time[k - 1] + (time[k] - time[k - 1]) * a / (a - b));
  }
  if (crossings.size() < 2) return 0.0;
  return static_cast<double>(crossings.size() - 1) / (crossings.back() - crossings.front());
}

CantileverVibration measure_cantilever_vibration(const std::string& backend_name, double dx, bool correction,
                                                 double periods) {
  const CantileverBeam beam = cantilever_beam();
  const double period = 2.0 * std::numbers::pi / beam.first_bending_omega();
  const Scene scene = cantilever_scene(beam, dx, 0.0, periods * period, correction);
  const double dt = scene.simulation.dt;
  const ParticleSetup setup = build_particles(scene);
  std::unique_ptr<Backend> backend = make_backend(backend_name, setup);

  std::vector<std::size_t> tip_layer;  // the last layer of particles, rest x within dx of the free end
  for (std::size_t i = 0; i < setup.size(); ++i) {
    if (setup.position[i].x() >= beam.length - dx) tip_layer.push_back(i);
  }
  const auto tip_sag = [&](const ParticleSnapshot& snapshot) {
    double sum = 0.0;
    for (std::size_t i : tip_layer) sum += setup.position[i].z() - double(snapshot.position[3 * i + 2]);
    return sum / static_cast<double>(tip_layer.size());
  };

  CantileverVibration v;
  v.particles = setup.size();
  v.steps = static_cast<std::size_t>(std::ceil(periods * period / dt));
  v.euler_bernoulli = 1.0 / period;
  const auto stride = std::max<std::size_t>(1, static_cast<std::size_t>(period / (200.0 * dt)));
  for (std::size_t s = 0; s <= v.steps; ++s) {
    if (s % stride == 0) {
      v.time.push_back(static_cast<double>(s) * dt);
      v.tip.push_back(tip_sag(backend->snapshot()));
    }
    if (s < v.steps) backend->step();
  }
  v.frequency = oscillation_frequency(v.time, v.tip);
  v.max_tip = *std::max_element(v.tip.begin(), v.tip.end());
  return v;
}

}  // namespace mssph::validation
