#include "lemma_instance.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>

#include "rstruct/core/error.hpp"
#include "rstruct/sampling/ellipsoid.hpp"
#include "rstruct/sampling/r_sample.hpp"
#include "rstruct/sampling/random.hpp"
#include "rstruct/sampling/rigid_transform.hpp"
#include "rstruct/sampling/sphere.hpp"
#include "rstruct/sampling/torus.hpp"

namespace rstruct::lemmas {

namespace {

double env_number(const char* name, double fallback) {
  const char* text = std::getenv(name);
  if (text == nullptr || *text == '\0') return fallback;
  char* end = nullptr;
  const double value = std::strtod(text, &end);
  if (end == text || *end != '\0' || !std::isfinite(value)) {
    throw InvalidInput(std::string(name) + ": not a number: '" + text + "'");
  }
  return value;
}

}  // namespace

LemmaSettings settings_from_environment() {
  LemmaSettings s;
  if (const char* text = std::getenv("RSTRUCT_LEMMAS_SEED"); text != nullptr && *text != '\0') {
    char* end = nullptr;
    s.seed = std::strtoull(text, &end, 10);
    if (end == text || *end != '\0') {
      throw InvalidInput(std::string("RSTRUCT_LEMMAS_SEED: not an integer: '") + text + "'");
    }
  }
  s.instances = static_cast<int>(env_number("RSTRUCT_LEMMAS_INSTANCES", s.instances));
  s.r_min = env_number("RSTRUCT_LEMMAS_RMIN", s.r_min);
  s.max_points = static_cast<std::size_t>(
      env_number("RSTRUCT_LEMMAS_MAX_POINTS", static_cast<double>(s.max_points)));
  if (s.instances < 1 || !(s.r_min > 0 && s.r_min <= kPaperR) || s.max_points < 100) {
    throw InvalidInput("RSTRUCT_LEMMAS_*: need INSTANCES ≥ 1, 0 < RMIN ≤ 0.08, MAX_POINTS ≥ 100");
  }
  return s;
}

std::string Instance::describe() const {
  std::ostringstream out;
  out << "instance " << id << ": " << surface->name() << ", r drawn " << r_drawn << ", certified "
      << r_certified << ", " << samples.size() << " samples, " << analysis.poles.size()
      << " poles, rho " << rho;
  return out.str();
}

Instance make_instance(const LemmaSettings& settings, int id) {
  Instance in;
  in.id = id;
  sampling::Random random(sampling::derive_seed(settings.seed, static_cast<std::uint64_t>(id)));
  std::shared_ptr<const sampling::Surface> base;
  switch (id % 3) {
    case 0:
      in.shape = "sphere";
      base = std::make_shared<sampling::Sphere>(random.uniform(0.5, 2.0));
      in.surface_betti.b = {1, 0, 1, 0};
      break;
    case 1: {
      in.shape = "ellipsoid";
      const double scale = random.uniform(0.5, 2.0);
      const double a = scale * random.uniform(1.0, 1.3);
      const double b = scale * random.uniform(0.85, 1.0);
      const double c = scale * random.uniform(0.7, 0.85);
      base = std::make_shared<sampling::Ellipsoid>(a, b, c);
      in.surface_betti.b = {1, 0, 1, 0};
      break;
    }
    default: {
      in.shape = "torus";
      const double minor = random.uniform(0.3, 1.0);
      // R ≥ 2a keeps lfs ≡ a on the torus; the sample size grows with R/a.
      base = std::make_shared<sampling::Torus>(minor * random.uniform(2.0, 2.4), minor);
      in.surface_betti.b = {1, 2, 1, 0};
      break;
    }
  }
  sampling::RigidTransform motion = sampling::RigidTransform::random_rotation(random);
  motion.t = Vec3{random.uniform(-10, 10), random.uniform(-10, 10), random.uniform(-10, 10)};
  in.surface = std::make_shared<sampling::TransformedSurface>(base, motion);

  // r log-uniform in [r_min, 0.08]; the sample cap moves it towards 0.08 when needed.
  in.r_drawn = settings.r_min * std::pow(kPaperR / settings.r_min, random.uniform01());
  in.rho = random.uniform(0.24, 0.56);
  sampling::RSampleOptions options;
  options.seed = random.bits();
  options.tighten = false;
  // Sparser than the generator's defaults (fewer points for the same certified r): the
  // lemmas need an r-sample, not a dense one, and the CI budget is tight.
  options.fill_fraction = 0.95;
  options.spacing = 2.0;
  for (;;) {
    // At r = 0.08 the cap no longer applies: r cannot grow further.
    options.max_points = in.r_drawn < kPaperR ? settings.max_points : 5000000;
    try {
      sampling::RSample sample = sampling::generate_r_sample(*in.surface, in.r_drawn, options);
      if (sample.points.size() > settings.max_points && in.r_drawn < kPaperR) {
        in.r_drawn = std::fmin(kPaperR, in.r_drawn * 1.1);
        continue;
      }
      in.r_certified = sample.certificate.certified ? sample.certificate.upper_bound : NAN;
      in.samples = std::move(sample.points);
      break;
    } catch (const InvalidInput&) {
      // Predicted initial sample above the cap.
      if (in.r_drawn >= kPaperR) throw;
      in.r_drawn = std::fmin(kPaperR, in.r_drawn * 1.1);
    }
  }

  poles::PoleAnalysisOptions pole_options;
  in.analysis = poles::analyse_poles(in.samples, pole_options);
  const poles::PoleSet& p = in.analysis.poles;
  in.pole_inside.resize(p.size());
  for (std::size_t k = 0; k < p.size(); ++k) {
    in.pole_inside[k] = in.surface->value(p.centre[k]) < 0;
  }
  std::vector<Point3> sites = in.samples;
  for (const Point3& b : poles::bounding_box_sites(in.samples, pole_options.box_scale)) {
    sites.push_back(b);
  }
  in.delaunay = std::make_unique<triangulation::RegularTriangulation3>(std::move(sites));
  return in;
}

}  // namespace rstruct::lemmas
