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
// Complexity: O(n) predicates for the rank; then compute_dual_cone inserts the generators in a fixed
// pseudo-random order with conflict lists (expected O(n log n) predicates, see run()), while
// compute_dual_cone_reference tests every vertex at every insertion (O(n·K) ≤ O(n²), K the polygon
// size) and serves as the tests' oracle. Memory O(n).
//
// Exactness: exact with an exact kernel; certified-or-undecided with a filtered kernel.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
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

  // The reference version: generators in input order, every vertex tested at every insertion.
  Dual_cone run_simple() {
    if (!start()) return out_;
    const std::size_t n = k_.size();
    for (std::size_t g = 0; g < n; ++g) {
      if (is_basis(g)) continue;
      if (!insert(g)) return undecided();
      if (out_.shape == Dual_shape::zero) break;
    }
    return out_;
  }

  // Randomized incremental construction with conflict lists (Clarkson–Shor): generators in a
  // fixed pseudo-random order; each pending generator remembers one vertex it cuts (d < 0), and
  // each vertex the pending generators that remember it. Inserting g walks only the vertices it
  // removes; a pending generator whose vertex was removed can only cut one of the two new vertices
  // (the part of a convex polygon's boundary on the negative side of a plane is one arc, and it
  // runs from the removed vertex to any surviving one through a new vertex) — or nothing, and then
  // it is redundant for good. Expected O(n log n) predicates instead of O(n·K).
  Dual_cone run() {
    if (!start()) return out_;
    const std::size_t n = k_.size();
    std::vector<std::size_t> order;
    order.reserve(n);
    for (std::size_t g = 0; g < n; ++g)
      if (!is_basis(g)) order.push_back(g);
    shuffle(order);
    // The initial triangle as a linked cycle of vertices (edge_in, edge_out).
    for (std::size_t j = 0; j < 3; ++j) new_vertex(out_.edges[j], out_.edges[(j + 1) % 3]);
    for (std::size_t j = 0; j < 3; ++j) link(j, (j + 1) % 3);
    conflict_.assign(n, kNone);
    for (std::size_t g : order) {
      for (std::size_t v = 0; v < 3; ++v) {
        const Sign s = value(v, g);
        if (s == Sign::uncertain) return undecided();
        if (s == Sign::negative) {
          attach(g, v);
          break;
        }
      }
    }
    for (std::size_t idx = 0; idx < order.size(); ++idx) {
      const std::size_t g = order[idx];
      if (out_.shape != Dual_shape::polygon) {  // collapsed to an arc or a ray: O(1) per generator
        if (!insert(g)) return undecided();
        if (out_.shape == Dual_shape::zero) break;
        continue;
      }
      if (conflict_[g] == kNone) continue;  // satisfied by every vertex: redundant
      const int r = cut(g);
      if (r < 0) return undecided();
      if (out_.shape == Dual_shape::zero) break;
    }
    if (out_.shape == Dual_shape::polygon) out_.edges = cycle_edges();
    return out_;
  }

 private:
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  struct Vertex {
    std::size_t in = 0, out = 0;    // the ray g_in × g_out, between edges `in` and `out`
    std::size_t prev = 0, next = 0;
    bool alive = true;
    std::vector<std::size_t> bucket;  // pending generators that cut this vertex
  };
  std::vector<Vertex> vs_;
  std::vector<std::size_t> conflict_;  // per generator: a vertex it cuts, or kNone
  std::size_t any_alive_ = 0;

  bool start() {
    const std::size_t n = k_.size();
    if (n == 0) return false;  // rank 0
    if (!find_basis(n)) return false;
    if (out_.rank < 3) return false;
    const std::size_t a = out_.basis[0], b = out_.basis[1], c = out_.basis[2];
    const Sign s = k_.det_sign(a, b, c);
    if (s == Sign::uncertain) {
      out_ = undecided();
      return false;
    }
    out_.shape = Dual_shape::polygon;
    // Room for a polygon of a few edges in both edge lists (they are swapped at each cut), so that small
    // cones grow without reallocating.
    out_.edges.reserve(8);
    scratch_.reserve(8);
    if (s == Sign::positive) out_.edges.assign({a, b, c});
    else out_.edges.assign({a, c, b});
    return true;
  }

  bool is_basis(std::size_t g) const {
    return g == out_.basis[0] || g == out_.basis[1] || g == out_.basis[2];
  }

  // A fixed, platform-independent permutation (Fisher–Yates driven by splitmix64), so answers and
  // certificates are reproducible and the exact and float runs visit generators in the same order.
  static void shuffle(std::vector<std::size_t>& v) {
    std::uint64_t x = 0x9E3779B97F4A7C15ull;
    for (std::size_t i = v.size(); i > 1; --i) {
      x += 0x9E3779B97F4A7C15ull;
      std::uint64_t z = x;
      z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
      z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
      z ^= z >> 31;
      std::swap(v[i - 1], v[static_cast<std::size_t>(z % i)]);
    }
  }

  std::size_t new_vertex(std::size_t in, std::size_t out) {
    Vertex v;
    v.in = in;
    v.out = out;
    vs_.push_back(std::move(v));
    any_alive_ = vs_.size() - 1;
    return vs_.size() - 1;
  }
  void link(std::size_t a, std::size_t b) {
    vs_[a].next = b;
    vs_[b].prev = a;
  }
  Sign value(std::size_t v, std::size_t g) const { return k_.det_sign(vs_[v].in, vs_[v].out, g); }
  void attach(std::size_t g, std::size_t v) {
    conflict_[g] = v;
    vs_[v].bucket.push_back(g);
  }

  std::vector<std::size_t> cycle_edges() const {
    std::vector<std::size_t> e;
    std::size_t v = any_alive_;
    do {
      e.push_back(vs_[v].in);
      v = vs_[v].next;
    } while (v != any_alive_);
    return e;
  }

  // Inserts g, which cuts the vertex conflict_[g]. Returns −1 if a predicate was uncertain.
  int cut(std::size_t g) {
    const std::size_t v0 = conflict_[g];
    // The maximal run of vertices with d ≤ 0 around v0 (d(v0) < 0).
    std::size_t first = v0, last = v0;
    bool whole = false;
    for (;;) {
      const std::size_t p = vs_[first].prev;
      if (p == last) {
        whole = true;
        break;
      }
      const Sign s = value(p, g);
      if (s == Sign::uncertain) return -1;
      if (s == Sign::positive) break;
      first = p;
    }
    if (!whole) {
      for (;;) {
        const std::size_t q = vs_[last].next;
        const Sign s = value(q, g);
        if (s == Sign::uncertain) return -1;
        if (s == Sign::positive) break;
        last = q;
      }
    }
    if (whole) {  // no vertex strictly inside: W* collapses (the general rules of collapse())
      out_.edges = cycle_edges();
      std::vector<Sign>& d = d_;
      d.resize(out_.edges.size());
      for (std::size_t j = 0; j < out_.edges.size(); ++j) {
        d[j] = k_.det_sign(out_.edges[j], out_.edges[(j + 1) % out_.edges.size()], g);
        if (d[j] == Sign::uncertain) return -1;
      }
      collapse(g, d);
      return 0;
    }
    // Replace the run first … last by (e_first.in, g) and (g, e_last.out).
    const std::size_t before = vs_[first].prev, after = vs_[last].next;
    const std::size_t n1 = new_vertex(vs_[first].in, g);
    const std::size_t n2 = new_vertex(g, vs_[last].out);
    link(before, n1);
    link(n1, n2);
    link(n2, after);
    // Pending generators of removed vertices move to n1 or n2, or become redundant.
    for (std::size_t v = first;; v = vs_[v].next) {
      vs_[v].alive = false;
      std::vector<std::size_t> bucket;
      bucket.swap(vs_[v].bucket);
      for (std::size_t q : bucket) {
        if (q == g || conflict_[q] != v) continue;
        conflict_[q] = kNone;
        for (std::size_t cand : {n1, n2}) {
          const Sign s = value(cand, q);
          if (s == Sign::uncertain) return -1;
          if (s == Sign::negative) {
            attach(q, cand);
            break;
          }
        }
      }
      if (v == last) break;
    }
    conflict_[g] = kNone;
    return 0;
  }

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
// inconsistent (a bug). Up to kSmallDualCone generators the plain clipping is used (no bookkeeping,
// fastest for grasps of a few contacts); beyond, randomized incremental construction in a fixed
// order: expected O(n log n) predicates. Both give the same cone (tests compare them).
inline constexpr std::size_t kSmallDualCone = 32;

template <class Kernel>
Dual_cone compute_dual_cone(const Kernel& kernel) {
  detail::Dual_cone_builder<Kernel> b(kernel);
  return kernel.size() <= kSmallDualCone ? b.run_simple() : b.run();
}

// Restricts a kernel to its first n rows as generators; predicates may still name row n and beyond
// (equilibrium asks det(g_a, g_b, w) with the load w as an extra row).
template <class Kernel>
struct First_rows {
  const Kernel& k;
  std::size_t n;
  std::size_t size() const { return n; }
  Sign cross_sign(std::size_t i, std::size_t j) const { return k.cross_sign(i, j); }
  Sign det_sign(std::size_t i, std::size_t j, std::size_t l) const { return k.det_sign(i, j, l); }
};

// [EQ-2] Is the load in kernel row `w` balanced, −w ∈ W, given the dual cone W* of the generators
// (decided, rank 3, so W* is the conic hull of its extreme rays g_a × g_b)? −w ∈ W ⇔ ⟨r, −w⟩ ≥ 0
// for every extreme ray r ⇔ det[g_a; g_b; w] ≤ 0 at every vertex; always when W* = {0}.
// Returns positive (balanced), negative (not balanced; `witness` = a vertex {a, b} whose ray
// g_a × g_b has power > 0 against the load) or uncertain.
template <class Kernel>
Sign load_balanced(const Kernel& kernel, const Dual_cone& dc, std::size_t w,
                   std::array<std::size_t, 2>* witness = nullptr) {
  if (!dc.decided || dc.rank < 3) throw std::logic_error("load_balanced: needs a decided rank-3 dual cone");
  if (dc.shape == Dual_shape::zero) return Sign::positive;
  const std::vector<std::size_t>& e = dc.edges;
  const std::size_t K = dc.shape == Dual_shape::ray ? 1 : e.size();
  for (std::size_t j = 0; j < K; ++j) {
    const std::size_t a = e[j], b = e[(j + 1) % e.size()];
    const Sign s = kernel.det_sign(a, b, w);
    if (s == Sign::uncertain) return s;
    if (s == Sign::positive) {
      if (witness) *witness = {a, b};
      return Sign::negative;
    }
  }
  return Sign::positive;
}

// The randomized construction whatever the size (for tests).
template <class Kernel>
Dual_cone compute_dual_cone_randomized(const Kernel& kernel) {
  return detail::Dual_cone_builder<Kernel>(kernel).run();
}

// The same cone by plain incremental clipping in input order, O(n·K): the reference the tests
// compare the randomized construction with.
template <class Kernel>
Dual_cone compute_dual_cone_reference(const Kernel& kernel) {
  return detail::Dual_cone_builder<Kernel>(kernel).run_simple();
}

}  // namespace wrenchkit
