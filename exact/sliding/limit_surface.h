// Polygonal limit surfaces of a planar sliding support, certified (theory.md §11, §12) [LS-1]–[LS-4].
//
// Conventions (theory.md §1.5): every wrench here is a frictional LOAD, the wrench the slider applies
// to the support (parallel to the sliding velocity); the friction wrench on the slider is its negative.
// Wrenches are (fx, fy, m) with m about the origin; twists (vx, vy, w), counter-clockwise positive.
//
// [LS-1] Directions. n (even, 4 ≤ n ≤ kMaxSides) rational unit vectors u_j = u(t_j) (§12.1), sorted
//   counter-clockwise, centrally symmetric; t_j = a_j/den is a rational approximation of tan(φ_j/2) chosen
//   with doubles (a CHOICE only) by core/limit_surface_directions.h, the rule the float twin shares (so its
//   polygons are these); the certificate λ² = (1 + min_j u_j·u_{j+1})/2 is computed exactly from the
//   rationals afterwards. Inner polygon conv{u_j}; outer polygon: the tangents at the u_j (§12.2).
// [LS-2] Polytopes. LS_in/out = ⊕_i A_{r_i}(ρ_i P_in/out) (§12.3), built exactly by candidate normals
//   (§12.4): ±ν_{r_i} and ±(A_{r_i} e × A_{r_j} g) over edge directions e, g. Because every polygon is
//   centrally symmetric, EVERY nonzero candidate is a facet normal (proofs/notes/LS-2-polytopes.md), so
//   the facets are exactly the distinct primitive candidates; coplanar faces are merged by construction
//   (one facet per distinct normal, its face F(q) = Σ_i F_i(q) computed from q itself).
//   Cost O(k²n²·k log n) exact integer operations (k points, n sides).
//   λ·LS ⊆ LS_in ⊆ LS ⊆ LS_out ⊆ LS/λ, i.e. λ h ≤ h_in ≤ h ≤ h_out ≤ h/λ for every twist.
// [LS-3] Queries (exact): the face of LS_in/out for a twist (∂h: a point, a segment or a facet),
//   h_in/h_out, the gauge, stick/slide/undecided for a load, the normal cone of twists.
// Degenerate supports: coincident points are merged (radii add), points with μ·f = 0 dropped; one
//   point → a flat polygon (dimension 2); all radii 0 → the single point 0 (dimension 0).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string>
#include <vector>

#include "core/limit_surface_directions.h"
#include "exact/numbers/rational.h"
#include "exact/io/scene.h"

namespace wrenchkit {

// Refuse to build polytopes with more candidate normals than this (a clear error, not a hang or an
// unbounded allocation; measured ~2.6 kB per candidate for both polytopes).
constexpr std::uint64_t kMaxCandidates = 400000;  // ≈ 1 GB (10 points, N = 128: 368 660)
// Refuse to build the polygons' tables (support values, faces, polytopes: every polygonal query) when their
// memory bound (Polygonal_ls::table_bytes) exceeds this (docs/scene-format.md "Limits").
constexpr std::uint64_t kMaxTableBytes = std::uint64_t(512) << 20;  // 512 MiB: ≈ 2 900 integer points at N = 128

// The support after merging coincident points and dropping ρ = 0: ρ_i = μ_i f_i > 0.
struct Ls_point {
  Vec2 at;
  Rational rho;    // μ_i f_{n,i}
  Rational force;  // f_{n,i}
};
struct Ls_support {
  std::vector<Ls_point> points;
  Rational total_force;    // f₀ = Σ f_{n,i} over ALL input points (ρ = 0 ones included)
  Vec2 weighted_force_sum; // Σ f_{n,i} r_i (all input points)
  bool collinear = false;  // ≥ 2 points, all on one line
};
// `distribution`: the normal forces to use, one per support point (a distribution of docs/theory-sliding.md
// §1); without it every force must be given (std::invalid_argument otherwise).
Ls_support merge_support(const Support& s, const std::vector<Rational>* distribution = nullptr);

// [LS-1]
struct Directions {
  int n = 0;
  std::vector<Vec2> u;  // n unit vectors, CCW, u[j + n/2] = −u[j]
  std::vector<Rational> t;  // u[j] = u(t[j]) for j < n/2 (t = ∞ never used)
  Rational lambda_sq;
};
Directions make_directions(int n);  // precondition: n even, 4 ≤ n ≤ kMaxSides (throws std::invalid_argument)
// Smallest even n ≤ max_sides with 1/λ − 1 ≤ eps (i.e. λ² ≥ 1/(1+eps)²), or 0 if none. Only
// direction sets that can possibly qualify (max gap ≥ 2π/n ⇒ λ ≤ cos(π/n)) are built.
int smallest_sides(const Rational& eps, int max_sides, int* direction_sets_built = nullptr);

enum class Side { inner, outer };
const char* side_name(Side s);

// A face of a polygonal LS (dimension 0: a point, 1: a segment, 2: a facet). Vertices in CCW order
// around the query normal when dimension 2.
struct Ls_face {
  int dimension = 0;
  std::vector<Vec3q> vertices;
  // Per support point: 0 the face of its polygon is a vertex, 1 an edge, 2 the whole polygon (v_i = 0).
  std::vector<int> point_face_dim;
};

struct Ls_facet {
  Vec3z normal;                    // primitive integer outward normal (a twist)
  Rational b;                      // support value: q·x ≤ b on the polytope
  std::vector<int> vertices;       // indices, CCW seen from outside
  int support_point = -1;          // ≥ 0: normal ∝ ±ν of that point (rotation about it)
};

struct Ls_polytope {
  int dimension = 3;               // 3, 2 (one point: flat polygon, two sides), 0 (the point 0)
  std::vector<Ls_facet> facets;    // dimension 2: the two sides ±ν; dimension 0: none
  std::vector<Vec3q> vertices;
  std::size_t edges = 0;
};

// The polygonal model of one support for one direction set: per point tables of exact integer data.
class Polygonal_ls {
 public:
  Polygonal_ls(Ls_support s, Directions d);
  const Ls_support& support() const { return s_; }
  const Directions& directions() const { return d_; }
  int dimension() const;

  // Candidate normals 2k + k(k−1)n²/4 (before deduplication): the work [LS-2] will do.
  std::uint64_t candidate_count() const;
  // An upper bound on the memory of the polygons' tables (k·n vertices per side, built on the first polygonal
  // query), computed in O(k + n) without building them; beyond kMaxTableBytes that query throws
  // std::length_error (tables_problem(): the message for the user, "" when within).
  std::uint64_t table_bytes() const;
  std::string tables_problem() const;
  Ls_polytope build(Side side) const;  // throws std::length_error beyond kMaxCandidates

  // h_in/out(q) = Σ ρ_i h_{P}(v_i(q)), exact.
  Rational support_value(Side side, const Vec3q& q) const;
  // ∂h_in/out(q): the face of the polygonal LS maximizing q·x (q ≠ 0).
  Ls_face face(Side side, const Vec3q& q) const;

  // Unit polygon vertices P[j], CCW (exposed for tests and pictures).
  const std::vector<Vec2>& unit_vertices(Side side) const { return tab(side).p; }

  // Gauge g(p) = min{s ≥ 0 : p ∈ s·P} of the built polytope P of this side; nullopt = +∞ (p outside
  // the polytope's linear span: flat or zero polytopes).
  std::optional<Rational> gauge(const Ls_polytope& P, Side side, const Vec3q& p) const;
  // Normal cone of twists at the boundary point p/g(p) (p ≠ 0): generators are the normals of the
  // facets attaining the gauge; `lineality` is ±ν for a flat polytope (any rotation rate about the
  // single point may be added).
  struct Normal_cone {
    std::vector<Vec3z> generators;
    std::vector<Vec3z> lineality;
  };
  Normal_cone normal_cone(const Ls_polytope& P, Side side, const Vec3q& p) const;

 private:
  struct Point_tab {
    std::vector<Vec3z> vert;   // L·ρ_i A_i(P[j]) (integers)
    std::vector<Vec3z> edir;   // primitive integer direction of A_i(edge j)
  };
  struct Side_tab {
    std::vector<Vec2> p;                    // unit polygon vertices P[j]
    std::vector<std::array<Integer, 2>> nrm;  // primitive outward normal of edge j (P[j] → P[j+1])
    Integer L;                              // common denominator of all vert
    std::vector<Point_tab> pts;
  };
  const Side_tab& tab(Side s) const {
    build_tables();
    return s == Side::inner ? in_ : out_;
  }
  void build_tables() const;
  // Per point: face index; returns −1 vertex m / edge m / whole polygon through kind.
  void point_faces(const Side_tab& t, const Vec3z& q, std::vector<int>& kind, std::vector<int>& idx) const;
  // The face as a cycle of vertex index tuples (dimension via *dim).
  std::vector<std::vector<std::uint16_t>> face_tuples(const Side_tab& t, const Vec3z& q, int* dim,
                                                      std::vector<int>* kinds = nullptr) const;
  Vec3z tuple_point(const Side_tab& t, const std::vector<std::uint16_t>& tuple) const;

  Ls_support s_;
  Directions d_;
  std::vector<Integer> den_;                 // D_i: common denominator of r_i
  std::vector<std::array<Integer, 2>> num_;  // D_i·r_i
  mutable Side_tab in_, out_;  // built on first use (build_tables)
  mutable bool tables_built_ = false;
};

Vec3q to_rational(const Vec3z& v);

// [LS-3] [SL-1] The motion for a quasistatic load p (exact/sliding/motion.h): sticks — p is in the interior of LS,
// friction holds it with margin; impending — p is on LS (friction can just hold it, and quasi-static slip is
// admitted too; every load in a flat LS is on it); slides — p is outside LS; over an unknown distribution also
// depends. classify_load reads the polytopes alone: g_in(p) < 1 ⇒ sticks, g_out(p) ≥ 1 ⇒ slides — on or outside the
// true surface, which a witness then tells apart —, else undecided (refine n).
enum class Motion { sticks, impending, slides, depends, undecided };
const char* motion_name(Motion m);
Motion classify_load(const std::optional<Rational>& gauge_inner, const std::optional<Rational>& gauge_outer);

}  // namespace wrenchkit
