// [FC-2] [FC-3] Force closure and first-order form closure, exact, with certificates.
//
// Force closure (Mason Def. 5.4): the possible resultants W = pos{contact wrench generators} are all
// of R³, equivalently W* = {0} (theory.md §3–4). First-order form closure: the same contacts read
// frictionless admit no nonzero first-order twist (theory.md §7), i.e. the frictionless cone is R³.
//
// Decision: core/dual_cone.h [FC-1] with the exact kernel. Every answer carries a certificate
// (proofs/certificate-format.md):
//   holds  — strictly positive rational weights on generators summing to the zero wrench, three of
//            which have a nonzero determinant [FC-2]; found by the exact LP [FC-4], run in integers
//            on the kernel's rows [FC-5], on the few generators that closed the dual cone;
//   !holds — a nonzero twist with power ≥ 0 against every generator [FC-3]: an extreme ray of W*,
//            or the normal of span W when rank W < 3.
// Exact, never perturbed; every degenerate case of theory.md §5.6 is an ordinary input.
// Complexity O(n·K) predicates (see dual_cone.h) plus O(K) exact work for the certificate.
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "core/dual_cone.h"
#include "exact/statics/generators.h"
#include "core/mode.h"

namespace wrenchkit {

enum class Property { force_closure, form_closure };

const char* property_name(Property p);
Reading reading_of(Property p);

struct Generator_ref {
  std::size_t contact = 0;
  Edge edge = Edge::normal;
};

struct Closure_certificate {
  Property property = Property::force_closure;
  bool holds = false;
  std::vector<std::pair<Generator_ref, Rational>> combination;  // holds: weights > 0
  std::array<Generator_ref, 3> independent{};                   // holds
  std::array<Rational, 3> twist;                                // !holds: primitive integers
};

struct Closure_answer {
  Mode mode = Mode::exact;
  bool decided = true;           // false only in Mode::float_only: then nothing below is set
  bool holds = false;
  int rank = 0;                  // rank of the generators
  std::size_t generators = 0;    // number of generators under the reading
  Dual_shape shape = Dual_shape::lineality;
  Closure_certificate certificate;   // built exactly from the decision's indices, in every mode
  std::size_t predicates = 0;        // signs the algorithm asked for
  std::size_t exact_predicates = 0;  // of which decided in exact arithmetic
  // "exact", "float" (no exact predicate) or "hybrid" (some of each): core/mode.h's rule.
  Arithmetic decided_by() const { return wrenchkit::decided_by(mode, predicates, exact_predicates); }
};

// `certify` false skips building the certificate (for throughput measurements and callers that
// only need the verdict); every command of the CLI certifies.
Closure_answer decide_closure(const Scene& scene, Property property, Mode mode = Mode::exact,
                              bool certify = true);

// [FC-5] Certificate parts from the integer rows of an exact kernel built With_provenance (also
// used by equilibrium): the primitive twist positively parallel to row_a × row_b (rows not parallel, else
// std::logic_error), and the positive
// certificate [FC-2] from generators H with pos(H) = R³ (weights on the unscaled generators,
// coprime integers). Throws std::logic_error if pos(H) ≠ R³ (a bug of the caller).
std::array<Rational, 3> twist_of_ray(const Exact_kernel& k, std::size_t a, std::size_t b);
void positive_certificate(const Exact_kernel& k, std::vector<std::size_t> H, Closure_certificate& cert);

// The twist read as a point of the two-sided plane, P(t) = (−vy, vx, w) (theory.md §2.2):
// label '+' or '-' with the rotation centre, or 'i' (infinity) with a primitive direction
// ((0, 0) for the zero twist, which is no certificate).
struct Twist_reading {
  char label = 'i';
  std::array<Rational, 2> point;  // or direction
};
Twist_reading read_twist(const std::array<Rational, 3>& t);

}  // namespace wrenchkit
