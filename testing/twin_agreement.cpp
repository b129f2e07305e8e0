#include "testing/twin_agreement.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "exact/pipeline/answer_json.h"

namespace wrenchkit {

bool within(const fl::Bounded& b, const Rational& x) {
  return std::isfinite(b.v) && std::isfinite(b.e) && abs(x - Rational(b.v)) <= Rational(b.e);
}

bool same_point(const fl::Point2& f, const Vec2& e) { return within(f.x, e.x) && within(f.y, e.y); }

bool same_direction(const fl::Point2& f, const Vec2& e) {
  if (!std::isfinite(f.x.v) || !std::isfinite(f.y.v) || !std::isfinite(f.x.e) || !std::isfinite(f.y.e)) return false;
  Rational lo = 0, hi;  // s ∈ (0, ∞) ∩ [lo, hi] with s·e in the box
  bool bounded = false;
  for (const auto& [b, d] : {std::pair<fl::Bounded, Rational>{f.x, e.x}, {f.y, e.y}}) {
    const Rational l = Rational(b.v) - Rational(b.e), h = Rational(b.v) + Rational(b.e);
    if (d == 0) {
      if (l > 0 || h < 0) return false;
      continue;
    }
    Rational a = l / d, c = h / d;
    if (d < 0) std::swap(a, c);
    if (a > lo) lo = a;
    if (!bounded || c < hi) {
      hi = c;
      bounded = true;
    }
  }
  return !bounded || (hi > 0 && lo <= hi);
}

namespace {

std::string describe(const fl::Region2& f) {
  std::ostringstream o;
  o.precision(17);
  o << fl::shape_name(f.shape) << " [";
  for (const auto& p : f.vertices) o << "(" << p.x.v << "±" << p.x.e << ", " << p.y.v << "±" << p.y.e << ") ";
  o << "] directions [";
  for (const auto& p : f.directions) o << "(" << p.x.v << ", " << p.y.v << ") ";
  return o.str() + "]";
}

}  // namespace

std::string region_disagreement(const fl::Region2& f, const Region& e) {
  const auto fail = [&](const char* why) {
    return std::string(why) + ": float " + describe(f) + " vs exact " + region_json(e);
  };
  if (std::string(fl::shape_name(f.shape)) != shape_name(e.shape)) return fail("shape");
  if (f.shape == fl::Region2::Shape::plane) return "";
  if (f.vertices.size() != e.vertices.size() || f.directions.size() != e.directions.size()) return fail("counts");
  const std::size_t n = e.vertices.size();
  bool found = n == 0;
  for (std::size_t k = 0; k < (e.bounded() ? n : std::min<std::size_t>(n, 1)) && !found; ++k) {
    bool all = true;
    for (std::size_t i = 0; i < n && all; ++i) all = same_point(f.vertices[i], e.vertices[(i + k) % n]);
    found = all;
  }
  if (!found) return fail("corners");
  for (std::size_t i = 0; i < e.directions.size(); ++i)
    if (!same_direction(f.directions[i], e.directions[i])) return fail("directions");
  return "";
}

std::string arc_disagreement(const fl::Arc2& f, const Cone2& e) {
  static const char* names[] = {"none", "direction", "arc", "whole circle"};
  const std::string fs = names[static_cast<int>(f.shape)];
  if (fs != shape_name(e.shape)) return "infinity: float " + fs + " vs exact " + infinity_json(e);
  if (f.shape == fl::Arc2::Shape::full) return "";
  for (std::size_t i = 0; i < e.extreme.size(); ++i)
    if (!same_direction(f.extreme[i], e.extreme[i])) return "infinity direction " + std::to_string(i) + ": " + infinity_json(e);
  return "";
}

std::string labels_disagreement(const fl::Labels_twin& f, const Moment_labels& e) {
  switch (f.status) {
    case fl::Twin_status::uncertain: return "";
    case fl::Twin_status::rank_deficient:
      return e.cone.rank < 3 ? "" : "the twin says rank < 3, the exact rank is " + std::to_string(e.cone.rank);
    case fl::Twin_status::not_pointed: return "labels cannot be not_pointed";
    case fl::Twin_status::decided: break;
  }
  if (e.cone.rank != 3) return "the twin decided a cone of rank " + std::to_string(e.cone.rank);
  std::string d = region_disagreement(f.plus, e.plus);
  if (!d.empty()) return "R+ " + d;
  if (!(d = region_disagreement(f.minus, e.minus)).empty()) return "R- " + d;
  if (!(d = arc_disagreement(f.infinity, e.infinity)).empty()) return d;
  if (f.nothing_labeled() != e.nothing_labeled()) return "nothing_labeled differs";
  return "";
}

std::string dual_disagreement(const fl::Dual_twin& f, const Force_dual& e) {
  if (!f.decided()) return "";
  if (f.covers_all != e.covers_all) return "covers_all differs";
  std::string d = region_disagreement(f.plus_sheet, e.plus_sheet);
  if (!d.empty()) return "+ sheet " + d;
  if (!(d = region_disagreement(f.minus_sheet, e.minus_sheet)).empty()) return "- sheet " + d;
  return arc_disagreement(f.infinity, e.infinity);
}

}  // namespace wrenchkit
