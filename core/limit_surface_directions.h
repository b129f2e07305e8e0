// [LS-1] The direction rule of the polygonal limit surfaces, written once: the exact engine
// (exact/sliding/limit_surface.cpp) builds rationals from these integers and the float twin
// (float/limit_surface_twin.cpp) certified Bounded values, so both have the SAME polygons and the twin's
// λ² brackets the exact λ² (proofs/notes/LS-1-directions.md). Standard library only.
//
// For even n, φ_j = 2π(j + ½)/n, and the n directions are u_j = u(t_j), u(t) = ((1 − t²), 2t)/(1 + t²):
//   j < q = ⌊n/4⌋ (φ_j < π/2):   t_j = a_j/den, a_j = max(1, round(tan(φ_j/2)·den)) — the double tan
//                                 only CHOOSES the integer;
//   n/2 odd, j = q (φ_j = π/2):  t_j = 1, u = (0, 1);
//   n/2 − 1 − j for j < q:       t = den/a_j, u = (−u_x, u_y) of u_j (the mirror in the y-axis);
//   j + n/2:                     −u_j.
// den = 32n, doubled until 1 ≤ a_0 < a_1 < … < a_{q−1} < den, which holds iff the n directions are
// strictly counter-clockwise (LS-1). den stays below 2^26 (32·4096 = 2^17 in practice: no doubling
// happens for any n ≤ 4096), so den² + a_j² < 2^53 and every integer of u(t_j) is an exact double.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace wrenchkit {

constexpr int kMaxSides = 4096;  // the largest n of a direction set

struct Direction_parameters {
  int n = 0;
  std::int64_t den = 0;         // the common denominator of the t_j < 1
  std::vector<std::int64_t> a;  // a_j for j < ⌊n/4⌋: t_j = a_j/den
  bool middle = false;          // n/2 odd: u_{⌊n/4⌋} = (0, 1)
};

// The integers of the rule above for even n, 4 ≤ n ≤ kMaxSides (else std::invalid_argument). O(n).
inline Direction_parameters direction_parameters(int n) {
  if (n < 4 || n % 2 != 0 || n > kMaxSides)
    throw std::invalid_argument("make_directions: n must be even, 4 <= n <= " + std::to_string(kMaxSides) +
                                ", not " + std::to_string(n));
  const int half = n / 2, q = half / 2;
  const double pi = 3.14159265358979323846;
  Direction_parameters p;
  p.n = n;
  p.middle = half % 2 == 1;
  for (std::int64_t den = 32 * static_cast<std::int64_t>(n); den < (std::int64_t(1) << 26); den *= 2) {
    p.den = den;
    p.a.assign(q, 0);
    bool ok = true;
    for (int j = 0; j < q; ++j) {
      const double phi = 2 * pi * (j + 0.5) / n;  // in (0, π/2): t in (0, 1)
      const double tj = std::round(std::tan(phi / 2) * static_cast<double>(den));
      p.a[j] = static_cast<std::int64_t>(std::max(1.0, tj));
      ok = ok && (j == 0 || p.a[j - 1] < p.a[j]);
    }
    if (ok && (q == 0 || p.a[q - 1] < den)) return p;  // else rounding merged two directions: finer
  }
  throw std::logic_error("direction_parameters: no denominator below 2^26 separates the directions");
}

}  // namespace wrenchkit
