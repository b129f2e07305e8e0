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

std::string float_point_json(const fl::Point2& p) { return "[" + float_number(p.x.v) + ", " + float_number(p.y.v) + "]"; }
std::string float_bounds_json(const fl::Point2& p) {
  return "[" + bound_number(shown_bound(p.x, float_number(p.x.v))) + ", " +
         bound_number(shown_bound(p.y, float_number(p.y.v))) + "]";
}

namespace {

std::string list(const std::vector<fl::Point2>& v, std::string (*f)(const fl::Point2&)) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + f(v[i]);
  return s + "]";
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

std::string float_value_json(const fl::Bounded& b) {
  if (!std::isfinite(b.v) || !std::isfinite(b.e)) return "null";
  const std::string v = float_number(b.v);
  return "{\"value\": " + v + ", \"bound\": " + bound_number(shown_bound(b, v)) + "}";
}

std::string float_load_json(const fl::Load_twin& l) {
  if (!l.decided) return "null";
  std::string s = "{\"load\": [" + float_value_json(l.load[0]) + ", " + float_value_json(l.load[1]) + ", " +
                  float_value_json(l.load[2]) + "], \"facet_points\": [";
  for (std::size_t i = 0; i < l.facet_points.size(); ++i) s += (i ? ", " : "") + std::to_string(l.facet_points[i]);
  return s + "]}";
}

std::string float_load_text(const fl::Load_twin& l) {
  if (!l.decided) return "undecided";
  std::string s = "(" + float_value_text(l.load[0]) + ", " + float_value_text(l.load[1]) + ", " + float_value_text(l.load[2]) + ")";
  if (!l.facet_points.empty()) s += " plus the friction disc(s) of the support point(s) at the rotation centre (a facet)";
  return s;
}

std::string float_region_json(const fl::Region2& r) {
  std::vector<fl::Point2> v = r.vertices, d = r.directions;
  if (r.shape == fl::Region2::Shape::plane) {  // as the exact format: the origin and the four axes
    v = {exact_point(0, 0)};
    d = {exact_point(1, 0), exact_point(0, 1), exact_point(-1, 0), exact_point(0, -1)};
  }
  return std::string("{\"empty\": ") + (r.shape == fl::Region2::Shape::empty ? "true" : "false") + ", \"shape\": \"" +
         fl::shape_name(r.shape) + "\", \"vertices\": " + list(v, float_point_json) +
         ", \"vertex_bounds\": " + list(v, float_bounds_json) + ", \"directions\": " + list(d, float_point_json) +
         ", \"direction_bounds\": " + list(d, float_bounds_json) + "}";
}

std::string float_infinity_json(const fl::Arc2& a) {
  switch (a.shape) {
    case fl::Arc2::Shape::zero: return "[]";
    case fl::Arc2::Shape::ray: return "[{\"direction\": " + float_point_json(a.extreme[0]) + "}]";
    case fl::Arc2::Shape::wedge:
      return "[{\"from\": " + float_point_json(a.extreme[0]) + ", \"to\": " + float_point_json(a.extreme[1]) + "}]";
    case fl::Arc2::Shape::full: return "[{\"from\": [1, 0], \"to\": [1, 0], \"full\": true}]";
  }
  return "[]";
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

std::string float_dual_point_json(const fl::Dual_point_twin& p) {
  if (p.sheet == 'i') return "{\"sheet\": \"infinity\", \"direction\": " + float_point_json(p.at) + "}";
  return std::string("{\"sheet\": \"") + p.sheet + "\", \"point\": " + float_point_json(p.at) +
         ", \"bounds\": " + float_bounds_json(p.at) + "}";
}

}  // namespace wrenchkit::cli
