#include "rstruct/sampling/uniform_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "rstruct/core/error.hpp"
#include "rstruct/sampling/implicit_mesher.hpp"
#include "rstruct/sampling/random.hpp"

namespace rstruct::sampling {

namespace {

constexpr std::size_t kMaxCount = 1000000000;

void check_count(std::size_t count) {
  if (count > kMaxCount) {
    std::ostringstream msg;
    msg << "sample count " << count << " exceeds the limit " << kMaxCount;
    throw InvalidInput(msg.str());
  }
}

/// Chooses an index with probability ∝ weights[i] from their prefix sums.
std::size_t choose(const std::vector<double>& prefix, Random& random) {
  const double x = random.uniform01() * prefix.back();
  const auto it = std::upper_bound(prefix.begin(), prefix.end(), x);
  const auto i = static_cast<std::size_t>(it - prefix.begin());
  return std::min(i, prefix.size() - 1);
}

/// Uniform point in triangle abc (square-root parametrization of the barycentrics).
Point3 point_in_triangle(const Point3& a, const Point3& b, const Point3& c, Random& random) {
  const double s = std::sqrt(random.uniform01());
  const double t = random.uniform01();
  return a * (1.0 - s) + b * (s * (1.0 - t)) + c * (s * t);
}

std::vector<Point3> sample_parametrized(const Surface& surface, std::size_t count, Random& random) {
  std::vector<double> prefix;
  double total = 0.0;
  for (int chart = 0; chart < surface.chart_count(); ++chart) {
    const ParamCell d = surface.chart_domain(chart);
    total += (d.u1 - d.u0) * (d.v1 - d.v0) * surface.max_area_element(chart);
    prefix.push_back(total);
  }
  if (!(total > 0.0) || !std::isfinite(total)) {
    throw InvalidInput("uniform sampling of " + surface.name() +
                       ": the area bound is not a positive finite number");
  }
  std::vector<Point3> points;
  points.reserve(count);
  while (points.size() < count) {
    const int chart = static_cast<int>(choose(prefix, random));
    const ParamCell d = surface.chart_domain(chart);
    const double u = random.uniform(d.u0, d.u1);
    const double v = random.uniform(d.v0, d.v1);
    if (random.uniform01() * surface.max_area_element(chart) < surface.area_element(chart, u, v)) {
      points.push_back(surface.point(chart, u, v));
    }
  }
  return points;
}

}  // namespace

std::vector<Point3> sample_uniform(const Surface& surface, std::size_t count, std::uint64_t seed,
                                   double mesh_step) {
  check_count(count);
  Random random(seed);
  if (surface.has_parametrization()) return sample_parametrized(surface, count, random);
  if (mesh_step == 0.0) mesh_step = surface.meshing_step();
  const TriangleMesh mesh = mesh_implicit_surface(surface, mesh_step, true);
  std::vector<Point3> points = sample_mesh_uniform(mesh, count, derive_seed(seed, 1));
  for (Point3& p : points) p = project_along_gradient(surface, p);
  return points;
}

namespace {

/// Checks the mesh's vertices and faces; returns the area of every face.
std::vector<double> checked_face_areas(const TriangleMesh& mesh) {
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    if (!is_finite(mesh.vertices[i])) {
      std::ostringstream msg;
      msg << "mesh sampling: vertex " << i << " is not finite";
      throw InvalidInput(msg.str());
    }
  }
  std::vector<double> areas;
  areas.reserve(mesh.faces.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const auto& tri = mesh.faces[f];
    for (std::uint32_t v : tri) {
      if (v >= mesh.vertices.size()) {
        std::ostringstream msg;
        msg << "mesh sampling: face " << f << " refers to vertex " << v << " but the mesh has "
            << mesh.vertices.size() << " vertices";
        throw InvalidInput(msg.str());
      }
    }
    const Point3& a = mesh.vertices[tri[0]];
    areas.push_back(0.5 * norm(cross(mesh.vertices[tri[1]] - a, mesh.vertices[tri[2]] - a)));
  }
  return areas;
}

std::vector<Point3> sample_faces(const TriangleMesh& mesh, const std::vector<double>& weights,
                                 std::size_t count, std::uint64_t seed) {
  std::vector<double> prefix;
  prefix.reserve(weights.size());
  double total = 0.0;
  for (double w : weights) {
    total += w;
    prefix.push_back(total);
  }
  if (!(total > 0.0) || !std::isfinite(total)) {
    throw InvalidInput("mesh sampling: the mesh has no triangle of positive finite area");
  }
  Random random(seed);
  std::vector<Point3> points;
  points.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    // upper_bound skips zero-weight triangles: their prefix equals the previous one.
    const auto& tri = mesh.faces[choose(prefix, random)];
    points.push_back(point_in_triangle(mesh.vertices[tri[0]], mesh.vertices[tri[1]],
                                       mesh.vertices[tri[2]], random));
  }
  return points;
}

}  // namespace

std::vector<Point3> sample_mesh_uniform(const TriangleMesh& mesh, std::size_t count,
                                        std::uint64_t seed) {
  check_count(count);
  return sample_faces(mesh, checked_face_areas(mesh), count, seed);
}

std::vector<Point3> sample_mesh_weighted(const TriangleMesh& mesh,
                                         std::span<const double> density, std::size_t count,
                                         std::uint64_t seed) {
  check_count(count);
  std::vector<double> weights = checked_face_areas(mesh);
  if (density.size() != weights.size()) {
    std::ostringstream msg;
    msg << "mesh sampling: " << density.size() << " face densities for " << weights.size()
        << " faces";
    throw InvalidInput(msg.str());
  }
  for (std::size_t f = 0; f < weights.size(); ++f) {
    if (!(density[f] >= 0.0) || !std::isfinite(density[f])) {
      std::ostringstream msg;
      msg << "mesh sampling: the density of face " << f << " is not a finite number >= 0";
      throw InvalidInput(msg.str());
    }
    weights[f] *= density[f];
  }
  return sample_faces(mesh, weights, count, seed);
}

}  // namespace rstruct::sampling
