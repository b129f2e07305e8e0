// [FL-1] A double with a certified error bound (running error analysis), for the float twin.
//
// A Bounded b stands for an unknown real x with |x − b.v| ≤ b.e. Arithmetic propagates the bound
// rigorously under IEEE 754 binary64, round-to-nearest, no contraction (-ffp-contract=off, no
// fast-math): the proof is proofs/notes/FL-1-bounded-arithmetic.md. In short, with u = 2^-53:
//   * the rounding error of a sum or product is computed *exactly* (TwoSum; fma for products), so
//     operations on exact operands stay exact (e = 0) or carry exactly their own rounding error;
//   * propagated input errors use |xy − âb̂| ≤ |â|e_b + |b̂|e_a + e_a·e_b, and every bound computed
//     in floating point is inflated by (1 + 2^-45), which dominates its own ≤ 6 roundings;
//   * results that may have lost precision to underflow (0 < |v| < 2^-960, or a zero product of
//     nonzero factors) get e = +∞; overflow gives ±∞ or NaN, and then e = +∞ or NaN.
// sign() is certified: it returns a sign only if |v| > e (or e = 0, v exact), else uncertain.
// Standard library only (float/ builds without GMP and CGAL).
#pragma once

#include <cmath>
#include <limits>

#include "core/sign.h"

namespace wrenchkit::fl {

struct Bounded {
  double v = 0;  // the computed value
  double e = 0;  // |exact − v| ≤ e; 0 means v is exact

  static Bounded exact(double x) { return {x, std::isfinite(x) ? 0.0 : kInf}; }

  static constexpr double kInf = std::numeric_limits<double>::infinity();
  static constexpr double kUnderflow = 0x1p-960;   // below this a result may have lost bits
  static constexpr double kSlack = 0x1p-1000;      // covers underflowed error terms
  static constexpr double kInflate = 1 + 0x1p-45;  // dominates the roundings of a bound

  Sign sign() const {
    if (!(e == e) || !std::isfinite(v)) return Sign::uncertain;  // NaN bound or ±∞/NaN value
    if (e == 0) return v > 0 ? Sign::positive : (v < 0 ? Sign::negative : Sign::zero);
    if (v > e) return Sign::positive;
    if (-v > e) return Sign::negative;
    return Sign::uncertain;
  }
};

namespace detail {

// Marks results that may have been rounded below the normal range.
inline double guard(double v, double e) {
  if (v != 0 && std::fabs(v) < Bounded::kUnderflow) return Bounded::kInf;
  return e;
}

// The bound of a non-exact operation: inflated, plus slack for underflowed terms.
inline double up(double e) { return e * Bounded::kInflate + Bounded::kSlack; }

}  // namespace detail

inline Bounded operator-(const Bounded& a) { return {-a.v, a.e}; }

inline Bounded operator+(const Bounded& a, const Bounded& b) {
  // Adding an exact zero changes nothing.
  if (b.v == 0 && b.e == 0) return a;
  if (a.v == 0 && a.e == 0) return b;
  const double v = a.v + b.v;
  // TwoSum (Knuth): r = (a.v + b.v) − v exactly, for any finite a.v, b.v without overflow.
  const double bb = v - a.v;
  const double r = (a.v - (v - bb)) + (b.v - bb);
  double e;
  if (a.e == 0 && b.e == 0) e = std::fabs(r);  // exact: only this operation's rounding
  else e = detail::up(a.e + b.e + std::fabs(r));
  return {v, detail::guard(v, e)};
}

inline Bounded operator-(const Bounded& a, const Bounded& b) { return a + (-b); }

inline Bounded operator*(const Bounded& a, const Bounded& b) {
  // An exact zero factor makes an exact zero product, whatever the other factor's error.
  if ((a.v == 0 && a.e == 0 && std::isfinite(b.v) && b.e == b.e && b.e < Bounded::kInf) ||
      (b.v == 0 && b.e == 0 && std::isfinite(a.v) && a.e == a.e && a.e < Bounded::kInf))
    return {0.0, 0.0};
  const double v = a.v * b.v;
  if (v == 0 && a.v != 0 && b.v != 0) return {v, Bounded::kInf};  // underflow to zero
  if (!(a.e < Bounded::kInf) || !(b.e < Bounded::kInf)) return {v, Bounded::kInf};  // no bound (never 0·∞ = NaN)
  // fma gives the exact rounding error of the product when v is normal (guard() covers the rest).
  const double r = std::fma(a.v, b.v, -v);
  double e;
  if (a.e == 0 && b.e == 0) e = std::fabs(r);
  else e = detail::up(std::fabs(a.v) * b.e + std::fabs(b.v) * a.e + a.e * b.e + std::fabs(r));
  return {v, detail::guard(v, e)};
}

// [FL-5] Division, square root, max and abs (proofs/notes/FL-1-bounded-arithmetic.md, "FL-5").
//
// a / b needs b certified nonzero (|b.v| > b.e); otherwise the result is uncertain (e = +∞).
// Operands within 2^-900 … 2^900 and a normal quotient keep the rounding error exactly computable
// (the remainder a.v − v·b.v is then representable: fma gives it), so an exact quotient of exact data
// stays exact; outside that range the standard model's error u·|v| + 2^-1074 is used.
inline Bounded operator/(const Bounded& a, const Bounded& b) {
  const double bv = std::fabs(b.v);
  if (!(bv > b.e) || !std::isfinite(b.v) || !(b.e < Bounded::kInf) || !std::isfinite(a.v) || !(a.e == a.e))
    return {a.v / b.v, Bounded::kInf};
  if (a.v == 0 && a.e == 0) return {0.0, 0.0};  // an exact zero over a certified nonzero
  const double v = a.v / b.v;
  if (!std::isfinite(v) || (v == 0) != (a.v == 0) || (v != 0 && std::fabs(v) < Bounded::kUnderflow))
    return {v, Bounded::kInf};  // overflow or (gradual) underflow
  double round = 0;
  const bool safe = std::fabs(a.v) > 0x1p-900 && std::fabs(a.v) < 0x1p900 && bv > 0x1p-900 && bv < 0x1p900;
  if (a.v == 0) {
    // 0 / b.v = 0 exactly: only the propagated error below.
  } else if (safe) {
    const double r = std::fma(-v, b.v, a.v);  // a.v − v·b.v, exact
    if (r == 0 && a.e == 0 && b.e == 0) return {v, 0.0};
    round = std::fabs(r) / bv;
  } else {
    round = std::fabs(v) * 0x1p-53 + 0x1p-1074;
  }
  // |x_a/x_b − a.v/b.v| ≤ (a.e·|b.v| + |a.v|·b.e) / (|b.v|·(|b.v| − b.e)).
  double prop = 0;
  if (a.e != 0 || b.e != 0) prop = (a.e * bv + std::fabs(a.v) * b.e) / (bv * (bv - b.e));
  return {v, detail::up(prop + round)};
}

// √a for an exact value known to be ≥ 0 (a sum of squares, a squared length): a computed value
// below zero is read as 0. |√x − √s| ≤ min(e/√s, √e) for s = max(a.v, 0), plus the rounding of √.
inline Bounded sqrt(const Bounded& a) {
  if (!std::isfinite(a.v) || !(a.e == a.e) || !(a.e < Bounded::kInf)) return {std::sqrt(std::fabs(a.v)), Bounded::kInf};
  if (a.v < 0 && -a.v > a.e) return {0.0, Bounded::kInf};  // certified negative: not a square
  const double s = a.v > 0 ? a.v : 0.0;
  const double v = std::sqrt(s);
  if (a.e == 0 && (s == 0 || (s > 0x1p-900 && std::fma(v, v, -s) == 0))) return {v, 0.0};  // exact square
  double prop = 0;
  if (a.e != 0) prop = s > 0 ? std::fmin(a.e / v, std::sqrt(a.e)) : std::sqrt(a.e);
  return {v, detail::up(prop + v * 0x1p-52 + 0x1p-1074)};
}

// max and |·| are 1-Lipschitz: the larger bound covers the result.
inline Bounded max(const Bounded& a, const Bounded& b) { return {a.v > b.v ? a.v : b.v, a.e > b.e ? a.e : b.e}; }
inline Bounded abs(const Bounded& a) { return {std::fabs(a.v), a.e}; }

// The interval [v − e, v + e] rounded outward (for reports and comparisons with exact values).
// (Each is one subtraction or addition and one product: a relative nudge of 2^-50 covers both roundings.)
inline double lower(const Bounded& a) {
  if (a.e == 0) return a.v;
  const double d = a.v - a.e;
  return d * (d > 0 ? 1 - 0x1p-50 : 1 + 0x1p-50) - 0x1p-1074;
}
inline double upper(const Bounded& a) {
  if (a.e == 0) return a.v;
  const double d = a.v + a.e;
  return d * (d > 0 ? 1 + 0x1p-50 : 1 - 0x1p-50) + 0x1p-1074;
}

}  // namespace wrenchkit::fl
