// Peers of the benchmarks (docs/benchmarks.md): force closure decided as other tools decide it,
// faithfully to how their users call them, on the same scenes as ours: each declaration below states
// the peer's options and verdict rule as its users' code applies them (GraspIt!'s qhull call in src/gws.cpp,
// the plain strict qhull test, cddlib's exact GMP H-representation, GLPK's exact simplex, CGAL's hulls);
// docs/benchmarks.md ("Performance notes": the suite and its peers) summarises them.
// Force closure ⇔ pos{g_i} = R³ ⇔ the origin is strictly inside conv{g_i} (theory.md §3–4).
//
// Float peers receive the wrenches computed in double from the scene's doubles (what their users
// do); exact peers receive the exact rational wrenches. A peer that throws, errors out or returns
// no answer reports `failure` (counted as a failure in the report, never as a verdict).
// bench/ only: no engine code depends on this (CGAL, qhull, cdd, GLPK stay out of the library).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "exact/numbers/rational.h"

namespace wrenchkit::peers {

using Wrench_d = std::array<double, 3>;
using Wrench_q = std::array<Rational, 3>;

enum class Verdict { closure, no_closure, failure };

// GraspIt! (src/gws.cpp): qhull "Pp n Qx QJ C-0.0001" on the wrenches; force closure iff no facet
// has offset > 0 (offset 0, the origin on the boundary, counts as closure). A qhull error is
// GraspIt's "0 volume, quick exit": not force closure (we report it as a failure, too).
Verdict qhull_graspit(const std::vector<Wrench_d>& g);
// The plain qhull test: "Qt" (no joggle), origin strictly inside with an absolute tolerance:
// every facet offset < −1e-12. A qhull error (flat input: QH6154) is a failure.
Verdict qhull_strict(const std::vector<Wrench_d>& g);
// GraspIt!'s epsilon quality (src/quality/qualEpsilon.cpp over src/gws.cpp's hull): qhull "Pp n Qx QJ C-0.0001" on
// the (already scaled) wrenches, ε = min over facets of −offset (the normals are unit); −1 when some −offset is
// negative (not force closure) or qhull fails ("0 volume, quick exit").
double qhull_graspit_epsilon(const std::vector<Wrench_d>& g);
// cddlib with GMP rationals: the exact H-representation of pos{g_i} (V-representation: the
// origin and the rays g_i); closure iff it has no inequality or equation with a nonzero normal.
Verdict cdd_gmp(const std::vector<Wrench_q>& g);
// GLPK's exact simplex (glp_exact) on the double wrenches: closure iff each of the four vectors
// e1, e2, e3, −(e1+e2+e3) (a positive basis of R³) is in pos{g_i}; one LP, four diagonal blocks
// Σ_i λ_ki g_i = d_k, λ ≥ 0 (feasible iff every block is). No rank test is needed: the four
// memberships hold iff pos{g_i} = R³.
Verdict glpk_exact(const std::vector<Wrench_d>& g);

// CGAL 5.5 convex_hull_3 of the wrenches into a Surface_mesh, origin strictly inside iff it is on
// the negative side of every face (CGAL::orientation of the face and the origin), with
// Epick (double input, exact predicates) and Epeck (exact rational input). bench/peers_cgal.cpp.
Verdict cgal_epick(const std::vector<Wrench_d>& g);
Verdict cgal_epeck(const std::vector<Wrench_q>& g);

// The limit surface by CGAL's generic exact hull (Epeck convex_hull_3) of all Minkowski vertex
// sums Σ_i v_i, v_i a vertex of summand polygon i (|sums| = Π_i |P_i|). Returns the hull's vertex
// count (to compare with ours).
std::size_t cgal_minkowski_hull_vertices(const std::vector<std::vector<Wrench_q>>& polygons);

}  // namespace wrenchkit::peers
