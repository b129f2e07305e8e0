// proofs/checker/generators.h - the generators of a scene, certificate-format.md §1: each contact's wrenches
// under a reading, recomputed exactly from the scene text, as integer wrenches over a number type N (numbers.h).
#pragma once

#include <string>

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

Q value(const Z& num, const Z& den);  // num / den as a rational in lowest terms (for messages)
template <class N>
std::string show(const Int_wrench<N>& w) {
  const Z d = to_z(w.d);
  return "(" + show(value(to_z(w.v[0]), d)) + ", " + show(value(to_z(w.v[1]), d)) + ", " + show(value(to_z(w.v[2]), d)) + ")";
}

// The edges of a contact under a reading (the table of §1): their number, names in `names`.
int edge_names(const Contact& c, Reading reading, const char* (&names)[2]);

// The generators of one contact under a reading, recomputed exactly from the scene text, in edge_names()' order.
template <class N>
struct Generators {
  int count;
  const char* edge[2];
  Int_wrench<N> w[2];
};
template <class N>
Generators<N> generators(const Contact& c, Reading reading, const Limits& lim);

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
