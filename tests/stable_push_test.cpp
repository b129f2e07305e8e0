// [PU-3] Stable pushing with a line contact (exact/sliding/stable_push.h, proofs/notes/PU-3-stable-pushing.md):
// golden cases worked by hand, tampered certificates refused, and the verdicts against brute force over every
// distribution of a finite support with the centre of friction (the LP's basic solutions: one, two or three points).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "exact/io/scene.h"
#include "exact/pipeline/push_answer.h"
#include "exact/sliding/pushing.h"
#include "proofs/checker/checker.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {

// The square [-1, 1]² on four legs of force 1, μ 1/2 (centre of friction 0, R² = 2), pushed along its bottom edge
// from (-1/2, -1) to (1/2, -1): normal (0, 1), μ 1/2 — cone edges e₊ = (-1/2, 1), e₋ = (1/2, 1).
std::string fence(const std::string& motion, const std::string& mu = "1/2") {
  return R"({"wrenchkit": 1, "body": {"outline": [[-1, -1], [1, -1], [1, 1], [-1, 1]]}, "support": {"mu": "1/2",
    "points": [{"at": [-1, -1], "force": 1}, {"at": [1, -1], "force": 1}, {"at": [1, 1], "force": 1},
    {"at": [-1, 1], "force": 1}]}, "pusher": {"segment": [["-1/2", -1], ["1/2", -1]], "normal": [0, 1], "mu": ")" +
         mu + R"(", )" + motion + "}}";
}

Push_item push(const std::string& text) { return answer_push(text, "test", Request{}); }

const Stable_push& stable(const Push_item& r) {
  EXPECT_EQ(r.status, Status::answered) << r.message;
  EXPECT_TRUE(r.push.stable.has_value());
  return *r.push.stable;
}

// Translating (the load is v through c for every distribution): v = (0, 1) inside (v × e₊ = 1/2, e₋ × v = 1/2, and
// the line x = 0 crosses the segment); v = (1, 1) beyond the right edge (e₋ × v = 1/2 − 1 < 0); v = (1/2, 1) along
// the right edge and through the end (−1/2, −1): stable, on the boundary at both. Rotating about q = m + rot90(v)/ω:
// ω = 1/10 puts q at (−10, −1): left: q·e₊ = 4 ≥ max x·e₊ = 3/2 (the leg (−1, 1)); right: q·e₋ = −6 ≤ min x·e₋ =
// −3/2; |q − e0|² = 90.25 ≤ |q − c|² = 101 (the bisector); tip at e1: (c − e1)·(q − c) = 4 ≥ R² + E = 2 + 0.037.
// ω = −1/10 is its mirror about x = 0 (cw). ω = 1/2 puts q at (−2, −1): the legs (−1, 1) and (1, −1), weights 1 and
// 1 (mean 0), have left-edge terms (x − q)·e₊/|x − q| = 2/√5 and −1/2: the load is beyond the left edge.
TEST(StablePush, GoldenCasesWorkedByHand) {
  const Push_item t = push(fence(R"("velocity": [0, 1])"));
  EXPECT_EQ(stable(t).verdict, Stability::stable);
  EXPECT_EQ(t.push.rotation, Rotation::none);
  EXPECT_FALSE(t.certificate.empty());

  const Push_item u = push(fence(R"("velocity": [1, 1])"));
  EXPECT_EQ(stable(u).verdict, Stability::unstable);
  EXPECT_EQ(stable(u).facet, Cone_facet::right_edge);
  EXPECT_EQ(u.push.rotation, Rotation::undecided);
  EXPECT_FALSE(u.certificate.empty());

  const Push_item b = push(fence(R"("velocity": ["1/2", 1])"));
  EXPECT_EQ(stable(b).verdict, Stability::stable);
  EXPECT_EQ(stable(b).values[1], 0);  // right edge
  EXPECT_EQ(stable(b).values[2], 0);  // end 0
  EXPECT_GT(stable(b).values[0], 0);
  EXPECT_GT(stable(b).values[3], 0);

  const Push_item r = push(fence(R"("velocity": [0, 1], "omega": "1/10")"));
  EXPECT_EQ(stable(r).verdict, Stability::stable) << stable(r).why;
  EXPECT_EQ(r.push.rotation, Rotation::ccw);
  EXPECT_EQ(stable(r).centre->x, -10);
  EXPECT_EQ(stable(r).centre->y, -1);
  EXPECT_EQ(stable(r).R2, 2);
  EXPECT_EQ(stable(r).tip, 1u);

  const Push_item w = push(fence(R"("velocity": [0, 1], "omega": "-1/10")"));
  EXPECT_EQ(stable(w).verdict, Stability::stable) << stable(w).why;
  EXPECT_EQ(w.push.rotation, Rotation::cw);
  EXPECT_EQ(stable(w).tip, 0u);

  // ω = 1/6, q = (−6, −1): the tip line fails (d = √37 ≈ 6.08, (c − e1)·(q − c) = 2 < R² + E ≈ 2.11), but over the four
  // legs the LP's dual proves end 1's facet: no distribution with mean 0 puts the load's line past (1/2, −1).
  const Push_item y = push(fence(R"("velocity": [0, 1], "omega": "1/6")"));
  EXPECT_EQ(stable(y).verdict, Stability::stable) << stable(y).why;
  ASSERT_EQ(stable(y).duals.size(), 1u);
  EXPECT_EQ(stable(y).duals[0].first, Cone_facet::end1);
  EXPECT_LT(stable(y).duals[0].second[0], 0);

  const Push_item x = push(fence(R"("velocity": [0, 1], "omega": "1/2")"));
  EXPECT_EQ(stable(x).verdict, Stability::unstable) << stable(x).why;
  EXPECT_EQ(stable(x).facet, Cone_facet::left_edge);
  ASSERT_EQ(stable(x).points.size(), 2u);
  EXPECT_EQ(stable(x).points[0].x, -1);
  EXPECT_EQ(stable(x).points[0].y, 1);
  EXPECT_EQ(stable(x).points[1].x, 1);
  EXPECT_EQ(stable(x).points[1].y, -1);
  EXPECT_EQ(stable(x).weights, (std::vector<Rational>{1, 1}));
  EXPECT_FALSE(x.certificate.empty());
}

// Unstable, yet the rotation is certain: frictionless along (1/2, −1)–(1, −1), every force the pusher can apply is
// along (0, 1) through a point right of c — the four corners vote ccw ((e_k − c) × (0, 1) = 1/2 and 1) — so the body
// turns ccw (PU-1's first lemma), though the line x = 0 through c along v misses the segment (end 0's facet).
TEST(StablePush, UnstableButEveryForceTurnsItOneWay) {
  const std::string text = R"({"wrenchkit": 1, "body": {"outline": [[-1, -1], [1, -1], [1, 1], [-1, 1]]}, "support": {"mu": "1/2",
    "points": [{"at": [-1, -1], "force": 1}, {"at": [1, -1], "force": 1}, {"at": [1, 1], "force": 1},
    {"at": [-1, 1], "force": 1}]}, "pusher": {"segment": [["1/2", -1], [1, -1]], "normal": [0, 1], "mu": 0,
    "velocity": [0, 1]}})";
  const Push_item r = push(text);
  EXPECT_EQ(stable(r).verdict, Stability::unstable);
  EXPECT_EQ(stable(r).facet, Cone_facet::end0);
  EXPECT_EQ(stable(r).corners, 1);
  EXPECT_EQ(r.push.rotation, Rotation::ccw) << r.push.why;
  EXPECT_TRUE(test::checker_accepts(text, r.certificate));
  EXPECT_TRUE(test::checker_refuses_edit(text, r.certificate, R"("rotation": "ccw")", R"("rotation": "cw")",
                                         "an unstable push's rotation needs every force"));
}

TEST(StablePush, SceneErrorsNameTheField) {
  const auto error = [](const std::string& text) {
    const Push_item r = push(text);
    EXPECT_EQ(r.status, Status::bad_input) << text;
    return r.message;
  };
  EXPECT_NE(error(fence(R"("velocity": [0, -1])")).find("pusher.velocity"), std::string::npos);
  const std::string slanted = fence(R"("velocity": [0, 1])");
  std::string t = slanted;
  t.replace(t.find(R"("normal": [0, 1])"), 16, R"("normal": [1, 1])");
  EXPECT_NE(error(t).find("pusher.normal: (1, 1) is not perpendicular to the segment"), std::string::npos);
  t = slanted;
  t.replace(t.find(R"(["1/2", -1]])"), 12, R"(["-1/2", -1]])");
  EXPECT_NE(error(t).find("pusher.segment: its two ends are the same point"), std::string::npos);
  t = slanted;
  t.replace(t.find(R"(["1/2", -1]])"), 12, R"(["1/2", -2]])");
  EXPECT_NE(error(t).find("pusher.normal"), std::string::npos);  // (no longer perpendicular)
  EXPECT_NE(error(R"({"wrenchkit": 1, "support": {"mu": 1, "points": [{"at": [0, 0], "force": 1}]}, "pusher": {"at": [0, -1],
    "normal": [0, 1], "velocity": [0, 1], "omega": 1}})").find("pusher.omega"), std::string::npos);
  // --contact is a point pusher's
  Push_query q;
  q.contact = true;
  const Push_item c = answer_push(fence(R"("velocity": [0, 1])"), "test", Request{}, q);
  EXPECT_EQ(c.status, Status::bad_input);
  EXPECT_NE(c.message.find("--contact"), std::string::npos);
}

TEST(StablePush, TamperedCertificatesAreRefused) {
  const auto refused = [](const std::string& scene, const std::string& cert, const std::string& from,
                          const std::string& to, const std::string& reason) {
    EXPECT_TRUE(test::checker_refuses_edit(scene, cert, from, to, reason));
  };
  const std::string ts = fence(R"("velocity": [0, 1])"), us = fence(R"("velocity": [1, 1])");
  const std::string rs = fence(R"("velocity": [0, 1], "omega": "1/10")"), xs = fence(R"("velocity": [0, 1], "omega": "1/2")");
  const std::string ds = fence(R"("velocity": [0, 1], "omega": "1/6")");
  const std::string tc = push(ts).certificate, uc = push(us).certificate, rc = push(rs).certificate, xc = push(xs).certificate;
  const std::string dc = push(ds).certificate;
  for (const auto& [s, c] : {std::pair{ts, tc}, {us, uc}, {rs, rc}, {xs, xc}, {ds, dc}})
    EXPECT_TRUE(test::checker_accepts(s, c));
  refused(ts, tc, R"("R2": "2")", R"("R2": "3")", "stable.R2: 3 is not the largest squared distance 2");
  refused(ts, tc, R"("center": ["0", "0"])", R"("center": ["0", "1"])", "is not the centre of friction");
  refused(ts, tc, R"("rotation": "none")", R"("rotation": "ccw")", "a stable push turns with the pusher");
  refused(ts, tc, R"("verdict": "stable")", R"("verdict": "unstable", "facet": "left edge")", "an unstable push's rotation needs");
  refused(us, uc, R"("verdict": "unstable", "R2": "2", "facet": "right edge")",
          R"("verdict": "unstable", "R2": "2", "facet": "left edge")", "the load is not beyond the composite cone's left edge");
  refused(us, uc, R"("verdict": "unstable", "R2": "2", "facet": "right edge")", R"("verdict": "stable", "R2": "2")",
          "rotation:");
  refused(us, uc, R"("center")", R"("rotation": "none", "center")", "an unstable push's rotation needs");
  refused(rs, rc, R"("d_lo": "10049/1000")", R"("d_lo": "11")", "stable.d_lo: not a lower bound");
  refused(rs, rc, R"("R_hi": "283/200")", R"("R_hi": "1")", "stable.R_hi: not an upper bound");
  refused(rs, rc, R"("alpha_hi": "1119/1000")", R"("alpha_hi": "1")", "stable.alpha_hi: not an upper bound");
  refused(rs, rc, R"("d_lo": "10049/1000")", R"("d_lo": "1")", "not more than R_hi");
  refused(xs, xc, R"("weights": ["1", "1"])", R"("weights": ["1", "2"])", "its mean is not the centre of friction");
  refused(xs, xc, R"([["-1", "1"], ["1", "-1"]])", R"([["-1", "1"], ["1", "-1"], ["1", "1"]])", "one weight per point");
  refused(xs, xc, R"([["-1", "1"], ["1", "-1"]])", R"([["-2", "2"], ["2", "-2"]])", "is not a place of the support");
  refused(xs, xc, R"("facet": "left edge")", R"("facet": "right edge")", "not certainly beyond the composite cone's right edge");
  refused(xs, xc, R"("bits": 64)", R"("bits": 8)", "expected bits from 16 to 4096");
  refused(ds, dc, R"("-37483/1000000")", R"("1/1000000")", "stable.duals.end 1: y0 is not negative");
  refused(ds, dc, R"("-37483/1000000")", R"("-1")", "is not certainly below the dual's plane");
  refused(ds, dc, R"("duals": {"end 1")", R"("duals": {"end 0")", "stable.duals.end 0: the support point");
  refused(ds, dc, R"(, "bits": 64)", "", "\"duals\" come with their \"bits\"");
  // a point pusher's certificate has no "stable"; a line pusher's needs it
  refused(ts, tc, R"(, "stable": {"verdict": "stable", "R2": "2"})", "", "missing required key");
}

// [PU-3 §6] The stable region of the fence: ccw, the half-planes (1/2, −1)·q ≤ −3/2 (every leg behind the left edge's
// line: max x·e₊ = 3/2 at (−1, 1)), (1/2, 1)·q ≤ −3/2 (min x·e₋ = −3/2 at (−1, −1)), (1, 2)·q ≤ −5/4 (the bisector of
// end 0 and c: 2q·(c − e0) ≤ |c|² − |e0|²) and (1/2, −1)·q ≤ −T (end 1's tip line (c − e1)·q ≥ T); cw their mirror.
// Every rotation centre inside (the polygon's vertices' mean and the midpoints toward each vertex) is stable by the
// query too, and the certificate's tampered region is refused.
TEST(StablePush, TheRegionWorkedByHandAndItsCentresStable) {
  Push_query q;
  q.region = true;
  const std::string scene = fence(R"("velocity": [0, 1], "omega": "1/10")");
  const Push_item r = answer_push(scene, "test", Request{}, q);
  ASSERT_EQ(r.status, Status::answered) << r.message;
  ASSERT_TRUE(r.push.region);
  const Stable_region& g = *r.push.region;
  const Stable_region_side& ccw = g.side[0];
  ASSERT_TRUE(ccw.possible);
  EXPECT_EQ(ccw.halfplanes[0].a.x, Rational(1, 2));
  EXPECT_EQ(ccw.halfplanes[0].a.y, -1);
  EXPECT_EQ(ccw.halfplanes[0].b, Rational(-3, 2));
  EXPECT_EQ(ccw.halfplanes[1].a.y, 1);
  EXPECT_EQ(ccw.halfplanes[1].b, Rational(-3, 2));
  EXPECT_EQ(ccw.halfplanes[2].a.x, 1);
  EXPECT_EQ(ccw.halfplanes[2].a.y, 2);
  EXPECT_EQ(ccw.halfplanes[2].b, Rational(-5, 4));
  EXPECT_EQ(ccw.tip, 1u);
  EXPECT_EQ(ccw.halfplanes[3].b, -ccw.T);
  EXPECT_GT(ccw.T, Rational(29, 10));  // the fixed point T = 2 + E(T/√(5/4)) ≈ 2.9099
  EXPECT_LT(ccw.T, Rational(292, 100));
  ASSERT_TRUE(g.translations);
  EXPECT_EQ((*g.translations)[0].x, Rational(1, 2));  // the friction cone itself: its lines through c cross the segment
  EXPECT_EQ((*g.translations)[1].x, Rational(-1, 2));
  EXPECT_TRUE(test::checker_accepts(scene, r.certificate));
  EXPECT_TRUE(test::checker_refuses_edit(scene, r.certificate, R"("T": "2909923/1000000")", R"("T": "29/10")",
                                         "region.ccw.T: 29/10 is below R^2 + E(T/alpha_hi)"));
  EXPECT_TRUE(test::checker_refuses_edit(scene, r.certificate, R"("alpha_hi": "559017/500000")", R"("alpha_hi": "1")",
                                         "region.ccw.alpha_hi: not an upper bound"));
  EXPECT_TRUE(test::checker_refuses_edit(scene, r.certificate, R"("translations": [["1/2", "1"])",
                                         R"("translations": [["1", "1"])", "region.translations[0]: (1, 1) is not a stable"));
  EXPECT_TRUE(test::checker_refuses_edit(scene, r.certificate, R"("R_hi": "707107/500000")", R"("R_hi": "7/5")",
                                         "region.R_hi: not an upper bound of R"));
  // every centre inside either polygon is stable by the query (and so by brute force: the test below)
  int tried = 0;
  for (int k = 0; k < 2; ++k) {
    const std::vector<Vec2>& poly = g.side[k].polygon;
    ASSERT_GE(poly.size(), 3u);
    Vec2 mean{0, 0};
    for (const Vec2& v : poly) mean.x += v.x / poly.size(), mean.y += v.y / poly.size();
    std::vector<Vec2> inside = {mean};
    for (const Vec2& v : poly) inside.push_back({(mean.x + v.x) / 2, (mean.y + v.y) / 2});
    for (const Vec2& c : inside) {
      const Rational omega = k == 0 ? 1 : -1;  // v at the middle (0, −1): ω rot90(m − c)
      const Vec2 v{-omega * (-1 - c.y), omega * (0 - c.x)};
      if (v.y <= 0) continue;  // (it would not push into the body)
      std::ostringstream motion;
      motion << R"("velocity": [")" << v.x << R"(", ")" << v.y << R"("], "omega": ")" << omega << R"(")";
      const Push_item at = push(fence(motion.str()));
      ASSERT_EQ(at.status, Status::answered) << at.message;
      EXPECT_EQ(at.push.stable->verdict, Stability::stable) << c.x << ", " << c.y << ": " << at.push.stable->why;
      ++tried;
    }
  }
  EXPECT_GE(tried, 6);
  // a point pusher has no stable region
  const Push_item point = answer_push(R"({"wrenchkit": 1, "support": {"mu": 1, "points": [{"at": [0, 0], "force": 1}]},
      "pusher": {"at": [0, -1], "normal": [0, 1], "velocity": [0, 1]}})", "test", Request{}, q);
  EXPECT_EQ(point.status, Status::bad_input);
  EXPECT_NE(point.message.find("--region"), std::string::npos);
}

// On a region: the square's support is a uniform patch [-1, 1]² (R² = 2 at its corners); rotating about (-2, -1)
// the witness lies on the patch's boundary (its ring's edges).
TEST(StablePush, ARegionSupport) {
  const std::string region = R"({"wrenchkit": 1, "body": {"outline": [[-1, -1], [1, -1], [1, 1], [-1, 1]]},
    "support": {"mu": "1/2", "regions": [{"outline": [[-1, -1], [1, -1], [1, 1], [-1, 1]], "pressure": "uniform",
    "force": 4}]}, "pusher": {"segment": [["-1/2", -1], ["1/2", -1]], "normal": [0, 1], "mu": "1/2",
    "velocity": [0, 1], "omega": ")";
  const Push_item far = push(region + R"(1/10"}})");
  EXPECT_EQ(stable(far).verdict, Stability::stable) << stable(far).why;
  const Push_item near = push(region + R"(1/2"}})");
  EXPECT_EQ(stable(near).verdict, Stability::unstable) << stable(near).why;
  EXPECT_FALSE(near.certificate.empty());
}

// Random supports of 3–8 legs (integer places, forces and one μ) under the square [-5, 5]², pushed along a random
// piece of its bottom edge, translating or turning about a random centre (1000 pushes, fixed seed). Every verdict comes with an
// accepted certificate; a stable one is never contradicted by brute force over every distribution of the legs with
// the centre of friction (the LP's basic solutions: one leg at c, two with c between them, three around c), and an
// unstable one is confirmed by it. Where PU-3's distribution-free conditions fail (they are sufficient, not necessary),
// the LP over the legs decides: a witness, or its dual (counted). And every 4th scene's stable region (PU-3 §6): points
// inside its polygons are never contradicted by brute force.
TEST(StablePush, AgainstBruteForceOverEveryDistribution) {
  std::mt19937_64 rng(20261129);
  std::uniform_int_distribution<int> coord(-4, 4), force(1, 3), count(3, 8), end(-5, 5), small(-3, 3), wide(-40, 40);
  int verdicts[3] = {0, 0, 0}, turning_stable = 0, by_dual = 0, region_points = 0;
  for (int sc = 0; sc < 1000; ++sc) {
    const std::uint64_t seed = rng();
    std::mt19937_64 r(seed);
    const int k = count(r);
    std::vector<std::array<double, 2>> legs;
    std::ostringstream t;
    t << R"({"wrenchkit": 1, "body": {"outline": [[-5, -5], [5, -5], [5, 5], [-5, 5]]}, "support": {"mu": "1/2", "points": [)";
    double W = 0, cx = 0, cy = 0;
    for (int i = 0; i < k; ++i) {
      const int x = coord(r), y = coord(r), f = force(r);
      legs.push_back({double(x), double(y)});
      W += f, cx += f * x, cy += f * y;
      t << (i ? ", " : "") << R"({"at": [)" << x << ", " << y << R"(], "force": )" << f << "}";
    }
    cx /= W, cy /= W;
    int a = end(r), b = end(r);
    if (a == b) b = a == 5 ? 4 : a + 1;
    const int mu_num = 1 + static_cast<int>(r() % 4);  // μ in {1/4, 1/2, 3/4, 1}
    const int vx = r() % 2 ? 0 : small(r), omega_den = 1 + static_cast<int>(r() % 100);
    const int omega_num = static_cast<int>(r() % 3) - 1;  // 0 a translation in a third of the pushes
    t << R"(]}, "pusher": {"segment": [[)" << a << R"(, -5], [)" << b << R"(, -5]], "normal": [0, 1], "mu": ")" << mu_num
      << R"(/4", "velocity": [)" << vx << ", 1]";
    if (omega_num != 0) t << R"(, "omega": ")" << omega_num << "/" << omega_den << "\"";
    t << "}}";
    const std::string text = t.str();
    const Push_item res = push(text);
    ASSERT_EQ(res.status, Status::answered) << "seed " << seed << "\n" << res.message << "\n" << text;
    const Stable_push& st = *res.push.stable;
    verdicts[static_cast<int>(st.verdict)]++;
    turning_stable += st.verdict == Stability::stable && st.sense != 0;
    // a stable push turns with the pusher; when every force the pusher can apply passes c on one side, that side
    // (PU-1's first lemma) — the two must agree (a translation's load passes through c: no corner sign)
    if (st.verdict == Stability::stable && st.corners != 0) {
      ASSERT_EQ(st.corners, st.sense) << "seed " << seed << "\n" << test::dump_failure(text, "stable_push");
    }
    by_dual += st.verdict == Stability::stable && !st.duals.empty();
    if (st.verdict != Stability::undecided) {
      ASSERT_FALSE(res.certificate.empty()) << "seed " << seed << "\n" << test::dump_failure(text, "stable_push");
    }
    // Brute force in doubles: the largest value of each facet's sum over every basic distribution.
    const double mu = mu_num / 4.0, m0 = (a + b) / 2.0, w = double(omega_num) / omega_den;
    const double eL[2] = {-mu, 1}, eR[2] = {mu, 1};
    const double e[2][2] = {{double(a), -5}, {double(b), -5}};
    const int s0 = b > a ? 1 : -1, s_end[2] = {s0, -s0};
    const int sigma = omega_num > 0 ? 1 : omega_num < 0 ? -1 : 0;
    const double qx = m0 - 1.0 / w, qy = -5 + vx / w;  // q = m + rot90(v)/ω, v = (vx, 1)
    // the largest value over every basic distribution of the facets' sums for the rotation about (qx, qy), sense sg
    const auto worst_about = [&](double qx, double qy, int sg) {
      double worst = -1e300;
      const auto load = [&](const std::vector<std::pair<int, double>>& dist) {  // max over facets of Σ w h/ℓ (scaled)
        if (sg == 0) return -1e300;
        double v[4] = {0, 0, 0, 0}, total = 0;
        for (const auto& [i, wt] : dist) {
          const double dx = legs[i][0] - qx, dy = legs[i][1] - qy, l = std::hypot(dx, dy);
          if (l == 0) return -1e300;
          v[0] += wt * sg * (dx * eL[0] + dy * eL[1]) / l;
          v[1] += -wt * sg * (dx * eR[0] + dy * eR[1]) / l;
          for (int j = 0; j < 2; ++j)
            v[2 + j] += -wt * s_end[j] * sg * ((legs[i][0] - e[j][0]) * dx + (legs[i][1] - e[j][1]) * dy) / l;
          total += wt;
        }
        return *std::max_element(v, v + 4) / total;
      };
      for (int i = 0; i < k; ++i) {
        const double ax = legs[i][0] - cx, ay = legs[i][1] - cy;
        if (std::abs(ax) + std::abs(ay) < 1e-12) worst = std::max(worst, load({{i, 1.0}}));
        for (int j = i + 1; j < k; ++j) {
          const double bx = legs[j][0] - cx, by = legs[j][1] - cy;
          if (std::abs(ax * by - ay * bx) < 1e-12 && ax * bx + ay * by < 0)
            worst = std::max(worst, load({{i, std::hypot(bx, by)}, {j, std::hypot(ax, ay)}}));
          for (int l = j + 1; l < k; ++l) {
            const double dx = legs[l][0] - cx, dy = legs[l][1] - cy;
            const double la = bx * dy - by * dx, lb = dx * ay - dy * ax, lc = ax * by - ay * bx;
            if ((la > 1e-12 && lb > 1e-12 && lc > 1e-12) || (la < -1e-12 && lb < -1e-12 && lc < -1e-12))
              worst = std::max(worst, load({{i, std::abs(la)}, {j, std::abs(lb)}, {l, std::abs(lc)}}));
          }
        }
      }
      return worst;
    };
    const double worst = worst_about(qx, qy, sigma);
    // [PU-3 §6] the stable region, every 4th push: its polygons' vertex means and the midpoints toward each vertex
    if (sc % 4 == 0) {
      const Scene scene = read_scene(text, Input_limits{});
      const Stable_region g = stable_region(Support_model(scene), *scene.pusher);
      for (int side = 0; side < 2; ++side) {
        const std::vector<Vec2>& poly = g.side[side].polygon;
        if (poly.empty()) continue;
        double mx = 0, my = 0;
        for (const Vec2& v : poly) mx += v.x.get_d() / poly.size(), my += v.y.get_d() / poly.size();
        for (std::size_t t = 0; t <= poly.size(); ++t) {
          const double px = t == 0 ? mx : (mx + poly[t - 1].x.get_d()) / 2, py = t == 0 ? my : (my + poly[t - 1].y.get_d()) / 2;
          ASSERT_LE(worst_about(px, py, side == 0 ? 1 : -1), 1e-9)
              << "seed " << seed << ": (" << px << ", " << py << ") is in the stable region, but a distribution leaves "
              << "the cone\n" << test::dump_failure(text, "stable_push");
          ++region_points;
        }
      }
    }
    if (st.verdict == Stability::stable && sigma != 0) {
      ASSERT_LE(worst, 1e-9) << "seed " << seed << ": stable, but a distribution leaves the cone\n"
                             << test::dump_failure(text, "stable_push");
    }
    if (st.verdict == Stability::unstable && sigma != 0) {
      ASSERT_GT(worst, 0) << "seed " << seed << ": unstable, but brute force finds no distribution leaving the cone\n"
                          << test::dump_failure(text, "stable_push");
    }
  }
  std::printf("stable %d (turning %d, by a dual %d), unstable %d, undecided %d of 1000; %d centres of stable regions\n",
              verdicts[0], turning_stable, by_dual, verdicts[1], verdicts[2], region_points);
  EXPECT_GT(region_points, 200);
  EXPECT_GT(turning_stable, 100);
  EXPECT_GT(by_dual, 10);
  EXPECT_LT(verdicts[2], 5);  // (the load exactly on the cone's boundary)
  EXPECT_GT(verdicts[1], 0);
}

}  // namespace
}  // namespace wrenchkit
