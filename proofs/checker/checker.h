// proofs/checker/checker.h - the independent certificate checker of wrenchkit (certificate format v1).
//
// check() decides whether a certificate (proofs/certificate-format.md) proves its claim about a scene
// (docs/scene-format.md): force and form closure (§3.1 holds = true, theory [FC-2]; §3.2 holds = false, [FC-3]),
// equilibrium of the scene's load (§3.3, [EQ-1]; a scene without a load has no such claim), sliding on the scene's
// support (property "motion", §6, [SL-1]: "sticks", "slides" or "depends", for its known distribution or for every
// admissible one, whose vertices the checker enumerates itself; an empty set of them is a bad scene), and fixtures on
// a support against the load (property "hold", §7, [HD-1]). proofs/checker/README.md maps each section to its file.
// Every generator, and the load, is recomputed from the scene text; the certificate supplies only indices and
// rationals. All arithmetic is exact (integers and rationals; no floating point).
//
// Independence: this checker uses the C++17 standard library and GMP only, with its own JSON reader
// and number parser. It shares no code with the engine (exact/, core/, float/) and does not use CGAL.
//
// Robustness: check() never throws and never aborts. Nesting is bounded by `max_depth` and nothing
// recurses; number texts are checked against the limits before any big number is built; memory is
// proportional to the input size.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace wrenchkit_checker {

// Limits on the scene (docs/scene-format.md "Limits"); max_depth also applies to the certificate.
// Certificate rationals are at most max(100000, 32 L + 64) characters for L the digits of the scene's longest
// number (certificate-format.md §2).
struct Limits {
  std::size_t max_digits = 10000;  // digits of a scene number's text (exponent included) and of its value written out
  long max_exponent = 10000;       // |exponent| of a scene number
  std::size_t max_depth = 64;      // JSON containers nested in one another
  std::size_t max_contacts = 100000;  // also the limit on support.points and on body.outline's points
  std::size_t max_region_vertices = 4096;  // vertices of all support regions' rings together
  // The scene-wide budget (docs/scene-format.md "Limits"): the digits of all the scene's numbers together
  // (each counted as max_digits counts it), and the longest number's digits times the number of contacts
  // and support points. A scene over either is a bad scene, refused while it is read, before the number
  // that takes it over is built.
  std::size_t max_total_digits = 20000000;
  std::size_t max_digits_times_contacts = 10000000;
  // Sliding certificates that claim "sticks" for every admissible distribution (certificate-format.md
  // §6): the checker enumerates the vertices of F itself, over n + C(n,2) + C(n,3) candidate bases for
  // n points without a given force, and rejects a larger certificate as too large to check.
  unsigned long long max_vertex_bases = 2000000;
  // A certificate longer than this is rejected before any of it is read (its reading costs a few bytes of memory per
  // byte, its checks time in proportion): the engine refuses to write a longer one (docs/scene-format.md "Limits").
  std::size_t max_certificate_bytes = 8u << 20;
  // The integer checks of §1 and §3 are written once over a number type and run on fixed-width integers (eight
  // 64-bit limbs on the stack) and, only if a result overflows them, again on GMP integers. false: GMP only (the
  // tests compare the two).
  bool fixed_width = true;
};

enum class Outcome {
  accepted,   // the certificate proves its claim for this scene
  rejected,   // anything wrong with the certificate (malformed, wrong type, failed condition, ...)
  bad_scene,  // the scene is not a valid scene; the certificate was not examined
};

struct Result {
  Outcome outcome;
  // "accepted", or the reason, naming the JSON path, e.g. "contacts[2].normal: zero vector",
  // "load.gravity: needs body.com (the point where the weight acts)",
  // "twist: power -1 against contacts[0] edge normal"; JSON syntax errors read
  // "<line>:<column>: invalid JSON: <what>".
  std::string message;
};

Result check(std::string_view scene_json, std::string_view certificate_json, const Limits& limits = {});

// check() of several certificates about one scene, reading the scene once: result k is exactly
// check(scene_json, certificates[k], limits). (Every result is bad_scene when the scene is bad.)
std::vector<Result> check_all(std::string_view scene_json, const std::vector<std::string_view>& certificates,
                              const Limits& limits = {});

}  // namespace wrenchkit_checker
