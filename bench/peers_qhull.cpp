// qhull peers (bench/peers.h): GraspIt!'s call and the plain strict test, with libqhull_r.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <vector>

#include "bench/peers.h"

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

namespace wrenchkit::peers {
namespace {

FILE* null_file() {
  static FILE* f = std::fopen("/dev/null", "w");
  return f;
}

// Hull of the wrenches with `flags`; `decide` sees every facet offset (normal·x + offset ≤ 0 inside).
template <class Decide>
Verdict run_qhull(const std::vector<Wrench_d>& g, const char* flags, Decide&& decide) {
  std::vector<coordT> pts;
  pts.reserve(3 * g.size());
  for (const Wrench_d& w : g) pts.insert(pts.end(), w.begin(), w.end());
  char cmd[64];
  std::snprintf(cmd, sizeof cmd, "%s", flags);
  qhT qh_qh;
  qhT* qh = &qh_qh;
  qh_zero(qh, null_file());
  const int exitcode = qh_new_qhull(qh, 3, static_cast<int>(g.size()), pts.data(), False, cmd, nullptr, null_file());
  Verdict v = Verdict::failure;
  if (exitcode == 0) {
    bool ok = true;
    facetT* facet;
    FORALLfacets ok = ok && decide(facet->offset);
    v = ok ? Verdict::closure : Verdict::no_closure;
  }
  qh->NOerrexit = True;
  qh_freeqhull(qh, !qh_ALL);
  int curlong, totlong;
  qh_memfreeshort(qh, &curlong, &totlong);
  return v;
}

}  // namespace

Verdict qhull_graspit(const std::vector<Wrench_d>& g) {
  return run_qhull(g, "qhull Pp n Qx QJ C-0.0001", [](double offset) { return !(offset > 0); });
}

double qhull_graspit_epsilon(const std::vector<Wrench_d>& g) {
  double eps = 1e300;
  bool negative = false;
  const Verdict v = run_qhull(g, "qhull Pp n Qx QJ C-0.0001", [&](double offset) {
    if (-offset < 0) negative = true;
    eps = std::min(eps, -offset);
    return true;
  });
  return v == Verdict::failure || negative ? -1.0 : eps;
}

Verdict qhull_strict(const std::vector<Wrench_d>& g) {
  return run_qhull(g, "qhull Qt", [](double offset) { return offset < -1e-12; });
}

}  // namespace wrenchkit::peers
