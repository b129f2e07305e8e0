// [RG-1] Support regions: validation (through region_cgal.cpp), exact measures, cells. No CGAL here.
#include "exact/io/region.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "exact/io/input_error.h"
#include "exact/numbers/work_budget.h"

namespace wrenchkit {

namespace {

std::string point_text(const Vec2& p) { return "(" + to_string(p.x) + ", " + to_string(p.y) + ")"; }

Rational twice_signed_area(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

Vec2 mid(const Vec2& a, const Vec2& b) { return {(a.x + b.x) / 2, (a.y + b.y) / 2}; }

// A sum of many rationals with unrelated denominators, added in a balanced tree: the exact sum's denominator is
// the lcm of all of them (thousands of digits for a few hundred vertices of long coordinates), and adding the
// terms one by one costs a gcd with that lcm per term; pairwise, each level costs about one such gcd in all.
class Tree_sum {
 public:
  void add(Rational q) { terms_.push_back(std::move(q)); }
  Rational value() {
    if (terms_.empty()) return 0;
    while (terms_.size() > 1) {
      std::size_t k = 0;
      for (std::size_t i = 0; i + 1 < terms_.size(); i += 2) terms_[k++] = terms_[i] + terms_[i + 1];
      if (terms_.size() % 2) terms_[k++] = std::move(terms_.back());
      terms_.resize(k);
    }
    return terms_[0];
  }

 private:
  std::vector<Rational> terms_;
};

}  // namespace

Rational pressure_at(const std::array<Rational, 3>& c, const Vec2& at) { return c[0] + c[1] * at.x + c[2] * at.y; }

Triangle_measures triangle_measures(const Region_triangle& t, const std::array<Rational, 3>& c) {
  Triangle_measures m;
  m.area = abs(twice_signed_area(t.a, t.b, t.c)) / 2;
  const Rational pa = pressure_at(c, t.a), pb = pressure_at(c, t.b), pc = pressure_at(c, t.c);
  m.force = m.area * (pa + pb + pc) / 3;
  // ∫ x p: degree 2, exact by the edge-midpoint rule.
  const Vec2 mab = mid(t.a, t.b), mbc = mid(t.b, t.c), mca = mid(t.c, t.a);
  const Rational qab = (pa + pb) / 2, qbc = (pb + pc) / 2, qca = (pc + pa) / 2;
  m.moment = {m.area * (mab.x * qab + mbc.x * qbc + mca.x * qca) / 3, m.area * (mab.y * qab + mbc.y * qbc + mca.y * qca) / 3};
  const Rational sum = pa + pb + pc;
  m.vertex_weights = {m.area * (pa + sum) / 12, m.area * (pb + sum) / 12, m.area * (pc + sum) / 12};
  return m;
}

void settle_region(Support_region& r, const std::string& path) {
  Ring_check c = check_and_triangulate(r.outline, r.holes);
  if (!c.why.empty())
    throw Input_error(path + (c.ring == 0 ? std::string(".outline") : ".holes[" + std::to_string(c.ring - 1) + "]") +
                      ": " + c.why);
  r.rings = std::move(c.rings);
  r.triangles = std::move(c.triangles);
  Tree_sum area;
  for (const Region_triangle& t : r.triangles) area.add(twice_signed_area(t.a, t.b, t.c));
  r.area = area.value() / 2;
  if (r.uniform) {
    if (r.force <= 0)
      throw Input_error(path + ".force: " + to_string(r.force) + " is not positive (a region's force must be > 0)");
    r.pressure = {r.force / r.area, Rational(0), Rational(0)};
  } else {
    r.pressure = r.linear;
    // A linear function is ≥ 0 on a polygon iff it is ≥ 0 at the outline's vertices (the holes lie inside).
    for (std::size_t i = 0; i < r.outline.size(); ++i) {
      const Rational p = pressure_at(r.pressure, r.outline[i]);
      if (p < 0)
        throw Input_error(path + ".pressure: p = " + to_string(p) + " < 0 at outline[" + std::to_string(i) + "] " +
                          point_text(r.outline[i]) + " (a pressure must be >= 0 on the region)");
    }
  }
  Tree_sum total, mx, my, sxx, sxy, syy;
  for (const Region_triangle& t : r.triangles) {
    const Triangle_measures m = triangle_measures(t, r.pressure);
    total.add(m.force);
    mx.add(m.moment.x);
    my.add(m.moment.y);
    // ∫ {x², xy, y²}·p: degree 3, exact by the 7-point rule (area/60)(27 f(g) + 3 Σ f(v) + 8 Σ f(m)).
    const Vec2 g{(t.a.x + t.b.x + t.c.x) / 3, (t.a.y + t.b.y + t.c.y) / 3};
    const Vec2 pts[7] = {g, t.a, t.b, t.c, mid(t.a, t.b), mid(t.b, t.c), mid(t.c, t.a)};
    const int w[7] = {27, 3, 3, 3, 8, 8, 8};
    Rational xx, xy, yy;
    for (int k = 0; k < 7; ++k) {
      const Rational wp = w[k] * pressure_at(r.pressure, pts[k]);
      xx += wp * pts[k].x * pts[k].x;
      xy += wp * pts[k].x * pts[k].y;
      yy += wp * pts[k].y * pts[k].y;
    }
    sxx.add(xx * m.area / 60);
    sxy.add(xy * m.area / 60);
    syy.add(yy * m.area / 60);
  }
  r.total = total.value();
  r.moment = {mx.value(), my.value()};
  r.second = {sxx.value(), sxy.value(), syy.value()};
  if (r.uniform) r.total = r.force;  // the same number (area · F/area), kept as written
  if (r.total <= 0)
    throw Input_error(path + ".pressure: the pressure is zero on the whole region (a region's total force must be > 0)");
  settle_doubles(r);
}

void settle_doubles(Support_region& r) {
  Support_region::Doubles& d = r.d;
  d = {};
  for (const auto& ring : r.rings) {
    d.rings.emplace_back();
    for (const Vec2& v : ring) d.rings.back().push_back({v.x.get_d(), v.y.get_d()});
  }
  for (const Region_triangle& t : r.triangles)
    d.triangles.push_back({t.a.x.get_d(), t.a.y.get_d(), t.b.x.get_d(), t.b.y.get_d(), t.c.x.get_d(), t.c.y.get_d()});
  d.pressure = {r.pressure[0].get_d(), r.pressure[1].get_d(), r.pressure[2].get_d()};
  d.total = r.total.get_d();
  for (const auto& v : d.rings[0]) d.gx += v[0], d.gy += v[1];
  d.gx /= static_cast<double>(d.rings[0].size()), d.gy /= static_cast<double>(d.rings[0].size());
  for (const auto& v : d.rings[0]) d.radius = std::max(d.radius, std::hypot(v[0] - d.gx, v[1] - d.gy));
}

Region_cells region_cells(const Support_region& r, int m) {
  {  // [WORK] kPerCell units per cell, times the size of the triangles' numbers
    std::size_t size = 1;
    for (const Region_triangle& t : r.triangles)
      for (const Vec2* v : {&t.a, &t.b, &t.c}) size = std::max({size, Work::size(v->x), Work::size(v->y)});
    const std::size_t cells = Work::times(r.triangles.size(), Work::times(static_cast<std::size_t>(m), m));
    Work::charge(Work::times(Work::times(cells, kPerCell), size),
                 "making " + std::to_string(cells) + " cells of a support region" +
                     (size > 1 ? " (numbers of size " + std::to_string(size) + ")" : ""));
  }
  Region_cells out;
  std::map<std::pair<Rational, Rational>, std::size_t> shared;  // vertices on the coarse triangles' edges
  const Rational step = Rational(1, m);
  for (const Region_triangle& t : r.triangles) {
    const Vec2 u{t.b.x - t.a.x, t.b.y - t.a.y}, v{t.c.x - t.a.x, t.c.y - t.a.y};
    // grid[i][j] = a + (i/m) u + (j/m) v, i + j ≤ m.
    std::vector<std::vector<std::size_t>> grid(static_cast<std::size_t>(m) + 1);
    for (int i = 0; i <= m; ++i)
      for (int j = 0; i + j <= m; ++j) {
        const Rational s = step * i, tt = step * j;
        Vec2 p{t.a.x + s * u.x + tt * v.x, t.a.y + s * u.y + tt * v.y};
        std::size_t index = out.vertices.size();
        if (i == 0 || j == 0 || i + j == m) {
          const auto [at, fresh] = shared.emplace(std::make_pair(p.x, p.y), index);
          if (!fresh) index = at->second;
        }
        if (index == out.vertices.size()) out.vertices.push_back(std::move(p));
        grid[static_cast<std::size_t>(i)].push_back(index);
      }
    for (int i = 0; i < m; ++i)
      for (int j = 0; i + j < m; ++j) {
        const auto I = static_cast<std::size_t>(i), J = static_cast<std::size_t>(j);
        out.triangles.push_back({grid[I][J], grid[I + 1][J], grid[I][J + 1]});
        if (i + j + 2 <= m) out.triangles.push_back({grid[I + 1][J], grid[I + 1][J + 1], grid[I][J + 1]});
      }
  }
  return out;
}

Support_region scaled_region(const Support_region& r, const Rational& k) {
  Support_region t = r;
  for (Vec2& v : t.outline) v = scaled(v, k);
  for (auto& h : t.holes)
    for (Vec2& v : h) v = scaled(v, k);
  for (auto& ring : t.rings)
    for (Vec2& v : ring) v = scaled(v, k);
  for (Region_triangle& g : t.triangles) g = {scaled(g.a, k), scaled(g.b, k), scaled(g.c, k)};
  const Rational k2 = k * k, k3 = k2 * k;
  if (!t.uniform) t.linear = {r.linear[0] / k2, r.linear[1] / k3, r.linear[2] / k3};
  t.pressure = {r.pressure[0] / k2, r.pressure[1] / k3, r.pressure[2] / k3};
  t.area = r.area * k2;
  t.moment = scaled(r.moment, k);  // total unchanged: ∫ p' dA' = ∫ (p/k²) k² dA
  t.second = {r.second[0] * k2, r.second[1] * k2, r.second[2] * k2};
  settle_doubles(t);
  return t;
}

}  // namespace wrenchkit
