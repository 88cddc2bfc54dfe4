#pragma once
/// \file
/// Everything `rstruct sample` needs, as one library call: a shape by name and parameters
/// (or a triangle mesh), an r-sample (`r`) or N points uniform by area (`n`), optional
/// random rotation, translation and Gaussian noise, all deterministic for a seed.
///
/// Shapes and parameters (defaults in brackets), see each class for the geometry:
///   sphere        radius [1]
///   ellipsoid     a [3], b [2], c [1]            (any order; equal axes allowed)
///   torus         R [3], a [1]                   (R > a; lfs = a on the torus when R ≥ 2a)
///   double-torus  R1 [1], a1 [0.35], R2 [0.45], a2 [0.18], c2 [1.7], k [0.04]
///                 (genus 2; lfs unknown, so only n; n = 85237 is the paper's Figure 11 size)
///
/// Order of operations: the surface is placed (rotation Q uniform on SO(3) from the seed
/// if `rotate`, then translation t: x ↦ Qx + t); points are generated on the placed surface
/// (an r-sample is certified there, cell reaches including the transform's rounding);
/// then noise is added. Seeds of the three random streams are derived from `seed`.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "rstruct/geometry/triangle_mesh.hpp"
#include "rstruct/sampling/noise.hpp"
#include "rstruct/sampling/r_sample.hpp"
#include "rstruct/sampling/rigid_transform.hpp"
#include "rstruct/sampling/surface.hpp"

namespace rstruct::sampling {

/// The shape names make_surface accepts ("double_torus" is accepted too).
std::vector<std::string> surface_names();

/// Builds a shape. \throws InvalidInput for an unknown name, an unknown parameter name
/// (the message lists the valid ones) or invalid values.
std::shared_ptr<const Surface> make_surface(const std::string& name,
                                            const std::map<std::string, double>& parameters = {});

/// Parses "key=value,key=value" (empty text: no parameters).
/// \throws InvalidInput naming the malformed item.
std::map<std::string, double> parse_shape_parameters(const std::string& text);

struct SampleRequest {
  std::string shape = "double-torus";
  std::map<std::string, double> parameters;
  /// Sample a triangle mesh's surface instead of a named shape (then only n applies).
  std::optional<TriangleMesh> mesh;
  /// Loop subdivision levels applied to `mesh` before sampling (loop_subdivision.hpp says
  /// why a polyhedral model needs it), at most 8.
  unsigned subdivide = 0;
  /// Replaces uniform-by-area sampling of the (subdivided) mesh: called with the mesh, n
  /// and a derived seed. The CLI passes pipeline::sample_mesh_feature_adaptive here (the
  /// sampling module cannot call it: it needs the pole stage).
  std::function<std::vector<Point3>(const TriangleMesh&, std::size_t, std::uint64_t)>
      mesh_sampler;
  std::optional<double> r;       ///< certified lfs-adaptive r-sample (exclusive with n)
  std::optional<std::size_t> n;  ///< n points uniform by area
  std::uint64_t seed = 1;
  double noise = 0.0;  ///< σ of the Gaussian noise (see noise_scale)
  NoiseScale noise_scale = NoiseScale::kAbsolute;
  bool rotate = false;
  Vec3 translate{};
  RSampleOptions r_options;  ///< its seed is replaced by one derived from `seed`
};

struct SampleOutput {
  std::shared_ptr<const Surface> surface;  ///< the placed surface (null for a mesh)
  RigidTransform transform;
  std::vector<Point3> points;       ///< final points (with noise, if any)
  std::vector<double> lfs;          ///< lfs at the noiseless points; empty if unknown
  std::optional<RSample> r_sample;  ///< generation details and certificate (r only)
  double seconds = 0;
};

/// Runs a request. \throws InvalidInput for inconsistent requests (both or neither of r
/// and n, r with a mesh or a shape of unknown lfs, lfs-relative noise without lfs, …) and
/// everything the called functions throw.
SampleOutput generate_sample(const SampleRequest& request);

/// The certificate as JSON (for --report).
nlohmann::json certificate_json(const Certificate& certificate);

/// A summary of a run for --report: surface name and medial axis, point count, lfs range,
/// transform, and for r-samples the generation counts, seconds and certificate.
nlohmann::json sample_output_json(const SampleOutput& output);

}  // namespace rstruct::sampling
