// [FC-1] The dual cone W* of a finite set of wrenches, by incremental clipping.
//
// Given generators g_0 … g_{n-1} of the cone W = pos{g_i} ⊂ R³ (theory.md §3), computes the
// dual cone W* = {t : ⟨t, g_i⟩ ≥ 0 ∀i} — the twists that have non-negative power against every
// generator. Force closure ⇔ W = R³ ⇔ rank W = 3 and W* = {0} (theory.md §3, §4).
//
// The algorithm is written once over a *predicate kernel* and is instantiated with exact rational
// predicates (exact/) and, later, with filtered floating-point predicates (float/). It only asks
// the kernel two questions about the *input* generators, so every float/exact disagreement is a
// filter bug:
//   Sign kernel.cross_sign(i, j)      zero iff g_i × g_j = 0 (g_i, g_j parallel), else positive;
//   Sign kernel.det_sign(i, j, k)     sign of det[g_i; g_j; g_k] = ⟨g_k, g_i × g_j⟩;
// plus `std::size_t kernel.size()`. Generators must be nonzero. A kernel may answer
// Sign::uncertain; the algorithm then stops with `decided == false` (never guesses).
//
// Representation (theory.md §5.7). When rank W = 3, W* is pointed: a convex spherical polygon,
// arc, ray, or {0}. It is stored as a cyclic list of *edge* generators e_0 … e_{K-1}: W* is
// {t : ⟨t, g_e⟩ ≥ 0 for e in the list}, and its extreme rays are exactly g_{e_j} × g_{e_{j+1}}
// (a positive multiple, with this orientation). No coordinates are ever constructed, so the
// predicates above, evaluated on input generators, are all the algorithm needs.
//   polygon: K ≥ 3, a full-dimensional W* (every edge is a facet);
//   arc:     K = 4, (p, e, q, e') with g_{e'} a negative multiple of g_e: a 2-D W* in the plane
//            ⟨t, g_e⟩ = 0, between the rays g_p × g_e and g_e × g_q;
//   ray:     the single ray g_a × g_b (edges = {a, b}); `defining` lists generators whose dual is
//            exactly this ray.
// Insertion of g_k evaluates d_j = det_sign(e_j, e_{j+1}, k) at every vertex: all d ≥ 0 ⇒ g_k is
// redundant; otherwise the vertices with d ≤ 0 form one contiguous run (convexity), the edges
// between them are dropped and k is inserted in their place (the new vertices are g_{e_a} × g_k
// and g_k × g_{e_b}). If no d is positive, W* collapses to a ray, an arc or {0}.
//
// Complexity: O(n) predicates for the rank, then O(K) per insertion: O(n·K) ≤ O(n²) in all, with
// K the size of the current polygon (small unless the generators are in convex position on a
// hemisphere). Memory O(n).
//
// Exactness: exact with an exact kernel; certified-or-undecided with a filtered kernel.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <stdexcept>
#include <vector>

#include "core/sign.h"

namespace wrenchkit {

enum class Dual_shape {
  lineality,  // rank W < 3: W* contains the orthogonal complement of span W (a line, plane or R³)
  polygon,    // rank 3, W* full-dimensional
  arc,        // rank 3, W* two-dimensional
  ray,        // rank 3, W* a single ray
  zero        // rank 3, W* = {0}: force closure
};

struct Dual_cone {
  bool decided = true;          // false: a predicate was uncertain; nothing else is meaningful
  int rank = 0;                 // rank of {g_i}: 0 … 3
  std::array<std::size_t, 3> basis{};  // basis[0 … rank-1]: independent generators, found first
  Dual_shape shape = Dual_shape::lineality;
  std::vector<std::size_t> edges;      // polygon / arc: cyclic edge list; ray: {a, b}
  // shape == zero: the generator whose insertion emptied W*, and generators `defining` whose dual
  // was the state just before; then pos(defining ∪ {closing}) = R³ already.
  // shape == ray: generators whose dual is exactly the ray.
  std::size_t closing = 0;
  std::vector<std::size_t> defining;

  bool force_closure() const { return decided && shape == Dual_shape::zero; }
};

namespace detail {

// Thrown when the kernel's answers contradict the convexity invariants; with an exact kernel this
// is a bug, with a float kernel a filter bug. Never caught inside the library.
struct Dual_cone_invariant_error : std::logic_error {
  using std::logic_error::logic_error;
};

template <class Kernel>
class Dual_cone_builder {
 public:
  explicit Dual_cone_builder(const Kernel& k) : k_(k) {}

  Dual_cone run() {
    const std::size_t n = k_.size();
    if (n == 0) return out_;  // rank 0
    if (!find_basis(n)) return out_;
    if (out_.rank < 3) return out_;
    const std::size_t a = out_.basis[0], b = out_.basis[1], c = out_.basis[2];
    const Sign s = k_.det_sign(a, b, c);
    if (s == Sign::uncertain) return undecided();
    out_.shape = Dual_shape::polygon;
    out_.edges = (s == Sign::positive) ? std::vector<std::size_t>{a, b, c}
                                       : std::vector<std::size_t>{a, c, b};
    for (std::size_t g = 0; g < n; ++g) {
      if (g == a || g == b || g == c) continue;
      if (!insert(g)) return undecided();
      if (out_.shape == Dual_shape::zero) break;
    }
    return out_;
  }

 private:
  const Kernel& k_;
  Dual_cone out_;
  std::vector<Sign> d_;                // vertex signs of the current insertion (reused)
  std::vector<std::size_t> scratch_;   // the next edge list (reused)

  Dual_cone undecided() {
    Dual_cone r;
    r.decided = false;
    return r;
  }

  // Rank and a basis, scanning generators in order: g_0, the first g not parallel to it, the
  // first g off their plane.
  bool find_basis(std::size_t n) {
    out_.rank = 1;
    out_.basis[0] = 0;
    std::size_t j = 1;
    for (; j < n; ++j) {
      const Sign s = k_.cross_sign(0, j);
      if (s == Sign::uncertain) { out_ = undecided(); return false; }
      if (s != Sign::zero) break;
    }
    if (j == n) return true;
    out_.rank = 2;
    out_.basis[1] = j;
    for (std::size_t l = j + 1; l < n; ++l) {
      const Sign s = k_.det_sign(0, j, l);
      if (s == Sign::uncertain) { out_ = undecided(); return false; }
      if (s != Sign::zero) {
        out_.rank = 3;
        out_.basis[2] = l;
        return true;
      }
    }
    return true;
  }

  // Clip W* by ⟨t, g⟩ ≥ 0. Returns false when a predicate was uncertain.
  bool insert(std::size_t g) {
    if (out_.shape == Dual_shape::ray) {
      const Sign d = k_.det_sign(out_.edges[0], out_.edges[1], g);
      if (d == Sign::uncertain) return false;
      if (d == Sign::negative) close_with(g, out_.defining);
      return true;
    }
    const std::vector<std::size_t>& e = out_.edges;
    const std::size_t K = e.size();
    std::vector<Sign>& d = d_;
    d.resize(K);
    bool any_pos = false, any_neg = false;
    for (std::size_t j = 0; j < K; ++j) {
      d[j] = k_.det_sign(e[j], e[(j + 1) % K], g);
      if (d[j] == Sign::uncertain) return false;
      any_pos |= d[j] == Sign::positive;
      any_neg |= d[j] == Sign::negative;
    }
    if (!any_neg) return true;  // g is redundant
    if (!any_pos) {
      collapse(g, d);
      return true;
    }
    // Proper cut: the vertices with d ≤ 0 form the run j0 … j1 (cyclic, no positive inside).
    std::size_t p = 0;
    while (d[p] != Sign::positive) ++p;
    std::size_t j0 = (p + 1) % K;
    while (d[j0] == Sign::positive) j0 = (j0 + 1) % K;
    std::size_t j1 = j0;
    while (d[(j1 + 1) % K] != Sign::positive) j1 = (j1 + 1) % K;
    // Keep edges j1+1 … j0 (each has an endpoint with d > 0), then insert g.
    std::vector<std::size_t>& next = scratch_;
    next.clear();
    for (std::size_t j = (j1 + 1) % K;; j = (j + 1) % K) {
      next.push_back(e[j]);
      if (j == j0) break;
    }
    next.push_back(g);
    if (out_.shape == Dual_shape::arc && next.size() != 4)
      throw Dual_cone_invariant_error("dual cone: an arc was cut into a non-arc");
    out_.edges.swap(next);
    out_.defining.clear();
    return true;
  }

  // No vertex strictly inside the new half-space: W* becomes {0}, a ray or an arc.
  void collapse(std::size_t g, const std::vector<Sign>& d) {
    const std::vector<std::size_t>& e = out_.edges;
    const std::size_t K = e.size();
    std::vector<std::size_t> zeros;
    for (std::size_t j = 0; j < K; ++j)
      if (d[j] == Sign::zero) zeros.push_back(j);
    if (zeros.empty()) {
      close_with(g, e);
      return;
    }
    if (out_.shape == Dual_shape::polygon && zeros.size() == 2) {
      // Two zero vertices: they must be adjacent, and g is a negative multiple of the edge
      // between them; W* becomes that edge (an arc).
      std::size_t j = zeros[0];
      if ((j + 1) % K != zeros[1]) {
        if ((zeros[1] + 1) % K != j)
          throw Dual_cone_invariant_error("dual cone: two non-adjacent vertices on a plane");
        j = zeros[1];
      }
      out_.edges = {e[j], e[(j + 1) % K], e[(j + 2) % K], g};
      out_.shape = Dual_shape::arc;
      out_.defining.clear();
      return;
    }
    // One zero ray (an arc lists each ray twice: its zeros are one ray or none).
    if (out_.shape == Dual_shape::polygon && zeros.size() != 1)
      throw Dual_cone_invariant_error("dual cone: three vertices of a polygon on a plane");
    const std::size_t j = zeros[0];
    std::vector<std::size_t> defining(e.begin(), e.end());
    defining.push_back(g);
    out_.edges = {e[j], e[(j + 1) % K]};
    out_.shape = Dual_shape::ray;
    out_.defining = std::move(defining);
  }

  void close_with(std::size_t g, std::vector<std::size_t> defining) {
    out_.shape = Dual_shape::zero;
    out_.closing = g;
    out_.defining = std::move(defining);
    out_.edges.clear();
  }
};

}  // namespace detail

// [FC-1] See the file comment. Throws detail::Dual_cone_invariant_error if the kernel's signs are
// inconsistent (a bug).
template <class Kernel>
Dual_cone compute_dual_cone(const Kernel& kernel) {
  return detail::Dual_cone_builder<Kernel>(kernel).run();
}

}  // namespace wrenchkit
