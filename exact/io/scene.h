// The scene model (docs/scene-format.md): every number an exact rational.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "exact/numbers/limits.h"
#include "exact/numbers/rational.h"
#include "exact/numbers/vectors.h"
#include "float/closure_twin.h"

namespace wrenchkit {

struct Contact {
  enum class Kind { point, wrench };
  Kind kind = Kind::point;
  Vec2 at;          // point contact: the contact point
  Vec2 normal;      // point contact: inward normal, nonzero, any length
  Rational mu;      // point contact: Coulomb coefficient ≥ 0 (0 = frictionless)
  bool mu_given = false;  // point contact: "mu" was written (else it is frictionless by default, said in the output)
  Vec3q wrench;    // wrench generator: nonzero
  std::string name;
  // Placed on body.outline as {"edge": i, "s": t} (exact/io/outline.h): `at` and `normal` are filled from it.
  std::optional<std::size_t> edge;
  Rational s;
  // The same contact as certified doubles for the float twin [FL-4], computed by read_scene from
  // the digits; `has_twin` false (a scene built in code) means: derive it from the rationals.
  fl::Bounded_contact twin;
  bool has_twin = false;
  // Lazy reading (read_scene(…, lazy = true)): the rationals above are NOT filled; the numbers'
  // texts are kept (point: at x, at y, normal x, normal y, mu; wrench: fx, fy, m) and
  // exact_contact() builds them when exact arithmetic is needed. Validation was exact all the same.
  bool exact_pending = false;
  std::array<std::string, 5> number_text;
  std::array<bool, 5> number_is_json{};
  // Lazy from doubles (set_point_contact): exact_pending, and the rationals are the twin's values, each
  // double being the binary rational it denotes (its bound is 0); no text.
  bool from_doubles = false;
};

// A point contact of doubles (the array front ends), each read as the exact binary rational it denotes — not
// as a decimal text: the certified twin is exact (bounds 0) and the rationals are built on demand by
// exact_contact (mpq_set_d, exact). Precondition (the caller validates, naming its own indices): every value
// finite, (nx, ny) ≠ 0, mu ≥ 0. Reuses `c`'s storage.
void set_point_contact(Contact& c, double ax, double ay, double nx, double ny, double mu);

// The contact with its rationals filled (a copy when it was read lazily).
Contact exact_contact(const Contact& c);

struct Load {
  enum class Kind { force, wrench, gravity };
  Kind kind = Kind::force;
  Vec2 force, at;   // force at a point
  Vec3q wrench;    // a wrench
  Rational weight;  // gravity: weight > 0 at body.com, acting in −y
};

struct Support_point {
  Vec2 at;
  std::optional<Rational> force;  // normal force ≥ 0; none: unknown (docs/theory-sliding.md §1)
  std::optional<Rational> mu;     // own coefficient, else support.mu
};

// A support region (docs/scene-format.md, "Support regions"; docs/regions.md) [RG-1]: a polygon with holes
// pressing on the support with the linear pressure p(x, y) = a + b·x + c·y ≥ 0 (uniform: b = c = 0). The model
// is plain exact rationals; CGAL checks and triangulates it once, when the scene is read (exact/io/region.h).
struct Region_triangle {
  Vec2 a, b, c;  // counter-clockwise, nonzero area
};
struct Support_region {
  // As written (the canonical scene writer writes these back).
  std::vector<Vec2> outline;
  std::vector<std::vector<Vec2>> holes;
  bool uniform = true;               // "pressure": "uniform" with "force", else {"linear": [a, b, c]}
  Rational force;                    // uniform: the given force F > 0 (linear: its integral, below)
  std::array<Rational, 3> linear;    // linear: the written (a, b, c)
  std::optional<Rational> mu;        // own coefficient, else support.mu
  // Settled when the scene is read (settle_region, exact/io/region.h), exact:
  std::vector<std::vector<Vec2>> rings;     // outline counter-clockwise, then each hole clockwise
  std::vector<Region_triangle> triangles;   // a triangulation of the region (vertices: the rings' vertices)
  std::array<Rational, 3> pressure;         // p = pressure[0] + pressure[1]·x + pressure[2]·y (uniform: F/area)
  Rational area;                            // > 0
  Rational total;                           // W_R = ∫ p dA > 0 (= force when uniform)
  Vec2 moment;                              // ∫ r p dA (the centre of pressure is moment / total)
  std::array<Rational, 3> second;           // ∫ x² p, ∫ x y p, ∫ y² p
  // The same in double, for the searches that propose twists (region_power_double): converted once when settled
  // (each search evaluates the power thousands of times; converting the rationals on every evaluation was most of
  // the time of a region decision).
  struct Doubles {
    std::vector<std::vector<std::array<double, 2>>> rings;
    std::vector<std::array<double, 6>> triangles;  // a, b, c
    std::array<double, 3> pressure{};
    double total = 0, gx = 0, gy = 0, radius = 0;  // the outline's vertex mean and the largest distance from it
  } d;
};

// A support: its points, and when a force is unknown the total normal force W and the centre of pressure c
// (pressure_center, else body.com) that fix the admissible distributions (exact/io/support_check.h).
struct Support {
  std::optional<Rational> mu;
  std::vector<Support_point> points;     // may be empty when there are regions
  std::vector<Support_region> regions;   // their pressure is always known
  std::optional<Rational> weight;        // W > 0; required when a force is unknown
  std::optional<Vec2> pressure_center;   // c
  // The μ rule (docs/scene-format.md): a point's or a region's own coefficient, else the support's, else 0.
  const Rational& mu_of(const Support_point& p) const { return effective_mu(p.mu); }
  const Rational& mu_of(const Support_region& r) const { return effective_mu(r.mu); }
  // Every point's force is given: one distribution.
  bool known() const {
    for (const Support_point& p : points)
      if (!p.force) return false;
    return true;
  }

 private:
  const Rational& effective_mu(const std::optional<Rational>& own) const {
    static const Rational zero;
    return own ? *own : mu ? *mu : zero;
  }
};

struct Body {
  std::vector<Vec2> outline;
  std::optional<Vec2> com;
  // Stated by check_outline (exact/io/outline.h) when there is an outline.
  bool outline_ccw = true, outline_convex = false;
};

// A pusher (docs/scene-format.md "The pusher"; docs/pushing.md): a point contact on the body — its point, inward
// normal and Coulomb coefficient, read as contacts[] are (placed by {"edge", "s"} too) — moving with `velocity`
// (velocity · normal > 0: it pushes into the body). A line contact (PU-3, a fence or a flat pusher: "segment"
// [[x1, y1], [x2, y2]] instead of "at") has its first end as `contact.at`, its second `end`, and moves as a rigid body:
// `velocity` at the middle of the segment and the rotation rate `omega` (counter-clockwise positive; 0 translates).
struct Pusher {
  Contact contact;
  Vec2 velocity;
  std::optional<Vec2> end;  // a line contact's second end
  Rational omega;           // a line contact's rotation rate
  bool line() const { return end.has_value(); }
};

struct Scene {
  std::string name;
  Body body;
  std::vector<Contact> contacts;
  std::optional<Load> load;
  std::optional<Support> support;
  std::optional<Pusher> pusher;
  // What a lenient reading let through (exact/io/outline.h): each a violation the strict reading refuses.
  std::vector<std::string> warnings;
  // The scene-wide "mu" as written (its point contacts have it already; grasp-regions' fingers take it).
  std::optional<Rational> mu;
};

// The scene with every contact's rationals filled: `s` itself when none was read lazily, else a copy kept in `storage`.
const Scene& exact_contacts(const Scene& s, std::optional<Scene>& storage);

// Reads and validates a scene: the one scene reader of the engine. Throws Input_error naming the JSON path
// and the offending text (or "SOURCE:LINE:COL: invalid JSON: …"). `source` names the input in messages.
// `lazy`: contacts keep their numbers as text and certified doubles (for the float twin) and build
// rationals only on demand (exact_contact); same validation, same errors.
// It reads in one pass without a JSON tree (exact/io/streaming_scene_reader.h, which also reads into a
// reused Scene); on any text the one pass does not accept it defers to read_scene_tree, whose message it
// throws.
Scene read_scene(std::string_view json_text, const Input_limits& limits, std::string_view source = "scene",
                 bool lazy = false);

// The reference reader behind read_scene's messages: the strict JSON tree of exact/io/json.h, then the
// schema. It accepts exactly what read_scene accepts, with the same Scene (the tests and the fuzz targets
// check it); call read_scene.
Scene read_scene_tree(std::string_view json_text, const Input_limits& limits, std::string_view source = "scene",
                      bool lazy = false);

}  // namespace wrenchkit
