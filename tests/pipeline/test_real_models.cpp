// Real models (issue #7): a polyhedral model, Loop-subdivided and sampled with a density
// that follows its feature size, goes through the seed pipeline to a closed 2-manifold with
// the model's genus. bench/bench_models runs every model of ../shared/data/models; this
// test keeps one (eight.off, genus 2, copied to tests/data/models) and checks the
// feature-adaptive sampler on two spheres whose lfs is known.
#include <catch2/catch.hpp>
#include <cmath>
#include <set>

#include "rstruct/core/error.hpp"
#include "rstruct/io/mesh_io.hpp"
#include "rstruct/pipeline/feature_adaptive_sampling.hpp"
#include "rstruct/pipeline/seed_polytope.hpp"
#include "rstruct/sampling/loop_subdivision.hpp"

using namespace rstruct;
using rstruct::pipeline::SeedOptions;

namespace {

const std::string kModels = RSTRUCT_MODEL_DATA;

/// A polyhedral sphere of radius `r` around `c`: a subdivided octahedron pushed out.
void append_sphere(TriangleMesh& mesh, const Point3& c, double r) {
  TriangleMesh octa;
  octa.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  octa.faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  const TriangleMesh fine = sampling::loop_subdivide(octa, 6);
  const auto offset = static_cast<std::uint32_t>(mesh.vertices.size());
  for (const Point3& p : fine.vertices) mesh.vertices.push_back(c + normalized(p) * r);
  for (const auto& f : fine.faces) {
    mesh.faces.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
  }
}

}  // namespace

TEST_CASE("feature-adaptive sampling: equal counts on spheres of radii 1 and 0.1") {
  TriangleMesh mesh;
  append_sphere(mesh, {0, 0, 0}, 1.0);
  const std::size_t big_faces = mesh.faces.size();
  append_sphere(mesh, {3, 0, 0}, 0.1);
  pipeline::FeatureAdaptiveOptions options;
  options.rounds = 1;
  const std::size_t n = 6000;
  const auto result = pipeline::sample_mesh_feature_adaptive(mesh, n, 11, options);
  REQUIRE(result.points.size() == n);
  std::size_t small = 0;
  for (const Point3& p : result.points) small += p.x > 2.0;
  // Density ∝ 1/lfs² and area ∝ lfs²: about half the points on each sphere (uniform by
  // area would put 1/101 of them on the small one).
  INFO("points on the small sphere: " << small);
  CHECK(small > n * 3 / 10);
  CHECK(small < n * 7 / 10);
  // The per-face scale is the distance to the nearest pole, close to the radius.
  for (std::size_t f = 0; f < mesh.faces.size(); f += 37) {
    const double radius = f < big_faces ? 1.0 : 0.1;
    INFO("face " << f << " scale " << result.face_scale[f]);
    CHECK(result.face_scale[f] > 0.5 * radius);
    CHECK(result.face_scale[f] < 1.5 * radius);
  }
  CHECK_THROWS_AS(pipeline::sample_mesh_feature_adaptive(mesh, 10, 1), InvalidInput);
  options.rounds = 0;
  CHECK_THROWS_AS(pipeline::sample_mesh_feature_adaptive(mesh, n, 1, options), InvalidInput);
}

TEST_CASE("eight.off (genus 2): subdivided, adaptive sample, seed polytope of genus 2") {
  const TriangleMesh model = io::read_mesh(kModels + "/eight.off");
  const TriangleMesh smooth = sampling::loop_subdivide(model, 3);
  const auto sample = pipeline::sample_mesh_feature_adaptive(smooth, 30000, 1);
  const std::vector<Point3>& samples = sample.points;
  SeedOptions options;
  options.rho = 0.5;
  options.rho_tilde = 0.03;
  options.require_clean_labels = true;
  const auto seed = pipeline::compute_seed_polytope(samples, options);
  CHECK(seed.betti_k == complex::BettiNumbers{{1, 4, 1, 0}});
  CHECK(seed.betti_output == complex::BettiNumbers{{1, 4, 1, 0}});
  CHECK(seed.manifold.is_closed_2_manifold);
  CHECK(seed.oriented);
  // Vertices are distinct samples, every sample is mapped to an output vertex.
  const std::set<std::uint32_t> vertices(seed.vertex_sample.begin(), seed.vertex_sample.end());
  CHECK(vertices.size() == seed.vertex_sample.size());
  for (std::uint32_t s : seed.vertex_sample) REQUIRE(s < samples.size());
  REQUIRE(seed.sample_vertex.size() == samples.size());
  for (std::uint32_t v : seed.sample_vertex) REQUIRE(v < seed.vertex_sample.size());
  CHECK(seed.vertex_sample.size() < samples.size());
}
