// Near-degenerate scene families, shared by the stress report (fuzz/stress_closure.cpp,
// docs/stability.md), the benchmarks (bench/, docs/benchmarks.md) and reference corpora.
//
// A family builds, from random base parameters and a distance ε to a degenerate configuration, a
// scene written as decimal text with 17 significant digits (what the double prints; the engine
// reads it exactly, a naive reader gets the same doubles back). Its question is force closure,
// first-order form closure or equilibrium of a gravity load. The expected verdict is the exact
// engine's (Mode::exact), itself verified against brute force in tests/: the construction only
// aims at the boundary, rounding to 17 digits decides the side.
//
//   const families::Family& f = *families::find("cone_edge");
//   families::Case c = families::make_case(f, 1e-12, /*seed*/ 7);   // c.text, c.expected
//
// Also here: the naive reading of a case (raw double signs, through the same generic algorithms
// as the certified twin), which only measurements may use, and generic random grasps for
// throughput measurements.
#pragma once

#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "exact/closure.h"
#include "float/float_kernel.h"

namespace wrenchkit::families {

// A point contact in doubles: at (ax, ay), inward normal (nx, ny), friction mu (or `mu_text`, an
// exact fraction, written instead when set).
struct Spec {
  double ax, ay, nx, ny, mu;
  std::string mu_text = "";
};

// Gravity w at (cx, cy), for equilibrium families.
struct Gravity {
  bool present = false;
  double cx = 0, cy = 0, w = 1;
};

enum class Question { force_closure, form_closure, equilibrium };
const char* question_name(Question q);

struct Family {
  const char* name;
  const char* what;
  Question question;
  // Contacts at distance eps from the degeneracy, from rng (and the load of equilibrium families).
  std::function<std::vector<Spec>(std::mt19937_64& rng, double eps, Gravity& load)> make;
};

// The families, in report order: friction_threshold, cone_edge, nearly_concurrent, nearly_parallel,
// huge_offset, ladder_equilibrium.
const std::vector<Family>& all();
// nullptr if no family has this name.
const Family* find(std::string_view name);

struct Case {
  std::string family;
  double eps = 0;
  Question question = Question::force_closure;
  std::vector<Spec> contacts;
  Gravity load;
  std::string text;       // the scene (JSON), as a user writes it
  bool expected = false;  // the exact verdict (closure holds / load balanced)
};

// Decimal text of x with 17 significant digits.
std::string num(double x);
// The scene JSON of contacts (and the load when present).
std::string scene_text(const std::vector<Spec>& contacts, const Gravity& load = {});

// The next case of a family from a running generator (the stress report draws a family's cases
// for every ε from one stream), or from its own seed.
Case make_case(const Family& f, double eps, std::mt19937_64& rng);
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
// The naive generators of a closure case (the contacts' doubles, raw double arithmetic) under the
// case's reading, for naive variants of other constructions (labels).
std::vector<fl::Bounded3> naive_generators(const Case& c);

// Generic random grasps for throughput (not near-degenerate): `contacts` contacts on the unit
// circle (6 decimals), inward normals perturbed by up to ±0.3, μ in [0.1, 0.6] (3 decimals).
// Mostly force closure, sometimes not.
std::string random_grasp_text(int contacts, std::mt19937_64& rng);

}  // namespace wrenchkit::families
