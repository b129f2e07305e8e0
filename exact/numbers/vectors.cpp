// exact/numbers/vectors.h: the vocabulary's functions that are not one line.
#include "exact/numbers/vectors.h"

#include <algorithm>
#include <cmath>

namespace wrenchkit {

std::optional<Vec3q> rationalized(const std::array<double, 3>& d) {
  const double m = std::max({std::fabs(d[0]), std::fabs(d[1]), std::fabs(d[2])});
  if (!(m > 0) || !std::isfinite(m)) return std::nullopt;
  Vec3q out;
  for (std::size_t i = 0; i < 3; ++i) {
    const double x = d[i] / m;
    // convergents h/k of x
    long h0 = 0, h1 = 1, k0 = 1, k1 = 0;
    double r = x;
    bool found = false;
    for (int it = 0; it < 40; ++it) {
      const double a = std::floor(r);
      const long h = static_cast<long>(a) * h1 + h0, k = static_cast<long>(a) * k1 + k0;
      if (k > 10000) break;
      h0 = h1, h1 = h, k0 = k1, k1 = k;
      if (std::fabs(x - static_cast<double>(h) / static_cast<double>(k)) <= 1e-10) {
        found = true;
        break;
      }
      if (r - a < 1e-300) break;
      r = 1 / (r - a);
    }
    if (!found) return std::nullopt;
    out[i] = Rational(h1, k1);
    out[i].canonicalize();
  }
  return out;
}

std::string motion_words(const Vec3q& t) {
  if (t[2] != 0)
    return std::string(t[2] > 0 ? "a counter-clockwise" : "a clockwise") + " rotation about (" +
           to_string(Rational(-t[1] / t[2])) + ", " + to_string(Rational(t[0] / t[2])) + ")";
  const std::array<Integer, 2> d = primitive(t[0], t[1]);
  return "a translation along (" + d[0].get_str() + ", " + d[1].get_str() + ")";
}

}  // namespace wrenchkit
