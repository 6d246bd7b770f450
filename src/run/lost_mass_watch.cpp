#include "lost_mass_watch.hpp"

#include "util/errors.hpp"

#include <sstream>

namespace mssph {

LostMassWatch::LostMassWatch(RunLog& log, const ParticleSetup& setup)
    : log_(log), max_fraction_(setup.max_lost_mass_fraction) {
  std::ostringstream domain;
  domain.precision(9);
  domain << "[" << setup.domain.min.x() << ", " << setup.domain.min.y() << ", " << setup.domain.min.z() << "] to ["
         << setup.domain.max.x() << ", " << setup.domain.max.y() << ", " << setup.domain.max.z() << "] m";
  log.set_attribute("/", "domain", domain.str());
  log.set_attribute("/", "max_lost_mass_fraction", max_fraction_);
  for (std::size_t b = 0; b < setup.bodies.size(); ++b) {
    const BodySetup& body = setup.bodies[b];
    if (body.kind != BodyKind::fluid && body.kind != BodyKind::deformable) continue;
    Watched w;
    w.body = b;
    w.name = body.name;
    w.particles = body.count;
    w.series = log.add_series("/bodies/" + body.name + "/left_domain_count", 1, "1",
                              "particles of the body deactivated after leaving the simulation domain (root "
                              "attribute domain): held where they left, no longer moving");
    watched_.push_back(w);
  }
}

void LostMassWatch::check(const std::vector<BodyState>& states, double time) {
  for (Watched& w : watched_) {
    w.left = states[w.body].left_domain_count;
    const double fraction = static_cast<double>(w.left) / static_cast<double>(w.particles);
    if (fraction <= max_fraction_) continue;
    std::ostringstream message;
    message << w.left << " particles of body \"" << w.name << "\" left the domain by t = " << time << " s ("
            << 100.0 * fraction << " % of its mass, beyond simulation/max_lost_mass_fraction = " << max_fraction_
            << ")";
    throw SimulationFailure(message.str());
  }
}

void LostMassWatch::record(const std::vector<BodyState>& states) {
  for (const Watched& w : watched_) {
    const double count = static_cast<double>(states[w.body].left_domain_count);
    log_.append(w.series, std::span<const double>(&count, 1));
  }
}

std::string LostMassWatch::finish() {
  std::ostringstream out;
  out.precision(3);
  for (const Watched& w : watched_) {
    log_.set_attribute("/bodies/" + w.name, "left_domain_count", static_cast<long long>(w.left));
    if (w.left == 0) continue;
    if (out.tellp() > 0) out << ", ";
    out << w.name << " " << w.left << " particles ("
        << 100.0 * static_cast<double>(w.left) / static_cast<double>(w.particles) << " %)";
  }
  return out.str();
}

StateArrays LostMassWatch::save_state() const {
  std::vector<std::int64_t> left;
  for (const Watched& w : watched_) left.push_back(static_cast<std::int64_t>(w.left));
  StateArrays state;
  state.put("left", std::move(left));
  return state;
}

void LostMassWatch::restore_state(const StateArrays& state) {
  const std::vector<std::int64_t>& left = state.get<std::int64_t>("left", watched_.size());
  for (std::size_t k = 0; k < watched_.size(); ++k) watched_[k].left = static_cast<std::size_t>(left[k]);
}

}  // namespace mssph
