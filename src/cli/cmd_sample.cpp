// `rstruct sample SHAPE [--r R | --n N] ... -o OUT`: point samples of surfaces with known
// local feature size (certified r-samples) or of a triangle mesh (--mesh), the fixtures of
// every later stage and test. The sampling itself is the library's
// (rstruct/sampling/sample_request.hpp); this file maps options to a SampleRequest and
// writes the points (with their lfs when known) atomically.

#include <optional>
#include <sstream>
#include <string>

#include "cli/command.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/io/mesh_io.hpp"
#include "rstruct/pipeline/feature_adaptive_sampling.hpp"
#include "rstruct/sampling/sample_request.hpp"

namespace rstruct::cli {

namespace {

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

class SampleCommand : public Command {
 public:
  void configure(CLI::App& app) override {
    app.add_option("shape", shape_,
                   "Shape: " + join(sampling::surface_names()) + " (ignored with --mesh)");
    app.add_option("-p,--params", params_,
                   "Shape parameters as key=value,... (e.g. R=3,a=1 for the torus)");
    app.add_option("--mesh", mesh_path_, "Sample the surface of this triangle mesh (needs --n)");
    app.add_option("--subdivide", subdivide_,
                   "With --mesh: Loop-subdivide the mesh this many times first (a smooth "
                   "surface near the model; a polyhedron has lfs 0 on its edges)")
        ->check(CLI::Range(0, 8));
    app.add_flag("--adaptive", adaptive_,
                 "With --mesh: density proportional to 1/lfs^2, lfs estimated by the distance "
                 "to the nearest pole of the previous round's sample (see --rounds)");
    app.add_option("--rounds", rounds_, "With --adaptive: resampling rounds")
        ->check(CLI::Range(1, 10))
        ->capture_default_str();
    auto* r = app.add_option("--r", r_, "Certified r-sample: max dist(x,S)/lfs(x) <= R");
    auto* n = app.add_option("--n", n_, "N points uniform by area");
    r->excludes(n);
    app.add_option("--seed", seed_, "Random seed")->capture_default_str();
    app.add_option("--noise", noise_, "Gaussian noise sigma (absolute; see --noise-lfs)");
    app.add_flag("--noise-lfs", noise_lfs_, "Noise sigma is relative to lfs at each point");
    app.add_flag("--rotate", rotate_, "Apply a random rotation (from the seed)");
    app.add_option("--translate", translate_, "Translate by X,Y,Z");
    app.add_option("-o,--output", output_, "Output file (.ply, .xyz, .off, .obj)")->required();
    app.add_flag("--ascii", ascii_, "ASCII PLY");
    app.footer(
        "Examples:\n"
        "  rstruct sample torus --r 0.04 -o torus.ply\n"
        "  rstruct sample double-torus --n 85237 -o dt.ply\n"
        "  rstruct sample --mesh bunny.off --n 100000 -o bunny.ply\n"
        "  rstruct sample --mesh bunny.off --subdivide 3 --adaptive --n 150000 -o bunny.ply");
  }

  int run(Context& context) override {
    sampling::SampleRequest request;
    if (!mesh_path_.empty()) {
      request.mesh = io::read_mesh(mesh_path_);
    } else if (shape_.empty()) {
      throw InvalidInput("give a shape (" + join(sampling::surface_names()) + ") or --mesh FILE");
    }
    if ((subdivide_ > 0 || adaptive_) && mesh_path_.empty()) {
      throw InvalidInput("--subdivide and --adaptive need --mesh");
    }
    request.subdivide = subdivide_;
    if (adaptive_) {
      pipeline::FeatureAdaptiveOptions options;
      options.rounds = rounds_;
      request.mesh_sampler = [options](const TriangleMesh& mesh, std::size_t n,
                                       std::uint64_t seed) {
        return pipeline::sample_mesh_feature_adaptive(mesh, n, seed, options).points;
      };
    }
    request.shape = shape_;
    request.parameters = sampling::parse_shape_parameters(params_);
    if (r_) request.r = require_range(*r_, 1e-4, 1.0, "--r");
    if (n_) {
      if (*n_ < 1 || *n_ > 200000000) throw InvalidInput("--n must be in [1, 2e8]");
      request.n = static_cast<std::size_t>(*n_);
    }
    request.seed = seed_;
    request.noise = require_range(noise_, 0.0, 1e300, "--noise");
    request.noise_scale =
        noise_lfs_ ? sampling::NoiseScale::kLfs : sampling::NoiseScale::kAbsolute;
    request.rotate = rotate_;
    if (!translate_.empty()) {
      const auto t = parse_triple(translate_, "--translate");
      request.translate = {t[0], t[1], t[2]};
    }
    io::WriteOptions write_options;
    write_options.format = io::format_from_extension(output_);
    write_options.ascii = ascii_;

    Report::Stage stage(context.report, "sample");
    sampling::SampleOutput out = sampling::generate_sample(request);
    stage.finish();

    auto& data = context.report.data();
    data["shape"] = request.mesh ? "mesh:" + mesh_path_ : shape_;
    data["seed"] = seed_;
    if (request.mesh) {
      data["subdivide"] = subdivide_;
      data["adaptive"] = adaptive_;
      if (adaptive_) data["rounds"] = rounds_;
    }
    data["points"] = out.points.size();
    std::ostringstream line;
    line << "sampled " << out.points.size() << " points in " << out.seconds << " s";
    if (out.r_sample) {
      const auto& cert = out.r_sample->certificate;
      data["certificate"] = sampling::certificate_json(cert);
      line << "; certified r-sample: sup dist(x,S)/lfs(x) <= " << cert.upper_bound
           << " (requested " << *r_ << ", grid max " << cert.grid_max << ")";
      if (!cert.certified) throw ComputationFailed("the sample could not be certified");
    }
    context.info(line.str());

    TriangleMesh mesh;
    mesh.vertices = std::move(out.points);
    if (!out.lfs.empty()) mesh.vertex_properties.emplace_back("lfs", std::move(out.lfs));
    Report::Stage write(context.report, "write");
    io::write_mesh(output_, mesh, write_options);
    return 0;
  }

 private:
  std::string shape_;
  std::string params_;
  std::string mesh_path_;
  unsigned subdivide_ = 0;
  bool adaptive_ = false;
  unsigned rounds_ = 2;
  std::optional<double> r_;
  std::optional<long long> n_;
  std::uint64_t seed_ = 1;
  double noise_ = 0;
  bool noise_lfs_ = false;
  bool rotate_ = false;
  std::string translate_;
  std::string output_;
  bool ascii_ = false;
};

}  // namespace

RSTRUCT_REGISTER_COMMAND(SampleCommand, "sample",
                         "Generate point samples: certified r-samples of surfaces with known "
                         "local feature size, or uniform samples of a mesh");

}  // namespace rstruct::cli
