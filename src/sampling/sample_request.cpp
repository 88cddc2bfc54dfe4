#include "rstruct/sampling/sample_request.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "rstruct/core/error.hpp"
#include "rstruct/core/stopwatch.hpp"
#include "rstruct/sampling/double_torus.hpp"
#include "rstruct/sampling/ellipsoid.hpp"
#include "rstruct/sampling/loop_subdivision.hpp"
#include "rstruct/sampling/random.hpp"
#include "rstruct/sampling/sphere.hpp"
#include "rstruct/sampling/torus.hpp"
#include "rstruct/sampling/uniform_sampling.hpp"

namespace rstruct::sampling {

namespace {

/// Reads the parameters a shape accepts, with defaults, rejecting unknown names.
class ParameterReader {
 public:
  ParameterReader(std::string shape, const std::map<std::string, double>& given)
      : shape_(std::move(shape)), given_(given) {}
  double get(const std::string& key, double fallback) {
    known_.push_back(key);
    const auto it = given_.find(key);
    return it == given_.end() ? fallback : it->second;
  }
  void finish() const {
    for (const auto& [key, value] : given_) {
      if (std::find(known_.begin(), known_.end(), key) == known_.end()) {
        std::string list;
        for (const auto& k : known_) list += (list.empty() ? "" : ", ") + k;
        throw InvalidInput(shape_ + ": unknown parameter '" + key + "' (valid: " + list + ")");
      }
    }
  }

 private:
  std::string shape_;
  const std::map<std::string, double>& given_;
  std::vector<std::string> known_;
};

std::shared_ptr<const Surface> place(std::shared_ptr<const Surface> base,
                                     const SampleRequest& request, RigidTransform& transform) {
  transform = RigidTransform::identity();
  if (request.rotate) {
    Random random(derive_seed(request.seed, 1));
    transform = RigidTransform::random_rotation(random);
  }
  if (!is_finite(request.translate)) throw InvalidInput("translation must be finite");
  transform.t = request.translate;
  if (!request.rotate && request.translate == Vec3{}) return base;
  return std::make_shared<TransformedSurface>(std::move(base), transform);
}

void check_request(const SampleRequest& request) {
  if (request.r.has_value() == request.n.has_value()) {
    throw InvalidInput("sample: give exactly one of r (certified r-sample) and n (point count)");
  }
  if (request.mesh && request.r) {
    throw InvalidInput("sample: a mesh can only be sampled with n points (its lfs is unknown)");
  }
  if (!request.mesh && (request.subdivide > 0 || request.mesh_sampler)) {
    throw InvalidInput("sample: subdivision and mesh samplers apply to a mesh only");
  }
  if (request.subdivide > 8) {
    throw InvalidInput("sample: at most 8 Loop subdivision levels (each multiplies the faces by 4)");
  }
  if (request.mesh && request.noise_scale == NoiseScale::kLfs && request.noise > 0.0) {
    throw InvalidInput("sample: noise relative to lfs is not available for a mesh");
  }
}

SampleOutput sample_mesh(const SampleRequest& request) {
  SampleOutput out;
  RigidTransform transform;
  if (request.rotate) {
    Random random(derive_seed(request.seed, 1));
    transform = RigidTransform::random_rotation(random);
  }
  if (!is_finite(request.translate)) throw InvalidInput("translation must be finite");
  transform.t = request.translate;
  out.transform = transform;
  TriangleMesh subdivided;
  if (request.subdivide > 0) subdivided = loop_subdivide(*request.mesh, request.subdivide);
  const TriangleMesh& mesh = request.subdivide > 0 ? subdivided : *request.mesh;
  out.points = request.mesh_sampler
                   ? request.mesh_sampler(mesh, *request.n, derive_seed(request.seed, 2))
                   : sample_mesh_uniform(mesh, *request.n, derive_seed(request.seed, 2));
  for (Point3& p : out.points) p = transform.apply(p);
  add_gaussian_noise(out.points, request.noise, NoiseScale::kAbsolute, nullptr,
                     derive_seed(request.seed, 3));
  return out;
}

}  // namespace

std::vector<std::string> surface_names() {
  return {"sphere", "ellipsoid", "torus", "double-torus"};
}

std::shared_ptr<const Surface> make_surface(const std::string& name,
                                            const std::map<std::string, double>& parameters) {
  ParameterReader p(name, parameters);
  std::shared_ptr<const Surface> surface;
  if (name == "sphere") {
    const double radius = p.get("radius", 1.0);
    p.finish();
    surface = std::make_shared<Sphere>(radius);
  } else if (name == "ellipsoid") {
    const double a = p.get("a", 3.0), b = p.get("b", 2.0), c = p.get("c", 1.0);
    p.finish();
    surface = std::make_shared<Ellipsoid>(a, b, c);
  } else if (name == "torus") {
    const double major = p.get("R", 3.0), minor = p.get("a", 1.0);
    p.finish();
    surface = std::make_shared<Torus>(major, minor);
  } else if (name == "double-torus" || name == "double_torus") {
    DoubleTorusParameters d;
    d.big_major = p.get("R1", d.big_major);
    d.big_minor = p.get("a1", d.big_minor);
    d.small_major = p.get("R2", d.small_major);
    d.small_minor = p.get("a2", d.small_minor);
    d.small_centre_x = p.get("c2", d.small_centre_x);
    d.blend = p.get("k", d.blend);
    p.finish();
    surface = std::make_shared<DoubleTorus>(d);
  } else {
    throw InvalidInput("unknown shape '" + name +
                       "' (valid: sphere, ellipsoid, torus, double-torus)");
  }
  return surface;
}

std::map<std::string, double> parse_shape_parameters(const std::string& text) {
  std::map<std::string, double> out;
  std::istringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0) {
      throw InvalidInput("shape parameter '" + item + "': expected key=value");
    }
    const std::string key = item.substr(0, eq);
    const std::string value = item.substr(eq + 1);
    std::size_t used = 0;
    double v = 0;
    try {
      v = std::stod(value, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != value.size() || !std::isfinite(v)) {
      throw InvalidInput("shape parameter '" + key + "': '" + value + "' is not a finite number");
    }
    if (!out.emplace(key, v).second) {
      throw InvalidInput("shape parameter '" + key + "' given twice");
    }
  }
  return out;
}

SampleOutput generate_sample(const SampleRequest& request) {
  check_request(request);
  Stopwatch clock;
  if (request.mesh) {
    SampleOutput out = sample_mesh(request);
    out.seconds = clock.seconds();
    return out;
  }
  SampleOutput out;
  out.surface = place(make_surface(request.shape, request.parameters), request, out.transform);
  if (request.r) {
    RSampleOptions options = request.r_options;
    options.seed = derive_seed(request.seed, 2);
    RSample sample = generate_r_sample(*out.surface, *request.r, options);
    out.points = std::move(sample.points);
    sample.points.clear();
    out.r_sample = std::move(sample);
  } else {
    out.points = sample_uniform(*out.surface, *request.n, derive_seed(request.seed, 2));
  }
  if (out.surface->has_known_lfs()) {
    out.lfs.reserve(out.points.size());
    for (const Point3& p : out.points) out.lfs.push_back(out.surface->lfs(p));
  }
  add_gaussian_noise(out.points, request.noise, request.noise_scale, out.surface.get(),
                     derive_seed(request.seed, 3));
  out.seconds = clock.seconds();
  return out;
}

nlohmann::json certificate_json(const Certificate& c) {
  nlohmann::json j;
  j["threshold"] = c.threshold;
  j["certified"] = c.certified;
  if (c.certified) j["upper_bound"] = c.upper_bound;
  j["grid_max"] = c.grid_max;
  j["grid_points"] = c.grid_points;
  j["leaf_cells"] = c.leaf_cells;
  j["max_leaf_reach_over_lfs"] = c.max_leaf_reach_over_lfs;
  j["min_leaf_reach_over_lfs"] = c.min_leaf_reach_over_lfs;
  if (c.violation) {
    j["violation"] = {c.violation->x, c.violation->y, c.violation->z};
    j["violation_ratio"] = c.violation_ratio;
  }
  j["undecided"] = c.undecided;
  j["seconds"] = c.seconds;
  return j;
}

nlohmann::json sample_output_json(const SampleOutput& out) {
  nlohmann::json j;
  if (out.surface) {
    j["surface"] = out.surface->name();
    j["medial_axis"] = out.surface->medial_axis_description();
  } else {
    j["surface"] = "triangle mesh";
  }
  j["points"] = out.points.size();
  if (!out.lfs.empty()) {
    const auto [lo, hi] = std::minmax_element(out.lfs.begin(), out.lfs.end());
    j["lfs_min"] = *lo;
    j["lfs_max"] = *hi;
  }
  j["rotation"] = out.transform.q;
  j["translation"] = {out.transform.t.x, out.transform.t.y, out.transform.t.z};
  if (out.r_sample) {
    const RSample& r = *out.r_sample;
    j["requested_r"] = r.requested_r;
    j["initial_points"] = r.initial_points;
    j["added_points"] = r.added_points;
    j["rounds"] = r.rounds;
    j["generation_seconds"] = r.generation_seconds;
    j["certification_seconds"] = r.certification_seconds;
    j["certificate"] = certificate_json(r.certificate);
  }
  j["seconds"] = out.seconds;
  return j;
}

}  // namespace rstruct::sampling
