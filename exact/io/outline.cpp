// [OL-1] The body's outline as geometry: see outline.h.
#include "exact/io/outline.h"

#include <functional>
#include <optional>

#include "exact/io/input_error.h"
#include "exact/io/region.h"
#include "exact/numbers/vectors.h"

namespace wrenchkit {

namespace {

std::string point(const Vec2& p) { return "(" + to_string(p.x) + ", " + to_string(p.y) + ")"; }

// n in the closed cone of u and w (two inward normals at a vertex; u ≠ −w for a simple polygon).
bool in_cone(const Vec2& n, const Vec2& u, const Vec2& w) {
  const int uw = sgn(cross(u, w));
  if (uw > 0) return sgn(cross(u, n)) >= 0 && sgn(cross(n, w)) >= 0;
  if (uw < 0) return sgn(cross(w, n)) >= 0 && sgn(cross(n, u)) >= 0;
  return sgn(cross(n, u)) == 0 && sgn(dot(n, u)) > 0;  // a straight vertex: the edges' common normal
}

// The squared distance from p to edge i (exact: the projection clamped to the segment).
Rational distance2(const std::vector<Vec2>& V, std::size_t i, const Vec2& p) {
  const Vec2& a = V[i];
  const Vec2 d = minus(V[(i + 1) % V.size()], a), ap = minus(p, a);
  Rational t = dot(ap, d) / dot(d, d);
  if (t < 0) t = 0;
  if (t > 1) t = 1;
  const Vec2 q{ap.x - t * d.x, ap.y - t * d.y};
  return dot(q, q);
}

// One point contact (or the pusher) against the outline: on it, its normal pointing into the body.
void check_on_outline(const Contact& c, const std::string& path, const std::vector<Vec2>& V, int orientation,
                      const std::function<void(const std::string&)>& violation) {
  const std::size_t n = V.size();
  // where it lies: a vertex, else an edge's interior
  std::optional<std::size_t> vertex, edge;
  for (std::size_t i = 0; i < n && !vertex; ++i) {
    if (c.at.x == V[i].x && c.at.y == V[i].y) {
      vertex = i;
      break;
    }
    const Vec2 d = minus(V[(i + 1) % n], V[i]), ap = minus(c.at, V[i]);
    if (sgn(cross(d, ap)) == 0 && sgn(dot(d, ap)) > 0 && dot(d, ap) < dot(d, d)) edge = i;
  }
  if (!vertex && !edge) {
    std::size_t near = 0;
    Rational best = distance2(V, 0, c.at);
    for (std::size_t i = 1; i < n; ++i)
      if (const Rational d = distance2(V, i, c.at); d < best) best = d, near = i;
    violation(path + ".at: " + point(c.at) + " is not on body.outline (a contact touches the body's boundary); the "
              "nearest edge is " + std::to_string(near) + ", from " + point(V[near]) + " to " + point(V[(near + 1) % n]) +
              ": place the contact on it, e.g. {\"edge\": " + std::to_string(near) + ", \"s\": \"1/2\"}");
    return;
  }
  if (edge) {
    const Vec2 in = edge_inward_normal(V, *edge, orientation);
    if (sgn(dot(c.normal, in)) <= 0)
      violation(path + ".normal: " + point(c.normal) + " does not point into the body at edge " + std::to_string(*edge) +
                " (from " + point(V[*edge]) + " to " + point(V[(*edge + 1) % n]) + ", inward normal " + point(in) +
                "); a contact's normal points into the body — " +
                (sgn(dot(c.normal, in)) < 0 ? "flip its sign?" : "it is tangent to the edge here"));
    return;
  }
  const std::size_t j = *vertex;
  const Vec2 u = edge_inward_normal(V, (j + n - 1) % n, orientation), w = edge_inward_normal(V, j, orientation);
  if (!in_cone(c.normal, u, w))
    violation(path + ".normal: " + point(c.normal) + " is not in the cone of inward normals at vertex " +
              std::to_string(j) + " " + point(V[j]) + " (between " + point(u) + " and " + point(w) +
              "); a contact's normal points into the body");
}

}  // namespace

int outline_orientation(const std::vector<Vec2>& V) {
  Rational area2 = 0;
  for (std::size_t i = 0; i < V.size(); ++i) area2 += cross(V[i], V[(i + 1) % V.size()]);
  return sgn(area2);
}

Vec2 edge_point(const std::vector<Vec2>& V, std::size_t i, const Rational& t) {
  const Vec2 &a = V[i], &b = V[(i + 1) % V.size()];
  return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
}

Vec2 edge_inward_normal(const std::vector<Vec2>& V, std::size_t i, int orientation) {
  const Vec2 d = minus(V[(i + 1) % V.size()], V[i]);
  return orientation > 0 ? Vec2{-d.y, d.x} : Vec2{d.y, -d.x};
}

Scene with_fingers(const Scene& part, const Rational& mu, const std::vector<std::size_t>& edges,
                   const std::vector<Rational>& at) {
  Scene s = part;
  s.contacts.clear();
  s.load.reset();
  s.support.reset();
  s.pusher.reset();
  const std::vector<Vec2>& V = part.body.outline;
  const int o = outline_orientation(V);
  for (std::size_t f = 0; f < edges.size(); ++f) {
    Contact c;
    c.at = edge_point(V, edges[f], at[f]);
    c.normal = edge_inward_normal(V, edges[f], o);
    c.mu = mu;
    c.mu_given = true;
    c.name = "finger " + std::to_string(f + 1);
    s.contacts.push_back(std::move(c));
  }
  return s;
}

void check_outline(Scene& s, bool lenient) {
  s.warnings.clear();
  const std::vector<Vec2>& V = s.body.outline;
  if (V.empty()) return;
  const auto violation = [&](const std::string& what) {
    if (!lenient) throw Input_error(what + "; or pass --lenient to analyse the scene as given");
    s.warnings.push_back(what);
  };
  const Ring_check ring = check_and_triangulate(V, {});
  if (!ring.why.empty()) {
    violation("body.outline: " + ring.why + " (a body's outline is a simple polygon, each vertex once: do not "
              "repeat the first vertex at the end)");
    return;  // (no contact can be checked against it)
  }
  const std::size_t n = V.size();
  const int orientation = outline_orientation(V);
  s.body.outline_ccw = orientation > 0;
  s.body.outline_convex = true;
  for (std::size_t i = 0; i < n; ++i)
    if (sgn(cross(minus(V[(i + 1) % n], V[i]), minus(V[(i + 2) % n], V[(i + 1) % n]))) * orientation < 0)
      s.body.outline_convex = false;
  for (std::size_t k = 0; k < s.contacts.size(); ++k) {
    if (s.contacts[k].kind != Contact::Kind::point) continue;
    std::optional<Contact> filled;  // (a lazily read contact: its rationals, for the check only; others as they are)
    const Contact& c = s.contacts[k].exact_pending ? filled.emplace(exact_contact(s.contacts[k])) : s.contacts[k];
    check_on_outline(c, "contacts[" + std::to_string(k) + "]", V, orientation, violation);
  }
  if (s.pusher) check_on_outline(s.pusher->contact, "pusher", V, orientation, violation);
  if (s.pusher && s.pusher->end) {  // a line contact: both its ends on the outline
    Contact second = s.pusher->contact;
    second.at = *s.pusher->end;
    check_on_outline(second, "pusher.segment[1]", V, orientation, violation);
  }
}

}  // namespace wrenchkit
