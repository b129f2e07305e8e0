// [ST-1] Scene families for stress tests, benchmarks and the reference corpus: scenes at a controlled
// distance ε from a degenerate configuration (friction threshold, friction-cone edge, concurrent
// normals, parallel walls, huge offsets, the ladder's μ* = 1/7; exact thresholds written as long
// fractions, turned by exact rational rotations, scaled to 10^±300 and beyond the double range, held by
// 10^3–10^4 contacts; a nearly collinear sliding support with a load near its limit surface), and
// random scenes (generic decimal text; degenerate-rich integer grids), each written as scene JSON text
// as a user would write it.
//
// One API for every user (fuzz/stress_report, `wrenchkit reference`, bench/): family name, ε, seed →
// scene text + the distance parameter, plus the doubles the text was printed from (for "naive"
// variants that parse the same text with strtod). Deterministic on every platform: mt19937_64 (fully
// specified by the C++ standard), uniform doubles built from its bits, and only +, −, ×, ÷ on doubles
// (correctly rounded by IEEE 754; no libm call, no std::uniform_*_distribution, whose output the
// standard leaves to the implementation). Rotations are rational-parametrised: (1−t², 2t)/(1+t²).
//
// Exactness: the TEXT is the scene. Two kinds of families:
// * nominal (friction_threshold, cone_edge, nearly_concurrent, nearly_parallel, huge_offset): numbers
//   are printed with 17 significant digits (read back to the same double by strtod); rotations and
//   offsets are applied in double, so the exact distance to the degenerate configuration is ε only up
//   to rounding — the family's ε is a nominal distance, and the reference corpus measures one for
//   every scene;
// * exact (`known` below: ladder_equilibrium and every family added with it in issue 6): the scene is
//   built in exact rational arithmetic (GMP integers; exact, hence the same on every platform) from
//   ε' = 10^-k, a power of ten within a factor 5 of ε (ε itself when ε = 10^-k), and written exactly
//   (decimals when the denominator is 2^a·5^b, else "p/q" strings), so the answer is known by
//   construction for every ε:
//   closure holds (the load is balanced, the load slides) iff `above`. The doubles handed to naive
//   variants are what naive code reads from that text (strtod, and p/q as strtod(p)/strtod(q)).
// The header needs the standard library only.
#pragma once

#include <array>
#include <cstdint>
#include <random>
#include <string>
#include <string_view>
#include <vector>

namespace wrenchkit {
struct Scene;
}

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

// What a family's scenes are made to test. stick_slide: does the load `Family_scene::load_text`
// stick or slide on the support's (true) limit surface (exact/sliding/motion.h decide_motion)?
// stick_slide_over: the support's distribution is unknown: does the load stick for every admissible
// distribution, slide for every one, or does it depend (exact/sliding/motion.h)?
// hold: can the contacts and the support's friction hold the body against the load (exact/fixture/hold.h)? A
// `known` hold scene holds iff not `above`.
// stick_slide_region: does the load stick or slide on a support with regions (continuous pressure) [RG-1]?
enum class Question { force_closure, form_closure, equilibrium, all, stick_slide, stick_slide_over, hold,
                      stick_slide_region, push, push_contact, push_stable };

// stick_slide_over: the answers a scene's construction leaves possible (a bit set).
enum Motion_answer : unsigned { answer_sticks = 1, answer_slides = 2, answer_depends = 4 };

struct Family {
  const char* name;
  const char* what;       // one line for reports
  Question question;
  bool uses_epsilon;      // false: random scenes (ε is ignored)
  bool known = false;     // exact by construction: every scene's answer is its side (Family_scene::known)
};

// The families of the reference corpus (`wrenchkit reference` enumerates this list), in a fixed
// order: the six near-degenerate families of the first corpus, then "random_generic" (3–8 contacts with
// 3-decimal coordinates and μ, sometimes a load) and "random_grid" (0–6 contacts on a small integer
// grid with axis and diagonal normals, μ ∈ {0, 1/4, 1/3, 1/2, 1, 2}, a few wrench generators,
// sometimes a load and a support: parallel, concurrent, coincident and cone-edge configurations are
// frequent), then the exact families long_rational and rational_rotation (appended, so the earlier
// corpus scenes keep their seeds and bytes).
const std::vector<Family>& families();
// Families for the stress report only (docs/stability.md): "huge_scale", "tiny_scale" and
// "beyond_double" (numbers beyond 10^±250: the corpus' boundary measure and `compare` do not handle
// them yet — see docs/stability.md), "many_contacts" (10^3–10^4 contacts, too large for the corpus and
// its O(k³) brute-force test) and "collinear_support" (a stick/slide question, which the corpus format
// does not carry), "unknown_support" (stick/slide over every admissible distribution: random supports of
// 4–8 points, the four-legged table and the dinner plate, loads 10^-k from the thresholds), "fixture_pin"
// (hold: a frictionless pin pushing through the centre of friction of a symmetric support, the push
// μW·(1 ± 10^-k): holds iff below), "push_near_tie" (push: the pusher's velocity 10^-k beside the line to the
// centre of friction, the cone's edges apart: it turns ccw iff above), "push_motion_cone" (push --contact: the
// pusher's velocity 10^-k beside a motion-cone edge — the left friction-cone edge's line through the centre of
// friction —: it slides left iff above, else it sticks), "push_fence_edge" (push with a line pusher: a fence
// translating 10^-k beside its friction cone's left edge: stable iff below, PU-3 §8).
const std::vector<Family>& report_only_families();
const Family* find_family(std::string_view name);  // either list; nullptr when unknown

// A support point as naive code reads it from the text (doubles).
struct Support_spec {
  double x = 0, y = 0, force = 0, mu = 0;
};

struct Family_scene {
  std::string family;
  double epsilon = 0;           // the nominal distance (0 for random families)
  bool above = false;           // which side of the degenerate configuration (+ε or −ε)
  // Exact by construction: the answer is `above` (closure holds / the load is balanced / it slides).
  bool known = false;
  std::string text;             // the scene, JSON (one line)
  std::vector<Contact_spec> contacts;  // the doubles of `text` (not for random_* families)
  Gravity_spec gravity;
  // A scene with exactly the same answers by an exact symmetry (the grasp before its exact rotation,
  // translation and scaling), for a second exact route; empty when the family has none.
  std::string untransformed;
  // stick_slide: the load (fx, fy, m) as exact number texts, and as naive doubles; the support's doubles.
  std::array<std::string, 3> load_text;
  std::array<double, 3> load{};
  std::vector<Support_spec> support;  // stick_slide_over: an unknown force as the naive even split of the rest
  unsigned allowed = 0;               // stick_slide_over: the Motion_answer bits the construction allows
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

// A generic fixture for hold's benchmarks (not near-degenerate): `points` known support points in [−1, 1]²
// (3 decimals, forces in [0.1, 1], μ in [0.2, 0.8]), `contacts` frictional contacts on the circle of radius 1.5
// pushing roughly inward (μ in [0.1, 0.6]), and a force at a random point of the square whose magnitude is `load`
// times the support's Σ μ_i f_i, in a random direction: about half of the scenes hold at load = 1.
std::string fixture_text(Rng& rng, int contacts, int points, double load);

// Decimal text with 17 significant digits: read back to the same double by strtod (the engine reads
// the decimal exactly, which is within half an ulp of 10^-17 relative of the double).
std::string number_text(double x);

// What naive code reads from a number's text: strtod, and "p/q" as strtod(p)/strtod(q) (quotes
// allowed). Out of the double range: ±inf or 0, as strtod gives.
double naive_double(std::string_view text);

// [PU-2] The contact mode as naive double code finds it, for a scene with a pusher and a support of points with every
// force given: the numbers' nearest doubles, ω* by bisection of the load's moment about the pusher (200 halvings in
// raw doubles), the load's force there against the friction cone's edges by raw double cross products. A guess
// (no error bound): "sticks", "slides left" or "slides right" (the nearer side when outside both edges' half-planes).
const char* naive_push_contact(const Scene& scene);

// [PU-3 §8] A translating line pusher's stable push as naive double code decides it: the numbers as strtod reads
// their text (naive_double) and the four facets' cross products in raw doubles (v × e₊, e₋ × v, the line through c
// along v against each end) — a guess: "stable" when none is negative, else "unstable".
const char* naive_push_stable(const Scene& scene);

}  // namespace wrenchkit::stress
