// Support regions [RG-1] (docs/regions.md, proofs/notes/RG-1-regions.md): polygons with holes carrying a linear
// pressure p(x, y) = a + b·x + c·y ≥ 0, in exact rationals. The model is Support_region (exact/io/scene.h);
// this header has no CGAL: CGAL (an exact kernel, Epeck) checks the rings and triangulates the region inside
// exact/io/region_cgal.cpp only, once, when the scene is read.
//
// Exact measures use two rules that are exact for the polynomials they meet (p linear):
//   ∫_T f dA = (area/3)·Σ f(edge midpoints)                         for f of degree ≤ 2,
//   ∫_T f dA = (area/60)·(27 f(centroid) + 3 Σ f(vertices) + 8 Σ f(edge midpoints))  for f of degree ≤ 3.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "exact/io/scene.h"

namespace wrenchkit {

// Validates a region as written and fills its settled fields (rings oriented, a triangulation, pressure
// coefficients, area, W_R, first and second moments), or throws Input_error naming `path` (e.g.
// "support.regions[0]") and the reason: fewer than 3 vertices, a ring that is not simple (it crosses or
// touches itself, or repeats a vertex), a hole not strictly inside the outline, holes that meet or nest, a
// negative pressure at an outline vertex, a zero total force (uniform: force ≤ 0).
void settle_region(Support_region& r, const std::string& path);
// The region's doubles (Support_region::Doubles) from its exact fields (settle_region calls it).
void settle_doubles(Support_region& r);
// The region scaled by k > 0 about the origin, settled without triangulating again (a similarity keeps the
// triangulation): points × k, pressure ÷ k² (the same forces), moments × k and × k², its doubles made anew.
Support_region scaled_region(const Support_region& r, const Rational& k);

// The pressure p = c[0] + c[1]·x + c[2]·y at a point.
Rational pressure_at(const std::array<Rational, 3>& c, const Vec2& at);

// Exact measures of a triangle (either orientation; its area is taken positive) under the pressure c.
struct Triangle_measures {
  Rational area;      // > 0 for a nondegenerate triangle
  Rational force;     // F = ∫ p dA = area · p(centroid)
  Vec2 moment;        // ∫ r p dA
  // w_j = ∫ λ_j p dA (λ_j the barycentric coordinate of vertex j) = area·(2 p_j + p_k + p_l)/12: the weights
  // of the slide bound ∫_T |v| p ≤ Σ_j w_j u_j when u_j ≥ |v(vertex j)| (|v| convex, p ≥ 0) [RG-1].
  std::array<Rational, 3> vertex_weights;
};
Triangle_measures triangle_measures(const Region_triangle& t, const std::array<Rational, 3>& c);

// The region's coarse triangles cut into m² congruent triangles each (vertices a + (i/m)(b − a) + (j/m)(c − a)),
// as a shared vertex list and counter-clockwise index triples: the cells of the certificates
// (proofs/certificate-format.md §6.4). A vertex on an edge shared by two coarse triangles is listed once.
struct Region_cells {
  std::vector<Vec2> vertices;
  std::vector<std::array<std::size_t, 3>> triangles;
};
Region_cells region_cells(const Support_region& r, int m);

// What CGAL answers about the rings (region_cgal.cpp): "" and the oriented rings and a triangulation whose
// vertices are the rings' vertices, or the reason and the ring (0 the outline, 1 + j the hole j) it is about.
struct Ring_check {
  std::string why;   // "" when valid
  int ring = 0;
  std::vector<std::vector<Vec2>> rings;     // outline counter-clockwise, holes clockwise
  std::vector<Region_triangle> triangles;   // counter-clockwise
};
Ring_check check_and_triangulate(const std::vector<Vec2>& outline, const std::vector<std::vector<Vec2>>& holes);

}  // namespace wrenchkit
