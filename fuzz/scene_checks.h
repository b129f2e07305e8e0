// The promises every fuzz target checks on a scene text (shared by fuzz_scene_parser, which feeds
// raw bytes, and fuzz_structured, which builds near-degenerate scenes from the bytes):
//   * every reader — the reference reader read_scene_tree eager and lazy, read_scene (the one-pass
//     reader) eager and lazy, into a fresh Scene and into one reused from the previous input — accepts
//     and rejects alike, with the same
//     message, and gives the same Scene field by field (readers_disagree; tests/scene_test.cpp runs
//     it on every bad-input case too);
//   * parse → write_scene → parse gives the same canonical text;
//   * closure: hybrid (always decided) and a decided float twin agree with exact;
//   * labels and the force dual agree with closure, the labels' load reading with equilibrium;
//   * every certificate (closure exact/hybrid, equilibrium in every mode) is accepted by the
//     independent checker, and float/hybrid equilibrium agrees with exact; hold's float and hybrid answers agree
//     and their certificates are accepted (small fixtures);
//   * hybrid labels are the exact labels; the labels and force-dual twins agree with them within their
//     stated bounds (testing/twin_agreement.h);
//   * with a small support: the float twin's true h lies in the exact polygonal bracket, and hybrid and
//     float stick/slide never contradict the exact polygons;
//   * with support regions (and legs whose forces are not given, RG-3): the power brackets are sound, and a load's
//     motion (over F) comes with a certificate the independent checker accepts.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#include "exact/certificates/certificates.h"
#include "exact/pipeline/answer_json.h"
#include "exact/statics/closure.h"
#include "exact/statics/equilibrium.h"
#include "exact/fixture/hold.h"
#include "fuzz/hold_scope.h"
#include "exact/statics/force_dual.h"
#include "exact/io/input_error.h"
#include "exact/io/scene.h"
#include "exact/io/scene_budget.h"
#include "exact/io/scene_writer.h"
#include "exact/pipeline/pipeline.h"
#include "exact/sliding/motion.h"
#include "exact/sliding/pushing.h"
#include "exact/sliding/region_sliding.h"
#include "exact/sliding/sliding.h"
#include "exact/sliding/strategies.h"
#include "exact/io/streaming_scene_reader.h"
#include "exact/io/to_float.h"
#include "testing/twin_agreement.h"
#include "proofs/checker/checker.h"

namespace scene_checks_detail {

using namespace wrenchkit;

inline bool same_bounded(const fl::Bounded& a, const fl::Bounded& b) {
  return (a.v == b.v || (a.v != a.v && b.v != b.v)) && (a.e == b.e || (a.e != a.e && b.e != b.e));
}
inline bool same_vec(const Vec2& a, const Vec2& b) { return a.x == b.x && a.y == b.y; }
inline bool same_wrench(const Vec3q& a, const Vec3q& b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }
inline bool same_twin(const fl::Bounded_contact& a, const fl::Bounded_contact& b) {
  return a.is_wrench == b.is_wrench && a.frictional == b.frictional && same_bounded(a.ax, b.ax) &&
         same_bounded(a.ay, b.ay) && same_bounded(a.nx, b.nx) && same_bounded(a.ny, b.ny) &&
         same_bounded(a.mu, b.mu) && same_bounded(a.fx, b.fx) && same_bounded(a.fy, b.fy) && same_bounded(a.m, b.m);
}
template <class T, class Same>
bool same_optional(const std::optional<T>& a, const std::optional<T>& b, Same same) {
  return a.has_value() == b.has_value() && (!a || same(*a, *b));
}

}  // namespace scene_checks_detail

// "" when a and b are the same Scene field by field (exact rationals, certified doubles bit for bit,
// kept number texts, flags), else the first field that differs.
inline std::string scene_difference(const wrenchkit::Scene& a, const wrenchkit::Scene& b) {
  using namespace scene_checks_detail;
  if (a.name != b.name) return "name";
  if (a.body.outline.size() != b.body.outline.size()) return "body.outline";
  for (std::size_t i = 0; i < a.body.outline.size(); ++i)
    if (!same_vec(a.body.outline[i], b.body.outline[i])) return "body.outline[" + std::to_string(i) + "]";
  if (!same_optional(a.body.com, b.body.com, same_vec)) return "body.com";
  if (a.contacts.size() != b.contacts.size()) return "contacts";
  for (std::size_t i = 0; i < a.contacts.size(); ++i) {
    const Contact &x = a.contacts[i], &y = b.contacts[i];
    const std::string at = "contacts[" + std::to_string(i) + "]";
    if (x.kind != y.kind || x.name != y.name) return at + " kind or name";
    if (!same_vec(x.at, y.at) || !same_vec(x.normal, y.normal) || x.mu != y.mu || !same_wrench(x.wrench, y.wrench))
      return at + " rationals";
    if (x.has_twin != y.has_twin || !same_twin(x.twin, y.twin)) return at + " certified doubles";
    if (x.exact_pending != y.exact_pending || x.number_text != y.number_text || x.number_is_json != y.number_is_json)
      return at + " kept number texts";
  }
  const auto same_load = [](const Load& x, const Load& y) {
    return x.kind == y.kind && same_vec(x.force, y.force) && same_vec(x.at, y.at) && same_wrench(x.wrench, y.wrench) &&
           x.weight == y.weight;
  };
  if (!same_optional(a.load, b.load, same_load)) return "load";
  const auto same_q = [](const Rational& x, const Rational& y) { return x == y; };
  const auto same_support = [&](const Support& x, const Support& y) {
    if (!same_optional(x.mu, y.mu, same_q) || !same_optional(x.weight, y.weight, same_q) ||
        !same_optional(x.pressure_center, y.pressure_center, same_vec) || x.points.size() != y.points.size())
      return false;
    for (std::size_t i = 0; i < x.points.size(); ++i)
      if (!same_vec(x.points[i].at, y.points[i].at) || !same_optional(x.points[i].force, y.points[i].force, same_q) ||
          !same_optional(x.points[i].mu, y.points[i].mu, same_q))
        return false;
    // Regions: as written, and everything settled from them (rings, triangles, pressure, measures).
    const auto same_ring = [&](const std::vector<Vec2>& r, const std::vector<Vec2>& t) {
      if (r.size() != t.size()) return false;
      for (std::size_t i = 0; i < r.size(); ++i)
        if (!same_vec(r[i], t[i])) return false;
      return true;
    };
    const auto same_rings = [&](const std::vector<std::vector<Vec2>>& r, const std::vector<std::vector<Vec2>>& t) {
      if (r.size() != t.size()) return false;
      for (std::size_t i = 0; i < r.size(); ++i)
        if (!same_ring(r[i], t[i])) return false;
      return true;
    };
    if (x.regions.size() != y.regions.size()) return false;
    for (std::size_t k = 0; k < x.regions.size(); ++k) {
      const Support_region &r = x.regions[k], &t = y.regions[k];
      if (!same_ring(r.outline, t.outline) || !same_rings(r.holes, t.holes) || r.uniform != t.uniform ||
          r.force != t.force || r.linear != t.linear || !same_optional(r.mu, t.mu, same_q) ||
          !same_rings(r.rings, t.rings) || r.pressure != t.pressure || r.area != t.area || r.total != t.total ||
          !same_vec(r.moment, t.moment) || r.second != t.second || r.triangles.size() != t.triangles.size())
        return false;
      for (std::size_t i = 0; i < r.triangles.size(); ++i)
        if (!same_vec(r.triangles[i].a, t.triangles[i].a) || !same_vec(r.triangles[i].b, t.triangles[i].b) ||
            !same_vec(r.triangles[i].c, t.triangles[i].c))
          return false;
    }
    return true;
  };
  if (!same_optional(a.support, b.support, same_support)) return "support";
  const auto same_pusher = [](const Pusher& x, const Pusher& y) {
    return same_vec(x.contact.at, y.contact.at) && same_vec(x.contact.normal, y.contact.normal) &&
           x.contact.mu == y.contact.mu && x.contact.name == y.contact.name && same_vec(x.velocity, y.velocity) &&
           x.end.has_value() == y.end.has_value() && (!x.end || same_vec(*x.end, *y.end)) && x.omega == y.omega;
  };
  if (!same_optional(a.pusher, b.pusher, same_pusher)) return "pusher";
  return "";
}

// Reads `text` with every reader: the reference reader read_scene_tree eager and lazy, and read_scene (one pass) eager and lazy,
// into a fresh Scene and into `reused_eager` / `reused_lazy` (whatever they held before: a previous
// scene, so stale state would show). Returns "" when all of them accept with the same Scene (eager
// with eager, lazy with lazy) or all reject with the same message, and the streaming reader read every
// valid scene in its one pass (unless max_depth < 5); else what differs. On return the reused scenes
// hold this text's scene when it was accepted.
inline std::string readers_disagree(std::string_view text, const wrenchkit::Input_limits& limits,
                                    wrenchkit::Scene& reused_eager, wrenchkit::Scene& reused_lazy) {
  using namespace wrenchkit;
  for (const bool lazy : {false, true}) {
    Scene reference, fresh;
    std::string want, got_fresh, got_reused;
    try {
      reference = read_scene_tree(text, limits, "fuzz", lazy);
    } catch (const Input_error& e) {
      want = e.what();
    }
    try {
      fresh = read_scene(text, limits, "fuzz", lazy);
    } catch (const Input_error& e) {
      got_fresh = e.what();
    }
    Scene& reused = lazy ? reused_lazy : reused_eager;
    bool one_pass = false;
    try {
      one_pass = read_scene_into(reused, text, limits, "fuzz", lazy);
    } catch (const Input_error& e) {
      got_reused = e.what();
    }
    const std::string reading = lazy ? "lazy" : "eager";
    if (got_fresh != want || got_reused != want)
      return reading + ": read_scene_tree says \"" + want + "\", the streaming reader \"" + got_fresh +
             "\" (into a reused scene: \"" + got_reused + "\")";
    if (!want.empty()) continue;
    if (!one_pass && limits.max_depth >= 5)
      return reading + ": the streaming reader deferred a valid scene to read_scene_tree (it must read it in one pass)";
    if (const std::string d = scene_difference(reference, fresh); !d.empty())
      return reading + ": the streaming reader's scene differs in " + d;
    if (const std::string d = scene_difference(reference, reused); !d.empty())
      return reading + ": the streaming reader's scene, read into a reused one, differs in " + d;
  }
  return "";
}

// [BUDGET] A valid scene (under `limits`) at the boundary of the scene-wide budget: with each budget set to
// the scene's own measure it is accepted, with either one less it is refused, by every reader alike
// (readers_disagree) and by the independent checker alike (bad_scene exactly when the engine refuses).
// The scene's canonical text (write_scene: what the Python bindings give the checker) measures no more.
// "" or what broke.
inline std::string budget_boundary_broken(std::string_view text, const wrenchkit::Input_limits& limits,
                                          wrenchkit::Scene& reused_eager, wrenchkit::Scene& reused_lazy) {
  using namespace wrenchkit;
  const Budget_tally m = measure_scene(text, limits);
  if (!m.within(limits)) return "a valid scene measures over its budget";
  const Budget_tally c = measure_scene(write_scene(read_scene(text, limits)), limits);
  if (c.total > m.total || c.longest > m.longest || c.entries != m.entries)
    return "the canonical text measures more than the scene";
  for (int k = 0; k < 3; ++k) {
    Input_limits l = limits;
    l.max_total_digits = m.total - (k == 1 && m.total > 0 ? 1 : 0);
    l.max_digits_times_contacts = m.digits_times_contacts() - (k == 2 && m.digits_times_contacts() > 0 ? 1 : 0);
    const bool refuse = (k == 1 && m.total > 0) || (k == 2 && m.digits_times_contacts() > 0);
    if (const std::string d = readers_disagree(text, l, reused_eager, reused_lazy); !d.empty())
      return "at the budget's boundary: " + d;
    bool engine_accepts = true;
    try {
      read_scene(text, l, "fuzz");
    } catch (const Input_error& e) {
      engine_accepts = false;
      if (refuse && std::string(e.what()).find(k == 1 ? "--max-total-digits" : "--max-digits-times-contacts") ==
                        std::string::npos)
        return std::string("over budget, but another message: ") + e.what();
    }
    if (engine_accepts == refuse) return std::string("budget ") + (refuse ? "one less accepted" : "itself refused");
    wrenchkit_checker::Limits cl = checker_limits(l);
    const auto r = wrenchkit_checker::check(text, "{}", cl);
    if ((r.outcome != wrenchkit_checker::Outcome::bad_scene) != engine_accepts)
      return std::string("the checker ") + (engine_accepts ? "refuses" : "accepts") +
             " the scene at the budget's boundary: " + r.message;
  }
  return "";
}

// Checks everything the engine promises about one input text; aborts (a finding) on a broken promise.
// Returns whether the text was a valid scene.
inline bool check_scene_text(std::string_view text) {
  wrenchkit::Input_limits limits;
  limits.max_digits = 200;  // keep big-number work small per input
  limits.max_exponent = 200;
  limits.max_contacts = 64;
  limits.max_region_vertices = 64;
  static wrenchkit::Scene reused_eager, reused_lazy;  // the previous input's scenes: reuse is checked too
  if (const std::string d = readers_disagree(text, limits, reused_eager, reused_lazy); !d.empty()) {
    std::cerr << "the scene readers disagree: " << d << "\n";
    std::abort();
  }
  wrenchkit::Scene scene, lazy;
  std::string eager_error, lazy_error;
  try {
    scene = wrenchkit::read_scene(text, limits, "fuzz");
  } catch (const wrenchkit::Input_error& e) {
    eager_error = e.what();
  }
  try {  // the lazy reading (batch) must accept and reject exactly the same, with the same message
    lazy = wrenchkit::read_scene(text, limits, "fuzz", true);
  } catch (const wrenchkit::Input_error& e) {
    lazy_error = e.what();
  }
  if (eager_error != lazy_error) {
    std::cerr << "eager: " << eager_error << "\nlazy: " << lazy_error << "\n";
    std::abort();
  }
  if (!eager_error.empty()) return false;
  if (const std::string d = budget_boundary_broken(text, limits, reused_eager, reused_lazy); !d.empty()) {
    std::cerr << d << "\n";
    std::abort();
  }
  // parse → print → parse: the canonical text reads back to the same scene.
  const std::string printed = wrenchkit::write_scene(scene);
  try {
    if (wrenchkit::write_scene(wrenchkit::read_scene(printed, limits, "printed")) != printed) {
      std::cerr << "round trip changed the scene:\n" << printed << "\n";
      std::abort();
    }
  } catch (const wrenchkit::Input_error& e) {
    std::cerr << "printed scene rejected: " << e.what() << "\n" << printed << "\n";
    std::abort();
  }
  std::string region_certificate;  // a support with regions and a load: its motion's certificate
  // A float answer, when the twin decides, is the exact one; hybrid always decides.
  for (auto p : {wrenchkit::Property::force_closure, wrenchkit::Property::form_closure}) {
    const bool exact = wrenchkit::decide_closure(scene, p, wrenchkit::Mode::exact, false).holds;
    const auto f = wrenchkit::decide_closure(scene, p, wrenchkit::Mode::float_only, false);
    if (f.decided && f.holds != exact) {
      std::cerr << "float twin certified a wrong closure verdict\n" << printed;
      std::abort();
    }
  }
  for (auto p : {wrenchkit::Property::force_closure, wrenchkit::Property::form_closure}) {
    const auto a = wrenchkit::decide_closure(scene, p, wrenchkit::Mode::hybrid, false);
    const auto b = wrenchkit::decide_closure(lazy, p, wrenchkit::Mode::hybrid, false);
    if (a.holds != b.holds || a.rank != b.rank) {
      std::cerr << "lazy and eager scenes disagree\n";
      std::abort();
    }
  }
  // Labels and the force dual come from the same cone: nothing labeled ⇔ closure ⇔ the dual covers
  // everything; the load read on the labels agrees with equilibrium.
  for (auto p : {wrenchkit::Property::force_closure, wrenchkit::Property::form_closure}) {
    const auto reading = wrenchkit::reading_of(p);
    std::vector<wrenchkit::Vec3q> w;
    for (const auto& g : wrenchkit::generators(scene, reading)) w.push_back(g.w);
    const auto l = wrenchkit::moment_labels(w);
    const auto d = wrenchkit::force_dual(l, w);
    const bool holds = wrenchkit::decide_closure(scene, p, wrenchkit::Mode::exact, false).holds;
    if (l.nothing_labeled() != holds || d.covers_all != holds) {
      std::cerr << "labels / dual disagree with closure\n" << printed;
      std::abort();
    }
    if (wrenchkit::labels_json(wrenchkit::moment_labels(scene, reading, wrenchkit::Mode::hybrid)) !=
        wrenchkit::labels_json(l)) {
      std::cerr << "hybrid labels differ from exact labels\n" << printed;
      std::abort();
    }
    const std::vector<wrenchkit::fl::Bounded3> tg = wrenchkit::fl::generators(wrenchkit::to_bounded(scene), reading);
    const wrenchkit::Dual_cone tdc = wrenchkit::compute_dual_cone(wrenchkit::fl::Float_kernel(tg));
    const std::string why = wrenchkit::labels_disagreement(wrenchkit::fl::moment_labels(tg, tdc), l) +
                            wrenchkit::dual_disagreement(wrenchkit::fl::force_dual(tg, tdc), d);
    if (!why.empty()) {
      std::cerr << "labels twin disagrees with exact: " << why << "\n" << printed;
      std::abort();
    }
    if (scene.load && reading == wrenchkit::Reading::friction) {
      const auto x = wrenchkit::load_wrench(scene);
      if (wrenchkit::in_cone(l.cone, {-x[0], -x[1], -x[2]}) !=
          wrenchkit::decide_equilibrium(scene, wrenchkit::Mode::exact, false).balanced) {
        std::cerr << "labels disagree with equilibrium\n" << printed;
        std::abort();
      }
    }
  }
  if (scene.support && !scene.support->regions.empty() && scene.support->known()) {
    // Support regions [RG-1] [RG-2]: certified power brackets that hold the double closed form (near the region),
    // and a load's motion only with a certificate the checker accepts (below).
    const wrenchkit::Vec3q twists[] = {{0, 0, 1}, {1, 0, 0}, {wrenchkit::Rational(1, 3), -2, -1}};
    for (const auto& q : twists) {
      const auto a = wrenchkit::region_sliding(*scene.support, q, wrenchkit::Rational(1, 1000));
      if (a.h_lo > a.h_hi || a.h_lo < 0) {
        std::cerr << "region power bracket is empty or negative\n" << printed;
        std::abort();
      }
    }
    if (scene.load) {
      const wrenchkit::Support_model model(scene);
      const auto p = wrenchkit::load_wrench(scene);
      const auto m = wrenchkit::decide_motion(model, p, wrenchkit::Mode::hybrid);
      if (m.motion != wrenchkit::Motion::undecided) region_certificate = wrenchkit::motion_certificate(model, p, m);
    }
  }
  if (scene.support && !scene.support->regions.empty() && !scene.support->known() && scene.load &&
      scene.support->points.size() <= 4) {
    // [RG-3] Regions beside legs whose forces are not given: stick/slide over F only with a format-2 certificate the
    // checker accepts (below).
    const wrenchkit::Support_model model(scene);
    const auto p = wrenchkit::load_wrench(scene);
    const auto m = wrenchkit::decide_motion(model, p, wrenchkit::Mode::hybrid);
    if (m.motion != wrenchkit::Motion::undecided) region_certificate = wrenchkit::motion_certificate(model, p, m);
  }
  if (scene.support && scene.support->regions.empty() && scene.support->points.size() <= 4) {
    // An unknown distribution: its first extreme distribution here, and sticks/slides/depends over all of them
    // in hybrid never contradicts exact (below).
    const wrenchkit::Admissible adm = wrenchkit::admissible_set(scene);
    const auto extreme = wrenchkit::vertices(*scene.support, adm);
    const wrenchkit::Polygonal_ls model(
        wrenchkit::merge_support(*scene.support, scene.support->known() ? nullptr : &extreme.at(0)),
        wrenchkit::make_directions(8));
    if (!scene.support->known() && scene.load) {
      const auto p = wrenchkit::load_wrench(scene);
      wrenchkit::Motion_options eight;
      eight.sides = 8;
      const wrenchkit::Support_model sm(scene);
      const auto e = wrenchkit::decide_motion(sm, p, wrenchkit::Mode::exact, eight);
      const auto h = wrenchkit::decide_motion(sm, p, wrenchkit::Mode::hybrid, eight);
      if (e.motion != wrenchkit::Motion::undecided && h.motion != wrenchkit::Motion::undecided &&
          e.motion != h.motion) {
        std::cerr << "stick/slide over the admissible distributions: hybrid contradicts exact\n" << printed;
        std::abort();
      }
    }
    const auto tw = wrenchkit::twin_support(model.support());
    const wrenchkit::Ls_polytope in = model.build(wrenchkit::Side::inner), out = model.build(wrenchkit::Side::outer);
    const wrenchkit::Vec3q twists[] = {{1, 0, 0}, {0, 1, 1}, {wrenchkit::Rational(1, 3), -2, -1}};
    for (const auto& q : twists) {
      const auto h = wrenchkit::fl::support_function(tw, {wrenchkit::to_bounded(q[0]), wrenchkit::to_bounded(q[1]),
                                                          wrenchkit::to_bounded(q[2])});
      const wrenchkit::Rational lo(wrenchkit::fl::lower(h)), hi(wrenchkit::fl::upper(h));
      if (std::isfinite(h.e) &&
          (hi < model.support_value(wrenchkit::Side::inner, q) || lo > model.support_value(wrenchkit::Side::outer, q))) {
        std::cerr << "float h outside the exact polygonal bracket\n" << printed;
        std::abort();
      }
    }
    if (scene.load) {
      const auto p = wrenchkit::load_wrench(scene);
      const auto e = wrenchkit::points_verdict(model, p, wrenchkit::Mode::exact, &in, &out);
      for (auto m : {wrenchkit::Mode::hybrid, wrenchkit::Mode::float_only}) {
        const auto f = wrenchkit::points_verdict(model, p, m, &in, &out);
        if (e.motion != wrenchkit::Motion::undecided && f.motion != wrenchkit::Motion::undecided && f.motion != e.motion) {
          std::cerr << "stick/slide: mode " << wrenchkit::mode_name(m) << " contradicts the exact polygons\n" << printed;
          std::abort();
        }
      }
    }
  }
  std::string push_certificate;  // [PU-1] a pushed body on its support: the rotation's certificate (below)
  if (scene.pusher && scene.pusher->line() && scene.support && scene.support->points.size() <= 8) {
    try {  // [PU-3] a line pusher: its stable-push verdict goes to the checker
      const wrenchkit::Support_model model(scene);
      const auto e = wrenchkit::decide_line_push(model, *scene.pusher);
      if (e.stable->verdict != wrenchkit::Stability::undecided) push_certificate = wrenchkit::push_certificate(e);
    } catch (const wrenchkit::Input_error&) {  // no friction under the body
    }
  } else if (scene.pusher && scene.support && scene.support->points.size() <= 8) {
    try {
      const wrenchkit::Support_model model(scene);
      const auto e = wrenchkit::decide_push(model, *scene.pusher, wrenchkit::Mode::exact);
      const auto f = wrenchkit::decide_push(model, *scene.pusher, wrenchkit::Mode::float_only);
      if (f.rotation != wrenchkit::Rotation::undecided && f.rotation != e.rotation) {
        std::cerr << "push: the float twin certified " << wrenchkit::rotation_name(f.rotation) << ", exact says "
                  << wrenchkit::rotation_name(e.rotation) << "\n" << printed;
        std::abort();
      }
      if (e.rotation != wrenchkit::Rotation::undecided) {
        wrenchkit::Push_answer with_contact = e;  // [PU-2] the contact mode's claim goes to the checker too
        with_contact.contact = wrenchkit::push_contact_mode(model, *scene.pusher, wrenchkit::Rational(1, 1000000));
        // [PU-4] and the rotation centres' pieces
        with_contact.locus = wrenchkit::push_locus(model, *scene.pusher, wrenchkit::senses_left(e.rotation));
        push_certificate = wrenchkit::push_certificate(with_contact);
      }
    } catch (const wrenchkit::Input_error&) {  // no friction under the body: refused, as the command refuses it
    }
  }
  wrenchkit_checker::Limits cl;
  cl.max_digits = limits.max_digits;
  cl.max_exponent = limits.max_exponent;
  cl.max_contacts = limits.max_contacts;
  cl.max_region_vertices = limits.max_region_vertices;
  std::vector<std::string> certs;
  if (!region_certificate.empty()) certs.push_back(region_certificate);
  if (!push_certificate.empty()) certs.push_back(push_certificate);
  for (auto p : {wrenchkit::Property::force_closure, wrenchkit::Property::form_closure})
    for (auto m : {wrenchkit::Mode::exact, wrenchkit::Mode::hybrid})
      certs.push_back(wrenchkit::certificate_json(wrenchkit::decide_closure(scene, p, m).certificate));
  if (scene.load) {
    const auto exact = wrenchkit::decide_equilibrium(scene, wrenchkit::Mode::exact);
    certs.push_back(wrenchkit::certificate_json(exact.certificate));
    for (auto m : {wrenchkit::Mode::hybrid, wrenchkit::Mode::float_only}) {
      const auto e = wrenchkit::decide_equilibrium(scene, m);
      if ((m == wrenchkit::Mode::hybrid && !e.decided) || (e.decided && e.balanced != exact.balanced)) {
        std::cerr << "equilibrium: mode " << wrenchkit::mode_name(m) << " disagrees with exact\n";
        std::abort();
      }
      if (e.decided) certs.push_back(wrenchkit::certificate_json(e.certificate));
    }
  }
  // hold (exact/fixture/hold.h) on small fixtures: float never contradicts hybrid, every certificate is checked.
  // (over support regions: every point force given, few coarse triangles — the cells run the exact LP)
  if (scene.load && (!scene.support || (scene.support->points.size() <= 12 && small_regions_for_hold(*scene.support))) &&
      scene.contacts.size() <= 12) {
    wrenchkit::Hold_verdict verdict[2];
    int k = 0;
    for (auto m : {wrenchkit::Mode::hybrid, wrenchkit::Mode::float_only}) {
      const wrenchkit::Hold_answer a = wrenchkit::decide_hold(scene, m);
      verdict[k++] = a.verdict;
      if (a.verdict != wrenchkit::Hold_verdict::undecided) certs.push_back(wrenchkit::hold_certificate(a));
    }
    if (verdict[0] != wrenchkit::Hold_verdict::undecided && verdict[1] != wrenchkit::Hold_verdict::undecided &&
        verdict[0] != verdict[1]) {
      std::cerr << "hold: float contradicts hybrid\n" << printed;
      std::abort();
    }
  }
  for (const std::string& cert : certs) {
    const auto r = wrenchkit_checker::check(text, cert, cl);
    if (r.outcome != wrenchkit_checker::Outcome::accepted) {
      std::cerr << "checker: " << r.message << "\ncertificate: " << cert << "\n";
      std::abort();
    }
  }
  return true;
}
