#include "exact/statics/wrench_cone.h"

#include <algorithm>
#include <optional>
#include <stdexcept>

#include "exact/numbers/wide_int.h"
#include "exact/statics/hybrid_kernel.h"
#include "exact/statics/planar_region.h"

namespace wrenchkit {

namespace {

Vec3q neg3(const Vec3q& a) { return {-a[0], -a[1], -a[2]}; }
bool zero3(const Vec3q& a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; }
Rational det3(const Vec3q& a, const Vec3q& b, const Vec3q& c) { return dot(a, cross(b, c)); }

// Extreme rays of a rank-3 dual cone, in the cycle's order (the vertices g_{e_j} × g_{e_{j+1}}).
std::vector<Vec3q> extreme_rays(const Dual_cone& dc, const std::vector<Vec3q>& g) {
  std::vector<Vec3q> r;
  const std::vector<std::size_t>& e = dc.edges;
  switch (dc.shape) {
    case Dual_shape::polygon:
      for (std::size_t j = 0; j < e.size(); ++j) r.push_back(primitive_vec(cross(g[e[j]], g[e[(j + 1) % e.size()]])));
      break;
    case Dual_shape::arc:
      // (p, e, q, e') up to a cyclic rotation (a cut of an arc keeps the cycle, not its start): each
      // of the two rays g_p × g_e, g_e × g_q appears at two consecutive pairs. Found by fuzz_structured.
      for (std::size_t j = 0; j < 4; ++j) {
        const Vec3q v = primitive_vec(cross(g[e[j]], g[e[(j + 1) % 4]]));
        if (std::find(r.begin(), r.end(), v) == r.end()) r.push_back(v);
      }
      if (r.size() != 2) throw std::logic_error("wrench_cone: an arc without two distinct rays");
      break;
    case Dual_shape::ray:
      r.push_back(primitive_vec(cross(g[e[0]], g[e[1]])));
      break;
    case Dual_shape::zero:
    case Dual_shape::lineality:
      break;
  }
  return r;
}

// Two integer vectors spanning the plane orthogonal to a ≠ 0.
std::pair<Vec3q, Vec3q> orthogonal_basis(const Vec3q& a) {
  const Vec3q unit[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (const Vec3q& e : unit) {
    const Vec3q u = cross(a, e);
    if (!zero3(u)) return {primitive_vec(u), primitive_vec(cross(a, u))};
  }
  throw std::logic_error("orthogonal_basis: zero vector");
}

void push_pm(std::vector<Vec3q>& out, const Vec3q& v) {
  out.push_back(v);
  out.push_back(neg3(v));
}

fl::Bounded3 bounded_of(const Vec3q& w) { return {to_bounded(w[0]), to_bounded(w[1]), to_bounded(w[2])}; }

// [FC-1] on the wrenches: exact, or hybrid (the twin's certified sign, exact where uncertain).
Dual_cone dual_cone_of(const std::vector<Vec3q>& ws, const std::vector<fl::Bounded3>& twin, Mode mode,
                       Wrench_cone& counts) {
  std::optional<Exact_kernel> exact;
  const Lazy_generators lazy(ws);
  Predicate_tally tally;
  Dual_cone dc = in_mode(
      mode, [&]() -> const Exact_kernel& { return exact.emplace(ws); }, [&] { return fl::Float_kernel(twin); }, lazy,
      tally, [](const auto& k) { return compute_dual_cone(k); });
  counts.predicates += tally.predicates;
  counts.exact_predicates += tally.exact;
  return dc;
}

// Integer rows and rays of the fixed-width construction (wrench_cone_of_rows).
using Row = std::array<std::int64_t, 3>;
using Ray = std::array<wide::i128, 3>;

// The primitive form of a nonzero integer vector (entries < 2^127): divided by the gcd of its entries.
template <class T>
std::array<T, 3> primitive_int(std::array<T, 3> v) {
  const wide::u128 d = wide::gcd128(wide::gcd128(wide::uabs(v[0]), wide::uabs(v[1])), wide::uabs(v[2]));
  for (T& x : v) x = static_cast<T>(static_cast<wide::i128>(x) / static_cast<wide::i128>(d));
  return v;
}

// a × b for |entries| ≤ 2^62 − 1: each coordinate a difference of two products < 2^124, so < 2^125.
Ray cross_int(const Row& a, const Row& b) {
  return {wide::minor2(a[1], a[2], b[1], b[2]), wide::minor2(a[2], a[0], b[2], b[0]),
          wide::minor2(a[0], a[1], b[0], b[1])};
}

Rational rational_of(wide::i128 v) {
  return wide::fits62(v) ? Rational(static_cast<long>(v)) : Rational(integer_of(v));
}

template <class T>
Vec3q vec_of(const std::array<T, 3>& v) {
  return {rational_of(v[0]), rational_of(v[1]), rational_of(v[2])};
}

// wrench_cone with W*'s combinatorics already known (`known`, over the same nonzero generators, found with
// `tally`'s predicates) or computed here (nullptr).
Wrench_cone cone_of(const std::vector<Vec3q>& generators, Mode mode, const std::vector<fl::Bounded3>* twin,
                    const Dual_cone* known, const Predicate_tally& tally);

}  // namespace

std::optional<Wrench_cone> wrench_cone_of_rows(const Scene& scene, Reading reading,
                                               const std::vector<fl::Bounded3>& twin) {
  const Exact_kernel rows(scene, reading);
  if (rows.size() != twin.size()) throw std::invalid_argument("wrench_cone_of_rows: twin of another size");
  std::vector<Row> g(rows.size());
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (!rows.small_row(i, g[i].data())) return std::nullopt;  // beyond 62 bits: the rationals
    if (g[i][0] == 0 && g[i][1] == 0 && g[i][2] == 0) return std::nullopt;  // wrench_cone drops zero wrenches
    g[i] = primitive_int(g[i]);
  }
  Wrench_cone c;
  const Lazy_generators lazy(scene, reading);
  Predicate_tally tally;
  const Dual_cone dc = in_mode(
      Mode::hybrid, [&]() -> const Exact_kernel& { return rows; }, [&] { return fl::Float_kernel(twin); }, lazy,
      tally, [](const auto& k) { return compute_dual_cone(k); });
  if (dc.rank != 3 || dc.shape == Dual_shape::ray) {  // the rational construction, from the same combinatorics
    std::vector<Vec3q> ws;
    ws.reserve(g.size());
    for (Generator& x : generators(scene, reading)) ws.push_back(std::move(x.w));
    return cone_of(ws, Mode::hybrid, &twin, &dc, tally);
  }
  c.predicates = tally.predicates;
  c.exact_predicates = tally.exact;
  c.rank = dc.rank;
  c.shape = dc.shape;
  c.dual_pointed = true;
  const std::vector<std::size_t>& e = dc.edges;
  switch (dc.shape) {
    case Dual_shape::polygon:  // as extreme_rays and wrench_cone above, in integers
      c.dual.reserve(e.size());
      c.primal.reserve(e.size());
      for (std::size_t j = 0; j < e.size(); ++j) {
        c.dual.push_back(vec_of(primitive_int(cross_int(g[e[j]], g[e[(j + 1) % e.size()]]))));
        c.primal.push_back(vec_of(g[e[j]]));
      }
      break;
    case Dual_shape::arc: {
      std::vector<Ray> r;
      for (std::size_t j = 0; j < 4; ++j) {
        const Ray v = primitive_int(cross_int(g[e[j]], g[e[(j + 1) % 4]]));
        if (std::find(r.begin(), r.end(), v) == r.end()) r.push_back(v);
      }
      if (r.size() != 2) throw std::logic_error("wrench_cone: an arc without two distinct rays");
      for (const Ray& v : r) c.dual.push_back(vec_of(v));
      for (std::size_t j : e) c.primal.push_back(vec_of(g[j]));
      c.primal_pointed = false;
      break;
    }
    case Dual_shape::zero:  // W = R³: ± the unit vectors, in wrench_cone's order (force closure: the common case)
      c.primal.reserve(6);
      for (std::size_t k = 0; k < 3; ++k)
        for (long sense : {1L, -1L}) {
          Vec3q x{0, 0, 0};
          x[k] = sense;
          c.primal.push_back(std::move(x));
        }
      c.primal_pointed = false;
      break;
    case Dual_shape::ray:
    case Dual_shape::lineality:
      return std::nullopt;
  }
  return c;
}

Vec3q J(const Vec3q& u) { return {-u[1], u[0], u[2]}; }

Wrench_cone wrench_cone(const std::vector<Vec3q>& generators, Mode mode, const std::vector<fl::Bounded3>* twin) {
  return cone_of(generators, mode, twin, nullptr, Predicate_tally{});
}

namespace {

Wrench_cone cone_of(const std::vector<Vec3q>& generators, Mode mode, const std::vector<fl::Bounded3>* twin,
                    const Dual_cone* known, const Predicate_tally& tally) {
  if (mode == Mode::float_only) throw std::invalid_argument("wrench_cone: the float twin is fl::moment_labels");
  if (twin && twin->size() != generators.size()) throw std::invalid_argument("wrench_cone: twin of another size");
  std::vector<Vec3q> ws;
  std::vector<Vec3q> g;
  std::vector<fl::Bounded3> tw;
  ws.reserve(generators.size());
  g.reserve(generators.size());
  if (mode == Mode::hybrid) tw.reserve(generators.size());
  for (std::size_t i = 0; i < generators.size(); ++i) {
    const Vec3q& w = generators[i];
    if (w[0] == 0 && w[1] == 0 && w[2] == 0) continue;
    ws.push_back(w);
    g.push_back(primitive_vec(w));
    if (mode == Mode::hybrid) tw.push_back(twin ? (*twin)[i] : bounded_of(w));
  }
  Wrench_cone c;
  c.predicates = tally.predicates;
  c.exact_predicates = tally.exact;
  if (known && ws.size() != generators.size())
    throw std::logic_error("wrench_cone: known combinatorics over other generators");
  const Dual_cone dc = known ? *known : dual_cone_of(ws, tw, mode, c);
  c.rank = dc.rank;
  c.shape = dc.shape;
  const Vec3q e[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  if (dc.rank == 3) {
    c.dual = extreme_rays(dc, g);
    c.dual_pointed = true;
    switch (dc.shape) {
      case Dual_shape::polygon:  // W pointed: its extreme rays are W*'s facet normals, in order
        for (std::size_t j : dc.edges) c.primal.push_back(g[j]);
        break;
      case Dual_shape::arc:
        for (std::size_t j : dc.edges) c.primal.push_back(g[j]);
        c.primal_pointed = false;
        break;
      case Dual_shape::ray: {  // W = {w : ⟨r, w⟩ ≥ 0}
        const Vec3q r = c.dual[0];
        const auto [u, v] = orthogonal_basis(r);
        c.primal = {r};
        push_pm(c.primal, u);
        push_pm(c.primal, v);
        c.primal_pointed = false;
        break;
      }
      case Dual_shape::zero:
      case Dual_shape::lineality:
        for (const Vec3q& x : e) push_pm(c.primal, x);
        c.primal_pointed = false;
        break;
    }
    return c;
  }
  if (dc.rank == 2) {
    const Vec3q b0 = g[dc.basis[0]], b1 = g[dc.basis[1]];
    const Vec3q n = primitive_vec(cross(b0, b1));
    c.lineality = {n};
    std::vector<Vec3q> with_n = ws;
    with_n.push_back(Vec3q{n[0], n[1], n[2]});
    std::vector<Vec3q> gn = g;
    gn.push_back(n);
    if (mode == Mode::hybrid) tw.push_back(bounded_of(with_n.back()));
    const Dual_cone half = dual_cone_of(with_n, tw, mode, c);
    if (half.rank != 3) throw std::logic_error("wrench_cone: rank did not rise to 3");
    c.dual = extreme_rays(half, gn);
    c.dual.push_back(neg3(n));
    c.dual_pointed = false;
    // W in the plane span{b0, b1}: coordinates (det(g, b1, n), det(b0, g, n)) ∝ (α, β), g = α b0 + β b1.
    std::vector<Vec2> xy;
    for (const Vec3q& x : g) xy.push_back({det3(x, b1, n), det3(b0, x, n)});
    const Cone2 k = cone_hull(xy);
    const auto back = [&](const Vec2& d) {
      return primitive_vec({d.x * b0[0] + d.y * b1[0], d.x * b0[1] + d.y * b1[1], d.x * b0[2] + d.y * b1[2]});
    };
    if (k.shape == Cone2::Shape::plane) {
      push_pm(c.primal, b0);
      push_pm(c.primal, b1);
    } else {
      for (const Vec2& d : k.extreme) c.primal.push_back(back(d));
    }
    c.primal_pointed = k.shape == Cone2::Shape::wedge || k.shape == Cone2::Shape::ray;
    return c;
  }
  if (dc.rank == 1) {
    const Vec3q a = g[dc.basis[0]];
    bool same_sense = true;
    for (const Vec3q& x : g) same_sense &= dot(a, x) > 0;
    const auto [u, v] = orthogonal_basis(a);
    c.lineality = {u, v};
    if (same_sense) c.dual.push_back(a);
    push_pm(c.dual, u);
    push_pm(c.dual, v);
    c.dual_pointed = false;
    c.primal = {a};
    if (!same_sense) c.primal.push_back(neg3(a));
    c.primal_pointed = same_sense;
    return c;
  }
  // rank 0: W = {0}, W* = R³.
  for (const Vec3q& x : e) {
    push_pm(c.dual, x);
    c.lineality.push_back(x);
  }
  c.dual_pointed = false;
  return c;
}

}  // namespace

bool in_cone(const Wrench_cone& c, const Vec3q& w) {
  for (const Vec3q& t : c.dual)
    if (dot(t, w) < 0) return false;
  return true;
}

}  // namespace wrenchkit
