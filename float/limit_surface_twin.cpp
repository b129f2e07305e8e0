#include "float/limit_surface_twin.h"

#include "core/limit_surface_directions.h"

#include <cmath>
#include <queue>
#include <stdexcept>
#include <string>

namespace wrenchkit::fl {

namespace {

constexpr double kSqrt2Up = 1.4142135623730952;  // the double above √2

Bounded ex(double x) { return Bounded::exact(x); }

// v_i(q) = (v_x − ω y_i, v_y + ω x_i).
std::array<Bounded, 2> velocity(const Support_point_twin& p, const Bounded3& q) {
  return {q[0] - q[2] * p.y, q[1] + q[2] * p.x};
}

Bounded norm2(const std::array<Bounded, 2>& v) { return fl::sqrt(v[0] * v[0] + v[1] * v[1]); }

Bounded min(const Bounded& a, const Bounded& b) { return -max(-a, -b); }

}  // namespace

const char* motion_name(Motion_twin m) {
  switch (m) {
    case Motion_twin::sticks: return "sticks";
    case Motion_twin::slides: return "slides";
    case Motion_twin::undecided: return "undecided";
  }
  return "?";
}

Point2 center_of_friction(const std::vector<Support_point_twin>& s) {
  Bounded f, fx, fy;
  for (const Support_point_twin& p : s) {
    f = f + p.force;
    fx = fx + p.force * p.x;
    fy = fy + p.force * p.y;
  }
  return {fx / f, fy / f};
}

Bounded support_function(const std::vector<Support_point_twin>& s, const Bounded3& q) {
  Bounded h;
  for (const Support_point_twin& p : s) h = h + p.rho * norm2(velocity(p, q));
  return h;
}

Load_twin load_for_twist(const std::vector<Support_point_twin>& s, const Bounded3& q) {
  Load_twin l;
  l.load = {Bounded{}, Bounded{}, Bounded{}};
  for (std::size_t i = 0; i < s.size(); ++i) {
    const Support_point_twin& p = s[i];
    const auto v = velocity(p, q);
    const Sign moving = (v[0] * v[0] + v[1] * v[1]).sign();
    if (moving == Sign::uncertain) return l;
    if (moving == Sign::zero) {
      l.facet_points.push_back(i);
      continue;
    }
    const Bounded n = norm2(v);
    const Bounded ux = v[0] / n, uy = v[1] / n;  // v̂_i
    l.load[0] = l.load[0] + p.rho * ux;
    l.load[1] = l.load[1] + p.rho * uy;
    l.load[2] = l.load[2] + p.rho * (p.x * uy - p.y * ux);
  }
  l.decided = true;
  return l;
}

Directions_twin make_directions(int n) {
  // The exact engine's integers (core/limit_surface_directions.h): t = a/den gives
  // u = ((den² − a²), 2·a·den)/(den² + a²), integers below 2^53 (exact doubles), one Bounded quotient each.
  const Direction_parameters p = direction_parameters(n);
  const int half = n / 2, q = static_cast<int>(p.a.size());
  Directions_twin d;
  d.n = n;
  d.u.resize(n);
  const double den = static_cast<double>(p.den), den2 = den * den;
  for (int j = 0; j < q; ++j) {
    const double a = static_cast<double>(p.a[j]);
    const Bounded norm = ex(den2 + a * a);
    d.u[j] = {ex(den2 - a * a) / norm, ex(2 * a * den) / norm};
    d.u[half - 1 - j] = {-d.u[j].x, d.u[j].y};  // u(1/t): the reflection in the y-axis, exactly
  }
  if (p.middle) d.u[q] = {ex(0), ex(1)};  // φ = π/2: u = (0, 1)
  for (int j = 0; j < half; ++j) d.u[j + half] = {-d.u[j].x, -d.u[j].y};
  Bounded cmin = ex(2);
  for (int j = 0; j < n; ++j) {
    const Point2& a = d.u[j];
    const Point2& b = d.u[(j + 1) % n];
    if ((a.x * b.y - a.y * b.x).sign() != Sign::positive)
      throw std::logic_error("make_directions: directions not certified counter-clockwise");
    cmin = min(cmin, a.x * b.x + a.y * b.y);
  }
  d.lambda_sq = (ex(1) + cmin) / ex(2);
  return d;
}

Bounded polygonal_support(const std::vector<Support_point_twin>& s, const Directions_twin& d, bool outer,
                          const Bounded3& q) {
  std::vector<Point2> w = d.u;
  if (outer)  // tangent intersections (u_j + u_{j+1}) / (1 + u_j·u_{j+1})
    for (int j = 0; j < d.n; ++j) {
      const Point2& a = d.u[j];
      const Point2& b = d.u[(j + 1) % d.n];
      const Bounded c = ex(1) + a.x * b.x + a.y * b.y;
      w[j] = {(a.x + b.x) / c, (a.y + b.y) / c};
    }
  Bounded h;
  for (const Support_point_twin& p : s) {
    const auto v = velocity(p, q);
    Bounded best = w[0].x * v[0] + w[0].y * v[1];
    for (int j = 1; j < d.n; ++j) best = max(best, w[j].x * v[0] + w[j].y * v[1]);
    h = h + p.rho * best;
  }
  return h;
}

Motion_answer classify_load(const std::vector<Support_point_twin>& s, const Bounded3& p, std::size_t max_cells) {
  Motion_answer a;
  using M = Motion_twin;
  std::vector<Support_point_twin> pts;  // the points with ρ > 0
  for (const Support_point_twin& x : s) {
    const Sign r = x.rho.sign();
    if (r == Sign::uncertain || r == Sign::negative) return a;
    if (r == Sign::positive) pts.push_back(x);
  }
  // A load sticks when it is inside the limit surface (on it, it slides; proofs/notes/SL-1). With friction at
  // fewer than two distinct points LS is flat (a disc, or {0}) and has no interior: every load slides.
  if (pts.empty()) {
    a.motion = M::slides;
    return a;
  }
  bool apart = false, all_equal = true;
  for (std::size_t i = 1; i < pts.size() && !apart; ++i) {
    const Sign dx = (pts[i].x - pts[0].x).sign(), dy = (pts[i].y - pts[0].y).sign();
    apart = (dx != Sign::zero && dx != Sign::uncertain) || (dy != Sign::zero && dy != Sign::uncertain);
    all_equal &= dx == Sign::zero && dy == Sign::zero;
  }
  if (!apart && !all_equal) return a;
  if (!apart) {
    a.motion = M::slides;
    return a;
  }
  // The zero load is inside a three-dimensional LS: it sticks.
  if (p[0].sign() == Sign::zero && p[1].sign() == Sign::zero && p[2].sign() == Sign::zero) {
    a.motion = M::sticks;
    return a;
  }
  // Three-dimensional LS. Work about a double origin c near the points, scaled by a power of two R ≥
  // max |r_i − c|: the twists q' = (v_c, ωR) and the load p' = (f, (m − c × f)/R) give the same powers.
  double cx = 0, cy = 0, wsum = 0;
  for (const Support_point_twin& x : pts) {
    cx += x.rho.v * x.x.v;
    cy += x.rho.v * x.y.v;
    wsum += x.rho.v;
  }
  cx /= wsum;
  cy /= wsum;
  if (!std::isfinite(cx) || !std::isfinite(cy)) return a;
  double far = 0;
  for (const Support_point_twin& x : pts) far = std::fmax(far, std::hypot(x.x.v - cx, x.y.v - cy) + x.x.e + x.y.e);
  if (!(far > 0) || !std::isfinite(far)) return a;
  const double R = std::exp2(std::ceil(std::log2(far)) + 1);
  const Bounded bc_x = ex(cx), bc_y = ex(cy), bR = ex(R);
  std::vector<Support_point_twin> sp;
  Bounded lip;
  for (const Support_point_twin& x : pts) {
    Support_point_twin y = x;
    y.x = (x.x - bc_x) / bR;
    y.y = (x.y - bc_y) / bR;
    sp.push_back(y);
    lip = lip + x.rho * fl::sqrt(ex(1) + y.x * y.x + y.y * y.y);
  }
  const Bounded3 ps = {p[0], p[1], (p[2] - (bc_x * p[1] - bc_y * p[0])) / bR};
  const double L = upper(lip + fl::sqrt(ps[0] * ps[0] + ps[1] * ps[1] + ps[2] * ps[2]));
  if (!std::isfinite(L)) return a;
  const auto to_input_frame = [&](const Bounded3& q) {
    const double w = q[2].v / R;
    return std::array<double, 3>{q[0].v + w * cy, q[1].v - w * cx, w};
  };
  // Best-first search over cells of the cube's surface (positive homogeneity: every q ≠ 0 is a positive
  // multiple of a point of it). Cell: face axis, side, centre (s, t), half-width w.
  struct Cell {
    double slack;  // lower(f(centre)) − L·w·√2: > 0 ⇒ f > 0 on the whole cell
    int axis, side;
    double s, t, w;
  };
  const auto worse = [](const Cell& x, const Cell& y) { return x.slack > y.slack; };
  std::priority_queue<Cell, std::vector<Cell>, decltype(worse)> open(worse);
  const auto visit = [&](int axis, int side, double s0, double t0, double w) -> bool {
    Bounded3 q;
    q[axis] = ex(side);
    q[(axis + 1) % 3] = ex(s0);
    q[(axis + 2) % 3] = ex(t0);
    const Bounded f = support_function(sp, q) - (q[0] * ps[0] + q[1] * ps[1] + q[2] * ps[2]);
    ++a.cells;
    if (!(f.e < Bounded::kInf) || !std::isfinite(f.v)) {  // no bound here: the cell cannot be dropped
      a.motion = M::undecided;
      return true;
    }
    if (upper(f) <= 0) {  // h(q) ≤ q·p: p is not in the interior
      a.motion = M::slides;
      a.witness = to_input_frame(q);
      return true;
    }
    // Two lower bounds of f on the cell: Lipschitz, f(q) ≥ f(c) − L·|q − c|; and convexity, f(q) ≥ f(c) +
    // ⟨g, q − c⟩ for a subgradient g = load(c) − p (the load of c is ∂h(c), or the centre of its facet),
    // with |q − c|_∞ ≤ w in the face's two free coordinates.
    double slack = lower(f) - L * w * kSqrt2Up * (1 + 0x1p-50);
    const Load_twin g = load_for_twist(sp, q);
    if (g.decided) {
      double reach = 0;
      for (int k : {(axis + 1) % 3, (axis + 2) % 3}) {
        const Bounded gk = g.load[k] - ps[k];
        reach += std::fabs(gk.v) + gk.e;
      }
      const double tangent = lower(f) - reach * w * (1 + 0x1p-50);
      if (std::isfinite(tangent) && tangent > slack) slack = tangent;
    }
    if (!(slack > 0)) open.push({slack, axis, side, s0, t0, w});
    return false;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side : {1, -1})
      if (visit(axis, side, 0, 0, 1)) return a;
  while (!open.empty()) {
    if (a.cells + 4 > max_cells) return a;  // undecided: within the search's resolution of LS
    const Cell c = open.top();
    open.pop();
    const double h = c.w / 2;
    for (double ds : {-h, h})
      for (double dt : {-h, h})
        if (visit(c.axis, c.side, c.s + ds, c.t + dt, h)) return a;
  }
  a.motion = M::sticks;
  return a;
}

std::vector<Support_point_twin> bounded_support(const std::vector<Support_contact>& points) {
  std::vector<Support_point_twin> out;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Support_contact& c = points[i];
    if (!std::isfinite(c.x) || !std::isfinite(c.y))
      throw std::invalid_argument("support.points[" + std::to_string(i) + "].at: not finite");
    if (!(c.force >= 0) || !std::isfinite(c.force))
      throw std::invalid_argument("support.points[" + std::to_string(i) + "].force: must be finite and >= 0");
    if (!(c.mu >= 0) || !std::isfinite(c.mu))
      throw std::invalid_argument("support.points[" + std::to_string(i) + "].mu: must be finite and >= 0");
    out.push_back({ex(c.x), ex(c.y), ex(c.force), ex(c.mu) * ex(c.force)});
  }
  return out;
}

}  // namespace wrenchkit::fl
