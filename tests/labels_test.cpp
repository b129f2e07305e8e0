// [LB-1..4] Moment labels, force dual and Reuleaux modes: the labeled cases of theory.md §5–§9 and
// §14.3 with their exact vertices, and random degenerate-rich scenes against independent brute
// forces — pointwise labels from the definition, region vertices from all pairwise intersections of
// lines of force, labeled directions from the definition, Carathéodory membership, the closure
// decision and the equilibrium decision. The REGION format is read here by its own membership test
// (half-planes of the counter-clockwise boundary), so a wrong order or a wrong direction fails.
#include <gtest/gtest.h>

#include <iostream>
#include <random>
#include <set>

#include "exact/pipeline/answer_json.h"
#include "exact/statics/closure.h"
#include "exact/statics/equilibrium.h"
#include "exact/statics/force_dual.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {

Rational q(const char* s) { return Rational(s); }
Vec2 P(const char* x, const char* y) { return {q(x), q(y)}; }
Rational cr(const Vec2& a, const Vec2& b) { return a.x * b.y - a.y * b.x; }
Vec2 sub(const Vec2& a, const Vec2& b) { return {a.x - b.x, a.y - b.y}; }
bool eq(const Vec2& a, const Vec2& b) { return a.x == b.x && a.y == b.y; }

// c ∈ conv(vertices) + pos(directions), read from the format's promises (docs/cli.md).
bool region_contains(const Region& r, const Vec2& c) {
  using S = Region::Shape;
  const auto& v = r.vertices;
  const auto& d = r.directions;
  switch (r.shape) {
    case S::empty: return false;
    case S::plane: return true;
    case S::point: return eq(v[0], c);
    case S::segment: {
      const Vec2 a = sub(v[1], v[0]), b = sub(c, v[0]);
      const Rational t = a.x * b.x + a.y * b.y;
      return cr(a, b) == 0 && t >= 0 && t <= a.x * a.x + a.y * a.y;
    }
    case S::polygon:
      for (std::size_t i = 0; i < v.size(); ++i)
        if (cr(sub(v[(i + 1) % v.size()], v[i]), sub(c, v[i])) < 0) return false;
      return true;
    case S::ray: {
      const Vec2 b = sub(c, v[0]);
      return cr(d[0], b) == 0 && d[0].x * b.x + d[0].y * b.y >= 0;
    }
    case S::line: return cr(d[0], sub(c, v[0])) == 0;
    case S::strip: {
      const int a = sgn(cr(d[0], sub(c, v[0]))), b = sgn(cr(d[0], sub(c, v[1])));
      return a * b <= 0;
    }
    case S::half_plane: {
      const Vec2 b = sub(c, v[0]);
      return d[1].x * b.x + d[1].y * b.y >= 0;
    }
    case S::wedge:
    case S::unbounded_polygon: {
      // Counter-clockwise boundary: in along −d_k to v_1, the corners, out along d_1 from v_m.
      const Vec2 in{-d.back().x, -d.back().y};
      if (cr(in, sub(c, v.front())) < 0) return false;
      for (std::size_t i = 0; i + 1 < v.size(); ++i)
        if (cr(sub(v[i + 1], v[i]), sub(c, v[i])) < 0) return false;
      return cr(d.front(), sub(c, v.back())) >= 0;
    }
  }
  return false;
}

Moment_labels labels_of(const std::string& scene_text, Reading reading = Reading::friction) {
  return moment_labels(read_scene(scene_text, Input_limits{}), reading);
}

std::vector<Vec3q> wrenches_of(const Scene& s, Reading reading) {
  std::vector<Vec3q> w;
  for (const Generator& g : generators(s, reading)) w.push_back(g.w);
  return w;
}

// Pointwise labels from the definition (theory.md §5.1).
bool plus_at(const std::vector<Vec3q>& g, const Vec2& c) {
  for (const Vec3q& w : g)
    if (w[2] - (c.x * w[1] - c.y * w[0]) < 0) return false;
  return true;
}
bool minus_at(const std::vector<Vec3q>& g, const Vec2& c) {
  for (const Vec3q& w : g)
    if (w[2] - (c.x * w[1] - c.y * w[0]) > 0) return false;
  return true;
}
bool infinity_at(const std::vector<Vec3q>& g, const Vec2& d) {
  for (const Vec3q& w : g)
    if (w[0] * d.y - w[1] * d.x < 0) return false;
  return true;
}

// Brute-force corners of {c : s·M_c(g_i) ≥ 0 ∀i}: pairwise intersections of lines of force that
// satisfy every constraint (theory.md §5.4: a vertex is where two lines of force cross).
std::set<std::pair<Rational, Rational>> brute_corners(const std::vector<Vec3q>& g, int s) {
  std::set<std::pair<Rational, Rational>> out;
  for (std::size_t i = 0; i < g.size(); ++i)
    for (std::size_t j = i + 1; j < g.size(); ++j) {
      // M_c(w) = m − c_x f_y + c_y f_x = 0 for both: solve the 2×2 system.
      const Rational a1 = -g[i][1], b1 = g[i][0], c1 = -g[i][2];
      const Rational a2 = -g[j][1], b2 = g[j][0], c2 = -g[j][2];
      const Rational det = a1 * b2 - a2 * b1;
      if (det == 0) continue;
      const Vec2 c{(c1 * b2 - c2 * b1) / det, (a1 * c2 - a2 * c1) / det};
      if (s > 0 ? plus_at(g, c) : minus_at(g, c)) out.insert({c.x, c.y});
    }
  return out;
}

std::set<std::pair<Rational, Rational>> as_set(const std::vector<Vec2>& v) {
  std::set<std::pair<Rational, Rational>> s;
  for (const Vec2& p : v) s.insert({p.x, p.y});
  return s;
}

// ---- textbook cases -------------------------------------------------------------------------------

TEST(LabelsGolden, BlockInCornerFrictionless) {  // theory.md §5.8, §9
  const Moment_labels l = labels_of(test::read_text(test::source_dir() + "/tests/golden/block_corner_mu_0.scene.json"));
  EXPECT_EQ(l.plus.shape, Region::Shape::wedge);
  ASSERT_EQ(l.plus.vertices.size(), 1u);
  EXPECT_TRUE(eq(l.plus.vertices[0], P("0", "1")));
  EXPECT_TRUE(eq(l.plus.directions[0], P("0", "1")) && eq(l.plus.directions[1], P("-1", "0")));
  EXPECT_TRUE(eq(l.minus.vertices[0], P("1", "0")));
  EXPECT_TRUE(eq(l.minus.directions[0], P("0", "-1")) && eq(l.minus.directions[1], P("1", "0")));
  ASSERT_EQ(l.infinity.shape, Cone2::Shape::wedge);
  EXPECT_TRUE(eq(l.infinity.extreme[0], P("0", "1")) && eq(l.infinity.extreme[1], P("-1", "0")));
  EXPECT_EQ(l.both.kind, Both_set::Kind::none);
}

TEST(LabelsGolden, BlockInCornerMuHalf) {  // theory.md §9
  const Moment_labels l = labels_of(test::read_text(test::source_dir() + "/tests/golden/block_corner_mu_1_2.scene.json"));
  EXPECT_TRUE(eq(l.plus.vertices.at(0), P("-2/3", "4/3")));
  EXPECT_TRUE(eq(l.minus.vertices.at(0), P("4/3", "-2/3")));
  EXPECT_TRUE(eq(l.infinity.extreme.at(0), P("-1", "2")) && eq(l.infinity.extreme.at(1), P("-2", "1")));
}

TEST(LabelsGolden, LadderAtAndBelowThreshold) {  // theory.md §9 leaning square
  const std::string dir = test::source_dir() + "/tests/golden/";
  const Moment_labels at = labels_of(test::read_text(dir + "ladder_mu_1_7.scene.json"));
  const auto v = as_set(at.plus.vertices);
  EXPECT_TRUE(v.count({q("-1/2"), q("7/2")}) && v.count({q("-4"), q("3")})) << region_json(at.plus);
  const Moment_labels below = labels_of(test::read_text(dir + "ladder_mu_1_8.scene.json"));
  EXPECT_TRUE(as_set(below.plus.vertices).count({q("-28/65"), q("224/65")})) << region_json(below.plus);
  const Moment_labels zero = labels_of(test::read_text(dir + "ladder_mu_0.scene.json"));
  EXPECT_EQ(zero.plus.shape, Region::Shape::wedge);
  EXPECT_TRUE(eq(zero.plus.vertices.at(0), P("0", "3")));
  EXPECT_TRUE(eq(zero.minus.vertices.at(0), P("0", "3")));
  ASSERT_EQ(zero.both.kind, Both_set::Kind::point);
  EXPECT_TRUE(eq(zero.both.point, P("0", "3")));
  EXPECT_TRUE(eq(zero.infinity.extreme.at(0), P("0", "1")) && eq(zero.infinity.extreme.at(1), P("-1", "0")));
}

TEST(LabelsGolden, SingleForce) {  // §5.2, §14.3 case 1
  const Moment_labels l = moment_labels(std::vector<Vec3q>{{1, 0, 0}});
  EXPECT_TRUE(region_contains(l.plus, P("0", "1")));
  EXPECT_FALSE(region_contains(l.plus, P("0", "-1")));
  EXPECT_TRUE(region_contains(l.minus, P("0", "-1")));
  EXPECT_TRUE(region_contains(l.plus, P("5", "0")) && region_contains(l.minus, P("5", "0")));
  EXPECT_EQ(l.both.kind, Both_set::Kind::line);
  EXPECT_TRUE(contains(l.infinity, P("0", "1")));
  EXPECT_FALSE(contains(l.infinity, P("0", "-1")));
  EXPECT_EQ(l.plus.shape, Region::Shape::half_plane);
}

TEST(LabelsGolden, ConcurrentNormalsTriangle) {  // §8.7 μ = 0 and μ > 0
  const std::string dir = test::source_dir() + "/tests/golden/";
  const Moment_labels l = labels_of(test::read_text(dir + "triangle_example3_mu_0.scene.json"));
  EXPECT_EQ(l.cone.rank, 2);
  ASSERT_EQ(l.both.kind, Both_set::Kind::point);
  EXPECT_TRUE(eq(l.both.point, P("1", "1")));
  EXPECT_EQ(l.plus.shape, Region::Shape::point);
  EXPECT_EQ(l.minus.shape, Region::Shape::point);
  EXPECT_EQ(l.infinity.shape, Cone2::Shape::zero);
  EXPECT_FALSE(in_cone(l.cone, {0, 0, 1}));          // a pure moment is not a possible resultant
  EXPECT_TRUE(in_cone(l.cone, {1, 0, -1}));          // a force (1, 0) through G = (1, 1) is
  for (const char* f : {"triangle_example3_mu_1_1000", "triangle_example3_mu_1_10", "triangle_example3_mu_1_2"})
    EXPECT_TRUE(labels_of(test::read_text(dir + f + ".scene.json")).nothing_labeled()) << f;
}

TEST(LabelsGolden, VerticalWallsOnlyInfinity) {  // §5.5, §14.3 case 4
  const Moment_labels l = moment_labels(std::vector<Vec3q>{{1, 0, -1}, {1, 0, 1}, {-1, 0, 1}, {-1, 0, -1}});
  EXPECT_TRUE(l.plus.empty() && l.minus.empty());
  EXPECT_EQ(l.infinity.shape, Cone2::Shape::line);
  EXPECT_FALSE(l.nothing_labeled());
  EXPECT_TRUE(in_cone(l.cone, {1, 0, 0}));
  EXPECT_TRUE(in_cone(l.cone, {0, 0, 1}));
  EXPECT_FALSE(in_cone(l.cone, {0, 1, 0}));
}

TEST(LabelsGolden, ReuleauxSquares) {  // §7
  const std::string dir = test::source_dir() + "/tests/golden/";
  const Moment_labels pin = labels_of(test::read_text(dir + "square_pinwheel.scene.json"), Reading::frictionless);
  EXPECT_TRUE(pin.plus.empty());
  EXPECT_EQ(pin.infinity.shape, Cone2::Shape::zero);
  ASSERT_EQ(pin.minus.shape, Region::Shape::polygon);
  const auto v = as_set(pin.minus.vertices);
  EXPECT_TRUE(v.count({q("1/2"), q("1/2")}) && v.count({q("3/2"), q("3/2")})) << region_json(pin.minus);
  EXPECT_TRUE(labels_of(test::read_text(dir + "square_crossed_couples.scene.json"), Reading::frictionless).nothing_labeled());
  const Moment_labels al = labels_of(test::read_text(dir + "square_aligned.scene.json"), Reading::frictionless);
  EXPECT_EQ(al.cone.rank, 2);
  ASSERT_EQ(al.both.kind, Both_set::Kind::point);
  EXPECT_TRUE(eq(al.both.point, P("1/2", "1")));
}

TEST(LabelsGolden, TriangleFourContactsSinglePoint) {  // §7: R₊ = {(1,1)}, R₋ = ∅, R∞ = ∅
  const Moment_labels l = labels_of(test::scene_json({{"1", "0", "0", "1", ""}, {"3", "0", "0", "1", ""},
                                                      {"0", "1", "1", "0", ""}, {"2", "2", "-1", "-1", ""}}));
  ASSERT_EQ(l.plus.shape, Region::Shape::point);
  EXPECT_TRUE(eq(l.plus.vertices[0], P("1", "1")));
  EXPECT_TRUE(l.minus.empty());
  EXPECT_EQ(l.infinity.shape, Cone2::Shape::zero);
  EXPECT_EQ(l.cone.rank, 3);
  const Moment_labels closed = labels_of(test::scene_json({{"1", "0", "0", "1", ""}, {"3", "0", "0", "1", ""},
                                                           {"0", "2", "1", "0", ""}, {"2", "2", "-1", "-1", ""}}));
  EXPECT_TRUE(closed.nothing_labeled());
}

TEST(LabelsGolden, FrictionWedgeOfOneContact) {  // §5.2, §14.3 case 10
  const Moment_labels l = labels_of(test::scene_json({{"1", "0", "0", "1", "1/2"}}));
  for (const Vec2& c : {P("0", "1"), P("-1", "1"), P("1/2", "1"), P("-1", "-1/2"), P("-5", "0")})
    EXPECT_TRUE(region_contains(l.plus, c) && !region_contains(l.minus, c)) << c.x << "," << c.y;
  for (const Vec2& c : {P("2", "1"), P("5", "0")})
    EXPECT_TRUE(region_contains(l.minus, c) && !region_contains(l.plus, c)) << c.x << "," << c.y;
  for (const Vec2& c : {P("1", "3"), P("1", "-3")})
    EXPECT_FALSE(region_contains(l.plus, c) || region_contains(l.minus, c)) << c.x << "," << c.y;
  ASSERT_EQ(l.both.kind, Both_set::Kind::point);
  EXPECT_TRUE(eq(l.both.point, P("1", "0")));
}

TEST(LabelsGolden, DegenerateTable) {  // §5.6
  // Parallel forces, same sense: half-planes bounded by the outermost lines; R∞ a half-circle.
  const Moment_labels par = moment_labels(std::vector<Vec3q>{{0, 1, 0}, {0, 1, 2}});  // x = 0 and x = 2
  EXPECT_EQ(par.plus.shape, Region::Shape::half_plane);
  EXPECT_TRUE(region_contains(par.plus, P("-1", "7")) && !region_contains(par.plus, P("1", "0")));
  EXPECT_EQ(par.minus.shape, Region::Shape::half_plane);
  EXPECT_TRUE(region_contains(par.minus, P("2", "-9")) && !region_contains(par.minus, P("1", "0")));
  EXPECT_EQ(par.infinity.shape, Cone2::Shape::half_plane);
  // Parallel forces in both senses on different lines: strips, R∞ ⊆ {±e}.
  const Moment_labels anti = moment_labels(std::vector<Vec3q>{{0, 1, 0}, {0, -1, -2}});  // up at x=0, down at x=2
  EXPECT_EQ(anti.plus.shape, Region::Shape::empty);
  EXPECT_EQ(anti.minus.shape, Region::Shape::strip);
  EXPECT_TRUE(region_contains(anti.minus, P("1", "100")) && !region_contains(anti.minus, P("3", "0")));
  EXPECT_EQ(anti.infinity.shape, Cone2::Shape::line);
  // Opposite forces on one line: the line is ±.
  const Moment_labels opp = moment_labels(std::vector<Vec3q>{{1, 0, 0}, {-1, 0, 0}});
  EXPECT_EQ(opp.plus.shape, Region::Shape::line);
  EXPECT_EQ(opp.both.kind, Both_set::Kind::line);
  // Pure moments of both signs: no finite label; infinity decides.
  const Moment_labels pm = moment_labels(std::vector<Vec3q>{{0, 0, 1}, {0, 0, -1}, {1, 0, 0}});
  EXPECT_TRUE(pm.plus.empty() && pm.minus.empty());
  EXPECT_EQ(pm.infinity.shape, Cone2::Shape::half_plane);
  // Empty generator set: everything ±.
  const Moment_labels none = moment_labels(std::vector<Vec3q>{});
  EXPECT_EQ(none.plus.shape, Region::Shape::plane);
  EXPECT_EQ(none.both.kind, Both_set::Kind::plane);
  EXPECT_EQ(none.infinity.shape, Cone2::Shape::plane);
  // A pure moment alone: every finite point +, R₋ empty, all of infinity.
  const Moment_labels m = moment_labels(std::vector<Vec3q>{{0, 0, 3}});
  EXPECT_EQ(m.plus.shape, Region::Shape::plane);
  EXPECT_TRUE(m.minus.empty());
  EXPECT_EQ(m.infinity.shape, Cone2::Shape::plane);
}

TEST(ForceDualGolden, BlockInCornerAboutReferencePoint) {  // theory.md §6.2
  const std::vector<Vec3q> g = {{0, 1, 0}, {0, 1, 1}, {1, 0, 0}, {1, 0, -1}};
  const Moment_labels l = moment_labels(g);
  const Force_dual d = force_dual(l, g);
  EXPECT_FALSE(d.covers_all);
  ASSERT_TRUE(d.reference.has_value());
  EXPECT_TRUE(eq(*d.reference, P("-1", "2")));  // (0,1) + (0,1) + (−1,0)
  EXPECT_EQ(as_set(d.about_reference.vertices), as_set({P("-1", "0"), P("-1/2", "0"), P("0", "1/2"), P("0", "1")}));
  // The wrench balancing gravity at (1/2, 1/2), (0, 1, 1/2) about the origin, is (0, 1, 3/2) about o = (−1, 2):
  // its dual point (−1/(3/2), 0) = (−2/3, 0) lies on the polygon's boundary.
  EXPECT_TRUE(region_contains(d.about_reference, P("-2/3", "0")));
  EXPECT_FALSE(region_contains(d.about_reference, P("-2/3", "-1/100")));
}

TEST(ForceDualGolden, ClosureCoversAll) {
  const Moment_labels l = labels_of(test::read_text(test::source_dir() + "/tests/golden/triangle_example3_mu_1_10.scene.json"));
  const Force_dual d = force_dual(l, {});
  EXPECT_TRUE(d.covers_all);
  EXPECT_EQ(d.plus_sheet.shape, Region::Shape::plane);
  EXPECT_EQ(d.infinity.shape, Cone2::Shape::plane);
}

TEST(Reuleaux, ContactModes) {  // §7 per-contact modes
  const Scene s = read_scene(test::scene_json({{"0", "0", "0", "1", ""}, {"2", "0", "0", "1", ""}}), Input_limits{});
  // Rotation about (0, 0) counter-clockwise: contact 0 sticks, contact 1 moves up (breaks).
  Mode_answer a = contact_modes(s, rotation_twist(P("0", "0"), 1));
  EXPECT_EQ(a.modes[0], Contact_mode::sticks);
  EXPECT_EQ(a.modes[1], Contact_mode::breaks);
  EXPECT_TRUE(a.feasible && a.marginal);
  // Clockwise about (0,0): contact 1 penetrates.
  a = contact_modes(s, rotation_twist(P("0", "0"), -1));
  EXPECT_EQ(a.modes[1], Contact_mode::penetrates);
  EXPECT_FALSE(a.feasible);
  // Translation to the right (the point at infinity (0, 1)... velocity (d_y, −d_x)): d = (0, −1) gives v = (−1, 0).
  a = contact_modes(s, translation_twist(P("0", "-1")));
  EXPECT_EQ(a.modes[0], Contact_mode::slides);
  EXPECT_EQ(a.modes[1], Contact_mode::slides);
  // Rotation about a centre on the + side: feasible and P(t) is the centre.
  const Vec3q t = rotation_twist(P("1", "5"), 1);
  EXPECT_TRUE(eq({J(t)[0] / J(t)[2], J(t)[1] / J(t)[2]}, P("1", "5")));
}

// ---- random scenes against brute forces -----------------------------------------------------------

// On a failure, dumps the scene for replay (`wrenchkit labels PATH`) and prints the path.
struct Dump_on_failure {
  const std::string& text;
  const std::string& tag;
  ~Dump_on_failure() {
    if (::testing::Test::HasFailure()) std::cerr << "failing scene: " << test::dump_failure(text, tag) << "\n";
  }
};

void check_labels_against_brute_force(const std::string& text, std::mt19937_64& rng, const std::string& tag) {
  const Dump_on_failure dump{text, tag};
  const Scene scene = read_scene(text, Input_limits{});
  for (Reading reading : {Reading::friction, Reading::frictionless}) {
    const std::vector<Vec3q> g = wrenches_of(scene, reading);
    const Moment_labels l = moment_labels(g);
    SCOPED_TRACE(tag + (reading == Reading::friction ? " friction" : " frictionless") +
                 "\nplus " + region_json(l.plus) + "\nminus " + region_json(l.minus));
    // Closure agrees with the labels (nothing labeled, infinity included).
    const Closure_answer ca = decide_closure(scene, reading == Reading::friction ? Property::force_closure : Property::form_closure);
    ASSERT_EQ(ca.holds, l.nothing_labeled());
    ASSERT_EQ(ca.holds, test::brute_force_closure(g));
    // Corners: exactly the feasible pairwise intersections that are corners of the region.
    for (int s : {1, -1}) {
      const Region& r = s > 0 ? l.plus : l.minus;
      const auto brute = brute_corners(g, s);
      const bool has_corners = r.shape == Region::Shape::segment || r.shape == Region::Shape::polygon ||
                               r.shape == Region::Shape::ray || r.shape == Region::Shape::wedge ||
                               r.shape == Region::Shape::unbounded_polygon;
      for (const Vec2& v : r.vertices) {
        if (has_corners) {
          ASSERT_TRUE(brute.count({v.x, v.y})) << "corner not an intersection of lines of force";
        }
      }
      for (const auto& [x, y] : brute) ASSERT_TRUE(region_contains(r, {x, y})) << "feasible intersection outside";
    }
    // Pointwise: sample points on lines of force, their intersections, and the grid.
    std::vector<Vec2> samples;
    std::uniform_int_distribution<int> coord(-12, 12);
    for (int k = 0; k < 40; ++k) samples.push_back({Rational(coord(rng)) / 4, Rational(coord(rng)) / 4});
    for (const auto& [x, y] : brute_corners(g, 1)) samples.push_back({x, y});
    for (const auto& [x, y] : brute_corners(g, -1)) samples.push_back({x, y});
    for (const Vec2& v : l.plus.vertices) samples.push_back(v);
    for (const Vec2& v : l.minus.vertices) samples.push_back(v);
    for (const Vec2& c : samples) {
      ASSERT_EQ(plus_at(g, c), region_contains(l.plus, c)) << "+ at " << c.x << "," << c.y;
      ASSERT_EQ(minus_at(g, c), region_contains(l.minus, c)) << "- at " << c.x << "," << c.y;
    }
    // Directions at infinity: every ±f_i, their perpendiculars and random ones.
    std::vector<Vec2> dirs;
    for (const Vec3q& w : g) {
      dirs.push_back({w[0], w[1]});
      dirs.push_back({-w[0], -w[1]});
      dirs.push_back({-w[1], w[0]});
    }
    for (int k = 0; k < 12; ++k) dirs.push_back({coord(rng), coord(rng)});
    for (const Vec2& d : dirs) {
      if (d.x == 0 && d.y == 0) continue;
      ASSERT_EQ(infinity_at(g, d), contains(l.infinity, d)) << "infinity " << d.x << "," << d.y;
      // R∞ is the recession cone of R₊ when R₊ is not empty (theory.md §5.1).
      if (!l.plus.empty() && infinity_at(g, d)) {
        ASSERT_TRUE(region_contains(l.plus, {l.plus.vertices[0].x + 1000 * d.x, l.plus.vertices[0].y + 1000 * d.y}))
            << "recession " << d.x << "," << d.y;
      }
    }
    // Membership: labels (W = W**) against Carathéodory, on generators, sums and random wrenches.
    std::vector<std::array<Rational, 3>> ws;
    for (const Vec3q& w : g) ws.push_back({w[0], w[1], w[2]});
    for (std::size_t i = 0; i + 1 < g.size(); ++i)
      ws.push_back({g[i][0] - g[i + 1][0], g[i][1] - g[i + 1][1], g[i][2] - g[i + 1][2]});
    for (int k = 0; k < 10; ++k) ws.push_back({coord(rng), coord(rng), coord(rng)});
    ws.push_back({0, 0, 1});
    ws.push_back({0, 0, -1});
    const Force_dual d = force_dual(l, g);
    ASSERT_EQ(d.covers_all, ca.holds);
    for (const auto& w : ws) {
      const bool brute = test::brute_force_in_cone(g, w);
      ASSERT_EQ(in_cone(l.cone, w), brute) << "resultant " << w[0] << "," << w[1] << "," << w[2];
      if (w[0] == 0 && w[1] == 0 && w[2] == 0) continue;
      // The same membership read on the force dual's sheets (theory.md §6.3).
      const Dual_point p = dual_point(w);
      const bool in_dual = p.sheet == '+' ? region_contains(d.plus_sheet, p.at)
                           : p.sheet == '-' ? region_contains(d.minus_sheet, p.at)
                                            : contains(d.infinity, p.at);
      ASSERT_EQ(in_dual, brute) << "dual " << w[0] << "," << w[1] << "," << w[2];
    }
    if (d.reference) {  // §6.2: every generator has positive moment about the reference point
      for (const Vec3q& w : g) ASSERT_GT(w[2] - (d.reference->x * w[1] - d.reference->y * w[0]), 0);
    }
  }
}

TEST(LabelsDifferential, RandomScenesAgainstBruteForce) {
  const std::uint64_t seed = test::seed(20261121);
  std::mt19937_64 rng(seed);
  for (int k = 0; k < 400; ++k) {
    const std::string text = test::scene_json(test::random_contacts(rng, 6));
    check_labels_against_brute_force(text, rng, "labels_seed" + std::to_string(seed) + "_case" + std::to_string(k));
    if (HasFatalFailure()) return;
  }
}

TEST(LabelsDifferential, LoadReadingAgreesWithEquilibrium) {
  std::mt19937_64 rng(test::seed(77));
  std::uniform_int_distribution<int> c(-3, 3);
  for (int k = 0; k < 300; ++k) {
    std::string text = test::scene_json(test::random_contacts(rng, 5));
    const std::string load = "\"load\": {\"wrench\": [" + std::to_string(c(rng)) + ", " + std::to_string(c(rng)) + ", " +
                             std::to_string(c(rng)) + "]}";
    text.insert(text.rfind('}'), ", " + load);
    const Scene s = read_scene(text, Input_limits{});
    const Moment_labels l = moment_labels(s, Reading::friction);
    const Vec3q w = load_wrench(s);
    EXPECT_EQ(in_cone(l.cone, {-w[0], -w[1], -w[2]}), decide_equilibrium(s).balanced) << text;
  }
}

TEST(LabelsDifferential, HugeTinyAndLongRationals) {
  // The block in a corner at scale 10^18 and 10^-20 and rotated by a 40-digit rational rotation:
  // corners transform exactly.
  const std::string big = "1000000000000000000", tiny = "1/100000000000000000000";
  for (const std::string& s : {big, tiny}) {
    const Moment_labels l = labels_of(test::scene_json({{"0", "0", "0", "1", ""}, {s, "0", "0", "1", ""},
                                                        {"0", "0", "1", "0", ""}, {"0", s, "1", "0", ""}}));
    EXPECT_TRUE(eq(l.plus.vertices.at(0), {Rational(0), Rational(s)}));
    EXPECT_TRUE(eq(l.minus.vertices.at(0), {Rational(s), Rational(0)}));
  }
  // Every golden scene (thresholds ± 10^-40, a 40-digit rotation, scales 10^18 and 10^-20, the
  // textbook cases, with and without loads) against the brute forces.
  std::vector<std::string> files = test::scene_files("tests/golden");
  for (const std::string& f : test::scene_files("tests/golden/equilibrium")) files.push_back(f);
  for (const std::string& f : files) {
    std::mt19937_64 rng(1);
    check_labels_against_brute_force(test::read_text(f), rng, "golden_" + f.substr(f.rfind('/') + 1));
    if (HasFatalFailure()) return;
  }
}

// Found by fuzz_structured: an arc-shaped W* whose edge cycle starts at the arc's plane generator
// ((e, q, e', p) instead of (p, e, q, e')) was read as one ray twice; R₊ must hold (0, −4).
TEST(LabelsRegression, ArcWithRotatedEdgeCycle) {
  const std::string text = R"({"wrenchkit": 1, "contacts": [
    {"at": ["0", "-1"], "normal": ["-1", "-2"], "mu": "1/10"}, {"at": ["-4", "-4"], "normal": ["1", "0"]},
    {"at": ["-4", "-4"], "normal": ["-2", "0"]}, {"at": ["-4", "-4"], "normal": ["-2", "-2"]},
    {"at": ["-4", "-4"], "normal": ["-2", "-2"]}, {"at": ["0", "-4"], "normal": ["-2", "-2"]}],
    "load": {"wrench": ["-1", "1", "-3"]}})";
  const Scene s = read_scene(text, Input_limits{});
  const Moment_labels l = moment_labels(s, Reading::friction);
  EXPECT_EQ(l.cone.dual.size(), 2u);
  EXPECT_TRUE(region_contains(l.plus, P("0", "-4"))) << region_json(l.plus);
  EXPECT_TRUE(region_contains(l.minus, P("-4", "-4"))) << region_json(l.minus);
  const Vec3q w = load_wrench(s);
  EXPECT_EQ(in_cone(l.cone, {-w[0], -w[1], -w[2]}), decide_equilibrium(s).balanced);
  std::mt19937_64 rng(3);
  check_labels_against_brute_force(text, rng, "arc_rotated");
}

}  // namespace
}  // namespace wrenchkit
