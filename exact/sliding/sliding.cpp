// Planar sliding quantities [LS-4]; derivation in proofs/notes/LS-3-queries.md.
#include "exact/sliding/sliding.h"

#include "exact/sliding/precise_motion.h"
#include "exact/sliding/strategies.h"

#include <cmath>
#include <stdexcept>

namespace wrenchkit {

std::pair<Rational, Rational> sqrt_bracket(const Rational& s, int bits) {
  if (s < 0) throw std::invalid_argument("sqrt_bracket: negative argument");
  if (s == 0) return {Rational(0), Rational(0)};
  const Integer& p = s.get_num();
  const Integer& q = s.get_den();
  // √(p/q) = √(p q)/q; scale by 2^B so the floor of the integer root is accurate to 2^-B/q.
  const unsigned long B = static_cast<unsigned long>(bits) + mpz_sizeinbase(q.get_mpz_t(), 2);
  Integer x = p * q, r;
  mpz_mul_2exp(x.get_mpz_t(), x.get_mpz_t(), 2 * B);
  mpz_sqrt(r.get_mpz_t(), x.get_mpz_t());
  Integer den = q;
  mpz_mul_2exp(den.get_mpz_t(), den.get_mpz_t(), B);
  Rational lo(r, den), hi(r + (r * r == x ? 0 : 1), den);
  lo.canonicalize();
  hi.canonicalize();
  return {lo, hi};
}

Twist_class classify_twist(const Ls_support& s, const Vec3q& q) {
  Twist_class c;
  if (s.points.empty()) {
    c.text = "the limit surface is the single point 0 (no point has mu*force > 0)";
    return c;
  }
  if (q[2] != 0) {
    const Rational cx = -q[1] / q[2], cy = q[0] / q[2];
    for (std::size_t i = 0; i < s.points.size(); ++i)
      if (s.points[i].at.x == cx && s.points[i].at.y == cy) {
        c.kind = Twist_kind::facet;
        c.support_point = static_cast<int>(i);
        c.text = std::string("rotation (") + (q[2] > 0 ? "counter-clockwise" : "clockwise") +
                 ") about the support point (" + to_string(cx) + ", " + to_string(cy) +
                 "): the load is a FACET of LS, that point's friction disc translated (theory.md §11.4)";
        return c;
      }
    if (s.collinear) {
      const Vec2& a = s.points[0].at;
      const Vec2& b = s.points[1].at;
      if ((b.x - a.x) * (cy - a.y) - (b.y - a.y) * (cx - a.x) == 0) {
        c.kind = Twist_kind::vertex;
        c.text = "the rotation centre lies on the line of the collinear support, between or beyond its points: "
                 "a non-smooth point of LS (every centre on that arc of the line gives the same load)";
        return c;
      }
    }
    c.text = "rotation about (" + to_string(cx) + ", " + to_string(cy) + "), not a support point: one load";
    return c;
  }
  if (s.collinear) {
    const Vec2& a = s.points[0].at;
    const Vec2& b = s.points[1].at;
    if (q[0] * (b.x - a.x) + q[1] * (b.y - a.y) == 0) {
      c.kind = Twist_kind::vertex;
      c.text = "a translation perpendicular to the line of the collinear support (rotation centre at infinity "
               "on that line): a non-smooth point of LS";
      return c;
    }
  }
  c.text = "a translation: the load is the force mu*f0 along v through the friction centroid";
  return c;
}

Sliding_answer compute_sliding(const Polygonal_ls& model, const std::optional<Vec3q>& q) {
  const Ls_support& s = model.support();
  Sliding_answer a;
  a.center_of_friction = {s.weighted_force_sum.x / s.total_force, s.weighted_force_sum.y / s.total_force};
  Vec2 rho_r;
  for (const Ls_point& p : s.points) {
    a.mu_f0 += p.rho;
    rho_r.x += p.rho * p.at.x;
    rho_r.y += p.rho * p.at.y;
  }
  a.friction_centroid = a.mu_f0 > 0 ? Vec2{rho_r.x / a.mu_f0, rho_r.y / a.mu_f0} : a.center_of_friction;
  if (!q) return a;
  const Vec3q& t = *q;
  if (t[0] == 0 && t[1] == 0 && t[2] == 0) throw std::invalid_argument("compute_sliding: zero twist");
  a.has_twist = true;
  a.twist = t;
  a.translation = t[2] == 0;
  a.cls = classify_twist(s, t);
  if (a.translation) {
    const Vec2& c = a.friction_centroid;
    a.load_direction = {t[0], t[1], c.x * t[1] - c.y * t[0]};
    a.speed_squared = t[0] * t[0] + t[1] * t[1];
    const auto [lo, hi] = sqrt_bracket(a.speed_squared);
    if (lo == hi) a.load = Vec3q{a.mu_f0 / lo * t[0], a.mu_f0 / lo * t[1], a.mu_f0 / lo * a.load_direction[2]};
  } else {
    a.rotation_center = {-t[1] / t[2], t[0] / t[2]};
  }
  a.h_inner = model.support_value(Side::inner, t);
  a.h_outer = model.support_value(Side::outer, t);
  a.inner_face = model.face(Side::inner, t);
  a.outer_face = model.face(Side::outer, t);
  for (int c = 0; c < 3; ++c) a.load_lo[c] = a.load_hi[c] = 0;
  // The facet's own point (v = 0): its disc, reported separately (the box holds the facet's centre).
  for (const Ls_point& p : s.points) add_point_bracket(p.at, p.rho, t, 80, a.h_lo, a.h_hi, a.load_lo, a.load_hi, false);
  return a;
}

void add_point_bracket(const Vec2& at, const Rational& rho, const Vec3q& q, int bits, Rational& h_lo, Rational& h_hi,
                       Vec3q& box_lo, Vec3q& box_hi, bool facet_box) {
  if (rho == 0) return;
  const Vec2 v = velocity(q, at);
  const Rational& vx = v.x;
  const Rational& vy = v.y;
  const Rational s2 = dot(v, v);
  if (s2 == 0) {
    if (!facet_box) return;
    // g = ρ u, |u| ≤ 1: each force component within ±ρ, the moment x g_y − y g_x within ±ρ(|x| + |y|).
    const Rational m = rho * (abs(at.x) + abs(at.y));
    box_lo[0] -= rho, box_hi[0] += rho, box_lo[1] -= rho, box_hi[1] += rho, box_lo[2] -= m, box_hi[2] += m;
    return;
  }
  const auto [lo, hi] = sqrt_bracket(s2, bits);
  h_lo += rho * lo;
  h_hi += rho * hi;
  const Vec3q comp = {rho * vx, rho * vy, rho * (at.x * vy - at.y * vx)};
  for (int c = 0; c < 3; ++c) {
    if (comp[c] >= 0) {
      box_lo[c] += comp[c] / hi;
      box_hi[c] += comp[c] / lo;
    } else {
      box_lo[c] += comp[c] / lo;
      box_hi[c] += comp[c] / hi;
    }
  }
}

Plane_minimum minimise_on_load_plane(const Vec3q& p, const std::function<double(const double*)>& h, const Vec3q* start,
                                     double stop_below) {
  Plane_minimum out;
  const double pd[3] = {p[0].get_d(), p[1].get_d(), p[2].get_d()};
  const double pn = pd[0] * pd[0] + pd[1] * pd[1] + pd[2] * pd[2];
  if (!(pn > 0) || !std::isfinite(pn)) return out;
  // An orthonormal basis (e1, e2) of p⊥ and q0 = p/|p|² (q0·p = 1).
  const double q0[3] = {pd[0] / pn, pd[1] / pn, pd[2] / pn};
  double e1[3];
  {
    const int a = std::fabs(pd[0]) <= std::fabs(pd[1]) && std::fabs(pd[0]) <= std::fabs(pd[2]) ? 0
                  : std::fabs(pd[1]) <= std::fabs(pd[2])                                      ? 1
                                                                                              : 2;
    double t[3] = {0, 0, 0};
    t[a] = 1;
    const double d = t[0] * pd[0] + t[1] * pd[1] + t[2] * pd[2];
    for (int c = 0; c < 3; ++c) e1[c] = t[c] - d * pd[c] / pn;
    const double n = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
    for (double& c : e1) c /= n;
  }
  const double sp = std::sqrt(pn);
  const double e2[3] = {(pd[1] * e1[2] - pd[2] * e1[1]) / sp, (pd[2] * e1[0] - pd[0] * e1[2]) / sp,
                        (pd[0] * e1[1] - pd[1] * e1[0]) / sp};
  const auto twist = [&](double a, double b, double* q) {
    for (int c = 0; c < 3; ++c) q[c] = q0[c] + a * e1[c] + b * e2[c];
  };
  const auto at = [&](double a, double b) {
    double q[3];
    twist(a, b, q);
    return h(q);
  };
  double a = 0, b = 0;
  if (start) {  // the start twist scaled onto the plane, when it points along p
    const double sq[3] = {(*start)[0].get_d(), (*start)[1].get_d(), (*start)[2].get_d()};
    const double d = sq[0] * pd[0] + sq[1] * pd[1] + sq[2] * pd[2];
    if (d > 0 && std::isfinite(d)) {
      a = (sq[0] * e1[0] + sq[1] * e1[1] + sq[2] * e1[2]) / d;
      b = (sq[0] * e2[0] + sq[1] * e2[1] + sq[2] * e2[2]) / d;
    }
  }
  double best = at(a, b), step = std::max(1.0, std::hypot(a, b)) / std::sqrt(pn), turn = 0;
  if (!std::isfinite(best)) return out;
  for (int it = 0; it < 4000 && best >= stop_below && step > 1e-13 / std::sqrt(pn); ++it) {
    bool moved = false;
    for (int d = 0; d < 8 && !moved; ++d) {
      const double angle = turn + d * 0.7853981633974483;
      const double na = a + step * std::cos(angle), nb = b + step * std::sin(angle), v = at(na, nb);
      if (v < best) a = na, b = nb, best = v, moved = true;
    }
    if (!moved) step /= 2, turn += 0.39269908169744964 * 0.61803398875;
  }
  out.found = true;
  out.h = best;
  twist(a, b, out.q.data());
  return out;
}

std::vector<fl::Support_point_twin> twin_support(const Ls_support& s) {
  std::vector<fl::Support_point_twin> out;
  out.reserve(s.points.size());
  for (const Ls_point& p : s.points)
    out.push_back({to_bounded(p.at.x), to_bounded(p.at.y), to_bounded(p.force), to_bounded(p.rho)});
  return out;
}

namespace {

// The float twin's certified search on the true surface [FL-7]; undecided when it cannot tell within `cells`.
// Hybrid gives it a tenth of its budget first: closer loads are decided in milliseconds by SL-6's Newton, and
// only what Newton cannot settle (a load near a facet, where h has a kink) gets the search's full budget.
constexpr std::size_t kSearchCells = 200000, kHybridFirstCells = 20000;
Points_verdict search(const Ls_support& support, const Vec3q& p, std::size_t cells = kSearchCells) {
  Points_verdict d;
  const fl::Motion_answer f =
      fl::classify_load(twin_support(support), {to_bounded(p[0]), to_bounded(p[1]), to_bounded(p[2])}, cells);
  d.cells = f.cells;
  if (f.motion != fl::Motion_twin::undecided) {
    d.motion = f.motion == fl::Motion_twin::sticks ? Motion::sticks : Motion::slides;
    d.decided_by = Decided_by::float_search;
    d.witness = f.witness;
  }
  return d;
}

// [SL-6] Both abstained (a load within their resolution of the surface): Newton in multiple precision proposes,
// exact rationals decide.
// Then, if Newton too abstains, the search with its full budget.
void precise_fallback(const Ls_support& support, const Vec3q& p, Points_verdict& d) {
  if (d.motion != Motion::undecided) return;
  std::vector<Rho_point> pts;
  pts.reserve(support.points.size());
  for (const Ls_point& q : support.points) pts.push_back({q.at, q.rho});
  const Precise_motion m = precise_motion(pts, p);
  if (m.motion == Motion::undecided) {
    const std::size_t spent = d.cells;
    d = search(support, p);
    d.cells += spent;
    d.proposal = m.proposal;
    return;
  }
  d.motion = m.motion;
  d.decided_by = Decided_by::newton;
  if (m.motion == Motion::slides) d.exact_witness = m.twist;
}

}  // namespace

Points_verdict points_verdict(const Polygonal_ls& model, const Vec3q& p, Mode mode, const Ls_polytope* inner,
                              const Ls_polytope* outer) {
  Points_verdict d;
  if (model.dimension() < 3) {  // a flat limit surface has no interior: every load slides (SL-1)
    d.motion = Motion::slides;
    d.decided_by = Decided_by::flat;
    return d;
  }
  if (mode != Mode::exact) {
    d = search(model.support(), p, mode == Mode::hybrid ? kHybridFirstCells : kSearchCells);
    if (d.motion != Motion::undecided || mode == Mode::float_only) return d;
  }
  if ((inner && outer) || model.candidate_count() <= kMaxCandidates) {  // else too large to build
    std::optional<Ls_polytope> built_in, built_out;
    if (!inner) inner = &built_in.emplace(model.build(Side::inner));
    if (!outer) outer = &built_out.emplace(model.build(Side::outer));
    d.motion = classify_load(model.gauge(*inner, Side::inner, p), model.gauge(*outer, Side::outer, p));
    if (d.motion != Motion::undecided) d.decided_by = Decided_by::polygons;
  }
  if (mode == Mode::hybrid) precise_fallback(model.support(), p, d);
  return d;
}

Points_verdict points_verdict(const Ls_support& support, const Vec3q& p, Mode mode, int sides) {
  if (support.points.size() < 2) return points_verdict(Polygonal_ls(support, make_directions(sides)), p, mode);
  std::size_t spent = 0;
  if (mode != Mode::exact) {
    const Points_verdict d = search(support, p, mode == Mode::hybrid ? kHybridFirstCells : kSearchCells);
    if (d.motion != Motion::undecided || mode == Mode::float_only) return d;
    spent = d.cells;
  }
  Points_verdict d = points_verdict(Polygonal_ls(support, make_directions(sides)), p, Mode::exact);
  d.cells = spent;
  if (mode == Mode::hybrid) precise_fallback(support, p, d);
  return d;
}

}  // namespace wrenchkit
