// The constructions' answers as JSON parts (exact/pipeline/answer_json.h).
#include "exact/pipeline/answer_json.h"

namespace wrenchkit {

void write_point(Json_writer& w, const Vec2& p) { w.array().rational(p.x).rational(p.y).end_array(); }

namespace {
void write_points(Json_writer& w, const std::vector<Vec2>& v) {
  w.array();
  for (const Vec2& p : v) write_point(w, p);
  w.end_array();
}
}  // namespace

void write_region(Json_writer& w, const Region& r) {
  w.object().member("empty", r.empty()).member("shape", shape_name(r.shape));
  write_points(w.key("vertices"), r.vertices);
  write_points(w.key("directions"), r.directions);
  w.end_object();
}

void write_infinity(Json_writer& w, const Cone2& c) {
  const auto arc = [&w](const Vec2& a, const Vec2& b, bool full = false) {
    write_point(w.object().key("from"), a);
    write_point(w.key("to"), b);
    if (full) w.member("full", true);
    w.end_object();
  };
  const auto dir = [&w](const Vec2& a) {
    write_point(w.object().key("direction"), a);
    w.end_object();
  };
  w.array();
  switch (c.shape) {
    case Cone2::Shape::zero: break;
    case Cone2::Shape::ray: dir(c.extreme[0]); break;
    case Cone2::Shape::line:
      dir(c.extreme[0]);
      dir(c.extreme[1]);
      break;
    case Cone2::Shape::wedge: arc(c.extreme[0], c.extreme[1]); break;
    case Cone2::Shape::half_plane: arc(c.extreme[0], c.extreme[2]); break;
    case Cone2::Shape::plane: arc(Vec2{1, 0}, Vec2{1, 0}, true); break;
  }
  w.end_array();
}

std::string region_json(const Region& r) { return json_text(write_region, r); }
std::string infinity_json(const Cone2& c) { return json_text(write_infinity, c); }
std::string point_json(const Vec2& p) { return json_text(write_point, p, 64); }

void write_both(Json_writer& w, const Both_set& b) {
  w.array();
  switch (b.kind) {
    case Both_set::Kind::none: break;
    case Both_set::Kind::point: write_point(w.object().key("point"), b.point); break;
    case Both_set::Kind::line:
      write_point(w.object().key("line").object().key("through"), b.point);
      write_point(w.key("direction"), b.direction);
      w.end_object();
      break;
    case Both_set::Kind::plane: w.object().member("plane", true); break;
  }
  if (b.kind != Both_set::Kind::none) w.end_object();
  w.end_array();
}

void write_labels(Json_writer& w, const Moment_labels& l) {
  write_region(w.key("plus"), l.plus);
  write_region(w.key("minus"), l.minus);
  write_both(w.key("both"), l.both);
  write_infinity(w.key("infinity"), l.infinity);
}

std::string labels_json(const Moment_labels& l) {
  Json_writer w(1024);
  w.object();
  write_labels(w, l);
  w.end_object();
  return w.take();
}

const char* mode_name(Contact_mode m) {
  switch (m) {
    case Contact_mode::breaks: return "break";
    case Contact_mode::slides: return "slide";
    case Contact_mode::sticks: return "stick";
    case Contact_mode::penetrates: return "penetrate";
    case Contact_mode::none: return "none";
  }
  return "?";
}

Mode_answer contact_modes(const Scene& scene, const Vec3q& t) {
  Mode_answer a;
  for (const Contact& stored : scene.contacts) {
    std::optional<Contact> built;
    if (stored.exact_pending) built = exact_contact(stored);
    const Contact& c = built ? *built : stored;
    Contact_mode m = Contact_mode::none;
    Rational s;
    if (c.kind == Contact::Kind::wrench) {
      s = t[0] * c.wrench[0] + t[1] * c.wrench[1] + t[2] * c.wrench[2];
    } else {
      const Vec2 v = velocity(t, c.at);
      s = dot(v, c.normal);
      m = s > 0 ? Contact_mode::breaks
                : s < 0 ? Contact_mode::penetrates : (is_zero(v) ? Contact_mode::sticks : Contact_mode::slides);
    }
    a.feasible &= s >= 0;
    a.marginal |= s == 0;
    a.modes.push_back(m);
  }
  a.marginal &= a.feasible;
  return a;
}

Vec3q rotation_twist(const Vec2& c, int sense) {
  const Rational w(sense);
  return {w * c.y, -w * c.x, w};
}

Vec3q translation_twist(const Vec2& d) { return {d.y, -d.x, 0}; }

void write_dual_point(Json_writer& w, const Dual_point& p) {
  w.object();
  if (p.sheet == '0') w.member("sheet", "none").member("zero", true);
  else if (p.sheet == 'i') write_point(w.member("sheet", "infinity").key("direction"), p.at);
  else write_point(w.member("sheet", std::string_view(&p.sheet, 1)).key("point"), p.at);
  w.end_object();
}

}  // namespace wrenchkit
