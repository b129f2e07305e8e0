// [SL-1] [SL-3] [RG-1] [RG-3] Does a load stick or slide on a support? One model of the support, one decision.
//
// The support (docs/theory-sliding.md §1): points, each with its normal force given or not, and regions with a known
// pressure. Its admissible distributions F = { f ≥ 0 : given forces kept, Σ f_i + Σ_R W_R = W, Σ f_i r_i + Σ_R M_R = W c }
// are data of the model: one distribution when every force is given, else a polytope whose vertices (the extreme
// distributions) are enumerated once, on first use. The load p is the wrench the slider applies to the support.
//
//   sticks     p is in the interior of LS(f) for every f ∈ F (LS is Minkowski-linear in f: ⇔ at every vertex of F):
//              friction holds it with margin;
//   impending  p is on LS(f) for every f ∈ F: friction can just hold it, and quasi-static slip with a twist in the
//              normal cone there is admitted too (the book's facets — a rotation about a support point — and
//              vertices); a flat LS (friction at fewer than two distinct points) is all surface;
//   slides     p is outside LS(f) for every f ∈ F;
//   depends    two of these occur over F (F has more than one distribution).
//
// decide_motion answers with plain witness data — the verdict, how it was decided, the witnesses a certificate is
// written from (exact/certificates/certificates.h, proofs/certificate-format.md §6) — whatever the support is made
// of. The strategies behind it (exact/sliding/strategies.h), cheapest certified means first:
//   every force given, points:  the float twin's certified search on the true surface (hybrid, float), the exact
//                               polygons [LS-3], Newton in multiple precision [SL-6]; then the witness: support forces
//                               strictly inside their discs (smoothed Newton, SL-6, the exact LP on inscribed N-gons),
//                               a twist with rational speed bounds whose power the load's exceeds, or on the surface a
//                               twist with exactly rational speeds whose power the load's meets and forces on the
//                               face that twist supports (rotations about support points, translations, the load,
//                               the search's and Newton's twists made rational);
//   every force given, regions: the twist minimising the power (in double) proposes; cells and slide blocks decide [RG-1];
//   some force not given:       each vertex of F by the above, then one twist for all of F (the LP over F, the regions'
//                               slide blocks), the union's minimax (points, hybrid), a distribution that sticks by the
//                               exact LP over F × inscribed N-gons [SL-3] [RG-3].
// Every verdict with witnesses is exact; what is not certified is `undecided` with the reason. Float mode (the twin
// alone) answers points with every force given; otherwise undecided (Undecided_error from decide_motion).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/mode.h"
#include "exact/sliding/distribution.h"
#include "exact/sliding/limit_surface.h"
#include "exact/sliding/region_sliding.h"

namespace wrenchkit {

// One model of a support: the scene's support and its admissible set F.
class Support_model {
 public:
  // Precondition: scene.support, accepted by read_scene (F is not empty).
  explicit Support_model(const Scene& scene);
  // A support built in code (the cells of regions as points, one distribution's forces put in place).
  Support_model(const Support& support, Admissible admissible);

  const Support& support() const { return *support_; }
  const Admissible& admissible() const { return admissible_; }
  // Every point's force is given: F is one distribution, given().
  bool known() const { return admissible_.known(); }
  const std::vector<Rational>& given() const { return admissible_.given; }
  bool has_regions() const { return !support_->regions.empty(); }
  // The vertices of F, each once (distribution.h `vertices`), enumerated on first use; {given()} when known.
  // Precondition: at most kMaxEnumeratedUnknowns unknown forces (std::length_error beyond; callers say why first).
  const std::vector<std::vector<Rational>>& extreme() const;

 private:
  const Support* support_;
  Admissible admissible_;
  mutable std::optional<std::vector<std::vector<Rational>>> extreme_;
};

// How a verdict was reached (the answers' "decided_by" and "motion_decided_by"; one list for motion and hold).
enum class Decided_by {
  none,              // undecided
  float_search,      // "float": the float twin's certified search on the true limit surface
  polygons,          // "polygons": the exact polygonal limit surfaces (motion), the exact LP on inscribed polygons (hold)
  newton,            // "newton": Newton's method in multiple precision, checked exactly [SL-6]
  flat,              // "flat": a flat limit surface (friction at fewer than two places) has no interior
  certificate,       // "certificate": found by its witness (regions; a flat surface met by the witness search)
  vertices,          // "vertices": every extreme distribution decided alike, or two decided apart
  twist,             // "twist": one twist for every distribution (motion), a candidate motion (hold)
  minimax,           // "minimax": the union's minimax over the extreme distributions [SL-3]
  lp,                // "lp": a distribution found by the exact LP over F (motion)
  lp_over_f,         // "lp over F": the exact LP over F × inscribed polygons (hold)
  zero_load,         // "zero load" (hold)
  equilibrium,       // "equilibrium": the contacts alone (hold)
  smoothed_witness,  // "smoothed witness": Newton in double proposes, one exact round (hold)
};
const char* decided_by_name(Decided_by d);
// The same for a sentence: "the float twin's certified search on the true limit surface", "the exact polygons", …
const char* decided_by_words(Decided_by d);

// The witnesses of one distribution f (proofs/certificate-format.md §6.1, §6.4, §7.1):
//   stick — support forces g_i, one per point, |g_i| < μ_i f_i (closed, ≤, when the load is on the surface), and one
//           stick block per region, that sum to the load (hold: with the contacts, to −w_L);
//   slide — a twist q ≠ 0 with rational speed bounds u_i ≥ |v_i(q)|, one per point, and one slide block per region,
//           whose power bound the load's power exceeds (meets, when the load is on the surface). For every distribution
//           of F: `distribution` empty, the LP dual (y0, yx, yy) over F in `dual`.
// A load on the surface has both: forces in the closed discs and a twist whose power bound the load's meets — then
// every bound is the exact speed, and the twist's plane supports LS(f) at the load.
struct Stick_witness {
  std::vector<Rational> distribution;  // one force per support point
  std::vector<Vec2> forces;            // one per support point
  std::vector<Region_stick_block> regions;
};
struct Slide_witness {
  std::vector<Rational> distribution;  // empty: every distribution of F (then `dual`)
  Vec3q twist;
  std::vector<Rational> speed_bounds;  // one per support point
  std::vector<Region_slide_block> regions;
  std::optional<std::array<Rational, 3>> dual;
};

struct Impending_witness {
  Stick_witness forces;  // closed discs
  Slide_witness twist;   // its power bound met
};

struct Motion_answer {
  Motion motion = Motion::undecided;
  Decided_by decided_by = Decided_by::none;
  // What the certificate is written from. Every force given: `sticking`, `impending` or `sliding`. Some force not
  // given: sticks — `vertices` (a strict stick witness per vertex of F); impending — `vertices` (closed) and `sliding`
  // (every distribution's twist, its bound met); slides — `sliding` (every distribution's); depends — `sticking` and
  // `sliding` of two distributions, one of them strict: one distribution inside and another not (sticks against
  // impending or slides), or one in its closed set and another outside (impending or sticks against slides).
  std::optional<Stick_witness> sticking;
  std::optional<Impending_witness> impending;
  std::optional<Slide_witness> sliding;
  std::vector<Stick_witness> vertices;
  // depends: what the distributions of `sticking` and `sliding` do (sticks or impending; impending or slides).
  Motion held_as = Motion::sticks, moved_as = Motion::slides;
  // How, for the answer's readers: each vertex's own verdict (some force not given), the float search's twists and its
  // sliding twist (points, every force given), the regions' estimate of the gauge (every force given) and the cells
  // of the certificate's blocks.
  std::vector<Motion> per_vertex;
  std::size_t search_twists = 0;
  std::array<double, 3> search_twist{};
  double gauge_estimate = 0;
  std::size_t cells = 0;
  std::string undecided_why;
  // A verdict for which no rational witness was found: reported undecided, with this sentence.
  std::string uncertified;
};

// The polytopes of a known support of points when the caller has built them (limit-surface lists them): the polygons'
// decision and the twists to try use them instead of building their own.
struct Built_polygons {
  const Polygonal_ls* model = nullptr;
  const Ls_polytope* inner = nullptr;
  const Ls_polytope* outer = nullptr;
};

struct Motion_options {
  int sides = 32;           // the polygons' sides N (every force given; the LPs' first N)
  Built_polygons polygons;  // optional
};

// The one decision. Throws Input_error beyond kMaxEnumeratedUnknowns unknown forces, Undecided_error-free: float mode
// answers what the twin decides and `undecided` otherwise (the pipeline makes float's undecided an Undecided_error).
Motion_answer decide_motion(const Support_model& model, const Vec3q& load, Mode mode, const Motion_options& options = {});

}  // namespace wrenchkit
