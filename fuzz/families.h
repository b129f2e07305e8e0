// The near-degenerate scene families as measurements use them (the stress report fuzz/stress_closure.cpp,
// docs/stability.md; the benchmarks bench/, docs/benchmarks.md): exact/stress_families.h [ST-1] builds
// the scenes (one generator for the reference corpus, the stress report and the benchmarks); this layer
// adds what measurements need on top — the exact verdict of a case, the NAIVE reading of the same
// doubles (raw double signs; a guess, for measurements only) and generic random grasps of any size.
//
//   const families::Family& f = *families::find("cone_edge");
//   stress::Rng rng(7);
//   families::Case c = families::make_case(f, 1e-12, rng);   // c.text, c.expected
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "exact/closure.h"
#include "exact/stress_families.h"
#include "float/float_kernel.h"

namespace wrenchkit::families {

using Family = stress::Family;
using Question = stress::Question;
using Spec = stress::Contact_spec;
using Gravity = stress::Gravity_spec;

const char* question_name(Question q);

// The families with a distance ε, in report order: friction_threshold, cone_edge, nearly_concurrent,
// nearly_parallel, huge_offset, ladder_equilibrium.
const std::vector<Family>& all();
const Family* find(std::string_view name);  // nullptr if no family has this name

struct Case {
  std::string family;
  double eps = 0;
  Question question = Question::force_closure;
  std::vector<Spec> contacts;  // the doubles printed in `text`
  Gravity load;
  std::string text;            // the scene (JSON), as a user writes it
  bool expected = false;       // the exact verdict (closure holds / load balanced)
};

// The next case of a family from a running generator (the stress report draws a family's cases for every
// ε from one stream), or from its own seed.
Case make_case(const Family& f, double eps, stress::Rng& rng);
Case make_case(const Family& f, double eps, std::uint64_t seed);

// The exact verdict of a parsed scene for a question, in any mode; `decided` false only when
// Mode::float_only abstains.
struct Verdict {
  bool decided = true, holds = false;
};
Verdict decide(const Scene& scene, Question q, Mode mode);

// The naive verdict: the contacts' doubles with raw double signs (fl::Naive_kernel) through
// core/dual_cone.h. A guess; for measurements only.
bool naive_verdict(const Case& c);
// The naive generators of a closure case (the contacts' doubles, raw double arithmetic) under the case's
// reading, for naive variants of other constructions (labels).
std::vector<fl::Bounded3> naive_generators(const Case& c);

// Generic random grasps for throughput (not near-degenerate): `contacts` contacts on the unit circle
// (6 decimals), inward normals perturbed by up to ±0.3, μ in [0.1, 0.6] (3 decimals).
std::string random_grasp_text(int contacts, stress::Rng& rng);

}  // namespace wrenchkit::families
