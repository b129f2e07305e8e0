// [ST-1] Scene families for stress tests, benchmarks and the reference corpus: scenes at a controlled
// distance ε from a degenerate configuration (friction threshold, friction-cone edge, concurrent
// normals, parallel walls, huge offsets, the ladder's μ* = 1/7), and random scenes (generic decimal
// text; degenerate-rich integer grids), each written as scene JSON text as a user would write it.
//
// One API for every user (fuzz/stress_closure, `wrenchkit reference`, bench/): family name, ε, seed →
// scene text + the distance parameter, plus the doubles the text was printed from (for "naive"
// variants that parse the same text with strtod). Deterministic on every platform: mt19937_64 (fully
// specified by the C++ standard), uniform doubles built from its bits, and only +, −, ×, ÷ on doubles
// (correctly rounded by IEEE 754; no libm call, no std::uniform_*_distribution, whose output the
// standard leaves to the implementation). Rotations are rational-parametrised: (1−t², 2t)/(1+t²).
//
// Exactness: the TEXT is the scene. Numbers are printed with 17 significant digits, so the exact
// scene the engine reads is the double the family chose; rotations and offsets are applied in double,
// so the exact distance to the degenerate configuration is ε only up to rounding — the family's ε is
// a nominal distance, and the reference corpus computes a measured one for every scene.
// Standard library only.
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <string_view>
#include <vector>

namespace wrenchkit::stress {

// A point contact as the doubles a family chose; `mu_text` (an exact fraction) is written instead of
// mu when set.
struct Contact_spec {
  double ax = 0, ay = 0, nx = 0, ny = 0, mu = 0;
  std::string mu_text;
};

// Gravity w at (cx, cy), for the equilibrium families.
struct Gravity_spec {
  bool present = false;
  double cx = 0, cy = 0, w = 1;
};

// What a family's scenes are made to test.
enum class Question { force_closure, form_closure, equilibrium, all };

struct Family {
  const char* name;
  const char* what;       // one line for reports
  Question question;
  bool uses_epsilon;      // false: random scenes (ε is ignored)
};

// The families, in a fixed order: the six near-degenerate families of docs/stability.md, then
// "random_generic" (3–8 contacts with 3-decimal coordinates and μ, sometimes a load) and
// "random_grid" (0–6 contacts on a small integer grid with axis and diagonal normals, μ ∈ {0, 1/4,
// 1/3, 1/2, 1, 2}, a few wrench generators, sometimes a load and a support: parallel, concurrent,
// coincident and cone-edge configurations are frequent).
const std::vector<Family>& families();
const Family* find_family(std::string_view name);  // nullptr when unknown

struct Family_scene {
  std::string family;
  double epsilon = 0;           // the nominal distance (0 for random families)
  bool above = false;           // which side of the degenerate configuration (+ε or −ε)
  std::string text;             // the scene, JSON (one line)
  std::vector<Contact_spec> contacts;  // the doubles printed in `text` (not for random_* families)
  Gravity_spec gravity;
};

// A deterministic random source (mt19937_64 and IEEE arithmetic only; see the file comment).
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : g_(seed) {}
  std::uint64_t bits() { return g_(); }
  bool coin() { return (g_() & 1) != 0; }
  double unit();                        // uniform in [0, 1), 53 random bits
  double uniform(double a, double b);   // a + (b − a)·unit()
  int integer(int lo, int hi);          // uniform in [lo, hi] (rejection sampling)

 private:
  std::mt19937_64 g_;
};

// The next scene of `family` at distance ε, drawing from `rng` (the stress tool draws many scenes
// from one generator). Throws std::invalid_argument for ε outside (0, 1) on a family that uses it.
Family_scene make_scene(const Family& family, double epsilon, Rng& rng);
// One scene from a seed: make_scene(family, ε, Rng(seed)). Throws std::invalid_argument for an
// unknown family.
Family_scene make_scene(std::string_view family, double epsilon, std::uint64_t seed);

// Decimal text with 17 significant digits: exactly the double, read back exactly by the engine and
// to the same double by strtod.
std::string number_text(double x);

}  // namespace wrenchkit::stress
