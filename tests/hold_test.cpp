// [HD-1] hold: contacts and the support's friction against the load (docs/theory-sliding.md §5). Oracles: the
// special cases (no support = equilibrium; no contacts = stick/slide except on the limit surface; a single
// frictionless pin pushing = the pushed object's closed limit surface), the four-legged table and the dinner
// plate over every distribution, and an independent brute force — LPs in double on inscribed and circumscribed
// 256-gons written here — on random fixtures (3–8 support points, 1–2 frictional contacts) with loads 10^-3
// relative from their threshold; every certificate accepted by the independent checker, tampered ones rejected.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "exact/certificates/certificates.h"
#include "exact/fixture/hold.h"
#include "exact/io/input_error.h"
#include "exact/io/scene.h"
#include "exact/numbers/exact_lp.h"
#include "exact/pipeline/hold_answer.h"
#include "exact/sliding/region_sliding.h"
#include "exact/sliding/sliding.h"
#include "exact/sliding/strategies.h"
#include "exact/statics/equilibrium.h"
#include "proofs/checker/checker.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {

const Input_limits kLimits;

std::string num(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

// hold through the pipeline (the independent checker accepts its certificate, or the item says why not).
Hold_item hold_of(const std::string& text, Mode mode) {
  Request r;
  r.mode = mode;
  return answer_hold(text, "test", r);
}

// ---------------------------------------------------------------------------------------------
// The brute force: maximise t subject to  Σ λ_k g_k + Σ_ij λ_ij (u_j, r_i × u_j) + t w_L = 0,
// Σ_j λ_ij ≤ ρ_i s (s = 1: inscribed N-gons, s = 1/cos(π/N): circumscribed), 0 ≤ t ≤ T, all ≥ 0 — a dense
// two-phase simplex in long double (Dantzig's rule, Bland's after many pivots). t_in ≤ t* ≤ t_out, where t* is the
// largest scale of the load that the contacts and the support's friction hold.
struct Dense_lp {
  // maximise c·x, A x = b, x ≥ 0; returns the optimum (−inf if infeasible).
  static long double solve(std::vector<std::vector<long double>> A, std::vector<long double> b,
                           const std::vector<long double>& c) {
    const std::size_t m = A.size(), n = c.size();
    for (std::size_t i = 0; i < m; ++i)
      if (b[i] < 0) {
        for (auto& v : A[i]) v = -v;
        b[i] = -b[i];
      }
    // Tableau with m artificials: columns 0..n-1, n..n+m-1, rhs last.
    const std::size_t N = n + m;
    std::vector<std::vector<long double>> T(m + 1, std::vector<long double>(N + 1, 0));
    std::vector<std::size_t> basis(m);
    for (std::size_t i = 0; i < m; ++i) {
      for (std::size_t j = 0; j < n; ++j) T[i][j] = A[i][j];
      T[i][n + i] = 1;
      T[i][N] = b[i];
      basis[i] = n + i;
    }
    const auto run = [&](const std::vector<long double>& cost, std::size_t columns) {
      // objective row: reduced costs z_j − c_j
      for (std::size_t j = 0; j <= N; ++j) T[m][j] = j < N ? -cost[j] : 0;
      for (std::size_t i = 0; i < m; ++i) {
        const long double cb = cost[basis[i]];
        if (cb == 0) continue;
        for (std::size_t j = 0; j <= N; ++j) T[m][j] += cb * T[i][j];
      }
      for (int it = 0; it < 100000; ++it) {
        std::size_t e = N;
        long double best = -1e-13L;
        for (std::size_t j = 0; j < columns; ++j) {
          if (T[m][j] < best) {
            best = T[m][j];
            e = j;
            if (it > 5000) break;  // Bland: the first improving column
          }
        }
        if (e == N) return true;
        std::size_t l = m;
        long double ratio = 0;
        for (std::size_t i = 0; i < m; ++i)
          if (T[i][e] > 1e-13L) {
            const long double r = T[i][N] / T[i][e];
            if (l == m || r < ratio - 1e-18L || (r <= ratio + 1e-18L && basis[i] < basis[l])) l = i, ratio = r;
          }
        if (l == m) return false;  // unbounded
        const long double p = T[l][e];
        for (auto& v : T[l]) v /= p;
        for (std::size_t i = 0; i <= m; ++i) {
          if (i == l || T[i][e] == 0) continue;
          const long double f = T[i][e];
          for (std::size_t j = 0; j <= N; ++j) T[i][j] -= f * T[l][j];
        }
        basis[l] = e;
      }
      return true;
    };
    std::vector<long double> phase1(N, 0);
    for (std::size_t i = 0; i < m; ++i) phase1[n + i] = -1;
    run(phase1, N);
    if (T[m][N] < -1e-9L) return -INFINITY;
    // drive out artificials at zero level where possible, then phase 2 without them
    std::vector<long double> phase2(N, 0);
    for (std::size_t j = 0; j < n; ++j) phase2[j] = c[j];
    for (std::size_t i = 0; i < m; ++i)
      if (basis[i] >= n) phase2[basis[i]] = 0;
    if (!run(phase2, n)) return INFINITY;
    long double v = 0;
    for (std::size_t i = 0; i < m; ++i)
      if (basis[i] < n) v += c[basis[i]] * T[i][N];
    return v;
  }
};

struct Fixture {
  std::vector<std::array<double, 3>> gens;  // friction generators
  std::vector<std::array<double, 3>> pts;   // support points x, y, ρ = μ f
  std::array<double, 3> load;               // w_L
};

long double gauge_lp(const Fixture& f, int sides, bool outer, double cap) {
  const std::size_t k = f.pts.size(), m = f.gens.size(), n = static_cast<std::size_t>(sides);
  const std::size_t cols = m + k * n + k + 2;  // λ_k, λ_ij, s_i, t, s_t
  std::vector<std::vector<long double>> A(3 + k + 1, std::vector<long double>(cols, 0));
  std::vector<long double> b(3 + k + 1, 0), c(cols, 0);
  const long double pi = 3.141592653589793238462643383279502884L;
  for (std::size_t j = 0; j < m; ++j)
    for (std::size_t r = 0; r < 3; ++r) A[r][j] = f.gens[j][r];
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      const long double a = 2 * pi * (static_cast<long double>(j) + 0.5L) / static_cast<long double>(n);
      const long double ux = std::cos(a), uy = std::sin(a);
      const std::size_t col = m + i * n + j;
      A[0][col] = ux, A[1][col] = uy, A[2][col] = f.pts[i][0] * uy - f.pts[i][1] * ux;
      A[3 + i][col] = 1;
    }
  const std::size_t t = m + k * n + k;
  for (std::size_t r = 0; r < 3; ++r) A[r][t] = f.load[r];
  for (std::size_t i = 0; i < k; ++i) {
    A[3 + i][m + k * n + i] = 1;
    b[3 + i] = f.pts[i][2] / (outer ? std::cos(pi / static_cast<long double>(n)) : 1.0L);
  }
  A[3 + k][t] = 1, A[3 + k][t + 1] = 1, b[3 + k] = cap;
  c[t] = 1;
  return Dense_lp::solve(A, b, c);
}

// ---------------------------------------------------------------------------------------------
// Special cases

// −w_L in the interior of W = pos{g_k} (the theorem's own statement, by an exact LP apart from the engine's): the
// generators span R³ and −w_L = Σ λ_k g_k with every λ_k > 0 (the relative interior of a finitely generated cone is
// the set of its strictly positive combinations of all generators): max t with λ_k = t + s_k, s_k ≥ 0, t ≤ 1.
bool in_interior_of_cone(const std::vector<Vec3q>& g, const Vec3q& x) {
  Vec3q n{};
  bool spans = false;
  for (const Vec3q& u : g)
    for (const Vec3q& v : g) {
      n = cross(u, v);
      for (const Vec3q& w : g) spans = spans || dot(n, w) != 0;
    }
  if (!spans) return false;
  const std::size_t k = g.size();  // columns: t, t's slack, s_1..s_k
  std::vector<std::vector<Rational>> A(4, std::vector<Rational>(k + 2));
  std::vector<Rational> b(4);
  for (std::size_t row = 0; row < 3; ++row) {
    for (std::size_t j = 0; j < k; ++j) A[row][0] += g[j][row], A[row][2 + j] = g[j][row];
    b[row] = x[row];
  }
  A[3][0] = 1, A[3][1] = 1, b[3] = 1;
  std::vector<Rational> c(k + 2);
  c[0] = 1;
  const Lp_result r = maximise(A, b, c);
  return r.status == Lp_result::Status::optimal && r.value > 0;
}

// No support: hold is equilibrium (theory.md §9) read with the boundary: held (balanced) iff "true" or "impending",
// and "true" (with margin) iff −w_L is in the interior of the contact wrench cone, on every equilibrium golden scene;
// the textbook's critical cases (the ladder at μ = 1/7, the pipe clamps at their critical depths) and the frictionless
// corner's neutral equilibria are "impending", 10^-40 either side of the ladder's μ holds or fails. Every mode, every
// certificate checked.
TEST(HoldSpecialCases, NoSupportIsEquilibrium) {
  int scenes = 0, impending = 0;
  for (const std::string& file : test::scene_files("tests/golden/equilibrium")) {
    const std::string text = test::read_text(file);
    const Scene s = read_scene(text, kLimits);
    if (!s.load || s.support) continue;
    const bool balanced = decide_equilibrium(s, Mode::exact).balanced;
    std::vector<Vec3q> g;
    for (const Generator& x : generators(s, Reading::friction)) g.push_back(x.w);
    const Vec3q w = load_wrench(s);
    const bool interior = balanced && in_interior_of_cone(g, {-w[0], -w[1], -w[2]});
    const Hold_verdict want = !balanced ? Hold_verdict::fails : interior ? Hold_verdict::holds : Hold_verdict::impending;
    impending += want == Hold_verdict::impending;
    for (const Mode m : {Mode::exact, Mode::hybrid}) {
      const Hold_item h = hold_of(text, m);
      ASSERT_EQ(h.status, Status::answered) << file << ": " << h.message;
      EXPECT_EQ(h.answer.verdict, want) << file << " " << mode_name(m);
      EXPECT_TRUE(test::checker_accepts(text, h.certificate)) << file;
    }
    ++scenes;
  }
  EXPECT_GE(scenes, 10);
  EXPECT_GE(impending, 5);
  for (const char* critical : {"ladder_mu_1_7_gravity", "pipe_clamp_mu_1_2_d_4", "pipe_clamp_mu_1_4_d_8"}) {
    const Hold_item h = hold_of(test::read_text(test::source_dir() + "/tests/golden/equilibrium/" + critical + ".scene.json"),
                                Mode::hybrid);
    EXPECT_EQ(h.answer.verdict, Hold_verdict::impending) << critical;
  }
}

std::string known_support(const std::vector<std::array<std::string, 3>>& pts, const std::string& mu) {
  std::string s = R"("support": {"mu": )" + mu + R"(, "points": [)";
  for (std::size_t i = 0; i < pts.size(); ++i)
    s += std::string(i ? ", " : "") + R"({"at": [)" + pts[i][0] + ", " + pts[i][1] + R"(], "force": ")" + pts[i][2] + "\"}";
  return s + "]}";
}

// No contacts: hold is "−w_L ∈ LS(f)", the one stick/slide decision for p = −w_L: holds iff sticks, impending iff
// impending, fails iff slides — the same answer as limit-surface --load, by construction; the barbell's (1/2, 0, 0)
// at μ = 1/2 is on its limit surface (both forces (1/4, 0) on their circles): impending in both, every mode.
TEST(HoldSpecialCases, NoContactsIsStickSlide) {
  std::mt19937_64 rng(test::seed(20261201));
  std::uniform_int_distribution<int> coord(-4, 4), force(1, 4);
  std::uniform_real_distribution<double> dir(-1, 1), scale(0.3, 1.7);
  int decided = 0;
  for (int n = 0; n < 60; ++n) {
    std::vector<std::array<std::string, 3>> pts;
    const int k = 2 + n % 5;
    for (int i = 0; i < k; ++i)
      pts.push_back({std::to_string(coord(rng)), std::to_string(coord(rng)), std::to_string(force(rng))});
    const std::string load = "[" + num(dir(rng) * scale(rng)) + ", " + num(dir(rng) * scale(rng)) + ", " +
                             num(dir(rng) * scale(rng) * 2) + "]";
    const std::string text =
        R"({"wrenchkit": 1, )" + known_support(pts, "\"1/4\"") + R"(, "load": {"wrench": )" + load + "}}";
    const Scene s = read_scene(text, kLimits);
    const Vec3q w = load_wrench(s);
    const Motion_answer m = decide_motion(Support_model(s), {-w[0], -w[1], -w[2]}, Mode::hybrid);
    const Hold_item h = hold_of(text, Mode::hybrid);
    ASSERT_EQ(h.status, Status::answered) << test::dump_failure(text, "hold_nocontact_" + std::to_string(n));
    const Hold_verdict want = m.motion == Motion::sticks      ? Hold_verdict::holds
                              : m.motion == Motion::impending ? Hold_verdict::impending
                              : m.motion == Motion::slides    ? Hold_verdict::fails
                                                              : Hold_verdict::undecided;
    EXPECT_EQ(h.answer.verdict, want) << test::dump_failure(text, "nc");
    if (h.answer.verdict != Hold_verdict::undecided) {
      ++decided;
      EXPECT_TRUE(test::checker_accepts(text, h.certificate));
    }
  }
  EXPECT_GE(decided, 55);
  const std::string barbell = R"({"wrenchkit": 1, "support": {"mu": "1/2", "points": [{"at": [0, -1], "force": "1/2"},
      {"at": [0, 1], "force": "1/2"}]}, "load": {"wrench": ["1/2", 0, 0]}})";
  for (const Mode mode : {Mode::exact, Mode::hybrid}) {
    const Hold_item h = hold_of(barbell, mode);
    ASSERT_EQ(h.status, Status::answered) << h.message;
    EXPECT_EQ(h.answer.verdict, Hold_verdict::impending);
    EXPECT_TRUE(test::checker_accepts(barbell, h.certificate));
    const Scene b = read_scene(barbell, kLimits);
    EXPECT_EQ(decide_motion(Support_model(b), {Rational(-1, 2), 0, 0}, mode).motion, Motion::impending);
  }
}

// A single frictionless pin plus a support: a push κ along the pin's normal through the centre of friction is the
// pushed object's translation load, κ n̂ through c, which the support carries iff κ ≤ μW (its limit surface is
// closed; the translation's witness is rational when n̂ is). So hold with margin iff κ < μW, impending at κ = μW (the
// translation along n̂ meets the friction's power exactly), fails beyond.
TEST(HoldSpecialCases, SinglePinPushThroughTheCentreOfFriction) {
  // Support: a square's corners and its centre, forces summing to W = 2, centre of friction (0, 0); μ = 1/2.
  const std::string support =
      known_support({{{"1", "1", "1/4"}}, {{"-1", "1", "1/4"}}, {{"-1", "-1", "1/4"}}, {{"1", "-1", "1/4"}}, {{"0", "0", "1"}}},
                    "\"1/2\"");
  // The pin at (-3/5, -4/5) (on the line through c along n̂ = (3/5, 4/5)), normal n̂.
  for (const auto& [kappa, want] : std::vector<std::pair<std::string, Hold_verdict>>{
           {"1", Hold_verdict::impending}, {"999/1000", Hold_verdict::holds}, {"1001/1000", Hold_verdict::fails},
           {"1/2", Hold_verdict::holds}, {"3", Hold_verdict::fails}}) {
    // The load κ n̂ on the pin's line, written as a force at the origin (the line passes through it).
    const Rational k(kappa);
    const std::string scene = R"({"wrenchkit": 1, "contacts": [{"at": ["-3/5", "-4/5"], "normal": ["3/5", "4/5"]}], )" +
                              support + R"(, "load": {"force": [")" + to_string(Rational(k * Rational(3, 5))) +
                              R"(", ")" + to_string(Rational(k * Rational(4, 5))) + R"("], "at": [0, 0]}})";
    for (const Mode mode : {Mode::hybrid, Mode::exact}) {
      const Hold_item h = hold_of(scene, mode);
      ASSERT_EQ(h.status, Status::answered) << h.message;
      EXPECT_EQ(h.answer.verdict, want) << kappa << " " << mode_name(mode);
      EXPECT_TRUE(test::checker_accepts(scene, h.certificate)) << kappa;
    }
  }
}

// The four-legged table (theory-sliding.md §6): legs (±1, ±1), μ = 1, W = 1, c = 0, every force unknown; no
// contacts. |f| < 1 holds for every distribution, > 1 fails for every one; a pure moment < √2 holds, > √2 fails;
// (1/2, 1/2, 9/10) depends. The dinner plate (8 rim points of radius 5 and the centre, c = centre): a pure moment
// 0 < m < μWR depends.
TEST(HoldSpecialCases, TableAndPlateOverEveryDistribution) {
  const std::string table = R"({"wrenchkit": 1, "support": {"mu": 1, "weight": 1, "pressure_center": [0, 0], "points":
      [{"at": [1, 1]}, {"at": [-1, 1]}, {"at": [-1, -1]}, {"at": [1, -1]}]}, "load": {"wrench": )";
  const std::vector<std::pair<std::string, Hold_verdict>> cases = {
      {"[\"0.99\", 0, 0]", Hold_verdict::holds},         {"[\"1.01\", 0, 0]", Hold_verdict::fails},
      {"[\"0.6\", \"-0.7\", 0]", Hold_verdict::holds},   {"[\"0.6\", \"0.81\", 0]", Hold_verdict::fails},
      {"[0, 0, \"1.414\"]", Hold_verdict::holds},        {"[0, 0, \"1.415\"]", Hold_verdict::fails},
      {"[\"0.5\", \"0.5\", \"0.9\"]", Hold_verdict::depends}};
  for (const auto& [load, want] : cases) {
    const std::string text = table + load + "}}";
    for (const Mode mode : {Mode::hybrid, Mode::exact}) {
      const Hold_item h = hold_of(text, mode);
      ASSERT_EQ(h.status, Status::answered) << h.message;
      EXPECT_EQ(h.answer.verdict, want) << load << " " << mode_name(mode) << " " << h.answer.undecided_why;
      EXPECT_TRUE(test::checker_accepts(text, h.certificate)) << load;
    }
  }
  std::string plate = R"({"wrenchkit": 1, "support": {"mu": "1/2", "weight": 2, "pressure_center": [0, 0], "points": [)";
  const char* rim[8][2] = {{"5", "0"}, {"3", "4"}, {"0", "5"}, {"-4", "3"}, {"-5", "0"}, {"-3", "-4"}, {"0", "-5"}, {"4", "-3"}};
  for (const auto& r : rim) plate += std::string(R"({"at": [)") + r[0] + ", " + r[1] + "]}, ";
  plate += R"({"at": [0, 0]}]}, "load": {"wrench": [0, 0, )";
  for (const auto& [m, want] : std::vector<std::pair<std::string, Hold_verdict>>{
           {"\"0.1\"", Hold_verdict::depends}, {"\"4.9\"", Hold_verdict::depends}, {"\"5.1\"", Hold_verdict::fails}}) {
    const std::string text = plate + m + "]}}";
    const Hold_item h = hold_of(text, Mode::hybrid);
    ASSERT_EQ(h.status, Status::answered) << h.message;
    EXPECT_EQ(h.answer.verdict, want) << m << " " << h.answer.undecided_why;
    EXPECT_TRUE(test::checker_accepts(text, h.certificate)) << m;
  }
}

// ---------------------------------------------------------------------------------------------
// Random fixtures against the brute force

struct Random_fixture {
  std::string text_without_load;
  Fixture f;
  std::array<std::string, 2> at;        // the load's point
  std::array<double, 2> force;          // its direction (scaled below)
};

Random_fixture random_fixture(std::mt19937_64& rng, int n) {
  std::uniform_real_distribution<double> u(-1, 1), pos(0.1, 1), mu(0.2, 0.8), cmu(0.1, 0.6);
  const auto d3 = [](double v) {  // 3 decimals, exactly as written
    char b[32];
    std::snprintf(b, sizeof b, "%.3f", v);
    return std::string(b);
  };
  Random_fixture r;
  const int k = 3 + n % 6, contacts = 1 + n % 2;
  std::string s = R"({"wrenchkit": 1, "contacts": [)";
  for (int c = 0; c < contacts; ++c) {
    // a contact on the unit circle pushing inward (roughly), with friction
    const double a = 6.283185307179586 * (u(rng) + 1) / 2;
    const std::string px = d3(1.5 * std::cos(a)), py = d3(1.5 * std::sin(a)), nx = d3(-std::cos(a) + 0.3 * u(rng)),
                      ny = d3(-std::sin(a) + 0.3 * u(rng)), m = d3(cmu(rng));
    s += std::string(c ? ", " : "") + R"({"at": [)" + px + ", " + py + R"(], "normal": [)" + nx + ", " + ny +
         R"(], "mu": )" + m + "}";
    const double X = std::stod(px), Y = std::stod(py), NX = std::stod(nx), NY = std::stod(ny), M = std::stod(m);
    for (const double sgn : {1.0, -1.0}) {
      const double fx = NX - sgn * M * NY, fy = NY + sgn * M * NX;
      r.f.gens.push_back({fx, fy, X * fy - Y * fx});
    }
  }
  s += R"(], "support": {"points": [)";
  for (int i = 0; i < k; ++i) {
    const std::string x = d3(u(rng)), y = d3(u(rng)), f = d3(pos(rng)), m = d3(mu(rng));
    s += std::string(i ? ", " : "") + R"({"at": [)" + x + ", " + y + R"(], "force": )" + f + R"(, "mu": )" + m + "}";
    r.f.pts.push_back({std::stod(x), std::stod(y), std::stod(f) * std::stod(m)});
  }
  r.text_without_load = s + "]}, ";
  r.at = {d3(u(rng)), d3(u(rng))};
  const double a = 6.283185307179586 * (u(rng) + 1) / 2;
  r.force = {std::cos(a), std::sin(a)};
  return r;
}

// hold against the brute force: the threshold scale t* of the load lies in [t_in, t_out] (256-gons); loads at
// t_in (1 − 10^-3) hold and at t_out (1 + 10^-3) fail, and hybrid must say so with a certificate the checker
// accepts; float either agrees or is undecided (never wrong); exact agrees on a subset (it is slower).
TEST(HoldOracle, RandomFixturesAgainstPolygonalBruteForce) {
  std::mt19937_64 rng(test::seed(20261202));
  int compared = 0, float_decided = 0, exact_compared = 0, capped = 0;
  for (int n = 0; n < 80; ++n) {
    Random_fixture r = random_fixture(rng, n);
    const double X = std::stod(r.at[0]), Y = std::stod(r.at[1]);
    r.f.load = {r.force[0], r.force[1], X * r.force[1] - Y * r.force[0]};
    const double cap = 1e6;
    const long double t_in = gauge_lp(r.f, 256, false, cap), t_out = gauge_lp(r.f, 256, true, cap);
    ASSERT_LE(t_in, t_out * (1 + 1e-9L)) << n;
    if (t_in >= cap * 0.999) {  // the contacts alone hold every multiple of the load
      ++capped;
      continue;
    }
    if (!(t_out / t_in - 1 < 1e-4L)) continue;  // only where the 256-gons pin the threshold well below 10^-3
    for (const bool above : {false, true}) {
      const double scale = static_cast<double>(above ? t_out * (1 + 1e-3L) : t_in * (1 - 1e-3L));
      const std::string text = r.text_without_load + R"("load": {"force": [)" + num(scale * r.force[0]) + ", " +
                               num(scale * r.force[1]) + R"(], "at": [)" + r.at[0] + ", " + r.at[1] + "]}}";
      const std::string tag = "hold_oracle_" + std::to_string(n) + (above ? "_above" : "_below");
      const Hold_verdict want = above ? Hold_verdict::fails : Hold_verdict::holds;
      const Hold_item h = hold_of(text, Mode::hybrid);
      ASSERT_EQ(h.status, Status::answered) << h.message << " " << test::dump_failure(text, tag);
      ASSERT_EQ(h.answer.verdict, want) << h.answer.undecided_why << " " << test::dump_failure(text, tag);
      ASSERT_TRUE(test::checker_accepts(text, h.certificate)) << test::dump_failure(text, tag);
      const Hold_item fl = hold_of(text, Mode::float_only);
      if (fl.status == Status::answered) {
        ++float_decided;
        EXPECT_EQ(fl.answer.verdict, want) << test::dump_failure(text, tag + "_float");
      } else {
        EXPECT_EQ(fl.status, Status::undecided) << fl.message;
      }
      if (n % 16 == 0) {
        const Hold_item ex = hold_of(text, Mode::exact);
        ASSERT_EQ(ex.status, Status::answered) << ex.message;
        if (ex.answer.verdict != Hold_verdict::undecided) {
          EXPECT_EQ(ex.answer.verdict, want) << test::dump_failure(text, tag + "_exact");
          ++exact_compared;
        }
      }
      ++compared;
    }
  }
  EXPECT_GE(compared, 100);
  EXPECT_GE(float_decided, compared / 2);
  EXPECT_GE(exact_compared, 4);
  std::printf("hold oracle: %d loads compared (%d decided by float alone, %d by exact), %d scenes held by the "
              "contacts alone\n", compared, float_decided, exact_compared, capped);
}

// Tampered certificates of random fixtures are rejected: a support force pushed out of its disc, a contact weight
// changed, a twist's speed bound lowered below the speed, a failing twist whose power is lowered to the bound.
TEST(HoldOracle, TamperedCertificatesRejected) {
  std::mt19937_64 rng(test::seed(20261203));
  int tampered = 0;
  for (int n = 0; n < 30; ++n) {
    Random_fixture r = random_fixture(rng, n);
    for (const double scale : {0.2, 5.0}) {
      const std::string text = r.text_without_load + R"("load": {"force": [)" + num(scale * r.force[0]) + ", " +
                               num(scale * r.force[1]) + R"(], "at": [)" + r.at[0] + ", " + r.at[1] + "]}}";
      const Hold_item h = hold_of(text, Mode::hybrid);
      ASSERT_EQ(h.status, Status::answered) << h.message;
      if (h.answer.verdict == Hold_verdict::undecided) continue;
      ASSERT_TRUE(test::checker_accepts(text, h.certificate));
      const Scene s = read_scene(text, kLimits);
      const std::size_t k = s.support->points.size();
      std::vector<std::string> bad;
      if (h.answer.verdict == Hold_verdict::holds) {
        const Hold_witness& w = *h.answer.holding;
        const std::vector<Vec2>& g = w.support.forces;
        // a support force scaled past its disc's radius (nonzero forces only), the others kept
        for (std::size_t i = 0; i < k; ++i) {
          if (is_zero(g[i])) continue;
          Hold_answer t = h.answer;
          const Rational rho = *s.support->points[i].mu * *s.support->points[i].force;
          const Rational f = rho * rho / dot(g[i], g[i]) + 1;  // f |g| = ρ²/|g| + |g| ≥ 2ρ > ρ: out of the disc
          t.holding->support.forces[i] = {g[i].x * f, g[i].y * f};
          bad.push_back(hold_certificate(t));
          break;
        }
        if (!w.combination.empty()) {
          Hold_answer t = h.answer;
          t.holding->combination[0].second *= Rational(3, 2);
          bad.push_back(hold_certificate(t));
        }
      } else {
        const Slide_witness& w = *h.answer.failing;
        Hold_answer t = h.answer;
        t.failing->speed_bounds[0] = 0;
        const Vec3q& q = w.twist;
        if (!is_zero(velocity(q, s.support->points[0].at))) bad.push_back(hold_certificate(t));
        Hold_answer neg = h.answer;  // the opposite motion pushes into some contact or is not driven by the load
        neg.failing->twist = {-q[0], -q[1], -q[2]};
        bad.push_back(hold_certificate(neg));
      }
      for (const std::string& c : bad) {
        EXPECT_FALSE(test::checker_accepts(text, c)) << c << "\n" << test::dump_failure(text, "hold_tamper");
        ++tampered;
      }
    }
  }
  EXPECT_GE(tampered, 30);
}

// ---------------------------------------------------------------------------------------------
// [HD-1] [RG-1] Hold over support regions. The square [-1, 1]² pressed uniformly with W = 1, μ = 1/2 (μW = 1/2; its
// largest pure moment μ ∫|r| p dA = (√2 + asinh 1)/6 ≈ 0.3826).
std::string square_scene(const std::string& contacts, const std::string& points, const std::string& load) {
  return R"({"wrenchkit": 1, )" + contacts + R"("support": {"mu": "1/2", "points": [)" + points +
         R"(], "regions": [{"outline": [[-1, -1], [1, -1], [1, 1], [-1, 1]], "pressure": "uniform", "force": 1}]}, "load": )" +
         load + "}";
}

TEST(HoldRegions, GoldenSquare) {
  const std::string pin = R"("contacts": [{"at": [-1, 0], "normal": [1, 0]}], )";
  struct Case {
    std::string scene;
    Hold_verdict verdict;
  };
  const std::vector<Case> cases = {
      // a pure force through the centre: held iff |f| ≤ μW = 1/2 (a translation's exact slide bound)
      {square_scene("", "", R"({"force": ["2/5", 0], "at": [0, 0]})"), Hold_verdict::holds},
      {square_scene("", "", R"({"force": ["3/5", 0], "at": [0, 0]})"), Hold_verdict::fails},
      // a pin at (-1, 0) pushing +x, the load (-1, 0) at height 1/4 (moment 1/4 < 0.3826 left to the support), at
      // height 1 (moment 1: the body turns)
      {square_scene(pin, "", R"({"force": [-1, 0], "at": [0, "1/4"]})"), Hold_verdict::holds},
      {square_scene(pin, "", R"({"force": [-1, 0], "at": [0, 1]})"), Hold_verdict::fails},
      // points and the region: a point (3, 0) carrying 1 (μW = 1 in all; friction centroid (3/2, 0))
      {square_scene("", R"({"at": [3, 0], "force": 1})", R"({"force": ["-4/5", 0], "at": [0, 0]})"), Hold_verdict::holds},
      {square_scene("", R"({"at": [3, 0], "force": 1})", R"({"force": ["-6/5", 0], "at": [0, 0]})"), Hold_verdict::fails},
  };
  for (const Case& c : cases)
    for (const Mode mode : {Mode::hybrid, Mode::exact}) {
      const Hold_item h = hold_of(c.scene, mode);
      ASSERT_EQ(h.status, Status::answered) << h.message << "\n" << c.scene;
      EXPECT_EQ(h.answer.verdict, c.verdict) << mode_name(mode) << " " << c.scene << "\n" << h.answer.undecided_why;
      EXPECT_NE(h.certificate.find("\"regions\""), std::string::npos);
      EXPECT_GT(h.answer.cells, 0u);
      EXPECT_TRUE(test::checker_accepts(c.scene, h.certificate)) << c.scene;
    }
}

// An independent oracle: the region sampled as a 6 × 6 grid of point masses at the cells' centres (a quadrature
// of its friction, O(h²) off), decided by the discrete hold; loads scaled 0.85 and 1.15 about a random direction:
// where the grid holds the larger load, the region holds the load; where the grid fails the smaller, it fails.
TEST(HoldRegions, AgainstAFineGridOfPoints) {
  std::mt19937_64 rng(test::seed(20261126));
  std::uniform_real_distribution<double> dir(-1, 1);
  const std::string grid_pts = [] {
    std::string s;
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        s += std::string(s.empty() ? "" : ", ") + R"({"at": [")" + std::to_string(2 * i - 5) + "/6\", \"" +
             std::to_string(2 * j - 5) + R"(/6"], "force": "1/36"})";
    return s;
  }();
  const auto at_scale = [](double fx, double fy, double m, double k) {
    return "{\"wrench\": [" + num(fx * k) + ", " + num(fy * k) + ", " + num(m * k) + "]}";
  };
  int decided = 0, compared = 0;
  for (int n = 0; n < 16; ++n) {
    const double fx = dir(rng) * 0.5, fy = dir(rng) * 0.5, m = dir(rng) * 0.4;
    const std::string contacts =
        n % 2 ? R"("contacts": [{"at": [-1, 0], "normal": [1, 0]}], )" : std::string();
    const std::string text = square_scene(contacts, "", at_scale(fx, fy, m, 1));
    const Hold_item h = hold_of(text, Mode::hybrid);
    ASSERT_EQ(h.status, Status::answered) << h.message << test::dump_failure(text, "hold_region_grid");
    if (h.answer.verdict == Hold_verdict::undecided) continue;
    ++decided;
    ASSERT_TRUE(test::checker_accepts(text, h.certificate)) << test::dump_failure(text, "hold_region_grid");
    const auto grid = [&](double k) {
      return hold_of(R"({"wrenchkit": 1, )" + contacts + R"("support": {"mu": "1/2", "points": [)" + grid_pts +
                         R"(]}, "load": )" + at_scale(fx, fy, m, k) + "}",
                     Mode::hybrid).answer.verdict;
    };
    if (grid(1.15) == Hold_verdict::holds) {
      ++compared;
      EXPECT_EQ(h.answer.verdict, Hold_verdict::holds) << test::dump_failure(text, "hold_region_grid");
    } else if (grid(0.85) == Hold_verdict::fails) {
      ++compared;
      EXPECT_EQ(h.answer.verdict, Hold_verdict::fails) << test::dump_failure(text, "hold_region_grid");
    }
  }
  EXPECT_GE(decided, 12);
  EXPECT_GE(compared, 8);
}

// [HD-2] Regions together with points whose force is not given. The mat [-1/2, 1/2]² (uniform, force 1) and three legs
// (-2, 0), (0, 0), (2, 0) without forces, W = 5 at the centre, μ = 1/2: the legs carry 4 with their centre at the
// origin, so F's vertices are (0, 4, 0) and (2, 0, 2). By hand: a pure force through the centre is held by every
// distribution iff |f| ≤ μW = 5/2 (every vertex is symmetric about the origin); a pure moment m is resisted by
// (2, 0, 2) up to μ(2·2 + 2·2) + the mat's μ ∫|r| p = 4 + (√2 + asinh 1)/12 ≈ 4.1913, by (0, 4, 0) only by the mat
// (the middle leg does not move): ≈ 0.1913. So m = 9/50 holds for every distribution, m = 1/5 and m = 1 depend.
std::string mat_and_legs(const std::string& contacts, const std::string& load) {
  return R"({"wrenchkit": 1, )" + contacts + R"("support": {"mu": "1/2", "weight": 5, "pressure_center": [0, 0],
      "points": [{"at": [-2, 0]}, {"at": [0, 0]}, {"at": [2, 0]}], "regions": [{"outline": [["-1/2", "-1/2"],
      ["1/2", "-1/2"], ["1/2", "1/2"], ["-1/2", "1/2"]], "pressure": "uniform", "force": 1}]}, "load": )" + load + "}";
}

TEST(HoldRegions, UnknownForcesGolden) {
  struct Case {
    std::string load;
    Hold_verdict verdict;
  };
  const std::vector<Case> cases = {
      {R"({"wrench": ["9/4", 0, 0]})", Hold_verdict::holds},   // 9/4 < 5/2: the mat's cells carry 1/4 of it
      {R"({"wrench": [3, 0, 0]})", Hold_verdict::fails},       // 3 > 5/2: the translation (1, 0, 0), dual (1/2, 0, 0)
      {R"({"wrench": [0, 0, 1]})", Hold_verdict::depends},     // the barbell holds, the middle leg does not
      {R"({"wrench": [0, 0, "9/50"]})", Hold_verdict::holds},  // below the mat's 0.1913: refined cells hold it
      {R"({"wrench": [0, 0, "1/5"]})", Hold_verdict::depends},  // above it: the mat's slide block proves the motion
  };
  for (const Case& c : cases)
    for (const Mode mode : {Mode::hybrid, Mode::exact}) {
      const std::string scene = mat_and_legs("", c.load);
      const Hold_item h = hold_of(scene, mode);
      ASSERT_EQ(h.status, Status::answered) << h.message << "\n" << scene;
      EXPECT_EQ(h.answer.verdict, c.verdict) << mode_name(mode) << " " << c.load << "\n" << h.answer.undecided_why;
      EXPECT_TRUE(h.answer.unknown);
      ASSERT_EQ(h.answer.extreme.size(), 2u);
      EXPECT_EQ(h.certificate.rfind(R"({"wrenchkit_certificate": 3, "property": "hold")", 0), 0u) << h.certificate;
      EXPECT_NE(h.certificate.find("\"regions\""), std::string::npos);
      EXPECT_TRUE(test::checker_accepts(scene, h.certificate)) << scene;
      if (c.verdict == Hold_verdict::depends) {
        EXPECT_EQ(h.answer.holding->support.distribution, (std::vector<Rational>{2, 0, 2}));
        EXPECT_EQ(h.answer.failing->distribution, (std::vector<Rational>{0, 4, 0}));
      }
      if (c.verdict == Hold_verdict::fails) {
        EXPECT_TRUE(h.answer.failing->dual.has_value());
        EXPECT_FALSE(h.answer.failing->regions.empty());
      }
      // Format 1 has no certificate for it; a witness without its regions' blocks proves nothing.
      std::string v1 = h.certificate;
      v1.replace(v1.find(": 3,"), 4, ": 1,");
      EXPECT_NE(wrenchkit_checker::check(scene, v1).message.find("no certificate in format 1"), std::string::npos);
      if (c.verdict != Hold_verdict::fails) {
        const std::string stripped = hold_certificate([&] {
          Hold_answer a = h.answer;
          if (a.holding) a.holding->support.regions.clear();
          for (Hold_witness& v : a.vertices) v.support.regions.clear();
          return a;
        }());
        EXPECT_NE(wrenchkit_checker::check(scene, stripped).message.find("missing required key \"regions\""), std::string::npos);
      }
    }
  // With a pin at (-3, 0) pushing +x: the push (-3, 0) through the centre is taken by the pin under every distribution.
  const std::string pinned = mat_and_legs(R"("contacts": [{"at": [-3, 0], "normal": [1, 0]}], )", R"({"wrench": [-3, 0, 0]})");
  const Hold_item p = hold_of(pinned, Mode::hybrid);
  ASSERT_EQ(p.status, Status::answered) << p.message;
  EXPECT_EQ(p.answer.verdict, Hold_verdict::holds);
  EXPECT_TRUE(test::checker_accepts(pinned, p.certificate));
  // float mode: undecided with the reason
  const Hold_item fl = hold_of(mat_and_legs("", R"({"wrench": ["1/10", 0, 0]})"), Mode::float_only);
  EXPECT_EQ(fl.status, Status::undecided);
  EXPECT_NE(fl.message.find("the float twin has no"), std::string::npos) << fl.message;
}

// The same oracle as above with four legs whose forces are not given (W − 1 = 2 on them, their centre a random
// rational point of the outer three's triangle): the grid's verdict over F at 1.15 and 0.85 times the load bounds the region's —
// some distribution holds the load where the grid holds the larger load under one, some fails it where the grid
// fails the smaller under one.
TEST(HoldRegions, UnknownForcesAgainstAFineGridOfPoints) {
  std::mt19937_64 rng(test::seed(20261127));
  std::uniform_real_distribution<double> dir(-1, 1);
  std::uniform_int_distribution<int> weight(1, 3);
  const std::string legs = R"({"at": [-2, -1]}, {"at": [2, -1]}, {"at": [0, 2]}, {"at": [0, 0]})";
  std::string grid_pts;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      grid_pts += R"(, {"at": [")" + std::to_string(2 * i - 5) + "/6\", \"" + std::to_string(2 * j - 5) +
                  R"(/6"], "force": "1/36"})";
  const auto scene = [&](const std::string& contacts, const std::string& c, bool grid, const std::string& load) {
    return R"({"wrenchkit": 1, )" + contacts + R"("support": {"mu": "1/2", "weight": 3, "pressure_center": )" + c +
           R"(, "points": [)" + legs + (grid ? grid_pts : "") + "]" +
           (grid ? "" : R"(, "regions": [{"outline": [[-1, -1], [1, -1], [1, 1], [-1, 1]], "pressure": "uniform", "force": 1}])") +
           R"(}, "load": )" + load + "}";
  };
  const auto at_scale = [](double fx, double fy, double m, double k) {
    return "{\"wrench\": [" + num(fx * k) + ", " + num(fy * k) + ", " + num(m * k) + "]}";
  };
  const auto some = [](Hold_verdict v, Hold_verdict w) { return v == w || v == Hold_verdict::depends; };
  int decided = 0, compared = 0;
  for (int n = 0; n < 16; ++n) {
    const int a = weight(rng), b = weight(rng), d = weight(rng);
    // c = (2/3) c', c' = (a (-2, -1) + b (2, -1) + d (0, 2)) / (a + b + d): the legs' centre, inside their triangle,
    // which holds the fourth leg (0, 0): F a segment from the outer legs alone to a vertex with the inner one
    const Rational cx(2 * (2 * b - 2 * a), 3 * (a + b + d)), cy(2 * (2 * d - a - b), 3 * (a + b + d));
    const std::string c = "[\"" + to_string(cx) + "\", \"" + to_string(cy) + "\"]";
    const double fx = dir(rng), fy = dir(rng), m = dir(rng) * 3;
    const std::string contacts = n % 2 ? R"("contacts": [{"at": [-3, 0], "normal": [1, 0]}], )" : std::string();
    const std::string text = scene(contacts, c, false, at_scale(fx, fy, m, 1));
    const Hold_item h = hold_of(text, Mode::hybrid);
    ASSERT_EQ(h.status, Status::answered) << h.message << test::dump_failure(text, "hold_region_unknown_grid");
    if (h.answer.verdict == Hold_verdict::undecided) continue;
    ++decided;
    ASSERT_TRUE(test::checker_accepts(text, h.certificate)) << test::dump_failure(text, "hold_region_unknown_grid");
    const Hold_verdict hi = hold_of(scene(contacts, c, true, at_scale(fx, fy, m, 1.15)), Mode::hybrid).answer.verdict;
    const Hold_verdict lo = hold_of(scene(contacts, c, true, at_scale(fx, fy, m, 0.85)), Mode::hybrid).answer.verdict;
    if (some(hi, Hold_verdict::holds)) {
      ++compared;
      EXPECT_TRUE(some(h.answer.verdict, Hold_verdict::holds)) << test::dump_failure(text, "hold_region_unknown_grid");
    }
    if (some(lo, Hold_verdict::fails)) {
      ++compared;
      EXPECT_TRUE(some(h.answer.verdict, Hold_verdict::fails)) << test::dump_failure(text, "hold_region_unknown_grid");
    }
  }
  EXPECT_GE(decided, 10);
  EXPECT_GE(compared, 8);
}

// Beyond the 32 cells of the hold's exact decision: the square's largest pure moment is (√2 + asinh 1)/6 ≈ 0.382598.
// With no contact, hold is the stick/slide decision over the regions (decide_on_regions: the regions' exact power
// and its brackets), which holds 0.379 and 0.3825 in both modes, like limit-surface --load; past the true value the
// load moves. The mat and legs likewise: the middle leg alone leaves the mat's ≈ 0.19130.
TEST(HoldRegions, FinerCellsForTheWitness) {
  for (const char* m : {"0.379", "0.3825"})
    for (const Mode mode : {Mode::hybrid, Mode::exact}) {
      const std::string scene = square_scene("", "", std::string(R"({"wrench": [0, 0, ")") + m + "\"]}");
      const Hold_item h = hold_of(scene, mode);
      ASSERT_EQ(h.status, Status::answered) << h.message;
      EXPECT_EQ(h.answer.verdict, Hold_verdict::holds) << m << " " << h.answer.undecided_why;
      EXPECT_GT(h.answer.cells, kMaxHoldRegionCells) << m;
      EXPECT_TRUE(test::checker_accepts(scene, h.certificate));
    }
  const std::string past = square_scene("", "", R"({"wrench": [0, 0, "0.3827"]})");
  const Hold_item p = hold_of(past, Mode::hybrid);
  EXPECT_NE(p.answer.verdict, Hold_verdict::holds);
  if (p.answer.verdict == Hold_verdict::fails) {
    EXPECT_TRUE(test::checker_accepts(past, p.certificate));
  }
  const std::string legs = mat_and_legs("", R"({"wrench": [0, 0, "0.1905"]})");
  const Hold_item l = hold_of(legs, Mode::hybrid);
  ASSERT_EQ(l.status, Status::answered) << l.message;
  EXPECT_EQ(l.answer.verdict, Hold_verdict::holds) << l.answer.undecided_why;
  EXPECT_GT(l.answer.cells, kMaxHoldRegionCells);
  EXPECT_TRUE(test::checker_accepts(legs, l.certificate));
}

// Bad input: no load; too many unknown forces is an Input_error of decide_hold; float mode with an unknown
// distribution is undecided (no LP over F in the twin).
// Float mode, no support, generators summing to the zero wrench (±e1, ±e2, ±e3): the push toward the interior along
// their sum has nothing to push with — any δ serves (fuzz_structured found 0/0 here, a zero load). Holds with margin,
// certified, for a zero load and for another.
TEST(HoldInput, FloatModeWithGeneratorsSummingToZero) {
  for (const char* load : {"[0, 0, 0]", "[1, -2, 3]"}) {
    const std::string scene = std::string(R"({"wrenchkit": 1, "contacts": [{"wrench": [1, 0, 0]}, {"wrench": [-1, 0, 0]},
      {"wrench": [0, 1, 0]}, {"wrench": [0, -1, 0]}, {"wrench": [0, 0, 1]}, {"wrench": [0, 0, -1]}], "load": {"wrench": )") +
                              load + "}}";
    const Hold_item h = hold_of(scene, Mode::float_only);
    ASSERT_EQ(h.status, Status::answered) << h.message;
    EXPECT_EQ(h.answer.verdict, Hold_verdict::holds) << load;
  }
}

TEST(HoldInput, NoLoadAndFloatOverF) {
  const Hold_item none = hold_of(R"({"wrenchkit": 1, "contacts": [{"at": [0, 0], "normal": [0, 1]}]})", Mode::hybrid);
  EXPECT_EQ(none.status, Status::bad_input);
  EXPECT_EQ(none.message, "load: the scene has no load (hold needs one)");
  const std::string table = R"({"wrenchkit": 1, "support": {"mu": 1, "weight": 1, "pressure_center": [0, 0], "points":
      [{"at": [1, 1]}, {"at": [-1, 1]}, {"at": [-1, -1]}, {"at": [1, -1]}]}, "load": {"wrench": ["0.5", 0, 0]}})";
  const Hold_item fl = hold_of(table, Mode::float_only);
  EXPECT_EQ(fl.status, Status::undecided);
  EXPECT_NE(fl.message.find("no LP over the admissible distributions"), std::string::npos) << fl.message;
}

// Past the threshold over regions, with contacts (issue 29): a fixed-seed family of a region (rectangle, L or
// triangle; uniform or linear pressure), 0–2 points and 1–2 contacts that allow a motion t (each contact's normal
// along its point's velocity under t), loaded with w_L = (1 + ε)·∂h(t), the true limit surface's load of t (the
// regions' certified load box, its midpoint): t·w_L = (1 + ε) h(t), so the body moves. At ε = 1 % and 0.1 % every
// scene fails, each failing motion certified by the independent checker (before the search on the regions' true
// power: 58 of 60 and 41 of 60).
TEST(HoldRegions, PastTheThresholdWithContacts) {
  std::mt19937_64 rng(test::seed(2911));
  std::uniform_real_distribution<double> u(0, 1);
  // three decimals, exactly: the value and its JSON text
  const auto q3 = [](double v) {
    Rational q(static_cast<long>(std::llround(v * 1000)), 1000);
    q.canonicalize();
    return q;
  };
  const auto dec = [&](double v) { return "\"" + to_string(q3(v)) + "\""; };
  const auto at = [&](double lo, double hi) { return lo + (hi - lo) * u(rng); };
  struct Case {
    std::string support, contacts;
    Vec3q twist;
  };
  std::vector<Case> family;
  const std::vector<std::vector<std::array<double, 2>>> shapes = {
      {{0, 0}, {2, 0}, {2, 1}, {0, 1}}, {{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 2}, {0, 2}}, {{0, 0}, {2, 0}, {1, 2}}};
  for (int n = 0; n < 60; ++n) {
    const double ox = at(-1.5, 0), oy = at(-1.5, 0);
    std::string shifted = "[";
    for (const auto& v : shapes[static_cast<std::size_t>(n % 3)])
      shifted += std::string(shifted.size() > 1 ? ", " : "") + "[" + dec(v[0] + ox) + ", " + dec(v[1] + oy) + "]";
    shifted += "]";
    const std::string pressure = n % 2 ? R"("pressure": "uniform", "force": )" + dec(at(0.5, 2))
                                       : R"("pressure": {"linear": [1, )" + dec(at(-0.2, 0.2)) + ", " + dec(at(-0.2, 0.2)) + "]}";
    std::string points;
    for (int i = 0; i < n % 3; ++i)
      points += std::string(i ? ", " : "") + R"({"at": [)" + dec(at(-2, 2)) + ", " + dec(at(-2, 2)) + R"(], "force": )" +
                dec(at(0.1, 1)) + "}";
    const std::string support = R"("support": {"mu": )" + dec(at(0.2, 0.8)) + R"(, "regions": [{"outline": )" + shifted +
                                ", " + pressure + "}]" + (points.empty() ? "" : R"(, "points": [)" + points + "]") + "}";
    double t[3];
    if (n % 5) {
      const double cx = at(-3, 3), cy = at(-3, 3), w = n % 2 ? 1 : -1;
      t[0] = w * cy, t[1] = -w * cx, t[2] = w;
    } else {
      const double a = at(0, 6.283185307179586);
      t[0] = std::cos(a), t[1] = std::sin(a), t[2] = 0;
    }
    Vec3q tq;
    for (int i = 0; i < 3; ++i) tq[static_cast<std::size_t>(i)] = q3(t[i]);
    std::string contacts;
    for (int i = 0; i < 1 + n % 2; ++i) {
      const double a = at(0, 6.283185307179586), px = 2.5 * std::cos(a), py = 2.5 * std::sin(a);
      const double vx = tq[0].get_d() - tq[2].get_d() * q3(py).get_d(), vy = tq[1].get_d() + tq[2].get_d() * q3(px).get_d(),
                   l = std::hypot(vx, vy);
      if (l < 1e-2) continue;
      // a normal within 10^-3 of the velocity, rounded so that the contact still allows t exactly (checked below)
      contacts += std::string(contacts.empty() ? "" : ", ") + R"({"at": [)" + dec(px) + ", " + dec(py) + R"(], "normal": [)" +
                  dec(vx / l) + ", " + dec(vy / l) + R"(], "mu": )" + dec(at(0, 0.3)) + "}";
    }
    family.push_back({support, contacts, tq});
  }
  for (const double eps : {1e-2, 1e-3}) {
    int fails = 0, scenes = 0;
    for (const Case& c : family) {
      const Scene s = read_scene(R"({"wrenchkit": 1, )" + c.support + "}", kLimits);
      const Region_sliding rs = region_sliding(*s.support, c.twist, Rational(1, 1000000000));
      std::string load = "[";
      for (std::size_t i = 0; i < 3; ++i) {
        char b[40];
        std::snprintf(b, sizeof b, "%.15g", (1 + eps) * Rational((rs.load_lo[i] + rs.load_hi[i]) / 2).get_d());
        load += std::string(i ? ", " : "") + "\"" + b + "\"";
      }
      load += "]";
      const std::string text = R"({"wrenchkit": 1, "contacts": [)" + c.contacts + "], " + c.support +
                               R"(, "load": {"wrench": )" + load + "}}";
      const Scene full = read_scene(text, kLimits);
      bool allowed = true;  // the rounded contacts still allow t (else the case proves nothing: skipped)
      for (const Generator& g : generators(full, Reading::friction)) allowed = allowed && dot(c.twist, g.w) >= 0;
      if (!allowed) continue;
      ++scenes;
      const Hold_item h = hold_of(text, Mode::hybrid);
      ASSERT_EQ(h.status, Status::answered) << h.message;
      EXPECT_EQ(h.answer.verdict, Hold_verdict::fails) << eps << " " << h.answer.undecided_why << "\n"
                                                       << test::dump_failure(text, "hold_past_threshold");
      if (h.answer.verdict == Hold_verdict::fails) {
        ++fails;
        EXPECT_TRUE(test::checker_accepts(text, h.certificate));
      }
    }
    EXPECT_GE(scenes, 40) << eps;
    EXPECT_EQ(fails, scenes) << eps;
  }
}

}  // namespace
}  // namespace wrenchkit
