#include "scene_builder.hpp"

#include "fluid_fill.hpp"
#include "hashed_cells.hpp"
#include "lattice.hpp"
#include "model/lattice_calibration.hpp"
#include "rigid_interior.hpp"
#include "simulation_domain.hpp"
#include "util/errors.hpp"

#include <cmath>
#include <cstdint>
#include <random>
#include <sstream>

namespace mssph {
namespace {

using Eigen::Vector3d;

// Rigid-body mass properties from equal-mass particles of physical mass m each. Each particle
// also carries the inertia of its own cube of side dx (m dx^2 / 6 about each axis), so that the
// sum converges to the continuum inertia and a thin body is never singular.
void set_rigid_mass_properties(BodySetup& body, const std::vector<Vector3d>& world, double density, double dx) {
  const double particle_mass = density * dx * dx * dx;
  Vector3d com = Vector3d::Zero();
  for (const Vector3d& x : world) com += x;
  com /= static_cast<double>(world.size());
  const Eigen::Matrix3d rotation = body.orientation.toRotationMatrix();
  Eigen::Matrix3d inertia =
      Eigen::Matrix3d::Identity() * (static_cast<double>(world.size()) * particle_mass * dx * dx / 6.0);
  for (const Vector3d& x : world) {
    const Vector3d r = rotation.transpose() * (x - com);  // body frame
    inertia += particle_mass * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
  }
  body.mass = particle_mass * static_cast<double>(world.size());
  body.centre_of_mass = com;
  body.inertia_body = inertia;
}

// The error for particles i and j of two bodies that overlap (check_overlaps).
InputError overlap_error(const Scene& scene, const ParticleSetup& setup, const Vector3d& site_i, std::size_t i,
                         std::size_t j) {
  const std::string& a = setup.bodies[setup.body[std::min(i, j)]].name;
  const std::string& b = setup.bodies[setup.body[std::max(i, j)]].name;
  std::ostringstream where;
  where << "[" << site_i.x() << ", " << site_i.y() << ", " << site_i.z() << "]";
  return InputError(scene.source_file + ": /bodies/" + b + "/position: bodies \"" + a + "\" and \"" + b +
                    "\" overlap near " + where.str() + " m (their particles' cells of side " +
                    std::to_string(setup.spacing) + " m intersect by half a spacing or more); move them apart");
}

// Each particle stands for the cube of side dx around its lattice site, aligned with its body. A
// particle of one body inside (or on the boundary of) a cube of another body means their volumes
// overlap by half a spacing or more, e.g. a ball placed inside a block whatever the offset of
// their lattices: such a start state would explode at the first step. Tested on the lattice sites
// before jitter; hashed cells of side dx keep this linear. Threads take ascending ranges of
// particles and each stops at its first overlap; the lowest particle's is reported, the one a
// single thread finds first.
void check_overlaps(const Scene& scene, const ParticleSetup& setup, const std::vector<Vector3d>& site) {
  const double half = 0.5 * setup.spacing * (1.0 + 1e-9);  // boundary included: interleaved lattices overlap
  const HashedCells cells(site, setup.spacing);
  std::vector<Eigen::Matrix3d> to_body_frame;
  for (const BodySetup& b : setup.bodies) to_body_frame.push_back(b.orientation.toRotationMatrix().transpose());
  const auto n = static_cast<std::int64_t>(setup.size());
  std::int64_t first = n;  // the lowest particle that overlaps another body's, n for none
  std::size_t partner = 0;
#pragma omp parallel
  {
    std::int64_t mine = n;
    std::size_t my_partner = 0;
#pragma omp for schedule(static)
    for (std::int64_t i = 0; i < n; ++i) {
      if (mine < n) continue;
      const auto s = static_cast<std::size_t>(i);
      cells.for_each_in_neighbourhood(cells.cell(s), [&](std::size_t j, const Vector3d& site_j) {
        if (setup.body[j] == setup.body[s]) return true;
        const Vector3d offset = to_body_frame[setup.body[j]] * (site[s] - site_j);
        if (offset.cwiseAbs().maxCoeff() > half) return true;
        mine = i;
        my_partner = j;
        return false;
      });
    }
#pragma omp critical(mssph_first_overlap)
    if (mine < first) {
      first = mine;
      partner = my_partner;
    }
  }
  if (first < n) {
    const auto i = static_cast<std::size_t>(first);
    throw overlap_error(scene, setup, site[i], i, partner);
  }
}

// A fluid or deformable particle outside a scene-set domain at the start would be deactivated by
// the first step: the domain is a mistake, refused as bad input.
void check_domain_holds_moving_particles(const Scene& scene, const ParticleSetup& setup) {
  if (!scene.simulation.domain) return;
  for (std::size_t i = 0; i < setup.size(); ++i) {
    const BodySetup& body = setup.bodies[setup.body[i]];
    if (body.kind != BodyKind::fluid && body.kind != BodyKind::deformable) continue;
    if (setup.domain.contains(setup.position[i])) continue;
    std::ostringstream message;
    const Vector3d& x = setup.position[i];
    message << scene.source_file << ": /simulation/domain: body \"" << body.name << "\" has a particle at [" << x.x()
            << ", " << x.y() << ", " << x.z()
            << "] m outside the domain at the start; the domain must hold every fluid and deformable particle";
    throw InputError(message.str(), "/simulation/domain");
  }
}

// Every body's lattice sites in the world frame, before jitter; a fluid that fills around bodies
// leaves out its sites closer than one spacing to another body's.
std::vector<std::vector<Vector3d>> lattice_sites(const Scene& scene) {
  const double dx = scene.simulation.particle_spacing;
  std::vector<std::vector<Vector3d>> sites;
  for (const BodyConfig& config : scene.bodies) {
    const Eigen::Matrix3d rotation = config.orientation.toRotationMatrix();
    std::vector<Vector3d> world;
    for (const Vector3d& p : sample_shape(config.shape, dx)) world.push_back(config.position + rotation * p);
    if (world.empty()) {
      throw InputError(scene.source_file + ": /bodies/" + config.name +
                       "/shape: the shape holds no particle at particle_spacing " + std::to_string(dx) +
                       " m; make it larger or the spacing smaller");
    }
    sites.push_back(std::move(world));
  }
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    if (!scene.bodies[b].fill_around_bodies) continue;
    std::vector<Vector3d> others;
    for (std::size_t o = 0; o < sites.size(); ++o) {
      if (o != b) others.insert(others.end(), sites[o].begin(), sites[o].end());
    }
    sites[b] = sites_clear_of(sites[b], others, dx);
    if (sites[b].empty()) {
      throw InputError(scene.source_file + ": /bodies/" + scene.bodies[b].name +
                       "/fill_around_bodies: no particle of the fluid is left once it leaves room for the other "
                       "bodies");
    }
  }
  return sites;
}

}  // namespace

ParticleSetup build_particles(const Scene& scene) {
  const SimulationConfig& sim = scene.simulation;
  ParticleSetup setup;
  setup.spacing = sim.particle_spacing;
  setup.smoothing_length = sim.smoothing_length;
  setup.rest_number_density = lattice_number_density(sim.particle_spacing, sim.smoothing_length);
  setup.gradient_consistency = lattice_gradient_consistency(sim.particle_spacing, sim.smoothing_length);
  setup.gravity = sim.gravity;
  setup.dt = sim.dt;
  setup.max_speed = sim.max_speed;

  std::mt19937_64 random(sim.seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double jitter = sim.jitter * sim.particle_spacing;
  std::vector<Vector3d> lattice_site;  // every particle's position before jitter
  const std::vector<std::vector<Vector3d>> sites = lattice_sites(scene);

  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    const BodyConfig& config = scene.bodies[b];
    const std::vector<Vector3d>& body_sites = sites[b];
    BodySetup body;
    body.name = config.name;
    body.kind = config.kind;
    body.material = config.material;
    body.first = setup.size();
    body.count = body_sites.size();
    body.lattice_sites = body_sites.size();
    body.orientation = config.orientation;
    body.velocity = config.velocity;
    body.angular_velocity = config.angular_velocity;
    body.fixed = config.fixed;

    const Eigen::Matrix3d rotation = config.orientation.toRotationMatrix();
    std::vector<Vector3d> world;
    world.reserve(body_sites.size());
    for (Vector3d x : body_sites) {
      lattice_site.push_back(x);
      if (jitter > 0.0) x += jitter * Vector3d(unit(random), unit(random), unit(random));
      world.push_back(x);
    }
    if (config.kind == BodyKind::rigid) set_rigid_mass_properties(body, world, config.density, sim.particle_spacing);

    // Each particle stands for its lattice cell: m = rho0 dx^3 (density.hpp reads densities
    // against the rest lattice, so a rest lattice is at rho0 whatever the kernel).
    const double sph_mass =
        config.material.rest_density * sim.particle_spacing * sim.particle_spacing * sim.particle_spacing;
    const std::uint32_t body_index = static_cast<std::uint32_t>(setup.bodies.size());
    for (const Vector3d& x : world) {
      Vector3d v = Vector3d::Zero();
      if (config.kind == BodyKind::rigid && !config.fixed) {
        v = config.velocity + config.angular_velocity.cross(x - body.centre_of_mass);
      } else if (config.kind == BodyKind::fluid || config.kind == BodyKind::deformable) {
        v = config.velocity;
      }
      const bool held = std::any_of(config.fixed_regions.begin(), config.fixed_regions.end(),
                                    [&](const Region& r) { return r.contains(x); });
      if (held) {
        v = Vector3d::Zero();
        ++body.fixed_count;
      }
      setup.position.push_back(x);
      setup.velocity.push_back(v);
      setup.mass.push_back(sph_mass);
      setup.body.push_back(body_index);
      setup.fixed.push_back(held ? 1 : 0);
      setup.rest_offset.push_back(config.kind == BodyKind::rigid
                                      ? Vector3d(rotation.transpose() * (x - body.centre_of_mass))
                                      : Vector3d::Zero());
    }
    setup.bodies.push_back(body);
  }
  check_overlaps(scene, setup, lattice_site);  // on every site: a body inside another's interior is refused
  if (!sim.sample_rigid_interiors) {
    leave_out_rigid_interiors(setup, lattice_site, rigid_surface_reach(sim.smoothing_length, sim.particle_spacing));
  }
  setup.domain = sim.domain ? *sim.domain : default_simulation_domain(setup.position, setup.smoothing_length);
  check_domain_holds_moving_particles(scene, setup);
  setup.max_lost_mass_fraction = sim.max_lost_mass_fraction;
  setup.viscosity_model = sim.viscosity_model;
  setup.neighbour_lists = sim.neighbour_lists;
  return setup;
}

}  // namespace mssph
