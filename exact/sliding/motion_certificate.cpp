#include "exact/sliding/motion_certificate.h"

#include "exact/io/json_writer.h"

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

void write_forces(Json_writer& w, const std::vector<Vec2>& g) {
  w.array();
  for (const Vec2& f : g) w.array().rational(f.x).rational(f.y).end_array();
  w.end_array();
}

// The certificate's object, opened, with its first members: the load and the motion.
Json_writer head(const Vec3q& p, const char* motion) {
  Json_writer w(512);
  w.object().member("wrenchkit_certificate", 1).member("property", "motion").key("load").rationals(p);
  w.member("motion", motion);
  return w;
}

void write_stick(Json_writer& w, const Stick_witness& s) {
  w.object().key("distribution").rationals(s.distribution);
  write_forces(w.key("support_forces"), s.forces);
  w.end_object();
}

}  // namespace

std::string sticks_certificate(const Vec3q& p, const Stick_witness& s) {
  Json_writer w = head(p, "sticks");
  write_forces(w.key("support_forces"), s.forces);
  return w.end_object().take();
}

std::string slides_certificate(const Vec3q& p, const Slide_witness& s) {
  Json_writer w = head(p, "slides");
  w.key("twist").rationals(s.twist).key("speed_bounds").rationals(s.speed_bounds);
  return w.end_object().take();
}

std::string sticks_for_every_certificate(const Vec3q& p, const std::vector<Stick_witness>& vertices) {
  Json_writer w = head(p, "sticks");
  w.key("vertices").array();
  for (const Stick_witness& s : vertices) write_stick(w, s);
  return w.end_array().end_object().take();
}

std::string slides_for_every_certificate(const Vec3q& p, const Vec3q& twist, const std::vector<Rational>& u,
                                         const std::array<Rational, 3>& dual) {
  Json_writer w = head(p, "slides");
  w.key("twist").rationals(twist).key("speed_bounds").rationals(u).key("dual").rationals(dual);
  return w.end_object().take();
}

std::string depends_certificate(const Vec3q& p, const Stick_witness& sticking, const Slide_witness& sliding) {
  Json_writer w = head(p, "depends");
  write_stick(w.key("sticking"), sticking);
  w.key("sliding").object().key("distribution").rationals(sliding.distribution).key("twist").rationals(sliding.twist);
  w.key("speed_bounds").rationals(sliding.speed_bounds).end_object();
  return w.end_object().take();
}

}  // namespace wrenchkit
