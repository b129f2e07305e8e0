// [SL-4] Certificates of stick / slide answers (proofs/certificate-format.md §6, property "motion"), built
// in exact rationals with no square root: support forces inside the friction discs (a stick witness, from
// the exact LP on inscribed N-gons), rational upper bounds of the speeds (u_i² ≥ |v_i(q)|²), and for an
// unknown distribution the LP dual over F. Every certificate is re-checked by the independent checker in the
// pipeline before an answer is given.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "exact/io/json_writer.h"
#include "exact/sliding/unknown_motion.h"

namespace wrenchkit {

struct Slide_witness {
  std::vector<Rational> distribution;
  Vec3q twist;
  std::vector<Rational> speed_bounds;  // u_i ≥ |v_i(q)|, one per support point
};

// Rational upper bounds of the speeds |v_i(q)| of every support point (80-bit square-root brackets).
std::vector<Rational> speed_bounds(const Support& s, const Vec3q& q);

// The slide witness of q (≠ 0) for the distribution f when q·p ≥ Σ μ_i f_i u_i (p on or past the limit surface:
// it slides); nothing otherwise.
std::optional<Slide_witness> slide_witness(const Support& s, const std::vector<Rational>& f, const Vec3q& p,
                                           const Vec3q& q);

// A stick witness for the distribution f: the smoothed Newton witness (forces along one twist's velocities, an
// exact last round), else the exact LP on inscribed N-gons, N = sides, 2·sides, … up to 256 sides, as long as
// the LP stays within kMaxStickWitnessColumns columns (support points × sides; the exact simplex grows fast).
constexpr std::size_t kMaxStickWitnessColumns = 2048;
std::optional<Stick_witness> stick_witness_refined(const Support& s, const Admissible& a, const Vec3q& p, int sides,
                                                   const std::vector<Rational>& f);

// The smoothed Newton witness alone (stick_witness_refined's first step; the support's points may be any discrete
// distribution, e.g. a region's cells as points): forces along one twist's velocities, one exact last round, each
// disc checked exactly. Nothing when it does not verify.
std::optional<Stick_witness> smoothed_stick_witness(const Support& s, const std::vector<Rational>& f, const Vec3q& p);

// A motion certificate's object, opened, with its first members ("wrenchkit_certificate", "property", "load",
// "motion"); and an array of [gx, gy] pairs.
Json_writer motion_certificate_head(const Vec3q& p, const char* motion);
void write_forces(Json_writer& w, const std::vector<Vec2>& g);

// The certificates, as JSON text (format 1).
std::string sticks_certificate(const Vec3q& p, const Stick_witness& w);                   // every force given
std::string slides_certificate(const Vec3q& p, const Slide_witness& w);                   // every force given
std::string sticks_for_every_certificate(const Vec3q& p, const std::vector<Stick_witness>& vertices);
std::string slides_for_every_certificate(const Vec3q& p, const Vec3q& q, const std::vector<Rational>& u,
                                         const std::array<Rational, 3>& dual);
std::string depends_certificate(const Vec3q& p, const Stick_witness& sticking, const Slide_witness& sliding);

}  // namespace wrenchkit
