#pragma once
/// \file
/// The result type of every predicate.

namespace rstruct {

enum class Sign : signed char { negative = -1, zero = 0, positive = 1 };

constexpr Sign operator-(Sign s) { return static_cast<Sign>(-static_cast<int>(s)); }
constexpr Sign operator*(Sign a, Sign b) {
  return static_cast<Sign>(static_cast<int>(a) * static_cast<int>(b));
}
constexpr int to_int(Sign s) { return static_cast<int>(s); }
template <class T>
constexpr Sign sign_of(const T& v) {
  return v > 0 ? Sign::positive : (v < 0 ? Sign::negative : Sign::zero);
}

}  // namespace rstruct
