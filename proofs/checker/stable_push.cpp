// proofs/checker/stable_push.cpp - certificate-format.md §8.3: a line pusher's stable push and its stable region
// (proofs/notes/PU-3-stable-pushing.md): the members "stable" and "region" and their check, beside push.cpp's §8.
#include "proofs/checker/certificate.h"

#include <algorithm>

namespace wrenchkit_checker::detail {

namespace {

Q cross(const Q& ax, const Q& ay, const Q& bx, const Q& by) { return ax * by - ay * bx; }

}  // namespace

void read_line_push_member(Reader& r, std::string_view key, Push_part& p) {
  if (key == "region") {  // the stable region
    p.has_region = true;
    begin_object(r, "expected an object {\"R_hi\", \"ccw\", \"cw\", \"translations\"?}");
    std::string_view k;
    unsigned seen = 0;
    while (r.next_key(k)) {
      if (k == "R_hi") {
        seen |= 1, p.region_R_hi = read_rational(r);
      } else if (k == "ccw" || k == "cw") {
        const int s = k == "ccw" ? 0 : 1;
        seen |= s == 0 ? 2 : 4;
        if (r.peek() == Reader::Kind::null) {
          r.skip();
          continue;
        }
        p.has_side[s] = true;
        begin_object(r, "expected an object {\"alpha_hi\", \"T\"} or null");
        std::string_view j;
        unsigned got = 0;
        while (r.next_key(j)) {
          if (j == "alpha_hi") got |= 1, p.side_alpha_hi[s] = read_rational(r);
          else if (j == "T") got |= 2, p.side_T[s] = read_rational(r);
          else r.fail("unknown key " + quote(j), true);
        }
        if (got != 3) r.fail("a side of the region needs \"alpha_hi\" and \"T\"");
      } else if (k == "translations") {
        p.has_translations = true;
        read_fixed(r, 2, "two directions [[dx, dy], [dx, dy]]", [&](std::size_t m) {
          read_fixed(r, 2, "a direction [dx, dy]", [&](std::size_t i) { p.translations[m][i] = read_rational(r); });
        });
      } else {
        r.fail("unknown key " + quote(k), true);
      }
    }
    if (seen != 7) r.fail("a region needs \"R_hi\", \"ccw\" and \"cw\"");
  } else {  // "stable"
    p.has_stable = true;
    begin_object(r, "expected an object {\"verdict\", \"R2\", …}");
    std::string_view k;
    bool verdict = false, r2 = false;
    unsigned bounds = 0;
    while (r.next_key(k)) {
      if (k == "verdict") {
        verdict = true;
        if (r.peek() != Reader::Kind::string) r.fail("expected \"stable\" or \"unstable\"");
        p.verdict = r.string_view();
        if (p.verdict != "stable" && p.verdict != "unstable") r.fail("expected \"stable\" or \"unstable\"");
      } else if (k == "R2") {
        r2 = true, p.R2 = read_rational(r);
      } else if (k == "R_hi") {
        bounds |= 1, p.R_hi = read_rational(r);
      } else if (k == "d_lo") {
        bounds |= 2, p.d_lo = read_rational(r);
      } else if (k == "alpha_hi") {
        bounds |= 4, p.alpha_hi = read_rational(r);
      } else if (k == "facet") {
        p.has_facet = true;
        if (r.peek() != Reader::Kind::string) r.fail("expected \"left edge\", \"right edge\", \"end 0\" or \"end 1\"");
        p.facet = r.string_view();
        if (p.facet != "left edge" && p.facet != "right edge" && p.facet != "end 0" && p.facet != "end 1")
          r.fail("expected \"left edge\", \"right edge\", \"end 0\" or \"end 1\"");
      } else if (k == "duals") {
        begin_object(r, "expected an object {facet: [y0, yx, yy]}");
        std::string_view j;
        while (r.next_key(j)) {
          const int f = j == "left edge" ? 0 : j == "right edge" ? 1 : j == "end 0" ? 2 : j == "end 1" ? 3 : -1;
          if (f < 0) r.fail("expected a facet: \"left edge\", \"right edge\", \"end 0\" or \"end 1\"", true);
          p.has_dual[f] = true;
          read_dual(r, p.dual[f]);
        }
      } else if (k == "bits") {
        p.has_dual_bits = true, p.dual_bits = read_index(r, "number of bits");
      } else if (k == "witness") {
        p.has_witness = true;
        begin_object(r, "expected an object {\"points\", \"weights\", \"bits\"}");
        std::string_view j;
        unsigned got = 0;
        while (r.next_key(j)) {
          if (j == "points") {
            got |= 1;
            begin_array(r, "expected an array of points [x, y]");
            while (r.next_item()) {
              if (p.points.size() == 3) r.fail("a witness has at most three points (a basic solution of three rows)");
              std::array<Q, 2>& x = p.points.emplace_back();
              read_fixed(r, 2, "a point [x, y]", [&](std::size_t m) { x[m] = read_rational(r); });
            }
          } else if (j == "weights") {
            got |= 2;
            begin_array(r, "expected an array of weights");
            while (r.next_item()) {
              if (p.weights.size() == 3) r.fail("a witness has at most three weights");
              p.weights.push_back(read_rational(r));
            }
          } else if (j == "bits") {
            got |= 4, p.witness_bits = read_index(r, "number of bits");
          } else {
            r.fail("unknown key " + quote(j), true);
          }
        }
        if (got != 7) r.fail("a witness needs \"points\", \"weights\" and \"bits\"");
      } else {
        r.fail("unknown key " + quote(k), true);
      }
    }
    if (!verdict || !r2) r.fail("\"stable\" needs \"verdict\" and \"R2\"");
    if (bounds != 0 && bounds != 7) r.fail("the tip line's bounds are \"R_hi\", \"d_lo\" and \"alpha_hi\" together");
    p.has_bounds = bounds == 7;
  }
}

// ---- §8.3 a line pusher's stable push (proofs/notes/PU-3-stable-pushing.md) ----
//
// The pusher touches the body along [e0, e1] (inward normal n, coefficient mu) and moves with velocity v at the middle
// m and rate omega: about q = m + rot90(v)/omega (sense sigma), or translating. The composite cone's facets, each as
// a term h(x) whose weighted sum over a distribution, sum w h(x)/|x - q|, is > 0 when the load leaves CF by it:
// left edge sigma (x - q).eL, right edge -sigma (x - q).eR, end k -s_k sigma (x - e_k).(x - q), where s_k = +1 for
// the end p1 with (p2 - p1) x n > 0 (its moment must be >= 0), -1 for the other.
Q tip_correction(const Q& R, const Q& dl, const Q& al) {
  const Q K = R * (2 * al + R) / (2 * dl - R);
  return K * K * (2 * dl + R) / (8 * dl) + al * R * R * R / (dl * (2 * dl - R));
}

Q friction_disc(const Scene& scene, const Limits& lim, const std::string& path, Q (&c)[2], std::vector<std::array<Q, 2>>& S) {
  // The centre of friction, one for every distribution: every force given, or one coefficient > 0 (the centre of
  // pressure); and S's vertices: the support points and region rings with mu > 0.
  const Support& s = *scene.support;
  std::vector<Q> mus;
  Q m[2] = {0, 0}, d = 0;
  for (const Support_point& sp : s.points) {
    Point_values scratch;
    const Point_values& pv = values(sp, lim, scratch);
    mus.push_back(pv.mu);
    if (sgn(pv.mu) > 0) S.push_back({pv.x, pv.y});
    if (sp.known) m[0] += pv.mu * pv.f * pv.x, m[1] += pv.mu * pv.f * pv.y, d += pv.mu * pv.f;
  }
  for (const Region& g : s.regions) {
    mus.push_back(g.mu);
    if (sgn(g.mu) > 0)
      for (const auto& ring : g.rings)
        for (const P2& x : ring) S.push_back({x.x, x.y});
    m[0] += g.mu * g.M[0], m[1] += g.mu * g.M[1], d += g.mu * g.W;
  }
  if (s.unknown == 0) {
    if (sgn(d) <= 0) throw Failure{path + ": no friction under the body"};
    c[0] = m[0] / d, c[1] = m[1] / d;
  } else {
    for (const Q& x : mus)
      if (x != mus.front() || sgn(x) <= 0)
        throw Failure{path + ": the support's coefficients differ (or are 0) and some force is not given: the centre "
                      "of friction moves with the distribution"};
    c[0] = s.c[0], c[1] = s.c[1];
  }
  Q R2 = 0;
  for (const auto& x : S) R2 = std::max(R2, Q((x[0] - c[0]) * (x[0] - c[0]) + (x[1] - c[1]) * (x[1] - c[1])));
  return R2;
}

void check_line_push(const Push_part& p, const Scene& scene, const Limits& lim) {
  const Pusher& pu = *scene.pusher;
  const Support& s = *scene.support;
  if (!p.has_stable) throw Failure{"stable: a line pusher's certificate claims whether its motion is stable (§8.3)"};
  if (p.has_friction || !p.votes.empty() || p.has_turns || p.has_contact || p.has_locus)
    throw Failure{"a line pusher's certificate has \"rotation\", \"center\" and \"stable\" only"};
  const std::vector<Q> pn = contact_numbers(pu.contact, lim);  // x, y, nx, ny, mu
  const Q e[2][2] = {{pn[0], pn[1]}, {pu.end[0], pu.end[1]}};
  const Q n[2] = {pn[2], pn[3]}, &mu = pn[4];
  const Q(&v)[2] = pu.velocity;
  const Q ax = e[1][0] - e[0][0], ay = e[1][1] - e[0][1];
  if ((sgn(ax) == 0 && sgn(ay) == 0) || sgn(Q(ax * n[0] + ay * n[1])) != 0)
    throw Failure{"pusher: a line contact has two ends and a normal perpendicular to its segment"};
  if (sgn(Q(v[0] * n[0] + v[1] * n[1])) <= 0) throw Failure{"pusher.velocity: does not push into the body (v . n <= 0)"};
  const int s_end[2] = {sgn(cross(ax, ay, n[0], n[1])) > 0 ? 1 : -1, sgn(cross(ax, ay, n[0], n[1])) > 0 ? -1 : 1};
  const Q eL[2] = {n[0] - mu * n[1], n[1] + mu * n[0]}, eR[2] = {n[0] + mu * n[1], n[1] - mu * n[0]};
  std::vector<std::array<Q, 2>> S;
  Q c[2];
  const Q R2 = friction_disc(scene, lim, "stable", c, S);
  if (p.center[0] != c[0] || p.center[1] != c[1])
    throw Failure{"center: " + show(p.center[0], p.center[1]) + " is not the centre of friction " + show(c[0], c[1])};
  if (p.R2 != R2) throw Failure{"stable.R2: " + show(p.R2) + " is not the largest squared distance " + show(R2) +
                                " from the centre of friction to the support's places with friction"};
  static const char* const facets[4] = {"left edge", "right edge", "end 0", "end 1"};
  if (p.has_region) {  // the stable region: each sense's tip line a.(q - c) >= T holds §5 for every q in it
    const Q& R = p.region_R_hi;
    if (sgn(R) < 0 || R * R < R2) throw Failure{"region.R_hi: not an upper bound of R"};
    for (int k = 0; k < 2; ++k) {
      if (!p.has_side[k]) continue;
      const int sg = k == 0 ? 1 : -1, tip = s_end[0] * sg > 0 ? 1 : 0;
      const Q tx = c[0] - e[tip][0], ty = c[1] - e[tip][1], &al = p.side_alpha_hi[k], &T = p.side_T[k];
      const std::string path = std::string("region.") + (k == 0 ? "ccw" : "cw");
      if (sgn(al) <= 0 || al * al < tx * tx + ty * ty) throw Failure{path + ".alpha_hi: not an upper bound of |c - end|"};
      if (sgn(T) <= 0 || T / al <= R) throw Failure{path + ".T: T/alpha_hi is not more than R_hi"};
      if (T < R2 + tip_correction(R, T / al, al))
        throw Failure{path + ".T: " + show(T) + " is below R^2 + E(T/alpha_hi) = " + show(Q(R2 + tip_correction(R, T / al, al))) +
                      " (the tip line's half-plane must hold PU-3 §5 at every point)"};
    }
    if (p.has_translations)
      for (int m = 0; m < 2; ++m) {
        const Q(&t)[2] = p.translations[m];
        if (sgn(cross(t[0], t[1], eL[0], eL[1])) < 0 || sgn(cross(eR[0], eR[1], t[0], t[1])) < 0 ||
            s_end[0] * sgn(cross(c[0] - e[0][0], c[1] - e[0][1], t[0], t[1])) < 0 ||
            s_end[1] * sgn(cross(c[0] - e[1][0], c[1] - e[1][1], t[0], t[1])) < 0 || sgn(Q(t[0] * n[0] + t[1] * n[1])) <= 0)
          throw Failure{"region.translations[" + std::to_string(m) + "]: " + show(t[0], t[1]) +
                        " is not a stable translation (its load leaves the composite cone)"};
      }
    if (p.has_translations && sgn(cross(p.translations[0][0], p.translations[0][1], p.translations[1][0],
                                        p.translations[1][1])) < 0)
      throw Failure{"region.translations: not a cone from the first direction counter-clockwise to the second"};
  }
  const bool stable = p.verdict == "stable";
  if (stable == p.has_facet) throw Failure{"stable: \"facet\" names the facet an unstable push leaves, and only then"};
  // The rotation: stable, the pusher's own; unstable, only when every force the pusher can apply passes c on one side
  // (both cone edges' lines through both ends, (e_k - c) x e of one strict sign: PU-1's first lemma)
  int corners = 2;
  for (int k = 0; k < 2; ++k)
    for (const Q* d : {eL, eR}) {
      const int sg = sgn(cross(e[k][0] - c[0], e[k][1] - c[1], d[0], d[1]));
      corners = corners == 2 ? sg : corners == sg ? sg : 0;
    }
  const std::string_view expect_rotation = !stable ? (corners > 0 ? "ccw" : corners < 0 ? "cw" : "")
                                           : sgn(pu.omega) > 0 ? "ccw" : sgn(pu.omega) < 0 ? "cw" : "none";
  if (p.rotation != expect_rotation && !(!stable && p.rotation.empty()))
    throw Failure{"rotation: " + (!stable ? std::string("an unstable push's rotation needs every force the pusher can "
                                                        "apply to pass the centre of friction on that side")
                                          : "a stable push turns with the pusher: \"" + std::string(expect_rotation) + "\"")};
  if (sgn(pu.omega) == 0) {  // translating: the load is v through c, the facets' values exact
    if (p.has_bounds || p.has_witness) throw Failure{"stable: a translating pusher's verdict needs no bounds or witness"};
    const Q value[4] = {cross(v[0], v[1], eL[0], eL[1]), cross(eR[0], eR[1], v[0], v[1]),
                        s_end[0] * cross(c[0] - e[0][0], c[1] - e[0][1], v[0], v[1]),
                        s_end[1] * cross(c[0] - e[1][0], c[1] - e[1][1], v[0], v[1])};
    for (int k = 0; k < 4; ++k) {
      if (stable && sgn(value[k]) < 0)
        throw Failure{std::string("stable: the load is beyond the composite cone's ") + facets[k]};
      if (!stable && p.facet == facets[k] && sgn(value[k]) >= 0)
        throw Failure{std::string("stable.facet: the load is not beyond the composite cone's ") + facets[k]};
    }
    return;
  }
  const int sigma = sgn(pu.omega);
  const Q q[2] = {(e[0][0] + e[1][0]) / 2 - v[1] / pu.omega, (e[0][1] + e[1][1]) / 2 + v[0] / pu.omega};
  const auto term = [&](int f, const Q& x, const Q& y) -> Q {
    const Q dx = x - q[0], dy = y - q[1];
    if (f == 0) return sigma * (dx * eL[0] + dy * eL[1]);
    if (f == 1) return -sigma * (dx * eR[0] + dy * eR[1]);
    return -s_end[f - 2] * sigma * ((x - e[f - 2][0]) * dx + (y - e[f - 2][1]) * dy);
  };
  bool any_dual = false;
  for (bool b : p.has_dual) any_dual |= b;
  if (!stable && (any_dual || p.has_dual_bits)) throw Failure{"stable.duals: a stable push's proof"};
  if (any_dual != p.has_dual_bits) throw Failure{"stable: \"duals\" come with their \"bits\""};
  if (stable) {  // each facet by PU-3's condition (§2, §3, §5), or by the LP's dual over the support's points (§6)
    if (p.has_witness) throw Failure{"stable: a stable push has no witness"};
    if (any_dual) {
      if (!s.regions.empty()) throw Failure{"stable.duals: the LP's dual is over a support of points (no regions)"};
      if (p.dual_bits < 16 || p.dual_bits > 4096) throw Failure{"stable.bits: expected bits from 16 to 4096"};
    }
    for (int f = 0; f < 4; ++f) {
      if (!p.has_dual[f]) continue;
      const Q(&y)[3] = p.dual[f];
      if (sgn(y[0]) >= 0) throw Failure{std::string("stable.duals.") + facets[f] + ": y0 is not negative"};
      for (const auto& x : S) {  // h(x)/|x - q| <= y0 + y.(x - c), the left side's upper bound
        const Q dx = x[0] - q[0], dy = x[1] - q[1];
        Q l0, l1;
        sqrt_bounds(dx * dx + dy * dy, p.dual_bits, l0, l1);
        if (sgn(l0) <= 0) throw Failure{"stable.duals: a support point at the rotation centre (its friction is not one force)"};
        const Q h = term(f, x[0], x[1]);
        if ((sgn(h) >= 0 ? Q(h / l0) : Q(h / l1)) > y[0] + y[1] * (x[0] - c[0]) + y[2] * (x[1] - c[1]))
          throw Failure{std::string("stable.duals.") + facets[f] + ": the support point " + show(x[0], x[1]) +
                        " is not certainly below the dual's plane (bits " + std::to_string(p.dual_bits) + ")"};
      }
    }
    for (int f = 0; f < 2; ++f)
      for (const auto& x : S)
        if (!p.has_dual[f] && sgn(term(f, x[0], x[1])) > 0)
          throw Failure{std::string("stable: the support's point ") + show(x[0], x[1]) + " is beyond the " + facets[f] +
                        "'s line through the rotation centre " + show(q[0], q[1])};
    const int bis = s_end[0] * sigma > 0 ? 0 : 1, tip = 1 - bis;
    const Q wx = q[0] - c[0], wy = q[1] - c[1], w2 = wx * wx + wy * wy;
    const Q bx = q[0] - e[bis][0], by = q[1] - e[bis][1];
    if (!p.has_dual[2 + bis] && bx * bx + by * by > w2)
      throw Failure{std::string("stable: the rotation centre is closer to the centre of friction than to end ") +
                    std::to_string(bis) + " (the bisector, PU-3 §3)"};
    if (p.has_dual[2 + tip]) {
      if (p.has_bounds) throw Failure{"stable: the tip line's bounds, but end " + std::to_string(tip) + " has its dual"};
      return;
    }
    if (!p.has_bounds) throw Failure{"stable: a rotating stable push needs \"R_hi\", \"d_lo\", \"alpha_hi\" (the tip line)"};
    const Q tx = c[0] - e[tip][0], ty = c[1] - e[tip][1];
    const Q &R = p.R_hi, &dl = p.d_lo, &al = p.alpha_hi;
    if (sgn(R) < 0 || R * R < R2) throw Failure{"stable.R_hi: not an upper bound of R"};
    if (sgn(dl) < 0 || dl * dl > w2) throw Failure{"stable.d_lo: not a lower bound of |q - c|"};
    if (sgn(al) < 0 || al * al < tx * tx + ty * ty) throw Failure{"stable.alpha_hi: not an upper bound of |c - end|"};
    if (dl <= R) throw Failure{"stable.d_lo: not more than R_hi (the tip line's theorem needs |q - c| > R)"};
    const Q E = tip_correction(R, dl, al);
    if (tx * wx + ty * wy < R2 + E)
      throw Failure{"stable: (c - end " + std::to_string(tip) + ") . (q - c) = " + show(Q(tx * wx + ty * wy)) +
                    " is below R^2 + E = " + show(Q(R2 + E)) + " (the corrected tip line, PU-3 §5)"};
    return;
  }
  // unstable: the witness — points of S, weights > 0 with mean c, the load certainly beyond the facet
  if (!p.has_witness || p.has_bounds) throw Failure{"stable: a rotating unstable push needs its \"witness\""};
  if (p.points.empty() || p.points.size() != p.weights.size())
    throw Failure{"stable.witness: one weight per point, at least one point"};
  if (p.witness_bits < 16 || p.witness_bits > 4096) throw Failure{"stable.witness.bits: expected bits from 16 to 4096"};
  const int f = p.facet == "left edge" ? 0 : p.facet == "right edge" ? 1 : p.facet == "end 0" ? 2 : 3;
  Q sx = 0, sy = 0, lo = 0;
  for (std::size_t k = 0; k < p.points.size(); ++k) {
    const Q &x = p.points[k][0], &y = p.points[k][1], &wk = p.weights[k];
    const std::string path = "stable.witness.points[" + std::to_string(k) + "]";
    if (sgn(wk) <= 0) throw Failure{"stable.witness.weights[" + std::to_string(k) + "]: not positive"};
    bool in = false;  // a support point with friction, or on an edge of a region's ring (with friction)
    for (const Support_point& sp : s.points) {
      Point_values scratch;
      const Point_values& pv = values(sp, lim, scratch);
      in |= sgn(pv.mu) > 0 && pv.x == x && pv.y == y;
    }
    for (const Region& g : s.regions)
      for (const auto& ring : g.rings)
        for (std::size_t i = 0; i < ring.size() && sgn(g.mu) > 0; ++i) {
          const P2 &a = ring[i], &b = ring[(i + 1) % ring.size()];
          const Q ux = b.x - a.x, uy = b.y - a.y, px = x - a.x, py = y - a.y, t = px * ux + py * uy;
          in |= sgn(cross(ux, uy, px, py)) == 0 && sgn(t) >= 0 && t <= ux * ux + uy * uy;
        }
    if (!in) throw Failure{path + ": " + show(x, y) + " is not a place of the support with friction"};
    sx += wk * (x - c[0]), sy += wk * (y - c[1]);
    const Q dx = x - q[0], dy = y - q[1];
    Q l0, l1;
    sqrt_bounds(dx * dx + dy * dy, p.witness_bits, l0, l1);
    if (sgn(l0) <= 0) throw Failure{path + ": the rotation centre itself (no velocity there)"};
    const Q h = wk * term(f, x, y);
    lo += sgn(h) >= 0 ? Q(h / l1) : Q(h / l0);
  }
  if (sgn(sx) != 0 || sgn(sy) != 0) throw Failure{"stable.witness: its mean is not the centre of friction"};
  if (sgn(lo) <= 0)
    throw Failure{std::string("stable.witness: its load is not certainly beyond the composite cone's ") + facets[f] +
                  " (bits " + std::to_string(p.witness_bits) + ")"};
}

}  // namespace wrenchkit_checker::detail
