// libFuzzer target: any bytes as "SCENE\0CERTIFICATE". The checker must never crash, and must never
// accept a certificate whose claim is false: whenever it accepts, the exact engine must agree with
// the claim (soundness, differential against the engine). For property "motion" (sliding) on a
// support the engine reads (every force given), the float twin's certified search on the true limit
// surface must not decide the opposite; unknown distributions have no engine oracle yet. "sticks" is the
// interior of a three-dimensional limit surface; format 3 tells the boundary ("impending") from the outside
// ("slides"), formats 1 and 2 call both "slides" (and "holds": true is the closed set there), so an older claim
// is compared with the engine's answer read the old way. The twin tells the interior from the rest only. When
// LS is flat (friction at fewer than two distinct points) it has no interior: the checker must never accept
// "sticks" there.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string>
#include <optional>
#include <string_view>

#include "exact/statics/closure.h"
#include "exact/statics/critical_mu.h"
#include "exact/statics/quality.h"
#include "exact/statics/equilibrium.h"
#include "exact/io/input_error.h"
#include "exact/io/json.h"
#include "exact/io/outline.h"
#include "exact/fixture/hold.h"
#include "fuzz/hold_scope.h"
#include "exact/io/scene.h"
#include "exact/numbers/rational.h"
#include "exact/sliding/limit_surface.h"
#include "exact/sliding/region_sliding.h"
#include "exact/sliding/sliding.h"
#include "exact/sliding/strategies.h"
#include "float/limit_surface_twin.h"
#include "proofs/checker/checker.h"

namespace {

// The JSON value text right after the key `"key"` and its colon (whitespace skipped), up to the next
// ',' or '}'. The checker accepted the certificate, so it is valid JSON with each key once; keys
// and string values of a certificate never contain the key text of another member.
std::string_view value_of(std::string_view json, std::string_view key) {
  const std::string quoted = "\"" + std::string(key) + "\"";
  std::size_t i = json.find(quoted);
  if (i == std::string_view::npos) return {};
  i += quoted.size();
  auto ws = [&] { while (i < json.size() && (json[i] == ' ' || json[i] == '\t' || json[i] == '\n' || json[i] == '\r')) ++i; };
  ws();
  if (i < json.size() && json[i] == ':') ++i;
  ws();
  const std::size_t end = json.find_first_of(",}", i);
  std::string_view v = json.substr(i, end == std::string_view::npos ? std::string_view::npos : end - i);
  while (!v.empty() && (v.back() == ' ' || v.back() == '\n' || v.back() == '\r' || v.back() == '\t')) v.remove_suffix(1);
  return v;
}

// The certificate's format ("wrenchkit_certificate"): 1, 2 or 3.
int version_of(std::string_view cert) {
  const std::string_view v = value_of(cert, "wrenchkit_certificate");
  return v == "3" ? 3 : v == "2" ? 2 : 1;
}

// The engine's motion as a claim of the format: before format 3 the boundary was "slides" (and "depends" needed a
// distribution strictly inside).
std::string motion_claim(const wrenchkit::Motion_answer& m, int version) {
  using wrenchkit::Motion;
  if (version >= 3 || m.motion == Motion::sticks) return wrenchkit::motion_name(m.motion);
  if (m.motion == Motion::depends && m.held_as == Motion::sticks) return "depends";
  return "slides";
}

// The engine's hold verdict as the claim's JSON value: before format 3 "true" was the closed set (and "depends"
// needed a distribution that fails strictly).
std::string hold_claim(const wrenchkit::Hold_answer& a, int version) {
  using wrenchkit::Hold_verdict;
  Hold_verdict v = a.verdict;
  if (version < 3 && (v == Hold_verdict::impending || (v == Hold_verdict::depends && a.moved_as != Hold_verdict::fails)))
    v = Hold_verdict::holds;
  if (v == Hold_verdict::holds) return "true";
  if (v == Hold_verdict::fails) return "false";
  return "\"" + std::string(wrenchkit::hold_word(v)) + "\"";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view all(reinterpret_cast<const char*>(data), size);
  const std::size_t cut = all.find('\0');
  if (cut == std::string_view::npos) return 0;
  const std::string_view scene_text = all.substr(0, cut), cert = all.substr(cut + 1);
  wrenchkit_checker::Limits cl;
  cl.max_digits = 200;
  cl.max_exponent = 200;
  cl.max_contacts = 64;
  cl.max_region_vertices = 64;
  const auto r = wrenchkit_checker::check(scene_text, cert, cl);
  if (r.outcome != wrenchkit_checker::Outcome::accepted) return 0;
  wrenchkit::Input_limits limits;
  limits.max_digits = cl.max_digits;
  limits.max_exponent = cl.max_exponent;
  limits.max_contacts = cl.max_contacts;
  limits.max_region_vertices = cl.max_region_vertices;
  wrenchkit::Scene scene;
  try {
    scene = wrenchkit::read_scene(scene_text, limits, "fuzz");
  } catch (const wrenchkit::Input_error& e) {
    return 0;  // the checker reads only what it needs; the engine's schema is stricter
  }
  // The claim, read token-wise (JSON allows whitespace around the colon).
  const bool claims_holds = value_of(cert, "holds") == "true";
  const std::string_view property = value_of(cert, "property");
  if (property == "\"motion\"") {
    if (!scene.support) {
      std::cerr << "checker accepted a motion claim on a scene without support\n";
      std::abort();
    }
    // The accepted certificate is valid JSON: its load and claim, read with the engine's parser.
    const wrenchkit::json::Value c = wrenchkit::json::parse(cert, limits, "certificate");
    const std::string claim = c.find("motion")->text;
    if (claim == "depends") return 0;  // only with unknown forces: no engine oracle yet
    for (const wrenchkit::Support_point& x : scene.support->points)
      if (!x.force) return 0;
    wrenchkit::fl::Bounded3 p;
    for (std::size_t k = 0; k < 3; ++k) {
      std::string why;
      wrenchkit::Input_limits unlimited;
      unlimited.max_digits = 200000;
      unlimited.max_exponent = 200000;
      const auto q = wrenchkit::parse_rational(c.find("load")->items[k].text, false, unlimited, why);
      if (!q) std::abort();  // the checker accepted it as a rational
      p[k] = wrenchkit::to_bounded(*q);
    }
    if (!scene.support->regions.empty()) {  // regions: the engine's certified decision is the oracle
      wrenchkit::Vec3q exact_p;
      for (std::size_t k = 0; k < 3; ++k) {
        std::string why;
        wrenchkit::Input_limits unlimited;
        unlimited.max_digits = 200000;
        unlimited.max_exponent = 200000;
        exact_p[k] = *wrenchkit::parse_rational(c.find("load")->items[k].text, false, unlimited, why);
      }
      const wrenchkit::Motion_answer m = wrenchkit::decide_on_regions(*scene.support, exact_p);
      if (m.motion != wrenchkit::Motion::undecided && motion_claim(m, version_of(cert)) != claim) {
        std::cerr << "checker accepted \"" << claim << "\" on a support with regions; the engine certifies "
                  << motion_claim(m, version_of(cert)) << "\n";
        std::abort();
      }
      return 0;
    }
    const wrenchkit::Ls_support merged = wrenchkit::merge_support(*scene.support);
    if (merged.points.size() < 2) {  // coincident points merged, rho = 0 dropped: LS is flat (or {0})
      if (claim == "sticks") {
        std::cerr << "checker accepted \"" << claim << "\" on a flat limit surface, which has no interior\n";
        std::abort();
      }
      return 0;
    }
    const wrenchkit::fl::Motion_answer a = wrenchkit::fl::classify_load(wrenchkit::twin_support(merged), p, 20000);
    if (a.motion != wrenchkit::fl::Motion_twin::undecided &&
        (a.motion == wrenchkit::fl::Motion_twin::sticks) != (claim == "sticks")) {
      std::cerr << "checker accepted \"" << claim << "\"; the certified float search decides the opposite\n";
      std::abort();
    }
    return 0;
  }
  if (property == "\"grasp_regions\"" && value_of(cert, "fingers") == "3" && scene.body.outline.size() <= 12) {
    // three fingers (GR-2): an accepted cube's centre and first corner close, and an accepted "never" triple's centre
    // placement does not, by the engine's own closure decision of the three placed contacts
    const wrenchkit::json::Value c = wrenchkit::json::parse(cert, limits, "certificate");
    const auto q = [](const wrenchkit::json::Value& v) {
      wrenchkit::Rational r(v.text);
      r.canonicalize();
      return r;
    };
    const wrenchkit::Rational mu = q(*c.find("mu"));
    const auto closes = [&](const wrenchkit::json::Value& edges, const std::array<wrenchkit::Rational, 3>& s) {
      std::vector<std::size_t> on;
      for (const wrenchkit::json::Value& e : edges.items) on.push_back(std::stoul(e.text));
      return wrenchkit::decide_closure(wrenchkit::with_fingers(scene, mu, on, {s.begin(), s.end()}),
                                       wrenchkit::Property::force_closure, wrenchkit::Mode::exact, false).holds;
    };
    std::size_t tried = 0;
    for (const wrenchkit::json::Value& t : c.find("triples")->items) {
      if (++tried > 20) break;
      const wrenchkit::json::Value& edges = *t.find("edges");
      if (const wrenchkit::json::Value* box = t.find("independent")) {
        std::array<wrenchkit::Rational, 3> centre, corner;
        for (std::size_t f = 0; f < 3; ++f) {
          corner[f] = q(box->items[f].items[0]);
          centre[f] = (corner[f] + q(box->items[f].items[1])) / 2;
        }
        if (!closes(edges, centre) || !closes(edges, corner)) {
          std::cerr << "checker accepted an independent cube that does not close\n";
          std::abort();
        }
      }
      if (t.find("never") && closes(edges, {wrenchkit::Rational(1, 2), wrenchkit::Rational(1, 2), wrenchkit::Rational(1, 2)})) {
        std::cerr << "checker accepted \"never\" for a triple whose centre placement closes\n";
        std::abort();
      }
    }
    return 0;
  }
  if (property == "\"quality\"" || property == "\"critical_mu\"") {  // format 4: the engine's answer must agree
    if (scene.contacts.empty() || scene.contacts.size() > 8) return 0;  // (ε = 0 of no contacts; μ*'s cost grows as n³)
    const wrenchkit::json::Value c = wrenchkit::json::parse(cert, limits, "certificate");
    const auto q = [](const wrenchkit::json::Value* v) {  // a certificate rational "p/q" (the checker read it)
      wrenchkit::Rational r(v->text);
      r.canonicalize();
      return r;
    };
    const auto overlap = [](const wrenchkit::Rational& a0, const wrenchkit::Rational& a1, const wrenchkit::Rational& b0,
                            const wrenchkit::Rational& b1) { return a0 <= b1 && b0 <= a1; };
    if (property == "\"quality\"") {
      wrenchkit::Quality_query query;
      query.critical_mu = false;
      const std::string norm = c.find("norm")->text, normalize = c.find("normalize")->text;
      query.norm = norm == "L1" ? wrenchkit::Quality_norm::l1 : wrenchkit::Quality_norm::linf;
      query.normalize = normalize == "unit-normal"  ? wrenchkit::Force_normalization::unit_normal
                        : normalize == "unit-force" ? wrenchkit::Force_normalization::unit_force
                                                    : wrenchkit::Force_normalization::as_given;
      query.torque_scale = q(c.find("torque_scale"));
      query.about = wrenchkit::Vec2{q(&c.find("about")->items[0]), q(&c.find("about")->items[1])};
      const wrenchkit::json::Value* e = c.find("epsilon");
      const wrenchkit::Rational lo = q(e->find("lower")), hi = q(e->find("upper"));
      const wrenchkit::Quality_answer a = wrenchkit::decide_quality(scene, query, wrenchkit::Mode::exact);
      if (!overlap(lo, hi, a.lower, a.upper)) {
        std::cerr << "checker accepted epsilon in [" << lo << ", " << hi << "]; the engine finds [" << a.lower << ", "
                  << a.upper << "]\n";
        std::abort();
      }
      return 0;
    }
    const bool balance = c.find("of")->text == "equilibrium";
    if (balance && !scene.load) {
      std::cerr << "checker accepted a critical mu of equilibrium on a scene without load\n";
      std::abort();
    }
    bool point = false;
    for (const auto& k : scene.contacts) point = point || k.kind == wrenchkit::Contact::Kind::point;
    if (!point) return 0;
    const wrenchkit::Critical_answer a = wrenchkit::decide_critical_mu(scene, wrenchkit::Mode::exact, wrenchkit::Rational(1, 1000000));
    const wrenchkit::json::Value* scaling = c.find("scaling");
    const bool proportional = scaling && scaling->text == "proportional";
    const std::optional<wrenchkit::Critical_mu> engine = balance ? a.equilibrium : proportional ? a.margin : a.closure;
    if (!engine) return 0;  // (no friction to scale: the checker's claim is about closure at any t)
    const wrenchkit::json::Value* claim = c.find("critical_mu");
    const std::string kind = claim->type == wrenchkit::json::Type::string ? claim->text : "value";
    if (kind != wrenchkit::critical_kind_name(engine->kind)) {
      std::cerr << "checker accepted critical mu \"" << kind << "\"; the engine finds " << wrenchkit::critical_kind_name(engine->kind) << "\n";
      std::abort();
    }
    if (kind == "value" && !overlap(q(claim->find("lower")), q(claim->find("upper")), engine->lower, engine->upper)) {
      std::cerr << "checker accepted critical mu in [" << claim->find("lower")->text << ", " << claim->find("upper")->text
                << "]; the engine finds [" << engine->lower << ", " << engine->upper << "]\n";
      std::abort();
    }
    return 0;
  }
  if (property == "\"hold\"") {  // the engine's certified answer, when it decides, must be the claim
    if (!scene.load) {
      std::cerr << "checker accepted a hold claim on a scene without load\n";
      std::abort();
    }
    if (scene.support && (scene.support->points.size() > 12 || !small_regions_for_hold(*scene.support))) return 0;
    const wrenchkit::Hold_answer a = wrenchkit::decide_hold(scene, wrenchkit::Mode::hybrid);
    if (a.verdict == wrenchkit::Hold_verdict::undecided) return 0;
    const std::string_view claim = value_of(cert, "holds");
    const std::string engine = hold_claim(a, version_of(cert));
    if (claim != engine) {
      std::cerr << "checker accepted hold " << claim << "; the engine certifies " << engine << "\n";
      std::abort();
    }
    return 0;
  }
  const bool form = property == "\"form_closure\"";
  const bool equilibrium = property == "\"equilibrium\"";
  if (equilibrium && !scene.load) {
    std::cerr << "checker accepted an equilibrium claim on a scene without load\n";
    std::abort();
  }
  const bool holds =
      equilibrium ? wrenchkit::decide_equilibrium(scene).balanced
                  : wrenchkit::decide_closure(scene, form ? wrenchkit::Property::form_closure
                                                          : wrenchkit::Property::force_closure)
                        .holds;
  if (holds != claims_holds) {
    std::cerr << "checker accepted a false claim\n";
    std::abort();
  }
  return 0;
}
