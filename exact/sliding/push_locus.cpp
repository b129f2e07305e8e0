// [PU-4] The rotation centres of a pushed body over every distribution. See push_locus.h.
#include "exact/sliding/push_locus.h"

#include <algorithm>

#include "core/contact_generators.h"
#include "exact/sliding/sliding.h"

namespace wrenchkit {

const char* locus_bound_name(Locus_bound b) {
  switch (b) {
    case Locus_bound::bisector: return "bisector";
    case Locus_bound::tip_line: return "tip line";
    case Locus_bound::advance: return "advance";
    case Locus_bound::left_edge: return "left edge";
    case Locus_bound::right_edge: return "right edge";
    case Locus_bound::line: return "sticking line";
    case Locus_bound::along_left: return "along left edge";
    case Locus_bound::along_right: return "along right edge";
    case Locus_bound::slip: return "slip";
  }
  return "?";
}

const char* locus_mode_name(Locus_mode m) {
  switch (m) {
    case Locus_mode::sticks: return "sticks";
    case Locus_mode::slides_left: return "slides left";
    case Locus_mode::slides_right: return "slides right";
  }
  return "?";
}

namespace {

bool lexless(const Vec2& x, const Vec2& y) { return x.x < y.x || (x.x == y.x && x.y < y.y); }
bool same(const Vec2& x, const Vec2& y) { return x.x == y.x && x.y == y.y; }

bool satisfies(const std::vector<Locus_halfplane>& hs, const Vec2& q) {
  return std::all_of(hs.begin(), hs.end(), [&](const Locus_halfplane& l) { return dot(l.h.a, q) <= l.h.b; });
}

// Bounded (and not the whole plane): no direction u ≠ 0 with a·u ≤ 0 for every half-plane. A nonzero recession cone
// other than the plane has a boundary ray on some line a·u = 0, so the candidates ±rot90(a) decide.
bool bounded(const std::vector<Locus_halfplane>& hs) {
  for (const Locus_halfplane& l : hs)
    for (const Vec2& u : {Vec2{-l.h.a.y, l.h.a.x}, Vec2{l.h.a.y, -l.h.a.x}}) {
      if (is_zero(u)) continue;
      if (std::all_of(hs.begin(), hs.end(), [&](const Locus_halfplane& m) { return sgn(dot(m.h.a, u)) <= 0; }))
        return false;
    }
  return true;
}

// The vertices of the intersection: the boundary lines' crossings that satisfy every half-plane.
std::vector<Vec2> corners(const std::vector<Locus_halfplane>& hs) {
  std::vector<Vec2> out;
  for (std::size_t i = 0; i < hs.size(); ++i)
    for (std::size_t j = i + 1; j < hs.size(); ++j) {
      const Vec2 &a = hs[i].h.a, &b = hs[j].h.a;
      const Rational det = cross(a, b);
      if (sgn(det) == 0) continue;
      const Vec2 q{(hs[i].h.b * b.y - hs[j].h.b * a.y) / det, (a.x * hs[j].h.b - b.x * hs[i].h.b) / det};
      if (satisfies(hs, q)) out.push_back(q);
    }
  return out;
}

// Their convex hull, counter-clockwise (Andrew's monotone chain, collinear points dropped); a point or a segment as one
// or two vertices. (statics' planar_region.h has one for the moment labels, behind the wall between statics and
// sliding — wrenchkit_sliding links io only —; this one is the few lines the pieces need.)
std::vector<Vec2> hull(std::vector<Vec2> p) {
  std::sort(p.begin(), p.end(), lexless);
  p.erase(std::unique(p.begin(), p.end(), same), p.end());
  if (p.size() <= 2) return p;
  std::vector<Vec2> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && sgn(cross(minus(h[k - 1], h[k - 2]), minus(p[i], h[k - 2]))) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && sgn(cross(minus(h[k - 1], h[k - 2]), minus(p[i], h[k - 2]))) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

}  // namespace

Push_locus push_locus(const Support_model& model, const Pusher& pusher, const std::array<bool, 2>& allowed) {
  Push_locus g;
  const Friction_disc D = friction_disc(model);
  g.friction_centre = D.c;
  g.why = D.why;
  if (!D.c) return g;
  const Contact& pc = pusher.contact;
  const Vec2 p = pc.at, n = pc.normal, v = pusher.velocity, c = *D.c;
  Vec2 left, right;
  point_contact_generators(p.x, p.y, n.x, n.y, pc.mu, true, Reading::friction,
                           [&](Edge e, const Rational& fx, const Rational& fy, const Rational&) {
                             (e == Edge::left ? left : right) = Vec2{fx, fy};
                           });
  g.R2 = D.R2;
  g.R_hi = outward(sqrt_bracket(g.R2, 64).second, 6, true);
  const Vec2 a = minus(c, p);
  if (!is_zero(a)) {
    g.alpha_hi = outward(sqrt_bracket(dot(a, a), 64).second, 6, true);
    g.T = tip_line_T(g.R2, g.R_hi, g.alpha_hi);
  }
  // S's extent along e₊ and e₋
  Rational lmin = dot(D.vertices[0], left), lmax = lmin, rmin = dot(D.vertices[0], right), rmax = rmin;
  for (const Vec2& x : D.vertices) {
    lmin = std::min(lmin, dot(x, left)), lmax = std::max(lmax, dot(x, left));
    rmin = std::min(rmin, dot(x, right)), rmax = std::max(rmax, dot(x, right));
  }
  const auto neg = [](const Vec2& u) { return Vec2{-u.x, -u.y}; };
  // the box the unbounded pieces are drawn in: the scene widened by ten times its size
  Vec2 lo = c, hi = c;
  const auto add = [&](const Vec2& x) {
    lo = {std::min(lo.x, x.x), std::min(lo.y, x.y)}, hi = {std::max(hi.x, x.x), std::max(hi.y, x.y)};
  };
  for (const Vec2& x : D.vertices) add(x);
  add(p);
  const Rational size = std::max({Rational(hi.x - lo.x), Rational(hi.y - lo.y), Rational(1)});
  g.box = {Vec2{lo.x - 10 * size, lo.y - 10 * size}, Vec2{hi.x + 10 * size, hi.y + 10 * size}};
  Rational H = 0;
  bool all_bounded = true, any = false;
  for (int k = 0; k < 2; ++k) {
    Locus_side& side = g.side[k];
    side.possible = allowed[k];
    if (!side.possible) continue;
    const int s = k == 0 ? 1 : -1;
    std::vector<Locus_halfplane> common = {
        {Locus_bound::bisector, {Vec2{2 * (p.x - c.x), 2 * (p.y - c.y)}, dot(p, p) - dot(c, c)}},  // |q − p| ≥ |q − c|
        {Locus_bound::advance, {Vec2{s * n.y, -s * n.x}, s * cross(p, n)}}};                      // σ(p − q) × n ≥ 0
    if (g.T) common.push_back({Locus_bound::tip_line, {a, *g.T + dot(a, c)}});                 // a·(q − c) ≤ T
    const Rational pv = dot(p, v);
    for (int m = 0; m < 3; ++m) {
      Locus_piece& piece = side.pieces[m];
      piece.halfplanes = common;
      auto& hs = piece.halfplanes;
      if (m == 0) {  // sticks: on the line (p − q)·v = 0, the load inside the cone
        piece.mode = Locus_mode::sticks;
        const Rational sl = s > 0 ? lmin : -lmax, sr = s > 0 ? rmax : -rmin;  // min σx·e₊, max σx·e₋
        hs.push_back({Locus_bound::left_edge, {Vec2{-s * left.x, -s * left.y}, -sl}});  // σ q·e₊ ≥ min σ x·e₊
        hs.push_back({Locus_bound::right_edge, {Vec2{s * right.x, s * right.y}, sr}});   // σ q·e₋ ≤ max σ x·e₋
        hs.push_back({Locus_bound::line, {v, pv}});
        hs.push_back({Locus_bound::line, {neg(v), -pv}});
      } else {  // slides: the load along the edge, the body slipping against its tangential part
        const bool l = m == 1;
        piece.mode = l ? Locus_mode::slides_left : Locus_mode::slides_right;
        const Vec2& e = l ? left : right;
        const Locus_bound along = l ? Locus_bound::along_left : Locus_bound::along_right;
        hs.push_back({along, {e, l ? lmax : rmax}});
        hs.push_back({along, {neg(e), l ? -lmin : -rmin}});
        // σ(p − q)·v ≤ 0 sliding left, ≥ 0 sliding right
        const int t = l ? s : -s;
        hs.push_back({Locus_bound::slip, {Vec2{-t * v.x, -t * v.y}, -t * pv}});
      }
      piece.bounded = bounded(hs);
      if (piece.bounded) {
        piece.polygon = hull(corners(hs));
      } else {
        std::vector<Vec2> poly = {g.box[0], {g.box[1].x, g.box[0].y}, g.box[1], {g.box[0].x, g.box[1].y}};
        for (const Locus_halfplane& h : hs) poly = clip(poly, h.h);
        piece.polygon = hull(poly);
      }
      if (piece.polygon.empty()) continue;
      any = true;
      if (!piece.bounded) {
        all_bounded = false;
        continue;
      }
      for (const Vec2& q : piece.polygon) H = std::max(H, Rational(s * cross(minus(p, q), n)));
    }
  }
  if (!any) {
    g.arm_why = !allowed[0] && !allowed[1] ? "the body translates (no rotation centre)" : "no rotation centre is possible";
  } else if (!all_bounded) {
    g.arm_why = "a piece of the locus is unbounded: the body may turn about centres arbitrarily far away (nearly "
                "translating), so no positive rate is certain";
  } else if (sgn(H) == 0) {
    g.arm_why = "every possible centre is on the pusher's normal line";
  } else {
    g.arm_hi = outward(sqrt_bracket(H * H / dot(n, n), 64).second, 6, true);
  }
  return g;
}

}  // namespace wrenchkit
