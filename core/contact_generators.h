// [FC-0] The generators of a contact's wrench cone, over any number type (theory.md §4, §8.2).
//
// Written once and instantiated with exact rationals (exact/statics/generators.cpp) and with the float
// twin's error-bounded doubles (float/), so both enumerate the same generators in the same order
// and a generator index means the same (contact, edge) in both.
#pragma once

namespace wrenchkit {

// Which cone a scene's contacts generate: with their friction (force closure, equilibrium) or all
// read frictionless (first-order form closure, Reuleaux's method; theory.md §7).
enum class Reading { friction, frictionless };

// Names of generators, as in the certificate format (proofs/certificate-format.md §1).
enum class Edge { normal, left, right, wrench };

inline const char* edge_name(Edge e) {
  switch (e) {
    case Edge::normal: return "normal";
    case Edge::left: return "left";
    case Edge::right: return "right";
    case Edge::wrench: return "wrench";
  }
  return "?";
}

// Calls emit(edge, fx, fy, m) for each generator of a point contact at p with inward normal n:
// `normal` W(p, n) when read frictionless or when the contact is frictionless (`frictional` false,
// i.e. μ = 0 exactly — decided by the caller from the exact input), else `left` W(p, n + μ·rot90 n)
// and `right` W(p, n − μ·rot90 n), with rot90(n) = (−ny, nx) and W(p, f) = (fx, fy, px·fy − py·fx).
// T needs +, −, * (exact: no rounding; float twin: each operation carries its error bound).
template <class T, class Emit>
void point_contact_generators(const T& px, const T& py, const T& nx, const T& ny, const T& mu,
                              bool frictional, Reading reading, Emit&& emit) {
  auto at_p = [&](Edge e, const T& fx, const T& fy) { emit(e, fx, fy, px * fy - py * fx); };
  if (reading == Reading::frictionless || !frictional) {
    at_p(Edge::normal, nx, ny);
    return;
  }
  const T mny = mu * ny, mnx = mu * nx;
  at_p(Edge::left, nx - mny, ny + mnx);
  at_p(Edge::right, nx + mny, ny - mnx);
}

}  // namespace wrenchkit
