// proofs/checker/support_witnesses.h - what the motion (certificate-format.md §6.2, §6.4, §6.5) and hold (§7.2,
// §7.4, §7.5) checks share about the support: keys and witnesses' regions, distributions in F, friction forces in
// their discs, bounds on the frictional power, the vertices of F.
#pragma once

#include <functional>
#include <map>
#include <set>

#include "proofs/checker/certificate.h"

namespace wrenchkit_checker::detail {

// "(a, b, c, ...)" for a message, at most 8 entries shown.
inline std::string show_list(const std::vector<Q>& v) {
  std::string s = "(";
  for (std::size_t i = 0; i < v.size() && i < 8; ++i) s += (i ? ", " : "") + show(v[i]);
  if (v.size() > 8) s += ", ... (" + std::to_string(v.size()) + " entries)";
  return s + ")";
}
inline std::string point_name(std::size_t i) { return "support.points[" + std::to_string(i) + "]"; }

inline const std::vector<Block>* own_blocks(const Witness& w) { return w.has_regions ? &w.regions : nullptr; }

// Where a witness's friction acts and how (HD-1 §10): whether every force is strictly inside its disc, and the
// distinct places with friction (counted up to two; the first kept). Two places span R^3 with their friction;
// one place (x, y) spans the plane of wrenches (g, r x g), normal (y, -x, 1); none spans nothing.
struct Friction_reach {
  bool open = true;
  int places = 0;
  Q x, y;
  void at(const Q& px, const Q& py) {
    if (places == 0) x = px, y = py, places = 1;
    else if (places == 1 && (px != x || py != y)) places = 2;
  }
};

// The support's witnesses of the sliding (§6) and hold (§7) certificates, checked the same way for both: their keys
// and regions, a distribution in F, support forces in their friction discs and their wrench, a bound on the
// frictional power of a twist (rational speed bounds; for every distribution, with the LP dual over F), and the
// vertices of F.
class Support_witnesses {
 public:
  Support_witnesses(const Support& s, const Limits& lim) : s_(s), lim_(lim) {}

  // A witness's own "regions" (format 2, §6.5, §7.5): `required` (one block per region) where the support has regions
  // and a force not given; an unknown key elsewhere.
  void witness_regions(const Witness& w, bool required) const {
    if (w.path.empty()) return;  // not present
    if (!required && w.has_regions) throw Failure{w.path + ": unknown key \"regions\""};
    if (!required) return;
    if (!w.has_regions) throw Failure{w.path + ": missing required key \"regions\""};
    if (w.regions.size() != s_.regions.size())
      throw Failure{w.path + ".regions: " + std::to_string(w.regions.size()) + " blocks, but the support has " +
                    std::to_string(s_.regions.size()) + " regions"};
  }

  // The keys of a motion (§6.1) or hold (§7.1) certificate among `keys`: the `allowed` ones are required, the
  // `optional` ones may be present, any other is not allowed `when` (its claim) for the reason `why` (or the
  // regions' own). Returns the regions' blocks at the top level (§6.4, §7.4: one per region) if allowed, or nullptr.
  const std::vector<Block>* claim_keys(const Certificate& c, const std::vector<const char*>& keys,
                                       const std::set<std::string>& allowed, const std::set<std::string>& optional,
                                       const std::string& when, const std::string& why) const {
    for (const char* key : keys)
      if (!allowed.count(key) && !optional.count(key) && c.keys.count(key))
        throw Failure{std::string("key \"") + key + "\" is not allowed when " + when +
                      (std::string(key) != "regions"  ? why
                       : !s_.regions.empty() ? " at the top level (format 2: inside each witness)"
                                             : " and the support has no regions")};
    for (const char* key : keys)
      if (allowed.count(key) && !c.keys.count(key)) throw Failure{std::string("missing required key \"") + key + "\""};
    if (!allowed.count("regions")) return nullptr;
    const std::vector<Block>& blocks = members(c).regions;
    if (blocks.size() != s_.regions.size())
      throw Failure{"regions: " + std::to_string(blocks.size()) + " blocks, but the support has " +
                    std::to_string(s_.regions.size()) + " regions"};
    return &blocks;
  }

  // What a list of blocks (if any) holds, by the claim that reads it: forces (a witness carrying the load), speed
  // bounds (a twist's bound), or both on one set of cells (a load on the limit surface, §6.6, §7.6).
  static void block_kinds(const std::vector<Block>* blocks, bool forces, bool speeds) {
    if (!blocks) return;
    for (const Block& b : *blocks)
      if (b.has_forces != forces || b.has_speeds != speeds)
        throw Failure{b.path + ": expected " +
                      (forces && speeds ? std::string("both \"forces\" and \"speed_bounds\" (a load on the limit surface)")
                       : forces         ? std::string("\"forces\" (a witness that carries the load) and no \"speed_bounds\"")
                                        : std::string("\"speed_bounds\" (a twist's bound) and no \"forces\"")) +
                      " here"};
  }

  // For every f in F (§6.2, §7.2): check(v) for every witness v of `vertices` (it is in F and its claim holds under
  // its distribution), and every vertex of F is the distribution of one.
  void every_vertex(const std::vector<Witness>& vertices, const std::function<void(const Witness&)>& check) const {
    std::vector<const std::vector<Q>*> distributions;
    for (const Witness& v : vertices) check(v), distributions.push_back(&v.distribution);
    vertices_covered(distributions, "vertices");
  }

  // The scene's forces (0 where unknown).
  std::vector<Q> given() const {
    std::vector<Q> f;
    f.reserve(s_.points.size());
    Point_values scratch;
    for (const Support_point& p : s_.points) f.push_back(values(p, lim_, scratch).f);
    return f;
  }

  // f is in F: one entry per point, f >= 0, f_i the given force where given, sum f = W, sum f r = W c.
  void in_f(const std::vector<Q>& f, const std::string& path) const {
    size(f.size(), path);
    Q sum = 0, moment[2] = {0, 0};
    for (std::size_t i = 0; i < f.size(); ++i) {
      Point_values scratch;
      const Point_values& v = values(s_.points[i], lim_, scratch);
      const auto at = [&] { return path + "[" + std::to_string(i) + "]: "; };  // (built only for a failure)
      if (sgn(f[i]) < 0) throw Failure{at() + show(f[i]) + " is negative"};
      if (s_.points[i].known && f[i] != v.f)
        throw Failure{at() + show(f[i]) + " is not the given force " + show(v.f) + " of " + point_name(i)};
      sum += f[i], moment[0] += f[i] * v.x, moment[1] += f[i] * v.y;
    }
    Q regions = 0;
    for (const Region& g : s_.regions) regions += g.W, moment[0] += g.M[0], moment[1] += g.M[1];  // a known pressure
    sum += regions;
    if (sum != s_.W)
      throw Failure{path + ": the forces sum to " + show(sum) +
                    (s_.regions.empty() ? std::string() : " with the regions' " + show(regions)) + ", not the weight " +
                    show(s_.W)};
    const Q wc[2] = {s_.W * s_.c[0], s_.W * s_.c[1]};
    if (moment[0] != wc[0] || moment[1] != wc[1])
      throw Failure{path + ": sum f_i r_i is " + show(moment[0], moment[1]) + ", not W c = " + show(wc[0], wc[1]) +
                    " (the centre of pressure is not " + show(s_.c[0], s_.c[1]) + ")"};
  }

  void size(std::size_t n, const std::string& path) const {
    if (n != s_.points.size())
      throw Failure{path + ": " + std::to_string(n) + " entries, but the support has " +
                    std::to_string(s_.points.size()) + " points"};
  }

  // Support forces g_i under f, each in its friction disc, and their wrench sum (g_i, r_i x g_i).
  // `strict` (a stick, §6): p in the INTERIOR of LS(f): |g_i|^2 < (mu_i f_i)^2 where mu_i f_i > 0, g_i = 0 where it
  // is 0, and LS(f) is three-dimensional (two distinct points with mu_i f_i > 0), so the sum of the discs' relative
  // interiors is its interior (SL-1). Not strict (a hold, or a load on the limit surface, §6.6, §7.6):
  // |g_i|^2 <= (mu_i f_i)^2, the closed discs (so g_i = 0 where mu_i f_i = 0), any number of points; `reach` (if
  // given) then tells whether every force is strictly inside its disc and where friction acts (HD-1 §10).
  // With `blocks` (one per support region, certificate-format.md §6.4), each region's cells add their forces,
  // acting at the cells' pressure centroids, inside their discs as the points' are.
  std::array<Q, 3> support_sum(const std::vector<Q>& f, const std::vector<Pair>& g, const std::string& path,
                               bool strict, const std::vector<Block>* blocks = nullptr,
                               Friction_reach* reach = nullptr) const {
    size(g.size(), path);
    std::array<Q, 3> sum{0, 0, 0};
    Friction_reach own;
    Friction_reach& r = reach ? *reach : own;
    const auto friction_at = [&r](const Q& x, const Q& y) { r.at(x, y); };
    for (std::size_t i = 0; i < g.size(); ++i) {
      Point_values scratch;
      const Point_values& v = values(s_.points[i], lim_, scratch);
      if (sgn(g[i][0]) == 0 && sgn(g[i][1]) == 0) {  // g_i = 0: in its disc (mu_i f_i >= 0), adds nothing to the sum
        if (sgn(v.mu) > 0 && sgn(f[i]) > 0) friction_at(v.x, v.y);
        continue;
      }
      const Q bound = v.mu * f[i];
      r.open = in_disc(g[i][0], g[i][1], bound, strict, path, i, "mu f") && r.open;
      if (sgn(bound) > 0) friction_at(v.x, v.y);
      sum[0] += g[i][0], sum[1] += g[i][1], sum[2] += v.x * g[i][1] - v.y * g[i][0];
    }
    if (blocks)  // each region's cells: forces spread over the cell as p, acting at its pressure centroid
      for (std::size_t k = 0; k < blocks->size(); ++k)
        r.open = add_stick_block(s_.regions[k], (*blocks)[k], sum, friction_at, strict) && r.open;
    if (strict && r.places < 2)
      throw Failure{path + ": friction acts at fewer than two distinct points, so the limit surface is flat and no "
                           "load is inside it"};
    return sum;
  }

  // A bound on the frictional power h_f(q) = sum mu_i f_i |v_i(q)| from the rational speed bounds u_i >= 0,
  // u_i^2 >= |v_i(q)|^2: sum mu_i f_i u_i for the distribution f, or, with a dual (every f in F),
  // sum_known mu_i f_i u_i + y0 W' + yx M'x + yy M'y where mu_i u_i <= y0 + y.r_i for every unknown i.
  // With `blocks`, each region's bound mu_R sum_cells sum_j w_j u_j (certificate-format.md §6.4) is added.
  Q friction_bound(const std::vector<Q>& f, const Q (&q)[3], const std::vector<Q>& u, const std::string& prefix,
                   const Q* dual, const std::vector<Block>* blocks = nullptr) const {
    const std::string path = prefix + "speed_bounds";
    size(u.size(), path);
    std::vector<Q> coef(u.size());
    for (std::size_t i = 0; i < u.size(); ++i) {
      Point_values scratch;
      const Point_values& v = values(s_.points[i], lim_, scratch);
      speed_bound(u[i], q, v.x, v.y, path, i, "v_i(q)");
      coef[i] = v.mu * u[i];
    }
    Q bound = linear_bound(coef, f, dual, "dual: mu_i u_i");
    if (blocks)  // each region's bound on mu times the integral of |v| p
      for (std::size_t k = 0; k < blocks->size(); ++k) bound += slide_block_bound(s_.regions[k], (*blocks)[k], q);
    return bound;
  }

  // A bound on sum_i coef_i f_i (one coefficient per point): the sum itself for the distribution f, or, with the LP
  // dual (y0, yx, yy) of F's three rows (every f in F; f then holds the given forces), sum_known coef_i f_i + y0 W' +
  // yx M'x + yy M'y, where coef_i <= y0 + yx x_i + yy y_i for every unknown i (else the Failure "<what> = …").
  Q linear_bound(const std::vector<Q>& coef, const std::vector<Q>& f, const Q* dual, const char* what) const {
    Q bound = 0;
    for (std::size_t i = 0; i < coef.size(); ++i) {
      if (!dual || s_.points[i].known) {
        bound += coef[i] * f[i];
        continue;
      }
      Point_values scratch;
      const Point_values& v = values(s_.points[i], lim_, scratch);
      if (coef[i] > dual[0] + dual[1] * v.x + dual[2] * v.y)
        throw Failure{std::string(what) + " = " + show(coef[i]) + " is more than y0 + yx x_i + yy y_i = " +
                      show(Q(dual[0] + dual[1] * v.x + dual[2] * v.y)) + " at " + point_name(i)};
    }
    if (dual) bound += dual[0] * s_.rest_weight + dual[1] * s_.rest_moment[0] + dual[2] * s_.rest_moment[1];
    return bound;
  }

  // Every vertex of F is one of `distributions` (each already checked to be in F). The vertices are the basic
  // feasible solutions of the three rows (1, x_i, y_i) over the unknown forces (SL-1 §3): a vertex's support S
  // (its positive unknown forces) has linearly independent columns, so |S| <= 3 and the vertex is the unique
  // solution on S. `what` names the list in messages ("vertices").
  void vertices_covered(const std::vector<const std::vector<Q>*>& distributions, const std::string& what) const {
    // Each distribution's unknown support (when at most 3 points) names the vertex it can be.
    std::map<std::vector<std::size_t>, std::size_t> by_support;
    for (std::size_t w = 0; w < distributions.size(); ++w) {
      const std::vector<Q>& d = *distributions[w];
      std::vector<std::size_t> support;
      for (std::size_t i = 0; i < d.size() && support.size() <= 3; ++i)
        if (!s_.points[i].known && sgn(d[i]) > 0) support.push_back(i);
      if (support.size() <= 3) by_support.emplace(support, w);
    }
    std::vector<std::size_t> unknown;  // indices of the points without a given force
    for (std::size_t i = 0; i < s_.points.size(); ++i)
      if (!s_.points[i].known) unknown.push_back(i);
    const unsigned long long n = unknown.size();
    const unsigned long long bases =  // no overflow: n is at most max_contacts, capped here at 10^6
        n > 1000000 ? ULLONG_MAX : n + n * (n - 1) / 2 + n * (n - 1) * (n - 2) / 6;
    if (bases > lim_.max_vertex_bases)
      throw Failure{what + ": too large to check: " + std::to_string(n) + " points without a given force give " +
                    std::to_string(bases) + " candidate bases (limit " + std::to_string(lim_.max_vertex_bases) + ")"};
    const std::vector<Q> base = given();
    // A vertex with unknown support S and values x_S: it must be some witness's distribution.
    auto covered = [&](const std::vector<std::size_t>& S, const std::vector<Q>& x) {
      std::vector<Q> f = base;
      for (std::size_t k = 0; k < S.size(); ++k) f[S[k]] = x[k];
      const auto at = by_support.find(S);
      if (at == by_support.end() || *distributions[at->second] != f)
        throw Failure{what + ": the vertex " + show_list(f) + " of the admissible distributions has no witness"};
    };
    if (s_.rest_weight == 0) return covered({}, {});  // F = {given forces, 0 elsewhere}: one vertex
    // Integer columns a_i = D_i (1, x_i, y_i) and b = B (W', M'): positive scalings, so the signs of
    // the solutions are those of the true ones (x_i = D_i x'_i / B).
    std::vector<std::array<Z, 3>> a;
    std::vector<Point_values> pt;
    for (const std::size_t i : unknown) {
      Point_values scratch;
      pt.push_back(values(s_.points[i], lim_, scratch));
      const Q &x = pt.back().x, &y = pt.back().y;
      a.push_back({Z(x.get_den() * y.get_den()), Z(x.get_num() * y.get_den()), Z(y.get_num() * x.get_den())});
    }
    const Int_wrench<Z> bw = integer_form<Z>({s_.rest_weight, s_.rest_moment[0], s_.rest_moment[1]});
    const Z(&b)[3] = bw.v;
    auto cross = [](const std::array<Z, 3>& u, const std::array<Z, 3>& v) {
      return std::array<Z, 3>{Z(u[1] * v[2] - u[2] * v[1]), Z(u[2] * v[0] - u[0] * v[2]), Z(u[0] * v[1] - u[1] * v[0])};
    };
    auto dot_b = [&b](const std::array<Z, 3>& v) { return Z(b[0] * v[0] + b[1] * v[1] + b[2] * v[2]); };
    const Q cx = s_.rest_moment[0] / s_.rest_weight, cy = s_.rest_moment[1] / s_.rest_weight;  // c' = M'/W'
    // |S| = 1: r_i = c', x_i = W'.
    for (std::size_t p = 0; p < n; ++p)
      if (pt[p].x == cx && pt[p].y == cy) covered({unknown[p]}, {s_.rest_weight});
    // |S| = 2: r_i != r_j and c' strictly between them: b . (a_i x a_j) = 0 (b in their span) and the
    // two coordinates of b in the basis have the sign of |a_i x a_j|^2 > 0.
    std::vector<std::vector<std::array<Z, 3>>> c(n, std::vector<std::array<Z, 3>>(n));  // c[i][j] = a_i x a_j, i < j
    std::vector<std::vector<Z>> beta(n, std::vector<Z>(n));                               // b . c[i][j]
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) {
        c[i][j] = cross(a[i], a[j]), beta[i][j] = dot_b(c[i][j]);
        if (c[i][j][0] == 0 && c[i][j][1] == 0 && c[i][j][2] == 0) continue;  // coincident points
        if (beta[i][j] != 0) continue;
        const std::array<Z, 3> bz{b[0], b[1], b[2]};
        if (sgn(Z(dot3(cross(bz, a[j]), c[i][j]))) <= 0 || sgn(Z(dot3(cross(a[i], bz), c[i][j]))) <= 0) continue;
        // t = x_j: (c' - r_i) = t/W' (r_j - r_i), read on the larger coordinate difference
        const Q dx = pt[j].x - pt[i].x, dy = pt[j].y - pt[i].y;
        const Q t = dx != 0 ? Q(s_.rest_weight * (cx - pt[i].x) / dx) : Q(s_.rest_weight * (cy - pt[i].y) / dy);
        covered({unknown[i], unknown[j]}, {Q(s_.rest_weight - t), t});
      }
    // |S| = 3: D = det[a_i a_j a_k] = a_i . (a_j x a_k) != 0; by Cramer the coordinates of b are
    // (b.(a_j x a_k), b.(a_k x a_i), b.(a_i x a_j)) / D, all > 0.
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j)
        for (std::size_t k = j + 1; k < n; ++k) {
          const Z D = dot3(a[i], c[j][k]);
          const int sd = sgn(D);
          if (sd == 0 || sgn(beta[j][k]) != sd || -sgn(beta[i][k]) != sd || sgn(beta[i][j]) != sd) continue;
          const Z B = bw.d;
          auto value = [&](std::size_t p, const Z& num) {  // x_p = D_p (num / D) / B
            Q x(Z(a[p][0] * num), Z(D * B));
            x.canonicalize();
            return x;
          };
          covered({unknown[i], unknown[j], unknown[k]},
                  {value(i, beta[j][k]), value(j, Z(-beta[i][k])), value(k, beta[i][j])});
        }
  }

  static Z dot3(const std::array<Z, 3>& u, const std::array<Z, 3>& v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; }

 private:
  const Support& s_;
  const Limits& lim_;
};
}  // namespace wrenchkit_checker::detail
