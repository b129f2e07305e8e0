// proofs/checker/scene.h - the scene (docs/scene-format.md), as the checker reads it: its contacts (the numbers
// of certificate-format.md §1's generators), the load of §3.3, and the support of §6 with its regions (§6.4).
#pragma once

#include <array>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "proofs/checker/regions.h"

namespace wrenchkit_checker::detail {

struct Wrench {  // (fx, fy, m), m about the origin (theory.md §1.2)
  Q fx, fy, m;
};

// One entry of contacts[], validated. When every number fits 64 bits (Small; short decimals, what
// scenes mostly hold) only those values are kept. Otherwise the numbers are kept as text and read again
// when a generator is needed: "1e10000" is 7 bytes of input but 4 KB as a rational, so keeping the text
// keeps memory proportional to the input; when every number is small (numerator and denominator of at
// most kKeptLimbs limbs each, a constant size) their values are kept as well.
struct Contact {
  bool wrench = false;
  bool frictional = false;         // a point contact with mu > 0 (edges left and right under the friction reading)
  bool fixed = false;              // every number fits a Small: `small` holds them, text and value are empty
  std::array<Small, 5> small{};    // point contact: x, y, nx, ny, mu (0 if absent); wrench: fx, fy, m
  std::vector<std::string> text;   // (!fixed) the numbers' texts, in the same order
  std::vector<Q> value;            // (!fixed) the same numbers' values, or empty (some number is not small)
};

// The scene's support (docs/scene-format.md; the unknown distribution of docs/theory-sliding.md §1).
// Each point's numbers are kept as text, and as values when they are small, as for contacts.
struct Point_values {
  Q x, y, mu, f;  // f = 0 if unknown
};
struct Support_point {
  bool known = false;                // "force" given
  std::array<std::string, 4> text;   // x, y, mu (its own or support.mu), force ("" if unknown)
  bool kept = false;                 // the values are small and kept in `value`
  Point_values value;                // (kept) the same values
};
// The point's values: the kept ones (no copy), or read again from their text into `scratch` (valid: read before).
const Point_values& values(const Support_point& p, const Limits& lim, Point_values& scratch);

struct Support {
  std::deque<Support_point> points;  // (a deque: no copies of its rationals as it grows)
  std::vector<Region> regions;  // settled: oriented, with W and M
  std::size_t unknown = 0;  // points without a given force
  bool has_weight = false, has_center = false;
  Q weight, center[2];      // as written (support.weight, support.pressure_center)
  // The admissible set F = {f >= 0 : f_i = given where given, sum f = W, sum f r = W c} (theory-sliding
  // §1): with unknown forces, W = weight and c = pressure_center or body.com, and the unknown forces
  // must carry rest_weight = W - sum_known f_i with moment rest_moment = W c - sum_known f_i r_i.
  Q W, c[2], rest_weight, rest_moment[2];  // (W: not set when every force is given and no weight is written)
};

// The pusher (docs/scene-format.md "The pusher"): a point contact moving with `velocity`; or a line contact from
// contact's point to `end` moving as a rigid body, `velocity` at the segment's middle, rotating at `omega`.
struct Pusher {
  Contact contact;
  Q velocity[2];
  bool has_velocity = false, line = false, has_omega = false;
  Q end[2], omega;
};

struct Scene {
  std::size_t longest = 0;  // digits of the longest number (as the budget counts them)
  std::vector<std::array<Q, 2>> outline;  // body.outline's points; outline_valid: every one read as a point
  bool outline_valid = false;
  std::vector<Contact> contacts;
  bool has_load = false;
  std::optional<Wrench> load;  // w_ext (certificate-format.md §3.3), if has_load
  std::optional<Support> support;
  std::optional<Pusher> pusher;
};

// The scene, or false and the bad_scene result that check() gives for it.
bool read_whole_scene(std::string_view scene_json, const Limits& limits, Scene& scene, Result& bad);

// Readers the regions share: a scene number, and "an array of n numbers".
Q read_number(Reader& r, const Limits& lim, std::string* text = nullptr);
const std::string& numbers_text(std::size_t n);

}  // namespace wrenchkit_checker::detail
