#include "cli/float_json.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "cli/common.h"
#include "exact/numbers/rational.h"

namespace wrenchkit::cli {

std::string float_number(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", x == 0 ? 0.0 : x);  // no "-0"
  return b;
}

namespace {

// A bound on |exact − decimal| for the decimal text `shown` of b.v: b.e plus |decimal − b.v| (exact),
// rounded up to a double.
double shown_bound(const fl::Bounded& b, const std::string& shown) {
  std::string why;
  const std::optional<Rational> d = parse_rational(shown, true, Input_limits{}, why);
  Rational diff = *d - Rational(b.v);
  if (diff < 0) diff = -diff;
  const double gap = diff.get_d();  // truncated toward zero: nudge it up
  if (gap == 0) return b.e;
  return (b.e + gap * (1 + 0x1p-50) + 0x1p-1074) * (1 + 0x1p-50);
}

// The bound written as a JSON number that is ≥ the bound (%.17g rounds to nearest: nudged first).
std::string bound_number(double e) { return float_number(e == 0 ? 0.0 : e * (1 + 0x1p-50)); }

}  // namespace

void write_float_point(Json_writer& w, const fl::Point2& p) {
  w.array().raw(float_number(p.x.v)).raw(float_number(p.y.v)).end_array();
}
void write_float_bounds(Json_writer& w, const fl::Point2& p) {
  w.array().raw(bound_number(shown_bound(p.x, float_number(p.x.v))));
  w.raw(bound_number(shown_bound(p.y, float_number(p.y.v)))).end_array();
}

namespace {

void write_list(Json_writer& w, const std::vector<fl::Point2>& v, void (*f)(Json_writer&, const fl::Point2&)) {
  w.array();
  for (const fl::Point2& p : v) f(w, p);
  w.end_array();
}

fl::Point2 exact_point(double x, double y) { return {fl::Bounded::exact(x), fl::Bounded::exact(y)}; }

std::string pt_text(const fl::Point2& p) { return "(" + float_value_text(p.x) + ", " + float_value_text(p.y) + ")"; }

}  // namespace

std::string float_value_text(const fl::Bounded& b) {
  if (!std::isfinite(b.v) || !std::isfinite(b.e)) return "unknown";
  char s[80];
  std::snprintf(s, sizeof s, "%.12g", b.v == 0 ? 0.0 : b.v);
  const double e = shown_bound(b, s);
  if (e == 0) return s;
  char t[40];
  std::snprintf(t, sizeof t, " ± %.2g", e * 1.1);  // 2 significant digits, never below the bound
  return std::string(s) + t;
}

void write_float_value(Json_writer& w, const fl::Bounded& b) {
  if (!std::isfinite(b.v) || !std::isfinite(b.e)) {
    w.null();
    return;
  }
  const std::string v = float_number(b.v);
  w.object().key("value").raw(v).key("bound").raw(bound_number(shown_bound(b, v))).end_object();
}

void write_float_load(Json_writer& w, const fl::Load_twin& l) {
  if (!l.decided) {
    w.null();
    return;
  }
  w.object().key("load").array();
  for (const fl::Bounded& x : l.load) write_float_value(w, x);
  w.end_array().key("facet_points").array();
  for (const auto i : l.facet_points) w.integer(i);
  w.end_array().end_object();
}

std::string float_load_text(const fl::Load_twin& l) {
  if (!l.decided) return "undecided";
  std::string s = "(" + float_value_text(l.load[0]) + ", " + float_value_text(l.load[1]) + ", " + float_value_text(l.load[2]) + ")";
  if (!l.facet_points.empty()) s += " plus the friction disc(s) of the support point(s) at the rotation centre (a facet)";
  return s;
}

void write_float_region(Json_writer& w, const fl::Region2& r) {
  std::vector<fl::Point2> v = r.vertices, d = r.directions;
  if (r.shape == fl::Region2::Shape::plane) {  // as the exact format: the origin and the four axes
    v = {exact_point(0, 0)};
    d = {exact_point(1, 0), exact_point(0, 1), exact_point(-1, 0), exact_point(0, -1)};
  }
  w.object().member("empty", r.shape == fl::Region2::Shape::empty).member("shape", fl::shape_name(r.shape));
  write_list(w.key("vertices"), v, write_float_point);
  write_list(w.key("vertex_bounds"), v, write_float_bounds);
  write_list(w.key("directions"), d, write_float_point);
  write_list(w.key("direction_bounds"), d, write_float_bounds);
  w.end_object();
}

void write_float_infinity(Json_writer& w, const fl::Arc2& a) {
  w.array();
  switch (a.shape) {
    case fl::Arc2::Shape::zero: break;
    case fl::Arc2::Shape::ray: write_float_point(w.object().key("direction"), a.extreme[0]); break;
    case fl::Arc2::Shape::wedge:
      write_float_point(w.object().key("from"), a.extreme[0]);
      write_float_point(w.key("to"), a.extreme[1]);
      break;
    case fl::Arc2::Shape::full:
      write_float_point(w.object().key("from"), exact_point(1, 0));
      write_float_point(w.key("to"), exact_point(1, 0));
      w.member("full", true);
      break;
  }
  if (a.shape != fl::Arc2::Shape::zero) w.end_object();
  w.end_array();
}

std::string float_region_text(const fl::Region2& r) {
  const auto texts = [](const std::vector<fl::Point2>& x) {
    std::vector<std::string> s;
    for (const fl::Point2& p : x) s.push_back(pt_text(p));
    return s;
  };
  return region_sentence(fl::shape_name(r.shape), texts(r.vertices), texts(r.directions));
}

std::string float_infinity_text(const fl::Arc2& a) {
  switch (a.shape) {
    case fl::Arc2::Shape::zero: return "none";
    case fl::Arc2::Shape::ray: return "the direction " + pt_text(a.extreme[0]);
    case fl::Arc2::Shape::wedge:
      return "the arc from " + pt_text(a.extreme[0]) + " counter-clockwise to " + pt_text(a.extreme[1]);
    case fl::Arc2::Shape::full: return "every direction";
  }
  return "?";
}

void write_float_dual_point(Json_writer& w, const fl::Dual_point_twin& p) {
  w.object();
  if (p.sheet == 'i') {
    write_float_point(w.member("sheet", "infinity").key("direction"), p.at);
  } else {
    write_float_point(w.member("sheet", std::string_view(&p.sheet, 1)).key("point"), p.at);
    write_float_bounds(w.key("bounds"), p.at);
  }
  w.end_object();
}

}  // namespace wrenchkit::cli
