#pragma once
// A scene as read from its JSON file: typed, validated, SI units throughout. The keys and their
// units are documented in configs/README.md and checked by configs/scene.schema.json.
#include "config/elastic_model.hpp"
#include "config/haptics_config.hpp"

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace mssph {

enum class BodyKind { fluid, deformable, rigid, boundary };
enum class ShapeType { box, sphere, container, spherical_container };
// The viscous force inside fluids and between bodies (cpu_reference/fluid_forces.hpp):
//   paper:       eq. 3 as printed, mu lap u, whose pair forces carry mu grad u across a surface;
//   full_stress: eq. 3 plus the divergence of mu (grad u)^T, so that a surface carries the whole
//                Newtonian stress mu (grad u + grad u^T) (decision 057).
enum class ViscosityModel { paper, full_stress };
// Whether the GPU's neighbour sums keep neighbour lists with a skin (kernels/common/team_lanes.hpp):
//   automatic: by the scene's size, up to about four waves of the device's resident threads;
//   always:    at any size, for ~470 more bytes of device memory a particle.
enum class NeighbourListUse { automatic, always };

const char* to_string(BodyKind kind);

struct Shape {
  ShapeType type = ShapeType::box;
  Eigen::Vector3d size = Eigen::Vector3d::Zero();  // box: full edge lengths; container: inner size [m]
  double radius = 0.0;                             // sphere; spherical_container: inner radius [m]
  int wall_layers = 0;                             // containers: wall thickness in particle layers
  bool open_top = true;                            // container
};

// Material parameters of one body (any subset may be irrelevant to its kind).
struct Material {
  double rest_density = 0.0;        // rho0 [kg/m^3], SPH rest density of the EOS
  double pressure_stiffness = 0.0;  // k [m^2/s^2] in P = k (rho - rho0); sound speed c = sqrt(k)
  double viscosity = 0.0;           // mu [Pa s], paper eq. 3 (and eq. 7 between bodies)
  // Deformable bodies only (paper eq. 4-6):
  double young_modulus = 0.0;                                 // E [Pa]
  double poisson_ratio = 0.0;                                 // nu [-], in (-1, 0.5)
  ElasticModel model = ElasticModel::saint_venant_kirchhoff;  // stress response to F (config/elastic_model.hpp)
  double damping = 0.0;                                       // mass-proportional damping rate [1/s], 0 = off
  double viscous_modulus = 0.0;        // eta [Pa s] of the Kelvin-Voigt stress (eta / E) C : strain rate, 0 = off
  double zero_energy_stiffness = 0.0;  // hourglass control coefficient [-], 0 = off
  // On by default: without it the forces of eq. 5-6 are not conservative, and a loaded beam or a
  // released bar gains energy until it breaks up (validation/physics/cantilever/README.md).
  bool kernel_gradient_correction = true;
};

// An axis-aligned box in world coordinates [m]: a fixed region (particles of a deformable body
// inside it are held in place, e.g. a block glued to the ground) or the simulation domain.
struct Region {
  Eigen::Vector3d min = Eigen::Vector3d::Zero();
  Eigen::Vector3d max = Eigen::Vector3d::Zero();
  bool contains(const Eigen::Vector3d& p) const {
    return (p.array() >= min.array()).all() && (p.array() <= max.array()).all();
  }
};

struct BodyConfig {
  std::string name;
  BodyKind kind = BodyKind::fluid;
  Shape shape;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // centre of the shape [m]
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();          // [m/s]
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  // rigid bodies [rad/s]
  Material material;
  double density = 0.0;               // rigid bodies: physical density for mass and inertia [kg/m^3]
  bool fixed = false;                 // rigid bodies: immovable (then it acts as a boundary)
  std::vector<Region> fixed_regions;  // deformable bodies
  // Fluids: leave out the lattice sites within one spacing of another body's particles, so that
  // bodies can start inside the fluid.
  bool fill_around_bodies = false;
};

struct SimulationConfig {
  double dt = 0.0;                           // [s]
  double duration = 0.0;                     // [s]
  Eigen::Vector3d gravity{0.0, 0.0, -9.81};  // [m/s^2]
  double particle_spacing = 0.0;             // lattice spacing dx [m]
  double smoothing_length = 0.0;             // kernel support radius h [m]
  std::uint64_t seed = 0;                    // for the lattice jitter
  double jitter = 0.0;                       // random lattice perturbation, fraction of dx
  double max_speed = 0.0;                    // blow-up bound on any particle's speed [m/s]
  // The simulation domain: a particle that leaves it is deactivated (sim/lost_mass_watch.hpp).
  // Absent: the bounding box of all bodies' particles at the start plus a margin
  // (scene/simulation_domain.hpp).
  std::optional<Region> domain;
  double max_lost_mass_fraction = 0.001;  // of a body's mass outside the domain before the run fails [-]
  ViscosityModel viscosity_model = ViscosityModel::paper;
  // Whether rigid bodies keep every lattice site, or only those within reach of their surface
  // (model/rigid_interior.hpp): the same physics, fewer particles.
  bool sample_rigid_interiors = false;
  NeighbourListUse neighbour_lists = NeighbourListUse::automatic;
};

struct ProxyConfig {
  std::string body;       // the rigid body the haptic device drives
  HapticsConfig haptics;  // coupling, device and trajectory (config/haptics_config.hpp)
};

struct OutputConfig {
  double log_interval = 0.0;       // time-series sampling interval [s]; 0 = every step
  double snapshot_interval = 0.0;  // particle snapshots [s]; 0 = none
  double flush_interval = 2.0;     // wall-clock seconds between HDF5 flushes
};

struct Scene {
  std::string name;
  std::string description;
  std::string source_file;  // the file it was read from
  nlohmann::json document;  // the document after --set overrides, recorded verbatim in the log
  SimulationConfig simulation;
  std::vector<BodyConfig> bodies;
  std::optional<ProxyConfig> proxy;
  OutputConfig output;

  const BodyConfig* find_body(const std::string& body_name) const;
};

}  // namespace mssph
