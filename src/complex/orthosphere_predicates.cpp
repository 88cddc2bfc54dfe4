#include "rstruct/complex/orthosphere_predicates.hpp"

#include <gmpxx.h>

#include <array>
#include <atomic>
#include <string>

#include "complex/filtered_number.hpp"
#include "rstruct/core/error.hpp"

namespace rstruct::complex {
namespace {

using detail::FilteredNumber;

std::atomic<std::uint64_t> g_filtered{0};
std::atomic<std::uint64_t> g_exact{0};

/// The quantities of a simplex relative to its first point (see the header), in number
/// type N (FilteredNumber for the filter, mpq_class for the exact stage).
template <class N>
struct OrthoSystem {
  int k = 0;
  std::array<std::array<N, 3>, 3> u;    // u_i = c_i − c₀
  std::array<N, 3> b;                   // b_i = |u_i|² − w_i + w₀
  std::array<std::array<N, 3>, 3> adj;  // adjugate of the Gram matrix
  N det;                                // Gram determinant D
  std::array<N, 3> origin;              // c₀
  N w0;

  explicit OrthoSystem(std::span<const WeightedPoint> sigma)
      : k(static_cast<int>(sigma.size()) - 1) {
    for (int j = 0; j < 3; ++j) origin[j] = N(sigma[0].c[j]);
    w0 = N(sigma[0].w);
    for (int i = 0; i < k; ++i) {
      for (int j = 0; j < 3; ++j) u[i][j] = N(sigma[i + 1].c[j]) - origin[j];
      b[i] = dot(u[i], u[i]) - N(sigma[i + 1].w) + w0;
    }
    std::array<std::array<N, 3>, 3> g;
    for (int i = 0; i < k; ++i) {
      for (int j = i; j < k; ++j) g[i][j] = g[j][i] = dot(u[i], u[j]);
    }
    compute_adjugate(g);
  }

  static N dot(const std::array<N, 3>& x, const std::array<N, 3>& y) {
    N s = x[0] * y[0];
    s += x[1] * y[1];
    s += x[2] * y[2];
    return s;
  }

  void compute_adjugate(const std::array<std::array<N, 3>, 3>& g) {
    if (k == 1) {
      adj[0][0] = N(1.0);
      det = g[0][0];
    } else if (k == 2) {
      adj[0][0] = g[1][1];
      adj[1][1] = g[0][0];
      adj[0][1] = adj[1][0] = N(0.0) - g[0][1];
      det = g[0][0] * g[1][1] - g[0][1] * g[0][1];
    } else {
      adj[0][0] = g[1][1] * g[2][2] - g[1][2] * g[1][2];
      adj[1][1] = g[0][0] * g[2][2] - g[0][2] * g[0][2];
      adj[2][2] = g[0][0] * g[1][1] - g[0][1] * g[0][1];
      adj[0][1] = adj[1][0] = g[0][2] * g[1][2] - g[0][1] * g[2][2];
      adj[0][2] = adj[2][0] = g[0][1] * g[1][2] - g[0][2] * g[1][1];
      adj[1][2] = adj[2][1] = g[0][1] * g[0][2] - g[0][0] * g[1][2];
      det = g[0][0] * adj[0][0] + g[0][1] * adj[0][1] + g[0][2] * adj[0][2];
    }
  }

  /// xᵀ adj(G) y.
  N form(const std::array<N, 3>& x, const std::array<N, 3>& y) const {
    N s = x[0] * adj[0][0] * y[0];
    for (int i = 0; i < k; ++i) {
      for (int j = 0; j < k; ++j) {
        if (i != 0 || j != 0) s += x[i] * adj[i][j] * y[j];
      }
    }
    return s;
  }

  /// bᵀ adj(G) b − 4 D w₀, of the sign of π_σ(z_σ).
  N power() const { return form(b, b) - N(4.0) * det * w0; }

  /// D b_p − g_pᵀ adj(G) b, of the sign of π_p(z_σ) − π_σ(z_σ).
  N attachment(const WeightedPoint& p) const {
    std::array<N, 3> up;
    for (int j = 0; j < 3; ++j) up[j] = N(p.c[j]) - origin[j];
    const N bp = dot(up, up) - N(p.w) + w0;
    std::array<N, 3> gp;
    for (int i = 0; i < k; ++i) gp[i] = dot(u[i], up);
    return det * bp - form(gp, b);
  }
};

void check_size(std::span<const WeightedPoint> sigma, std::size_t max) {
  if (sigma.empty() || sigma.size() > max) {
    throw InvalidInput("orthosphere predicate: " + std::to_string(sigma.size()) +
                       " points, expected 1 to " + std::to_string(max));
  }
}

Sign exact_sign(const mpq_class& x) { return static_cast<Sign>(sgn(x)); }

void require_independent(const mpq_class& det) {
  if (sgn(det) == 0) {
    throw InvalidInput("orthosphere predicate: the points of the simplex are affinely dependent");
  }
}

}  // namespace

Sign orthosphere_power_sign_exact(std::span<const WeightedPoint> sigma) {
  check_size(sigma, 4);
  if (sigma.size() == 1) return -sign_of(sigma[0].w);
  const OrthoSystem<mpq_class> s(sigma);
  require_independent(s.det);
  return exact_sign(s.power());
}

Sign orthosphere_attachment_sign_exact(std::span<const WeightedPoint> sigma,
                                       const WeightedPoint& p) {
  check_size(sigma, 3);
  if (sigma.size() == 1) {
    // π_p(c₀) − π₀(c₀) = |c_p − c₀|² − w_p + w₀.
    const OrthoSystem<mpq_class> s(std::array<WeightedPoint, 2>{sigma[0], p});
    return exact_sign(s.b[0]);
  }
  const OrthoSystem<mpq_class> s(sigma);
  require_independent(s.det);
  return exact_sign(s.attachment(p));
}

Sign orthosphere_power_sign(std::span<const WeightedPoint> sigma) {
  check_size(sigma, 4);
  if (sigma.size() == 1) return -sign_of(sigma[0].w);
  const OrthoSystem<FilteredNumber> s(sigma);
  if (s.det.certified_sign() == 1) {
    const int sign = s.power().certified_sign();
    if (sign != 2) {
      g_filtered.fetch_add(1, std::memory_order_relaxed);
      return static_cast<Sign>(sign);
    }
  }
  g_exact.fetch_add(1, std::memory_order_relaxed);
  return orthosphere_power_sign_exact(sigma);
}

Sign orthosphere_attachment_sign(std::span<const WeightedPoint> sigma, const WeightedPoint& p) {
  check_size(sigma, 3);
  if (sigma.size() == 1) {
    const OrthoSystem<FilteredNumber> s(std::array<WeightedPoint, 2>{sigma[0], p});
    const int sign = s.b[0].certified_sign();
    if (sign != 2) {
      g_filtered.fetch_add(1, std::memory_order_relaxed);
      return static_cast<Sign>(sign);
    }
  } else {
    const OrthoSystem<FilteredNumber> s(sigma);
    if (s.det.certified_sign() == 1) {
      const int sign = s.attachment(p).certified_sign();
      if (sign != 2) {
        g_filtered.fetch_add(1, std::memory_order_relaxed);
        return static_cast<Sign>(sign);
      }
    }
  }
  g_exact.fetch_add(1, std::memory_order_relaxed);
  return orthosphere_attachment_sign_exact(sigma, p);
}

OrthospherePredicateCounters orthosphere_predicate_counters() {
  return {g_filtered.load(std::memory_order_relaxed), g_exact.load(std::memory_order_relaxed)};
}

void reset_orthosphere_predicate_counters() {
  g_filtered.store(0, std::memory_order_relaxed);
  g_exact.store(0, std::memory_order_relaxed);
}

}  // namespace rstruct::complex
