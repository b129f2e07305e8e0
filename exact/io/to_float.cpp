#include "exact/io/to_float.h"

#include <cmath>

namespace wrenchkit {

fl::Bounded_contact to_bounded(const Contact& c) {
  if (c.has_twin) return c.twin;  // computed from the digits by read_scene
  fl::Bounded_contact b;
  if (c.kind == Contact::Kind::wrench) {
    b.is_wrench = true;
    b.fx = to_bounded(c.wrench[0]);
    b.fy = to_bounded(c.wrench[1]);
    b.m = to_bounded(c.wrench[2]);
  } else {
    b.ax = to_bounded(c.at.x);
    b.ay = to_bounded(c.at.y);
    b.nx = to_bounded(c.normal.x);
    b.ny = to_bounded(c.normal.y);
    b.mu = to_bounded(c.mu);
    b.frictional = c.mu != 0;  // decided exactly
  }
  return b;
}

std::vector<fl::Bounded_contact> to_bounded(const Scene& scene) {
  std::vector<fl::Bounded_contact> out;
  out.reserve(scene.contacts.size());
  for (const Contact& c : scene.contacts) out.push_back(to_bounded(c));
  return out;
}

}  // namespace wrenchkit
