#pragma once
/// \file
/// The sampling module in one include: surfaces with known local feature size (sphere,
/// ellipsoid, torus), the genus-2 double torus, rigid transforms, uniform and certified
/// r-sample generation (paper, Definition 1; DESIGN.md §8), noise, marching-tetrahedra
/// meshes with topology checks, and the one-call request API behind `rstruct sample`.

#include "rstruct/sampling/double_torus.hpp"
#include "rstruct/sampling/ellipse_projection.hpp"
#include "rstruct/sampling/ellipsoid.hpp"
#include "rstruct/sampling/implicit_mesher.hpp"
#include "rstruct/sampling/mesh_topology.hpp"
#include "rstruct/sampling/noise.hpp"
#include "rstruct/sampling/r_sample.hpp"
#include "rstruct/sampling/random.hpp"
#include "rstruct/sampling/rigid_transform.hpp"
#include "rstruct/sampling/sample_request.hpp"
#include "rstruct/sampling/sphere.hpp"
#include "rstruct/sampling/surface.hpp"
#include "rstruct/sampling/torus.hpp"
#include "rstruct/sampling/uniform_sampling.hpp"
