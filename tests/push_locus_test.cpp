// [PU-4] Where a pushed body may turn about (exact/sliding/push_locus.h, proofs/notes/PU-4-rotation-centres.md): the
// locus worked by hand, its certificate tampered with, and against the engine's own motion (PU-2) on random known
// distributions: every rotation centre the contact mode finds lies in the piece of its sense and mode.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>
#include <string>

#include "exact/pipeline/push_answer.h"
#include "exact/sliding/pushing.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {

// The square [-1, 1]² on four legs of force 1, μ 1/2 (c = 0, R² = 2), pushed at (1/2, −1) with μ 1 along v.
std::string square(const std::string& velocity, const std::string& forces = "1") {
  return R"({"wrenchkit": 1, "body": {"outline": [[-1, -1], [1, -1], [1, 1], [-1, 1]]}, "support": {"mu": "1/2",
    "points": [{"at": [-1, -1], "force": )" + forces + R"(}, {"at": [1, -1], "force": )" + forces + R"(},
    {"at": [1, 1], "force": )" + forces + R"(}, {"at": [-1, 1], "force": )" + forces + R"(}]},
    "pusher": {"at": ["1/2", -1], "normal": [0, 1], "mu": 1, "velocity": )" + velocity + "}}";
}

Push_item locus_of(const std::string& text, bool contact = false) {
  Push_query q;
  q.locus = true;
  q.contact = contact;
  return answer_push(text, "test", Request{}, q);
}

bool holds(const Locus_piece& piece, double x, double y, double slack) {
  for (const Locus_halfplane& h : piece.halfplanes)
    if (h.h.a.x.get_d() * x + h.h.a.y.get_d() * y > h.h.b.get_d() + slack) return false;
  return true;
}

// By hand (PU-4 §6): e₊ = (−1, 1), e₋ = (1, 1), a = c − p = (−1/2, 1). The bisector (1, −2)·q ≤ 5/4, the contact
// advancing (ccw) q.x ≤ 1/2, the sticking line q.x + q.y = −1/2, the legs' extents min x·e₊ = −2, max x·e₋ = 2, the tip
// line −q.x/2 + q.y ≤ T. On the sticking line the bisector stops at (1/12, −7/12) and the tip line at
// q.x = −(2/3)(T + 1/2); the left and right facets (q.x ≤ 3/4, and 2 ≥ −1/2) do not cut. The votes say ccw (the edges
// apart, v passes c on its left): no cw piece. The uniform legs' own sticking centre (PU-2) is on that segment.
TEST(PushLocus, TheSquareWorkedByHand) {
  const Push_item r = locus_of(square("[1, 1]"), true);
  ASSERT_EQ(r.status, Status::answered) << r.message;
  ASSERT_TRUE(r.push.locus && r.push.locus->T);
  const Push_locus& g = *r.push.locus;
  EXPECT_EQ(r.push.rotation, Rotation::ccw);
  EXPECT_FALSE(g.side[1].possible);
  ASSERT_TRUE(g.side[0].possible);
  const Locus_piece& stick = g.side[0].pieces[0];
  EXPECT_TRUE(stick.bounded);
  ASSERT_EQ(stick.polygon.size(), 2u);
  const Rational T = *g.T, x0 = Rational(-2, 3) * (T + Rational(1, 2));
  EXPECT_EQ(stick.polygon[0].x, x0);
  EXPECT_EQ(stick.polygon[0].y, Rational(-1, 2) - x0);
  EXPECT_EQ(stick.polygon[1].x, Rational(1, 12));
  EXPECT_EQ(stick.polygon[1].y, Rational(-7, 12));
  EXPECT_GT(T, 2);
  EXPECT_LT(T, Rational(29100, 10000));  // R² + E at the fixed point: 2.9099…
  // the sticking centre of the uniform legs: p + rot90(v)/ω
  ASSERT_TRUE(r.push.contact);
  EXPECT_EQ(r.push.contact->mode, Push_mode::sticks);
  const Vec2 q = rotation_centre(r.push.at, r.push.velocity, r.push.contact->omega_lo);
  EXPECT_TRUE(holds(stick, q.x.get_d(), q.y.get_d(), 1e-9));
  // the arm: the farthest vertex from the normal line x = 1/2 over the three pieces
  ASSERT_TRUE(g.arm_hi);
  Rational H = 0;
  for (const Locus_piece& piece : g.side[0].pieces)
    for (const Vec2& v : piece.polygon) H = std::max(H, Rational(Rational(1, 2) - v.x));
  EXPECT_GE(*g.arm_hi, H);
  EXPECT_LT(*g.arm_hi, H + Rational(1, 100000));
  EXPECT_FALSE(r.certificate.empty());
  // the other side (PU-4 §5): the legs' own rate puts their centre at least arm_lo from the normal line — just below
  // its true distance 1/2 − q.x = 1.86549…
  ASSERT_TRUE(r.push.slowest);
  EXPECT_EQ(r.push.slowest->contact.mode, Push_mode::sticks);
  const Rational arm = Rational(1, 2) - q.x;
  EXPECT_LE(r.push.slowest->arm_lo, arm);
  EXPECT_GT(r.push.slowest->arm_lo, arm - Rational(1, 100000));
  EXPECT_LE(r.push.slowest->arm_lo, *g.arm_hi);

  // pushed straight at the centre of friction (v = (−1/2, 1) through c): the sticking motion translates; the votes
  // say "none" (an edge and the velocity through c? no: the velocity alone through c, the edges apart) — no piece
  const Push_item t = locus_of(square("[\"-1/2\", 1]"));
  ASSERT_EQ(t.status, Status::answered) << t.message;
  EXPECT_EQ(t.push.rotation, Rotation::none);
  EXPECT_FALSE(t.push.locus->side[0].possible);
  EXPECT_FALSE(t.push.locus->side[1].possible);
  EXPECT_FALSE(t.push.locus->arm_hi);
}

TEST(PushLocus, WhatItDoesNotAnswer) {
  // a line pusher: its rotation centres are its stable region
  const Push_item l = locus_of(R"({"wrenchkit": 1, "body": {"outline": [[-1, -1], [1, -1], [1, 1], [-1, 1]]},
    "support": {"mu": "1/2", "points": [{"at": [-1, -1], "force": 1}, {"at": [1, 1], "force": 1}]},
    "pusher": {"segment": [[0, -1], [1, -1]], "normal": [0, 1], "mu": 1, "velocity": [0, 1]}})");
  EXPECT_EQ(l.status, Status::bad_input);
  EXPECT_NE(l.message.find("--locus"), std::string::npos) << l.message;
  // the centre of friction moves with the distribution: no locus, and why
  const Push_item m = locus_of(R"({"wrenchkit": 1, "body": {"outline": [[-1, -1], [1, -1], [1, 1], [-1, 1]]},
    "support": {"weight": 4, "pressure_center": [0, 0], "points": [{"at": [-1, 0], "mu": 1}, {"at": [1, 0], "mu": "1/10"},
    {"at": [0, 1], "mu": "1/2"}, {"at": [0, -1], "mu": "1/2"}]},
    "pusher": {"at": ["-1/10", -1], "normal": [0, 1], "velocity": [0, 1]}})");
  ASSERT_EQ(m.status, Status::answered) << m.message;
  ASSERT_TRUE(m.push.locus);
  EXPECT_FALSE(m.push.locus->friction_centre);
  EXPECT_NE(m.push.locus->why.find("moves with the distribution"), std::string::npos);
}

TEST(PushLocus, TamperedCertificatesAreRefused) {
  const std::string s = square("[1, 1]");
  const std::string c = locus_of(s).certificate;
  ASSERT_TRUE(test::checker_accepts(s, c));
  const auto refused = [&](const std::string& from, const std::string& to, const std::string& reason) {
    EXPECT_TRUE(test::checker_refuses_edit(s, c, from, to, reason));
  };
  refused(R"(["1/2", "5/2"])", R"(["1/2", "2"])", "of the centres' bound is outside it");
  refused(R"("arm_hi": "1886641/500000")", R"("arm_hi": "3")", "is below a possible centre's distance");
  refused(R"("T": "2909923/1000000")", R"("T": "2")", "locus.T:");
  refused(R"("R_hi": "707107/500000")", R"("R_hi": "1")", "locus.R_hi: not an upper bound");
  refused(R"("alpha_hi": "559017/500000")", R"("alpha_hi": "1")", "locus.alpha_hi: not an upper bound");
  refused(R"("cw": null)", R"("cw": null, "ccw": null)", "duplicate");
  refused(R"("mode": "sticks")", R"("mode": "slides left")", "expected \"sticks\"");
  refused(R"("alpha_hi": "559017/500000", "T": "2909923/1000000", )", "", "claimed bounded, but its half-planes recede");
  refused(R"("arm_lo": "186549/100000")", R"("arm_lo": "2")", "locus.arm_lo: 2 is more than v.n / (|omega| |n|)");
  refused(R"("slowest": {"forces": ["1", "1", "1", "1"])", R"("slowest": {"forces": ["2", "0", "1", "1"])",
          "locus.slowest.forces: not the given forces");
}

// Against the engine's own motion (PU-2) on random known distributions (fixed seed): legs on a grid with random
// forces, a pusher on the bottom edge with a random coefficient and velocity. Wherever the contact mode is decided
// with its motion, the centre (midpoints of the certified brackets, in doubles) satisfies every half-plane of the
// piece of its sense and mode (slack 1e-7), is within the arm of the normal line, and the certificate is accepted.
TEST(PushLocus, ContainsTheMotionOfEveryKnownDistribution) {
  std::mt19937_64 rng(20261130);
  std::uniform_int_distribution<int> coord(-4, 4), force(1, 5), count(3, 7), at(-39, 39), vel(-3, 3);
  int checked[3] = {0, 0, 0}, translating = 0, with_arm_lo = 0;
  for (int sc = 0; sc < 400; ++sc) {
    const std::uint64_t seed = rng();
    std::mt19937_64 r(seed);
    const int k = count(r);
    std::ostringstream t;
    t << R"({"wrenchkit": 1, "body": {"outline": [[-5, -5], [5, -5], [5, 5], [-5, 5]]}, "support": {"mu": "1/2", "points": [)";
    for (int i = 0; i < k; ++i) t << (i ? ", " : "") << R"({"at": [)" << coord(r) << ", " << coord(r) << R"(], "force": )" << force(r) << "}";
    const int mu = static_cast<int>(r() % 5);  // μ in {0, 1/4, …, 1}
    t << R"(]}, "pusher": {"at": [")" << at(r) << R"(/8", -5], "normal": [0, 1], "mu": ")" << mu << R"(/4", "velocity": [)"
      << vel(r) << ", " << 1 + static_cast<int>(r() % 3) << "]}}";
    const std::string text = t.str();
    const Push_item res = locus_of(text, true);
    ASSERT_EQ(res.status, Status::answered) << "seed " << seed << "\n" << res.message << "\n" << text;
    ASSERT_TRUE(res.push.locus && res.push.contact) << "seed " << seed;
    if (res.push.rotation != Rotation::undecided) {
      ASSERT_FALSE(res.certificate.empty()) << "seed " << seed << "\n" << test::dump_failure(text, "push_locus");
    }
    const Push_locus& g = *res.push.locus;
    const Push_contact& c = *res.push.contact;
    const Vec2 p = res.push.at, v = res.push.velocity, n = res.push.normal;
    std::optional<std::array<double, 2>> q;
    int sense = 0, mode = -1;
    const auto centre = [&](const Vec2& u, const Rational& lo, const Rational& hi) {
      if (sgn(lo) != sgn(hi) || sgn(lo) == 0) return;
      const Vec2 x = rotation_centre(p, u, (lo + hi) / 2);
      q = std::array<double, 2>{x.x.get_d(), x.y.get_d()};
      sense = sgn(lo);
    };
    const Support& sup = *res.scene.support;
    if (c.mode == Push_mode::sticks) {
      mode = 0;
      if (c.pivot) {
        q = std::array<double, 2>{sup.points[*c.pivot].at.x.get_d(), sup.points[*c.pivot].at.y.get_d()};
        sense = sgn(c.omega_lo);
      } else if (c.omega_lo == 0 && c.omega_hi == 0) {
        ++translating;  // a translation: no centre, and the sticking piece must run off (no arm)
        EXPECT_FALSE(g.arm_hi) << "seed " << seed << ": translates, but the locus claims an arm\n" << text;
        continue;
      } else {
        centre(v, c.omega_lo, c.omega_hi);
      }
    } else if ((c.mode == Push_mode::slides_left || c.mode == Push_mode::slides_right) && c.has_motion) {
      mode = c.mode == Push_mode::slides_left ? 1 : 2;
      const Rational tau = (c.slip_lo + c.slip_hi) / 2;
      if (c.motion_pivot) {
        q = std::array<double, 2>{sup.points[*c.motion_pivot].at.x.get_d(), sup.points[*c.motion_pivot].at.y.get_d()};
        sense = sgn(c.motion_lo);
      } else if (c.motion_lo == 0 && c.motion_hi == 0) {
        ++translating;
        EXPECT_FALSE(g.arm_hi) << "seed " << seed << ": translates, but the locus claims an arm\n" << text;
        continue;
      } else {
        centre({v.x - tau * n.y, v.y + tau * n.x}, c.motion_lo, c.motion_hi);
      }
    }
    if (!q || sense == 0) continue;
    const int side = sense > 0 ? 0 : 1;
    ASSERT_TRUE(g.side[side].possible) << "seed " << seed << ": turns " << (sense > 0 ? "ccw" : "cw")
                                       << " but the locus excludes that sense\n" << test::dump_failure(text, "push_locus");
    const double scale = 1e-7 * (1 + std::abs((*q)[0]) + std::abs((*q)[1])) * 64;
    ASSERT_TRUE(holds(g.side[side].pieces[mode], (*q)[0], (*q)[1], scale))
        << "seed " << seed << ": the centre (" << (*q)[0] << ", " << (*q)[1] << ") of mode " << mode
        << " is outside its piece\n" << test::dump_failure(text, "push_locus");
    const double arm = std::abs((p.x.get_d() - (*q)[0]) * n.y.get_d() - (p.y.get_d() - (*q)[1]) * n.x.get_d()) /
                       std::hypot(n.x.get_d(), n.y.get_d());
    if (g.arm_hi) {
      ASSERT_LE(arm, g.arm_hi->get_d() + scale) << "seed " << seed << "\n" << test::dump_failure(text, "push_locus");
    }
    if (res.push.slowest) {  // (the one distribution: arm_lo is a bound of its own centre's distance)
      ASSERT_LE(res.push.slowest->arm_lo.get_d(), arm + scale) << "seed " << seed << "\n" << test::dump_failure(text, "push_locus");
      ++with_arm_lo;
    }
    ++checked[mode];
  }
  // the oracle is not vacuous: every mode met
  EXPECT_GT(checked[0], 50);
  EXPECT_GT(checked[1] + checked[2], 50);
  EXPECT_GT(with_arm_lo, 100);
  std::printf("centres inside their pieces: %d sticking, %d sliding left, %d sliding right; %d translations\n", checked[0],
              checked[1], checked[2], translating);
}

// [PU-2 over F] Forces not given: the contact mode at F's extreme distributions; two that differ prove "depends". The
// square with a fifth leg at (0, 1/2), W = 4 at the origin, pushed at (1/2, −1) with μ 1/4 along y: under the
// diagonal legs (2, 0, 2, 0, 0) the contact slides left, under (0, 2, 0, 2, 0) it sticks — each confirmed by
// `push --contact` on the scene with those forces given; the certificate's witnesses tampered with are refused.
// Then 200 random supports of 4–6 legs with forces not given (fixed seed): every "depends" has witnesses in F whose
// known scenes' own contact modes are the claimed ones, and differ.
TEST(PushContactOverF, DependsWithTwoCertifiedDistributions) {
  const auto with_forces = [](const std::vector<std::string>& f) {
    std::string legs;
    const char* at[5] = {"[-1, -1]", "[1, -1]", "[1, 1]", "[-1, 1]", "[0, \"1/2\"]"};
    for (int i = 0; i < 5; ++i) legs += std::string(i ? ", " : "") + "{\"at\": " + at[i] + (f.empty() ? "" : ", \"force\": " + f[i]) + "}";
    return R"({"wrenchkit": 1, "body": {"outline": [[-1, -1], [1, -1], [1, 1], [-1, 1]]}, "support": {"mu": "1/2", )" +
           std::string(f.empty() ? R"("weight": 4, "pressure_center": [0, 0], )" : "") + R"("points": [)" + legs +
           R"(]}, "pusher": {"at": ["1/2", -1], "normal": [0, 1], "mu": "1/4", "velocity": [0, 1]}})";
  };
  Push_query q;
  q.contact = true;
  const std::string scene = with_forces({});
  const Push_item r = answer_push(scene, "test", Request{}, q);
  ASSERT_EQ(r.status, Status::answered) << r.message;
  ASSERT_TRUE(r.push.contact);
  const Push_contact& c = *r.push.contact;
  ASSERT_EQ(c.mode, Push_mode::depends) << c.why;
  ASSERT_EQ(c.witnesses.size(), 2u);
  for (const Push_contact& w : c.witnesses) {
    std::vector<std::string> f;
    for (const Rational& x : w.forces) f.push_back("\"" + x.get_str() + "\"");
    const Push_item k = answer_push(with_forces(f), "test", Request{}, q);
    ASSERT_EQ(k.status, Status::answered) << k.message;
    EXPECT_EQ(k.push.contact->mode, w.mode);
  }
  EXPECT_EQ(c.witnesses[0].mode, Push_mode::slides_left);
  EXPECT_EQ(c.witnesses[1].mode, Push_mode::sticks);
  ASSERT_FALSE(r.certificate.empty());
  EXPECT_TRUE(test::checker_accepts(scene, r.certificate));
  EXPECT_TRUE(test::checker_refuses_edit(scene, r.certificate, R"("forces": ["2", "0", "2", "0", "0"])",
                                         R"("forces": ["1", "0", "2", "0", "0"])", "the forces sum to 3, not the weight 4"));
  EXPECT_TRUE(test::checker_refuses_edit(scene, r.certificate, R"("mode": "depends")", R"("mode": "sticks")",
                                         "a contact needs \"mode\", \"bits\" and \"omega\""));
  EXPECT_TRUE(test::checker_refuses_edit(scene, r.certificate, R"("mode": "slides left")", R"("mode": "sticks")",
                                         "contact.witnesses: \"depends\" needs two distributions whose contact modes differ"));

  std::mt19937_64 rng(20261130);
  std::uniform_int_distribution<int> coord(-3, 3), count(4, 6), at(-19, 19), vel(-2, 2);
  int depends = 0;
  for (int sc = 0; sc < 200; ++sc) {
    const std::uint64_t seed = rng();
    std::mt19937_64 g(seed);
    const int k = count(g);
    std::vector<std::array<int, 2>> legs;
    for (int i = 0; i < k; ++i) legs.push_back({coord(g), coord(g)});
    const int mu = 1 + static_cast<int>(g() % 4), vx = vel(g), px = at(g);
    const auto text = [&](const std::vector<std::string>& f) {
      std::ostringstream t;
      t << R"({"wrenchkit": 1, "body": {"outline": [[-5, -5], [5, -5], [5, 5], [-5, 5]]}, "support": {"mu": "1/2", )";
      if (f.empty()) t << R"("weight": 1, "pressure_center": [")" << legs[0][0] + legs[1][0] << R"(/2", ")"
                       << legs[0][1] + legs[1][1] << R"(/2"], )";
      t << R"("points": [)";
      for (int i = 0; i < k; ++i)
        t << (i ? ", " : "") << R"({"at": [)" << legs[i][0] << ", " << legs[i][1] << "]" << (f.empty() ? "" : ", \"force\": " + f[i]) << "}";
      t << R"(]}, "pusher": {"at": [")" << px << R"(/4", -5], "normal": [0, 1], "mu": ")" << mu << R"(/4", "velocity": [)"
        << vx << ", 1]}}";
      return t.str();
    };
    const std::string unknown = text({});
    const Push_item res = answer_push(unknown, "test", Request{}, q);
    if (res.status != Status::answered) continue;  // (e.g. the two legs coincide: F empty is refused by the reader)
    if (!res.push.contact || res.push.contact->mode != Push_mode::depends) continue;
    ++depends;
    ASSERT_FALSE(res.certificate.empty()) << "seed " << seed;
    for (const Push_contact& w : res.push.contact->witnesses) {
      std::vector<std::string> f;
      for (const Rational& x : w.forces) f.push_back("\"" + x.get_str() + "\"");
      const Push_item kn = answer_push(text(f), "test", Request{}, q);
      ASSERT_EQ(kn.status, Status::answered) << "seed " << seed << ": " << kn.message;
      ASSERT_EQ(kn.push.contact->mode, w.mode) << "seed " << seed << "\n" << test::dump_failure(unknown, "contact_depends");
    }
  }
  EXPECT_GT(depends, 5);  // not vacuous (12 with this seed)
  std::printf("depends over F: %d of 200 random supports\n", depends);
}

}  // namespace
}  // namespace wrenchkit
