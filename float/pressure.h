// [FL-8] A continuous pressure distribution over a polygon, by quadrature with a certified error
// (theory.md §10, §12.6). Standard library only.
//
// The support region is a simple polygon (either orientation) with a linear pressure
// p(r) = c₀ + c_x x + c_y y ≥ 0 (uniform: c_x = c_y = 0). The polygon is triangulated (ear clipping
// with certified orientation signs), each triangle is cut into m² similar cells (midpoint
// subdivision), and each cell C_k becomes a support point at its centroid s_k carrying
// F_k = ∫_{C_k} p dA = area_k · p(s_k) (exact for linear p) and ρ_k = μ F_k. With δ_k ≥ max_{r ∈ C_k} |r − s_k|
// and ε = μ Σ_k F_k δ_k, the true support function satisfies |h_true(q) − h_cells(q)| ≤ ε|ω| (theory.md
// §12.6: ||v(r)| − |v(s)|| ≤ |ω||r − s|), so support_function below returns a certified bracket of the
// TRUE h(q) of the continuous distribution; it narrows as O(1/m). Loads for a twist and stick/slide on
// the cells (limit_surface_twin.h) approximate the continuous ones (not certified for the continuum).
#pragma once

#include <array>
#include <vector>

#include "float/limit_surface_twin.h"

namespace wrenchkit::fl {

struct Pressure_polygon {
  std::vector<std::array<double, 2>> outline;  // a simple polygon, ≥ 3 vertices
  double mu = 0;                               // support friction, ≥ 0
  double c0 = 1, cx = 0, cy = 0;               // p(r) = c0 + cx·x + cy·y, ≥ 0 on the polygon
};

// Uniform pressure with total normal force f0 > 0 (c0 = f0 / area).
Pressure_polygon uniform_pressure(std::vector<std::array<double, 2>> outline, double mu, double f0);

struct Pressure_cells {
  std::vector<Support_point_twin> points;  // one per cell: centroid, F_k, ρ_k = μ F_k
  Bounded total_force;                     // f₀ = ∫ p dA (exact up to its bound)
  Bounded epsilon;                         // μ Σ F_k δ_k: |h_true − h_cells| ≤ ε|ω|
};

// Throws std::invalid_argument: fewer than 3 vertices, non-finite numbers, μ < 0, a polygon that is not
// simple or has zero area, a pressure that is negative somewhere on it, m < 1 or m > 4096.
Pressure_cells discretize(const Pressure_polygon& region, int m);

// The certified bracket of the continuous distribution's h(q): h_cells(q) with ε|ω| added to its bound.
Bounded support_function(const Pressure_cells& cells, const Bounded3& q);

}  // namespace wrenchkit::fl
