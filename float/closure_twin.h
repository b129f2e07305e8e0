// [FL-3] The float twin of force and form closure: core/dual_cone.h [FC-1] over the certified
// Float_kernel [FL-2]. A robot-side C++ API on plain doubles; standard library only.
//
// Exactness: certified-or-undecided. `closed`/`open` is the exact answer for the contacts as given
// (each double taken as the exact value it denotes, or, for Bounded inputs, for every scene within
// the stated input errors — in particular the exact scene the bounds were derived from).
// `undecided` means a predicate was too close to zero for its error bound: ask the exact engine.
// Complexity: as FC-1, O(n·K) predicates of ~20 flops each.
#pragma once

#include <cstddef>
#include <vector>

#include "core/contact_generators.h"
#include "core/dual_cone.h"
#include "float/float_kernel.h"

namespace wrenchkit::fl {

// A point contact given by plain doubles: point, inward normal (nonzero, any length), μ ≥ 0.
struct Point_contact {
  double ax = 0, ay = 0, nx = 0, ny = 0, mu = 0;
};

// A contact with error-bounded coordinates, as the exact engine hands scenes to the twin: either a
// point contact (frictional decided from the exact μ ≠ 0) or a wrench generator (fx, fy, m).
struct Bounded_contact {
  bool is_wrench = false;
  Bounded ax, ay, nx, ny, mu;
  bool frictional = false;
  Bounded fx, fy, m;
};

// The generators in the order of core/contact_generators.h (the exact engine's order).
std::vector<Bounded3> generators(const std::vector<Bounded_contact>& contacts, Reading reading);

// Plain-double contacts as exact Bounded inputs (each double is the exact value it denotes).
// Throws std::invalid_argument for a zero normal, a negative or non-finite μ.
std::vector<Bounded_contact> bounded_contacts(const std::vector<Point_contact>& contacts);

// [FL-1 "Static generators"] The generators of plain-double contacts (each double exact), in the order
// of generators(), computed in plain doubles with a bound on each coordinate's rounding error taken from
// the formula (a few products of magnitudes with u = 2^-53; no TwoSum, no fma): appended to `out`, with
// their column bounds for Stage 0 in `columns` (if given), true. False, and `out` unchanged, when a
// nonzero input's magnitude is outside [2^-64, 2^64] (or not finite): the guard under which every
// operation rounds relative to its result and Stage 0's guard holds. Inputs validated by the caller.
// Exact zeros of the generators' determinants are not certified this way (the bounds are not 0): the
// robot-side calls use these first and the running-error generators only when a predicate is undecided.
bool static_generators(const std::vector<Point_contact>& contacts, Reading reading, std::vector<Bounded3>& out,
                       Float_kernel::Column_bounds* columns = nullptr);

enum class Verdict { closed, open, undecided };

// Force closure (friction reading) and first-order form closure (frictionless reading).
// Throws std::invalid_argument for a zero normal, a negative or non-finite μ.
Verdict force_closure(const std::vector<Point_contact>& contacts);
Verdict form_closure(const std::vector<Point_contact>& contacts);

// The same with the whole dual cone (indices into generators(…)), for callers that build
// certificates or labels from it.
Dual_cone dual_cone(const std::vector<Bounded_contact>& contacts, Reading reading);

}  // namespace wrenchkit::fl
