// The near-degenerate scene families as measurements use them (the stress report fuzz/stress_report.cpp,
// docs/stability.md; the benchmarks bench/, docs/benchmarks.md): testing/stress_families.h [ST-1] builds
// the scenes (one generator for the reference corpus, the stress report and the benchmarks); this layer
// adds what measurements need on top — the truth of a case, the NAIVE reading of the same doubles (raw
// double signs; a guess, for measurements only) for closure, equilibrium, moment labels and stick/slide,
// and generic random grasps of any size.
//
//   const families::Family& f = *families::find("cone_edge");
//   stress::Rng rng(7);
//   families::Case c = families::make_case(f, 1e-12, rng);   // c.text, c.expected
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "exact/statics/closure.h"
#include "exact/sliding/limit_surface.h"
#include "exact/statics/moment_labels.h"
#include "testing/stress_families.h"
#include "float/float_kernel.h"
#include "float/labels_twin.h"

namespace wrenchkit::families {

using Family = stress::Family;
using Question = stress::Question;
using Spec = stress::Contact_spec;
using Gravity = stress::Gravity_spec;

const char* question_name(Question q);

// The six families of the benchmarks (docs/benchmarks.md), in report order: friction_threshold,
// cone_edge, nearly_concurrent, nearly_parallel, huge_offset, ladder_equilibrium.
const std::vector<Family>& all();
// Every family with a distance ε, in the stress report's order: the corpus families of
// stress::families(), then stress::report_only_families().
const std::vector<Family>& report();
const Family* find(std::string_view name);  // among report(); nullptr if no family has this name

struct Case {
  std::string family;
  double eps = 0;
  Question question = Question::force_closure;
  std::vector<Spec> contacts;  // the doubles naive code reads from `text`
  Gravity load;
  std::string text;            // the scene (JSON), as a user writes it
  // The truth: closure holds / the load is balanced / the load slides. `known`: by construction (the
  // family is exact, expected = above); otherwise the exact engine's verdict.
  bool expected = false;
  bool known = false;
  bool above = false;
  std::string untransformed;   // the same answers by an exact symmetry (stress::Family_scene), or ""
  // stick_slide: the load (exact) and the doubles naive code reads for it and for the support.
  Vec3q motion_load;
  std::array<double, 3> motion_load_naive{};
  std::vector<stress::Support_spec> support;
  unsigned allowed = 0;  // stick_slide_over: the answers the construction leaves possible (stress::Motion_answer)
};

// The next case of a family from a running generator (the stress report draws a family's cases for every
// ε from one stream), or from its own seed.
Case make_case(const Family& f, double eps, stress::Rng& rng);
Case make_case(const Family& f, double eps, std::uint64_t seed);

// The exact verdict of a parsed scene for a closure or equilibrium question, in any mode; `decided`
// false only when Mode::float_only abstains.
struct Verdict {
  bool decided = true, holds = false;
};
Verdict decide(const Scene& scene, Question q, Mode mode);
Reading reading_of(Question q);  // frictionless for form closure, friction otherwise

// The naive verdict: the contacts' doubles with raw double signs (fl::Naive_kernel) through
// core/dual_cone.h. A guess; for measurements only.
bool naive_verdict(const Case& c);
// The naive generators of a closure case (the contacts' doubles, raw double arithmetic) under the case's
// reading, for naive variants of other constructions (labels).
std::vector<fl::Bounded3> naive_generators(const Case& c);

// Stick/slide of a stick_slide case (holds = slides) [LS-3] [FL-7]: exact — the polygonal bounds with
// `sides` directions (undecided when the load is within their gap of the limit surface); hybrid —
// points_verdict of exact/sliding/strategies.h (the certified search, the polygons only when it is undecided); float —
// fl::classify_load alone.
Verdict decide_motion(const Case& c, const Scene& scene, Mode mode, int sides);
// The naive stick/slide: minimise f(q) = h(q) − q·p over twists in plain doubles without error bounds
// (the centres of an 8×8 grid on each face of the twist cube, then a compass search from the best one,
// steps halved down to 2^-60); slides iff some f(q) ≤ 0. A guess; for measurements only.
bool naive_slides(const Case& c);
// The naive stick/slide of a case with regions: the double closed form of the regions' power minimised on the plane
// q·p = 1 without bounds (points whose force is not given at the naive even split); slides iff the minimum is at
// most 1. A guess; for measurements only.
bool naive_region_slides(const Case& c);

// The combinatorics of a labeling: shapes and vertex/direction counts of R+, R−, the ± set and R∞.
std::string labels_signature(const Moment_labels& l);
std::string labels_signature(const fl::Labels_twin& l);

// Generic random grasps for throughput (not near-degenerate): `contacts` contacts on the unit circle
// (6 decimals), inward normals perturbed by up to ±0.3, μ in [0.1, 0.6] (3 decimals).
std::string random_grasp_text(int contacts, stress::Rng& rng);

}  // namespace wrenchkit::families
