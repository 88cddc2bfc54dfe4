// The one-call API behind `rstruct sample`: shapes by name, parameters, r or n, rotation,
// translation, noise, meshes, and the errors for inconsistent requests.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "rstruct/core/error.hpp"
#include "rstruct/sampling/sample_request.hpp"

using namespace rstruct;
using namespace rstruct::sampling;

TEST_CASE("shapes by name with parameters") {
  CHECK(surface_names().size() == 4);
  CHECK(make_surface("sphere", {{"radius", 2.0}})->lfs({2, 0, 0}) == Approx(2.0));
  CHECK(make_surface("torus")->name() == "torus(R=3, a=1)");
  CHECK(make_surface("ellipsoid", {{"a", 1.0}, {"b", 1.0}, {"c", 1.0}})->area() ==
        Approx(4 * std::numbers::pi));
  CHECK_FALSE(make_surface("double_torus")->has_known_lfs());
  CHECK_THROWS_AS(make_surface("cube"), InvalidInput);
  CHECK_THROWS_WITH(make_surface("torus", {{"r", 1.0}}), Catch::Contains("valid: R, a"));
  CHECK_THROWS_AS(make_surface("torus", {{"R", 1.0}, {"a", 2.0}}), InvalidInput);
}

TEST_CASE("shape parameter parsing") {
  const auto p = parse_shape_parameters("a=3,b=2.5,c=1e-1");
  CHECK(p.at("a") == 3.0);
  CHECK(p.at("b") == 2.5);
  CHECK(p.at("c") == 0.1);
  CHECK(parse_shape_parameters("").empty());
  CHECK_THROWS_AS(parse_shape_parameters("a"), InvalidInput);
  CHECK_THROWS_AS(parse_shape_parameters("=3"), InvalidInput);
  CHECK_THROWS_AS(parse_shape_parameters("a=x"), InvalidInput);
  CHECK_THROWS_AS(parse_shape_parameters("a=3x"), InvalidInput);
  CHECK_THROWS_AS(parse_shape_parameters("a=nan"), InvalidInput);
  CHECK_THROWS_AS(parse_shape_parameters("a=1,a=2"), InvalidInput);
}

TEST_CASE("r request: certified sample with lfs, moved and noisy") {
  SampleRequest request;
  request.shape = "sphere";
  request.r = 0.1;
  request.seed = 5;
  request.rotate = true;
  request.translate = {10, 20, 30};
  const SampleOutput out = generate_sample(request);
  REQUIRE(out.r_sample.has_value());
  CHECK(out.r_sample->certificate.certified);
  CHECK(out.r_sample->certificate.upper_bound <= 0.1);
  REQUIRE(out.lfs.size() == out.points.size());
  for (const Point3& p : out.points) REQUIRE(std::fabs(distance(p, {10, 20, 30}) - 1.0) <= 1e-12);
  // Same request, same output; noise moves points by about sigma·lfs.
  CHECK(generate_sample(request).points == out.points);
  const auto summary = sample_output_json(out);
  CHECK(summary["points"] == out.points.size());
  CHECK(summary["certificate"]["certified"] == true);
  CHECK(summary["requested_r"] == 0.1);
  CHECK(summary["lfs_min"].get<double>() == Approx(1.0));
  CHECK(summary["translation"][2] == 30.0);
  request.noise = 0.01;
  request.noise_scale = NoiseScale::kLfs;
  const SampleOutput noisy = generate_sample(request);
  REQUIRE(noisy.points.size() == out.points.size());
  double mean_sq = 0;
  for (std::size_t i = 0; i < out.points.size(); ++i) {
    mean_sq += squared_distance(noisy.points[i], out.points[i]) / out.points.size();
  }
  CHECK(mean_sq == Approx(3 * 0.01 * 0.01).epsilon(0.1));
}

TEST_CASE("n request: double torus and mesh") {
  SampleRequest request;
  request.n = 1000;
  request.noise = 0.001;
  const SampleOutput out = generate_sample(request);
  CHECK(out.points.size() == 1000);
  CHECK(out.lfs.empty());
  CHECK_FALSE(out.r_sample.has_value());

  SampleRequest mesh_request;
  TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.faces = {{0, 1, 2}};
  mesh_request.mesh = mesh;
  mesh_request.n = 100;
  mesh_request.translate = {0, 0, 5};
  const SampleOutput m = generate_sample(mesh_request);
  REQUIRE(m.points.size() == 100);
  for (const Point3& p : m.points) REQUIRE(p.z == 5.0);
}

TEST_CASE("inconsistent requests are rejected") {
  SampleRequest both;
  both.r = 0.1;
  both.n = 10;
  CHECK_THROWS_AS(generate_sample(both), InvalidInput);
  SampleRequest neither;
  CHECK_THROWS_AS(generate_sample(neither), InvalidInput);
  SampleRequest r_on_double_torus;
  r_on_double_torus.r = 0.1;
  CHECK_THROWS_AS(generate_sample(r_on_double_torus), InvalidInput);
  SampleRequest lfs_noise;
  lfs_noise.n = 10;
  lfs_noise.noise = 0.1;
  lfs_noise.noise_scale = NoiseScale::kLfs;
  CHECK_THROWS_AS(generate_sample(lfs_noise), InvalidInput);
  SampleRequest negative_noise;
  negative_noise.shape = "sphere";
  negative_noise.n = 10;
  negative_noise.noise = -1;
  CHECK_THROWS_AS(generate_sample(negative_noise), InvalidInput);
  SampleRequest bad_translation;
  bad_translation.shape = "sphere";
  bad_translation.n = 10;
  bad_translation.translate = {INFINITY, 0, 0};
  CHECK_THROWS_AS(generate_sample(bad_translation), InvalidInput);
  SampleRequest mesh_r;
  mesh_r.mesh = TriangleMesh{};
  mesh_r.r = 0.1;
  CHECK_THROWS_AS(generate_sample(mesh_r), InvalidInput);
}

TEST_CASE("certificate JSON") {
  Certificate c;
  c.certified = true;
  c.upper_bound = 0.07;
  c.threshold = 0.08;
  const auto j = certificate_json(c);
  CHECK(j["certified"] == true);
  CHECK(j["upper_bound"] == 0.07);
  CHECK(j.contains("grid_max"));
}
