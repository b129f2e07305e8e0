// wrenchkit analyze (and demo): everything the scene's contents call for.
#include <iostream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli/common.h"
#include "exact/io/json_writer.h"
#include "exact/io/support_check.h"
#include "exact/pipeline/answer_json.h"
#include "exact/pipeline/support_answer.h"
#include "exact/statics/planar_region.h"
#include "exact/statics/equilibrium.h"
#include "exact/sliding/limit_surface.h"
#include "exact/sliding/sliding.h"

namespace wrenchkit::cli {

namespace {

// The support's limit surface: with --tolerance ε at the smallest N whose certified ratio meets ε
// (1/λ − 1 ≤ ε), else at the finest N in {32, 16, 8, 4} whose candidate normals stay within a small budget
// (analyze summarises; `limit-surface` answers any N and queries). With a force or wrench load, also
// whether that load sticks or slides on the support (by the mode: hybrid asks the float twin's search on
// the true surface first). Empty (with `why`) when the polytopes exceed the budget.
struct Ls_summary {
  std::string json, human;
  bool undecided = false;  // the load's motion
};
std::optional<Ls_summary> limit_surface_summary(const Options& o, const std::optional<Rational>& tolerance,
                                                const Scene& scene, std::string& why) {
  const Ls_support sup = merge_support(*scene.support);
  std::vector<int> sizes = {32, 16, 8, 4};
  if (tolerance) {
    const int n = smallest_sides(*tolerance, kMaxSides);
    if (n == 0) {
      why = "--tolerance needs more than " + std::to_string(kMaxSides) + " sides";
      return std::nullopt;
    }
    sizes = {n};
  }
  for (int n : sizes) {
    const Polygonal_ls model(sup, make_directions(n));
    if (!tolerance && model.candidate_count() > 20000 && n > 4) continue;
    if (model.candidate_count() > kMaxCandidates) {
      why = "the polytopes at " + std::to_string(n) + " sides would need " + std::to_string(model.candidate_count()) +
            " candidate normals (limit " + std::to_string(kMaxCandidates) + "); use wrenchkit limit-surface";
      return std::nullopt;
    }
    const Ls_polytope in = model.build(Side::inner), out = model.build(Side::outer);
    const Vec2 cof{sup.weighted_force_sum.x / sup.total_force, sup.weighted_force_sum.y / sup.total_force};
    const std::string lam = number_text(model.directions().lambda_sq);
    Ls_summary r;
    Json_writer j;
    j.object().member("sides", n).member("lambda_squared", model.directions().lambda_sq);
    j.key("center_of_friction").array().rational(cof.x).rational(cof.y).end_array();
    write_approx(j, "center_of_friction", {cof.x, cof.y});
    j.key("inner").object().member("facets", in.facets.size()).member("vertices", in.vertices.size()).end_object();
    j.key("outer").object().member("facets", out.facets.size()).member("vertices", out.vertices.size()).end_object();
    r.human = "limit surface (" + std::to_string(n) + " sides" + (tolerance ? ", the fewest meeting --tolerance" : "") +
              "): lambda^2 = " + lam + ", inner " + std::to_string(in.facets.size()) + " facets, outer " +
              std::to_string(out.facets.size()) + " facets; centre of friction " + vec_text(cof) + " — 'wrenchkit limit-surface' for any N, tolerances and queries\n";
    if (scene.load) {  // gravity beside the support presses it: nothing in-plane (load_wrench)
      const Vec3q p = load_wrench(scene);
      Motion_options mo;
      mo.sides = n;
      mo.polygons = {&model, &in, &out};
      const Motion_answer m = decide_motion(Support_model(scene), p, o.mode, mo);
      j.key("load_motion").object().key("load").rationals(p);
      write_approx(j, "load", {p[0], p[1], p[2]});
      j.member("motion", motion_name(m.motion)).member("decided_by", decided_by_name(m.decided_by)).end_object();
      r.human += "the load on the support: " + std::string(motion_name(m.motion)) + " (" +
                 (m.motion == Motion::undecided ? m.undecided_why : std::string(decided_by_words(m.decided_by))) + ")\n";
      r.undecided = m.motion == Motion::undecided;
    }
    r.json = j.end_object().take();
    return r;
  }
  why = "too many support points for analyze's summary; use wrenchkit limit-surface";
  return std::nullopt;
}

// A support with regions [RG-1]: the exact statics and, with a force or wrench load, its motion with the certificate
// the pipeline checked (answer_support). Empty (with `why`) when the pipeline does not answer (float mode).
std::optional<Ls_summary> region_summary(const Options& o, const Scene& scene, const std::string& text,
                                         const std::string& source, std::string& why) {
  Support_query q;
  if (scene.load) q.load = load_wrench(scene);
  const Support_item r = answer_support(scene, text, source, request_of(o), q);
  if (r.status != Status::answered) {
    why = r.message;
    return std::nullopt;
  }
  const Region_sliding& st = *r.regions;
  Ls_summary out;
  Json_writer j;
  j.object().member("regions", scene.support->regions.size()).member("total_force", st.total_force);
  j.key("center_of_friction").array().rational(st.center_of_pressure.x).rational(st.center_of_pressure.y).end_array();
  write_approx(j, "center_of_friction", {st.center_of_pressure.x, st.center_of_pressure.y});
  j.member("mu_f0", st.mu_f0).member("strictly_convex", true);
  out.human = "limit surface: " + std::to_string(scene.support->regions.size()) +
              " region(s) with a continuous pressure (strictly convex, no polytope); total force " +
              number_text(st.total_force) + ", centre of friction " + vec_text(st.center_of_pressure) + " — 'wrenchkit sliding' and 'limit-surface' for twists and loads\n";
  if (q.load) {
    const Motion_answer& m = *r.motion;
    j.key("load_motion").object().key("load").rationals(*q.load);
    write_approx(j, "load", {(*q.load)[0], (*q.load)[1], (*q.load)[2]});
    j.member("motion", motion_name(m.motion));
    j.member("decided_by", decided_by_name(m.decided_by)).member("certificate_checked", !r.certificate.empty()).end_object();
    out.human += "the load on the support: " + std::string(motion_name(m.motion)) +
                 (m.motion == Motion::undecided ? " (" + m.undecided_why + ")"
                                                : " (a certificate over the regions' cells, accepted by the checker)") +
                 "\n";
    out.undecided = m.motion == Motion::undecided;
  }
  out.json = j.end_object().take();
  return out;
}

// analyze: everything the scene's contents call for, and nothing else — closure of its contacts
// (always: no contacts is an answer too), equilibrium when it has a load, a summary of the limit
// surface when it has a support. What cannot be computed within analyze's budget is listed under
// "skipped", never silently dropped.
struct Analysis {
  Scene scene;
  Closure_item closure;
  std::optional<Equilibrium_item> equilibrium;
  std::optional<Ls_summary> limit_surface;
  std::optional<Hold_item> hold;  // contacts, a support and an in-plane load: the two together
  std::optional<Quality_item> quality;  // point contacts: ε and μ* (docs/quality.md)
  std::vector<std::pair<std::string, std::string>> skipped;
  // Some answer is undecided (the exit code is 3).
  bool undecided() const {
    return (limit_surface && limit_surface->undecided) || (hold && hold->answer.verdict == Hold_verdict::undecided);
  }
};

Analysis analyze(const Options& o, const std::optional<Rational>& tolerance, const std::string& scene_text,
                 const std::string& source) {
  Analysis a;
  const Request request = request_of(o);
  a.closure = answered(answer_closure(scene_text, source, request, a.scene));
  if (a.scene.load) a.equilibrium = answered(answer_equilibrium(a.scene, scene_text, request));
  if (a.scene.support && !a.scene.support->known()) {
    a.skipped.push_back({"limit_surface", "the forces of some support points are not given: use 'wrenchkit "
                                          "limit-surface --load' or 'sliding --twist' (they answer over every "
                                          "admissible distribution)"});
  } else if (a.scene.support) {
    std::string why;
    a.limit_surface = a.scene.support->regions.empty() ? limit_surface_summary(o, tolerance, a.scene, why)
                                                       : region_summary(o, a.scene, scene_text, source, why);
    if (!a.limit_surface) a.skipped.push_back({"limit_surface", why});
  } else if (tolerance) {
    a.skipped.push_back({"limit_surface", "--tolerance was given but the scene has no support"});
  }
  // Equilibrium above is the contacts without the support; the load's motion on the support is the support without
  // the contacts; hold is both together (docs/fixtures.md).
  if (!a.scene.contacts.empty() && a.scene.support && a.scene.load)
    a.hold = answered(answer_hold(a.scene, scene_text, request));
  // How good the grasp is (ε with the defaults of `wrenchkit quality`); the critical friction is `quality`'s own
  // question: ~1 ms of exact decisions per scene, a hundred times analyze's other answers (bench/performance-notes.md)
  std::size_t points = 0;
  for (const Contact& c : a.scene.contacts) points += c.kind == Contact::Kind::point;
  if (points > 0 && o.mode == Mode::float_only) {
    a.skipped.push_back({"quality", "epsilon has no float twin: use --mode hybrid or exact"});
  } else if (points > 0) {
    Quality_query q;
    q.critical_mu = false;
    Quality_item item = answer_quality(a.scene, scene_text, request, q);
    if (item.status == Status::bad_input) a.skipped.push_back({"quality", item.message});  // past its work bound
    else a.quality = answered(std::move(item));
  }
  return a;
}

void write_analysis(Json_writer& w, const Options& o, const Analysis& a, const char* command) {
  w.member("command", command).member("name", a.scene.name);
  if (!a.scene.body.outline.empty() && a.scene.warnings.empty())  // the outline as checked (exact/io/outline.h)
    w.key("outline").object().member("vertices", a.scene.body.outline.size())
        .member("orientation", a.scene.body.outline_ccw ? "counter-clockwise" : "clockwise")
        .member("convex", a.scene.body.outline_convex).end_object();
  if (!a.scene.warnings.empty()) {
    w.key("warnings").array();
    for (const std::string& x : a.scene.warnings) w.string(x);
    w.end_array();
  }
  write_closure(w.key("closure").object(), o, a.closure, "closure");
  w.end_object();
  if (a.equilibrium) {
    write_equilibrium(w.key("equilibrium").object(), o, *a.equilibrium, "equilibrium");
    w.end_object();
  }
  if (a.limit_surface) w.key("limit_surface").raw(a.limit_surface->json);
  if (a.hold) {
    write_hold(w.key("hold").object(), *a.hold);
    w.end_object();
  }
  if (a.quality) {
    write_quality(w.key("quality").object(), *a.quality);
    w.end_object();
  }
  w.key("skipped").array();
  for (const auto& [what, why] : a.skipped) w.object().member("what", what).member("why", why).end_object();
  w.end_array();
}

}  // namespace

Scene_answer prepare_analyze_json(const Options& o) {
  return [o, tolerance = o.tolerance](Json_writer& w, const std::string& text, const std::string& source) {
    write_analysis(w, o, analyze(o, tolerance, text, source), "analyze");
  };
}

int run_analyze(const Options& o, const std::string& scene_text, const std::string& source, const char* command) {
  const Analysis a = analyze(o, o.tolerance, scene_text, source);
  if (o.json) {
    std::cout << json_answer([&](Json_writer& w) { write_analysis(w, o, a, command); }, 2048) << "\n";
    return a.undecided() ? kUndecided : kAnswered;
  }
  // No contacts: closure and equilibrium have nothing to say (their JSON keeps the trivial answers); say so in words.
  const bool contacts = !a.scene.contacts.empty();
  const Body& body = a.scene.body;
  if (!body.outline.empty() && a.scene.warnings.empty())
    std::cout << scene_line(a.scene, source) << "outline: " << body.outline.size() << " vertices, "
              << (body.outline_ccw ? "counter-clockwise" : "clockwise") << ", " << (body.outline_convex ? "convex" : "not convex")
              << "; every contact on it, its normal pointing into the body\n";
  else
    std::cout << scene_line(a.scene, source);
  std::cout << frictionless_note(a.scene)
            << (contacts ? closure_human(a.closure, a.scene)
                         : std::string("contacts: none (closure and equilibrium are questions about contacts") +
                               (a.scene.support ? "; the support's friction is below)\n" : ")\n"));
  if (a.equilibrium && contacts) std::cout << equilibrium_human(*a.equilibrium);
  if (a.limit_surface) std::cout << a.limit_surface->human;
  if (a.hold)
    std::cout << "hold — the contacts and the support's friction together (equilibrium above is the contacts alone, the "
                 "load on the support the support alone):\n"
              << hold_human(*a.hold);
  if (a.quality) std::cout << quality_body(*a.quality) << "  (the friction it needs: wrenchkit quality --only critical-mu)\n";
  for (const auto& [what, why] : a.skipped) std::cout << "skipped " << what << ": " << why << "\n";
  if (contacts)
    std::cout << "decided by: " << arithmetic_name(a.closure.decided_by()) << " for closure"
              << (a.equilibrium ? std::string(", ") + arithmetic_name(a.equilibrium->answer.decided_by()) +
                                      " for equilibrium"
                                : std::string())
              << "\n";
  std::cout
            << "every certificate accepted by the independent checker (exact arithmetic)\n";
  return a.undecided() ? kUndecided : kAnswered;
}

}  // namespace wrenchkit::cli
