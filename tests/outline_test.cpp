// [OL-1] The body's outline as geometry (exact/io/outline.h, docs/scene-format.md "The outline"): named fixtures for
// every refusal (off the outline, an outward normal on an edge, a normal outside a vertex's cone, a repeated or a
// crossing outline) with the message pinned, --lenient keeping them as warnings, contacts placed by {"edge", "s"}
// (the exact point and inward normal, clockwise outlines too, a given normal checked like any other), the two readers
// (one pass and the tree) agreeing, the independent checker making the same contacts, and on random convex polygons
// the theorem's own statement: every placed contact passes, and moving it off its edge by any rational step fails.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "exact/io/input_error.h"
#include "exact/io/outline.h"
#include "exact/io/scene.h"
#include "exact/certificates/certificates.h"
#include "exact/statics/closure.h"
#include "proofs/checker/checker.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {

const char* kTriangle = R"("body": {"outline": [[0, 0], [4, 0], [0, 4]]})";

std::string scene(const std::string& contacts, const std::string& body = kTriangle) {
  return R"({"wrenchkit": 1, )" + body + R"(, "contacts": [)" + contacts + "]}";
}
std::string error_of(const std::string& text, bool lenient = false) {
  Input_limits limits;
  limits.lenient = lenient;
  try {
    read_scene(text, limits);
  } catch (const Input_error& e) {
    return e.what();
  }
  return "";
}

TEST(Outline, ContactsOnTheOutlineWithInwardNormalsPass) {
  // an edge's interior (perpendicular or oblique but inward), a vertex inside its cone, the cone's edges included
  EXPECT_EQ(error_of(scene(R"({"at": [2, 0], "normal": [0, 1]}, {"at": [2, 2], "normal": [-1, -1]},
                              {"at": [0, 1], "normal": [3, 1]}, {"at": [0, 0], "normal": [1, 1]},
                              {"at": [4, 0], "normal": [-1, 0]}, {"at": [0, 0], "normal": [0, 1]})")), "");
  const Scene s = read_scene(scene(R"({"at": [2, 0], "normal": [0, 1]})"), Input_limits{});
  EXPECT_TRUE(s.body.outline_ccw);
  EXPECT_TRUE(s.body.outline_convex);
  EXPECT_TRUE(s.warnings.empty());
}

TEST(Outline, RefusalsNameTheContactAndTheFix) {
  EXPECT_EQ(error_of(scene(R"({"at": [5, 5], "normal": [-1, -1]})")),
            "contacts[0].at: (5, 5) is not on body.outline (a contact touches the body's boundary); the nearest edge "
            "is 1, from (4, 0) to (0, 4): place the contact on it, e.g. {\"edge\": 1, \"s\": \"1/2\"}; or pass "
            "--lenient to analyse the scene as given");
  EXPECT_EQ(error_of(scene(R"({"at": [2, 0], "normal": [0, -1]})")),
            "contacts[0].normal: (0, -1) does not point into the body at edge 0 (from (0, 0) to (4, 0), inward normal "
            "(0, 4)); a contact's normal points into the body — flip its sign?; or pass --lenient to analyse the scene "
            "as given");
  EXPECT_NE(error_of(scene(R"({"at": [2, 0], "normal": [1, 0]})")).find("it is tangent to the edge here"), std::string::npos);
  EXPECT_EQ(error_of(scene(R"({"at": [4, 0], "normal": [1, 1]})")),
            "contacts[0].normal: (1, 1) is not in the cone of inward normals at vertex 1 (4, 0) (between (0, 4) and "
            "(-4, -4)); a contact's normal points into the body; or pass --lenient to analyse the scene as given");
  // the outline itself: the first vertex repeated at the end, a bow tie
  EXPECT_NE(error_of(scene("", R"("body": {"outline": [[0, 0], [4, 0], [0, 4], [0, 0]]})"))
                .find("body.outline: is not a simple polygon (a vertex is repeated) (a body's outline is a simple polygon, "
                      "each vertex once: do not repeat the first vertex at the end)"),
            std::string::npos);
  EXPECT_NE(error_of(scene("", R"("body": {"outline": [[0, 0], [2, 2], [2, 0], [0, 2]]})")).find("two of its edges cross"),
            std::string::npos);
  // the second offender is named when the first is fine; wrench generators are not on the outline
  EXPECT_NE(error_of(scene(R"({"at": [2, 0], "normal": [0, 1]}, {"wrench": [1, 0, 0]}, {"at": [1, 1], "normal": [0, 1]})"))
                .find("contacts[2].at: (1, 1) is not on body.outline"),
            std::string::npos);
}

TEST(Outline, LenientKeepsViolationsAsWarnings) {
  const std::string text = scene(R"({"at": [2, 0], "normal": [0, -1]}, {"at": [5, 5], "normal": [-1, -1]})");
  EXPECT_EQ(error_of(text, true), "");
  Input_limits limits;
  limits.lenient = true;
  const Scene s = read_scene(text, limits);
  ASSERT_EQ(s.warnings.size(), 2u);
  EXPECT_EQ(s.warnings[0].rfind("contacts[0].normal: (0, -1) does not point into the body", 0), 0u);
  EXPECT_EQ(s.warnings[1].rfind("contacts[1].at: (5, 5) is not on body.outline", 0), 0u);
  EXPECT_EQ(s.contacts[0].normal.y, -1);  // analysed as given
}

TEST(Outline, PlacedContactsAreExact) {
  const Scene s = read_scene(scene(R"({"edge": 0, "s": "1/3", "mu": "1/2"}, {"edge": 1, "s": 0.25, "name": "hyp"},
                                      {"edge": 2, "s": 1}, {"edge": 0, "s": "1/2", "normal": [1, 3]})"),
                             Input_limits{});
  ASSERT_EQ(s.contacts.size(), 4u);
  EXPECT_EQ(s.contacts[0].at.x, Rational(4, 3));
  EXPECT_EQ(s.contacts[0].at.y, 0);
  EXPECT_EQ(s.contacts[0].normal.x, 0);  // rot90 of (4, 0): (0, 4), inward for a counter-clockwise outline
  EXPECT_EQ(s.contacts[0].normal.y, 4);
  EXPECT_EQ(s.contacts[0].mu, Rational(1, 2));
  EXPECT_EQ(*s.contacts[0].edge, 0u);
  EXPECT_EQ(s.contacts[1].at.x, 3);  // (4, 0) + 1/4 (-4, 4)
  EXPECT_EQ(s.contacts[1].at.y, 1);
  EXPECT_EQ(s.contacts[1].normal.x, -4);
  EXPECT_EQ(s.contacts[1].normal.y, -4);
  EXPECT_EQ(s.contacts[1].name, "hyp");
  EXPECT_EQ(s.contacts[2].at.x, 0);  // s = 1: edge 2's last vertex, (0, 0)
  EXPECT_EQ(s.contacts[2].at.y, 0);
  EXPECT_EQ(s.contacts[3].normal.x, 1);
  // clockwise: the same triangle the other way round; edge 0 from (0, 0) to (0, 4), its inward normal (4, 0)
  const Scene cw = read_scene(scene(R"({"edge": 0, "s": "1/2"})", R"("body": {"outline": [[0, 0], [0, 4], [4, 0]]})"),
                              Input_limits{});
  EXPECT_FALSE(cw.body.outline_ccw);
  EXPECT_EQ(cw.contacts[0].normal.x, 4);
  EXPECT_EQ(cw.contacts[0].normal.y, 0);
  // bad placements
  EXPECT_EQ(error_of(scene(R"({"edge": 3, "s": 0})")),
            "contacts[0].edge: 3 is not an edge of body.outline (an integer from 0 to 2: edge i runs from vertex i to "
            "vertex i + 1)");
  EXPECT_NE(error_of(scene(R"({"edge": "1/2", "s": 0})")).find("is not an edge of body.outline"), std::string::npos);
  EXPECT_NE(error_of(scene(R"({"edge": 0, "s": "3/2"})")).find("contacts[0].s: \"3/2\" is not in [0, 1]"), std::string::npos);
  EXPECT_NE(error_of(scene(R"({"edge": 0, "s": 0, "at": [0, 0]})")).find("give either \"at\" or {\"edge\", \"s\"}"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"wrenchkit": 1, "contacts": [{"edge": 0, "s": 0}]})").find("contacts[0].edge: needs body.outline"),
            std::string::npos);
  EXPECT_NE(error_of(scene(R"({"edge": 0, "s": "1/2", "normal": [0, -1]})")).find("does not point into the body"),
            std::string::npos);
  // the one-pass reader defers to the tree for a placed contact: the same scene either way
  const std::string text = scene(R"({"edge": 1, "s": "1/4", "mu": 1})");
  EXPECT_EQ(read_scene(text, Input_limits{}).contacts[0].at.x, read_scene_tree(text, Input_limits{}).contacts[0].at.x);
}

// The checker makes the same contacts from {"edge", "s"}: the engine's certificates of placed scenes are accepted,
// and a certificate of the scene with the contacts written out is accepted against the placed scene too.
TEST(Outline, TheCheckerPlacesContactsAsTheEngineDoes) {
  const char* outlines[] = {R"("body": {"outline": [[0, 0], [4, 0], [0, 4]]})",
                            R"("body": {"outline": [[0, 0], [0, 4], [4, 0]]})",
                            R"("body": {"outline": [[0, 0], [6, 0], [6, 2], [2, 2], [2, 5], [0, 5]]})"};
  std::mt19937_64 rng(test::seed(20261129));
  int closed = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const std::string body = outlines[trial % 3];
    const std::size_t edges = trial % 3 == 2 ? 6 : 3;
    std::string contacts;
    for (int k = 0; k < 3; ++k)
      contacts += (k ? ", " : "") + std::string(R"({"edge": )") + std::to_string(rng() % edges) + R"(, "s": ")" +
                  std::to_string(1 + rng() % 7) + "/8\"" + (k == 0 ? R"(, "mu": "1/2")" : "") + "}";
    const std::string text = R"({"wrenchkit": 1, "mu": "1/3", )" + body + R"(, "contacts": [)" + contacts + "]}";
    const Scene s = read_scene(text, Input_limits{});
    const Closure_answer a = decide_closure(s, Property::force_closure, Mode::exact, true);
    closed += a.holds;
    const std::string cert = certificate_json(a.certificate);
    const auto r = wrenchkit_checker::check(text, cert, wrenchkit_checker::Limits{});
    ASSERT_EQ(r.outcome, wrenchkit_checker::Outcome::accepted) << r.message << "\n" << test::dump_failure(text, "outline");
  }
  EXPECT_GT(closed, 5);
}

// On random convex polygons (points on a circle of rational points, counter-clockwise): a contact at any rational
// place of any edge with its inward normal passes; the same point moved off the edge along the normal, either way, is
// refused (inside: not on the outline; outside: not on it either), and the normal flipped is refused.
TEST(Outline, PlacedContactsPassAndMovedOnesDoNot) {
  std::mt19937_64 rng(test::seed(20261130));
  // rational points on the unit circle: ((1 − t²), 2t) / (1 + t²) for t = tan(θ/2) rational
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<Rational> ts;
    const int n = 3 + static_cast<int>(rng() % 6);
    for (int k = 0; k < n; ++k) ts.push_back(Rational(-20 + static_cast<long>(rng() % 41), 7));
    std::sort(ts.begin(), ts.end());
    ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
    if (ts.size() < 3) continue;
    std::string outline;
    std::vector<Vec2> V;
    for (const Rational& t : ts) {
      const Vec2 p{(1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)};
      V.push_back(p);
      outline += (outline.empty() ? "" : ", ") + std::string("[\"") + to_string(p.x) + "\", \"" + to_string(p.y) + "\"]";
    }
    // t increasing: the angle increases, so the polygon runs counter-clockwise
    const std::string body = R"("body": {"outline": [)" + outline + "]}";
    const std::size_t e = rng() % V.size();
    const Rational s(1 + static_cast<long>(rng() % 9), 10);
    const Vec2 p = edge_point(V, e, s), in = edge_inward_normal(V, e, 1);
    const auto contact = [](const Vec2& at, const Vec2& n) {
      return R"({"at": [")" + to_string(at.x) + "\", \"" + to_string(at.y) + R"("], "normal": [")" + to_string(n.x) +
             "\", \"" + to_string(n.y) + "\"]}";
    };
    EXPECT_EQ(error_of(scene(contact(p, in), body)), "") << body;
    EXPECT_EQ(error_of(scene(R"({"edge": )" + std::to_string(e) + R"(, "s": ")" + to_string(s) + "\"}", body)), "") << body;
    const Rational step(1, 1000000 + static_cast<long>(rng() % 1000));
    for (const int side : {1, -1}) {
      const Vec2 off{p.x + side * step * in.x, p.y + side * step * in.y};
      EXPECT_NE(error_of(scene(contact(off, in), body)).find("is not on body.outline"), std::string::npos) << body;
    }
    EXPECT_NE(error_of(scene(contact(p, Vec2{-in.x, -in.y}), body)).find("does not point into the body"), std::string::npos);
    const Scene sc = read_scene(scene(contact(p, in), body), Input_limits{});
    EXPECT_TRUE(sc.body.outline_convex);
    EXPECT_TRUE(sc.body.outline_ccw);
  }
}

}  // namespace
}  // namespace wrenchkit
