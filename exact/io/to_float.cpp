#include "exact/io/to_float.h"

#include <cmath>

namespace wrenchkit {

std::vector<fl::Bounded_contact> to_bounded(const Scene& scene) {
  std::vector<fl::Bounded_contact> out;
  out.reserve(scene.contacts.size());
  for (const Contact& c : scene.contacts) {
    if (c.has_twin) {  // computed from the digits by read_scene
      out.push_back(c.twin);
      continue;
    }
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
    out.push_back(b);
  }
  return out;
}

}  // namespace wrenchkit
