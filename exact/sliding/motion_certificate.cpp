#include "exact/sliding/motion_certificate.h"

#include "exact/io/json.h"

namespace wrenchkit {

std::vector<Rational> speed_bounds(const Support& s, const Vec3q& q) {
  std::vector<Rational> u;
  u.reserve(s.points.size());
  for (const Support_point& p : s.points) {
    const Rational vx = q[0] - q[2] * p.at.y, vy = q[1] + q[2] * p.at.x;
    u.push_back(sqrt_bracket(vx * vx + vy * vy).second);
  }
  return u;
}

std::optional<Slide_witness> slide_witness(const Support& s, const std::vector<Rational>& f, const Vec3q& p,
                                           const Vec3q& q) {
  if (q[0] == 0 && q[1] == 0 && q[2] == 0) return std::nullopt;
  Slide_witness w{f, q, speed_bounds(s, q)};
  Rational bound;
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const Support_point& pt = s.points[i];
    const Rational mu = pt.mu ? *pt.mu : (s.mu ? *s.mu : Rational(0));
    bound += mu * f[i] * w.speed_bounds[i];
  }
  if (q[0] * p[0] + q[1] * p[1] + q[2] * p[2] > bound) return w;
  return std::nullopt;
}

std::optional<Stick_witness> stick_witness_refined(const Support& s, const Admissible& a, const Vec3q& p, int sides,
                                                   const std::vector<Rational>& f) {
  for (int n = sides; n <= 1024; n *= 2)
    if (auto w = stick_witness(s, a, p, n, &f)) return w;
  return std::nullopt;
}

namespace {

std::string q(const Rational& x) { return json::quote(to_string(x)); }

std::string list(const std::vector<Rational>& v) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + q(v[i]);
  return s + "]";
}

std::string triple(const Vec3q& v) { return "[" + q(v[0]) + ", " + q(v[1]) + ", " + q(v[2]) + "]"; }

std::string forces(const std::vector<Vec2>& g) {
  std::string s = "[";
  for (std::size_t i = 0; i < g.size(); ++i) s += (i ? ", " : "") + std::string("[") + q(g[i].x) + ", " + q(g[i].y) + "]";
  return s + "]";
}

std::string head(const Vec3q& p, const char* motion) {
  return std::string("{\"wrenchkit_certificate\": 1, \"property\": \"motion\", \"load\": ") + triple(p) +
         ", \"motion\": \"" + motion + "\"";
}

std::string stick_object(const Stick_witness& w) {
  return "{\"distribution\": " + list(w.distribution) + ", \"support_forces\": " + forces(w.forces) + "}";
}

}  // namespace

std::string sticks_certificate(const Vec3q& p, const Stick_witness& w) {
  return head(p, "sticks") + ", \"support_forces\": " + forces(w.forces) + "}";
}

std::string slides_certificate(const Vec3q& p, const Slide_witness& w) {
  return head(p, "slides") + ", \"twist\": " + triple(w.twist) + ", \"speed_bounds\": " + list(w.speed_bounds) + "}";
}

std::string sticks_for_every_certificate(const Vec3q& p, const std::vector<Stick_witness>& vertices) {
  std::string s = head(p, "sticks") + ", \"vertices\": [";
  for (std::size_t i = 0; i < vertices.size(); ++i) s += (i ? ", " : "") + stick_object(vertices[i]);
  return s + "]}";
}

std::string slides_for_every_certificate(const Vec3q& p, const Vec3q& twist, const std::vector<Rational>& u,
                                         const std::array<Rational, 3>& dual) {
  return head(p, "slides") + ", \"twist\": " + triple(twist) + ", \"speed_bounds\": " + list(u) + ", \"dual\": [" +
         q(dual[0]) + ", " + q(dual[1]) + ", " + q(dual[2]) + "]}";
}

std::string depends_certificate(const Vec3q& p, const Stick_witness& sticking, const Slide_witness& sliding) {
  return head(p, "depends") + ", \"sticking\": " + stick_object(sticking) + ", \"sliding\": {\"distribution\": " +
         list(sliding.distribution) + ", \"twist\": " + triple(sliding.twist) + ", \"speed_bounds\": " +
         list(sliding.speed_bounds) + "}}";
}

}  // namespace wrenchkit
