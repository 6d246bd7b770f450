#include "compression_watch.hpp"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <sstream>

namespace mssph {

CompressionWatch::CompressionWatch(RunLog& log, const ParticleSetup& setup) : log_(log) {
  for (std::size_t b = 0; b < setup.bodies.size(); ++b) {
    const BodySetup& body = setup.bodies[b];
    if (body.kind != BodyKind::deformable) continue;
    Watched w;
    w.body = b;
    w.name = body.name;
    w.model = to_string(body.material.model);
    w.lowest_valid = lowest_valid_volume_ratio(body.material.model);
    const std::string g = "/bodies/" + body.name;
    log.set_attribute(g, "model", w.model);
    log.set_attribute(g, "lowest_valid_volume_ratio", w.lowest_valid);
    w.min_series = log.add_series(g + "/min_volume_ratio", 1, "1",
                                  "smallest volume ratio J = det F of the body's particle neighbourhoods (1 at rest, "
                                  "0 collapsed, negative inverted)");
    std::ostringstream description;
    description << "particles with J <= " << w.lowest_valid << ", the lowest volume ratio the " << w.model
                << " model is valid for (attribute lowest_valid_volume_ratio)";
    w.count_series = log.add_series(g + "/compressed_count", 1, "1", description.str());
    watched_.push_back(w);
  }
}

void CompressionWatch::record(const std::vector<BodyState>& states, double time) {
  for (Watched& w : watched_) {
    const BodyState& s = states[w.body];
    const double row_min = s.min_volume_ratio;
    const double row_count = static_cast<double>(s.compressed_count);
    log_.append(w.min_series, std::span<const double>(&row_min, 1));
    log_.append(w.count_series, std::span<const double>(&row_count, 1));
    ++w.samples;
    if (s.compressed_count == 0) continue;
    ++w.samples_outside;
    if (w.warned) continue;
    w.warned = true;
    std::ostringstream message;
    message << "body \"" << w.name << "\" is compressed beyond its material model's valid range at t = " << time
            << " s: smallest volume ratio det F = " << s.min_volume_ratio << " <= " << w.lowest_valid << " (" << w.model
            << ", " << s.compressed_count << " particles); its forces no longer describe the material";
    if (w.model == "stvk") message << " (consider model neo_hookean or corotated)";
    std::cerr << "warning: " << message.str() << "\n";
    log_.set_attribute("/bodies/" + w.name, "compression_warning", message.str());
  }
}

double CompressionWatch::finish() {
  double largest = 0.0;
  for (const Watched& w : watched_) {
    log_.set_attribute("/bodies/" + w.name, "fraction_outside_valid_range", w.fraction());
    largest = std::max(largest, w.fraction());
  }
  if (!watched_.empty()) log_.set_attribute("/", "fraction_outside_valid_range", largest);
  return largest;
}

std::string CompressionWatch::summary() const {
  std::ostringstream out;
  out.precision(3);
  for (const Watched& w : watched_) {
    if (w.samples_outside == 0) continue;
    if (out.tellp() > 0) out << ", ";
    out << w.name << " " << 100.0 * w.fraction() << " %";
  }
  return out.str();
}

StateArrays CompressionWatch::save_state() const {
  std::vector<std::int64_t> samples, outside;
  std::vector<std::uint8_t> warned;
  for (const Watched& w : watched_) {
    samples.push_back(static_cast<std::int64_t>(w.samples));
    outside.push_back(static_cast<std::int64_t>(w.samples_outside));
    warned.push_back(w.warned);
  }
  StateArrays state;
  state.put("samples", std::move(samples));
  state.put("samples_outside", std::move(outside));
  state.put("warned", std::move(warned));
  return state;
}

void CompressionWatch::restore_state(const StateArrays& state) {
  const std::vector<std::int64_t>& samples = state.get<std::int64_t>("samples", watched_.size());
  const std::vector<std::int64_t>& outside = state.get<std::int64_t>("samples_outside", watched_.size());
  const std::vector<std::uint8_t>& warned = state.get<std::uint8_t>("warned", watched_.size());
  for (std::size_t k = 0; k < watched_.size(); ++k) {
    watched_[k].samples = static_cast<std::size_t>(samples[k]);
    watched_[k].samples_outside = static_cast<std::size_t>(outside[k]);
    watched_[k].warned = warned[k] != 0;
  }
}

}  // namespace mssph
