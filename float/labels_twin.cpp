#include "float/labels_twin.h"

#include <cmath>

namespace wrenchkit::fl {

namespace {

Bounded3 cross(const Bounded3& a, const Bounded3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Bounded dot(const Bounded3& a, const Bounded3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Bounded3 J(const Bounded3& u) { return {-u[1], u[0], u[2]}; }
Bounded3 neg(const Bounded3& u) { return {-u[0], -u[1], -u[2]}; }

// The certified sign, or — for the naive variant only (benchmarks, stress tests) — the raw sign of the
// computed value, a guess.
Sign sign_of(const Bounded& b, bool naive) {
  if (!naive) return b.sign();
  return b.v > 0 ? Sign::positive : (b.v < 0 ? Sign::negative : Sign::zero);
}

// One item of the walk around a cone's boundary: a corner on the front sheet or a direction.
struct Item {
  bool vertex;
  Point2 p;
};

// Walks the extreme rays p_0 … p_{K−1} (counter-clockwise; `closed`: consecutive pairs wrap around,
// else an open chain) and returns the items in boundary order, rotated so that the run of corners
// comes first; false when a sign is uncertain.
bool walk(const std::vector<Bounded3>& p, bool closed, bool naive, std::vector<Item>& items) {
  const std::size_t K = p.size();
  std::vector<Sign> z(K);
  for (std::size_t j = 0; j < K; ++j)
    if ((z[j] = sign_of(p[j][2], naive)) == Sign::uncertain) return false;
  items.clear();
  for (std::size_t j = 0; j < K; ++j) {
    if (z[j] == Sign::positive) {
      const Bounded x = p[j][0] / p[j][2], y = p[j][1] / p[j][2];
      items.push_back({true, {x, y}});
    } else if (z[j] == Sign::zero) {
      items.push_back({false, {p[j][0], p[j][1]}});
    }
    if (!closed && j + 1 == K) break;
    const std::size_t k = (j + 1) % K;
    if (k == j) break;
    // An edge from Z > 0 to Z < 0 leaves the front sheet through infinity (and back the other way):
    // Z_a p_b − Z_b p_a has Z = 0 and is a positive combination.
    const bool exit = z[j] == Sign::positive && z[k] == Sign::negative;
    const bool entry = z[j] == Sign::negative && z[k] == Sign::positive;
    if (exit || entry) {
      const Bounded3& a = exit ? p[j] : p[k];  // the ray with Z > 0
      const Bounded3& b = exit ? p[k] : p[j];  // the ray with Z < 0
      items.push_back({false, {a[2] * b[0] - b[2] * a[0], a[2] * b[1] - b[2] * a[1]}});
    }
  }
  // Rotate a closed walk so that it starts at the first corner after a direction.
  if (closed && !items.empty()) {
    std::size_t start = 0;
    for (std::size_t i = 0; i < items.size(); ++i) {
      const Item& prev = items[(i + items.size() - 1) % items.size()];
      if (items[i].vertex && !prev.vertex) {
        start = i;
        break;
      }
    }
    std::vector<Item> r(items.begin() + static_cast<std::ptrdiff_t>(start), items.end());
    r.insert(r.end(), items.begin(), items.begin() + static_cast<std::ptrdiff_t>(start));
    items.swap(r);
  }
  return true;
}

Region2 region_of(const std::vector<Item>& items) {
  Region2 r;
  for (const Item& i : items) (i.vertex ? r.vertices : r.directions).push_back(i.p);
  const std::size_t nv = r.vertices.size(), nd = r.directions.size();
  using S = Region2::Shape;
  if (nv == 0) {
    r.directions.clear();  // directions alone are points at infinity, not part of the region
    r.shape = S::empty;
  } else if (nd == 0) {
    r.shape = nv == 1 ? S::point : (nv == 2 ? S::segment : S::polygon);
  } else {
    r.shape = nv == 1 ? (nd == 1 ? S::ray : S::wedge) : S::unbounded_polygon;
  }
  return r;
}

// pos(directions) as an arc, extremes counter-clockwise; false when the order is uncertain.
bool arc_of(const std::vector<Item>& items, bool naive, Arc2& out) {
  out = Arc2{};
  for (const Item& i : items)
    if (!i.vertex) out.extreme.push_back(i.p);
  if (out.extreme.empty()) return true;
  if (out.extreme.size() == 1) {
    out.shape = Arc2::Shape::ray;
    return true;
  }
  if (out.extreme.size() != 2) return false;  // a pointed cone meets Z = 0 in at most two extreme rays
  const Point2& a = out.extreme[0];
  const Point2& b = out.extreme[1];
  const Sign s = sign_of(a.x * b.y - a.y * b.x, naive);
  if (s == Sign::uncertain || s == Sign::zero) return false;
  if (s == Sign::negative) std::swap(out.extreme[0], out.extreme[1]);
  out.shape = Arc2::Shape::wedge;
  return true;
}

// Front and back sheets and infinity of the pointed cone pos(p) (p counter-clockwise).
bool slices(const std::vector<Bounded3>& p, bool closed, bool naive, Region2& front, Region2& back, Arc2& infinity) {
  std::vector<Item> items;
  if (!walk(p, closed, naive, items)) return false;
  front = region_of(items);
  if (!arc_of(items, naive, infinity)) return false;
  std::vector<Bounded3> q;  // −p, reversed: counter-clockwise again
  for (std::size_t j = p.size(); j-- > 0;) q.push_back(neg(p[j]));
  if (!walk(q, closed, naive, items)) return false;
  back = region_of(items);
  return true;
}

// Every constructed coordinate has a finite value and a finite bound (else the construction says nothing
// and the answer is reported uncertain, for the exact engine to give).
bool finite(const Point2& p) {
  return std::isfinite(p.x.v) && std::isfinite(p.y.v) && p.x.e < Bounded::kInf && p.y.e < Bounded::kInf;
}
bool finite(const Region2& r) {
  for (const Point2& p : r.vertices)
    if (!finite(p)) return false;
  for (const Point2& p : r.directions)
    if (!finite(p)) return false;
  return true;
}
bool finite(const Arc2& a) {
  for (const Point2& p : a.extreme)
    if (!finite(p)) return false;
  return true;
}

Region2 whole_plane() {
  Region2 r;
  r.shape = Region2::Shape::plane;
  return r;
}

}  // namespace

const char* shape_name(Region2::Shape s) {
  using S = Region2::Shape;
  switch (s) {
    case S::empty: return "empty";
    case S::point: return "point";
    case S::segment: return "segment";
    case S::ray: return "ray";
    case S::wedge: return "wedge";
    case S::polygon: return "polygon";
    case S::unbounded_polygon: return "unbounded polygon";
    case S::plane: return "plane";
  }
  return "?";
}

const char* status_name(Twin_status s) {
  switch (s) {
    case Twin_status::decided: return "decided";
    case Twin_status::uncertain: return "uncertain";
    case Twin_status::rank_deficient: return "rank < 3 (the float twin represents pointed dual cones only)";
    case Twin_status::not_pointed: return "W contains a line (the float twin represents pointed cones only)";
  }
  return "?";
}

namespace {

Labels_twin labels_of(const std::vector<Bounded3>& g, const Dual_cone& dc, bool naive) {
  Labels_twin l;
  l.rank = dc.rank;
  l.shape = dc.shape;
  if (!dc.decided) return l;
  if (dc.rank < 3) {
    l.status = Twin_status::rank_deficient;
    return l;
  }
  const std::vector<std::size_t>& e = dc.edges;
  bool closed = false;
  switch (dc.shape) {
    case Dual_shape::polygon:
      for (std::size_t j = 0; j < e.size(); ++j) l.rays.push_back(cross(g[e[j]], g[e[(j + 1) % e.size()]]));
      closed = true;
      break;
    case Dual_shape::arc:
      // (p, e, q, e') up to a rotation of the cycle, g_{e'} a negative multiple of g_e: of the four
      // products of consecutive edges, the first and the third are positive multiples of the two
      // rays g_p × g_e and g_e × g_q, whatever the rotation (the other two repeat them).
      l.rays = {cross(g[e[0]], g[e[1]]), cross(g[e[2]], g[e[3]])};
      break;
    case Dual_shape::ray:
      l.rays.push_back(cross(g[e[0]], g[e[1]]));
      break;
    case Dual_shape::zero:
    case Dual_shape::lineality:
      break;
  }
  std::vector<Bounded3> P;  // rotation centres P(t) = J t
  for (const Bounded3& t : l.rays) P.push_back(J(t));
  if (!slices(P, closed, naive, l.plus, l.minus, l.infinity)) return l;
  if (!naive && (!finite(l.plus) || !finite(l.minus) || !finite(l.infinity))) return l;
  l.status = Twin_status::decided;
  return l;
}

}  // namespace

Labels_twin moment_labels(const std::vector<Bounded3>& g, const Dual_cone& dc) { return labels_of(g, dc, false); }

Labels_twin moment_labels_naive(const std::vector<Bounded3>& g) {
  return labels_of(g, compute_dual_cone(Naive_kernel(g)), true);
}

Labels_twin moment_labels(const std::vector<Bounded3>& g) {
  return moment_labels(g, compute_dual_cone(Float_kernel(g)));
}

Labels_twin moment_labels(const std::vector<Point_contact>& contacts, Reading reading) {
  return moment_labels(generators(bounded_contacts(contacts), reading));
}

Dual_point_twin dual_point(const Bounded3& w) {
  const Bounded3 d = J(w);
  Dual_point_twin p;
  switch (d[2].sign()) {
    case Sign::positive:
    case Sign::negative:
      p.sheet = d[2].sign() == Sign::positive ? '+' : '-';
      p.at = {d[0] / d[2], d[1] / d[2]};
      break;
    case Sign::zero:
      p.sheet = 'i';
      p.at = {d[0], d[1]};
      break;
    case Sign::uncertain:
      p.sheet = '?';
      break;
  }
  return p;
}

Dual_twin force_dual(const std::vector<Bounded3>& g, const Dual_cone& dc) {
  Dual_twin d;
  if (!dc.decided) return d;
  if (dc.rank < 3) {
    d.status = Twin_status::rank_deficient;
    return d;
  }
  if (dc.shape == Dual_shape::zero) {
    d.covers_all = true;
    d.plus_sheet = d.minus_sheet = whole_plane();
    d.infinity.shape = Arc2::Shape::full;
    d.status = Twin_status::decided;
    return d;
  }
  if (dc.shape != Dual_shape::polygon) {
    d.status = Twin_status::not_pointed;
    return d;
  }
  // W* a polygon ⇒ W pointed, with the edge generators as its extreme rays in the same orientation.
  std::vector<Bounded3> D;
  for (std::size_t j : dc.edges) D.push_back(J(g[j]));
  if (!slices(D, true, false, d.plus_sheet, d.minus_sheet, d.infinity)) return d;
  if (!finite(d.plus_sheet) || !finite(d.minus_sheet) || !finite(d.infinity)) return d;
  d.status = Twin_status::decided;
  return d;
}

Truth in_cone(const Labels_twin& l, const Bounded3& w) {
  if (!l.decided()) return Truth::uncertain;
  bool uncertain = false;
  for (const Bounded3& t : l.rays) {
    const Sign s = dot(t, w).sign();
    if (s == Sign::negative) return Truth::no;
    uncertain |= s == Sign::uncertain;
  }
  return uncertain ? Truth::uncertain : Truth::yes;
}

char label_of(const std::vector<Bounded3>& g, const Bounded& cx, const Bounded& cy) {
  bool pos = false, neg = false, uncertain = false;
  for (const Bounded3& w : g) {
    // M_c(w) = m − c_x f_y + c_y f_x (theory.md §2.2).
    const Sign s = (w[2] - cx * w[1] + cy * w[0]).sign();
    pos |= s == Sign::positive;
    neg |= s == Sign::negative;
    uncertain |= s == Sign::uncertain;
  }
  if (pos && neg) return '0';
  if (uncertain) return '?';
  return pos ? '+' : (neg ? '-' : 'b');
}

Contact_motion contact_motion(const Bounded_contact& c, const Bounded3& t) {
  Contact_motion m;
  if (c.is_wrench) {
    m.power = (t[0] * c.fx + t[1] * c.fy + t[2] * c.m).sign();
    m.speed = Sign::zero;
    return m;
  }
  const Bounded vx = t[0] - t[2] * c.ay, vy = t[1] + t[2] * c.ax;  // v(p)
  m.power = (vx * c.nx + vy * c.ny).sign();
  m.speed = (vx * vx + vy * vy).sign();
  return m;
}

}  // namespace wrenchkit::fl
