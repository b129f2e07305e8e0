// [GR-1] Two-finger force-closure regions: golden cases worked by hand (the square's opposite sides with μ = 1/2:
// 1/2 < s + t < 3/2, area 3/4; adjacent sides: empty up to μ = 1 — the boundary itself — and a triangle above it);
// the theorem's own statement on random polygons: every sampled placement, on a grid and 10⁻ᵏ beside each corner, is
// inside the region exactly when the engine's closure decision of the two contacts says closed (an independent
// oracle: the dual-cone decision, not Nguyen's test), and Nguyen's criterion written here from angles' signs agrees;
// the independent checker accepts every answer and refuses a moved corner.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <string>

#include "exact/certificates/certificates.h"
#include "exact/io/input_error.h"
#include "exact/io/outline.h"
#include "exact/io/scene.h"
#include "exact/statics/closure.h"
#include "exact/statics/grasp_regions.h"
#include "float/grasp_twin.h"
#include "proofs/checker/checker.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {

std::string part(const std::string& outline) { return R"({"wrenchkit": 1, "body": {"outline": )" + outline + "}}"; }
Scene scene_of(const std::string& text) { return read_scene(text, Input_limits{}); }
const char* kSquare = "[[0, 0], [1, 0], [1, 1], [0, 1]]";

// Is (s, t) strictly inside the convex counter-clockwise polygon?
bool strictly_inside(const std::vector<std::array<Rational, 2>>& P, const Rational& s, const Rational& t) {
  if (P.empty()) return false;
  for (std::size_t k = 0; k < P.size(); ++k) {
    const auto &a = P[k], &b = P[(k + 1) % P.size()];
    if (sgn((b[0] - a[0]) * (t - a[1]) - (b[1] - a[1]) * (s - a[0])) <= 0) return false;
  }
  return true;
}

TEST(GraspRegionsGolden, SquareOppositeSides) {
  const Grasp_regions g = two_finger_regions(scene_of(part(kSquare)), Rational(1, 2));
  ASSERT_EQ(g.pairs.size(), 6u);
  EXPECT_EQ(g.closed_pairs(), 2u);
  for (const Pair_region& p : g.pairs) {
    const bool opposite = (p.i == 0 && p.j == 2) || (p.i == 1 && p.j == 3);
    EXPECT_EQ(!p.polygon.empty(), opposite) << p.i << " " << p.j;
    if (!opposite) continue;
    // bottom finger at x = s, top at x = 1 − t: |1 − s − t| < 1/2
    EXPECT_EQ(p.area, Rational(3, 4));
    EXPECT_EQ(p.polygon.size(), 6u);
    EXPECT_TRUE(closed_at(p, Rational(1, 2), Rational(1, 2)));
    EXPECT_FALSE(closed_at(p, Rational(1, 4), Rational(1, 4)));  // s + t = 1/2 exactly: on the cone's edge
    EXPECT_TRUE(closed_at(p, Rational(1, 4), Rational(1, 4) + Rational(1, 1000000000)));
  }
  EXPECT_EQ(two_finger_regions(scene_of(part(kSquare)), 0).closed_pairs(), 0u);  // frictionless: never
}

TEST(GraspRegionsGolden, AdjacentSidesNeedMoreThanOne) {
  // fingers at (s, 0) and (1, t): the segment (1 − s, t) must be within 45°·(μ = 1) of both normals: t > 1 − s and
  // t < 1 − s — exactly on the boundary at μ = 1, so empty; with μ = 2 a region
  for (const auto& [mu, closed] : {std::pair<Rational, bool>{1, false}, {2, true}}) {
    const Grasp_regions g = two_finger_regions(scene_of(part(kSquare)), mu, {0, 1});
    ASSERT_EQ(g.pairs.size(), 1u);
    EXPECT_EQ(!g.pairs[0].polygon.empty(), closed) << to_string(mu);
  }
  EXPECT_THROW(two_finger_regions(scene_of(part(kSquare)), 1, {0, 4}), Input_error);
  EXPECT_THROW(two_finger_regions(scene_of(R"({"wrenchkit": 1})"), 1), Input_error);
}

// The placements of a pair as a scene of two placed contacts with μ (the engine's own closure decides it).
std::string two_fingers(const std::string& outline, std::size_t i, const Rational& s, std::size_t j, const Rational& t,
                        const Rational& mu) {
  return R"({"wrenchkit": 1, "mu": ")" + to_string(mu) + R"(", "body": {"outline": )" + outline +
         R"(}, "contacts": [{"edge": )" + std::to_string(i) + R"(, "s": ")" + to_string(s) + R"("}, {"edge": )" +
         std::to_string(j) + R"(, "s": ")" + to_string(t) + R"("}]})";
}

// Nguyen written here from its statement: d = p_j − p_i strictly inside cone i and −d strictly inside cone j, a cone
// {n + x·rot90 n : |x| < μ} — d·n > 0 and |cross(n, d)| < μ (d·n), with n each edge's inward normal.
bool nguyen(const std::vector<Vec2>& V, std::size_t i, const Rational& s, std::size_t j, const Rational& t,
            const Rational& mu) {
  const int o = outline_orientation(V);
  const Vec2 pi = edge_point(V, i, s), pj = edge_point(V, j, t), d{pj.x - pi.x, pj.y - pi.y};
  const auto inside = [&](const Vec2& n, const Vec2& v) {
    const Rational along = dot(n, v), side = cross(n, v);
    return sgn(along) > 0 && abs(side) < mu * along;
  };
  return inside(edge_inward_normal(V, i, o), d) && inside(edge_inward_normal(V, j, o), Vec2{-d.x, -d.y});
}

TEST(GraspRegionsOracle, RegionsAgreeWithClosureAndNguyen) {
  const char* outlines[] = {"[[0, 0], [4, 0], [0, 3]]", "[[0, 0], [6, 0], [6, 2], [2, 2], [2, 5], [0, 5]]",
                            "[[0, 0], [3, 0], [5, 2], [4, 5], [1, 4]]", "[[0, 0], [0, 4], [4, 4], [4, 0]]"};
  const Rational mus[] = {Rational(1, 4), Rational(1, 2), Rational(1), Rational(3, 2)};
  std::mt19937_64 rng(test::seed(20261129));
  int inside = 0, outside = 0, near_in = 0, near_out = 0;
  for (const char* o : outlines)
    for (const Rational& mu : mus) {
      const Scene sc = scene_of(part(o));
      const Grasp_regions g = two_finger_regions(sc, mu);
      const auto rejected = wrenchkit_checker::check(part(o), grasp_regions_certificate(g), wrenchkit_checker::Limits{});
      ASSERT_EQ(rejected.outcome, wrenchkit_checker::Outcome::accepted) << rejected.message;
      for (const Pair_region& p : g.pairs) {
        std::vector<std::pair<Rational, Rational>> samples;
        for (int k = 0; k < 6; ++k) samples.push_back({Rational(1 + rng() % 15) / 16, Rational(1 + rng() % 15) / 16});
        for (const auto& c : p.polygon)  // beside each corner, 10^-9 toward and away from the centre
          for (const int dir : {1, -1}) {
            const Rational e(dir, 1000000000);
            samples.push_back({c[0] + e * (Rational(1, 2) - c[0]), c[1] + e * (Rational(1, 2) - c[1])});
          }
        for (std::size_t k = 0; k < samples.size(); ++k) {
          const auto& [s, t] = samples[k];
          if (s < 0 || s > 1 || t < 0 || t > 1) continue;
          const bool in = strictly_inside(p.polygon, s, t);
          const std::string text = two_fingers(o, p.i, s, p.j, t, mu);
          const bool closed = decide_closure(scene_of(text), Property::force_closure, Mode::exact, false).holds;
          ASSERT_EQ(in, closed) << test::dump_failure(text, "grasp_regions");
          ASSERT_EQ(closed_at(p, s, t), closed) << test::dump_failure(text, "grasp_regions");
          ASSERT_EQ(nguyen(sc.body.outline, p.i, s, p.j, t, mu), closed) << test::dump_failure(text, "grasp_regions");
          (in ? inside : outside) += 1;
          if (k >= 6) (in ? near_in : near_out) += 1;  // (beside a corner)
        }
        // the independent box: its corners and centre close (the engine's closure decision), and no axis-aligned
        // square of a side 1/1000 larger than its supremum fits the region (its four corners cannot all be inside)
        ASSERT_EQ(p.box.has_value(), !p.polygon.empty());
        if (!p.box) continue;
        const auto& b = *p.box;
        for (const Rational& s : {b[0][0], b[0][1], Rational((b[0][0] + b[0][1]) / 2)})
          for (const Rational& t : {b[1][0], b[1][1], Rational((b[1][0] + b[1][1]) / 2)}) {
            const std::string text = two_fingers(o, p.i, s, p.j, t, mu);
            ASSERT_TRUE(decide_closure(scene_of(text), Property::force_closure, Mode::exact, false).holds)
                << test::dump_failure(text, "grasp_regions_box");
          }
        const Rational big = p.side * Rational(1001, 1000);
        for (int a = 0; a <= 40; ++a)
          for (int c = 0; c <= 40; ++c) {
            const Rational s0 = Rational(a) / 40 * (1 - big), t0 = Rational(c) / 40 * (1 - big);
            if (big > 1) break;
            bool all = true;
            for (const Rational& s : {s0, Rational(s0 + big)})
              for (const Rational& t : {t0, Rational(t0 + big)}) all = all && closed_at(p, s, t);
            ASSERT_FALSE(all) << "a square of side " << to_string(big) << " fits at " << to_string(s0) << ", " << to_string(t0);
          }
      }
    }
  EXPECT_GT(inside, 50);
  EXPECT_GT(outside, 200);
  EXPECT_GT(near_in, 20);  // the samples beside the corners fall on both sides of the regions' boundaries
  EXPECT_GT(near_out, 20);
}

TEST(GraspRegionsChecker, RefusesAMovedCornerAMissingPairAndAClaimedEmptyRegion) {
  const Grasp_regions g = two_finger_regions(scene_of(part(kSquare)), Rational(1, 2));
  const std::string good = grasp_regions_certificate(g);
  const auto check = [&](std::string cert) {
    return wrenchkit_checker::check(part(kSquare), cert, wrenchkit_checker::Limits{}).message;
  };
  EXPECT_EQ(check(good), "accepted");
  std::string moved = good;
  moved.replace(moved.find("[\"1/2\", \"0\"]"), 12, "[\"1/3\", \"0\"]");
  EXPECT_NE(check(moved).find("pairs[1].closed: not the force-closure region of edges 0 and 2"), std::string::npos);
  std::string missing = good;
  missing.erase(missing.find("{\"edges\": [0, 1]"), std::string("{\"edges\": [0, 1], \"closed\": []}, ").size());
  EXPECT_NE(check(missing).find("pairs[0]: expected edges [0, 1]"), std::string::npos) << check(missing);
  std::string empty = good;
  const std::size_t a = empty.find("[[[\"1/2\""), b = empty.find("]]]", a) + 3;
  empty.replace(a, b - a, "[]");
  EXPECT_NE(check(empty).find("not the force-closure region"), std::string::npos);
  std::string big_box = good;
  const std::size_t at = big_box.find("\"independent\": [[");
  ASSERT_NE(at, std::string::npos);
  big_box.replace(at, big_box.find("]]", at) + 2 - at, "\"independent\": [[\"0\", \"1/2\"], [\"1/2\", \"1\"]]");
  EXPECT_NE(check(big_box).find(".independent: the corner (0, 1/2) does not close the grasp"), std::string::npos) << check(big_box);
  std::string wrong_mu = good;
  wrong_mu.replace(wrong_mu.find("\"mu\": \"1/2\""), 11, "\"mu\": \"1/3\"");
  EXPECT_NE(check(wrong_mu).find("not the force-closure region"), std::string::npos);
}

// The float twin of Nguyen's test (float/grasp_twin.h) against the exact regions, beside every corner at 10⁻ᵏ
// (k = 3 … 17) and on a grid: certified closed or open always right, uncertain only within 10⁻⁹ of a cone's line.
TEST(GraspRegionsTwin, NeverWrongAndUncertainOnlyBesideTheBoundary) {
  const char* outlines[] = {"[[0, 0], [4, 0], [0, 3]]", "[[0, 0], [6, 0], [6, 2], [2, 2], [2, 5], [0, 5]]",
                            "[[0, 0], [3, 0], [5, 2], [4, 5], [1, 4]]", kSquare};
  std::size_t certain = 0, uncertain = 0;
  for (const char* o : outlines)
    for (const Rational& mu : {Rational(1, 3), Rational(1, 2), Rational(1)}) {
      const Scene sc = scene_of(part(o));
      const std::vector<Vec2>& V = sc.body.outline;
      const int orient = outline_orientation(V);
      const Grasp_regions g = two_finger_regions(sc, mu);
      for (const Pair_region& p : g.pairs) {
        std::vector<std::pair<std::array<Rational, 2>, int>> at;  // (s, t) and its k (0: a grid point)
        for (int a = 0; a <= 8; ++a)
          for (int b = 0; b <= 8; ++b) at.push_back({{Rational(a) / 8, Rational(b) / 8}, 0});
        for (const auto& c : p.polygon)
          for (int k = 3; k <= 17; k += 2)
            for (const int dir : {1, -1}) {
              Integer ten;
              mpz_ui_pow_ui(ten.get_mpz_t(), 10, static_cast<unsigned long>(k));
              const Rational e = Rational(dir) / Rational(ten);
              at.push_back({{c[0] + e * (Rational(1, 2) - c[0]), c[1] + e * (Rational(1, 2) - c[1])}, k});
            }
        for (const auto& [st, k] : at) {
          if (st[0] < 0 || st[0] > 1 || st[1] < 0 || st[1] > 1) continue;
          const Vec2 pi = edge_point(V, p.i, st[0]), pj = edge_point(V, p.j, st[1]);
          const Vec2 ni = edge_inward_normal(V, p.i, orient), nj = edge_inward_normal(V, p.j, orient);
          const Sign v = fl::nguyen_twin({to_bounded(pi.x), to_bounded(pi.y), to_bounded(ni.x), to_bounded(ni.y)},
                                         {to_bounded(pj.x), to_bounded(pj.y), to_bounded(nj.x), to_bounded(nj.y)},
                                         to_bounded(mu));
          if (v == Sign::uncertain) {  // only within 10⁻⁹ (relative) of a cone's line: the boundary or beside it
            ++uncertain;
            bool near = false;
            for (const Region_constraint& h : p.cones)
              near = near || abs(Rational(h.a * st[0] + h.b * st[1] + h.c)) <=
                                 Rational(1, 1000000000) * (abs(h.a) + abs(h.b) + abs(h.c));
            EXPECT_TRUE(near) << "uncertain 1e-" << k << " beside a corner of " << o << " at " << to_string(st[0]) << ", "
                              << to_string(st[1]);
            continue;
          }
          ++certain;
          ASSERT_EQ(v == Sign::positive, closed_at(p, st[0], st[1]))
              << o << " mu " << to_string(mu) << " edges " << p.i << ", " << p.j << " at " << to_string(st[0]) << ", " << to_string(st[1]);
        }
      }
    }
  EXPECT_GT(certain, 5000u);
  EXPECT_GT(uncertain, 10u);  // the 10⁻¹⁵ … 10⁻¹⁷ placements, and grid points exactly on a side
}

// ---- [GR-2] three fingers ------------------------------------------------------------------------------------------

std::string three_fingers(const std::string& outline, const std::array<std::size_t, 3>& e, const std::array<Rational, 3>& s,
                          const Rational& mu) {
  std::string c;
  for (int f = 0; f < 3; ++f)
    c += std::string(f ? ", " : "") + R"({"edge": )" + std::to_string(e[f]) + R"(, "s": ")" + to_string(s[f]) + R"("})";
  return R"({"wrenchkit": 1, "mu": ")" + to_string(mu) + R"(", "body": {"outline": )" + outline + R"(}, "contacts": [)" +
         c + "]}";
}

bool closes(const std::string& text) {
  return decide_closure(scene_of(text), Property::force_closure, Mode::exact, false).holds;
}

const char* kL = "[[0, 0], [6, 0], [6, 2], [2, 2], [2, 5], [0, 5]]";

TEST(GraspRegionsThreeGolden, LPartsRightTopAndInnerEdgesCloseOnlyAboveMuOne) {
  // edges 1 (x = 6, pushing −x), 2 (y = 2, pushing −y) and 3 (x = 2, pushing −x): the cones' edges (−1, ±μ) and
  // (±μ, −1) all have u·f ≤ 0 for u = (1, 1) while μ ≤ 1 — at μ = 1 exactly two of them lie on that line, the
  // boundary — so no placement closes; just above 1 they positively span the plane, and a cube of placements closes.
  for (const Rational& mu : {Rational(1, 2), Rational(1)}) {
    const Grasp_regions g = three_finger_regions(scene_of(part(kL)), mu, {1, 2, 3});
    ASSERT_EQ(g.triples.size(), 1u);
    const Triple_region& t = g.triples[0];
    ASSERT_TRUE(t.never && t.never_direction) << to_string(mu);
    const auto& u = *t.never_direction;
    EXPECT_EQ(sgn(u[2]), 0);
    EXPECT_EQ(u[1], u[0] / mu) << "(μ, 1) up to a positive factor";
    EXPECT_GT(u[0], 0);
  }
  const Rational above = 1 + Rational(1, 1000000000);
  const Grasp_regions g = three_finger_regions(scene_of(part(kL)), above, {1, 2, 3});
  const Triple_region& t = g.triples[0];
  ASSERT_TRUE(t.box);
  EXPECT_FALSE(t.never);
  std::array<Rational, 3> c;
  for (int f = 0; f < 3; ++f) c[f] = ((*t.box)[f][0] + (*t.box)[f][1]) / 2;
  EXPECT_TRUE(closes(three_fingers(kL, {1, 2, 3}, c, above)));
  EXPECT_FALSE(closes(three_fingers(kL, {1, 2, 3}, c, Rational(1))));  // the same placement at μ = 1: open
  EXPECT_EQ(wrenchkit_checker::check(part(kL), grasp_regions_certificate(g), wrenchkit_checker::Limits{}).message, "accepted");
}

TEST(GraspRegionsThreeGolden, FrictionlessThreeFingersNeverClose) {
  const Grasp_regions g = three_finger_regions(scene_of(part(kSquare)), 0);
  ASSERT_EQ(g.triples.size(), 4u);
  EXPECT_EQ(g.never_triples(), 4u);
  for (const Triple_region& t : g.triples) EXPECT_FALSE(t.never_direction);  // the count argument, not a direction
  EXPECT_EQ(wrenchkit_checker::check(part(kSquare), grasp_regions_certificate(g), wrenchkit_checker::Limits{}).message,
            "accepted");
  // and the square's opposite sides with μ = 1/2 close whatever the third finger does: the pair's square extends
  EXPECT_EQ(three_finger_regions(scene_of(part(kSquare)), Rational(1, 2)).boxed_triples(), 4u);
  EXPECT_THROW(three_finger_regions(scene_of(part(kSquare)), 1, {0, 4}), Input_error);
}

// The theorem's own statement on small polygons: every placement sampled in a certified cube closes, and none of a
// triple certified "never" does (the engine's dual-cone closure decision of the three placed contacts decides); the
// search finds at least the pairs' own squares (a closed pair closes whatever the third finger does); a brute-force
// grid finds no robustly closed placement (a closed grid point whose 26 neighbours 1/20 away all close) in a triple
// the search left without a cube.
TEST(GraspRegionsThreeOracle, CubesCloseNeversOpenAndTheGridFindsNothingMissed) {
  const char* outlines[] = {"[[0, 0], [6, 0], [0, 6]]", kL, "[[0, 0], [3, 0], [5, 2], [4, 5], [1, 4]]", kSquare};
  const Rational mus[] = {Rational(1, 50), Rational(1, 5), Rational(1, 2), Rational(1)};
  std::mt19937_64 rng(test::seed(20261129));
  int boxed = 0, never = 0, neither = 0, sampled_in = 0, sampled_never = 0, grid_closed = 0;
  for (const char* o : outlines)
    for (const Rational& mu : mus) {
      const Scene sc = scene_of(part(o));
      const Grasp_regions g = three_finger_regions(sc, mu);
      const Grasp_regions pairs = two_finger_regions(sc, mu);
      ASSERT_EQ(wrenchkit_checker::check(part(o), grasp_regions_certificate(g), wrenchkit_checker::Limits{}).message, "accepted");
      for (const Triple_region& t : g.triples) {
        const auto random_in = [&](const std::array<std::array<Rational, 2>, 3>& b) {
          std::array<Rational, 3> s;
          for (int f = 0; f < 3; ++f) s[f] = b[f][0] + (b[f][1] - b[f][0]) * Rational(static_cast<long>(rng() % 1025)) / 1024;
          return s;
        };
        if (t.box) {
          ++boxed;
          for (int k = 0; k < 13; ++k) {  // five random placements and the eight corners
            std::array<Rational, 3> at = random_in(*t.box);
            if (k >= 5)
              for (int f = 0; f < 3; ++f) at[f] = (*t.box)[f][(k - 5) >> f & 1];
            const std::string text = three_fingers(o, t.edges, at, mu);
            ASSERT_TRUE(closes(text)) << test::dump_failure(text, "three_finger_box");
            ++sampled_in;
          }
          // at least every pair's own square (its side 1023/1024 of the supremum; the search's doubles lose a little)
          for (const Pair_region& p : pairs.pairs) {
            const bool in = std::count(t.edges.begin(), t.edges.end(), p.i) && std::count(t.edges.begin(), t.edges.end(), p.j);
            if (in && p.box) {
              EXPECT_GE(t.side, (*p.box)[0][1] - (*p.box)[0][0] - Rational(1, 1000)) << o << " " << to_string(mu);
            }
          }
        } else if (t.never) {
          ++never;
          for (int k = 0; k < 5; ++k) {
            const std::string text = three_fingers(o, t.edges, random_in({{{0, 1}, {0, 1}, {0, 1}}}), mu);
            ASSERT_FALSE(closes(text)) << test::dump_failure(text, "three_finger_never");
            ++sampled_never;
          }
        } else {
          ++neither;
          for (int a = 1; a < 10; a += 2)
            for (int b = 1; b < 10; b += 2)
              for (int c = 1; c < 10; c += 2) {
                const std::array<Rational, 3> s{Rational(a) / 10, Rational(b) / 10, Rational(c) / 10};
                if (!closes(three_fingers(o, t.edges, s, mu))) continue;
                ++grid_closed;
                bool robust = true;
                for (int d = 0; d < 27 && robust; ++d) {
                  const std::array<Rational, 3> n{s[0] + Rational(d % 3 - 1) / 20, s[1] + Rational(d / 3 % 3 - 1) / 20,
                                                  s[2] + Rational(d / 9 - 1) / 20};
                  robust = closes(three_fingers(o, t.edges, n, mu));
                }
                EXPECT_FALSE(robust) << "edges " << t.edges[0] << ", " << t.edges[1] << ", " << t.edges[2] << " of " << o
                                     << " with mu " << to_string(mu) << ": a robustly closed placement and no cube";
              }
        }
      }
    }
  EXPECT_GT(boxed, 20);
  EXPECT_GT(never, 10);
  EXPECT_GT(sampled_in, 100);
  std::printf("three fingers: %d boxed, %d never, %d neither (grid: %d closed placements there)\n", boxed, never, neither,
              grid_closed);
}

// Scale-free: the doubles propose in a frame where the force and moment rows are scaled by powers of two, so a part
// at 10^±400 (beyond the doubles' range) gets the same cubes and nevers as at scale 1, certified in its own numbers.
TEST(GraspRegionsThreeGolden, TheSameAnswersAtTenToThePlusMinus400) {
  const auto scaled_l = [](const std::string& factor) {
    std::string o = "[";
    const int V[6][2] = {{0, 0}, {6, 0}, {6, 2}, {2, 2}, {2, 5}, {0, 5}};
    for (int k = 0; k < 6; ++k)
      o += std::string(k ? ", " : "") + "[\"" + std::to_string(V[k][0]) + factor + "\", \"" + std::to_string(V[k][1]) + factor + "\"]";
    return o + "]";
  };
  const Grasp_regions one = three_finger_regions(scene_of(part(kL)), Rational(1, 2));
  for (const std::string factor : {"e400", "e-400"}) {
    const std::string o = scaled_l(factor);
    const Grasp_regions g = three_finger_regions(scene_of(part(o)), Rational(1, 2));
    EXPECT_EQ(g.boxed_triples(), one.boxed_triples()) << factor;
    EXPECT_EQ(g.never_triples(), one.never_triples()) << factor;
    EXPECT_EQ(wrenchkit_checker::check(part(o), grasp_regions_certificate(g), wrenchkit_checker::Limits{}).message,
              "accepted") << factor;
  }
}

TEST(GraspRegionsThreeChecker, RefusesAnOpenCornerAWrongWrenchANeverThatClosesAndAMissingTriple) {
  const Grasp_regions g = three_finger_regions(scene_of(part(kL)), Rational(1, 2));
  const std::string good = grasp_regions_certificate(g);
  const auto check = [&](std::string cert) {
    return wrenchkit_checker::check(part(kL), cert, wrenchkit_checker::Limits{}).message;
  };
  ASSERT_EQ(check(good), "accepted");
  // the first triple's cube stretched to the whole unit cube
  std::string big = good;
  const std::size_t at = big.find("\"independent\": [[");
  ASSERT_NE(at, std::string::npos);
  big.replace(at, big.find("]]", at) + 2 - at, R"("independent": [["0", "1"], ["0", "1"], ["0", "1"]])");
  EXPECT_NE(check(big).find("triples[0].independent: at the corner"), std::string::npos) << check(big);
  std::string label = good;
  const std::size_t w = label.find("\"wrenches\": [\"") + 14;
  label.replace(w, 2, label.substr(w, 2) == "R0" ? "L0" : "R0");
  EXPECT_NE(check(label).find("triples[0]"), std::string::npos) << check(label);
  // a boxed triple claimed never
  std::string never = good;
  const std::size_t n = never.find("{\"edges\": [0, 1, 2], ");
  ASSERT_NE(n, std::string::npos);
  never.replace(n, never.find("]}", n) + 2 - n, R"({"edges": [0, 1, 2], "never": ["1", "0", "0"]})");
  EXPECT_NE(check(never).find("triples[0].never: the wrench"), std::string::npos) << check(never);
  std::string frictionless = never;
  frictionless.replace(frictionless.find(R"(["1", "0", "0"])"), 15, R"("frictionless")");
  EXPECT_NE(check(frictionless).find("\"frictionless\" but mu is 1/2"), std::string::npos) << check(frictionless);
  std::string missing = good;
  missing.erase(n, missing.find("}, ", n) + 3 - n);
  EXPECT_NE(check(missing).find("triples[0]: expected edges [0, 1, 2]"), std::string::npos) << check(missing);
}

}  // namespace
}  // namespace wrenchkit
