// Poles and labels of certified r-samples (sampling module), decided against the analytic
// implicit functions: every inner pole inside the solid, every outer pole outside, none
// unlabelled (issue 5). Also the pole distance bound of Lemma 5.1 and Theorem 4.1 on the
// sphere.

#include "rstruct/poles/pole_labeling.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <memory>

#include "rstruct/poles/pole_analysis.hpp"
#include "rstruct/sampling/ellipsoid.hpp"
#include "rstruct/sampling/r_sample.hpp"
#include "rstruct/sampling/random.hpp"
#include "rstruct/sampling/rigid_transform.hpp"
#include "rstruct/sampling/sphere.hpp"
#include "rstruct/sampling/torus.hpp"

using rstruct::Point3;
using rstruct::poles::PoleAnalysis;
using rstruct::poles::PoleLabel;
namespace sampling = rstruct::sampling;

namespace {

constexpr double kR = 0.08;  // the paper's sampling constant

struct Case {
  std::shared_ptr<const sampling::Surface> surface;
  std::vector<Point3> samples;
};

Case certified_case(std::shared_ptr<const sampling::Surface> base, std::uint64_t seed,
                    const rstruct::Vec3& translation) {
  sampling::Random random(seed);
  sampling::RigidTransform motion = sampling::RigidTransform::random_rotation(random);
  motion.t = translation;
  auto surface = std::make_shared<sampling::TransformedSurface>(std::move(base), motion);
  sampling::RSampleOptions options;
  options.seed = seed;
  options.tighten = false;
  auto sample = sampling::generate_r_sample(*surface, kR, options);
  REQUIRE(sample.certificate.certified);
  REQUIRE(sample.certificate.upper_bound <= kR);
  return {surface, std::move(sample.points)};
}

/// The labels agree with the analytic implicit function, nothing is unlabelled, and every
/// sample has one inner and one outer pole.
void check_labels(const Case& c, const PoleAnalysis& a) {
  const auto& poles = a.poles;
  INFO(c.surface->name() << ", " << c.samples.size() << " samples, " << poles.size()
                         << " poles");
  CHECK(poles.is_valid());
  CHECK(a.labeling.unlabelled == 0);
  CHECK(a.labeling.contradictory == 0);
  CHECK(a.labeling.inconsistent_samples == 0);
  CHECK(a.labeling.samples_without_inner == 0);
  CHECK(a.labeling.is_clean());
  std::size_t wrong_inner = 0, wrong_outer = 0;
  for (std::uint32_t p = 0; p < poles.size(); ++p) {
    const double f = c.surface->value(poles.centre[p]);
    if (poles.label[p] == PoleLabel::inner && !(f < 0)) ++wrong_inner;
    if (poles.label[p] == PoleLabel::outer && !(f > 0)) ++wrong_outer;
  }
  CHECK(wrong_inner == 0);
  CHECK(wrong_outer == 0);
  // Lemma 5.1: lfs(s) ≤ 1.2802·D̂(s) for r ≤ 0.08.
  std::size_t lemma_5_1 = 0;
  for (std::size_t s = 0; s < c.samples.size(); ++s) {
    if (!(c.surface->lfs(c.samples[s]) <= 1.2802 * a.dhat.distance[s])) ++lemma_5_1;
  }
  CHECK(lemma_5_1 == 0);
}

}  // namespace

TEST_CASE("sphere: inner poles near the centre, outer poles far outside") {
  for (const rstruct::Vec3 t : {rstruct::Vec3{0, 0, 0}, rstruct::Vec3{1e6, -1e6, 3e5}}) {
    const Case c = certified_case(std::make_shared<sampling::Sphere>(1.0), 11, t);
    const PoleAnalysis a = rstruct::poles::analyse_poles(c.samples);
    check_labels(c, a);
    // Theorem 4.1 with the constants of Lemma 5.1 (r ≤ 0.08): an inner pole lies within
    // 0.2802·R_p of the medial axis, here the centre t.
    std::size_t far = 0, near_outer = 0;
    for (std::uint32_t p = 0; p < a.poles.size(); ++p) {
      const double d = rstruct::distance(a.poles.centre[p], t);
      if (a.poles.label[p] == PoleLabel::inner && !(d <= 0.2802 * a.poles.radius[p])) ++far;
      // The sphere has no outer medial axis: its outer poles are the box poles, far away.
      if (a.poles.label[p] == PoleLabel::outer && !(d > 2.0)) ++near_outer;
    }
    CHECK(far == 0);
    CHECK(near_outer == 0);
  }
}

TEST_CASE("ellipsoids: random axes, rotations and translations") {
  sampling::Random random(2024);
  const rstruct::Vec3 translations[] = {{0, 0, 0}, {1e6, 2e6, -1e6}, {-3.5, 0.25, 1e3}};
  for (int k = 0; k < 3; ++k) {
    const double a = random.uniform(1.0, 1.6), b = random.uniform(0.8, 1.2),
                 cc = random.uniform(0.7, 1.0);
    const Case c = certified_case(std::make_shared<sampling::Ellipsoid>(a, b, cc),
                                  100 + static_cast<std::uint64_t>(k), translations[k]);
    check_labels(c, rstruct::poles::analyse_poles(c.samples));
  }
}

TEST_CASE("tori: random radii, rotations and translations") {
  sampling::Random random(77);
  const rstruct::Vec3 translations[] = {{0, 0, 0}, {-1e6, 1e6, 1e6}, {12.5, -7.0, 0.5}};
  for (int k = 0; k < 3; ++k) {
    const double minor = random.uniform(0.5, 1.0), major = minor * random.uniform(2.0, 3.5);
    const Case c = certified_case(std::make_shared<sampling::Torus>(major, minor),
                                  200 + static_cast<std::uint64_t>(k), translations[k]);
    check_labels(c, rstruct::poles::analyse_poles(c.samples));
  }
}
