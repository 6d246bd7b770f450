#include "run_estimate.hpp"

#include "util/errors.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

namespace mssph::cli {
namespace {

// Peak resident memory per particle [bytes]: the maximum resident set size (/usr/bin/time -v)
// less that of a 227-particle run, on a 64,000-particle box (0.4 m at 1 cm, h = 2 dx, 2 steps)
// and on tests/data/tiny_drop.json at 5 mm, rounded up. The cpu backend's figure is dominated by
// its two sets of neighbour lists (64 entries a particle each), which grow with the neighbours
// per particle, (h / dx)^3; a deformable scene's peak is its set-up's.
constexpr double kReferenceBytes = 1750.0, kReferenceDeformableBytes = 4300.0;
constexpr double kHostFloatBytes = 900.0, kHostFloatDeformableBytes = 4900.0;
// The cuda backend keeps the scene set-up on the host (position, velocity, mass, body, rest
// offset: about 90 bytes, twice) and float32 arrays on the device: the cpu backend's figures
// without its neighbour lists, above what the device holds at 1M particles (117 fluid, 139 rigid,
// 377 deformable bytes).
constexpr double kCudaHostBytes = 200.0;
constexpr double kCudaDeviceBytes = 330.0, kCudaDeviceDeformableBytes = 4900.0;
// A scene that asks for neighbour lists at any size (simulation/neighbour_lists: always) adds two
// lanes of 56 four-byte entries a particle, their counts and the rebuild positions
// (kernels/cuda/device_arrays.hpp, team_list_capacity); by size, only scenes too small for the
// device's memory to matter keep them.
constexpr double kCudaListBytes = 2.0 * 56.0 * 4.0 + 2.0 * 4.0 + 16.0;

// float32 has a 24-bit significand: at a distance R from the origin positions are resolved to
// R 2^-23. Requiring that to be at most 2^-10 (about 0.1 %) of a spacing keeps lattice offsets
// and kernel gradients meaningful: R / dx <= 2^13.
constexpr double kMaxFloatExtentInSpacings = 8192.0;

double lattice_count(const Eigen::Vector3d& size, double dx) {
  double n = 1.0;
  for (int a = 0; a < 3; ++a) n *= std::max(0.0, std::round(size[a] / dx));
  return n;
}

double shape_particles(const Shape& shape, double dx) {
  switch (shape.type) {
    case ShapeType::box:
      return lattice_count(shape.size, dx);
    case ShapeType::sphere:
      return std::max(1.0, 4.0 / 3.0 * std::numbers::pi * std::pow(shape.radius / dx, 3));
    case ShapeType::container: {
      const double wall = shape.wall_layers * dx;
      const Eigen::Vector3d outer =
          shape.size + Eigen::Vector3d(2.0 * wall, 2.0 * wall, shape.open_top ? wall : 2.0 * wall);
      return lattice_count(outer, dx) - lattice_count(shape.size, dx);
    }
    case ShapeType::spherical_container:
      return 4.0 / 3.0 * std::numbers::pi *
             (std::pow(shape.radius / dx + shape.wall_layers, 3) - std::pow(shape.radius / dx, 3));
  }
  return 0.0;
}

// Half the edge of the shape's axis-aligned bounding box in any orientation (its bounding
// sphere's radius for boxes and box containers).
double shape_reach(const Shape& shape, double dx) {
  if (shape.type == ShapeType::sphere) return shape.radius;
  if (shape.type == ShapeType::spherical_container) return shape.radius + shape.wall_layers * dx;
  const Eigen::Vector3d full = shape.type == ShapeType::container
                                   ? shape.size + Eigen::Vector3d::Constant(2.0 * shape.wall_layers * dx)
                                   : shape.size;
  return 0.5 * full.norm();
}

std::optional<double> read_number_file(const std::string& path) {
  std::ifstream in(path);
  double value = 0.0;
  if (in >> value) return value;
  return std::nullopt;  // missing, or "max" (no limit)
}

}  // namespace

std::string format_bytes(double bytes) {
  const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  int u = 0;
  while (bytes >= 1024.0 && u < 6) {
    bytes /= 1024.0;
    ++u;
  }
  std::ostringstream out;
  out.precision(3);
  out << bytes << " " << units[u];
  return out.str();
}

RunEstimate estimate_run(const Scene& scene, const std::string& backend) {
  const double dx = scene.simulation.particle_spacing;
  const double neighbour_scale = std::max(1.0, std::pow(scene.simulation.smoothing_length / dx / 2.0, 3));
  RunEstimate e;
  e.steps = scene.simulation.duration / scene.simulation.dt;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = Eigen::Vector3d::Constant(-INFINITY);
  double per_particle_bytes = 0.0, device_bytes = 0.0;
  for (const BodyConfig& body : scene.bodies) {
    const double n = shape_particles(body.shape, dx);
    e.bodies.push_back({body.name, n});
    e.particles += n;
    const bool deformable = body.kind == BodyKind::deformable;
    const double bytes = backend == "reference" ? (deformable ? kReferenceDeformableBytes : kReferenceBytes)
                                                : (deformable ? kHostFloatDeformableBytes : kHostFloatBytes);
    per_particle_bytes += n * bytes;
    device_bytes += n * (deformable ? kCudaDeviceDeformableBytes : kCudaDeviceBytes);
    const double reach = shape_reach(body.shape, dx);
    lo = lo.cwiseMin(body.position - Eigen::Vector3d::Constant(reach));
    hi = hi.cwiseMax(body.position + Eigen::Vector3d::Constant(reach));
  }
  per_particle_bytes *= neighbour_scale;
  if (backend == "cuda") {
    e.device_bytes = device_bytes * neighbour_scale;
    if (scene.simulation.neighbour_lists == NeighbourListUse::always) e.device_bytes += e.particles * kCudaListBytes;
    e.host_bytes = e.particles * kCudaHostBytes;
  } else {
    e.host_bytes = per_particle_bytes;
  }
  e.extent_in_spacings = 0.5 * (hi - lo).maxCoeff() / dx;
  return e;
}

std::optional<double> available_host_memory() {
  std::optional<double> available;
  std::ifstream meminfo("/proc/meminfo");
  for (std::string key; meminfo >> key;) {
    double kib = 0.0;
    meminfo >> kib;
    if (key == "MemAvailable:") available = kib * 1024.0;
    meminfo.ignore(256, '\n');
  }
  // cgroup v2: what the group may still use.
  const std::optional<double> limit = read_number_file("/sys/fs/cgroup/memory.max");
  const std::optional<double> used = read_number_file("/sys/fs/cgroup/memory.current");
  if (limit && used) {
    const double left = std::max(0.0, *limit - *used);
    available = available ? std::min(*available, left) : left;
  }
  return available;
}

void check_run_fits(const Scene& scene, const std::string& backend, const RunEstimate& estimate,
                    std::optional<double> host_memory, std::optional<double> device_memory) {
  const std::string where = scene.source_file + ": ";
  // Particle indices are 32-bit in the backends.
  if (estimate.particles > 2147483647.0) {
    std::ostringstream m;
    m << where << "about " << estimate.particles << " particles at particle_spacing "
      << scene.simulation.particle_spacing << " m, beyond the 2^31 a run can index";
    throw InputError(m.str(), "/simulation/particle_spacing");
  }
  if (host_memory && estimate.host_bytes > *host_memory) {
    std::ostringstream m;
    m << where << "about " << estimate.particles << " particles need about " << format_bytes(estimate.host_bytes)
      << " of host memory on the " << backend << " backend; this machine has " << format_bytes(*host_memory)
      << " available (raise simulation/particle_spacing or shrink the bodies)";
    throw InputError(m.str(), "/simulation/particle_spacing");
  }
  if (device_memory && estimate.device_bytes > *device_memory) {
    std::ostringstream m;
    m << where << "about " << estimate.particles << " particles need about " << format_bytes(estimate.device_bytes)
      << " of GPU memory; the GPU has " << format_bytes(*device_memory);
    throw InputError(m.str(), "/simulation/particle_spacing");
  }
  if (backend != "reference" && estimate.extent_in_spacings > kMaxFloatExtentInSpacings) {
    std::ostringstream m;
    m << where << "the bodies reach " << estimate.extent_in_spacings
      << " particle spacings from the scene's centre; the float32 backends (cpu, cuda) resolve positions to "
         "0.1 % of a spacing only within "
      << kMaxFloatExtentInSpacings << " spacings (use --backend reference, or bring the bodies closer)";
    throw InputError(m.str(), "/bodies");
  }
}

}  // namespace mssph::cli
