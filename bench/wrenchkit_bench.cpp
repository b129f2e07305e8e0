// The benchmark suite of docs/benchmarks.md: run time against error, ours and the peers', on the
// same scenes in the same run. Google Benchmark; names are SECTION/PARAMETERS/METHOD and the
// counters carry the verdict quality, so one JSON file holds the whole report
// (bench/make_report.py turns it into docs/benchmarks.md and docs/benchmarks/*.svg).
//
//   family/FAMILY/EPS/METHOD   near-degenerate families (fuzz/families.h), 64 cases each:
//                              counters wrong, failures, undecided, cases (against the exact verdict);
//                              labels_* methods: moment labels, wrong = not the exact labels' shapes
//                              and counts (twin: not within its stated bounds of them)
//   generic/N/METHOD           random generic N-contact grasps (256 scenes): the twin's own targets
//   contacts/N/METHOD          growth with the number of contacts (3 … 10^4)
//   ls_sides/N/METHOD          exact polygonal limit surface vs CGAL's generic hull, 3 support points,
//                              N directions: counters rel_error (1/λ − 1), vertices
//   ls_points/K/METHOD         growth with the number of support points (N = 8)
//   ls_query/N/METHOD          one support-function value h(q): exact polygonal, float polygonal (N
//                              directions) and the float TRUE support function (N = "true"):
//                              counter rel_error (certified bound on |value − h|/h)
//
//   wrenchkit_bench [--smoke] [Google Benchmark flags]
// --smoke: small sizes, for the CI test that keeps the suite from rotting. Exit status 1 if one of
// our certified methods (twin, hybrid, exact) was ever wrong, or an exact peer disagreed with the
// exact limit surface's vertex count.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <memory>
#include <random>
#include <regex>
#include <string>
#include <vector>

#include "bench/peers.h"
#include "exact/certificates/certificates.h"
#include "exact/statics/closure.h"
#include "exact/statics/critical_mu.h"
#include "exact/statics/quality.h"
#include "exact/pipeline/hold_answer.h"
#include "exact/pipeline/support_answer.h"
#include "exact/sliding/region_sliding.h"
#include "exact/sliding/limit_surface.h"
#include "exact/statics/moment_labels.h"
#include "testing/stress_families.h"
#include "testing/twin_agreement.h"
#include "exact/io/outline.h"
#include "exact/io/to_float.h"
#include "exact/pipeline/grasp_regions_answer.h"
#include "exact/pipeline/push_answer.h"
#include "float/closure_twin.h"
#include "float/labels_twin.h"
#include "float/limit_surface_twin.h"
#include "float/grasp_twin.h"
#include "float/quality_twin.h"
#include "exact/io/to_float.h"
#include "exact/pipeline/quality_answer.h"
#include "float/push_twin.h"
#include "fuzz/families.h"

namespace {

using namespace wrenchkit;
namespace fam = wrenchkit::families;

bool g_smoke = false;
bool g_failed = false;

// One scene ready for every method: parsed, the double wrenches (computed in double from the
// scene's doubles, as float peers' users do) and the exact rational wrenches.
struct Prepared {
  std::string text;
  Scene scene;
  fam::Question question = fam::Question::force_closure;
  bool expected = false;
  std::vector<peers::Wrench_d> wd;
  std::vector<peers::Wrench_q> wq;
  fam::Case family_case;  // for the naive reading (families only)
  std::string labels;     // the exact moment labels' shapes and counts (closure families)
};

Reading reading_of(fam::Question q) {
  return q == fam::Question::form_closure ? Reading::frictionless : Reading::friction;
}

Prepared prepare(const std::string& text, fam::Question q) {
  Prepared p;
  p.text = text;
  p.scene = read_scene(text, Input_limits{});
  p.question = q;
  p.expected = fam::decide(p.scene, q, Mode::exact).holds;
  if (q != fam::Question::equilibrium) p.labels = fam::labels_signature(moment_labels(p.scene, reading_of(q), Mode::exact));
  if (q != fam::Question::equilibrium) {
    const Reading r = q == fam::Question::force_closure ? Reading::friction : Reading::frictionless;
    for (const fl::Bounded3& g : fl::generators(to_bounded(p.scene), r)) p.wd.push_back({g[0].v, g[1].v, g[2].v});
    for (const Generator& g : generators(p.scene, r)) p.wq.push_back({g.w[0], g.w[1], g.w[2]});
  }
  return p;
}

// A method answers one prepared scene: 1 holds, 0 does not, -1 undecided (twin), -2 failure (peer).
using Method = std::function<int(const Prepared&)>;

int of(peers::Verdict v) { return v == peers::Verdict::closure ? 1 : (v == peers::Verdict::no_closure ? 0 : -2); }

int ours(const Prepared& p, Mode m) {
  const fam::Verdict v = fam::decide(p.scene, p.question, m);
  return v.decided ? int(v.holds) : -1;
}

struct Named_method {
  std::string name;
  Method run;
  bool certified;  // ours: must never be wrong
  bool peer;
  bool agreement = false;  // run() says 1 agrees with the exact answer, 0 does not (not a verdict)
  Method timed = nullptr;  // what is timed, when run() also does the checking
};

// Moment labels (theory.md §5): 1 the same labeling as exact, 0 not, -1 the twin abstained.
std::vector<Named_method> label_methods() {
  return {
      {"labels_naive",
       [](const Prepared& p) {
         const fl::Labels_twin l = fl::moment_labels_naive(fam::naive_generators(p.family_case));
         return int(l.decided() && fam::labels_signature(l) == p.labels);
       },
       false, false, true},
      {"labels_twin",
       [](const Prepared& p) {
         const fl::Labels_twin l = fl::moment_labels(fl::generators(to_bounded(p.scene), reading_of(p.question)));
         if (!l.decided()) return -1;
         return int(labels_disagreement(l, moment_labels(p.scene, reading_of(p.question), Mode::exact)).empty());
       },
       true, false, true,
       [](const Prepared& p) {
         return int(fl::moment_labels(fl::generators(to_bounded(p.scene), reading_of(p.question))).decided());
       }},
      {"labels_hybrid",
       [](const Prepared& p) {
         return int(fam::labels_signature(moment_labels(p.scene, reading_of(p.question), Mode::hybrid)) == p.labels);
       },
       true, false, true},
      {"labels_exact",
       [](const Prepared& p) {
         return int(fam::labels_signature(moment_labels(p.scene, reading_of(p.question), Mode::exact)) == p.labels);
       },
       true, false, true},
  };
}

std::vector<Named_method> methods(bool with_peers, bool naive) {
  std::vector<Named_method> m;
  if (naive) m.push_back({"naive", [](const Prepared& p) { return int(fam::naive_verdict(p.family_case)); }, false, false});
  m.push_back({"twin", [](const Prepared& p) { return ours(p, Mode::float_only); }, true, false});
  m.push_back({"hybrid", [](const Prepared& p) { return ours(p, Mode::hybrid); }, true, false});
  m.push_back({"exact", [](const Prepared& p) { return ours(p, Mode::exact); }, true, false});
  if (!with_peers) return m;
  m.push_back({"qhull_graspit", [](const Prepared& p) { return of(peers::qhull_graspit(p.wd)); }, false, true});
  m.push_back({"qhull_strict", [](const Prepared& p) { return of(peers::qhull_strict(p.wd)); }, false, true});
  m.push_back({"cgal_epick", [](const Prepared& p) { return of(peers::cgal_epick(p.wd)); }, false, true});
  m.push_back({"cgal_epeck", [](const Prepared& p) { return of(peers::cgal_epeck(p.wq)); }, false, true});
  m.push_back({"cdd_gmp", [](const Prepared& p) { return of(peers::cdd_gmp(p.wq)); }, false, true});
  m.push_back({"glpk_exact", [](const Prepared& p) { return of(peers::glpk_exact(p.wd)); }, false, true});
  return m;
}

// Registers the timing of `method` over `set`; verdict quality is counted once, before timing.
void register_set(const std::string& name, std::shared_ptr<const std::vector<Prepared>> set, Named_method method) {
  benchmark::RegisterBenchmark(name.c_str(), [set, method, name](benchmark::State& st) {
    int wrong = 0, failures = 0, undecided = 0;
    for (const Prepared& p : *set) {
      const int v = method.run(p);
      if (v == -1) ++undecided;
      else if (v == -2) ++failures;
      else if (method.agreement ? v != 1 : (v == 1) != p.expected) ++wrong;
    }
    if (method.certified && wrong > 0) {
      std::fprintf(stderr, "WRONG certified verdict: %s (%d wrong)\n", name.c_str(), wrong);
      g_failed = true;
    }
    const Method& timed = method.timed ? method.timed : method.run;
    std::size_t i = 0;
    for (auto _ : st) benchmark::DoNotOptimize(timed((*set)[i++ % set->size()]));
    st.counters["wrong"] = wrong;
    st.counters["failures"] = failures;
    st.counters["undecided"] = undecided;
    st.counters["cases"] = double(set->size());
  })->Unit(benchmark::kMicrosecond);
}

std::string eps_name(double eps) {
  char b[32];
  std::snprintf(b, sizeof b, "1e%d", static_cast<int>(std::lround(std::log10(eps))));
  return b;
}

void register_families() {
  const std::vector<double> eps = g_smoke ? std::vector<double>{1e-3, 1e-17}
                                          : std::vector<double>{1e-3, 1e-8, 1e-13, 1e-15, 1e-17, 1e-30};
  const int cases = g_smoke ? 4 : 64;
  for (const fam::Family& f : fam::all())
    for (double e : eps) {
      auto set = std::make_shared<std::vector<Prepared>>();
      stress::Rng rng(20261122);
      for (int c = 0; c < cases; ++c) {
        fam::Case k = fam::make_case(f, e, rng);
        Prepared p = prepare(k.text, f.question);
        p.family_case = std::move(k);
        set->push_back(std::move(p));
      }
      std::vector<Named_method> ms = methods(f.question != fam::Question::equilibrium, true);
      if (f.question != fam::Question::equilibrium)
        for (Named_method& m : label_methods()) ms.push_back(std::move(m));
      for (const Named_method& m : ms)
        register_set("family/" + std::string(f.name) + "/" + eps_name(e) + "/" + m.name, set, m);
    }
}

// Generic random grasps: the float twin's targets (issue 5) and the peers at ordinary scenes.
void register_generic() {
  for (int n : g_smoke ? std::vector<int>{6} : std::vector<int>{3, 4, 6, 8}) {
    auto set = std::make_shared<std::vector<Prepared>>();
    stress::Rng rng(20261121 + n);
    for (int s = 0; s < (g_smoke ? 8 : 256); ++s)
      set->push_back(prepare(fam::random_grasp_text(n, rng), fam::Question::force_closure));
    const std::string base = "generic/" + std::to_string(n) + "/";
    // The robot-side API on plain doubles (float/closure_twin.h): no scene, no GMP.
    auto contacts = std::make_shared<std::vector<std::vector<fl::Point_contact>>>();
    for (const Prepared& p : *set) {
      std::vector<fl::Point_contact> c;
      for (const Contact& k : p.scene.contacts)
        c.push_back({k.at.x.get_d(), k.at.y.get_d(), k.normal.x.get_d(), k.normal.y.get_d(), k.mu.get_d()});
      contacts->push_back(std::move(c));
    }
    benchmark::RegisterBenchmark((base + "twin_api").c_str(), [contacts](benchmark::State& st) {
      int decided = 0;
      for (const auto& c : *contacts) decided += fl::force_closure(c) != fl::Verdict::undecided;
      std::size_t i = 0;
      for (auto _ : st) benchmark::DoNotOptimize(fl::force_closure((*contacts)[i++ % contacts->size()]));
      st.counters["decided"] = decided;
      st.counters["cases"] = double(contacts->size());
    })->Unit(benchmark::kMicrosecond);
    // Hybrid: how many queries the twin decided alone (no exact predicate).
    benchmark::RegisterBenchmark((base + "hybrid_twin_alone").c_str(), [set](benchmark::State& st) {
      int alone = 0;
      for (const Prepared& p : *set)
        alone += decide_closure(p.scene, Property::force_closure, Mode::hybrid, false).exact_predicates == 0;
      for (auto _ : st) benchmark::DoNotOptimize(alone);
      st.counters["decided"] = alone;
      st.counters["cases"] = double(set->size());
    })->Iterations(1);
    for (bool certify : {true}) {
      for (Mode m : {Mode::hybrid, Mode::exact}) {
        const std::string name = base + mode_name(m) + "_certified";
        benchmark::RegisterBenchmark(name.c_str(), [set, m, certify](benchmark::State& st) {
          std::size_t i = 0;
          for (auto _ : st)
            benchmark::DoNotOptimize(decide_closure((*set)[i++ % set->size()].scene, Property::force_closure, m, certify).holds);
        })->Unit(benchmark::kMicrosecond);
      }
    }
    for (const Named_method& m : methods(true, false)) register_set(base + m.name, set, m);
  }
}

void register_growth() {
  const std::vector<int> sizes = g_smoke ? std::vector<int>{3, 30}
                                         : std::vector<int>{3, 10, 30, 100, 300, 1000, 3000, 10000};
  for (int n : sizes) {
    auto set = std::make_shared<std::vector<Prepared>>();
    stress::Rng rng(7 + n);
    for (int s = 0; s < (n <= 300 ? 16 : 4); ++s) set->push_back(prepare(fam::random_grasp_text(n, rng), fam::Question::force_closure));
    for (const Named_method& m : methods(true, false)) {
      if ((m.name == "cdd_gmp" || m.name == "glpk_exact") && n > 300) continue;  // seconds per query
      register_set("contacts/" + std::to_string(n) + "/" + m.name, set, m);
    }
  }
}

// A support of k points: random positions on a 1/100 grid in [-1, 1]², normal forces 1 … 10, μ = 1/2.
Support random_support(int k, std::mt19937_64& rng) {
  Support s;
  s.mu = Rational(1, 2);
  for (int i = 0; i < k; ++i) {
    Support_point p;
    p.at = {Rational(static_cast<long>(rng() % 201) - 100, 100), Rational(static_cast<long>(rng() % 201) - 100, 100)};
    p.force = Rational(static_cast<long>(1 + rng() % 10));
    s.points.push_back(p);
  }
  return s;
}

// The summand polygons A_i(ρ_i P) of the inner polytope, as the generic hull's input.
std::vector<std::vector<peers::Wrench_q>> summands(const Polygonal_ls& ls) {
  std::vector<std::vector<peers::Wrench_q>> out;
  for (const Ls_point& pt : ls.support().points) {
    std::vector<peers::Wrench_q> poly;
    for (const Vec2& u : ls.unit_vertices(Side::inner)) {
      const Rational fx = pt.rho * u.x, fy = pt.rho * u.y;
      poly.push_back({fx, fy, pt.at.x * fy - pt.at.y * fx});
    }
    out.push_back(std::move(poly));
  }
  return out;
}

void register_ls(const std::string& name, int k, int sides, bool peer) {
  benchmark::RegisterBenchmark(name.c_str(), [k, sides, peer, name](benchmark::State& st) {
    std::mt19937_64 rng(11 + k);
    const Ls_support sup = merge_support(random_support(k, rng));
    const Directions dirs = make_directions(sides);
    const Polygonal_ls probe(sup, dirs);
    const std::size_t ours = probe.build(Side::inner).vertices.size();
    std::size_t vertices = ours;
    if (peer) {
      const auto polys = summands(probe);
      for (auto _ : st) vertices = peers::cgal_minkowski_hull_vertices(polys);
      if (vertices != ours) {
        std::fprintf(stderr, "%s: CGAL hull has %zu vertices, ours %zu\n", name.c_str(), vertices, ours);
        g_failed = true;
      }
    } else {
      for (auto _ : st) benchmark::DoNotOptimize(Polygonal_ls(sup, dirs).build(Side::inner).facets.size());
    }
    st.counters["rel_error"] = 1 / std::sqrt(dirs.lambda_sq.get_d()) - 1;
    st.counters["vertices"] = double(vertices);
  })->Unit(benchmark::kMillisecond);
}

// Per-query support values on 64 random integer twists: exact polygonal (rational), float polygonal
// and float true (float/limit_surface_twin.h), each with its certified relative error.
void register_ls_query(int sides) {  // sides 0: the true support function
  const std::string name = "ls_query/" + (sides ? std::to_string(sides) : std::string("true")) + "/";
  auto run = [sides](benchmark::State& st, int which) {  // 0 exact polygonal, 1 float polygonal, 2 float true
    std::mt19937_64 rng(11 + 3);
    const Ls_support sup = merge_support(random_support(3, rng));
    std::vector<fl::Support_point_twin> twin;
    for (const Ls_point& p : sup.points)
      twin.push_back({to_bounded(p.at.x), to_bounded(p.at.y), to_bounded(p.force), to_bounded(p.rho)});
    std::vector<Vec3q> qs;
    std::vector<fl::Bounded3> qb;
    for (int i = 0; i < 64; ++i) {
      const long a = long(rng() % 21) - 10, b = long(rng() % 21) - 10, c = long(rng() % 21) - 10;
      if (a == 0 && b == 0 && c == 0) continue;
      qs.push_back({Rational(a), Rational(b), Rational(c)});
      qb.push_back({fl::Bounded::exact(double(a)), fl::Bounded::exact(double(b)), fl::Bounded::exact(double(c))});
    }
    double rel = 0;
    std::size_t i = 0;
    if (which == 0) {
      const Directions dirs = make_directions(sides);
      const Polygonal_ls ls(sup, dirs);
      rel = 1 / std::sqrt(dirs.lambda_sq.get_d()) - 1;
      for (auto _ : st) benchmark::DoNotOptimize(ls.support_value(Side::inner, qs[i++ % qs.size()]));
    } else if (which == 1) {
      const fl::Directions_twin d = fl::make_directions(sides);
      double value_rel = 0;
      for (const fl::Bounded3& q : qb) {
        const fl::Bounded h = fl::polygonal_support(twin, d, false, q);
        value_rel = std::max(value_rel, h.e / std::fabs(h.v));
      }
      rel = 1 / std::sqrt(d.lambda_sq.v - d.lambda_sq.e) - 1 + value_rel;
      for (auto _ : st) benchmark::DoNotOptimize(fl::polygonal_support(twin, d, false, qb[i++ % qb.size()]).v);
    } else {
      for (const fl::Bounded3& q : qb) {
        const fl::Bounded h = fl::support_function(twin, q);
        rel = std::max(rel, h.e / std::fabs(h.v));
      }
      for (auto _ : st) benchmark::DoNotOptimize(fl::support_function(twin, qb[i++ % qb.size()]).v);
    }
    st.counters["rel_error"] = rel;
  };
  if (sides) {
    benchmark::RegisterBenchmark((name + "exact_polygonal").c_str(), run, 0)->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark((name + "float_polygonal").c_str(), run, 1)->Unit(benchmark::kMicrosecond);
  } else {
    benchmark::RegisterBenchmark((name + "float_true").c_str(), run, 2)->Unit(benchmark::kMicrosecond);
  }
}

void register_limit_surface() {
  for (int n : g_smoke ? std::vector<int>{4, 0} : std::vector<int>{4, 8, 16, 32, 64, 256, 1024, 0}) register_ls_query(n);
  for (int n : g_smoke ? std::vector<int>{4, 8} : std::vector<int>{4, 8, 16, 32, 64}) {
    register_ls("ls_sides/" + std::to_string(n) + "/exact_polygonal", 3, n, false);
    if (n <= 32) register_ls("ls_sides/" + std::to_string(n) + "/cgal_epeck_minkowski_hull", 3, n, true);
  }
  for (int k : g_smoke ? std::vector<int>{2, 3} : std::vector<int>{2, 4, 8, 16, 32, 64}) {
    register_ls("ls_points/" + std::to_string(k) + "/exact_polygonal", k, 8, false);
    if (k <= 4) register_ls("ls_points/" + std::to_string(k) + "/cgal_epeck_minkowski_hull", k, 8, true);
  }
}

}  // namespace

// Stick / slide through the pipeline, with certificates checked by the independent checker (issue 15's
// targets): a support of k points on a disc (a discretised plate; random forces, or all unknown with the
// weight at the centre), loads cycled over sticking, sliding and (unknown) depending ones. `polytopes`:
// the same support's polytopes built at N = 32, for comparison.
std::string plate_text(int k, bool unknown, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  std::string pts;
  for (int i = 0; i < k; ++i) {
    const double a = 6.283185307179586 * u(rng), r = std::sqrt(u(rng));
    char b[160];
    std::snprintf(b, sizeof b, "%s{\"at\": [\"%.6f\", \"%.6f\"]%s}", i ? ", " : "", r * std::cos(a), r * std::sin(a),
                  unknown ? "" : ", \"force\": 1");
    pts += b;
  }
  return std::string("{\"wrenchkit\": 1, \"support\": {\"mu\": \"1/2\"") +
         (unknown ? ", \"weight\": 1, \"pressure_center\": [0, 0]" : "") + ", \"points\": [" + pts + "]}}";
}

void register_sliding() {
  const auto run = [](int k, bool unknown, Mode mode, bool polytopes) {
    return [k, unknown, mode, polytopes](benchmark::State& st) {
      std::mt19937_64 rng(1234 + k);
      const std::string text = plate_text(k, unknown, rng);
      const Scene scene = read_scene(text, Input_limits{});
      const double w = unknown ? 1.0 : k;  // μ W = w/2: loads at 0.3, 0.6, 1.2 times it
      const std::vector<Vec3q> loads = {{Rational(0.15 * w), 0, 0}, {0, 0, Rational(0.15 * w)},
                                        {Rational(0.6 * w), 0, Rational(0.1 * w)}, {0, Rational(0.3 * w), Rational(0.2 * w)}};
      Request request;
      request.mode = mode;
      std::size_t i = 0, certified = 0, decided = 0;
      for (auto _ : st) {
        Support_query q;
        q.sides = 32;
        if (polytopes) {
          const Polygonal_ls model(merge_support(*scene.support), make_directions(32));
          benchmark::DoNotOptimize(model.build(Side::inner).facets.size() + model.build(Side::outer).facets.size());
          continue;
        }
        q.load = loads[i++ % loads.size()];
        q.polytopes = false;
        const Support_item r = answer_support(scene, text, "bench", request, q);
        if (r.status != Status::answered) {
          std::fprintf(stderr, "sliding bench: %s\n", r.message.c_str());
          g_failed = true;
        }
        const bool d = r.motion && r.motion->motion != Motion::undecided;
        decided += d;
        certified += !r.certificate.empty();
      }
      st.counters["decided"] = double(decided);
      st.counters["certified"] = double(certified);
    };
  };
  const int unknown_k = 10, known_k = g_smoke ? 100 : 1000;
  benchmark::RegisterBenchmark(("sliding/unknown/" + std::to_string(unknown_k) + "/hybrid_certified").c_str(),
                               run(unknown_k, true, Mode::hybrid, false))
      ->Unit(benchmark::kMillisecond);
  for (const Mode m : {Mode::hybrid, Mode::float_only})
    benchmark::RegisterBenchmark(("sliding/known/" + std::to_string(known_k) + "/" + mode_name(m)).c_str(),
                                 run(known_k, false, m, false))
        ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("sliding/known/10/hybrid_certified", run(10, false, Mode::hybrid, false))
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("sliding/known/10/polytopes_n32", run(10, false, Mode::exact, true))
      ->Unit(benchmark::kMillisecond);
}

// hold (issue 16): 4 frictional contacts and 10 known support points (testing/stress_families.h fixture_text,
// loads 0.5–1.5 of Σ μ_i f_i, about half held), the answer with its certificate checked by the independent checker,
// per scene. Goal: ≤ 1 ms in hybrid. Counters: the share held and the undecided answers (must stay 0 in hybrid).
void register_hold() {
  const auto run = [](Mode mode) {
    return [mode](benchmark::State& st) {
      stress::Rng rng(16);
      std::vector<std::string> texts;
      for (int s = 0; s < 64; ++s) texts.push_back(stress::fixture_text(rng, 4, 10, 0.5 + (s % 11) / 10.0));
      Request request;
      request.mode = mode;
      std::size_t i = 0, held = 0, undecided = 0;
      for (auto _ : st) {
        const Hold_item r = answer_hold(texts[i++ % texts.size()], "bench", request);
        if (r.status != Status::answered && r.status != Status::undecided) {
          std::fprintf(stderr, "hold bench: %s\n", r.message.c_str());
          g_failed = true;
        }
        held += r.status == Status::answered && r.answer.verdict == Hold_verdict::holds;
        undecided += r.status != Status::answered || r.answer.verdict == Hold_verdict::undecided;
      }
      st.counters["held"] = double(held) / double(st.iterations());
      st.counters["undecided"] = double(undecided);
    };
  };
  for (const Mode m : {Mode::hybrid, Mode::float_only, Mode::exact})
    benchmark::RegisterBenchmark((std::string("hold/4_contacts_10_points/") + mode_name(m)).c_str(), run(m))
        ->Unit(benchmark::kMicrosecond);
}

// Support regions [RG-1] [RG-2] (issue 16's targets): a uniform 20-vertex polygon (its vertices on a wobbly circle,
// 6-decimal coordinates). regions/power: the certified power and load of one rotation to relative width 1e-6 (twists
// cycled over centres inside, on the rim and outside); regions/motion: stick / slide with the certificate, checked
// by the independent checker (loads cycled over sticking and sliding ones, ~0.5 and ~1.5 of the limit surface).
std::string region_text(int n) {
  std::string pts;
  for (int i = 0; i < n; ++i) {
    const double a = 6.283185307179586 * i / n, r = 1 + 0.15 * std::sin(3 * a);
    char b[96];
    std::snprintf(b, sizeof b, "%s[\"%.6f\", \"%.6f\"]", i ? ", " : "", r * std::cos(a), r * std::sin(a));
    pts += b;
  }
  return "{\"wrenchkit\": 1, \"support\": {\"mu\": \"1/2\", \"regions\": [{\"outline\": [" + pts +
         "], \"pressure\": \"uniform\", \"force\": 2}]}}";
}

void register_regions() {
  const int n = 20;
  benchmark::RegisterBenchmark(("regions/power/" + std::to_string(n) + "/tolerance_1e-6").c_str(), [n](benchmark::State& st) {
    const Scene scene = read_scene(region_text(n), Input_limits{});
    const std::vector<Vec3q> twists = {{Rational(1, 5), Rational(-1, 10), 1}, {0, -1, 1}, {3, -4, 1}, {0, 0, 1}};
    std::size_t i = 0, met = 0;
    for (auto _ : st) {
      const Region_sliding a = region_sliding(*scene.support, twists[i++ % twists.size()], Rational(1, 1000000));
      met += a.met;
      benchmark::DoNotOptimize(a.h_hi);
    }
    st.counters["decided"] = double(met);
  })->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark(("regions/motion/" + std::to_string(n) + "/hybrid_certified").c_str(), [n](benchmark::State& st) {
    const std::string text = region_text(n);
    const Scene scene = read_scene(text, Input_limits{});
    // μW = 1: forces 1/2 and 3/2; the pure moment ~0.67 at the limit (a disc of radius ~1): 1/3 and 1.
    const std::vector<Vec3q> loads = {{Rational(1, 2), 0, 0}, {Rational(3, 2), 0, 0}, {0, 0, Rational(1, 3)},
                                      {0, 0, 1}, {Rational(3, 10), Rational(1, 5), Rational(1, 5)}};
    Request request;
    std::size_t i = 0, certified = 0, decided = 0;
    for (auto _ : st) {
      Support_query q;
      q.load = loads[i++ % loads.size()];
      const Support_item r = answer_support(scene, text, "bench", request, q);
      if (r.status != Status::answered) {
        std::fprintf(stderr, "regions bench: %s\n", r.message.c_str());
        g_failed = true;
      }
      decided += r.motion && r.motion->motion != Motion::undecided;
      certified += !r.certificate.empty();
    }
    st.counters["decided"] = double(decided);
    st.counters["certified"] = double(certified);
  })->Unit(benchmark::kMillisecond);
}

// quality/6/METHOD: the grasp quality of 6 frictional contacts pressing inward on a hexagon (issue 31's targets):
// ε (L1, unit-normal) with and without its certificate's JSON, for normals of rational length (ε² exact) and of
// irrational length (a bracket to 1e-12), GraspIt!'s qhull ε on the same generators in double, and μ* (closure).
void register_quality() {
  const auto scene_text = [](bool rational_normals) {
    // points on a hexagon; normals toward the centre, of length 5 ((3, 4)-type) or not ((1, 1)-type)
    const int at[6][2] = {{4, 0}, {2, 3}, {-2, 3}, {-4, 0}, {-2, -3}, {2, -3}};
    const int n5[6][2] = {{-4, -3}, {-3, -4}, {4, -3}, {4, 3}, {3, 4}, {-3, 4}};
    const int n2[6][2] = {{-1, 0}, {-1, -1}, {1, -1}, {1, 0}, {1, 1}, {-1, 1}};
    std::string t = R"({"wrenchkit": 1, "contacts": [)";
    for (int i = 0; i < 6; ++i) {
      const int* n = rational_normals ? n5[i] : n2[i];
      t += (i ? ", " : "") + std::string("{\"at\": [") + std::to_string(at[i][0]) + ", " + std::to_string(at[i][1]) +
           "], \"normal\": [" + std::to_string(n[0]) + ", " + std::to_string(n[1]) + "], \"mu\": \"1/2\"}";
    }
    return t + "]}";
  };
  for (const bool rational : {true, false}) {
    const std::string base = std::string("quality/6/") + (rational ? "rational_normals/" : "irrational_normals/");
    const auto scene = std::make_shared<Scene>(read_scene(scene_text(rational), Input_limits{}));
    for (const bool certify : {false, true})
      benchmark::RegisterBenchmark((base + (certify ? "epsilon_hybrid_certificate" : "epsilon_hybrid")).c_str(),
                                   [scene, certify](benchmark::State& st) {
                                     for (auto _ : st) {
                                       const Quality_answer a = decide_quality(*scene, Quality_query{}, Mode::hybrid);
                                       if (certify) benchmark::DoNotOptimize(certificate_json(a));
                                       benchmark::DoNotOptimize(a.lower);
                                     }
                                   })
          ->Unit(benchmark::kMicrosecond);
    // GraspIt!'s ε on the same unit-normal generators, in double
    std::vector<peers::Wrench_d> g;
    for (const Generator& gen : generators(*scene, Reading::friction)) {
      const Contact& c = scene->contacts[gen.contact];
      const double len = std::sqrt(dot(c.normal, c.normal).get_d());
      g.push_back({gen.w[0].get_d() / len, gen.w[1].get_d() / len, gen.w[2].get_d() / len});
    }
    benchmark::RegisterBenchmark((base + "qhull_graspit_epsilon").c_str(), [g](benchmark::State& st) {
      for (auto _ : st) benchmark::DoNotOptimize(peers::qhull_graspit_epsilon(g));
    })->Unit(benchmark::kMicrosecond);
  }
  // the float twin of ε (float/quality_twin.h) on 6 contacts in general position (doubles, as quality_arrays reads
  // them): the twin alone, decide_quality with twin_first, and the pipeline without a certificate (the array rows)
  {
    std::string t = R"({"wrenchkit": 1, "contacts": [)";
    const double at[6][2] = {{3.91, 0.42}, {2.13, 2.61}, {-1.87, 2.77}, {-3.96, -0.31}, {-2.24, -2.58}, {1.78, -2.85}};
    const double n[6][2] = {{-0.97, -0.2}, {-0.6, -0.8}, {0.52, -0.85}, {0.99, 0.12}, {0.61, 0.79}, {-0.4, 0.92}};
    for (int i = 0; i < 6; ++i) {
      char buf[160];
      std::snprintf(buf, sizeof buf, R"(%s{"at": [%.17g, %.17g], "normal": [%.17g, %.17g], "mu": 0.4})", i ? ", " : "",
                    at[i][0], at[i][1], n[i][0], n[i][1]);
      t += buf;
    }
    const auto scene = std::make_shared<Scene>(read_scene(t + "]}", Input_limits{}));
    std::vector<fl::Quality_twin_contact> in;
    for (const fl::Bounded_contact& c : to_bounded(*scene)) in.push_back({c.ax, c.ay, c.nx, c.ny, c.mu});
    benchmark::RegisterBenchmark("quality/6/general_position/epsilon_twin", [in](benchmark::State& st) {
      fl::Quality_twin_answer a;
      for (auto _ : st) {
        a = fl::epsilon_twin(in, fl::Twin_normalization::unit_normal, fl::Bounded::exact(1), fl::Bounded::exact(0),
                             fl::Bounded::exact(0));
        benchmark::DoNotOptimize(a.lower);
      }
      if (!a.certain || !a.closed) throw std::logic_error("quality twin bench: the twin should certify this grasp");
    })->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark("quality/6/general_position/decide_quality_twin_first", [scene](benchmark::State& st) {
      Quality_query q;
      q.twin_first = true;
      q.critical_mu = false;
      for (auto _ : st) benchmark::DoNotOptimize(decide_quality(*scene, q, Mode::hybrid).lower);
    })->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark("quality/6/general_position/answer_quality_no_certificate", [scene](benchmark::State& st) {
      Quality_query q;
      q.twin_first = true;
      q.critical_mu = false;
      Request r;
      r.certify = false;
      Scene row = *scene;
      for (auto _ : st) {  // as quality_arrays answers a row: the scene moved in and back out
        Quality_item item = answer_quality(std::move(row), "", r, q);
        row = std::move(item.scene);
        benchmark::DoNotOptimize(item.answer.lower);
      }
    })->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark("quality/6/general_position/decide_quality_exact_hybrid", [scene](benchmark::State& st) {
      Quality_query q;
      q.critical_mu = false;
      for (auto _ : st) benchmark::DoNotOptimize(decide_quality(*scene, q, Mode::hybrid).lower);
    })->Unit(benchmark::kMicrosecond);
  }
  // μ* of 6 contacts whose normals are turned off the centre (a pinwheel: free to turn without friction, closed above
  // a threshold): its closure's value (exact or bracketed), all decisions and certificates included
  for (const int turn : {1, 2}) {
    const int at[6][2] = {{4, 0}, {2, 3}, {-2, 3}, {-4, 0}, {-2, -3}, {2, -3}};
    std::string t = R"({"wrenchkit": 1, "contacts": [)";
    for (int i = 0; i < 6; ++i) {  // n = −p + rot90(p)/turn·(1 or 2): rational or not
      const int nx = -at[i][0] * 2 - at[i][1] * turn, ny = -at[i][1] * 2 + at[i][0] * turn;
      t += (i ? ", " : "") + std::string("{\"at\": [") + std::to_string(at[i][0]) + ", " + std::to_string(at[i][1]) +
           "], \"normal\": [" + std::to_string(nx) + ", " + std::to_string(ny) + "]}";
    }
    const auto scene = std::make_shared<Scene>(read_scene(t + "]}", Input_limits{}));
    const Critical_answer probe = decide_critical_mu(*scene, Mode::hybrid, Rational(1, 1000000000000ul));
    const std::string name = std::string("quality/6/pinwheel_") + std::to_string(turn) + "/critical_mu_" +
                             (probe.closure.exact() ? "exact" : "bracket");
    benchmark::RegisterBenchmark(name.c_str(), [scene](benchmark::State& st) {
      for (auto _ : st) {
        const Critical_answer a = decide_critical_mu(*scene, Mode::hybrid, Rational(1, 1000000000000ul));
        benchmark::DoNotOptimize(critical_mu_certificate(a.closure, true));
      }
    })->Unit(benchmark::kMicrosecond);
  }
}

// grasp_regions/100gon/…: every edge pair of a 100-gon (rational points near a circle, μ = 1/2) — the exact regions
// with their certificate checked (issue 32's target: ≤ 1 s), and the naive double Nguyen test (the guess a float tool
// makes) on placements 10⁻ᵏ beside every region corner, toward the region and away from it: the counter
// "naive_wrong_per_1000" is how often it contradicts the exact region (it may guess; nothing certified uses it).
void register_grasp_regions() {
  std::string outline;
  for (int k = 0; k < 100; ++k) {
    const double th = -M_PI + 2 * M_PI * (k + 0.5) / 100;
    const Rational t(std::lround(std::tan(th / 2) * 1000), 1000);  // a rational point exactly on the circle
    const Rational x = (1 - t * t) / (1 + t * t), y = 2 * t / (1 + t * t);
    outline += (k ? ", " : "") + std::string("[\"") + to_string(x) + "\", \"" + to_string(y) + "\"]";
  }
  const auto text = std::make_shared<std::string>(R"({"wrenchkit": 1, "mu": "1/2", "body": {"outline": [)" + outline + "]}}");
  benchmark::RegisterBenchmark("grasp_regions/100gon/exact_with_certificate", [text](benchmark::State& st) {
    std::size_t closed = 0;
    for (auto _ : st) {
      const Grasp_regions_item r = answer_grasp_regions(*text, "100-gon", Request{}, Grasp_regions_query{});
      if (r.status != Status::answered) throw std::logic_error("grasp regions: " + r.message);
      closed = r.regions.closed_pairs();
    }
    st.counters["closed_pairs"] = static_cast<double>(closed);
  })->Unit(benchmark::kMillisecond)->Iterations(g_smoke ? 1 : 3);
  // three fingers on a 20-gon of the same circle (1 140 edge triples): issue 32's target ≤ 10 s with certificates
  std::string outline20;
  for (int k = 0; k < 20; ++k) {
    const double th = -M_PI + 2 * M_PI * (k + 0.5) / 20;
    const Rational t(std::lround(std::tan(th / 2) * 1000), 1000);
    const Rational x = (1 - t * t) / (1 + t * t), y = 2 * t / (1 + t * t);
    outline20 += (k ? ", " : "") + std::string("[\"") + to_string(x) + "\", \"" + to_string(y) + "\"]";
  }
  for (const char* mu : {"1/2", "1/5"}) {
    const auto text20 = std::make_shared<std::string>(R"({"wrenchkit": 1, "mu": ")" + std::string(mu) +
                                                       R"(", "body": {"outline": [)" + outline20 + "]}}");
    benchmark::RegisterBenchmark(("grasp_regions/20gon_mu_" + std::string(mu[2] == '2' ? "1_2" : "1_5") +
                                  "/three_fingers_with_certificate").c_str(),
                                 [text20](benchmark::State& st) {
      Grasp_regions_query q;
      q.fingers = 3;
      std::size_t boxed = 0, never = 0;
      for (auto _ : st) {
        const Grasp_regions_item r = answer_grasp_regions(*text20, "20-gon", Request{}, q);
        if (r.status != Status::answered) throw std::logic_error("grasp regions: " + r.message);
        boxed = r.regions.boxed_triples(), never = r.regions.never_triples();
      }
      st.counters["boxed_triples"] = static_cast<double>(boxed);
      st.counters["never_triples"] = static_cast<double>(never);
    })->Unit(benchmark::kMillisecond)->Iterations(g_smoke ? 1 : 3);
  }
  // the placements both rows decide: 10⁻ᵏ (k = 6, 9, 12, 15) beside every region corner, toward (1/2, 1/2) and away
  struct Near_corner {
    const Pair_region* p;
    Rational s, t;
  };
  const auto near_corners = [](const Grasp_regions& g) {
    std::vector<Near_corner> out;
    for (const Pair_region& p : g.pairs)
      for (const auto& c : p.polygon)
        for (const int k : {6, 9, 12, 15})
          for (const int dir : {1, -1}) {
            Integer ten;
            mpz_ui_pow_ui(ten.get_mpz_t(), 10, static_cast<unsigned long>(k));
            const Rational e = Rational(dir) / Rational(ten);
            const Rational s = c[0] + e * (Rational(1, 2) - c[0]), t = c[1] + e * (Rational(1, 2) - c[1]);
            if (s >= 0 && s <= 1 && t >= 0 && t <= 1) out.push_back({&p, s, t});
          }
    return out;
  };
  benchmark::RegisterBenchmark("grasp_regions/100gon/naive_double_near_corners", [text, near_corners](benchmark::State& st) {
    const Scene scene = read_scene(*text, Input_limits{});
    const Grasp_regions g = two_finger_regions(scene, Rational(1, 2));
    const std::vector<Near_corner> P = near_corners(g);
    const std::vector<Vec2>& V = scene.body.outline;
    const int o = outline_orientation(V);
    std::size_t wrong = 0;
    for (auto _ : st) {
      wrong = 0;
      for (const Near_corner& x : P) {
        // the naive test in doubles: the segment inside both cones, |cross(n, d)| < mu (n . d)
        const Vec2 pi = edge_point(V, x.p->i, x.s), pj = edge_point(V, x.p->j, x.t);
        const Vec2 ni = edge_inward_normal(V, x.p->i, o), nj = edge_inward_normal(V, x.p->j, o);
        const double dx = pj.x.get_d() - pi.x.get_d(), dy = pj.y.get_d() - pi.y.get_d();
        const auto inside = [](double nx, double ny, double vx, double vy) {
          const double along = nx * vx + ny * vy, side = nx * vy - ny * vx;
          return along > 0 && std::abs(side) < 0.5 * along;
        };
        const bool guess = inside(ni.x.get_d(), ni.y.get_d(), dx, dy) && inside(nj.x.get_d(), nj.y.get_d(), -dx, -dy);
        wrong += guess != closed_at(*x.p, x.s, x.t);
      }
      benchmark::DoNotOptimize(wrong);
    }
    st.counters["placements"] = static_cast<double>(P.size());
    st.counters["naive_wrong_per_1000"] = P.empty() ? 0 : 1000.0 * static_cast<double>(wrong) / static_cast<double>(P.size());
  })->Unit(benchmark::kMillisecond)->Iterations(1);
  // the float twin (float/grasp_twin.h: Nguyen's four signs in Bounded arithmetic) on the same placements: certified
  // closed or open, or uncertain — never wrong (the counter must stay 0), abstaining only beside the boundary
  benchmark::RegisterBenchmark("grasp_regions/100gon/twin_near_corners", [text, near_corners](benchmark::State& st) {
    const Scene scene = read_scene(*text, Input_limits{});
    const Grasp_regions g = two_finger_regions(scene, Rational(1, 2));
    const std::vector<Vec2>& V = scene.body.outline;
    const int o = outline_orientation(V);
    struct Placement {
      fl::Finger_twin a, b;
      bool closed;
    };
    std::vector<Placement> P;
    for (const Near_corner& x : near_corners(g)) {
      const Vec2 pi = edge_point(V, x.p->i, x.s), pj = edge_point(V, x.p->j, x.t);
      const Vec2 ni = edge_inward_normal(V, x.p->i, o), nj = edge_inward_normal(V, x.p->j, o);
      P.push_back({{to_bounded(pi.x), to_bounded(pi.y), to_bounded(ni.x), to_bounded(ni.y)},
                   {to_bounded(pj.x), to_bounded(pj.y), to_bounded(nj.x), to_bounded(nj.y)}, closed_at(*x.p, x.s, x.t)});
    }
    std::size_t abstain = 0, wrong = 0;
    const fl::Bounded mu = to_bounded(Rational(1, 2));
    for (auto _ : st) {
      abstain = wrong = 0;
      for (const Placement& x : P) {
        const Sign v = fl::nguyen_twin(x.a, x.b, mu);
        if (v == Sign::uncertain) ++abstain;
        else wrong += (v == Sign::positive) != x.closed;
      }
      benchmark::DoNotOptimize(wrong);
    }
    st.counters["placements"] = static_cast<double>(P.size());
    st.counters["twin_abstains_per_1000"] = P.empty() ? 0 : 1000.0 * static_cast<double>(abstain) / static_cast<double>(P.size());
    st.counters["twin_wrong"] = static_cast<double>(wrong);
  })->Unit(benchmark::kMicrosecond);
}


// push/…: which way a pushed body turns. A body on 10 legs with given decimal forces and coefficients, pushed at a
// point with friction: the voting decision alone (the scene read once), the whole pipeline (read, decide, certificate,
// the independent checker), and the same over F (forces not given, two coefficients: six exact LPs). And the near-tie
// family: the pusher's velocity 10⁻ᵏ (k = 9, 12, 15 … 18) beside the line to the centre of friction, each side, on 50
// supports of decimal numbers — the naive double vote (the guess a float tool makes) against the exact one: the
// counter "naive_wrong_per_1000" (it may guess; nothing certified uses it); the twin abstains ("twin_uncertain_per_1000")
// and is never wrong, nor is the hybrid (the exact sign where the twin abstains): a wrong one fails the run.
void register_push() {
  std::string legs;
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> milli(-2000, 2000), f(1, 900), m(10, 90);
  for (int i = 0; i < 10; ++i)
    legs += (i ? ", " : "") + std::string("{\"at\": [") + std::to_string(milli(rng) / 1000.0) + ", " +
            std::to_string(milli(rng) / 1000.0) + "], \"force\": " + std::to_string(f(rng) / 100.0) + ", \"mu\": 0." +
            std::to_string(m(rng)) + "}";
  const auto known = std::make_shared<std::string>(
      R"({"wrenchkit": 1, "support": {"points": [)" + legs +
      R"(]}, "pusher": {"at": [0.25, -2.5], "normal": [0.1, 1], "mu": 0.3, "velocity": [0.4, 1]}})");
  std::string unknown_legs;
  for (int i = 0; i < 10; ++i)
    unknown_legs += (i ? ", " : "") + std::string("{\"at\": [") + std::to_string(milli(rng) / 1000.0) + ", " +
                    std::to_string(milli(rng) / 1000.0) + "], \"mu\": " + (i % 2 ? "0.3" : "0.6") + "}";
  const auto unknown = std::make_shared<std::string>(
      R"({"wrenchkit": 1, "support": {"weight": 10, "pressure_center": [0, 0], "points": [)" + unknown_legs +
      R"(]}, "pusher": {"at": [0.25, -2.5], "normal": [0.1, 1], "mu": 0.3, "velocity": [0.4, 1]}})");
  benchmark::RegisterBenchmark("push/10_legs/rotation_exact", [known](benchmark::State& st) {
    const Scene scene = read_scene(*known, Input_limits{});
    const Support_model model(scene);
    for (auto _ : st) benchmark::DoNotOptimize(decide_push(model, *scene.pusher).rotation);
  })->Unit(benchmark::kMicrosecond);
  for (const auto& [name, text] : {std::pair{"push/10_legs/with_certificate", known},
                                   std::pair{"push/10_legs_forces_not_given/with_certificate", unknown}})
    benchmark::RegisterBenchmark(name, [text = text](benchmark::State& st) {
      Rotation got = Rotation::undecided;
      for (auto _ : st) {
        const Push_item r = answer_push(*text, "legs", Request{});
        if (r.status != Status::answered || r.certificate.empty()) throw std::logic_error("push: " + r.message);
        got = r.push.rotation;
      }
      st.SetLabel(rotation_name(got));
    })->Unit(benchmark::kMicrosecond);
  // the rotation centres over every distribution (PU-4, --locus) beside the rotation alone, with the certificate
  // checked: the 10 legs' forces given (c their friction centre) and not given (one coefficient: c the pressure centre)
  const auto one_mu = std::make_shared<std::string>(
      R"({"wrenchkit": 1, "support": {"mu": 0.5, "weight": 10, "pressure_center": [0, 0], "points": [)" +
      std::regex_replace(unknown_legs, std::regex(R"(, "mu": 0\.[36])"), "") +
      R"(]}, "pusher": {"at": [0.25, -2.5], "normal": [0.1, 1], "mu": 0.3, "velocity": [0.4, 1]}})");
  // the contact mode over forces not given (PU-2 §9): the extreme distributions of F until two differ ("depends")
  benchmark::RegisterBenchmark("push/10_legs_forces_not_given/contact_with_certificate", [unknown](benchmark::State& st) {
    Push_query q;
    q.contact = true;
    std::string label;
    for (auto _ : st) {
      const Push_item r = answer_push(*unknown, "legs", Request{}, q);
      if (r.status != Status::answered || !r.push.contact) throw std::logic_error("push --contact: " + r.message);
      label = push_mode_name(r.push.contact->mode);
    }
    st.SetLabel(label);
  })->Unit(benchmark::kMicrosecond);
  for (const auto& [name, text] : {std::pair{"push/10_legs/locus_with_certificate", known},
                                   std::pair{"push/10_legs_forces_not_given/locus_with_certificate", one_mu}})
    benchmark::RegisterBenchmark(name, [text = text](benchmark::State& st) {
      Push_query q;
      q.locus = true;
      std::string label;
      for (auto _ : st) {
        const Push_item r = answer_push(*text, "legs", Request{}, q);
        if (r.status != Status::answered || r.certificate.empty() || !r.push.locus || !r.push.locus->friction_centre)
          throw std::logic_error("push --locus: " + r.message);
        label = std::string(rotation_name(r.push.rotation)) + (r.push.locus->arm_hi ? ", arm " +
                                                               std::to_string(r.push.locus->arm_hi->get_d()) : ", no arm");
      }
      st.SetLabel(label);
    })->Unit(benchmark::kMicrosecond);
  // the contact mode with its certificate (PU-2; --contact at the default tolerance 1e-12): the pusher's μ 0.3 and
  // 0.02 (then the contact slides and the body's sliding motion is bracketed too, §5)
  for (const auto& [name, mu] : {std::pair{"push/10_legs/contact_with_certificate", "0.3"},
                                 std::pair{"push/10_legs/contact_slides_with_certificate", "0.02"}}) {
    std::string text = *known;
    text.replace(text.find("\"mu\": 0.3, \"velocity\""), 9, std::string("\"mu\": ") + mu);
    benchmark::RegisterBenchmark(name, [text](benchmark::State& st) {
      Push_query q;
      q.contact = true;
      std::string mode;
      for (auto _ : st) {
        const Push_item r = answer_push(text, "legs", Request{}, q);
        if (r.status != Status::answered || r.certificate.empty()) throw std::logic_error("push: " + r.message);
        mode = push_mode_name(r.push.contact->mode);
        if (r.push.contact->mode != Push_mode::sticks && !r.push.contact->has_motion) mode += " (motion not bracketed)";
      }
      st.SetLabel(mode);
    })->Unit(benchmark::kMicrosecond);
  }
  // [PU-3] a line pusher under the same 10 legs (a fence from (-1, -2.5) to (1.5, -2.5), μ 0.5, velocity (0, 1) at
  // its middle): is its motion stable, with the certificate checked — translating (four exact signs), turning far away
  // (PU-3's inequalities), nearer (the LP's dual over the legs where the tip line fails) and close (a witness)
  for (const auto& [name, omega] : {std::pair{"push/stable/10_legs/translating", "0"},
                                    std::pair{"push/stable/10_legs/turning_far", "0.02"},
                                    std::pair{"push/stable/10_legs/turning_near", "0.12"},
                                    std::pair{"push/stable/10_legs/turning_close", "1"}}) {
    const std::string text = R"({"wrenchkit": 1, "support": {"points": [)" + legs +
                             R"(]}, "pusher": {"segment": [[-1, -2.5], [1.5, -2.5]], "normal": [0, 1], "mu": 0.5, )"
                             R"("velocity": [0, 1], "omega": )" + omega + "}}";
    benchmark::RegisterBenchmark(name, [text](benchmark::State& st) {
      std::string label;
      for (auto _ : st) {
        const Push_item r = answer_push(text, "fence", Request{});  // (the stable region below: push/stable/…/region)
        if (r.status != Status::answered) throw std::logic_error("push: " + r.message);
        const Stable_push& v = *r.push.stable;
        label = stability_name(v.verdict);
        if (v.verdict == Stability::stable && v.sense != 0)
          label += v.duals.empty() ? " (PU-3's inequalities)" : " (a dual)";
        if (v.verdict == Stability::unstable && v.sense != 0) label += " (a witness)";
      }
      st.SetLabel(label);
    })->Unit(benchmark::kMicrosecond);
  }
  // the stable region (PU-3 §6; the issue's target 1 ms): both senses' half-planes, polygons and the translations,
  // with the query and the certificate checked
  benchmark::RegisterBenchmark("push/stable/10_legs/region", [legs](benchmark::State& st) {
    const std::string text = R"({"wrenchkit": 1, "support": {"points": [)" + legs +
                             R"(]}, "pusher": {"segment": [[-1, -2.5], [1.5, -2.5]], "normal": [0, 1], "mu": 0.5, )"
                             R"("velocity": [0, 1], "omega": 0.02}})";
    Push_query q;
    q.region = true;
    std::size_t vertices = 0;
    for (auto _ : st) {
      const Push_item r = answer_push(text, "fence", Request{}, q);
      if (r.status != Status::answered || !r.push.region) throw std::logic_error("push: " + r.message);
      vertices = r.push.region->side[0].polygon.size() + r.push.region->side[1].polygon.size();
    }
    st.SetLabel(std::to_string(vertices) + " polygon vertices");
  })->Unit(benchmark::kMicrosecond);
  // the twin alone on the 10 legs (its input as certified doubles, converted once: the robot-side cost)
  benchmark::RegisterBenchmark("push/10_legs/rotation_twin", [known](benchmark::State& st) {
    const Scene scene = read_scene(*known, Input_limits{});
    const Support& s = *scene.support;
    fl::Push_twin_input in;
    for (const Support_point& p : s.points) {
      in.x.push_back(to_bounded(p.at.x)), in.y.push_back(to_bounded(p.at.y));
      in.w.push_back(to_bounded(s.mu_of(p)) * to_bounded(*p.force));
    }
    const Contact& c = scene.pusher->contact;
    in.px = to_bounded(c.at.x), in.py = to_bounded(c.at.y), in.nx = to_bounded(c.normal.x), in.ny = to_bounded(c.normal.y);
    in.mu = to_bounded(c.mu), in.vx = to_bounded(scene.pusher->velocity.x), in.vy = to_bounded(scene.pusher->velocity.y);
    int rot = 0;
    for (auto _ : st) {
      const fl::Push_twin_answer a = fl::push_twin(in);
      rot = a.certain ? a.rotation : 2;
      benchmark::DoNotOptimize(rot);
    }
    st.SetLabel(rot == 1 ? "ccw" : rot == -1 ? "cw" : rot == 0 ? "none" : "uncertain");
  })->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("push/near_tie/naive_twin_hybrid", [](benchmark::State& st) {
    std::size_t tried = 0, wrong = 0, twin_uncertain = 0, twin_wrong = 0, hybrid_wrong = 0;
    for (auto _ : st) {
      tried = wrong = twin_uncertain = twin_wrong = hybrid_wrong = 0;
      std::mt19937_64 r(11);
      std::uniform_int_distribution<int> milli(-2000, 2000), f(1, 900), m(10, 90);
      for (int sc = 0; sc < 50; ++sc) {
        std::vector<Vec2> at(10);
        std::vector<Rational> w(10);
        Vec2 cm{0, 0};
        Rational D = 0;
        for (int i = 0; i < 10; ++i) {
          at[i] = {Rational(milli(r), 1000), Rational(milli(r), 1000)};
          w[i] = Rational(f(r), 100) * Rational(m(r), 100);  // mu_i f_i
          cm.x += w[i] * at[i].x, cm.y += w[i] * at[i].y, D += w[i];
        }
        const Vec2 c{cm.x / D, cm.y / D}, p{Rational(1, 4), Rational(-5, 2)};
        const Vec2 d{c.x - p.x, c.y - p.y};
        for (const int k : {9, 12, 15, 16, 17, 18})
          for (const int side : {1, -1}) {
            Integer ten;
            mpz_ui_pow_ui(ten.get_mpz_t(), 10, static_cast<unsigned long>(k));
            const Rational e = Rational(side) / Rational(ten);
            const Vec2 v{d.x - e * d.y, d.y + e * d.x};  // d turned by about e: passes c 1e-k·|d| to one side
            Rational N = 0;  // the exact vote: sum w_i (p - r_i) x v
            for (int i = 0; i < 10; ++i) N += w[i] * cross(Vec2{p.x - at[i].x, p.y - at[i].y}, v);
            // the naive double vote: c and the cross product in doubles from the numbers' nearest doubles
            double cx = 0, cy = 0, dd = 0;
            for (int i = 0; i < 10; ++i) {
              const double wi = w[i].get_d();
              cx += wi * at[i].x.get_d(), cy += wi * at[i].y.get_d(), dd += wi;
            }
            cx /= dd, cy /= dd;
            const double naive = (p.x.get_d() - cx) * v.y.get_d() - (p.y.get_d() - cy) * v.x.get_d();
            ++tried;
            wrong += (naive > 0) != (sgn(N) > 0) || naive == 0;
            // the twin's vote of the velocity (its certified sign), and the hybrid: the exact sign when uncertain
            fl::Bounded Nt;
            const fl::Bounded vx = to_bounded(v.x), vy = to_bounded(v.y), px = to_bounded(p.x), py = to_bounded(p.y);
            for (int i = 0; i < 10; ++i)
              Nt = Nt + to_bounded(w[i]) * ((px - to_bounded(at[i].x)) * vy - (py - to_bounded(at[i].y)) * vx);
            const Sign t = Nt.sign();
            if (t == Sign::uncertain) ++twin_uncertain;
            else twin_wrong += static_cast<int>(t) != sgn(N);
            const int hybrid = t == Sign::uncertain ? sgn(N) : static_cast<int>(t);
            hybrid_wrong += hybrid != sgn(N);
          }
      }
      benchmark::DoNotOptimize(wrong);
    }
    if (twin_wrong || hybrid_wrong) {
      std::fprintf(stderr, "push/near_tie: the twin or the hybrid was wrong\n");
      g_failed = true;
    }
    st.counters["votes"] = static_cast<double>(tried);
    st.counters["naive_wrong_per_1000"] = tried ? 1000.0 * static_cast<double>(wrong) / static_cast<double>(tried) : 0;
    st.counters["twin_uncertain_per_1000"] =
        tried ? 1000.0 * static_cast<double>(twin_uncertain) / static_cast<double>(tried) : 0;
    st.counters["twin_wrong"] = static_cast<double>(twin_wrong);
    st.counters["hybrid_wrong"] = static_cast<double>(hybrid_wrong);
  })->Unit(benchmark::kMillisecond)->Iterations(1);
  // the contact mode beside a motion-cone edge (the stress family push_motion_cone: the velocity 10^-k off the edge,
  // k = 3, 6, …, 18, 20 supports each side): the naive double search (a guess) against the certified mode with its
  // certificate checked (the pipeline: never wrong, or the run fails); the time is the certified answers'
  benchmark::RegisterBenchmark("push/motion_cone/naive_and_certified", [](benchmark::State& st) {
    std::size_t tried = 0, naive_wrong = 0, certified_wrong = 0;
    const int seeds = g_smoke ? 2 : 20;
    for (auto _ : st) {
      tried = naive_wrong = certified_wrong = 0;
      for (const double eps : {1e-3, 1e-6, 1e-9, 1e-12, 1e-15, 1e-18})
        for (int seed = 1; seed <= 2 * seeds; ++seed) {
          const stress::Family_scene k = stress::make_scene("push_motion_cone", eps, static_cast<std::uint64_t>(seed));
          const Push_mode truth = k.above ? Push_mode::slides_left : Push_mode::sticks;
          Push_query q;
          q.contact = true;
          const Push_item r = answer_push(k.text, "push_motion_cone", Request{}, q);
          ++tried;
          certified_wrong += r.status != Status::answered || !r.push.contact || r.push.contact->mode != truth;
          naive_wrong += std::string(stress::naive_push_contact(read_scene(k.text, Input_limits{}))) != push_mode_name(truth);
        }
    }
    if (certified_wrong) {
      std::fprintf(stderr, "push/motion_cone: the certified contact mode was wrong or failed\n");
      g_failed = true;
    }
    st.counters["pushes"] = static_cast<double>(tried);
    st.counters["naive_wrong_per_1000"] = tried ? 1000.0 * static_cast<double>(naive_wrong) / static_cast<double>(tried) : 0;
    st.counters["certified_wrong"] = static_cast<double>(certified_wrong);
  })->Unit(benchmark::kMillisecond)->Iterations(1);
}

int main(int argc, char** argv) {
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i) {
    if (std::strcmp(argv[i], "--smoke") == 0) g_smoke = true;
    else args.push_back(argv[i]);
  }
  int n = static_cast<int>(args.size());
  benchmark::Initialize(&n, args.data());
  if (benchmark::ReportUnrecognizedArguments(n, args.data())) return 2;
  register_families();
  register_generic();
  register_growth();
  register_limit_surface();
  register_sliding();
  register_hold();
  register_regions();
  register_quality();
  register_grasp_regions();
  register_push();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  if (g_failed) std::fprintf(stderr, "wrenchkit_bench: a certified method was wrong (see above)\n");
  return g_failed ? 1 : 0;
}
