#include "exact/statics/moment_labels.h"

#include <optional>

#include "exact/io/to_float.h"

namespace wrenchkit {

namespace {

std::vector<Vec3q> centres(const std::vector<Vec3q>& twists) {
  std::vector<Vec3q> p;
  p.reserve(twists.size());
  for (const Vec3q& t : twists) p.push_back(J(t));
  return p;
}

// R₊ ∩ R₋: the lineality space of W* (in rotation-centre coordinates) on the front sheet.
Both_set both_of(const Wrench_cone& c) {
  Both_set b;
  if (c.rank == 0) {
    b.kind = Both_set::Kind::plane;
  } else if (c.rank == 2) {
    const Vec3q l = J(c.lineality[0]);
    if (l[2] != 0) {
      b.kind = Both_set::Kind::point;
      b.point = {l[0] / l[2], l[1] / l[2]};
    }
  } else if (c.rank == 1) {
    // The plane {P : a·P = 0}, a = J(g) (g the one generator direction): the line of force of g.
    const Vec3q a = J(cross(c.lineality[0], c.lineality[1]));
    if (a[0] != 0 || a[1] != 0) {
      b.kind = Both_set::Kind::line;
      b.direction = primitive2(a[1], -a[0]);
      // a_x x + a_y y + a_z = 0: a point of it.
      if (a[0] != 0)
        b.point = {-a[2] / a[0], 0};
      else
        b.point = {0, -a[2] / a[1]};
    }
  }
  return b;
}

// The labels read from a cone (the slices of J(W*) and the ± set).
Moment_labels labels_of(Wrench_cone cone) {
  Moment_labels l;
  l.cone = std::move(cone);
  const std::vector<Vec3q> p = centres(l.cone.dual);
  l.plus = slice_front(p, l.cone.dual_pointed);
  l.minus = slice_front(negated(p), l.cone.dual_pointed);
  l.infinity = slice_infinity(p, l.cone.dual_pointed);
  l.both = both_of(l.cone);
  return l;
}

}  // namespace

Moment_labels moment_labels(const std::vector<Vec3q>& generators, Mode mode, const std::vector<fl::Bounded3>* twin) {
  return labels_of(wrench_cone(generators, mode, twin));
}

Moment_labels moment_labels(const Scene& scene, Reading reading, Mode mode) {
  std::optional<std::vector<fl::Bounded3>> twin;
  if (mode == Mode::hybrid) {
    twin = fl::generators(to_bounded(scene), reading);
    // The cone from the scene's integer rows; rows beyond 62 bits from the rational generators below.
    if (std::optional<Wrench_cone> c = wrench_cone_of_rows(scene, reading, *twin)) return labels_of(std::move(*c));
  }
  std::vector<Vec3q> w;
  for (const Generator& g : generators(scene, reading)) w.push_back(g.w);
  return moment_labels(w, mode, twin ? &*twin : nullptr);
}

}  // namespace wrenchkit
