// proofs/checker/generators.h - the generators of a scene, certificate-format.md §1: each contact's wrenches
// under a reading, recomputed exactly from the scene text, as integer wrenches over a number type N (numbers.h).
#pragma once

#include <string>
#include <vector>

#include "proofs/checker/scene.h"

namespace wrenchkit_checker::detail {

enum class Reading { friction, frictionless };  // of force_closure, of form_closure

// A wrench in integers: (v[0], v[1], v[2]) / d with d > 0. A positive denominator changes neither the
// sign of a power nor whether a determinant is zero, and a sum of such fractions is zero exactly when
// the numerator over their product (or their common denominator) is: so the conditions of §3 are
// checked on integers, with no gcd (mpq arithmetic reduces every intermediate result).
template <class N>
struct Int_wrench {
  N v[3], d;
};

// The rationals (a, b, c) as an Int_wrench over the product of their denominators.
template <class N>
Int_wrench<N> integer_form(const Frac<N>& a, const Frac<N>& b, const Frac<N>& c) {
  return {{N(a.num * b.den * c.den), N(b.num * a.den * c.den), N(c.num * a.den * b.den)}, N(a.den * b.den * c.den)};
}
template <class N, class T>
Int_wrench<N> integer_form(const T (&x)[3]) {  // of three rationals (Q) or certificate rational texts
  return integer_form(fraction<N>(x[0]), fraction<N>(x[1]), fraction<N>(x[2]));
}

inline Q value(const Z& num, const Z& den) {  // num / den as a rational in lowest terms (for messages)
  Q q(num, den);
  q.canonicalize();
  return q;
}
template <class N>
std::string show(const Int_wrench<N>& w) {
  const Z d = to_z(w.d);
  return "(" + show(value(to_z(w.v[0]), d)) + ", " + show(value(to_z(w.v[1]), d)) + ", " + show(value(to_z(w.v[2]), d)) + ")";
}

// The edges of a contact under a reading (the table of §1): their number, names in `names`.
inline int edge_names(const Contact& c, Reading reading, const char* (&names)[2]) {
  if (c.wrench) return names[0] = "wrench", 1;
  if (reading == Reading::frictionless || !c.frictional) return names[0] = "normal", 1;
  names[0] = "left", names[1] = "right";
  return 2;
}

// A contact's numbers, exactly: a point contact's x, y, nx, ny, mu (0 if absent); a wrench contact's fx, fy, m.
inline std::vector<Q> contact_numbers(const Contact& c, const Limits& lim) {
  std::vector<Q> out(c.wrench ? 3 : 5);
  for (std::size_t k = 0; k < out.size(); ++k) {
    if (c.fixed) set_small(out[k], c.small[k]);
    else out[k] = c.value.empty() ? scene_number(c.text[k], lim, "contacts") : c.value[k];  // valid: read before
  }
  return out;
}

// The generators of one contact under a reading, recomputed exactly from the scene text, in edge_names()' order.
template <class N>
struct Generators {
  int count;
  const char* edge[2];
  Int_wrench<N> w[2];
};
template <class N>
Generators<N> generators(const Contact& c, Reading reading, const Limits& lim) {
  Frac<N> in[5];  // point contact: x, y, nx, ny, mu; wrench: fx, fy, m
  const std::size_t count = c.wrench ? 3 : 5;
  if (c.fixed) {
    for (std::size_t k = 0; k < count; ++k) in[k] = {N(static_cast<long>(c.small[k].num)), N(static_cast<long>(c.small[k].den))};
  } else {
    std::vector<Q> read;
    if (c.value.empty())
      for (const std::string& s : c.text) read.push_back(scene_number(s, lim, "contacts"));  // valid: read before
    for (std::size_t k = 0; k < count; ++k) in[k] = fraction<N>(c.value.empty() ? read[k] : c.value[k]);
  }
  Generators<N> g;
  g.count = edge_names(c, reading, g.edge);
  if (c.wrench) return g.w[0] = integer_form(in[0], in[1], in[2]), g;
  // p = P / dp, n = Nn / dn over the products of the coordinates' denominators. W(p, f) = (fx, fy, px*fy - py*fx)
  // for f = F / df: (dp*Fx, dp*Fy, Px*Fy - Py*Fx) / (dp*df).
  const N P[2] = {N(in[0].num * in[1].den), N(in[1].num * in[0].den)}, dp(in[0].den * in[1].den);
  const N Nn[2] = {N(in[2].num * in[3].den), N(in[3].num * in[2].den)}, dn(in[2].den * in[3].den);
  const auto force_at = [&](const N& Fx, const N& Fy, const N& df) {
    return Int_wrench<N>{{N(dp * Fx), N(dp * Fy), N(P[0] * Fy - P[1] * Fx)}, N(dp * df)};
  };
  if (g.count == 1) return g.w[0] = force_at(Nn[0], Nn[1], dn), g;
  // n + mu*rot90(n) = (nx - mu*ny, ny + mu*nx),  n - mu*rot90(n) = (nx + mu*ny, ny - mu*nx); with mu = a/b
  // these are (b*Nn -+ a*rot90(Nn)) / (dn*b).
  const N &a = in[4].num, &b = in[4].den;
  const N bN[2] = {N(b * Nn[0]), N(b * Nn[1])}, aN[2] = {N(a * Nn[0]), N(a * Nn[1])}, df(dn * b);
  g.w[0] = force_at(N(bN[0] - aN[1]), N(bN[1] + aN[0]), df);
  g.w[1] = force_at(N(bN[0] + aN[1]), N(bN[1] - aN[0]), df);
  return g;
}

// Power <T, w> = vx*fx + vy*fy + w*m (theory.md §1.4) of the numerators: the power of T/T.d against w/w.d times
// T.d * w.d > 0.
template <class N>
N power(const Int_wrench<N>& t, const Int_wrench<N>& g) {
  return N(t.v[0] * g.v[0] + t.v[1] * g.v[1] + t.v[2] * g.v[2]);
}

// det[a; b; c] of the numerators: the determinant of the wrenches times a.d * b.d * c.d > 0.
template <class N>
N det3(const Int_wrench<N>& a, const Int_wrench<N>& b, const Int_wrench<N>& c) {
  const N(&x)[3] = a.v, (&y)[3] = b.v, (&z)[3] = c.v;
  return N(x[0] * N(y[1] * z[2] - y[2] * z[1]) - x[1] * N(y[0] * z[2] - y[2] * z[0]) + x[2] * N(y[0] * z[1] - y[1] * z[0]));
}

// x + y: over the common denominator when the denominators are equal, else over their product.
template <class N>
Int_wrench<N> operator+(const Int_wrench<N>& x, const Int_wrench<N>& y) {
  if (x.d == y.d) return {{N(x.v[0] + y.v[0]), N(x.v[1] + y.v[1]), N(x.v[2] + y.v[2])}, x.d};
  return {{N(x.v[0] * y.d + y.v[0] * x.d), N(x.v[1] * y.d + y.v[1] * x.d), N(x.v[2] * y.d + y.v[2] * x.d)}, N(x.d * y.d)};
}
}  // namespace wrenchkit_checker::detail
