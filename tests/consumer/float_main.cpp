// Checks a grasp with the installed wrenchkit::float alone (plain doubles, no GMP). Exit 0 on success.
#include <cstdio>
#include <vector>

#include "float/closure_twin.h"

int main() {
  using namespace wrenchkit::fl;
  // Two fingers, mu = 0.25 > slope 0 of the segment between them: closed; frictionless: open.
  const std::vector<Point_contact> grasp = {{0, 0.5, 1, 0, 0.25}, {1, 0.5, -1, 0, 0.25}};
  const std::vector<Point_contact> frictionless = {{0, 0.5, 1, 0, 0}, {1, 0.5, -1, 0, 0}};
  const Verdict a = force_closure(grasp), b = force_closure(frictionless);
  std::printf("float: force closure %s, frictionless %s\n", a == Verdict::closed ? "closed" : "not closed",
              b == Verdict::open ? "open" : "not open");
  return a == Verdict::closed && b == Verdict::open ? 0 : 1;
}
