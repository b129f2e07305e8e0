// [ST-2] The numerical-stability stress report (docs/stability.md, issue 6): families of scenes at a controlled
// distance ε from a degenerate configuration (testing/stress_families.h [ST-1], fuzz/families.h), written as
// text as users write it. For each family and ε, and for each question the family's scenes ask —
// closure or equilibrium (the verdict), moment labels, stick/slide — it counts how often naive floating
// point (the text read by strtod, raw double signs) is wrong, how often the certified twin abstains, and
// that the twin, hybrid and exact answers are never wrong; with times per query. The truth of every case
// is cross-checked: by construction for the exact families (the answer is known for every ε), by the
// independent certificate checker (proofs/checker, no engine code) for every closure and equilibrium
// verdict, by the untransformed scene where the family has one (an exact symmetry: same answers), and for
// labels by their own closure / load reading (theory.md §5.5).
//
//   stress_report [--cases N] [--seed S] [--families A,B,…] [--report DIR] [--campaign FILE]
//                 [--inject-fault twin|hybrid|exact]
//
//   --report DIR     write DIR/stability.md and DIR/stability.svg (keeps the campaign section of an
//                    existing DIR/stability.md)
//   --campaign FILE  write the totals of this run into the campaign section of FILE (a stability.md)
//   --inject-fault   test only: flip the first decided answer of that kind, to prove the run then fails
// Exit status 1 if a certified (twin, hybrid, exact) answer was ever wrong, 2 on a usage error.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "exact/certificates/certificates.h"
#include "exact/pipeline/answer_json.h"
#include "exact/pipeline/hold_answer.h"
#include "exact/pipeline/push_answer.h"
#include "exact/pipeline/support_answer.h"
#include "exact/statics/equilibrium.h"
#include "exact/io/to_float.h"
#include "testing/twin_agreement.h"
#include "fuzz/families.h"
#include "proofs/checker/checker.h"

namespace {

using namespace wrenchkit;
using families::Family;
using families::Question;

const std::vector<double> kEpsilons = {1e-2,  1e-4,  1e-6,  1e-8,  1e-10, 1e-12, 1e-13,
                                       1e-14, 1e-15, 1e-16, 1e-20, 1e-30, 1e-40};
constexpr int kSides = 16;  // polygonal bounds of the exact stick/slide route (1/λ − 1 ≈ 2 %)

// What a row measures: the family's verdict (closure / equilibrium), its moment labels, or stick/slide.
enum class Measure { verdict, labels, motion, motion_over, hold, push, push_contact, push_stable };
const char* check_name(Measure c) {
  return c == Measure::verdict ? "verdict" : c == Measure::labels ? "labels" : c == Measure::motion ? "stick/slide"
                                           : c == Measure::motion_over ? "stick/slide over F"
                                           : c == Measure::hold ? "hold"
                                           : c == Measure::push ? "rotation (push)"
                                           : c == Measure::push_contact ? "contact mode (push)" : "stable push (fence)";
}
// The questions without moment labels (a support's, or the support's and the contacts' together).
bool is_motion(Question q) {
  return q == Question::stick_slide || q == Question::stick_slide_over || q == Question::hold ||
         q == Question::stick_slide_region || q == Question::push || q == Question::push_contact ||
         q == Question::push_stable;
}

struct Row {
  std::string family;
  Measure check = Measure::verdict;
  double eps = 0;
  long cases = 0, naive_wrong = 0, twin_undecided = 0, twin_wrong = 0, hybrid_undecided = 0, hybrid_wrong = 0,
       exact_undecided = 0, exact_wrong = 0;
  double t_naive = 0, t_twin = 0, t_hybrid = 0, t_exact = 0;  // seconds in all
  void add(const Row& o) {
    cases += o.cases, naive_wrong += o.naive_wrong, twin_undecided += o.twin_undecided, twin_wrong += o.twin_wrong;
    hybrid_undecided += o.hybrid_undecided, hybrid_wrong += o.hybrid_wrong, exact_undecided += o.exact_undecided;
    exact_wrong += o.exact_wrong, t_naive += o.t_naive, t_twin += o.t_twin, t_hybrid += o.t_hybrid,
        t_exact += o.t_exact;
  }
  long certified_wrong() const { return twin_wrong + hybrid_wrong + exact_wrong; }
};

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

template <class F>
auto timed(double& acc, F&& f) {
  const double t = now();
  auto r = f();
  acc += now() - t;
  return r;
}

// Test-only fault injection (--inject-fault): the first decided answer of this kind is flipped.
std::string g_fault;
bool fault(const char* kind) {
  if (g_fault != kind) return false;
  g_fault.clear();
  return true;
}
// The three modes' verdicts of one case, the injected fault applied to the decided one of its kind (`flip`: the other
// verdict).
template <class V, class Flip>
void inject_faults(V& twin, V& hybrid, V& exact, V undecided, Flip flip) {
  if (twin != undecided && fault("twin")) twin = flip(twin);
  if (hybrid != undecided && fault("hybrid")) hybrid = flip(hybrid);
  if (exact != undecided && fault("exact")) exact = flip(exact);
}

// Cases per ε for a family: the large families are expensive per case (measured in docs/stability.md).
long cases_for(const Family& f, long cases) {
  const std::string n = f.name;
  if (n == "many_contacts") return std::max(1L, cases / 25);
  if (n == "collinear_support") return std::max(1L, cases / 20);
  if (n == "unknown_support") return std::max(1L, cases / 20);
  if (n == "fixture_pin") return std::max(1L, cases / 10);
  if (n == "region_support" || n == "region_legs") return std::max(1L, cases / 20);
  if (n == "push_motion_cone") return std::max(1L, cases / 10);
  return cases;
}

// A wrong certified answer: say so with the seed, and dump the scene to failures/ (and, when short, to stderr).
void report_wrong(const char* what, const families::Case& k, std::uint64_t seed, long index, const std::string& why) {
  std::error_code ec;
  std::filesystem::create_directories("failures", ec);
  const std::string file = "failures/stress_" + k.family + "_" + std::to_string(k.eps) + "_" + std::to_string(index) +
                           ".scene.json";
  std::ofstream(file, std::ios::binary) << k.text << "\n";
  std::fprintf(stderr, "WRONG certified answer (%s): family %s eps %g seed %llu case %ld%s%s; scene in %s\n%s\n", what,
               k.family.c_str(), k.eps, static_cast<unsigned long long>(seed), index, why.empty() ? "" : ": ",
               why.c_str(), file.c_str(), k.text.size() < 20000 ? k.text.c_str() : "");
}

// The exact verdict's certificate, accepted by the independent checker, proves it (a second exact route).
bool certificate_proves(const Scene& scene, const std::string& text, Question q, bool holds) {
  std::string cert;
  if (q == Question::equilibrium) {
    const Equilibrium_answer a = decide_equilibrium(scene, Mode::exact, true);
    if (a.balanced != holds) return false;
    cert = certificate_json(a.certificate);
  } else {
    const Closure_answer a = decide_closure(
        scene, q == Question::force_closure ? Property::force_closure : Property::form_closure, Mode::exact);
    if (a.holds != holds) return false;
    cert = certificate_json(a.certificate);
  }
  return wrenchkit_checker::check(text, cert).outcome == wrenchkit_checker::Outcome::accepted;
}

// One case of a closure or equilibrium family: the verdict row and the labels row.
void run_contact_case(const families::Case& k, std::uint64_t seed, long index, Row& verdict, Row& labels) {
  const Scene scene = read_scene(k.text, Input_limits{});
  const Question q = k.question;
  const bool truth = k.expected;
  // Verdict.
  families::Verdict exact = timed(verdict.t_exact, [&] { return families::decide(scene, q, Mode::exact); });
  families::Verdict twin = timed(verdict.t_twin, [&] { return families::decide(scene, q, Mode::float_only); });
  families::Verdict hybrid = timed(verdict.t_hybrid, [&] { return families::decide(scene, q, Mode::hybrid); });
  const bool naive = timed(verdict.t_naive, [&] { return families::naive_verdict(k); });
  if (twin.decided && fault("twin")) twin.holds = !twin.holds;
  if (fault("hybrid")) hybrid.holds = !hybrid.holds;
  if (fault("exact")) exact.holds = !exact.holds;
  ++verdict.cases;
  verdict.naive_wrong += naive != truth;
  verdict.twin_undecided += !twin.decided;
  if (twin.decided && twin.holds != truth) ++verdict.twin_wrong, report_wrong("twin", k, seed, index, "");
  if (!hybrid.decided || hybrid.holds != truth) ++verdict.hybrid_wrong, report_wrong("hybrid", k, seed, index, "");
  std::string why;
  if (exact.holds != truth) why = "differs from the truth by construction";
  else if (!certificate_proves(scene, k.text, q, exact.holds)) why = "certificate not accepted by the checker";
  else if (!k.untransformed.empty() &&
           families::decide(read_scene(k.untransformed, Input_limits{}), q, Mode::exact).holds != exact.holds)
    why = "differs from the untransformed scene's";
  if (!why.empty()) ++verdict.exact_wrong, report_wrong("exact", k, seed, index, why);

  // Moment labels (of the question's reading; friction for equilibrium).
  const Reading reading = families::reading_of(q);
  const Moment_labels le = timed(labels.t_exact, [&] { return moment_labels(scene, reading, Mode::exact); });
  const Moment_labels lh = timed(labels.t_hybrid, [&] { return moment_labels(scene, reading, Mode::hybrid); });
  const fl::Labels_twin lt =
      timed(labels.t_twin, [&] { return fl::moment_labels(fl::generators(to_bounded(scene), reading)); });
  const fl::Labels_twin ln =
      timed(labels.t_naive, [&] { return fl::moment_labels_naive(families::naive_generators(k)); });
  ++labels.cases;
  labels.naive_wrong += !ln.decided() || families::labels_signature(ln) != families::labels_signature(le);
  labels.twin_undecided += !lt.decided();
  std::string twin_why = labels_disagreement(lt, le);
  if (lt.decided() && fault("twin")) twin_why = "injected fault";
  if (!twin_why.empty()) ++labels.twin_wrong, report_wrong("labels twin", k, seed, index, twin_why);
  if (labels_json(lh) != labels_json(le) || fault("hybrid"))
    ++labels.hybrid_wrong, report_wrong("labels hybrid", k, seed, index, "not the exact labels");
  // The exact labels read back: nothing labeled ⇔ closure (§5.5); the load balanced ⇔ −w ∈ W.
  bool exact_ok;
  if (q == Question::equilibrium) {
    const Vec3q w = load_wrench(scene);
    exact_ok = in_cone(le.cone, {-w[0], -w[1], -w[2]}) == truth;
  } else {
    exact_ok = le.nothing_labeled() == truth;
  }
  if (!exact_ok || fault("exact"))
    ++labels.exact_wrong, report_wrong("labels exact", k, seed, index, "labels contradict the truth");
}

// One stick/slide case.
void run_motion_case(const families::Case& k, std::uint64_t seed, long index, Row& row) {
  const Scene scene = read_scene(k.text, Input_limits{});
  const bool truth = k.expected;
  families::Verdict exact = timed(row.t_exact, [&] { return families::decide_motion(k, scene, Mode::exact, kSides); });
  families::Verdict twin =
      timed(row.t_twin, [&] { return families::decide_motion(k, scene, Mode::float_only, kSides); });
  families::Verdict hybrid =
      timed(row.t_hybrid, [&] { return families::decide_motion(k, scene, Mode::hybrid, kSides); });
  const bool naive = timed(row.t_naive, [&] {
    return scene.support->regions.empty() ? families::naive_slides(k) : families::naive_region_slides(k);
  });
  if (twin.decided && fault("twin")) twin.holds = !twin.holds;
  if (hybrid.decided && fault("hybrid")) hybrid.holds = !hybrid.holds;
  if (exact.decided && fault("exact")) exact.holds = !exact.holds;
  ++row.cases;
  row.naive_wrong += naive != truth;
  row.twin_undecided += !twin.decided;
  row.hybrid_undecided += !hybrid.decided;
  row.exact_undecided += !exact.decided;
  if (twin.decided && twin.holds != truth) ++row.twin_wrong, report_wrong("stick/slide twin", k, seed, index, "");
  if (hybrid.decided && hybrid.holds != truth)
    ++row.hybrid_wrong, report_wrong("stick/slide hybrid", k, seed, index, "");
  if (exact.decided && exact.holds != truth) ++row.exact_wrong, report_wrong("stick/slide exact", k, seed, index, "");
}

// A support question through the pipeline in `mode`; `why` gets the message of any ending but answered or undecided
// (an error, or a certificate the checker rejected: a wrong answer).
Support_item pipeline_answer(const Scene& scene, const std::string& text, const Support_query& query, Mode mode,
                             std::string& why) {
  Request request;
  request.mode = mode;
  Support_item item = answer_support(scene, text, "stress", request, query);
  if (item.status != Status::answered && item.status != Status::undecided) why = item.message;
  return item;
}

// stick/slide over every admissible distribution (unknown_support): each mode through the pipeline (the same
// answer_support as the CLI), the certificate checked by the independent checker there (a rejected one is a
// wrong answer). Right = one of the answers the construction leaves possible, and the same as the other mode
// when both decide. The naive guess: the even split of the unknown weight, then the naive search — one
// definite answer where the truth may be "depends".
void run_motion_over_case(const families::Case& k, std::uint64_t seed, long index, Row& row) {
  const Scene scene = read_scene(k.text, Input_limits{});
  Support_query query;
  query.question = Support_question::limit_surface;
  query.sides = kSides;
  query.load = k.motion_load;
  query.polytopes = false;
  const auto answer_in = [&](Mode mode, std::string& why) {
    const Support_item item = pipeline_answer(scene, k.text, query, mode, why);
    return item.status == Status::answered && item.motion ? item.motion->motion : Motion::undecided;
  };
  std::string why_exact, why_twin, why_hybrid;
  Motion exact = timed(row.t_exact, [&] { return answer_in(Mode::exact, why_exact); });
  Motion twin = timed(row.t_twin, [&] { return answer_in(Mode::float_only, why_twin); });
  Motion hybrid = timed(row.t_hybrid, [&] { return answer_in(Mode::hybrid, why_hybrid); });
  const bool naive = timed(row.t_naive, [&] {
    return scene.support->regions.empty() ? families::naive_slides(k) : families::naive_region_slides(k);
  });
  const auto bit = [](Motion m) {
    return m == Motion::sticks ? stress::answer_sticks : m == Motion::slides ? stress::answer_slides
                                                                                         : stress::answer_depends;
  };
  const auto flip = [&](Motion m) {  // fault injection: an answer the construction rules out, or another one
    for (Motion o : {Motion::sticks, Motion::slides, Motion::depends})
      if (o != m && !(k.allowed & bit(o))) return o;
    return m == Motion::sticks ? Motion::depends : Motion::sticks;
  };
  inject_faults(twin, hybrid, exact, Motion::undecided, flip);
  const auto wrong = [&](Motion m, Motion other, const std::string& why) {
    if (!why.empty()) return true;  // an error or a rejected certificate
    if (m == Motion::undecided) return false;
    return !(k.allowed & bit(m)) || (other != Motion::undecided && other != m);
  };
  ++row.cases;
  const Motion truth = exact != Motion::undecided ? exact : hybrid;
  const Motion naive_answer = naive ? Motion::slides : Motion::sticks;
  row.naive_wrong += !(k.allowed & bit(naive_answer)) || (truth != Motion::undecided && truth != naive_answer);
  row.twin_undecided += twin == Motion::undecided;
  row.hybrid_undecided += hybrid == Motion::undecided;
  row.exact_undecided += exact == Motion::undecided;
  if (wrong(twin, hybrid, why_twin)) ++row.twin_wrong, report_wrong("over F twin", k, seed, index, why_twin);
  if (wrong(hybrid, exact, why_hybrid)) ++row.hybrid_wrong, report_wrong("over F hybrid", k, seed, index, why_hybrid);
  if (wrong(exact, hybrid, why_exact)) ++row.exact_wrong, report_wrong("over F exact", k, seed, index, why_exact);
}

// hold (fixture_pin): exact, twin (--mode float) and hybrid through the pipeline (every certificate checked);
// naive: the push's magnitude against μW in doubles read from the text (the closed form, guessed). The truth is
// known by construction: holds iff not `above`.
void run_hold_case(const families::Case& k, std::uint64_t seed, long index, Row& row) {
  const Scene scene = read_scene(k.text, Input_limits{});
  const auto answer_in = [&](Mode mode, std::string& why) {
    Request request;
    request.mode = mode;
    const Hold_item item = answer_hold(scene, k.text, request);
    if (item.status == Status::answered) return item.answer.verdict;
    if (item.status != Status::undecided) why = item.message;
    return Hold_verdict::undecided;
  };
  std::string why_exact, why_twin, why_hybrid;
  Hold_verdict exact = timed(row.t_exact, [&] { return answer_in(Mode::exact, why_exact); });
  Hold_verdict twin = timed(row.t_twin, [&] { return answer_in(Mode::float_only, why_twin); });
  Hold_verdict hybrid = timed(row.t_hybrid, [&] { return answer_in(Mode::hybrid, why_hybrid); });
  const bool naive_holds = timed(row.t_naive, [&] {
    double mw = 0, mu = 0;
    const Support& s = *scene.support;
    mu = Rational(*s.mu).get_d();
    for (const Support_point& p : s.points) mw += mu * Rational(*p.force).get_d();
    const double fx = Rational(scene.load->force.x).get_d(), fy = Rational(scene.load->force.y).get_d();
    return std::sqrt(fx * fx + fy * fy) <= mw;
  });
  const auto flip = [](Hold_verdict v) { return v == Hold_verdict::holds ? Hold_verdict::fails : Hold_verdict::holds; };
  inject_faults(twin, hybrid, exact, Hold_verdict::undecided, flip);
  const Hold_verdict truth = k.above ? Hold_verdict::fails : Hold_verdict::holds;
  const auto wrong = [&](Hold_verdict v, const std::string& why) {
    return !why.empty() || (v != Hold_verdict::undecided && v != truth);
  };
  ++row.cases;
  row.naive_wrong += naive_holds != (truth == Hold_verdict::holds);
  row.twin_undecided += twin == Hold_verdict::undecided;
  row.hybrid_undecided += hybrid == Hold_verdict::undecided;
  row.exact_undecided += exact == Hold_verdict::undecided;
  if (wrong(twin, why_twin)) ++row.twin_wrong, report_wrong("hold twin", k, seed, index, why_twin);
  if (wrong(hybrid, why_hybrid)) ++row.hybrid_wrong, report_wrong("hold hybrid", k, seed, index, why_hybrid);
  if (wrong(exact, why_exact)) ++row.exact_wrong, report_wrong("hold exact", k, seed, index, why_exact);
}

// push (push_near_tie): exact through the pipeline (its certificate checked), the twin (--mode float) and hybrid
// (the twin, exact where it abstains); naive: the velocity's vote in doubles read from the text — the centre of
// friction and the cross product in raw double arithmetic (a guess). The truth by construction: ccw iff `above`.
void run_push_case(const families::Case& k, std::uint64_t seed, long index, Row& row) {
  const Scene scene = read_scene(k.text, Input_limits{});
  const Support_model model(scene);
  std::string why_exact;
  Rotation exact = timed(row.t_exact, [&] {
    const Push_item item = answer_push(k.text, "push_near_tie", Request{});
    if (item.status != Status::answered) why_exact = item.message;
    return item.status == Status::answered ? item.push.rotation : Rotation::undecided;
  });
  Rotation twin = timed(row.t_twin, [&] { return decide_push(model, *scene.pusher, Mode::float_only).rotation; });
  Rotation hybrid = timed(row.t_hybrid, [&] { return decide_push(model, *scene.pusher, Mode::hybrid).rotation; });
  const int naive = timed(row.t_naive, [&] {
    double mx = 0, my = 0, d = 0;
    const Support& s = *scene.support;
    for (const Support_point& p : s.points) {
      const double w = s.mu_of(p).get_d() * p.force->get_d();
      mx += w * p.at.x.get_d(), my += w * p.at.y.get_d(), d += w;
    }
    const Pusher& ps = *scene.pusher;
    const double v = (ps.contact.at.x.get_d() - mx / d) * ps.velocity.y.get_d() -
                     (ps.contact.at.y.get_d() - my / d) * ps.velocity.x.get_d();
    return v > 0 ? 1 : v < 0 ? -1 : 0;
  });
  const auto flip = [](Rotation v) { return v == Rotation::ccw ? Rotation::cw : Rotation::ccw; };
  inject_faults(twin, hybrid, exact, Rotation::undecided, flip);
  const Rotation truth = k.above ? Rotation::ccw : Rotation::cw;
  ++row.cases;
  row.naive_wrong += naive != (k.above ? 1 : -1);
  row.twin_undecided += twin == Rotation::undecided;
  row.hybrid_undecided += hybrid == Rotation::undecided;
  row.exact_undecided += exact == Rotation::undecided;
  const auto wrong = [&](Rotation v) { return v != Rotation::undecided && v != truth; };
  if (wrong(twin)) ++row.twin_wrong, report_wrong("push twin", k, seed, index, "");
  if (wrong(hybrid)) ++row.hybrid_wrong, report_wrong("push hybrid", k, seed, index, "");
  if (wrong(exact) || !why_exact.empty()) ++row.exact_wrong, report_wrong("push exact", k, seed, index, why_exact);
}

// push --contact (push_motion_cone): each mode through the pipeline (the certificate checked there: a rejected one,
// or any error, is a wrong answer). The contact mode has no float twin: in every mode it is the certified bracket
// search of PU-2 (exact signs of interval sums), so the three columns measure one method; naive: the double search
// of testing/stress_families.h (a guess). The truth by construction: slides left iff `above`, else sticks.
void run_push_contact_case(const families::Case& k, std::uint64_t seed, long index, Row& row) {
  const Scene scene = read_scene(k.text, Input_limits{});
  Push_query query;
  query.contact = true;
  // (why: set when the pipeline failed — anything but an answer or an honest "undecided")
  const auto answer_in = [&](Mode mode, std::string& why) {
    Request request;
    request.mode = mode;
    const Push_item item = answer_push(k.text, "push_motion_cone", request, query);
    if (item.status != Status::answered && item.status != Status::undecided) why = item.message;
    return item.status == Status::answered && item.push.contact ? item.push.contact->mode : Push_mode::undecided;
  };
  std::string why_exact, why_twin, why_hybrid;
  Push_mode exact = timed(row.t_exact, [&] { return answer_in(Mode::exact, why_exact); });
  Push_mode twin = timed(row.t_twin, [&] { return answer_in(Mode::float_only, why_twin); });
  Push_mode hybrid = timed(row.t_hybrid, [&] { return answer_in(Mode::hybrid, why_hybrid); });
  const std::string naive = timed(row.t_naive, [&] { return std::string(stress::naive_push_contact(scene)); });
  const auto flip = [](Push_mode m) { return m == Push_mode::sticks ? Push_mode::slides_left : Push_mode::sticks; };
  inject_faults(twin, hybrid, exact, Push_mode::undecided, flip);
  const Push_mode truth = k.above ? Push_mode::slides_left : Push_mode::sticks;
  ++row.cases;
  row.naive_wrong += naive != push_mode_name(truth);
  row.twin_undecided += twin == Push_mode::undecided;
  row.hybrid_undecided += hybrid == Push_mode::undecided;
  row.exact_undecided += exact == Push_mode::undecided;
  const auto wrong = [&](Push_mode m) { return m != Push_mode::undecided && m != truth; };
  if (wrong(twin) || !why_twin.empty()) ++row.twin_wrong, report_wrong("push contact twin", k, seed, index, why_twin);
  if (wrong(hybrid) || !why_hybrid.empty()) ++row.hybrid_wrong, report_wrong("push contact hybrid", k, seed, index, why_hybrid);
  if (wrong(exact) || !why_exact.empty()) ++row.exact_wrong, report_wrong("push contact exact", k, seed, index, why_exact);
}

// push with a line pusher (push_fence_edge): each mode through the pipeline (the certificate checked there: a rejected
// one, or any error, is a wrong answer). A line pusher is exact in every mode (PU-3: no float twin), so the three
// columns measure one method; naive: the four facets' signs in raw doubles (testing/stress_families.h, a guess). The
// truth by construction: stable iff below.
void run_push_stable_case(const families::Case& k, std::uint64_t seed, long index, Row& row) {
  const Scene scene = read_scene(k.text, Input_limits{});
  const auto answer_in = [&](Mode mode, std::string& why) {
    Request request;
    request.mode = mode;
    const Push_item item = answer_push(k.text, "push_fence_edge", request);
    if (item.status != Status::answered && item.status != Status::undecided) why = item.message;
    return item.status == Status::answered && item.push.stable ? item.push.stable->verdict : Stability::undecided;
  };
  std::string why_exact, why_twin, why_hybrid;
  Stability exact = timed(row.t_exact, [&] { return answer_in(Mode::exact, why_exact); });
  Stability twin = timed(row.t_twin, [&] { return answer_in(Mode::float_only, why_twin); });
  Stability hybrid = timed(row.t_hybrid, [&] { return answer_in(Mode::hybrid, why_hybrid); });
  const std::string naive = timed(row.t_naive, [&] { return std::string(stress::naive_push_stable(scene)); });
  const auto flip = [](Stability v) { return v == Stability::stable ? Stability::unstable : Stability::stable; };
  inject_faults(twin, hybrid, exact, Stability::undecided, flip);
  const Stability truth = k.above ? Stability::unstable : Stability::stable;
  ++row.cases;
  row.naive_wrong += naive != stability_name(truth);
  row.twin_undecided += twin == Stability::undecided;
  row.hybrid_undecided += hybrid == Stability::undecided;
  row.exact_undecided += exact == Stability::undecided;
  const auto wrong = [&](Stability v) { return v != Stability::undecided && v != truth; };
  if (wrong(twin) || !why_twin.empty()) ++row.twin_wrong, report_wrong("push stable twin", k, seed, index, why_twin);
  if (wrong(hybrid) || !why_hybrid.empty()) ++row.hybrid_wrong, report_wrong("push stable hybrid", k, seed, index, why_hybrid);
  if (wrong(exact) || !why_exact.empty()) ++row.exact_wrong, report_wrong("push stable exact", k, seed, index, why_exact);
}

// stick/slide on a support with regions (region_support): each mode through the pipeline, the certificate checked
// by the independent checker there (a rejected one, or any error, is a wrong answer); the truth is the side, by
// construction. float has no twin of regions (always undecided); naive: the double search without bounds.
void run_region_case(const families::Case& k, std::uint64_t seed, long index, Row& row) {
  const Scene scene = read_scene(k.text, Input_limits{});
  Support_query query;
  query.question = Support_question::limit_surface;
  query.load = k.motion_load;
  query.polytopes = false;
  const auto answer_in = [&](Mode mode, std::string& why) {
    const Support_item item = pipeline_answer(scene, k.text, query, mode, why);
    return item.status == Status::answered && item.motion ? item.motion->motion : Motion::undecided;
  };
  std::string why_exact, why_twin, why_hybrid;
  Motion exact = timed(row.t_exact, [&] { return answer_in(Mode::exact, why_exact); });
  Motion twin = timed(row.t_twin, [&] { return answer_in(Mode::float_only, why_twin); });
  Motion hybrid = timed(row.t_hybrid, [&] { return answer_in(Mode::hybrid, why_hybrid); });
  const bool naive = timed(row.t_naive, [&] { return families::naive_region_slides(k); });
  const auto flip = [](Motion m) { return m == Motion::sticks ? Motion::slides : Motion::sticks; };
  inject_faults(twin, hybrid, exact, Motion::undecided, flip);
  const Motion truth = k.above ? Motion::slides : Motion::sticks;
  const auto wrong = [&](Motion m, const std::string& why) { return !why.empty() || (m != Motion::undecided && m != truth); };
  ++row.cases;
  row.naive_wrong += naive != k.above;
  row.twin_undecided += twin == Motion::undecided;
  row.hybrid_undecided += hybrid == Motion::undecided;
  row.exact_undecided += exact == Motion::undecided;
  if (wrong(twin, why_twin)) ++row.twin_wrong, report_wrong("region twin", k, seed, index, why_twin);
  if (wrong(hybrid, why_hybrid)) ++row.hybrid_wrong, report_wrong("region hybrid", k, seed, index, why_hybrid);
  if (wrong(exact, why_exact)) ++row.exact_wrong, report_wrong("region exact", k, seed, index, why_exact);
}

std::string pct(long n, long d) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f%%", d ? 100.0 * double(n) / double(d) : 0.0);
  return b;
}
std::string us(double seconds, long cases) {
  char b[32];
  const double v = cases ? 1e6 * seconds / double(cases) : 0;
  std::snprintf(b, sizeof b, v < 100 ? "%.2f" : "%.0f", v);
  return b;
}
std::string eps_text(double e) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", e);
  return b;
}

// ---- the SVG: one panel per family and check, rates against ε (the ε axis by category) -----------------

void write_svg(const std::vector<Row>& rows, const std::vector<std::pair<std::string, Measure>>& panels,
               const std::string& path) {
  const auto cases_per_eps = [&](const std::pair<std::string, Measure>& p) {
    for (const Row& r : rows)
      if (r.family == p.first && r.check == p.second) return r.cases;
    return 0L;
  };
  const int cols = 4, pw = 330, ph = 190, left = 44, top = 22, w = pw - left - 12, h = ph - top - 52;
  const int nrows = int((panels.size() + cols - 1) / cols);
  std::ostringstream s;
  s << "<svg xmlns='http://www.w3.org/2000/svg' width='" << cols * pw << "' height='" << nrows * ph + 56
    << "' font-family='sans-serif' font-size='10'>\n<rect width='100%' height='100%' fill='white'/>\n";
  // Drawn in this order: the twin's wide light line first, so that a rate drawn over it stays visible.
  struct Series {
    const char* label;
    const char* color;
    const char* dash;
    double width;
    std::function<double(const Row&)> rate;
    bool motion_only;
  };
  const Series series[] = {
      {"certified twin: undecided", "#ffbb78", "", 5, [](const Row& r) { return double(r.twin_undecided) / r.cases; },
       false},
      {"exact polygons (N = 16): undecided", "#7f7f7f", "2,2", 2,
       [](const Row& r) { return double(r.exact_undecided) / r.cases; }, true},
      {"hybrid: undecided (stick/slide only)", "#9467bd", "5,3", 2,
       [](const Row& r) { return double(r.hybrid_undecided) / r.cases; }, true},
      {"naive double: wrong", "#d62728", "", 2, [](const Row& r) { return double(r.naive_wrong) / r.cases; }, false},
      {"twin, hybrid or exact: wrong", "#2ca02c", "", 2,
       [](const Row& r) { return double(r.certified_wrong()) / r.cases; }, false},
  };
  for (std::size_t p = 0; p < panels.size(); ++p) {
    const int x0 = int(p % cols) * pw + left, y0 = int(p / cols) * ph + top;
    const bool motion = panels[p].second == Measure::motion;
    s << "<text x='" << x0 << "' y='" << y0 - 7 << "'><tspan font-weight='bold'>" << panels[p].first << " — "
      << check_name(panels[p].second) << "</tspan> (" << cases_per_eps(panels[p]) << " per ε)</text>\n";
    s << "<rect x='" << x0 << "' y='" << y0 << "' width='" << w << "' height='" << h
      << "' fill='none' stroke='#888'/>\n";
    for (int pc : {0, 50, 100}) {
      const double y = y0 + h - h * pc / 100.0;
      s << "<text x='" << x0 - 4 << "' y='" << y + 3 << "' text-anchor='end'>" << pc << "%</text>\n";
      if (pc == 50)
        s << "<line x1='" << x0 << "' x2='" << x0 + w << "' y1='" << y << "' y2='" << y << "' stroke='#ddd'/>\n";
    }
    const auto X = [&](std::size_t i) { return x0 + w * (double(i) + 0.5) / double(kEpsilons.size()); };
    for (std::size_t i = 0; i < kEpsilons.size(); ++i) {
      const double x = X(i), y = y0 + h + 8;
      s << "<text x='" << x << "' y='" << y << "' font-size='8' text-anchor='end' transform='rotate(-50 " << x << " "
        << y << ")'>" << eps_text(kEpsilons[i]) << "</text>\n";
    }
    for (const Series& se : series) {
      if (se.motion_only && !motion) continue;
      s << "<polyline fill='none' stroke='" << se.color << "' stroke-width='" << se.width << "'"
        << (*se.dash ? std::string(" stroke-dasharray='") + se.dash + "'" : std::string()) << " points='";
      for (const Row& r : rows)
        if (r.family == panels[p].first && r.check == panels[p].second && r.cases > 0) {
          std::size_t i = 0;
          while (i < kEpsilons.size() && kEpsilons[i] != r.eps) ++i;
          s << X(i) << "," << y0 + h - h * se.rate(r) << " ";
        }
      s << "'/>\n";
    }
  }
  int x = 10;
  const int y = nrows * ph + 20;
  s << "<text x='" << x << "' y='" << y
    << "'>rate of cases against ε (distance to the degenerate configuration; ε axis by "
    << "category, not to scale):</text>\n";
  for (const Series& se : series) {
    s << "<line x1='" << x << "' x2='" << x + 24 << "' y1='" << y + 18 << "' y2='" << y + 18 << "' stroke='" << se.color
      << "' stroke-width='" << se.width << "'"
      << (*se.dash ? std::string(" stroke-dasharray='") + se.dash + "'" : std::string()) << "/><text x='" << x + 28
      << "' y='" << y + 21 << "'>" << se.label << "</text>\n";
    x += 40 + 6 * int(std::string(se.label).size());
  }
  s << "</svg>\n";
  std::ofstream(path) << s.str();
}

// ---- the Markdown --------------------------------------------------------------------------------------

const char* kCampaignBegin = "<!-- campaign: written by stress_report --campaign; kept by --report -->";
const char* kCampaignEnd = "<!-- end of campaign -->";

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The campaign section of an existing report (with its markers), or a placeholder.
std::string campaign_section(const std::string& md) {
  const std::size_t a = md.find(kCampaignBegin), b = md.find(kCampaignEnd);
  if (a == std::string::npos || b == std::string::npos || b < a)
    return std::string(kCampaignBegin) + "\n(no campaign recorded yet)\n" + kCampaignEnd;
  return md.substr(a, b + std::string(kCampaignEnd).size() - a);
}

std::string table_header() {
  return "| ε | cases | naive wrong | twin undecided | twin wrong | hybrid undecided | hybrid wrong | exact undecided "
         "| "
         "exact wrong | naive µs | twin µs | hybrid µs | exact µs "
         "|\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
}
std::string table_row(const Row& r, const std::string& first) {
  return "| " + first + " | " + std::to_string(r.cases) + " | " + pct(r.naive_wrong, r.cases) + " | " +
         pct(r.twin_undecided, r.cases) + " | " + std::to_string(r.twin_wrong) + " | " +
         pct(r.hybrid_undecided, r.cases) + " | " + std::to_string(r.hybrid_wrong) + " | " +
         pct(r.exact_undecided, r.cases) + " | " + std::to_string(r.exact_wrong) + " | " + us(r.t_naive, r.cases) +
         " | " + us(r.t_twin, r.cases) + " | " + us(r.t_hybrid, r.cases) + " | " + us(r.t_exact, r.cases) + " |\n";
}

const char* cross_check(const Family& f, Measure c) {
  const std::string n = f.name;
  if (c == Measure::motion) return "the answer by construction (p(q) on LS, load p(q)·(1 ± 10^-k))";
  if (c == Measure::push) return "the rotation by construction (the velocity's vote) + the checker (exact's certificate)";
  if (c == Measure::push_stable)
    return "the verdict by construction (the velocity ε inside or outside the cone's left edge) + the checker";
  if (c == Measure::push_contact)
    return "the mode by construction (the force turns with the velocity past the motion-cone edge) + the checker";
  if (c == Measure::motion_over)
    return "the answers left possible by construction + the checker (every certificate) + exact = hybrid";
  if (c == Measure::labels)
    return f.question == Question::equilibrium ? "−load ∈ W read on the exact labels = the true balance"
                                               : "nothing labeled ⇔ the true closure verdict (§5.5)";
  if (n == "rational_rotation" || n == "huge_scale" || n == "tiny_scale" || n == "beyond_double")
    return "by construction + checker + the untransformed scene";
  return f.known ? "by construction + checker" : "independent checker (certificate)";
}

struct Summary {
  std::string first_naive_wrong = "never", first_undecided = "never";
  double max_naive = 0;
  Row total;
};
Summary summarize(const std::vector<Row>& rows, const std::string& family, Measure check) {
  Summary s;
  for (const Row& r : rows) {
    if (r.family != family || r.check != check) continue;
    s.total.add(r);
    if (r.naive_wrong > 0 && s.first_naive_wrong == "never") s.first_naive_wrong = eps_text(r.eps);
    if (r.twin_undecided > 0 && s.first_undecided == "never") s.first_undecided = eps_text(r.eps);
    s.max_naive = std::max(s.max_naive, double(r.naive_wrong) / r.cases);
  }
  return s;
}

std::vector<Measure> checks_of(const Family& f) {
  if (f.question == Question::stick_slide || f.question == Question::stick_slide_region) return {Measure::motion};
  if (f.question == Question::stick_slide_over) return {Measure::motion_over};
  if (f.question == Question::hold) return {Measure::hold};
  if (f.question == Question::push) return {Measure::push};
  if (f.question == Question::push_contact) return {Measure::push_contact};
  if (f.question == Question::push_stable) return {Measure::push_stable};
  return {Measure::verdict, Measure::labels};
}

std::string totals_table(const std::vector<Row>& rows, const std::vector<Family>& fams) {
  std::string s =
      "| family | question | cases | naive wrong | twin undecided | twin wrong | hybrid undecided | hybrid wrong | "
      "exact "
      "undecided | exact wrong |\n|---|---|---|---|---|---|---|---|---|---|\n";
  Row all;
  for (const Family& f : fams)
    for (Measure c : checks_of(f)) {
      const Row t = summarize(rows, f.name, c).total;
      all.add(t);
      s += "| " + std::string(f.name) + " | " + check_name(c) + " | " + std::to_string(t.cases) + " | " +
           std::to_string(t.naive_wrong) + " | " + std::to_string(t.twin_undecided) + " | " +
           std::to_string(t.twin_wrong) + " | " + std::to_string(t.hybrid_undecided) + " | " +
           std::to_string(t.hybrid_wrong) + " | " + std::to_string(t.exact_undecided) + " | " +
           std::to_string(t.exact_wrong) + " |\n";
    }
  s += "| **all** | | **" + std::to_string(all.cases) + "** | " + std::to_string(all.naive_wrong) + " | " +
       std::to_string(all.twin_undecided) + " | **" + std::to_string(all.twin_wrong) + "** | " +
       std::to_string(all.hybrid_undecided) + " | **" + std::to_string(all.hybrid_wrong) + "** | " +
       std::to_string(all.exact_undecided) + " | **" + std::to_string(all.exact_wrong) + "** |\n";
  return s;
}

std::string report_markdown(const std::vector<Row>& rows, const std::vector<Family>& fams, long cases,
                            std::uint64_t seed, double seconds, const std::string& campaign) {
  std::ostringstream md;
  md << "# Numerical stability: naive double vs certified twin vs hybrid vs exact\n\n"
     << "Regenerate with `./build.sh stability` (runs `stress_report --cases " << cases << " --seed " << seed
     << " --report docs`; this run took " << std::lround(seconds) << " s on the shared 2-core machine).\n"
     << "Every family builds scenes at distance ε from a degenerate configuration and writes them as text, as a\n"
     << "user would (testing/stress_families.h [ST-1], fuzz/families.h). Cases per ε: " << cases << " per family, "
     << cases_for(*families::find("many_contacts"), cases) << " for many_contacts (each has 1000–10000 contacts) and "
     << cases_for(*families::find("collinear_support"), cases)
     << " for collinear_support (each runs a search and builds polytopes), "
     << cases_for(*families::find("unknown_support"), cases)
     << " for unknown_support (each decides every extreme distribution, with certificates, in three modes) and "
     << cases_for(*families::find("region_support"), cases)
     << " for region_support and region_legs (certificates over cells of the region, in three modes).\n\n"
     << "* **naive**: what tolerance-free float code does with the same text: the numbers read by strtod (a fraction\n"
     << "  p/q as strtod(p)/strtod(q)), raw double signs in the same algorithms (fl::Naive_kernel through\n"
     << "  core/dual_cone.h for closure and equilibrium, fl::moment_labels_naive for labels). For stick/slide, naive\n"
     << "  minimises f(q) = h(q) − q·p over twists in plain doubles (an 8×8 grid on each face of the twist cube,\n"
     << "  then a compass search down to steps of 2^-60) and says \"slides\" iff some f(q) ≤ 0 — the float version of\n"
     << "  the support-function test, without error bounds (peers approximate the limit surface instead: an\n"
     << "  ellipsoid or polynomial fit, or a sampled hull, which is wrong at much larger ε).\n"
     << "* **twin**: the certified float twin alone (`--mode float`); it abstains when a sign is within its error\n"
     << "  bound (closure, labels [FL-6]) or when its search runs out of cells (stick/slide [FL-7]).\n"
     << "* **hybrid**: the default mode: the twin, exact arithmetic where it abstains. For stick/slide, the search\n"
     << "  first, then the exact polygons (N = " << kSides << ").\n"
     << "* **exact**: exact arithmetic only. For stick/slide, the exact polygonal bounds with N = " << kSides
     << " directions\n"
     << "  (1/λ − 1 ≈ 2 %): undecided for loads closer to the limit surface than that (refining N is the cure).\n"
     << "* **wrong** is measured against the truth of the case: the answer by construction for the exact families\n"
     << "  (`known`: the answer is the side of the threshold for every ε), else the exact engine's verdict; and the\n"
     << "  truth is cross-checked (column *cross-check*). Labels: *naive wrong* = not the exact labels' shapes and\n"
     << "  corner counts; *twin wrong* = a decided twin whose shapes, counts, order or any corner is outside its\n"
     << "  stated bound of the exact one (testing/twin_agreement.h); *hybrid wrong* = not byte-equal to exact.\n"
     << "* Times are per query (verdict without certificate; labels; stick/slide), on a noisy shared machine.\n\n"
     << "## Family by family\n\n"
     << "Where naive double goes wrong (the largest ε at which it was ever wrong, and its worst rate), where the\n"
     << "twin starts to abstain, and the certified answers' wrong counts over all ε (each must be 0).\n\n"
     << "| family | question | naive wrong from ε ≤ | naive worst | twin abstains from ε ≤ | twin wrong | hybrid wrong "
        "| exact wrong | cross-check of the truth |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const Family& f : fams)
    for (Measure c : checks_of(f)) {
      const Summary s = summarize(rows, f.name, c);
      md << "| " << f.name << " | " << (c == Measure::verdict ? families::question_name(f.question) : check_name(c))
         << " | " << s.first_naive_wrong << " | " << pct(long(std::lround(1000 * s.max_naive)), 1000) << " | "
         << s.first_undecided << " | " << s.total.twin_wrong << " | " << s.total.hybrid_wrong << " | "
         << s.total.exact_wrong << " | " << cross_check(f, c) << " |\n";
    }
  md << "\nWhat it shows:\n\n"
     << "* **Verdicts** (closure, equilibrium): naive double goes wrong once ε nears the rounding of the input (10^-14\n"
     << "  … 10^-16 relative; from 10^-12 when the grasp sits 10^3 of its sizes away from the origin) and is then wrong\n"
     << "  in a third to a half of the cases; beyond the double range it is wrong in half of them at every ε. The\n"
     << "  twin starts to abstain a decade or two earlier and never answers wrongly; hybrid then asks exact\n"
     << "  arithmetic and is never wrong.\n"
     << "* **Labels** are more fragile than verdicts: a labeling rests on every sign of the dual cone, a verdict on a\n"
     << "  few, so where naive verdicts are wrong in a third to a half of the cases, naive labels have the wrong shapes\n"
     << "  or corner counts in half to four fifths of them.\n"
     << "* **Scale** costs the twin nothing (its bounds are relative) until values leave its range: below 2^-960 ≈\n"
     << "  10^-289 it declines (a quarter of tiny_scale, at every ε), beyond the double range always.\n"
     << "* **Many contacts** change none of this: the decisive pair decides, among 1000–10000 contacts.\n"
     << "* **Stick/slide**: the certified search decides loads down to about 10^-8 of the limit surface and abstains\n"
     << "  on many closer ones (its budget is 200 000 twists; a load on the surface itself is undecidable by design),\n"
     << "  where the exact polygons with N = " << kSides << " already gave up at 2 %; hybrid then runs Newton's method\n"
     << "  in multiple precision, checked in exact rationals (proofs/notes/SL-6), and decides them down to 10^-40.\n"
     << "  The naive double minimisation is right down to 10^-15 and wrong in half the cases below.\n"
     << "* **Stick/slide over every distribution** (unknown_support): naive code picks one distribution (the even\n"
     << "  split) and answers sticks or slides where the truth is often \"depends\": wrong at every ε. Hybrid answers\n"
     << "  with a certificate the independent checker accepts, or says undecided: near 10^-3 in under 1 % of the\n"
     << "  cases (a test), and rarely closer (an extreme distribution near its own surface is decided by SL-6's\n"
     << "  Newton in multiple precision, checked in exact rationals). The twin\n"
     << "  alone has no LP over the distributions and abstains; exact mode decides far from the thresholds only.\n"
     << "* **Support regions** (region_support): hybrid and exact (the same certificate search) answer with a\n"
     << "  certificate the checker accepts or say undecided: every case above the limit surface is decided at every ε\n"
     << "  (the translation along the load's force gives an exact slide bound), the ones below down to about 10^-10\n"
     << "  (the stick witness is found in double, then made exact); the float twin has no model of regions and always\n"
     << "  abstains. The naive double search (no bounds) is wrong from about 10^-15.\n"
     << "* **Regions with legs whose force is not given** (region_legs): every admissible distribution has the same\n"
     << "  translation boundary load, so the truth is sticks for every one or slides for every one; hybrid and exact\n"
     << "  decide each extreme distribution over the region's cells and answer with a format-2 certificate\n"
     << "  (proofs/certificate-format.md §6.5) or say undecided. Naive code takes the even split of the legs' weight.\n"
     << "\n| family | what |\n|---|---|\n";
  for (const Family& f : fams) {
    std::string what = f.what;  // a table cell: escape the bars of |x|
    for (std::size_t i = what.find('|'); i != std::string::npos; i = what.find('|', i + 2)) what.insert(i, "\\");
    md << "| " << f.name << " | " << what << " |\n";
  }
  md << "\n![error rates against ε, family by family](stability.svg)\n\n"
     << "## Why the exact answers are known\n\n"
     << "* Two fingers with normals ±x at A and B: force closure ⇔ the segment AB lies strictly inside both friction\n"
     << "  cones ⇔ |slope of AB| < μ (Nguyen). The exact families write μ = μ*·(10^k ± 1)/10^k exactly (10^-k the "
        "power\n"
     << "  of ten nearest ε from below), so closure ⇔ *above*, for every ε. Rotations by rationals on the unit "
        "circle,\n"
     << "  translations and positive scalings map the wrench cone linearly onto itself (exactly), so the\n"
     << "  untransformed scene has the same answer: a second exact route.\n"
     << "* many_contacts: contacts at u(t) = ((1 − t²), 2t)/(1 + t²) on an arc t1 < t < t2 with inward normals, the "
        "ends\n"
     << "  with μ, the others with μ_small < μ. Every contact's force directions lie in the arc of directions between\n"
     << "  the ends' outer friction edges, of width π − δ + 2·atan μ with δ = π − (θ2 − θ1). If μ > tan(δ/2) the two\n"
     << "  ends alone close (the chord makes the angle δ/2 with both inward normals); if μ < tan(δ/2) all forces lie "
        "in\n"
     << "  an open half-plane and nothing closes. tan(δ/2) = cot(atan t2 − atan t1) = (1 + t1·t2)/(t2 − t1) = μ*.\n"
     << "* collinear_support: for the rotation q about c (not a support point) the limit surface is smooth at q and\n"
     << "  p(q) = ∇h(q) = Σ ρ_i (v̂_i, r_i × v̂_i) lies on it (q·p(q) = h(q)); the points are at rational distances\n"
     << "  from c, so p(q) is rational. LS is convex with 0 in its interior (two distinct points), so p(q)·(1 − "
        "10^-k)\n"
     << "  sticks and p(q)·(1 + 10^-k) slides (q·p > h(q)).\n"
     << "* unknown_support: for a twist q and an extreme distribution f, the forces g_i = μ_i f_i l_i v_i(q) with\n"
     << "  rational l_i ≤ 1/|v_i(q)| (10^-(k+6) below it) lie in their discs and sum to p̂ within 10^-(k+6) of the\n"
     << "  boundary point of LS(f) for q. Below, p̂·(1 − 10^-k) is held by the forces (1 − 10^-k)·g_i, strictly inside:\n"
     << "  f sticks, so the answer is sticks or depends. Above, q·p > Σ μ_i f_i u_i with rational u_i ≥ |v_i(q)|\n"
     << "  (checked exactly when the scene is made): f slides, so slides or depends; and when f has the largest\n"
     << "  power bound of all extreme distributions (found by brute force, not by the engine), q·p exceeds every\n"
     << "  one's: it slides for every distribution. Right = an answer left possible, the same in exact and hybrid,\n"
     << "  and a certificate the checker accepts.\n"
     << "* region_support: the translation q = (v̂, 0) with |v̂| = 1 rational moves every point with speed 1, so\n"
     << "  h(q) = μf0 exactly and its load p* = μf0 (v̂, c_f × v̂) (c_f the friction centroid) is ∂h(q), on the limit\n"
     << "  surface. Below, p*·(1 − 10^-k) is inside (0 is interior, the set convex): sticks; above, q·p = (1 + 10^-k) μf0 >\n"
     << "  h(q): slides.\n"
     << "* region_legs: the same translation moves every point at speed 1 whatever the distribution, so every f ∈ F has\n"
     << "  h_f(q) = μW and the friction centroid c (Σ f_i r_i + Σ_R M_R = W c on F): p* is on every limit surface of F.\n"
     << "  Above: q proves slides for every distribution; below: (1 − 10^-k)p* is inside each: sticks for every one.\n"
     << "* Labels: nothing is labeled ⇔ force closure (theory.md §5.5), and a load is balanced ⇔ −w ∈ W, read on the\n"
     << "  exact labels' cone; both are compared with the (cross-checked) truth of the verdict.\n\n"
     << "## Totals of this run\n\n"
     << totals_table(rows, fams) << "\n"
     << "## The million-case campaign\n\n"
     << campaign << "\n\n"
     << "## Every family and ε\n\n";
  for (const Family& f : fams)
    for (Measure c : checks_of(f)) {
      md << "### " << f.name << " — " << (c == Measure::verdict ? families::question_name(f.question) : check_name(c))
         << "\n\n"
         << table_header();
      for (const Row& r : rows)
        if (r.family == f.name && r.check == c) md << table_row(r, eps_text(r.eps));
      md << "\n";
    }
  return md.str();
}

std::string campaign_markdown(const std::vector<Row>& rows, const std::vector<Family>& fams, const std::string& command,
                              double seconds) {
  Row all;
  for (const Row& r : rows) all.add(r);
  std::ostringstream s;
  s << kCampaignBegin << "\n"
    << "Command: `" << command << "` (single-threaded, at `nice 19` on the shared 2-core machine; it took "
    << std::lround(seconds) << " s = " << std::lround(seconds / 60) << " min). " << all.cases
    << " cases in all, each answered by the twin, hybrid and exact (" << 3 * all.cases
    << " certified answers) and by the naive variant; every closure and equilibrium verdict's certificate was\n"
    << "accepted by the independent checker. **Certified answers wrong: twin " << all.twin_wrong << ", hybrid "
    << all.hybrid_wrong << ", exact " << all.exact_wrong << ".**\n\n"
    << totals_table(rows, fams) << kCampaignEnd;
  return s.str();
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : s) {
    if (c == ',') out.push_back(cur), cur.clear();
    else cur += c;
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  long cases = 200;
  std::uint64_t seed = 20261121;
  std::string report, campaign, only;
  std::string command = "stress_report";
  for (int i = 1; i < argc; ++i) command += std::string(" ") + argv[i];
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--cases" && i + 1 < argc) cases = std::atol(argv[++i]);
    else if (a == "--seed" && i + 1 < argc) seed = std::strtoull(argv[++i], nullptr, 10);
    else if (a == "--report" && i + 1 < argc) report = argv[++i];
    else if (a == "--campaign" && i + 1 < argc) campaign = argv[++i];
    else if (a == "--families" && i + 1 < argc) only = argv[++i];
    else if (a == "--inject-fault" && i + 1 < argc) g_fault = argv[++i];
    else {
      std::fprintf(stderr,
                   "usage: stress_report [--cases N] [--seed S] [--families A,B,...] [--report DIR] [--campaign FILE] "
                   "[--inject-fault twin|hybrid|exact]\n");
      return 2;
    }
  }
  if (cases < 1 || (!g_fault.empty() && g_fault != "twin" && g_fault != "hybrid" && g_fault != "exact")) {
    std::fprintf(stderr, "stress_report: --cases must be positive, --inject-fault twin, hybrid or exact\n");
    return 2;
  }
  std::vector<Family> fams;
  if (only.empty()) fams = families::report();
  else
    for (const std::string& n : split(only)) {
      const Family* f = families::find(n);
      if (!f) {
        std::fprintf(stderr, "stress_report: unknown family \"%s\"\n", n.c_str());
        return 2;
      }
      fams.push_back(*f);
    }
  const bool injecting = !g_fault.empty();
  const double start = now();
  std::vector<Row> rows;
  for (const Family& fam : fams) {
    // One stream per family, so a family's cases do not depend on which other families run.
    std::uint64_t name_hash = 14695981039346656037ull;  // FNV-1a of the name: the same on every platform
    for (const char* c = fam.name; *c; ++c) name_hash = (name_hash ^ static_cast<unsigned char>(*c)) * 1099511628211ull;
    stress::Rng rng(seed ^ name_hash);
    const long n = cases_for(fam, cases);
    const double t0 = now();
    for (double eps : kEpsilons) {
      Row verdict, labels;
      verdict.family = labels.family = fam.name;
      verdict.eps = labels.eps = eps;
      verdict.check = fam.question == Question::stick_slide || fam.question == Question::stick_slide_region
                          ? Measure::motion
                      : fam.question == Question::stick_slide_over ? Measure::motion_over
                      : fam.question == Question::hold             ? Measure::hold
                      : fam.question == Question::push             ? Measure::push
                      : fam.question == Question::push_contact     ? Measure::push_contact
                      : fam.question == Question::push_stable      ? Measure::push_stable
                                                                   : Measure::verdict;
      labels.check = Measure::labels;
      for (long c = 0; c < n; ++c) {
        const families::Case k = families::make_case(fam, eps, rng);
        if (fam.question == Question::stick_slide) run_motion_case(k, seed, c, verdict);
        else if (fam.question == Question::stick_slide_over) run_motion_over_case(k, seed, c, verdict);
        else if (fam.question == Question::hold) run_hold_case(k, seed, c, verdict);
        else if (fam.question == Question::push) run_push_case(k, seed, c, verdict);
        else if (fam.question == Question::push_contact) run_push_contact_case(k, seed, c, verdict);
        else if (fam.question == Question::push_stable) run_push_stable_case(k, seed, c, verdict);
        else if (fam.question == Question::stick_slide_region) run_region_case(k, seed, c, verdict);
        else run_contact_case(k, seed, c, verdict, labels);
      }
      rows.push_back(verdict);
      if (!is_motion(fam.question)) rows.push_back(labels);
    }
    std::fprintf(stderr, "stress_report: %-20s %6ld cases per eps, %.1f s\n", fam.name, n, now() - t0);
  }
  const double seconds = now() - start;
  Row all;
  for (const Row& r : rows) all.add(r);
  std::fputs(totals_table(rows, fams).c_str(), stdout);
  std::printf("%.1f s\n", seconds);
  if (!report.empty() && !injecting) {
    const std::string md_path = report + "/stability.md";
    const std::string md = report_markdown(rows, fams, cases, seed, seconds, campaign_section(read_file(md_path)));
    std::ofstream(md_path, std::ios::binary) << md;
    std::vector<std::pair<std::string, Measure>> panels;
    for (const Family& f : fams)
      for (Measure c : checks_of(f)) panels.emplace_back(f.name, c);
    write_svg(rows, panels, report + "/stability.svg");
  }
  if (!campaign.empty() && !injecting) {
    std::string md = read_file(campaign);
    const std::string section = campaign_markdown(rows, fams, command, seconds);
    const std::size_t a = md.find(kCampaignBegin), b = md.find(kCampaignEnd);
    if (a == std::string::npos || b == std::string::npos) md += "\n" + section + "\n";
    else md.replace(a, b + std::string(kCampaignEnd).size() - a, section);
    std::ofstream(campaign, std::ios::binary) << md;
  }
  return all.certified_wrong() > 0 ? 1 : 0;
}
