#include "float/grasp_twin.h"

#include <initializer_list>

namespace wrenchkit::fl {

Sign nguyen_twin(const Finger_twin& a, const Finger_twin& b, const Bounded& mu) {
  const Bounded dx = b.px - a.px, dy = b.py - a.py;
  bool uncertain = false;
  for (int f = 0; f < 2; ++f) {
    const Finger_twin& c = f == 0 ? a : b;
    const Bounded ex = f == 0 ? dx : -dx, ey = f == 0 ? dy : -dy;  // toward the other finger
    const Bounded along = c.nx * ex + c.ny * ey, side = c.nx * ey - c.ny * ex;
    for (const Bounded& v : {mu * along - side, mu * along + side}) {
      const Sign s = v.sign();
      if (s == Sign::negative || s == Sign::zero) return Sign::negative;  // certainly not strictly inside: open
      uncertain = uncertain || s == Sign::uncertain;
    }
  }
  return uncertain ? Sign::uncertain : Sign::positive;
}

}  // namespace wrenchkit::fl
