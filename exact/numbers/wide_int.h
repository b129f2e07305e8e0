// [FC-0] Exact signs of 2×2 and 3×3 integer determinants in fixed-width integers, for the exact
// kernel's rows of moderate size (GMP only beyond). Integer arithmetic, exact: no floating point.
//
// Bounds (|x| ≤ 2^62 − 1 = kMax62 for every entry):
//   2×2 minor  b1·c2 − b2·c1:   |·| < 2^125          (fits __int128)
//   3×3 det    Σ ± a_i·minor_i: |·| < 3·2^187 < 2^189 (fits the signed 192-bit Int192)
// Tested against GMP on random and extreme inputs (tests/wide_int_test.cpp).
#pragma once

#include <cstdint>

namespace wrenchkit::wide {

__extension__ typedef __int128 i128;           // GCC and Clang both provide it
__extension__ typedef unsigned __int128 u128;

constexpr std::int64_t kMax62 = (std::int64_t(1) << 62) - 1;

inline bool fits62(i128 v) { return v <= kMax62 && v >= -kMax62; }

inline int sign(i128 v) { return (v > 0) - (v < 0); }

// A signed 192-bit integer, two's complement, limbs least significant first.
struct Int192 {
  std::uint64_t w[3] = {0, 0, 0};
};

// a·b exactly, for |a| ≤ 2^63 − 1 and |b| < 2^127 (|a·b| < 2^190).
inline Int192 mul(std::int64_t a, i128 b) {
  const bool neg = (a < 0) != (b < 0);
  const std::uint64_t ua = a < 0 ? 0 - static_cast<std::uint64_t>(a) : static_cast<std::uint64_t>(a);
  const u128 ub = b < 0 ? 0 - static_cast<u128>(b) : static_cast<u128>(b);
  const u128 p0 = static_cast<u128>(ua) * static_cast<std::uint64_t>(ub);
  const u128 p1 = static_cast<u128>(ua) * static_cast<std::uint64_t>(ub >> 64);
  const u128 mid = (p0 >> 64) + static_cast<std::uint64_t>(p1);  // < 2^65
  Int192 r;
  r.w[0] = static_cast<std::uint64_t>(p0);
  r.w[1] = static_cast<std::uint64_t>(mid);
  r.w[2] = static_cast<std::uint64_t>(p1 >> 64) + static_cast<std::uint64_t>(mid >> 64);
  if (neg) {  // two's complement: invert and add one
    std::uint64_t carry = 1;
    for (std::uint64_t& x : r.w) {
      x = ~x + carry;
      carry = carry && x == 0;
    }
  }
  return r;
}

// x + y modulo 2^192 (exact when the true sum fits in signed 192 bits).
inline Int192 add(const Int192& x, const Int192& y) {
  Int192 r;
  std::uint64_t carry = 0;
  for (int i = 0; i < 3; ++i) {
    const u128 s = static_cast<u128>(x.w[i]) + y.w[i] + carry;
    r.w[i] = static_cast<std::uint64_t>(s);
    carry = static_cast<std::uint64_t>(s >> 64);
  }
  return r;
}

inline int sign(const Int192& x) {
  if (x.w[2] >> 63) return -1;
  return (x.w[0] | x.w[1] | x.w[2]) ? 1 : 0;
}

inline u128 uabs(i128 v) { return v < 0 ? 0 - static_cast<u128>(v) : static_cast<u128>(v); }

// gcd(a, b) (binary, Stein); gcd(0, b) = b.
inline std::uint64_t gcd64(std::uint64_t a, std::uint64_t b) {
  if (a == 0) return b;
  if (b == 0) return a;
  const int shift = __builtin_ctzll(a | b);
  a >>= __builtin_ctzll(a);
  do {
    b >>= __builtin_ctzll(b);
    if (a > b) {
      const std::uint64_t t = a;
      a = b;
      b = t;
    }
    b -= a;
  } while (b != 0);
  return a << shift;
}

// gcd(a, b) in 128 bits: Euclid until both fit 64 bits, then gcd64.
inline u128 gcd128(u128 a, u128 b) {
  while ((a >> 64) != 0 || (b >> 64) != 0) {
    if (b == 0) return a;
    const u128 t = a % b;
    a = b;
    b = t;
  }
  return gcd64(static_cast<std::uint64_t>(a), static_cast<std::uint64_t>(b));
}

// b1·c2 − b2·c1 for |entries| ≤ kMax62.
inline i128 minor2(std::int64_t b1, std::int64_t b2, std::int64_t c1, std::int64_t c2) {
  return static_cast<i128>(b1) * c2 - static_cast<i128>(b2) * c1;
}

// det[a; b; c] for |entries| ≤ kMax62 (|·| < 2^189).
inline Int192 det3(const std::int64_t a[3], const std::int64_t b[3], const std::int64_t c[3]) {
  const Int192 t0 = mul(a[0], minor2(b[1], b[2], c[1], c[2]));
  const Int192 t1 = mul(-a[1], minor2(b[0], b[2], c[0], c[2]));
  const Int192 t2 = mul(a[2], minor2(b[0], b[1], c[0], c[1]));
  return add(add(t0, t1), t2);
}

// sign det[a; b; c] for |entries| ≤ kMax62.
inline int det3_sign(const std::int64_t a[3], const std::int64_t b[3], const std::int64_t c[3]) {
  return sign(det3(a, b, c));
}

// sign det[a; b; c] for |entries| < 2^40: every term and the sum fit __int128 (< 6·2^120).
inline int det3_sign_small(const std::int64_t a[3], const std::int64_t b[3], const std::int64_t c[3]) {
  return sign(a[0] * minor2(b[1], b[2], c[1], c[2]) - a[1] * minor2(b[0], b[2], c[0], c[2]) +
              a[2] * minor2(b[0], b[1], c[0], c[1]));
}

}  // namespace wrenchkit::wide
