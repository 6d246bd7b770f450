#include "lattice.hpp"

#include <cmath>

namespace mssph {
namespace {

// Cells of width dx that best fill `length`. A length under half a spacing rounds to none: the
// lattice cannot resolve it, and inflating it to a full cell would silently change the body's
// volume (and a rigid body's mass) by more than a factor of two.
int cells_along(double length, double dx) { return static_cast<int>(std::lround(length / dx)); }

// Cell centres of n cells of width dx centred on 0.
double cell_centre(int i, int n, double dx) { return (i - 0.5 * (n - 1)) * dx; }

}  // namespace

std::vector<Eigen::Vector3d> sample_box(const Eigen::Vector3d& size, double dx) {
  const int nx = cells_along(size.x(), dx);
  const int ny = cells_along(size.y(), dx);
  const int nz = cells_along(size.z(), dx);
  std::vector<Eigen::Vector3d> points;
  points.reserve(static_cast<std::size_t>(nx) * ny * nz);
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        points.emplace_back(cell_centre(i, nx, dx), cell_centre(j, ny, dx), cell_centre(k, nz, dx));
      }
    }
  }
  return points;
}

std::vector<Eigen::Vector3d> sample_sphere(double radius, double dx) {
  const int n = static_cast<int>(std::ceil(radius / dx));
  std::vector<Eigen::Vector3d> points;
  for (int k = -n; k <= n; ++k) {
    for (int j = -n; j <= n; ++j) {
      for (int i = -n; i <= n; ++i) {
        const Eigen::Vector3d p(i * dx, j * dx, k * dx);
        if (p.norm() < radius) points.push_back(p);
      }
    }
  }
  return points;
}

std::vector<Eigen::Vector3d> sample_container(const Eigen::Vector3d& inner, int layers, bool open_top, double dx) {
  // Inner cells per axis, then `layers` more on each side; the floor (and lid) likewise.
  int n_inner[3];
  for (int a = 0; a < 3; ++a) n_inner[a] = cells_along(inner[a], dx);
  // Without an inner cell along some axis the walls would merge into a solid block: not a container.
  if (n_inner[0] == 0 || n_inner[1] == 0 || n_inner[2] == 0) return {};
  const int nx = n_inner[0] + 2 * layers;
  const int ny = n_inner[1] + 2 * layers;
  const int nz = n_inner[2] + layers + (open_top ? 0 : layers);
  // z of the first layer so that the inner cells are centred on the container's centre.
  const double z0 = cell_centre(0, n_inner[2], dx) - layers * dx;
  std::vector<Eigen::Vector3d> points;
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        const bool inside_x = i >= layers && i < layers + n_inner[0];
        const bool inside_y = j >= layers && j < layers + n_inner[1];
        const bool inside_z = k >= layers && k < layers + n_inner[2];
        if (inside_x && inside_y && inside_z) continue;
        points.emplace_back(cell_centre(i, nx, dx), cell_centre(j, ny, dx), z0 + k * dx);
      }
    }
  }
  return points;
}

std::vector<Eigen::Vector3d> sample_spherical_container(double inner_radius, int layers, double dx) {
  const double outer_radius = inner_radius + layers * dx;
  std::vector<Eigen::Vector3d> points;
  for (const Eigen::Vector3d& p : sample_sphere(outer_radius, dx)) {
    if (p.norm() >= inner_radius) points.push_back(p);
  }
  return points;
}

std::vector<Eigen::Vector3d> sample_shape(const Shape& shape, double dx) {
  switch (shape.type) {
    case ShapeType::box:
      return sample_box(shape.size, dx);
    case ShapeType::sphere:
      return sample_sphere(shape.radius, dx);
    case ShapeType::container:
      return sample_container(shape.size, shape.wall_layers, shape.open_top, dx);
    case ShapeType::spherical_container:
      return sample_spherical_container(shape.radius, shape.wall_layers, dx);
  }
  return {};
}

}  // namespace mssph
