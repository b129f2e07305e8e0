// [SL-4] Certificates of stick / slide answers (proofs/certificate-format.md §6, property "motion"), built
// in exact rationals with no square root: support forces inside the friction discs (a stick witness, from
// the exact LP on inscribed N-gons), rational upper bounds of the speeds (u_i² ≥ |v_i(q)|²), and for an
// unknown distribution the LP dual over F. Every certificate is re-checked by the independent checker in the
// pipeline before an answer is given.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "exact/io/json_writer.h"
#include "exact/sliding/unknown_motion.h"

namespace wrenchkit {

class Json_writer;

struct Slide_witness {
  std::vector<Rational> distribution;
  Vec3q twist;
  std::vector<Rational> speed_bounds;  // u_i ≥ |v_i(q)|, one per support point
};

// Rational upper bounds of the speeds |v_i(q)| of every support point (square-root brackets of `bits` bits).
std::vector<Rational> speed_bounds(const Support& s, const Vec3q& q, int bits = 80);

// The slide witness of q (≠ 0) for the distribution f when q·p ≥ Σ μ_i f_i u_i (p on or past the limit surface:
// it slides); nothing otherwise. The speeds are bounded to 80 bits, and when that does not prove it and q has long
// numbers (the precise Newton's twists, SL-6), to 2·b + 64 bits, b the longest component's bits.
std::optional<Slide_witness> slide_witness(const Support& s, const std::vector<Rational>& f, const Vec3q& p,
                                           const Vec3q& q);

// Support forces and non-negative multiples of the `cone`'s wrenches c_j that sum to p exactly:
// Σ_i (g_i, r_i × g_i) + Σ_j weights_j c_j = p with g_i·g_i < (μ_i f_i)² (g_i = 0 where μ_i f_i = 0). With an empty
// cone, a stick witness (friction at two distinct points is required, as for it); with the contacts' wrench
// generators, the support's part and the contacts' part of a hold witness (exact/fixture/hold.h). Found by
// Newton's method in double on a smoothed dual, then made exact by one rational 3×3 solve and checked exactly
// (SL-4); nothing when it does not verify. `probe`: first whether p itself is reachable (a Newton run at σ → 1);
// when not, nothing, and `escape` (if given) gets the run's last dual iterate λ, along which the smoothed dual
// decreases without bound: λ·p > h_f(λ) and λ·c_j ≤ 0 to first order (a candidate separating twist).
// `short_numbers`: the exact round's weights rounded to a few more bits than the slack needs (shorter certificates).
struct Support_witness {
  std::vector<Vec2> forces;       // g_i, one per support point
  std::vector<Rational> weights;  // one per cone wrench, ≥ 0
};
std::optional<Support_witness> smoothed_witness(const Support& s, const std::vector<Rational>& f, const Vec3q& p,
                                                const std::vector<Vec3q>& cone, bool probe,
                                                std::array<double, 3>* escape, bool short_numbers);

// A stick witness for the distribution f: the smoothed Newton witness (forces along one twist's velocities, an
// exact last round), else the precise one (SL-6: Newton in multiple precision, an exact last round), else the
// exact LP on inscribed N-gons, N = sides, 2·sides, … up to 256 sides, as long as the LP stays within
// kMaxStickWitnessColumns columns (support points × sides; the exact simplex grows fast).
constexpr std::size_t kMaxStickWitnessColumns = 2048;
std::optional<Stick_witness> stick_witness_refined(const Support& s, const Admissible& a, const Vec3q& p, int sides,
                                                   const std::vector<Rational>& f);

// The certificates' block of support forces: [[gx, gy], …], one pair per support point (motion and hold alike).
void write_support_forces(Json_writer& w, const std::vector<Vec2>& g);

// The smoothed Newton witness alone (stick_witness_refined's first step; the support's points may be any discrete
// distribution, e.g. a region's cells as points): forces along one twist's velocities, one exact last round, each
// disc checked exactly. Nothing when it does not verify.
std::optional<Stick_witness> smoothed_stick_witness(const Support& s, const std::vector<Rational>& f, const Vec3q& p);

// [SL-6] The precise witnesses of the distribution f: the support's points with ρ_i = μ_i f_i for precise_motion
// (exact/sliding/precise_motion.h): a stick witness, or a slide witness (strict: Σ μ_i f_i u_i < q·p), or neither.
struct Precise_witness {
  std::optional<Stick_witness> sticks;
  std::optional<Slide_witness> slides;
};
Precise_witness precise_witness(const Support& s, const std::vector<Rational>& f, const Vec3q& p);

// A motion certificate's object, opened, with its first members ("wrenchkit_certificate", "property", "load",
// "motion"); `version` 2 only where format 1 has no certificate (regions with a force not given, §6.5).
Json_writer motion_certificate_head(const Vec3q& p, const char* motion, int version = 1);

// The certificates, as JSON text (format 1).
std::string sticks_certificate(const Vec3q& p, const Stick_witness& w);                   // every force given
std::string slides_certificate(const Vec3q& p, const Slide_witness& w);                   // every force given
std::string sticks_for_every_certificate(const Vec3q& p, const std::vector<Stick_witness>& vertices);
std::string slides_for_every_certificate(const Vec3q& p, const Vec3q& q, const std::vector<Rational>& u,
                                         const std::array<Rational, 3>& dual);
std::string depends_certificate(const Vec3q& p, const Stick_witness& sticking, const Slide_witness& sliding);

}  // namespace wrenchkit
