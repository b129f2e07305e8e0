// proofs/checker/generators.cpp - the generators of a scene, certificate-format.md §1 (see generators.h).
#include "proofs/checker/generators.h"

namespace wrenchkit_checker::detail {

Q value(const Z& num, const Z& den) {  // num / den as a rational in lowest terms (for messages)
  Q q(num, den);
  q.canonicalize();
  return q;
}

int edge_names(const Contact& c, Reading reading, const char* (&names)[2]) {
  if (c.wrench) return names[0] = "wrench", 1;
  if (reading == Reading::frictionless || !c.frictional) return names[0] = "normal", 1;
  names[0] = "left", names[1] = "right";
  return 2;
}

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
template Generators<Z> generators(const Contact&, Reading, const Limits&);
template Generators<Fixed> generators(const Contact&, Reading, const Limits&);

}  // namespace wrenchkit_checker::detail
