// CGAL peers (bench/peers.h): convex_hull_3 with Epick and Epeck, and the generic exact hull of
// Minkowski vertex sums for the limit surface. The only CGAL translation unit (~16 s to compile).
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include "bench/peers.h"

namespace wrenchkit::peers {
namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;

// What a CGAL user writes: the hull as a Surface_mesh, then the origin against every face.
template <class K>
Verdict origin_strictly_inside(const std::vector<typename K::Point_3>& pts) {
  try {
    CGAL::Surface_mesh<typename K::Point_3> m;
    CGAL::convex_hull_3(pts.begin(), pts.end(), m);
    if (m.number_of_faces() < 4) return Verdict::no_closure;  // a flat or lower-dimensional hull
    const typename K::Point_3 origin = CGAL::ORIGIN;
    for (auto f : m.faces()) {
      auto h = m.halfedge(f);
      const auto& p = m.point(m.target(h));
      const auto& q = m.point(m.target(m.next(h)));
      const auto& r = m.point(m.target(m.next(m.next(h))));
      if (CGAL::orientation(p, q, r, origin) != CGAL::NEGATIVE) return Verdict::no_closure;
    }
    return Verdict::closure;
  } catch (const std::exception&) {
    return Verdict::failure;
  }
}

}  // namespace

Verdict cgal_epick(const std::vector<Wrench_d>& g) {
  std::vector<Epick::Point_3> pts;
  pts.reserve(g.size());
  for (const Wrench_d& w : g) pts.emplace_back(w[0], w[1], w[2]);
  return origin_strictly_inside<Epick>(pts);
}

Verdict cgal_epeck(const std::vector<Wrench_q>& g) {
  std::vector<Epeck::Point_3> pts;
  pts.reserve(g.size());
  for (const Wrench_q& w : g) pts.emplace_back(Epeck::FT(w[0]), Epeck::FT(w[1]), Epeck::FT(w[2]));
  return origin_strictly_inside<Epeck>(pts);
}

std::size_t cgal_minkowski_hull_vertices(const std::vector<std::vector<Wrench_q>>& polygons) {
  std::vector<Wrench_q> sums{{Rational(0), Rational(0), Rational(0)}};
  for (const std::vector<Wrench_q>& poly : polygons) {
    std::vector<Wrench_q> next;
    next.reserve(sums.size() * poly.size());
    for (const Wrench_q& s : sums)
      for (const Wrench_q& v : poly) next.push_back({s[0] + v[0], s[1] + v[1], s[2] + v[2]});
    sums.swap(next);
  }
  std::vector<Epeck::Point_3> pts;
  pts.reserve(sums.size());
  for (const Wrench_q& w : sums) pts.emplace_back(Epeck::FT(w[0]), Epeck::FT(w[1]), Epeck::FT(w[2]));
  CGAL::Surface_mesh<Epeck::Point_3> m;
  CGAL::convex_hull_3(pts.begin(), pts.end(), m);
  return m.number_of_vertices();
}

}  // namespace wrenchkit::peers
