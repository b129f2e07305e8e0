#include "exact/io/support_check.h"

#include <vector>

namespace wrenchkit {

namespace {


// Is c in the convex hull of `points` (nonempty)? The minimal wedge [a, b] (counter-clockwise, angle < π)
// holding every p − c so far; 0 ∈ conv{p − c} exactly when some p − c is zero or no such wedge exists.
bool in_hull(const std::vector<Vec2>& points, const Vec2& c) {
  bool started = false;
  Vec2 a, b;
  for (const Vec2& p : points) {
    const Vec2 d{p.x - c.x, p.y - c.y};
    if (d.x == 0 && d.y == 0) return true;
    if (!started) {
      a = b = d;
      started = true;
      continue;
    }
    const Rational ad = cross(a, d), db = cross(d, b);
    const bool inside = ad >= 0 && db >= 0 && !(ad == 0 && dot(a, d) < 0) && !(db == 0 && dot(d, b) < 0);
    if (inside) continue;
    if (cross(b, d) > 0 && ad > 0) b = d;        // past b counter-clockwise, within π of a
    else if (cross(d, a) > 0 && db > 0) a = d;   // past a clockwise, within π of b
    else return true;                            // the wedge would reach π: no open half-plane holds them
  }
  return false;
}

std::string point_text(const Vec2& p) { return "(" + to_string(p.x) + ", " + to_string(p.y) + ")"; }

}  // namespace

std::optional<Vec2> pressure_center_of(const Scene& scene) {
  if (!scene.support) return std::nullopt;
  const Support& s = *scene.support;
  if (s.pressure_center) return s.pressure_center;
  if (!s.known()) return scene.body.com;
  return std::nullopt;
}

std::optional<std::pair<Vec2, Vec2>> gravity_off_pressure_center(const Scene& scene) {
  if (!scene.support || !scene.load || scene.load->kind != Load::Kind::gravity || !scene.body.com) return std::nullopt;
  const Support& s = *scene.support;
  Vec2 c;
  if (s.pressure_center) {
    c = *s.pressure_center;
  } else if (s.known()) {
    Rational w;
    for (const Support_point& p : s.points) {
      w += *p.force;
      c.x += *p.force * p.at.x;
      c.y += *p.force * p.at.y;
    }
    for (const Support_region& r : s.regions) {
      w += r.total;
      c.x += r.moment.x;
      c.y += r.moment.y;
    }
    c = {c.x / w, c.y / w};
  } else {
    return std::nullopt;  // c is body.com itself
  }
  const Vec2& com = *scene.body.com;
  if (com.x == c.x && com.y == c.y) return std::nullopt;
  return std::make_pair(com, c);
}

std::string support_inadmissible(const Scene& scene) {
  if (!scene.support) return "";
  const Support& s = *scene.support;
  // Every force given and neither weight nor pressure_center written: nothing to agree with.
  if (!s.weight && !s.pressure_center && s.known()) return "";
  Rational given;
  Vec2 moment;
  std::vector<Vec2> unknown;
  for (const Support_point& p : s.points) {
    if (!p.force) {
      unknown.push_back(p.at);
      continue;
    }
    given += *p.force;
    moment.x += *p.force * p.at.x;
    moment.y += *p.force * p.at.y;
  }
  // A region's pressure is known: its force W_R and moment ∫ r p dA count as given.
  for (const Support_region& r : s.regions) {
    given += r.total;
    moment.x += r.moment.x;
    moment.y += r.moment.y;
  }
  if (unknown.empty()) {
    if (s.weight && *s.weight != given)
      return "support.weight: " + to_string(*s.weight) + " is not the sum of the given forces" +
             (s.regions.empty() ? "" : " and the regions' forces") + ", " + to_string(given) +
             ": no admissible distribution";
    if (s.pressure_center && (s.pressure_center->x * given != moment.x || s.pressure_center->y * given != moment.y))
      return "support.pressure_center: " + point_text(*s.pressure_center) +
             " is not the centre of pressure of the given forces, " +
             point_text({moment.x / given, moment.y / given}) + ": no admissible distribution";
    return "";
  }
  if (!s.weight) return "support.weight: missing (the total normal force is needed when a point's force is not given)";
  const std::optional<Vec2> c = pressure_center_of(scene);
  if (!c)
    return "support.pressure_center: missing, and the body has no com (the centre of pressure is needed when a "
           "point's force is not given)";
  const Rational rest = *s.weight - given;
  const Vec2 rest_moment{*s.weight * c->x - moment.x, *s.weight * c->y - moment.y};
  if (rest < 0)
    return "support.weight: " + to_string(*s.weight) + " is less than the sum of the given forces, " +
           to_string(given) + ": no admissible distribution";
  if (rest == 0) {
    if (rest_moment.x == 0 && rest_moment.y == 0) return "";
    return "support: no admissible distribution: the given forces carry the whole weight, but their centre of "
           "pressure is " + point_text({moment.x / given, moment.y / given}) + ", not " + point_text(*c);
  }
  const Vec2 needed{rest_moment.x / rest, rest_moment.y / rest};
  if (in_hull(unknown, needed)) return "";
  return "support: no admissible distribution: the centre of pressure " + point_text(*c) +
         " needs the unknown forces to act at " + point_text(needed) +
         ", outside the convex hull of the points whose force is not given (the body would tip over)";
}

}  // namespace wrenchkit
