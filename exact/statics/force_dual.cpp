#include "exact/statics/force_dual.h"

#include <stdexcept>


namespace wrenchkit {

Dual_point dual_point(const Vec3q& w) {
  const Vec3q d = J(w);
  if (d[0] == 0 && d[1] == 0 && d[2] == 0) return {'0', {0, 0}};
  if (d[2] == 0) return {'i', primitive2(d[0], d[1])};
  return {d[2] > 0 ? '+' : '-', {d[0] / d[2], d[1] / d[2]}};
}

namespace {

// A rational point in the interior of a full-dimensional region: the vertices' centroid plus the
// sum of the recession directions (proofs/notes/LB-1.md).
Vec2 interior_point(const Region& r) {
  Vec2 o{0, 0};
  for (const Vec2& v : r.vertices) {
    o.x += v.x;
    o.y += v.y;
  }
  o.x /= static_cast<long>(r.vertices.size());
  o.y /= static_cast<long>(r.vertices.size());
  for (const Vec2& d : r.directions) {
    o.x += d.x;
    o.y += d.y;
  }
  return o;
}

}  // namespace

Force_dual force_dual(const Moment_labels& labels, const std::vector<Vec3q>& generators) {
  Force_dual f;
  const Wrench_cone& c = labels.cone;
  f.covers_all = c.force_closure();
  std::vector<Vec3q> d;
  for (const Vec3q& w : c.primal) d.push_back(J(w));
  f.plus_sheet = slice_front(d, c.primal_pointed);
  f.minus_sheet = slice_front(negated(d), c.primal_pointed);
  f.infinity = slice_infinity(d, c.primal_pointed);
  for (const Vec3q& w : generators) f.generators.push_back(dual_point(w));
  if (labels.plus.full_dimensional() && !c.primal.empty()) {
    const Vec2 o = interior_point(labels.plus);
    std::vector<Vec2> pts;
    for (const Vec3q& w : c.primal) {
      // Moment about o: m_o = m − (o_x f_y − o_y f_x) > 0 strictly inside R₊.
      const Rational mo = w[2] - (o.x * w[1] - o.y * w[0]);
      if (mo <= 0) throw std::logic_error("force_dual: reference point not strictly inside R+");
      pts.push_back({-w[1] / mo, w[0] / mo});
    }
    f.reference = o;
    f.about_reference = region_of(std::move(pts), Cone2{});
  }
  return f;
}

}  // namespace wrenchkit
