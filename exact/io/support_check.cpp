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

std::optional<Rational> support_weight_of(const Scene& scene) {
  if (!scene.support) return std::nullopt;
  if (scene.support->weight) return scene.support->weight;
  if (gravity_across_support(scene)) return scene.load->weight;
  return std::nullopt;
}

bool gravity_across_support(const Scene& scene) {
  return scene.support && scene.load && scene.load->kind == Load::Kind::gravity;
}

// Gravity beside a support fixes W (the weight) and c (body.com): a written weight or pressure_center that
// says otherwise is a contradiction, refused with both values.
static std::string gravity_conflict(const Scene& scene) {
  if (!gravity_across_support(scene)) return "";
  const Support& s = *scene.support;
  const Rational& g = scene.load->weight;
  if (s.weight && *s.weight != g)
    return "load.gravity: the weight " + to_string(g) + " presses the body on the support, but support.weight is " +
           to_string(*s.weight) + " (gravity beside a support sets the support's total normal force: give one of "
           "them, or the same value)";
  const Vec2& com = *scene.body.com;
  if (s.pressure_center && (s.pressure_center->x != com.x || s.pressure_center->y != com.y))
    return "support.pressure_center: " + point_text(*s.pressure_center) + " is not body.com " + point_text(com) +
           ", where the weight (load.gravity) acts (gravity beside a support sets the centre of pressure: drop "
           "pressure_center or move body.com)";
  return "";
}

std::string support_inadmissible(const Scene& scene) {
  if (!scene.support) return "";
  const Support& s = *scene.support;
  // Every force given and neither weight nor pressure_center written: nothing to agree with.
  if (const std::string why = gravity_conflict(scene); !why.empty()) return why;
  const std::optional<Rational> weight = support_weight_of(scene);
  // With gravity the weight acts at body.com: the centre of pressure is held there as if it were written.
  const std::optional<Vec2> center = gravity_across_support(scene) ? scene.body.com : s.pressure_center;
  // Every force given and neither weight nor pressure_center written: nothing to agree with.
  if (!weight && !center && s.known()) return "";
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
    if (weight && *weight != given)
      return std::string(s.weight ? "support.weight: " : "load.gravity: the weight ") + to_string(*weight) +
             " is not the sum of the given forces" +
             (s.regions.empty() ? "" : " and the regions' forces") + ", " + to_string(given) +
             ": no admissible distribution";
    if (center && (center->x * given != moment.x || center->y * given != moment.y))
      return std::string(s.pressure_center ? "support.pressure_center: " : "body.com: the weight's point ") +
             point_text(*center) + " is not the centre of pressure of the given forces, " +
             point_text({moment.x / given, moment.y / given}) + ": no admissible distribution";
    return "";
  }
  if (!weight) return "support.weight: missing (the total normal force is needed when a point's force is not given)";
  const std::optional<Vec2> c = pressure_center_of(scene);
  if (!c)
    return "support.pressure_center: missing, and the body has no com (the centre of pressure is needed when a "
           "point's force is not given)";
  const Rational rest = *weight - given;
  const Vec2 rest_moment{*weight * c->x - moment.x, *weight * c->y - moment.y};
  if (rest < 0)
    return std::string(s.weight ? "support.weight: " : "load.gravity: the weight ") + to_string(*weight) + " is less than the sum of the given forces, " +
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
