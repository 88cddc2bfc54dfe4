#pragma once
/// \file
/// BoundedInt<N>: an exact signed integer of at most N 64-bit limbs, stored inline
/// (sign and magnitude, no heap). It is the fast exact stage of the predicates: their
/// inputs, scaled to integers (predicates/scaled_integer.hpp), usually need a few hundred
/// bits, where GMP's allocation and call overhead dominate. The caller bounds the bit
/// length of every intermediate result in advance (`bit_capacity()`); exceeding it is a
/// bug and throws rstruct::InternalError rather than wrapping around.

#include <algorithm>
#include <bit>
#include <cstdint>

#include "rstruct/core/error.hpp"

namespace rstruct::numeric {

/// 128-bit unsigned products and sums (a GCC/Clang extension; `__extension__` keeps
/// -Wpedantic quiet).
__extension__ typedef unsigned __int128 UInt128;

template <int N>
class BoundedInt {
  static_assert(N >= 1 && N <= 64);

 public:
  BoundedInt() = default;
  /// From a signed 64-bit integer.
  BoundedInt(std::int64_t v) {  // NOLINT(google-explicit-constructor): integer-like type
    negative_ = v < 0;
    const std::uint64_t m = negative_ ? 0 - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v);
    limb_[0] = m;
    size_ = m != 0 ? 1 : 0;
  }

  /// (−1)^negative · m · 2^shift for a mantissa m ≥ 0 and shift ≥ 0.
  /// \throws InternalError if the result does not fit in N limbs.
  static BoundedInt shifted(std::uint64_t m, int shift, bool negative) {
    BoundedInt r;
    r.assign_shifted(m, shift, negative);
    return r;
  }

  /// *this = (−1)^negative · m · 2^shift, in place. \throws InternalError if too large.
  void assign_shifted(std::uint64_t m, int shift, bool negative) {
    size_ = 0;
    negative_ = negative;
    if (m == 0) return;
    const int word = shift / 64, bit = shift % 64;
    const std::uint64_t high = bit != 0 ? m >> (64 - bit) : 0;
    const int size = word + (high != 0 ? 2 : 1);
    if (size > N) overflow();
    for (int i = 0; i < word; ++i) limb_[i] = 0;
    limb_[word] = m << bit;
    if (high != 0) limb_[word + 1] = high;
    size_ = size;
  }

  /// Copies only the limbs in use.
  BoundedInt(const BoundedInt& o) : size_(o.size_), negative_(o.negative_) {
    for (int i = 0; i < o.size_; ++i) limb_[i] = o.limb_[i];
  }
  BoundedInt& operator=(const BoundedInt& o) {
    size_ = o.size_;
    negative_ = o.negative_;
    for (int i = 0; i < o.size_; ++i) limb_[i] = o.limb_[i];
    return *this;
  }

  static constexpr int bit_capacity() { return 64 * N; }

  /// −1, 0 or +1.
  int sign() const { return size_ == 0 ? 0 : (negative_ ? -1 : 1); }
  int limbs() const { return size_; }
  std::uint64_t limb(int i) const { return limb_[i]; }
  bool is_negative() const { return negative_ && size_ != 0; }

  friend BoundedInt operator-(BoundedInt a) {
    a.negative_ = !a.negative_;
    return a;
  }
  friend BoundedInt operator+(const BoundedInt& a, const BoundedInt& b) {
    return signed_sum(a, b, b.negative_);
  }
  friend BoundedInt operator-(const BoundedInt& a, const BoundedInt& b) {
    return signed_sum(a, b, !b.negative_);
  }
  friend BoundedInt operator*(const BoundedInt& a, const BoundedInt& b) {
    BoundedInt r;
    if (a.size_ == 0 || b.size_ == 0) return r;
    const int n = a.size_ + b.size_;  // the product has n or n − 1 limbs
    if (n > N + 1) overflow();
    std::uint64_t acc[N + 1];
    for (int k = 0; k < n; ++k) acc[k] = 0;
    for (int i = 0; i < a.size_; ++i) {
      std::uint64_t carry = 0;
      for (int j = 0; j < b.size_; ++j) {
        const UInt128 t =
            static_cast<UInt128>(a.limb_[i]) * b.limb_[j] + acc[i + j] + carry;
        acc[i + j] = static_cast<std::uint64_t>(t);
        carry = static_cast<std::uint64_t>(t >> 64);
      }
      acc[i + b.size_] = carry;
    }
    int size = n;
    while (size > 0 && acc[size - 1] == 0) --size;
    if (size > N) overflow();
    for (int k = 0; k < size; ++k) r.limb_[k] = acc[k];
    r.size_ = size;
    r.negative_ = a.negative_ != b.negative_;
    return r;
  }

  friend bool operator==(const BoundedInt& a, const BoundedInt& b) {
    if (a.sign() != b.sign() || a.size_ != b.size_) return false;
    return std::equal(a.limb_, a.limb_ + a.size_, b.limb_);
  }

 private:
  [[noreturn]] static void overflow() {
    throw InternalError("BoundedInt: result exceeds the declared capacity");
  }

  /// |a| vs |b|: −1, 0, +1.
  static int compare_magnitude(const BoundedInt& a, const BoundedInt& b) {
    if (a.size_ != b.size_) return a.size_ < b.size_ ? -1 : 1;
    for (int i = a.size_ - 1; i >= 0; --i) {
      if (a.limb_[i] != b.limb_[i]) return a.limb_[i] < b.limb_[i] ? -1 : 1;
    }
    return 0;
  }

  /// a + (−1)^b_negative |b|.
  static BoundedInt signed_sum(const BoundedInt& a, const BoundedInt& b, bool b_negative) {
    if (b.size_ == 0) return a;
    if (a.size_ == 0) {
      BoundedInt r = b;
      r.negative_ = b_negative;
      return r;
    }
    if (a.negative_ == b_negative) {
      BoundedInt r = add_magnitudes(a, b);
      r.negative_ = b_negative;
      return r;
    }
    const int c = compare_magnitude(a, b);
    if (c == 0) return BoundedInt();
    BoundedInt r = c > 0 ? subtract_magnitudes(a, b) : subtract_magnitudes(b, a);
    r.negative_ = c > 0 ? a.negative_ : b_negative;
    return r;
  }

  static BoundedInt add_magnitudes(const BoundedInt& a, const BoundedInt& b) {
    const BoundedInt& big = a.size_ >= b.size_ ? a : b;
    const BoundedInt& small = a.size_ >= b.size_ ? b : a;
    BoundedInt r;
    std::uint64_t carry = 0;
    for (int i = 0; i < big.size_; ++i) {
      const UInt128 t = static_cast<UInt128>(big.limb_[i]) +
                                  (i < small.size_ ? small.limb_[i] : 0) + carry;
      r.limb_[i] = static_cast<std::uint64_t>(t);
      carry = static_cast<std::uint64_t>(t >> 64);
    }
    r.size_ = big.size_;
    if (carry != 0) {
      if (r.size_ == N) overflow();
      r.limb_[r.size_++] = carry;
    }
    return r;
  }

  /// |a| − |b| for |a| > |b|.
  static BoundedInt subtract_magnitudes(const BoundedInt& a, const BoundedInt& b) {
    BoundedInt r;
    std::uint64_t borrow = 0;
    for (int i = 0; i < a.size_; ++i) {
      const std::uint64_t bi = i < b.size_ ? b.limb_[i] : 0;
      const std::uint64_t d = a.limb_[i] - bi - borrow;
      borrow = (a.limb_[i] < bi) || (a.limb_[i] - bi < borrow) ? 1 : 0;
      r.limb_[i] = d;
    }
    int size = a.size_;
    while (size > 0 && r.limb_[size - 1] == 0) --size;
    r.size_ = size;
    return r;
  }

  std::uint64_t limb_[N];  // limbs at and above size_ are never read
  int size_ = 0;
  bool negative_ = false;
};

}  // namespace rstruct::numeric
