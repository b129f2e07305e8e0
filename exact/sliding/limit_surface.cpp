// Polygonal limit surfaces [LS-1]–[LS-3]; derivations in proofs/notes/LS-1-directions.md and
// proofs/notes/LS-2-polytopes.md. All arithmetic is exact (GMP integers and rationals); doubles are
// used only to CHOOSE the rational parameters t_j of the directions.
#include "exact/sliding/limit_surface.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <unordered_map>
#include <utility>

namespace wrenchkit {
namespace {

using Vec2z = std::array<Integer, 2>;

Integer lcm_of(const Integer& a, const Integer& b) {
  Integer r;
  mpz_lcm(r.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
  return r;
}


Vec3z neg(const Vec3z& v) { return {-v[0], -v[1], -v[2]}; }

Vec3z cross3(const Vec3z& a, const Vec3z& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

int lex_cmp(const Vec3z& a, const Vec3z& b) {
  for (int i = 0; i < 3; ++i) {
    const int c = mpz_cmp(a[i].get_mpz_t(), b[i].get_mpz_t());
    if (c) return c < 0 ? -1 : 1;
  }
  return 0;
}

// Sign of a·(b × c) with scratch integers (the hot predicate of the face walk).
int triple_sign(const Vec3z& a, const Vec3z& b, const Vec3z& c) {
  thread_local Integer s, t;
  mpz_mul(s.get_mpz_t(), b[1].get_mpz_t(), c[2].get_mpz_t());
  mpz_submul(s.get_mpz_t(), b[2].get_mpz_t(), c[1].get_mpz_t());
  mpz_mul(t.get_mpz_t(), s.get_mpz_t(), a[0].get_mpz_t());
  mpz_mul(s.get_mpz_t(), b[2].get_mpz_t(), c[0].get_mpz_t());
  mpz_submul(s.get_mpz_t(), b[0].get_mpz_t(), c[2].get_mpz_t());
  mpz_addmul(t.get_mpz_t(), s.get_mpz_t(), a[1].get_mpz_t());
  mpz_mul(s.get_mpz_t(), b[0].get_mpz_t(), c[1].get_mpz_t());
  mpz_submul(s.get_mpz_t(), b[1].get_mpz_t(), c[0].get_mpz_t());
  mpz_addmul(t.get_mpz_t(), s.get_mpz_t(), a[2].get_mpz_t());
  return mpz_sgn(t.get_mpz_t());
}

int dot_sign(const Vec3z& a, const Vec3z& b) {
  thread_local Integer s;
  mpz_mul(s.get_mpz_t(), a[0].get_mpz_t(), b[0].get_mpz_t());
  mpz_addmul(s.get_mpz_t(), a[1].get_mpz_t(), b[1].get_mpz_t());
  mpz_addmul(s.get_mpz_t(), a[2].get_mpz_t(), b[2].get_mpz_t());
  return mpz_sgn(s.get_mpz_t());
}

int cross2_sign(const Vec2z& a, const Vec2z& b) {
  thread_local Integer s;
  mpz_mul(s.get_mpz_t(), a[0].get_mpz_t(), b[1].get_mpz_t());
  mpz_submul(s.get_mpz_t(), a[1].get_mpz_t(), b[0].get_mpz_t());
  return mpz_sgn(s.get_mpz_t());
}

int dot2_sign(const Vec2z& a, const Vec2z& b) {
  thread_local Integer s;
  mpz_mul(s.get_mpz_t(), a[0].get_mpz_t(), b[0].get_mpz_t());
  mpz_addmul(s.get_mpz_t(), a[1].get_mpz_t(), b[1].get_mpz_t());
  return mpz_sgn(s.get_mpz_t());
}

Vec2 unit_of(const Rational& t) {  // u(t) of theory.md §12.1
  const Rational d = 1 + t * t;
  return {(1 - t * t) / d, 2 * t / d};
}

}  // namespace

Vec3q to_rational(const Vec3z& v) { return {Rational(v[0]), Rational(v[1]), Rational(v[2])}; }

const char* side_name(Side s) { return s == Side::inner ? "inner" : "outer"; }

const char* motion_name(Motion m) {
  switch (m) {
    case Motion::sticks: return "sticks";
    case Motion::impending: return "impending";
    case Motion::slides: return "slides";
    case Motion::depends: return "depends";
    case Motion::undecided: return "undecided";
  }
  return "?";
}

Motion classify_load(const std::optional<Rational>& gi, const std::optional<Rational>& go) {
  if (gi && *gi < 1) return Motion::sticks;
  if (!go || *go >= 1) return Motion::slides;
  return Motion::undecided;
}

// ---------------------------------------------------------------------------------------------
// Support

Ls_support merge_support(const Support& s, const std::vector<Rational>* distribution) {
  if (distribution && distribution->size() != s.points.size())
    throw std::invalid_argument("merge_support: a distribution of another size");
  Ls_support r;
  std::map<std::pair<Rational, Rational>, std::size_t> where;
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const Support_point& p = s.points[i];
    if (!distribution && !p.force) throw std::invalid_argument("merge_support: a force is unknown; give a distribution");
    const Rational& force = distribution ? (*distribution)[i] : *p.force;
    const Rational mu = s.mu_of(p);
    r.total_force += force;
    r.weighted_force_sum.x += force * p.at.x;
    r.weighted_force_sum.y += force * p.at.y;
    const Rational rho = mu * force;
    if (rho == 0) continue;
    const auto key = std::make_pair(p.at.x, p.at.y);
    const auto it = where.find(key);
    if (it != where.end()) {
      r.points[it->second].rho += rho;
      r.points[it->second].force += force;
    } else {
      where.emplace(key, r.points.size());
      r.points.push_back({p.at, rho, force});
    }
  }
  if (r.points.size() >= 2) {
    r.collinear = true;
    const Vec2& a = r.points[0].at;
    const Vec2& b = r.points[1].at;
    for (std::size_t i = 2; i < r.points.size() && r.collinear; ++i) {
      const Vec2& c = r.points[i].at;
      r.collinear = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x) == 0;
    }
  }
  return r;
}

// ---------------------------------------------------------------------------------------------
// [LS-1] Directions

Directions make_directions(int n) {
  const Direction_parameters p = direction_parameters(n);  // the rule shared with the twin
  const int half = n / 2, q = static_cast<int>(p.a.size());
  Directions d;
  d.n = n;
  d.t.assign(half, Rational(0));
  std::vector<Vec2> up(half);
  for (int j = 0; j < q; ++j) {
    Rational t(static_cast<long>(p.a[j]), static_cast<long>(p.den));
    t.canonicalize();
    d.t[j] = t;
    up[j] = unit_of(t);
    up[half - 1 - j] = {-up[j].x, up[j].y};  // reflection in the y-axis: u(1/t)
    d.t[half - 1 - j] = 1 / t;
  }
  if (p.middle) {  // φ = π/2 exactly: t = 1
    d.t[q] = 1;
    up[q] = {Rational(0), Rational(1)};
  }
  d.u.resize(n);
  for (int j = 0; j < half; ++j) {
    d.u[j] = up[j];
    d.u[j + half] = {-up[j].x, -up[j].y};
  }
  Rational cmin = 2;
  for (int j = 0; j < n; ++j) {
    const Vec2& a = d.u[j];
    const Vec2& b = d.u[(j + 1) % n];
    if (a.x * b.y - a.y * b.x <= 0) throw std::logic_error("make_directions: directions not counter-clockwise");
    const Rational c = a.x * b.x + a.y * b.y;
    if (c < cmin) cmin = c;
  }
  d.lambda_sq = (1 + cmin) / 2;
  return d;
}

int smallest_sides(const Rational& eps, int max_sides, int* built) {
  const Rational target = 1 / ((1 + eps) * (1 + eps));
  const double tdouble = target.get_d();
  const double pi = 3.14159265358979323846;
  if (built) *built = 0;
  for (int n = 4; n <= max_sides; n += 2) {
    // Any n directions leave a gap ≥ 2π/n, so λ ≤ cos(π/n): skip sets that cannot qualify. The
    // margin makes this float test conservative (it only skips sets far from qualifying).
    const double c = std::cos(pi / n);
    if (c * c < tdouble * (1 - 1e-9)) continue;
    const Directions d = make_directions(n);
    if (built) ++*built;
    if (d.lambda_sq >= target) return n;
  }
  return 0;
}

// ---------------------------------------------------------------------------------------------
// The per-point tables

Polygonal_ls::Polygonal_ls(Ls_support s, Directions d) : s_(std::move(s)), d_(std::move(d)) {
  for (const Ls_point& p : s_.points) {
    const Integer D = lcm_of(p.at.x.get_den(), p.at.y.get_den());
    den_.push_back(D);
    num_.push_back({p.at.x.get_num() * (D / p.at.x.get_den()), p.at.y.get_num() * (D / p.at.y.get_den())});
  }
}

// The inner and outer polygons' tables, built on first use: a query answered on the true surface (or with
// the support values alone) never pays for them.
//
// Their memory, bounded before they are built: per point i and side, n vertices of 3 integers over the common
// denominator L, which divides the product of the lcms of the unit polygons' denominators, of the ρ_i's, of the
// x_i's and of the y_i's (ρ_i A_i(P_j) = (ρ P_x, ρ P_y, x ρ P_y − y ρ P_x)), so a vertex integer has at most
// digits(L) + digits(numerators of ρ_i, r_i) + 2 digits (0.42 byte each); n edge directions; about 650 bytes
// of fixed cost per vertex and side (measured: 2 048 integer points at N = 128, 339 MB resident in all).
std::uint64_t Polygonal_ls::table_bytes() const {
  const auto digits = [](const Integer& z) { return static_cast<std::uint64_t>(mpz_sizeinbase(z.get_mpz_t(), 10)); };
  const auto join = [](Integer& l, const Integer& d) {
    if (mpz_divisible_p(l.get_mpz_t(), d.get_mpz_t()) == 0) l = lcm_of(l, d);
  };
  Integer p = 1, rho = 1, x = 1, y = 1;
  const int n = d_.n;
  for (int j = 0; j < n; ++j) {
    const Vec2& a = d_.u[j];
    const Vec2& b = d_.u[(j + 1) % n];
    const Rational k = 1 + a.x * b.x + a.y * b.y;
    for (const Rational& c : {a.x, a.y, Rational((a.x + b.x) / k), Rational((a.y + b.y) / k)}) join(p, c.get_den());
  }
  for (const Ls_point& pt : s_.points) {
    join(rho, pt.rho.get_den());
    join(x, pt.at.x.get_den());
    join(y, pt.at.y.get_den());
  }
  const std::uint64_t L = digits(p) + digits(rho) + digits(x) + digits(y);
  std::uint64_t bytes = 0;
  for (const Ls_point& pt : s_.points) {
    const std::uint64_t d = L + digits(pt.rho.get_num()) + digits(pt.at.x.get_num()) + digits(pt.at.y.get_num()) + 2;
    bytes += static_cast<std::uint64_t>(n) * 2 * (650 + 3 * (d * 5 / 12 + 8));
  }
  return bytes;
}

std::string Polygonal_ls::tables_problem() const {
  const std::uint64_t bytes = table_bytes();
  if (bytes <= kMaxTableBytes) return std::string();
  return "sides " + std::to_string(d_.n) + " with " + std::to_string(s_.points.size()) +
         " distinct support points needs polygons of " + std::to_string(s_.points.size() * std::uint64_t(d_.n)) +
         " vertices taking up to " + std::to_string(bytes >> 20) + " MiB, more than the limit of " +
         std::to_string(kMaxTableBytes >> 20) + " MiB; use fewer sides";
}

void Polygonal_ls::build_tables() const {
  if (tables_built_) return;
  if (const std::string why = tables_problem(); !why.empty()) throw std::length_error("limit surface: " + why);
  tables_built_ = true;
  const int n = d_.n;
  for (Side side : {Side::inner, Side::outer}) {
    Side_tab& t = side == Side::inner ? in_ : out_;
    t.p.resize(n);
    t.nrm.resize(n);
    for (int j = 0; j < n; ++j) {
      const Vec2& a = d_.u[j];
      const Vec2& b = d_.u[(j + 1) % n];
      if (side == Side::inner) {
        t.p[j] = a;
        t.nrm[j] = primitive(a.x + b.x, a.y + b.y);  // ≠ 0: the gap is < π
      } else {
        const Rational k = 1 + a.x * b.x + a.y * b.y;
        t.p[j] = {(a.x + b.x) / k, (a.y + b.y) / k};
        t.nrm[j] = primitive(b.x, b.y);
      }
    }
    // Rational vertices ρ_i A_i(P[j]), then one common denominator L.
    std::vector<std::vector<Vec3q>> vq(s_.points.size(), std::vector<Vec3q>(n));
    Integer L = 1;
    for (std::size_t i = 0; i < s_.points.size(); ++i) {
      const Ls_point& pt = s_.points[i];
      for (int j = 0; j < n; ++j) {
        const Rational fx = pt.rho * t.p[j].x, fy = pt.rho * t.p[j].y;
        vq[i][j] = {fx, fy, pt.at.x * fy - pt.at.y * fx};
        for (const Rational& c : vq[i][j])
          if (mpz_divisible_p(L.get_mpz_t(), c.get_den_mpz_t()) == 0) L = lcm_of(L, c.get_den());
      }
    }
    t.L = L;
    t.pts.resize(s_.points.size());
    for (std::size_t i = 0; i < s_.points.size(); ++i) {
      Point_tab& pt = t.pts[i];
      pt.vert.resize(n);
      pt.edir.resize(n);
      for (int j = 0; j < n; ++j) {
        for (int c = 0; c < 3; ++c) pt.vert[j][c] = vq[i][j][c].get_num() * (L / vq[i][j][c].get_den());
        // Edge j runs P[j] → P[j+1], direction rot90(nrm[j]) = (−n_y, n_x); A_i of it, times D_i.
        const Integer dx = -t.nrm[j][1], dy = t.nrm[j][0];
        pt.edir[j] = primitive(Vec3z{dx * den_[i], dy * den_[i], num_[i][0] * dy - num_[i][1] * dx});
      }
    }
  }
}

int Polygonal_ls::dimension() const {
  return s_.points.empty() ? 0 : (s_.points.size() == 1 ? 2 : 3);
}

std::uint64_t Polygonal_ls::candidate_count() const {
  const std::uint64_t k = s_.points.size(), n = static_cast<std::uint64_t>(d_.n);
  return 2 * k + (k * (k - 1) / 2) * 2 * (n / 2) * (n / 2);
}

// For each point i, the face of its polygon in direction v_i(q) = A_iᵀ q: kind 0 vertex idx,
// kind 1 edge idx (P[idx] → P[idx+1]), kind 2 the whole polygon (v_i = 0). Binary search on the
// CCW-sorted edge normals: vertex m maximizes iff v lies strictly between nrm[m−1] and nrm[m].
void Polygonal_ls::point_faces(const Side_tab& t, const Vec3z& q, std::vector<int>& kind,
                               std::vector<int>& idx) const {
  const int n = d_.n, half = n / 2;
  const std::size_t k = s_.points.size();
  kind.assign(k, 0);
  idx.assign(k, 0);
  Vec2z v;
  for (std::size_t i = 0; i < k; ++i) {
    // D_i v_i(q) = (D_i q_x − q_w Y_i, D_i q_y + q_w X_i)
    v[0] = den_[i] * q[0] - q[2] * num_[i][1];
    v[1] = den_[i] * q[1] + q[2] * num_[i][0];
    if (v[0] == 0 && v[1] == 0) {
      kind[i] = 2;
      continue;
    }
    const int c0 = cross2_sign(t.nrm[0], v);
    const int hv = (c0 > 0 || (c0 == 0 && dot2_sign(t.nrm[0], v) > 0)) ? 0 : 1;
    // lower_bound: first m with nrm[m] not strictly before v in the angular order from nrm[0].
    int lo = 0, hi = n;
    while (lo < hi) {
      const int m = (lo + hi) / 2;
      const int hm = m < half ? 0 : 1;
      const bool before = hm != hv ? hm < hv : cross2_sign(t.nrm[m], v) > 0;
      if (before) lo = m + 1;
      else hi = m;
    }
    if (lo < n && (lo < half ? 0 : 1) == hv && cross2_sign(t.nrm[lo], v) == 0) {
      kind[i] = 1;
      idx[i] = lo;
    } else {
      kind[i] = 0;
      idx[i] = lo % n;
    }
  }
}

std::vector<std::vector<std::uint16_t>> Polygonal_ls::face_tuples(const Side_tab& t, const Vec3z& q, int* dim,
                                                                   std::vector<int>* kinds_out) const {
  const int n = d_.n, half = n / 2;
  const std::size_t k = s_.points.size();
  std::vector<int> kind, idx;
  point_faces(t, q, kind, idx);
  if (kinds_out) *kinds_out = kind;
  struct Item {
    int pt, from, to;
    const Vec3z* dir;
    int half = 0;
  };
  std::vector<Item> items;
  std::vector<std::uint16_t> cur(k, 0);
  for (std::size_t i = 0; i < k; ++i) {
    const auto& ed = t.pts[i].edir;
    const int pi = static_cast<int>(i);
    if (kind[i] == 0) {
      cur[i] = static_cast<std::uint16_t>(idx[i]);
    } else if (kind[i] == 1) {
      const int m = idx[i];
      items.push_back({pi, m, (m + 1) % n, &ed[m]});
      items.push_back({pi, (m + 1) % n, m, &ed[(m + half) % n]});
    } else {
      // The polygon's own orientation is CCW about ν_i = (y_i, −x_i, 1) ∝ (Y_i, −X_i, D_i).
      const Vec3z nu = {num_[i][1], -num_[i][0], den_[i]};
      const bool ccw = dot_sign(q, nu) > 0;
      for (int m = 0; m < n; ++m) {
        if (ccw) items.push_back({pi, m, (m + 1) % n, &ed[m]});
        else items.push_back({pi, (m + 1) % n, m, &ed[(m + half) % n]});
      }
    }
  }
  if (items.empty()) {
    *dim = 0;
    return {cur};
  }
  const Vec3z& d0 = *items[0].dir;
  const Vec3z qd0 = cross3(q, d0);  // a·(q × d0)... half by the sign of q·(d0 × a) = a·(q × d0)
  for (Item& it : items) {
    const int s = dot_sign(*it.dir, qd0);
    it.half = (s > 0 || (s == 0 && dot_sign(d0, *it.dir) > 0)) ? 0 : 1;
  }
  std::sort(items.begin(), items.end(), [&](const Item& a, const Item& b) {
    if (a.half != b.half) return a.half < b.half;
    return triple_sign(q, *a.dir, *b.dir) > 0;
  });
  std::vector<char> seen(k, 0);
  for (const Item& it : items)
    if (!seen[it.pt]) {
      seen[it.pt] = 1;
      cur[it.pt] = static_cast<std::uint16_t>(it.from);
    }
  std::vector<std::vector<std::uint16_t>> cycle;
  cycle.push_back(cur);
  std::size_t groups = 0;
  for (std::size_t a = 0; a < items.size();) {
    std::size_t b = a + 1;
    while (b < items.size() && items[b].half == items[a].half && triple_sign(q, *items[a].dir, *items[b].dir) == 0)
      ++b;
    for (std::size_t c = a; c < b; ++c) {
      if (cur[items[c].pt] != items[c].from) throw std::logic_error("limit surface: inconsistent face walk");
      cur[items[c].pt] = static_cast<std::uint16_t>(items[c].to);
    }
    ++groups;
    a = b;
    if (a < items.size()) cycle.push_back(cur);
  }
  if (cur != cycle.front()) throw std::logic_error("limit surface: face walk did not close");
  *dim = groups <= 2 ? 1 : 2;
  return cycle;
}

Vec3z Polygonal_ls::tuple_point(const Side_tab& t, const std::vector<std::uint16_t>& tuple) const {
  Vec3z x = {Integer(0), Integer(0), Integer(0)};
  for (std::size_t i = 0; i < tuple.size(); ++i)
    for (int c = 0; c < 3; ++c) x[c] += t.pts[i].vert[tuple[i]][c];
  return x;
}

Rational Polygonal_ls::support_value(Side side, const Vec3q& q) const {
  const Side_tab& t = tab(side);
  if (is_zero(q) || s_.points.empty()) return 0;
  const Vec3z qz = primitive(q);
  std::vector<int> kind, idx;
  point_faces(t, qz, kind, idx);
  Vec3z x = {Integer(0), Integer(0), Integer(0)};
  for (std::size_t i = 0; i < kind.size(); ++i)
    for (int c = 0; c < 3; ++c) x[c] += t.pts[i].vert[kind[i] == 2 ? 0 : idx[i]][c];
  Rational h = q[0] * x[0] + q[1] * x[1] + q[2] * x[2];
  return h / t.L;
}

Ls_face Polygonal_ls::face(Side side, const Vec3q& q) const {
  const Side_tab& t = tab(side);
  if (is_zero(q)) throw std::invalid_argument("limit surface face: zero twist");
  const Vec3z qz = primitive(q);
  Ls_face f;
  if (s_.points.empty()) {
    f.vertices.push_back({Rational(0), Rational(0), Rational(0)});
    return f;
  }
  std::vector<int> kinds;
  const auto cyc = face_tuples(t, qz, &f.dimension, &kinds);
  f.point_face_dim = kinds;
  for (const auto& tu : cyc) {
    const Vec3z x = tuple_point(t, tu);
    f.vertices.push_back({Rational(x[0], t.L), Rational(x[1], t.L), Rational(x[2], t.L)});
    for (auto& c : f.vertices.back()) c.canonicalize();
  }
  return f;
}

// ---------------------------------------------------------------------------------------------
// [LS-2] The polytopes

Ls_polytope Polygonal_ls::build(Side side) const {
  const Side_tab& t = tab(side);
  const int n = d_.n, half = n / 2;
  const std::size_t k = s_.points.size();
  Ls_polytope P;
  auto to_q = [&](const Vec3z& x) {
    Vec3q r = {Rational(x[0], t.L), Rational(x[1], t.L), Rational(x[2], t.L)};
    for (auto& c : r) c.canonicalize();
    return r;
  };
  if (k == 0) {
    P.dimension = 0;
    P.vertices.push_back({Rational(0), Rational(0), Rational(0)});
    return P;
  }
  if (k == 1) {  // a flat polygon in the plane ν·x = 0: its two sides
    P.dimension = 2;
    for (int j = 0; j < n; ++j) P.vertices.push_back(to_q(t.pts[0].vert[j]));
    const Vec3z nu = primitive(Vec3z{num_[0][1], -num_[0][0], den_[0]});
    Ls_facet up{nu, Rational(0), {}, 0}, down{neg(nu), Rational(0), {}, 0};
    for (int j = 0; j < n; ++j) {
      up.vertices.push_back(j);
      down.vertices.push_back(n - 1 - j);
    }
    P.facets = {up, down};
    P.edges = static_cast<std::size_t>(n);
    return P;
  }
  if (candidate_count() > kMaxCandidates)
    throw std::length_error("the limit surface would need " + std::to_string(candidate_count()) +
                            " candidate normals (more than " + std::to_string(kMaxCandidates) + ")");
  // Candidates with the sign fixed (first nonzero coordinate positive); −q is handled by symmetry.
  std::vector<Vec3z> cand;
  cand.reserve(static_cast<std::size_t>(candidate_count() / 2 + 1));
  auto canon = [](Vec3z v) {  // v ≠ 0
    v = primitive(std::move(v));
    const int s = v[0] != 0 ? sgn(v[0]) : (v[1] != 0 ? sgn(v[1]) : sgn(v[2]));
    return s < 0 ? neg(v) : v;
  };
  for (std::size_t i = 0; i < k; ++i) cand.push_back(canon({num_[i][1], -num_[i][0], den_[i]}));
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t l = i + 1; l < k; ++l)
      for (int a = 0; a < half; ++a)
        for (int b = 0; b < half; ++b) {
          Vec3z c = cross3(t.pts[i].edir[a], t.pts[l].edir[b]);
          if (!is_zero(c)) cand.push_back(canon(std::move(c)));
        }
  std::sort(cand.begin(), cand.end(), [](const Vec3z& a, const Vec3z& b) { return lex_cmp(a, b) < 0; });
  cand.erase(std::unique(cand.begin(), cand.end(), [](const Vec3z& a, const Vec3z& b) { return lex_cmp(a, b) == 0; }),
             cand.end());

  std::unordered_map<std::string, int> vid;
  std::vector<Vec3z> vz;
  auto vertex_id = [&](const std::vector<std::uint16_t>& tu) {
    std::string key(reinterpret_cast<const char*>(tu.data()), tu.size() * sizeof(std::uint16_t));
    const auto [it, fresh] = vid.emplace(std::move(key), static_cast<int>(vz.size()));
    if (fresh) vz.push_back(tuple_point(t, tu));
    return it->second;
  };
  P.facets.reserve(cand.size() * 2);
  std::vector<int> kinds;
  for (const Vec3z& q : cand) {
    int dim = 0;
    const auto cyc = face_tuples(t, q, &dim, &kinds);
    if (dim != 2) throw std::logic_error("limit surface: a candidate normal is not a facet normal");
    int sp = -1;
    for (std::size_t i = 0; i < k; ++i)
      if (kinds[i] == 2) sp = static_cast<int>(i);
    Ls_facet f{q, Rational(0), {}, sp}, g{neg(q), Rational(0), {}, sp};
    for (const auto& tu : cyc) f.vertices.push_back(vertex_id(tu));
    for (auto it = cyc.rbegin(); it != cyc.rend(); ++it) {  // −F(q): antipodal indices, reversed order
      std::vector<std::uint16_t> a = *it;
      for (auto& j : a) j = static_cast<std::uint16_t>((j + half) % n);
      g.vertices.push_back(vertex_id(a));
    }
    const Vec3z& x = vz[static_cast<std::size_t>(f.vertices[0])];
    f.b = Rational(q[0] * x[0] + q[1] * x[1] + q[2] * x[2], t.L);
    f.b.canonicalize();
    g.b = f.b;
    P.edges += f.vertices.size() + g.vertices.size();
    P.facets.push_back(std::move(f));
    P.facets.push_back(std::move(g));
  }
  P.edges /= 2;
  P.vertices.reserve(vz.size());
  for (const Vec3z& x : vz) P.vertices.push_back(to_q(x));
  if (P.vertices.size() + P.facets.size() != P.edges + 2)
    throw std::logic_error("limit surface: Euler's formula fails (V - E + F != 2)");
  return P;
}

// ---------------------------------------------------------------------------------------------
// [LS-3] Gauge and normal cone

std::optional<Rational> Polygonal_ls::gauge(const Ls_polytope& P, Side side, const Vec3q& p) const {
  const bool zero = p[0] == 0 && p[1] == 0 && p[2] == 0;
  if (zero) return Rational(0);
  if (P.dimension == 0) return std::nullopt;
  if (P.dimension == 2) {
    const Ls_point& pt = s_.points[0];
    if (pt.at.y * p[0] - pt.at.x * p[1] + p[2] != 0) return std::nullopt;  // ν·p ≠ 0
    const Side_tab& t = tab(side);
    Rational g = 0;
    for (int j = 0; j < d_.n; ++j) {
      const Rational a = t.nrm[j][0] * p[0] + t.nrm[j][1] * p[1];
      const Rational b = pt.rho * (t.nrm[j][0] * t.p[j].x + t.nrm[j][1] * t.p[j].y);
      if (a / b > g) g = a / b;
    }
    return g;
  }
  Rational g = 0;
  for (const Ls_facet& f : P.facets) {
    const Rational r = (f.normal[0] * p[0] + f.normal[1] * p[1] + f.normal[2] * p[2]) / f.b;
    if (r > g) g = r;
  }
  return g;
}

Polygonal_ls::Normal_cone Polygonal_ls::normal_cone(const Ls_polytope& P, Side side, const Vec3q& p) const {
  Normal_cone c;
  const auto g = gauge(P, side, p);
  if (P.dimension == 0 || (g && *g == 0)) {
    c.lineality = {{Integer(1), Integer(0), Integer(0)}, {Integer(0), Integer(1), Integer(0)},
                   {Integer(0), Integer(0), Integer(1)}};
    return c;
  }
  if (P.dimension == 2) {
    const Ls_point& pt = s_.points[0];
    const Vec3z nu = primitive(Vec3q{pt.at.y, -pt.at.x, Rational(1)});
    const Rational s = pt.at.y * p[0] - pt.at.x * p[1] + p[2];
    if (!g) {  // off the plane: rotation about the point, in the sense of the load's moment about it
      c.generators.push_back(s > 0 ? nu : neg(nu));
      return c;
    }
    c.lineality.push_back(nu);
    const Side_tab& t = tab(side);
    for (int j = 0; j < d_.n; ++j) {
      const Rational a = t.nrm[j][0] * p[0] + t.nrm[j][1] * p[1];
      const Rational b = pt.rho * (t.nrm[j][0] * t.p[j].x + t.nrm[j][1] * t.p[j].y);
      if (a == *g * b) c.generators.push_back({t.nrm[j][0], t.nrm[j][1], Integer(0)});
    }
    return c;
  }
  for (const Ls_facet& f : P.facets)
    if (f.normal[0] * p[0] + f.normal[1] * p[1] + f.normal[2] * p[2] == *g * f.b) c.generators.push_back(f.normal);
  return c;
}

}  // namespace wrenchkit
