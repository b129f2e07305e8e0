#include "exact/to_float.h"

#include <cmath>

namespace wrenchkit {

fl::Bounded to_bounded(const Rational& q) {
  const double v = q.get_d();  // truncation toward zero: |q − v| < ulp(v)
  if (!std::isfinite(v)) return {v, fl::Bounded::kInf};
  if (Rational(v) == q) return {v, 0.0};
  if (std::fabs(v) < fl::Bounded::kUnderflow) return {v, fl::Bounded::kInf};
  return {v, std::fabs(v) * 0x1p-51};
}

std::vector<fl::Bounded_contact> to_bounded(const Scene& scene) {
  std::vector<fl::Bounded_contact> out;
  out.reserve(scene.contacts.size());
  for (const Contact& c : scene.contacts) {
    fl::Bounded_contact b;
    if (c.kind == Contact::Kind::wrench) {
      b.is_wrench = true;
      b.fx = to_bounded(c.wrench.fx);
      b.fy = to_bounded(c.wrench.fy);
      b.m = to_bounded(c.wrench.m);
    } else {
      b.ax = to_bounded(c.at.x);
      b.ay = to_bounded(c.at.y);
      b.nx = to_bounded(c.normal.x);
      b.ny = to_bounded(c.normal.y);
      b.mu = to_bounded(c.mu);
      b.frictional = c.mu != 0;  // decided exactly
    }
    out.push_back(b);
  }
  return out;
}

}  // namespace wrenchkit
