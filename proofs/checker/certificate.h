// proofs/checker/certificate.h - the certificate object, certificate-format.md §3 (the table of keys), §6.1,
// §6.4 (blocks), §6.5, §7.1 and §7.5, as read; and the checks of its properties (each in its own file).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "proofs/checker/generators.h"

namespace wrenchkit_checker::detail {

// Texts below (std::string_view) are views of the certificate's text or of its reader's decoded strings:
// valid while the reader is.
struct Ref {  // {"contact": i, "edge": E}, the item-th element of the array `list` (in the object at `owner`)
  std::string owner;  // "" at the top level, else the path of the witness holding `list`, and "."
  const char* list = "";
  std::size_t item = 0;
  std::string_view index, edge;
  std::size_t contact = SIZE_MAX;  // SIZE_MAX if the index text is too long to be in range
  std::string path() const { return owner + list + ("[" + std::to_string(item) + "]"); }  // for messages
};
struct Term {
  Ref ref;
  std::string_view weight;  // its text (grammar checked); rational_value() is the weight
};
using Pair = std::array<Q, 2>;
// A stick witness {"distribution", "support_forces"} or a slide witness {"distribution", "twist",
// "speed_bounds"} (§6.2); a hold witness {"distribution", "combination", "support_forces"} and a fail witness
// (a slide witness's keys) of property "hold" (§7).
struct Witness {
  std::string path;
  std::vector<Q> distribution;
  std::vector<Pair> forces;  // support_forces
  Q twist[3];
  std::vector<Q> speeds;  // speed_bounds
  bool has_combination = false;
  std::vector<Term> combination;
  bool has_regions = false;  // format 2 (§7.5): the regions' blocks of this witness's distribution
  std::vector<struct Block> regions;
};
// A region's block (certificate-format.md §6.4): cells (vertices and counter-clockwise index triples) that tile
// the region, with a force per cell (sticks) or a speed bound per vertex (slides).
struct Block {
  std::string path;
  std::vector<P2> vertices;
  std::vector<std::array<std::size_t, 3>> triangles;
  std::vector<Pair> forces;
  std::vector<Q> speeds;
  bool has_forces = false, has_speeds = false;
};
// The keys present in a certificate: one bit per key of the format (an unknown key is rejected as it is
// read, so it is never asked for). Used as the set of keys it replaces: insert() and count().
class Key_set {
 public:
  void insert(std::string_view key) {
    const int i = index(key);
    if (i >= 0) bits_ |= std::uint64_t{1} << i;
  }
  std::size_t count(std::string_view key) const { return (bits_ & bit(key)) != 0; }
  // The bits of these keys, to test many at once (any()): computed once by the caller, not per certificate.
  template <std::size_t N>
  static std::uint64_t mask(const char* const (&keys)[N]) {
    std::uint64_t m = 0;
    for (const char* k : keys) m |= bit(k);
    return m;
  }
  bool any(std::uint64_t mask) const { return (bits_ & mask) != 0; }

 private:
  static int index(std::string_view key) {
    static const std::string_view known[] = {"wrenchkit_certificate", "property", "holds", "combination",
                                             "independent", "twist", "reading", "load", "motion",
                                             "support_forces", "speed_bounds", "dual", "vertices", "sticking",
                                             "sliding", "holding", "failing", "regions", "norm", "normalize",
                                             "torque_scale", "about", "scales", "epsilon", "boundary", "nearest",
                                             "normal", "of", "critical_mu", "below", "above", "constant",
                                             "constant_beyond", "limit_twist", "scaling", "torque_radius_squared",
                                             "torque_scale_error", "fingers", "mu", "edges", "pairs", "triples",
                                             "rotation", "friction", "votes", "center", "turns",
                                             "contact", "stable", "region", "locus"};
    for (int i = 0; i < static_cast<int>(sizeof known / sizeof known[0]); ++i)
      if (known[i] == key) return i;
    return -1;
  }
  static std::uint64_t bit(std::string_view key) {
    const int i = index(key);
    if (i < 0) throw std::logic_error("Key_set: \"" + std::string(key) + "\" is not a key of the format");
    return std::uint64_t{1} << i;
  }
  std::uint64_t bits_ = 0;
};

// The members of properties "motion" (§6) and "hold" (§7), read only when present (each costs allocations).
struct Motion_part {
  Q load[3], dual[3];
  std::vector<Pair> support_forces;
  std::vector<Q> speed_bounds;
  std::vector<Witness> vertices;
  Witness sticking, sliding;
  Witness holding, failing;  // property "hold", "holds": "depends"
  std::vector<Block> regions;
};

// The members of property "quality" (§3.4).
struct Quality_part {
  std::string_view norm, normalize;  // "L1" or "Linf"; "unit-normal", "unit-force" or "as-given"
  Q torque_scale, about[2];
  bool has_radius = false;  // "torque_radius_squared" r2 and "torque_scale_error" η: s = 1/√r2 within η of torque_scale
  Q radius_squared, torque_error;
  struct Scale {
    Q scale, error, bound, moment_bound;
    bool has_moment_bound = false;
  };
  std::vector<Scale> scales;
  Q lower, upper, squared;  // epsilon
  bool has_squared = false;
  std::vector<std::array<std::size_t, 3>> boundary;
  std::array<std::size_t, 3> nearest{};
  Q normal[3];
};

// The members of property "critical_mu" (§3.5): the certificates below and above μ* are certificate objects of
// §3.1–§3.3 (read by read_certificate), for the scene with every point contact's μ set to their `mu`.
struct Certificate;
struct Critical_part {
  std::string_view of;       // "force_closure" or "equilibrium"
  bool proportional = false;  // "scaling": "proportional" (μ_i·t, force closure only); "common" (the default): μ = t
  std::string_view word;     // "always" or "never"; empty: a value {"lower", "upper"}
  Q lower, upper;
  struct Side {
    bool present = false;
    Q mu;
    std::unique_ptr<Certificate> certificate;
  } below, above;
  bool constant = false, constant_beyond = false;
  bool has_limit_twist = false;
  Q limit_twist[3];
};

// The members of property "grasp_regions" (§3.6, format 5): each pair's claimed polygons.
struct Regions_part {
  std::size_t fingers = 0;
  Q mu;
  bool has_edges = false;
  std::vector<std::size_t> edges;  // "edges": the edges asked (else every edge of the outline)
  struct Pair {
    std::size_t i = 0, j = 0;
    std::vector<std::vector<std::array<Q, 2>>> closed;
    bool has_box = false;
    Q box[2][2];  // "independent": [[s0, s1], [t0, t1]]
  };
  std::vector<Pair> pairs;
  struct Triple {  // "fingers": 3
    std::size_t e[3] = {0, 0, 0};
    bool has_box = false;
    Q box[3][2];     // "independent": [[a0, b0], [a1, b1], [a2, b2]]
    int wrench[4] = {0, 0, 0, 0};  // "wrenches": "R0".."L2" as 2·finger + (0 R, 1 L)
    int never = 0;   // 1: "never": "frictionless"; 2: "never": [ux, uy, um]
    Q direction[3];
  };
  std::vector<Triple> triples;
};

// The members of property "push" (§8, format 6): bounds over F of the friction under the body and of the three votes
// (left edge, right edge, velocity), each with the LP's dual when some force is not given; "depends": two
// distributions.
struct Push_part {
  std::string_view rotation;  // "ccw", "cw", "none" or "depends"
  struct Range {
    Q lower, upper;
    bool has_upper = false, has_dual_lower = false, has_dual_upper = false;
    Q dual_lower[3], dual_upper[3];
  };
  bool has_friction = false;
  Range friction;
  std::vector<Range> votes;
  bool has_center = false;
  Q center[2];
  bool has_turns = false;
  std::vector<Q> turns_ccw, turns_cw;
  // "contact" (§8.2): the contact mode, the sticking candidate's ω bracket and, sliding, the tangent's; "depends" (forces
  // not given): two witnesses, each a distribution (`witness_forces`) with its own contact claim
  bool has_contact = false;
  std::vector<Q> witness_forces;
  std::vector<std::unique_ptr<Push_part>> contact_witnesses;
  std::string_view mode;
  std::size_t bits = 0;
  Q omega[2], tangent[2];
  bool has_tangent = false;
  // F(t) the facet of the rotation about support point `tangent_pivot` (PU-2 §8): its chord beyond the claimed edge
  bool has_tangent_pivot = false;
  std::size_t tangent_pivot = 0;
  // the sticking motion the rotation about support point `stick_pivot` (PU-2 §7–8): sticking, a force of its facet
  // along `force`, inside the cone; sliding, every force of its facet through p beyond the claimed edge
  bool has_stick_pivot = false;
  std::size_t stick_pivot = 0;
  Q force[2];
  // "sliding" (§8.2): the slip bracket, each end's ω bracket, and the rate's bracket over the slip bracket
  bool has_sliding = false, has_slip_omega = false, has_pivot = false;
  std::size_t pivot = 0;  // the rotation about support point `pivot` (PU-2 §6)
  Q slip[2], slip_omega[2][2], motion[2];
  // "stable" (§8.3): a line pusher's verdict, R² and, stable and rotating, the bounds of the corrected tip line;
  // unstable, the facet left and, rotating, the witness distribution
  bool has_stable = false, has_bounds = false, has_facet = false, has_witness = false;
  std::string_view verdict, facet;
  Q R2, R_hi, d_lo, alpha_hi;
  std::vector<std::array<Q, 2>> points;
  std::vector<Q> weights;
  std::size_t witness_bits = 0;
  // stable on a support of points: facets proven by the LP's dual [y0, yx, yy] (indexed as the facets), at `dual_bits`
  bool has_dual[4] = {false, false, false, false};
  Q dual[4][3];
  std::size_t dual_bits = 0;
  bool has_dual_bits = false;
  // "region" (§8.3): the stable region's R_hi and, per sense (ccw, cw), its tip line's alpha_hi and T; the stable
  // translations' extreme rays
  bool has_region = false, has_side[2] = {false, false}, has_translations = false;
  Q region_R_hi, side_alpha_hi[2], side_T[2], translations[2][2];
  // "locus" (§8.4): a point pusher's rotation centres — the bounds, per sense (ccw, cw) null or its three pieces
  // (a contact mode, bounded or not, a polygon), and the arm's bound
  struct Piece {
    std::string_view mode;
    bool bounded = false;
    std::vector<std::array<Q, 2>> polygon;
  };
  bool has_locus = false, has_tip = false, has_arm = false, has_sense[2] = {false, false};
  Q locus_R_hi, locus_alpha_hi, locus_T, arm_hi;
  // "slowest" (§8.4): a distribution of F with its certified contact mode and rate, and arm_lo
  std::unique_ptr<Push_part> slowest;
  Q arm_lo;
  std::vector<Piece> pieces[2];
};

struct Certificate {
  Key_set keys;  // the keys present
  std::string_view property;
  Reading reading = Reading::friction;
  bool equilibrium = false;  // property "equilibrium" (§3.3), read with friction
  bool motion = false;       // property "motion" (§6)
  bool hold = false;         // property "hold" (§7), read with friction
  bool quality = false;      // property "quality" (§3.4, format 4), read with friction
  bool critical = false;     // property "critical_mu" (§3.5, format 4)
  bool regions = false;      // property "grasp_regions" (§3.6, format 5)
  bool push = false;         // property "push" (§8, format 6)
  bool holds = false;
  bool depends = false;      // "holds": "depends" (property "hold" only)
  bool impending = false;    // "holds": "impending" (property "hold", format 3 only)
  // "wrenchkit_certificate": 1; 2 (§6.5, §7.5: a witness may carry its regions' blocks); 3 (§6.6, §7.6: the boundary
  // is its own outcome — "sticks" and "holds": true with margin, "slides" and "holds": false strictly past it)
  int version = 1;
  std::vector<Term> combination;
  std::vector<Ref> independent;
  std::string_view twist[3] = {"0", "0", "0"}, where[2] = {"0", "0"};  // texts; where: reading.point or .direction
  std::string_view label;  // reading.label
  // property "motion" (and, in motion_members, the support's blocks that "hold" shares with it)
  std::string_view claim;  // "sticks", "impending", "slides" or "depends"
  std::unique_ptr<Motion_part> motion_members;  // allocated by m() when a member is read; see members()
  Motion_part& m() {
    if (!motion_members) motion_members = std::make_unique<Motion_part>();
    return *motion_members;
  }
  std::unique_ptr<Critical_part> critical_members;  // allocated by cm() when a member of §3.5 is read
  Critical_part& cm() {
    if (!critical_members) critical_members = std::make_unique<Critical_part>();
    return *critical_members;
  }
  std::unique_ptr<Regions_part> regions_members;  // allocated by g() when a member of §3.6 is read
  Regions_part& g() {
    if (!regions_members) regions_members = std::make_unique<Regions_part>();
    return *regions_members;
  }
  std::unique_ptr<Push_part> push_members;  // allocated by pu() when a member of §8 is read
  Push_part& pu() {
    if (!push_members) push_members = std::make_unique<Push_part>();
    return *push_members;
  }
  std::unique_ptr<Quality_part> quality_members;  // allocated by q() when a member of §3.4 is read
  Quality_part& q() {
    if (!quality_members) quality_members = std::make_unique<Quality_part>();
    return *quality_members;
  }
};

const Motion_part& members(const Certificate& c);  // its members of "motion" and "hold" (all empty if none)
Certificate read_certificate(Reader& r);
std::size_t read_index(Reader& r, const char* what);  // a JSON integer without sign, fraction or exponent
Q read_rational(Reader& r);
std::string_view read_rational_text(Reader& r);
void check_keys(const Certificate& c);  // the keys that must, and must not, be present (§3, §3.3)

// The checks of the properties, each against the scene: closure.cpp (§3.1, §3.2), equilibrium.cpp (§3.3),
// quality.cpp (§3.4), motion.cpp (§6), hold.cpp (§7). Each returns if the certificate proves its claim, else throws the Failure.
void check_closure(const Certificate& c, const Scene& scene, const Limits& lim);
void check_equilibrium(const Certificate& c, const Scene& scene, const Limits& lim);
void check_motion(const Certificate& c, const Scene& scene, const Limits& lim);
void check_hold(const Certificate& c, const Scene& scene, const Limits& lim);
void check_quality(const Certificate& c, const Scene& scene, const Limits& lim);  // quality.cpp (§3.4)
void check_critical_mu(const Certificate& c, const Scene& scene, const Limits& lim);  // critical_mu.cpp (§3.5)
void read_region_member(Reader& r, std::string_view key, Certificate& c);  // grasp_regions.cpp (§3.6): a member
void check_grasp_regions(const Certificate& c, const Scene& scene, const Limits& lim);  // grasp_regions.cpp (§3.6)
void read_push_member(Reader& r, std::string_view key, Certificate& c);  // push.cpp (§8): a member
void check_push(const Certificate& c, const Scene& scene, const Limits& lim);  // push.cpp (§8)
void read_line_push_member(Reader& r, std::string_view key, Push_part& p);  // stable_push.cpp (§8.3): "stable", "region"
void check_line_push(const Push_part& p, const Scene& scene, const Limits& lim);  // stable_push.cpp (§8.3)
// stable_push.cpp: the centre of friction c (one for every distribution, else a Failure under `path`), S's vertices
// (the places with friction), and R² = max |x − c|² over them; PU-3 §5's correction E at R, d, alpha (an upper bound
// of the true E when R, alpha are upper bounds and d a lower bound: it grows with R and alpha, falls with d).
Q friction_disc(const Scene& scene, const Limits& lim, const std::string& path, Q (&c)[2], std::vector<std::array<Q, 2>>& S);
Q tip_correction(const Q& R, const Q& d, const Q& alpha);
void read_locus_member(Reader& r, Push_part& p);  // push_locus.cpp (§8.4): "locus"
// push.cpp (§8.2): a contact object; `witness`: one of given forces ("forces" required, no "depends")
void read_contact(Reader& r, Push_part& p, bool witness);
void check_locus(const Push_part& p, const Scene& scene, const Limits& lim);  // push_locus.cpp (§8.4)
// lo <= sqrt(s) <= hi for a rational s >= 0, at `bits` (push.cpp; the engine's precision for the same bits)
void sqrt_bounds(const Q& s, std::size_t bits, Q& lo, Q& hi);
void read_dual(Reader& r, Q (&out)[3]);  // push.cpp: an LP dual [y0, yx, yy]

}  // namespace wrenchkit_checker::detail
