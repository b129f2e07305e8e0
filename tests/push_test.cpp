// [PU-1] Which way a pushed body turns: golden cases worked by hand (a square on four legs pushed from below: both
// edges ccw; edges apart with the velocity deciding either way or pointing at c; an edge through c with and without
// the velocity's vote; a line support where the translation is smooth and one where it is not; forces not given with
// one coefficient and with two, where the centre moves: depends), the refusals, and the rule against an independent
// oracle: a quasi-static push simulated in doubles on random supports with known forces (proofs/notes/PU-1 §7) —
// never a contradiction; every certificate accepted by the independent checker, tampered ones refused.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "exact/certificates/certificates.h"
#include "exact/io/input_error.h"
#include "exact/io/scene.h"
#include "exact/io/scene_writer.h"
#include "exact/pipeline/push_answer.h"
#include "core/mode.h"
#include "exact/sliding/pushing.h"
#include "exact/sliding/sliding.h"
#include "float/limit_surface_twin.h"
#include "fuzz/scene_checks.h"
#include "proofs/checker/checker.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {

// A square body [-1, 1]² on four legs of force 1 and mu 1/2 (centre of friction at the origin), pushed at `at`
// with normal (0, 1) unless given.
std::string square(const std::string& pusher, const std::string& support = "") {
  return R"({"wrenchkit": 1, "body": {"outline": [[-1, -1], [1, -1], [1, 1], [-1, 1]]}, "support": )" +
         (support.empty() ? R"({"mu": "1/2", "points": [{"at": [-1, -1], "force": 1}, {"at": [1, -1], "force": 1},
            {"at": [1, 1], "force": 1}, {"at": [-1, 1], "force": 1}]})"
                          : support) +
         R"(, "pusher": )" + pusher + "}";
}

// The certificate with `from` replaced by `to` is rejected by the checker for `reason`.
void refused(const std::string& scene, const std::string& cert, const std::string& from, const std::string& to,
             const std::string& reason) {
  EXPECT_TRUE(test::checker_refuses_edit(scene, cert, from, to, reason));
}

Push_item push(const std::string& text) { return answer_push(text, "test", Request{}); }

Rotation rotation(const std::string& text) {
  const Push_item r = push(text);
  EXPECT_EQ(r.status, Status::answered) << r.message << "\n" << text;
  if (r.push.rotation != Rotation::undecided) {
    EXPECT_FALSE(r.certificate.empty());
  }
  return r.push.rotation;
}

TEST(PushGolden, BothEdgesVoteAlike) {
  // p = (1/2, -1), mu 1/4: edges (∓1/4, 1); (p - c) × d = 1/2 ∓ ... > 0 for both: ccw, whatever the velocity.
  EXPECT_EQ(rotation(square(R"({"at": ["1/2", -1], "normal": [0, 1], "mu": "1/4", "velocity": [0, 1]})")), Rotation::ccw);
  EXPECT_EQ(rotation(square(R"({"at": ["1/2", -1], "normal": [0, 1], "mu": "1/4", "velocity": [-5, 1]})")), Rotation::ccw);
  EXPECT_EQ(rotation(square(R"({"at": ["-1/2", -1], "normal": [0, 1], "mu": "1/4", "velocity": [5, 1]})")), Rotation::cw);
  // frictionless pusher: one line, the normal
  EXPECT_EQ(rotation(square(R"({"at": ["-1/2", -1], "normal": [0, 1], "velocity": [1, 1]})")), Rotation::cw);
}

TEST(PushGolden, EdgesApartTheVelocityDecides) {
  // mu 1: edges (-1, 1) votes (1/2)(1) - (-1)(-1) = -1/2 (cw), (1, 1) votes 3/2 (ccw)
  const std::string p = R"({"at": ["1/2", -1], "normal": [0, 1], "mu": 1, "velocity": )";
  EXPECT_EQ(rotation(square(p + "[1, 1]}")), Rotation::ccw);
  EXPECT_EQ(rotation(square(p + "[-1, 1]}")), Rotation::cw);
  EXPECT_EQ(rotation(square(p + "[-1, 2]}")), Rotation::none);  // along p -> c: a translation
  const Push_item r = push(square(p + "[-1, 2]}"));
  EXPECT_NE(r.push.why.find("translates"), std::string::npos) << r.push.why;
}

TEST(PushGolden, AnEdgeThroughTheCentre) {
  // mu 1/2 at (1/2, -1): the left edge (-1/2, 1) passes through c = (0, 0)
  const std::string p = R"({"at": ["1/2", -1], "normal": [0, 1], "mu": "1/2", "velocity": )";
  EXPECT_EQ(rotation(square(p + "[0, 1]}")), Rotation::ccw);    // the velocity votes with the right edge
  EXPECT_EQ(rotation(square(p + "[-1, 1]}")), Rotation::none);  // it does not: a translation along pc
  EXPECT_EQ(rotation(square(p + "[-1, 2]}")), Rotation::none);  // through c itself
  // a frictionless push along a line through c: none
  EXPECT_EQ(rotation(square(R"({"at": [0, -1], "normal": [0, 1], "velocity": [1, 1]})")), Rotation::none);
}

TEST(PushGolden, LineSupportsAndTheSmoothTranslation) {
  // two legs on the x axis; the pusher's tied edge is along d = c - p = (-1/2, 1): the legs are off the line through
  // c perpendicular to d, so the translation's point of the limit surface is smooth: none.
  const std::string legs = R"({"mu": "1/2", "points": [{"at": [-1, 0], "force": 1}, {"at": [1, 0], "force": 1}]})";
  EXPECT_EQ(rotation(square(R"({"at": ["1/2", -1], "normal": [0, 1], "mu": "1/2", "velocity": [-1, 1]})", legs)),
            Rotation::none);
  // pushed straight at c from below with mu = 0, legs on the x axis: the friction lies on the line through c
  // perpendicular to pc — the body can turn about a point of that line: the votes do not decide.
  const Push_item r = push(square(R"({"at": [0, -1], "normal": [0, 1], "velocity": [1, 1]})", legs));
  ASSERT_EQ(r.status, Status::answered) << r.message;
  EXPECT_EQ(r.push.rotation, Rotation::undecided);
  EXPECT_TRUE(r.push.line_friction_possible);
  EXPECT_TRUE(r.certificate.empty());
  // the same with a region under the body: friction over an area, none
  const std::string region =
      R"({"mu": "1/2", "regions": [{"outline": [[-1, -1], [1, -1], [1, 1], [-1, 1]], "pressure": "uniform", "force": 4}]})";
  EXPECT_EQ(rotation(square(R"({"at": [0, -1], "normal": [0, 1], "velocity": [1, 1]})", region)), Rotation::none);
  // and a region off-centre pushed from below through (0, -1): c = (1/2, 0) on the right: cw? the push line x = 0
  // passes left of c, pushing up: cw.
  const std::string right =
      R"({"mu": "1/2", "regions": [{"outline": [[0, -1], [1, -1], [1, 1], [0, 1]], "pressure": "uniform", "force": 2}]})";
  EXPECT_EQ(rotation(square(R"({"at": [0, -1], "normal": [0, 1], "velocity": [0, 1]})", right)), Rotation::cw);
}

TEST(PushGolden, ForcesNotGiven) {
  // one coefficient: c is the centre of pressure for every distribution
  const std::string uniform = R"({"mu": "1/2", "weight": 4, "pressure_center": [0, 0], "points": [{"at": [-1, -1]},
     {"at": [1, -1]}, {"at": [1, 1]}, {"at": [-1, 1]}]})";
  const Push_item u = push(square(R"({"at": ["1/2", -1], "normal": [0, 1], "mu": "1/4", "velocity": [0, 1]})", uniform));
  ASSERT_EQ(u.status, Status::answered) << u.message;
  EXPECT_EQ(u.push.rotation, Rotation::ccw);
  ASSERT_TRUE(u.push.center);
  EXPECT_EQ(u.push.center->x, 0);
  EXPECT_EQ(u.push.center->y, 0);
  // two coefficients: c = (-9a/10) / (11a/10 + b) along x moves over [-9/11, 0]; a push up along x = -1/10 depends
  const std::string two = R"({"weight": 4, "pressure_center": [0, 0], "points": [{"at": [-1, 0], "mu": 1},
     {"at": [1, 0], "mu": "1/10"}, {"at": [0, 1], "mu": "1/2"}, {"at": [0, -1], "mu": "1/2"}]})";
  const Push_item d = push(square(R"({"at": ["-1/10", -1], "normal": [0, 1], "velocity": [0, 1]})", two));
  ASSERT_EQ(d.status, Status::answered) << d.message;
  EXPECT_EQ(d.push.rotation, Rotation::depends);
  EXPECT_FALSE(d.push.center);
  EXPECT_EQ(d.push.turns_ccw, (std::vector<Rational>{2, 2, 0, 0}));
  EXPECT_EQ(d.push.turns_cw, (std::vector<Rational>{0, 0, 2, 2}));
  // a push along x = 1/10 passes right of every such c: ccw for all, certified by the LP's duals
  const Push_item a = push(square(R"({"at": ["1/10", -1], "normal": [0, 1], "velocity": [0, 1]})", two));
  EXPECT_EQ(a.push.rotation, Rotation::ccw);
  EXPECT_NE(a.certificate.find("dual_lower"), std::string::npos);
}

TEST(PushRefusals, ClearErrorsNamingTheField) {
  const auto message = [](const std::string& text) {
    const Push_item r = push(text);
    EXPECT_EQ(r.status, Status::bad_input) << text;
    return r.message;
  };
  EXPECT_EQ(message(square(R"({"at": ["1/2", -1], "normal": [0, 1], "velocity": [0, -1]})")).rfind("pusher.velocity: (0, -1) moves away", 0), 0u);
  EXPECT_EQ(message(square(R"({"at": ["1/2", -1], "normal": [0, 1], "velocity": [1, 0]})")).rfind("pusher.velocity: (1, 0) is tangent", 0), 0u);
  EXPECT_EQ(message(square(R"({"at": [0, 0], "normal": [0, 1], "velocity": [0, 1]})")).rfind("pusher.at: (0, 0) is not on body.outline", 0), 0u);
  EXPECT_EQ(message(square(R"({"at": [0, -1], "normal": [0, -1], "velocity": [0, -1]})")).rfind("pusher.normal", 0), 0u);
  EXPECT_EQ(message(square(R"({"at": [0, -1], "normal": [0, 1]})")).rfind("pusher: missing key \"velocity\"", 0), 0u);
  EXPECT_EQ(message(square(R"({"wrench": [0, 1, 0], "velocity": [0, 1]})")).rfind("pusher: is a point contact", 0), 0u);
  EXPECT_EQ(message(R"({"wrenchkit": 1, "support": {"mu": 1, "points": [{"at": [0, 0], "force": 1}]}})").rfind("pusher: missing", 0), 0u);
  EXPECT_EQ(message(R"({"wrenchkit": 1, "pusher": {"at": [0, 0], "normal": [0, 1], "velocity": [0, 1]}})").rfind("support: missing", 0), 0u);
  EXPECT_EQ(message(square(R"({"at": [0, -1], "normal": [0, 1], "velocity": [0, 1]})",
                           R"({"mu": 0, "points": [{"at": [0, 0], "force": 1}]})")).rfind("support: no friction", 0), 0u);
  // placed on the outline: edge 0 at s = 3/4 is (1/2, -1), its inward normal (0, 2)
  const Push_item placed = push(square(R"({"edge": 0, "s": "3/4", "mu": "1/4", "velocity": [0, 1]})"));
  ASSERT_EQ(placed.status, Status::answered) << placed.message;
  EXPECT_EQ(placed.push.at.x, Rational(1, 2));
  EXPECT_EQ(placed.push.normal.y, 2);
  EXPECT_EQ(placed.push.rotation, Rotation::ccw);
}

TEST(PushScene, WrittenBackReadsTheSame) {
  const Scene s = read_scene(square(R"({"edge": 0, "s": "3/4", "mu": "1/4", "velocity": [0, 1], "name": "finger"})"),
                             Input_limits{});
  const Scene t = read_scene(write_scene(s), Input_limits{});
  ASSERT_TRUE(t.pusher);
  EXPECT_EQ(t.pusher->contact.at.x, Rational(1, 2));
  EXPECT_EQ(t.pusher->contact.normal.y, 2);
  EXPECT_EQ(t.pusher->contact.mu, Rational(1, 4));
  EXPECT_EQ(t.pusher->velocity.y, 1);
  EXPECT_EQ(t.pusher->contact.name, "finger");
  EXPECT_EQ(write_scene(t), write_scene(s));
  // a line pusher keeps its segment and rotation rate
  const Scene l = read_scene(square(R"({"segment": [["-1/2", -1], ["1/2", -1]], "normal": [0, 1], "mu": "1/2",
                                        "velocity": [0, 1], "omega": "-1/10"})"), Input_limits{});
  const Scene m = read_scene(write_scene(l), Input_limits{});
  ASSERT_TRUE(m.pusher && m.pusher->line());
  EXPECT_EQ(m.pusher->end->x, Rational(1, 2));
  EXPECT_EQ(m.pusher->omega, Rational(-1, 10));
  EXPECT_EQ(write_scene(m), write_scene(l));
}

// Every reader reads the pusher alike (the one-pass reader in one pass, the tree reader, eager and lazy, into fresh
// and reused scenes), refuses alike, and the scene-wide budget counts its numbers the same at its boundary. (A pusher
// placed by {"edge", "s"} is read by the tree reader, as placed contacts are: PushRefusals above.)
TEST(PushScene, EveryReaderAlikeAndTheBudgetCountsIt) {
  Scene reused_eager, reused_lazy;
  const std::vector<std::string> texts = {
      square(R"({"at": ["1/2", -1], "normal": [0, 1], "mu": "1/4", "velocity": [0, 1], "name": "finger"})"),
      square(R"({"at": ["1/2", -1], "normal": [0, 1], "velocity": ["1e-30", 1]})"),  // no mu: frictionless
      R"({"wrenchkit": 1, "mu": "1/3", "pusher": {"at": [0, 0], "normal": [0, 1], "velocity": [1, 1]},
          "support": {"mu": 1, "points": [{"at": [0, 1], "force": 1}, {"at": [1, 1], "force": 2}]}})",  // the scene's mu
      R"({"wrenchkit": 1, "pusher": {"velocity": [1, 1], "mu": 0.25, "normal": [0, 1], "at": [0.5, 0]}, "mu": 2})",
      square(R"({"at": ["1/2", -1], "normal": [0, 1], "velocity": [1, 0]})"),   // tangent: refused
      square(R"({"at": ["1/2", -1], "normal": [0, 1], "mu": 1})"),               // no velocity: refused
      square(R"({"wrench": [0, 1, 0], "velocity": [0, 1]})"),                   // a wrench: refused
      square(R"({"at": ["1/2", -1], "normal": [0, 1], "velocity": [0, 1], "speed": 2})"),  // unknown key: refused
      square(R"({"at": ["1/2", -1], "normal": [0, 0], "velocity": [0, 1]})"),   // zero normal: refused
      // a line pusher (PU-3): its segment and rotation rate
      square(R"({"segment": [["-1/2", -1], ["1/2", -1]], "normal": [0, 1], "mu": "1/2", "velocity": [0, 1], "omega": "1/10"})"),
      square(R"({"segment": [["-1/2", -1], ["1/2", -1]], "normal": [0, 1], "velocity": [0, 1], "name": "fence"})"),
      square(R"({"segment": [["-1/2", -1], ["1/2", -1]], "at": [0, -1], "normal": [0, 1], "velocity": [0, 1]})"),  // both
      square(R"({"at": [0, -1], "normal": [0, 1], "velocity": [0, 1], "omega": 1})"),  // omega without a segment
      square(R"({"segment": [["-1/2", -1]], "normal": [0, 1], "velocity": [0, 1]})"),  // one end
      square(R"({"segment": [["-1/2", -1], ["1/2", -1]], "normal": [0, 1], "velocity": [0, 1], "omega": []})"),
  };
  for (const std::string& t : texts) {
    EXPECT_EQ(readers_disagree(t, Input_limits{}, reused_eager, reused_lazy), "") << t;
    bool valid = true;
    try {
      read_scene(t, Input_limits{});
    } catch (const Input_error&) {
      valid = false;
    }
    if (valid) {
      EXPECT_EQ(budget_boundary_broken(t, Input_limits{}, reused_eager, reused_lazy), "") << t;
      const Scene s = read_scene(t, Input_limits{});
      EXPECT_TRUE(s.pusher) << t;
    }
  }
  // the pusher's numbers count in the scene-wide budget: 10 000 digits in its velocity are refused under 9 999
  Input_limits tight;
  tight.max_total_digits = 9999;
  const std::string big = square(R"({"at": ["1/2", -1], "normal": [0, 1], "velocity": [")" + std::string(5000, '7') +
                                 "/" + std::string(5000, '3') + R"(", 1]})");
  try {
    read_scene(big, tight);
    ADD_FAILURE() << "a pusher over the digit budget was read";
  } catch (const Input_error& e) {
    EXPECT_NE(std::string(e.what()).find("--max-total-digits"), std::string::npos) << e.what();
  }
}

TEST(PushCertificate, TamperedOnesAreRefused) {
  const std::string scene = square(R"({"at": ["1/2", -1], "normal": [0, 1], "mu": 1, "velocity": [1, 1]})");
  const Push_item r = push(scene);
  ASSERT_EQ(r.push.rotation, Rotation::ccw);
  const auto verdict = [&](std::string cert, const std::string& from, const std::string& to) {
    const std::size_t at = cert.rfind(from);  // (the last: the velocity's vote of the votes)
    EXPECT_NE(at, std::string::npos) << from << " in " << cert;
    cert.replace(at, from.size(), to);
    return wrenchkit_checker::check(scene, cert);
  };
  EXPECT_EQ(wrenchkit_checker::check(scene, r.certificate).outcome, wrenchkit_checker::Outcome::accepted);
  const auto refused = [&](const std::string& from, const std::string& to, const std::string& reason) {
    const wrenchkit_checker::Result v = verdict(r.certificate, from, to);
    EXPECT_EQ(v.outcome, wrenchkit_checker::Outcome::rejected) << from << " -> " << to;
    EXPECT_NE(v.message.find(reason), std::string::npos) << v.message;
  };
  refused(R"("rotation": "ccw")", R"("rotation": "cw")", "rotation: \"cw\", but votes");
  refused(R"("rotation": "ccw")", R"("rotation": "none")", "rotation: \"none\", but votes");
  refused(R"("wrenchkit_certificate": 6)", R"("wrenchkit_certificate": 5)", "is format 6");
  // D = 4 legs x 1/2
  refused(R"("friction": {"lower": "2"})", R"("friction": {"lower": "3"})", "friction.lower");
  refused(R"("friction": {"lower": "2"})", R"("friction": {"lower": "2", "dual_lower": ["0", "0", "0"]})", "no dual");
  // the velocity's vote (1/2)(1) - (-1)(1) = 3/2 times D = 2: claim an upper bound below it
  refused(R"("upper": "3")", R"("upper": "-1")", "votes[2].upper");
  refused(R"("center": ["0", "0"])", R"("center": ["0", "1"])", "center: (0, 1) is not the centre of friction");
  refused(R"("rotation": "ccw")", R"("rotation": "ccw", "mu": "1")", "key \"mu\" is not allowed when \"property\" is \"push\"");
  // depends with a distribution that is not the scene's
  const std::string two = square(R"({"at": ["-1/10", -1], "normal": [0, 1], "velocity": [0, 1]})",
                                 R"({"weight": 4, "pressure_center": [0, 0], "points": [{"at": [-1, 0], "mu": 1},
     {"at": [1, 0], "mu": "1/10"}, {"at": [0, 1], "mu": "1/2"}, {"at": [0, -1], "mu": "1/2"}]})");
  const Push_item d = push(two);
  ASSERT_EQ(d.push.rotation, Rotation::depends);
  EXPECT_EQ(wrenchkit_checker::check(two, d.certificate).outcome, wrenchkit_checker::Outcome::accepted);
  std::string bad = d.certificate;
  const std::string was = R"("ccw": ["2", "2", "0", "0"])";
  ASSERT_NE(bad.find(was), std::string::npos) << bad;
  bad.replace(bad.find(was), was.size(), R"("ccw": ["0", "0", "2", "2"])");
  const wrenchkit_checker::Result v = wrenchkit_checker::check(two, bad);
  EXPECT_EQ(v.outcome, wrenchkit_checker::Outcome::rejected) << bad;
  EXPECT_NE(v.message.find("turns.ccw"), std::string::npos) << v.message;
}

// [PU-2] The contact mode through the pipeline, certified: the square pushed with μ = 1 along (1, 1) sticks (the
// body moves with the pusher, turning ccw at about 0.536 — the simulation's sticking rate is inside the bracket); with
// μ = 1/2 along (−1, 1) it slides on the left edge (the force the sticking motion needs is beyond it); a region is not
// answered yet (undecided, exit 3); tampered contact claims are refused.
TEST(PushContact, GoldenModesAndTamperedClaims) {
  Push_query q;
  q.contact = true;
  const std::string stick = square(R"({"at": ["1/2", -1], "normal": [0, 1], "mu": 1, "velocity": [1, 1]})");
  const Push_item a = answer_push(stick, "test", Request{}, q);
  ASSERT_EQ(a.status, Status::answered) << a.message;
  ASSERT_TRUE(a.push.contact);
  EXPECT_EQ(a.push.contact->mode, Push_mode::sticks);
  EXPECT_LT(a.push.contact->omega_lo, a.push.contact->omega_hi);
  EXPECT_GT(a.push.contact->omega_lo, Rational(536, 1000));
  EXPECT_LT(a.push.contact->omega_hi, Rational(537, 1000));
  EXPECT_LE(a.push.contact->omega_hi - a.push.contact->omega_lo, Rational(1, 1000000000));
  const Push_item b = answer_push(square(R"({"at": ["1/2", -1], "normal": [0, 1], "mu": "1/2", "velocity": [-1, 1]})"),
                                  "test", Request{}, q);
  ASSERT_EQ(b.status, Status::answered) << b.message;
  EXPECT_EQ(b.push.contact->mode, Push_mode::slides_left);
  // through c exactly: a translation along (−1/2, 1), which is the left edge: on the edge (impending)
  const Push_item e = answer_push(square(R"({"at": ["1/2", -1], "normal": [0, 1], "mu": "1/2", "velocity": [-1, 2]})"),
                                  "test", Request{}, q);
  ASSERT_EQ(e.status, Status::answered) << e.message;
  EXPECT_EQ(e.push.contact->mode, Push_mode::impending);
  EXPECT_EQ(e.push.contact->omega_lo, 0);
  const std::string region =
      R"({"mu": "1/2", "regions": [{"outline": [[-1, -1], [1, -1], [1, 1], [-1, 1]], "pressure": "uniform", "force": 4}]})";
  const Push_item g = answer_push(square(R"({"at": [0, -1], "normal": [0, 1], "velocity": [1, 1]})", region), "test",
                                  Request{}, q);
  EXPECT_EQ(g.push.contact->mode, Push_mode::undecided);
  // the checker: each certificate accepted; a changed mode, a bracket end moved across the root, too few bits refused
  EXPECT_EQ(wrenchkit_checker::check(stick, a.certificate).outcome, wrenchkit_checker::Outcome::accepted);
  refused(stick, a.certificate, R"("mode": "sticks")", R"("mode": "slides left")", "needs \"tangent_omega\"");
  const Rational near_hi = a.push.contact->omega_hi - (a.push.contact->omega_hi - a.push.contact->omega_lo) / 10;
  refused(stick, a.certificate, "\"omega\": [\"" + to_string(a.push.contact->omega_lo) + "\"",
          "\"omega\": [\"" + to_string(near_hi) + "\"", "not certainly negative");
  refused(stick, a.certificate, R"("bits": 64)", R"("bits": 3)", "expected bits from 16 to 4096");
  const std::string slide = square(R"({"at": ["1/2", -1], "normal": [0, 1], "mu": "1/2", "velocity": [-1, 1]})");
  EXPECT_EQ(wrenchkit_checker::check(slide, b.certificate).outcome, wrenchkit_checker::Outcome::accepted);
  refused(slide, b.certificate, R"("mode": "slides left")", R"("mode": "slides right")", "not certainly beyond");
  // a sliding contact carries its sliding motion: a sticking claim with it is refused for that
  refused(slide, b.certificate, R"("mode": "slides left")", R"("mode": "sticks")", "only a sliding contact has");
  // the body's motion while sliding (PU-2 §5). The left edge (−1/2, 1) through c = 0: the translation along it with
  // the pusher's normal speed 1, u = (−1/2, 1) = v + τ (−1, 0) with τ = −1/2 exactly, ω = 0.
  ASSERT_TRUE(b.push.contact->has_motion) << b.push.contact->motion_why;
  EXPECT_EQ(b.push.contact->slip_lo, Rational(-1, 2));
  EXPECT_EQ(b.push.contact->slip_hi, Rational(-1, 2));
  EXPECT_EQ(b.push.contact->motion_lo, 0);
  EXPECT_EQ(b.push.contact->motion_hi, 0);
  refused(slide, b.certificate, R"("slip": ["-1/2", "-1/2"])", R"("slip": ["-1/4", "-1/4"])", "an exact slip is only");
  // μ = 1/4 along (1, 1): slides on the right edge, slipping τ ≈ 0.3184902 along (−1, 0) and turning at ω ≈ 0.4257531
  // (the quasi-static simulation's values: PushOracle below checks such brackets on thousands of pushes)
  const std::string right = square(R"({"at": ["1/2", -1], "normal": [0, 1], "mu": "1/4", "velocity": [1, 1]})");
  const Push_item c = answer_push(right, "test", Request{}, q);
  ASSERT_EQ(c.status, Status::answered) << c.message;
  ASSERT_EQ(c.push.contact->mode, Push_mode::slides_right);
  ASSERT_TRUE(c.push.contact->has_motion) << c.push.contact->motion_why;
  EXPECT_LT(c.push.contact->slip_lo, c.push.contact->slip_hi);
  EXPECT_GT(c.push.contact->slip_lo, Rational(3184901, 10000000));
  EXPECT_LT(c.push.contact->slip_hi, Rational(3184902, 10000000));
  EXPECT_GT(c.push.contact->motion_lo, Rational(4257531, 10000000));
  EXPECT_LT(c.push.contact->motion_hi, Rational(4257532, 10000000));
  EXPECT_EQ(wrenchkit_checker::check(right, c.certificate).outcome, wrenchkit_checker::Outcome::accepted);
  refused(right, c.certificate, "\"omega\": [\"" + to_string(c.push.contact->motion_lo) + "\"",
          "\"omega\": [\"" + to_string(c.push.contact->motion_hi) + "\"", "over the slip bracket");
}

// [PU-2 §7] A sticking pivot, worked by hand. Legs (0, 0) (ρ 1), (2, 0) (ρ 1) and (0, 2) (ρ 1/8); the pusher at
// p = (1, −1), normal (0, 1), μ = 1, moving v = (1, 1) ⟂ (0, 0) − p: the rotation about the leg at the origin with
// ω = 1 moves p with v. The other legs move along (0, 2) and (−2, 0): F' = (0, 1) + (−1/8, 0) = (−1/8, 1), their moment
// about p M' = (1, 1) × (0, 1) + (−1, 3) × (−1/8, 0) = 1 + 3/8 = 11/8 < ρ_0 |d| = √2: g jumps across 0 at ω = 1, the
// sticking candidate is the pivot. Its forces through p: d × F = d × F' − M' = −7/8 − 11/8 = −9/4 with d = (−1, 1),
// i.e. F_x + F_y = 9/4, within |F − F'| ≤ 1: the chord's middle (9/16, 27/16) = (9/16)(1, 3) is inside the cone
// |F_x| < F_y, and |λe − F'|² = |(11/16, 11/16)|² = 242/256 < 1. It sticks, turning at exactly 1 about (0, 0).
TEST(PushContact, StickingPivotWorkedByHand) {
  Push_query q;
  q.contact = true;
  const auto scene = [](const std::string& third, const std::string& velocity) {
    return R"({"wrenchkit": 1, "support": {"points": [{"at": [0, 0], "force": 1, "mu": 1}, {"at": [2, 0], "force": 1, "mu": 1}, )" +
           third + R"(]}, "pusher": {"at": [1, -1], "normal": [0, 1], "mu": 1, "velocity": )" + velocity + "}}";
  };
  const std::string t = scene(R"({"at": [0, 2], "force": "1/8", "mu": 1})", "[1, 1]");
  const Push_item a = answer_push(t, "test", Request{}, q);
  ASSERT_EQ(a.status, Status::answered) << a.message;
  ASSERT_TRUE(a.push.contact);
  const Push_contact& c = *a.push.contact;
  EXPECT_EQ(c.mode, Push_mode::sticks) << c.why;
  ASSERT_TRUE(c.pivot && c.force);
  EXPECT_EQ(*c.pivot, 0u);
  EXPECT_EQ(c.omega_lo, 1);
  EXPECT_EQ(c.omega_hi, 1);
  EXPECT_EQ(c.force->x, Rational(9) / 16);
  EXPECT_EQ(c.force->y, Rational(27) / 16);
  EXPECT_EQ(wrenchkit_checker::check(t, a.certificate).outcome, wrenchkit_checker::Outcome::accepted) << a.certificate;
  const auto refused_here = [&](const std::string& from, const std::string& to, const std::string& reason) {
    refused(t, a.certificate, from, to, reason);
  };
  refused_here(R"("omega": ["1", "1"])", R"("omega": ["2", "2"])", "the rotation about the pivot has omega 1");
  refused_here(R"("pivot": 0)", R"("pivot": 1)", "not perpendicular");
  refused_here(R"("force": ["9/16", "27/16"])", R"("force": ["1", "0"])", "not strictly inside the friction cone");
  refused_here(R"("force": ["9/16", "27/16"])", R"("force": ["1", "5"])", "no force of the pivot's facet");  // (F = (3/8, 15/8): |F − F'|² > 1)
  refused_here(R"("mode": "sticks")", R"("mode": "impending")", "\"force\" is a sticking pivot's");
  // the third leg heavier: M' = 1 + 3ρ > √2 for ρ = 1/4, the jump misses 0 — the root is no pivot, the usual bracket
  const Push_item b = answer_push(scene(R"({"at": [0, 2], "force": "1/4", "mu": 1})", "[1, 1]"), "test", Request{}, q);
  ASSERT_EQ(b.status, Status::answered) << b.message;
  EXPECT_FALSE(b.push.contact->pivot);
  EXPECT_NE(b.push.contact->omega_lo, b.push.contact->omega_hi);
  // nearby velocities (not perpendicular: no leg at rest) are decided by the ordinary bracket: they stick too, their
  // rates closing in on 1 from both sides — the pivot's answer is the limit of its neighbours'
  for (const char* v : {R"(["1", "1.000000001"])", R"(["1.000000001", "1"])"}) {
    const Push_item n = answer_push(scene(R"({"at": [0, 2], "force": "1/8", "mu": 1})", v), "test", Request{}, q);
    ASSERT_EQ(n.status, Status::answered) << n.message;
    EXPECT_EQ(n.push.contact->mode, Push_mode::sticks) << v;
    EXPECT_FALSE(n.push.contact->pivot);
    EXPECT_LT(abs(n.push.contact->omega_lo - 1), Rational(1, 1000)) << v;
  }
}

// [PU-2 §8] Sliding from a sticking pivot, worked by hand: the legs of StickingPivotWorkedByHand with the pusher's μ
// lowered. The sticking motion is still the rotation about (0, 0) at ω = 1 (M' = 11/8 < √2), its forces through p the
// chord F_x + F_y = 9/4 of the unit disc about F' = (−1/8, 1): middle (9/16, 27/16), half-length √(1 − M'²/|d|²) =
// √(7/128) along (1, −1)/√2, so its ends are ((9 ± √7)/16, (27 ∓ √7)/16). Every force of it is beyond the right edge
// (μ, 1) — F_x > μ F_y — exactly when μ < (9 − √7)/(27 + √7) ≈ 0.2143394. The certificate's inequality at μ = 1/5, with
// l = −rot90(e_R) = (1, −1/5): A = |d|² l·F' − M' l·rot90(d) = 2(−13/40) − (11/8)(−4/5) = 9/20 > 0 and A² = 81/400 >
// (l·d)²(ρ²|d|² − M'²) = (36/25)(7/64) = 63/400. μ = 3/14 (5·10⁻⁵ below the threshold) slides too; 134/625 (6·10⁻⁵
// above) sticks.
TEST(PushContact, SlidingFromAStickingPivotWorkedByHand) {
  Push_query q;
  q.contact = true;
  const auto scene = [](const std::string& mu) {
    return R"({"wrenchkit": 1, "support": {"points": [{"at": [0, 0], "force": 1, "mu": 1}, {"at": [2, 0], "force": 1, "mu": 1}, {"at": [0, 2], "force": "1/8", "mu": 1}]}, "pusher": {"at": [1, -1], "normal": [0, 1], "mu": ")" +
           mu + R"(", "velocity": [1, 1]}})";
  };
  for (const char* mu : {"1/5", "3/14", "134/625"}) {
    const std::string t = scene(mu);
    const Push_item a = answer_push(t, "test", Request{}, q);
    ASSERT_EQ(a.status, Status::answered) << a.message;
    const Push_contact& c = *a.push.contact;
    const bool slides = std::string(mu) != "134/625";
    EXPECT_EQ(c.mode, slides ? Push_mode::slides_right : Push_mode::sticks) << mu << ": " << c.why;
    ASSERT_TRUE(c.pivot) << mu;
    EXPECT_EQ(*c.pivot, 0u);
    EXPECT_EQ(c.omega_lo, 1);
    EXPECT_EQ(c.omega_hi, 1);
    EXPECT_EQ(c.force.has_value(), !slides);
    EXPECT_EQ(wrenchkit_checker::check(t, a.certificate).outcome, wrenchkit_checker::Outcome::accepted) << a.certificate;
    if (!slides) continue;
    // the sliding motion: it slips right (τ > 0) and turns ccw, near the pivot's rate
    ASSERT_TRUE(c.has_motion) << c.motion_why;
    EXPECT_GT(c.slip_lo, 0);
    EXPECT_GT(c.motion_lo, Rational(9, 10));
    EXPECT_LT(c.motion_hi, 1);
    refused(t, a.certificate, R"("mode": "slides right")", R"("mode": "slides left")", "not every force of the pivot's facet");
    refused(t, a.certificate, R"("pivot": 0)", R"("pivot": 1)", "not perpendicular");
    refused(t, a.certificate, R"("omega": ["1", "1"])", R"("omega": ["2", "2"])", "the rotation about the pivot has omega 1");
  }
  // The same sliding claim on the scene with μ = 1/4, where the chord crosses the right edge: refused.
  const Push_item a = answer_push(scene("1/5"), "test", Request{}, q);
  EXPECT_EQ(wrenchkit_checker::check(scene("1/4"), a.certificate).outcome, wrenchkit_checker::Outcome::rejected);
}

// [PU-2 §8] The tangent a pivot: legs (0, 0) (ρ 1), (±1, 1) (ρ 1/8 each); the pusher at (0, −1), normal (0, 1), μ =
// 1/10, moving (1, 1). The tangent t = (−1, 0) is ⟂ the line to (0, 0): the rotation about it at ω = −1 moves p with t.
// The others then move along (1, ∓1)/√2: F' = (√2/8, 0), M' = −3/(4√2) ≈ −0.530 > −ρ_0|d| = −1, so the jump holds 0 and
// F(t) is the chord F_x = √2/8 − 3/(4√2) = −√2/4 ≈ −0.3536, |F_y| ≤ √(1 − 9/32) ≈ 0.848. The right edge (1/10, 1) has
// e_R × F = F_y/10 − F_x ≥ 0.3536 − 0.0848 > 0 on all of it: e_R is among the forces that push, and the contact slides
// right (before, the tangent's bracket closed in on the pivot without deciding: undecided).
TEST(PushContact, TheTangentAPivotWorkedByHand) {
  Push_query q;
  q.contact = true;
  const std::string t =
      R"({"wrenchkit": 1, "support": {"points": [{"at": [0, 0], "force": 1, "mu": 1}, {"at": [1, 1], "force": "1/8", "mu": 1}, {"at": [-1, 1], "force": "1/8", "mu": 1}]}, "pusher": {"at": [0, -1], "normal": [0, 1], "mu": "1/10", "velocity": [1, 1]}})";
  const Push_item a = answer_push(t, "test", Request{}, q);
  ASSERT_EQ(a.status, Status::answered) << a.message;
  const Push_contact& c = *a.push.contact;
  EXPECT_EQ(c.mode, Push_mode::slides_right) << c.why;
  ASSERT_TRUE(c.tangent_pivot);
  EXPECT_EQ(*c.tangent_pivot, 0u);
  EXPECT_EQ(c.tangent_lo, -1);
  EXPECT_EQ(c.tangent_hi, -1);
  EXPECT_FALSE(c.pivot);
  EXPECT_TRUE(c.has_motion) << c.motion_why;
  EXPECT_EQ(wrenchkit_checker::check(t, a.certificate).outcome, wrenchkit_checker::Outcome::accepted) << a.certificate;
  refused(t, a.certificate, R"("tangent_pivot": 0)", R"("tangent_pivot": 1)", "not perpendicular");
  refused(t, a.certificate, R"("tangent_omega": ["-1", "-1"])", R"("tangent_omega": ["-2", "-2"])", "has omega -1");
}

// [PU-2 §7] On random supports (fixed seed) with the pusher's velocity perpendicular to the line to a random leg. The
// velocity turned by ±10⁻⁹ (no leg at rest: the ordinary bracket) is the oracle: its force is near the ccw (cw) end of
// the pivot's chord of forces, so where the engine answers a sticking pivot (accepted by the checker) the two turned
// velocities do not both slide past the same edge, and one that sticks turns at a rate within 10⁻³ of the pivot's;
// where it says every force of the facet is beyond an edge (PU-2 §8: it slides from the facet), both slide past that
// edge — and every answer's certificate is accepted by the checker.
TEST(PushContact, StickingPivotsAgreeWithTheirNeighbours) {
  std::mt19937_64 rng(20261129);
  std::uniform_int_distribution<int> coord(-10, 10), force(1, 10), tenth(1, 10), small(-5, 5), count(2, 6);
  Push_query q;
  q.contact = true;
  int pivots = 0, missed = 0, both_stick = 0, slides_with_motion = 0;
  for (int sc = 0; sc < 400; ++sc) {
    const std::uint64_t seed = rng();
    std::mt19937_64 r(seed);
    const int k = count(r);
    std::vector<std::array<int, 2>> at;
    std::ostringstream pts;
    for (int i = 0; i < k; ++i) {
      at.push_back({coord(r), coord(r)});
      pts << (i ? ", " : "") << R"({"at": [)" << at.back()[0] << ", " << at.back()[1] << R"(], "force": )" << force(r)
          << R"(, "mu": ")" << tenth(r) << "/10\"}";
    }
    const int px = coord(r), py = coord(r), j = static_cast<int>(r() % k);
    const int dx = at[j][0] - px, dy = at[j][1] - py;
    int nx = small(r), ny = small(r);
    if (nx == 0 && ny == 0) ny = 1;
    if (dx == 0 && dy == 0) continue;
    int vx = -dy, vy = dx;  // ⟂ d, pushing into the body
    if (vx * nx + vy * ny < 0) vx = -vx, vy = -vy;
    if (vx * nx + vy * ny == 0) continue;
    const int mu10 = tenth(r);
    const auto text = [&](const std::string& v) {
      return R"({"wrenchkit": 1, "support": {"points": [)" + pts.str() + R"(]}, "pusher": {"at": [)" +
             std::to_string(px) + ", " + std::to_string(py) + R"(], "normal": [)" + std::to_string(nx) + ", " +
             std::to_string(ny) + R"(], "mu": ")" + std::to_string(mu10) + R"(/10", "velocity": )" + v + "}}";
    };
    const std::string t = text("[" + std::to_string(vx) + ", " + std::to_string(vy) + "]");
    const Push_item a = answer_push(t, "test", Request{}, q);
    if (a.status != Status::answered || !a.push.contact) continue;
    const Push_contact& c = *a.push.contact;
    ASSERT_NE(c.mode, Push_mode::undecided) << c.why << "\n" << test::dump_failure(t, "sticking_pivot");
    if (!c.pivot) continue;
    const bool pivot = c.mode == Push_mode::sticks, misses = !pivot;
    (pivot ? pivots : missed) += 1;
    const auto& pv = at[*c.pivot];  // (that leg, or another on the same line through p)
    ASSERT_EQ((pv[0] - px) * vx + (pv[1] - py) * vy, 0) << test::dump_failure(t, "sticking_pivot");
    ASSERT_EQ(wrenchkit_checker::check(t, a.certificate).outcome, wrenchkit_checker::Outcome::accepted)
        << test::dump_failure(t, "sticking_pivot");
    if (misses) slides_with_motion += c.has_motion;
    const Rational e(1, 1000000000);
    Push_mode m[2];
    for (const int side : {0, 1}) {  // v ± 10⁻⁹·rot90(v)
      const int sign = side ? -1 : 1;
      const Rational tx = vx - sign * e * vy, ty = vy + sign * e * vx;
      const Push_item n = answer_push(text("[\"" + to_string(tx) + "\", \"" + to_string(ty) + "\"]"), "test", Request{}, q);
      ASSERT_EQ(n.status, Status::answered) << n.message;
      m[side] = n.push.contact->mode;
      if (m[side] == Push_mode::sticks && pivot) {
        ASSERT_LT(abs(n.push.contact->omega_lo - c.omega_lo), abs(c.omega_lo) / 1000 + Rational(1, 1000000))
            << "seed " << seed << "\n" << test::dump_failure(t, "sticking_pivot");
      }
      if (misses) {
        ASSERT_EQ(m[side], c.mode) << "seed " << seed << "\n" << test::dump_failure(t, "sticking_pivot");
      }
    }
    if (pivot) {
      const bool past_one_edge = m[0] == m[1] && (m[0] == Push_mode::slides_left || m[0] == Push_mode::slides_right);
      ASSERT_FALSE(past_one_edge) << "seed " << seed << "\n" << test::dump_failure(t, "sticking_pivot");
      both_stick += m[0] == Push_mode::sticks && m[1] == Push_mode::sticks;
    }
  }
  EXPECT_GT(pivots, 20);
  EXPECT_GT(both_stick, 10);
  EXPECT_GT(missed, 5);
  EXPECT_EQ(slides_with_motion, missed);
  std::printf("sticking pivots: %d answered (%d with both neighbours sticking); %d slide from the facet (%d with the "
              "sliding motion)\n", pivots, both_stick, missed, slides_with_motion);
}

// One model (issue 33): the body's twist that push --contact brackets, handed to the limit surface's own load of a
// twist (the float twin's ∇h, the engine's one construction, with its certified bounds): that load is a force through
// the pusher — along the claimed cone edge when sliding, strictly inside the cone when sticking — and the twist's
// velocity at the pusher is the pusher's plus the slip along its face. 300 random pushes (fixed seed), every force
// given; the twist from the brackets' midpoints (the brackets are 10⁻¹² wide), so the relations hold to 10⁻⁶.
TEST(PushContact, TheMotionIsTheLimitSurfacesOwnTwistForThePushersForce) {
  std::mt19937_64 rng(20261130);
  std::uniform_int_distribution<int> coord(-10, 10), force(1, 10), tenth(1, 10), small(-5, 5), count(2, 7);
  int sticks = 0, slides = 0, pivots = 0, exact_pivots = 0;
  for (int sc = 0; sc < 300; ++sc) {
    const std::uint64_t seed = rng();
    std::mt19937_64 r(seed);
    const int k = count(r);
    std::ostringstream t;
    t << R"({"wrenchkit": 1, "support": {"points": [)";
    for (int i = 0; i < k; ++i)
      t << (i ? ", " : "") << R"({"at": [)" << coord(r) << ", " << coord(r) << R"(], "force": )" << force(r)
        << R"(, "mu": ")" << tenth(r) << "/10\"}";
    int nx = small(r), ny = small(r), vx = small(r), vy = small(r);
    if (nx == 0 && ny == 0) ny = 1;
    if (vx * nx + vy * ny <= 0) vx += 6 * nx, vy += 6 * ny;
    if (vx * nx + vy * ny <= 0) continue;
    t << R"(]}, "pusher": {"at": [)" << coord(r) << ", " << coord(r) << R"(], "normal": [)" << nx << ", " << ny
      << R"(], "mu": ")" << tenth(r) - 1 << R"(/10", "velocity": [)" << vx << ", " << vy << "]}}";
    const std::string text = t.str();
    const Scene scene = read_scene(text, Input_limits{});
    const Push_contact c = push_contact_mode(Support_model(scene), *scene.pusher, Rational(1, 1000000) / 1000000);
    const bool sliding = c.mode == Push_mode::slides_left || c.mode == Push_mode::slides_right;
    if (c.mode != Push_mode::sticks && !(sliding && c.has_motion)) continue;
    const Contact& pc = scene.pusher->contact;
    const double px = pc.at.x.get_d(), py = pc.at.y.get_d(), nnx = pc.normal.x.get_d(), nny = pc.normal.y.get_d();
    const double mu = pc.mu.get_d();
    const double tau = sliding ? Rational((c.slip_lo + c.slip_hi) / 2).get_d() : 0.0;
    const double w = sliding ? Rational((c.motion_lo + c.motion_hi) / 2).get_d() : Rational((c.omega_lo + c.omega_hi) / 2).get_d();
    const double ux = vx - tau * nny, uy = vy + tau * nnx;  // v + τ rot90(n)
    const fl::Bounded3 q{fl::Bounded::exact(ux + w * py), fl::Bounded::exact(uy - w * px), fl::Bounded::exact(w)};
    const fl::Load_twin L = fl::load_for_twist(twin_support(merge_support(*scene.support)), q);
    if (!L.decided || !L.facet_points.empty()) continue;  // a pivot's load is a set (not this check's)
    // Near a pivot (the motion a rotation about a support point: a facet of the limit surface, whose loads form a set
    // — the sliding motion often is one, robustly) the load of the midpoint twist swings: counted, not checked here.
    bool pivot = false;
    for (const Support_point& sp : scene.support->points) {
      const double rx = sp.at.x.get_d(), ry = sp.at.y.get_d();
      pivot |= std::hypot(q[0].v - w * ry, q[1].v + w * rx) < 1e-6 * (std::hypot(ux, uy) + std::fabs(w));
    }
    if (pivot) {
      ++pivots;
      exact_pivots += (sliding ? c.motion_pivot : c.pivot).has_value();
      continue;
    }
    EXPECT_FALSE((sliding ? c.motion_pivot : c.pivot).has_value()) << "seed " << seed << ": an exact pivot whose points all move\n" << text;
    const double fx = L.load[0].v, fy = L.load[1].v, m = L.load[2].v, f = std::hypot(fx, fy);
    ASSERT_GT(f, 0) << "seed " << seed << "\n" << text;
    const double arm = 10 * std::hypot(px, py) + 10;
    EXPECT_LT(std::fabs(m - (px * fy - py * fx)), 1e-6 * f * arm) << "seed " << seed << ": the load misses the pusher\n" << text;
    const double nn = std::hypot(nnx, nny), ex = nnx / nn, ey = nny / nn, tx = -ey, ty = ex;
    const double eLx = ex + mu * tx, eLy = ey + mu * ty, eRx = ex - mu * tx, eRy = ey - mu * ty;
    const double right = (eRx * fy - eRy * fx) / f, left = (fx * eLy - fy * eLx) / f;
    if (c.mode == Push_mode::sticks) {
      ++sticks;
      EXPECT_GT(std::min(right, left), -1e-9) << "seed " << seed << ": the sticking force leaves the cone\n" << text;
    } else {
      ++slides;
      const bool on_left = c.mode == Push_mode::slides_left;
      EXPECT_LT(std::fabs(on_left ? left : right), 1e-6) << "seed " << seed << ": the sliding force is off its edge\n"
                                                         << text;
      EXPECT_GT(on_left ? fx * eLx + fy * eLy : fx * eRx + fy * eRy, 0) << "seed " << seed << "\n" << text;
      EXPECT_GT(on_left ? -tau : tau, 0) << "seed " << seed << ": the slip opposes the friction's side\n" << text;
    }
  }
  std::printf("[ push one model ] 300 pushes: the limit surface's load of the bracketed twist through the pusher on %d "
              "sticking (inside the cone) and %d sliding (on the claimed edge); %d motions a rotation about a support "
              "point (not checked here; %d of them answered exactly as that pivot, PU-2 §6)\n", sticks, slides, pivots,
              exact_pivots);
  EXPECT_GT(exact_pivots, 20);
  EXPECT_GT(sticks, 30);
  EXPECT_GT(slides, 30);
}

// ---- the oracle: a quasi-static push in doubles (proofs/notes/PU-1 §7) ----

struct Sim {
  std::vector<double> x, y, w;  // support points and mu_i f_i
  double px, py, nx, ny, mu, vx, vy;
};

// The load (the pusher's force and moment about the origin) of the twist (a, b, om); a support point at rest under
// it (a pivot: its friction anywhere in its disc) is left out and returned in *pivot.
void load(const Sim& s, double a, double b, double om, double& fx, double& fy, double& m, int* pivot = nullptr) {
  fx = fy = m = 0;
  double scale = std::fabs(a) + std::fabs(b);
  for (std::size_t i = 0; i < s.x.size(); ++i) scale = std::max(scale, std::fabs(om) * (std::fabs(s.x[i]) + std::fabs(s.y[i])));
  if (pivot) *pivot = -1;
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    const double ux = a - om * s.y[i], uy = b + om * s.x[i], n = std::hypot(ux, uy);
    if (n <= 1e-12 * scale) {
      if (pivot) *pivot = static_cast<int>(i);
      continue;
    }
    fx += s.w[i] * ux / n, fy += s.w[i] * uy / n, m += s.w[i] * (s.x[i] * uy - s.y[i] * ux) / n;
  }
}

// The twist whose velocity at p is (qx, qy) and whose load can pass through p: the moment about p of the load,
// nondecreasing in ω (the derivative of the convex power along the rotation about p), is zero — by bisection. A
// root at a jump is a pivot about a support point (returned in *pivot, with the rest's load); else *pivot = -1.
double omega_through_p(const Sim& s, double qx, double qy, double& fx, double& fy, double& m, int& pivot) {
  const auto g = [&](double om) {
    double ffx, ffy, mm;
    load(s, qx + om * s.py, qy - om * s.px, om, ffx, ffy, mm);
    return mm - (s.px * ffy - s.py * ffx);
  };
  double lo = -1, hi = 1;
  while (g(lo) > 0) lo *= 2;
  while (g(hi) < 0) hi *= 2;
  for (int k = 0; k < 200 && hi - lo > 1e-13 * (std::fabs(lo) + std::fabs(hi)) + 1e-200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (g(mid) < 0 ? lo : hi) = mid;
  }
  double dsum = 0;
  for (double w : s.w) dsum += w;
  const double om = 0.5 * (lo + hi), jump = g(hi) - g(lo);
  load(s, qx + om * s.py, qy - om * s.px, om, fx, fy, m, &pivot);
  if (jump < 1e-6 * dsum * 40) pivot = -1;  // continuous: not a pivot
  return om;
}

double cross2(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

// At a pivot about support point j with the rest's load (fx, fy, m): the forces g at r_j, |g| <= w_j, with which the
// whole load passes through p form a chord of the disc; its ends' total forces (false: none).
bool pivot_chord(const Sim& s, int j, double fx, double fy, double m, double (&f0)[2], double (&f1)[2]) {
  // moment about p of (F + g at r_j): (m - p x F) + (r_j - p) x g = 0
  const double rx = s.x[j] - s.px, ry = s.y[j] - s.py, c = m - cross2(s.px, s.py, fx, fy), rr = std::hypot(rx, ry);
  if (rr == 0) return false;
  // g = g0 + t u with u along r_j - p, g0 = the nearest point of the line r x g = -c: g0 = -c rot90(r)/|r|^2 ... sign:
  // r x (a rot90(r)) = a |r|^2, so a = -c / |r|^2
  const double a = -c / (rr * rr), g0x = -a * ry, g0y = a * rx, d = std::hypot(g0x, g0y), w = s.w[j];
  if (d > w) return false;
  const double h = std::sqrt(w * w - d * d), ux = rx / rr, uy = ry / rr;
  f0[0] = fx + g0x - h * ux, f0[1] = fy + g0y - h * uy, f1[0] = fx + g0x + h * ux, f1[1] = fy + g0y + h * uy;
  return true;
}

// The sticking candidate's ω (the twist with the pusher's velocity at p whose load passes through p) and the contact
// mode it implies: 0 sticks, +1 slides left (its force beyond n + μ rot90 n), −1 slides right, 2 not told (a pivot,
// or within 1e-9 of an edge).
int sim_contact(const Sim& s, double& om) {
  const double nn = std::hypot(s.nx, s.ny), ux = s.nx / nn, uy = s.ny / nn, tx = -uy, ty = ux;
  const double eL[2] = {ux + s.mu * tx, uy + s.mu * ty}, eR[2] = {ux - s.mu * tx, uy - s.mu * ty};
  double fx, fy, m;
  int pivot;
  om = omega_through_p(s, s.vx, s.vy, fx, fy, m, pivot);
  if (pivot >= 0) return 2;
  const double f = std::hypot(fx, fy), right = cross2(eR[0], eR[1], fx, fy), left = cross2(fx, fy, eL[0], eL[1]);
  if (std::fabs(right) < 1e-9 * f || std::fabs(left) < 1e-9 * f) return 2;
  if (right > 0 && left > 0) return 0;
  return right < 0 ? -1 : 1;
}

// The body's ω under the push, or NaN when the simulation cannot tell (within its tolerances); *mode (if given): 0
// sticks, +1 slides with its force on the left edge, −1 on the right edge, 2 not told.
double simulate(const Sim& s, int* mode = nullptr) {
  int unused;
  int& out_mode = mode ? *mode : unused;
  out_mode = 2;
  const double nn = std::hypot(s.nx, s.ny), ux = s.nx / nn, uy = s.ny / nn, tx = -uy, ty = ux;  // n̂, τ̂ = rot90 n̂
  const double eL[2] = {ux + s.mu * tx, uy + s.mu * ty}, eR[2] = {ux - s.mu * tx, uy - s.mu * ty};
  const auto in_cone = [&](double fx, double fy, double tol) {  // strictly inside pos{eR, eL} by tol·|f|
    const double f = std::hypot(fx, fy);
    return cross2(eR[0], eR[1], fx, fy) > tol * f && cross2(fx, fy, eL[0], eL[1]) > tol * f;
  };
  double fx, fy, m;
  int pivot;
  const double om = omega_through_p(s, s.vx, s.vy, fx, fy, m, pivot);
  if (pivot < 0) {
    if (in_cone(fx, fy, 1e-9)) return out_mode = 0, om;  // sticks
    if (in_cone(fx, fy, -1e-9)) return NAN;  // on an edge, within the tolerance
  } else {
    double f0[2], f1[2];
    if (!pivot_chord(s, pivot, fx, fy, m, f0, f1)) return NAN;
    // sticking at the pivot: some point of the chord inside the cone (both ends' sides tell)
    const double a0 = cross2(eR[0], eR[1], f0[0], f0[1]), a1 = cross2(eR[0], eR[1], f1[0], f1[1]);
    const double b0 = cross2(f0[0], f0[1], eL[0], eL[1]), b1 = cross2(f1[0], f1[1], eL[0], eL[1]);
    if ((a0 > 0 && b0 > 0) || (a1 > 0 && b1 > 0)) return out_mode = 0, om;
    if ((a0 > 0) != (a1 > 0) && (b0 > 0) != (b1 > 0)) return NAN;  // (the chord may cross the cone: not decided here)
  }
  // slides, on one edge: the body slips along +τ̂ (edge R) or −τ̂ (edge L) relative to the pusher. Try both edges,
  // every root of the force's side of the edge over a grid of slip speeds; keep the admissible solutions.
  std::vector<double> found;
  std::vector<int> edges;  // −1 right, +1 left, per solution found
  for (int which = 0; which < 2; ++which) {
    const double* e = which == 0 ? eR : eL;
    const double sigma = which == 0 ? 1 : -1;
    struct At {
      double side, om, fx, fy, m;
      int pivot;
    };
    const auto at = [&](double kappa) {
      At r;
      r.om = omega_through_p(s, s.vx + sigma * kappa * tx, s.vy + sigma * kappa * ty, r.fx, r.fy, r.m, r.pivot);
      r.side = cross2(e[0], e[1], r.fx, r.fy);
      return r;
    };
    double prev_k = 0;
    At prev = at(0);
    for (int k = 0; k <= 120; ++k) {
      const double kappa = 1e-6 * std::pow(10.0, k / 10.0);
      const At cur = at(kappa);
      if ((prev.side > 0) != (cur.side > 0)) {
        double lo = prev_k, hi = kappa;
        At alo = prev, ahi = cur;
        for (int it = 0; it < 100 && hi - lo > 1e-13 * hi; ++it) {
          const double mid = 0.5 * (lo + hi);
          const At am = at(mid);
          if ((am.side > 0) == (alo.side > 0)) lo = mid, alo = am;
          else hi = mid, ahi = am;
        }
        const double fn = std::hypot(alo.fx, alo.fy);
        if (std::fabs(alo.side) < 1e-7 * fn && std::fabs(ahi.side) < 1e-7 * fn && alo.pivot < 0 && ahi.pivot < 0) {
          if (alo.fx * e[0] + alo.fy * e[1] > 0) found.push_back(alo.om), edges.push_back(which == 0 ? -1 : 1);
        } else {
          // a jump: a pivot; admissible when some force of its chord lies along +e
          const At& pv = alo.pivot >= 0 ? alo : ahi;
          double f0[2], f1[2];
          if (pv.pivot >= 0 && pivot_chord(s, pv.pivot, pv.fx, pv.fy, pv.m, f0, f1)) {
            const double c0 = cross2(e[0], e[1], f0[0], f0[1]), c1 = cross2(e[0], e[1], f1[0], f1[1]);
            if ((c0 > 0) != (c1 > 0)) {
              const double t = c0 / (c0 - c1), gx = f0[0] + t * (f1[0] - f0[0]), gy = f0[1] + t * (f1[1] - f0[1]);
              if (gx * e[0] + gy * e[1] > 0) found.push_back(pv.om), edges.push_back(which == 0 ? -1 : 1);
            }
          } else if (pv.pivot < 0) {
            return NAN;  // a jump the simulation cannot explain
          }
        }
      }
      prev = cur, prev_k = kappa;
    }
  }
  if (found.empty()) return NAN;
  for (double o : found)
    if ((o > 0) != (found[0] > 0)) return NAN;  // (two solutions turning apart: not expected; the test counts it)
  bool one_edge = true;
  for (int e : edges) one_edge &= e == edges[0];
  if (one_edge) out_mode = edges[0];
  return found[0];
}

TEST(PushOracle, VotingTheoremAgainstAQuasiStaticSimulation) {
  const char* env = std::getenv("WRENCHKIT_PUSH_ORACLE_SCENES");
  const int scenes = env ? std::atoi(env) : 250;
  const int per_scene = 20;
  std::mt19937_64 rng(20261129);
  std::uniform_int_distribution<int> coord(-10, 10), force(1, 10), tenth(1, 10), small(-5, 5), count(2, 7);
  int decided = 0, cases = 0, certified = 0, twin_certain = 0, modes_decided = 0, sticking_checked = 0;
  int sliding_checked = 0, sliding_unbracketed = 0;
  for (int sc = 0; sc < scenes; ++sc) {
    const std::uint64_t seed = rng();
    std::mt19937_64 r(seed);
    Sim s;
    const int k = count(r);
    std::vector<int> X(k), Y(k), M(k);
    for (int i = 0; i < k; ++i) X[i] = coord(r), Y[i] = coord(r), M[i] = tenth(r);
    int nx = small(r), ny = small(r);
    if (nx == 0 && ny == 0) ny = 1;
    const int px = coord(r), py = coord(r), mup = tenth(r) - 1;  // pusher mu in 0 .. 9/10 (tenths)
    int vx = small(r), vy = small(r);
    if (vx * nx + vy * ny <= 0) vx += 6 * nx, vy += 6 * ny;  // into the body
    if (vx * nx + vy * ny <= 0) continue;
    for (int d = 0; d < per_scene; ++d) {
      std::vector<int> F(k);
      for (int i = 0; i < k; ++i) F[i] = force(r);
      std::ostringstream t;
      t << R"({"wrenchkit": 1, "support": {"points": [)";
      s.x.clear(), s.y.clear(), s.w.clear();
      for (int i = 0; i < k; ++i) {
        t << (i ? ", " : "") << R"({"at": [)" << X[i] << ", " << Y[i] << R"(], "force": )" << F[i] << R"(, "mu": ")"
          << M[i] << "/10\"}";
        s.x.push_back(X[i]), s.y.push_back(Y[i]), s.w.push_back(M[i] / 10.0 * F[i]);
      }
      t << R"(]}, "pusher": {"at": [)" << px << ", " << py << R"(], "normal": [)" << nx << ", " << ny << R"(], "mu": ")"
        << mup << R"(/10", "velocity": [)" << vx << ", " << vy << "]}}";
      s.px = px, s.py = py, s.nx = nx, s.ny = ny, s.mu = mup / 10.0, s.vx = vx, s.vy = vy;
      const std::string text = t.str();
      const Scene scene = read_scene(text, Input_limits{});
      const Support_model model(scene);
      const Push_answer a = decide_push(model, *scene.pusher);
      ++cases;
      // the float twin: certain only where it is right
      const Push_answer twin = decide_push(model, *scene.pusher, Mode::float_only);
      if (twin.rotation != Rotation::undecided) {
        ++twin_certain;
        ASSERT_TRUE(twin.by_twin);
        ASSERT_EQ(twin.rotation, a.rotation) << "seed " << seed << ": the twin says " << rotation_name(twin.rotation)
                                             << ", the exact rule " << rotation_name(a.rotation) << "\n" << text;
      }
      int sim_mode = 2;  // the mode of the solution the simulation found (sticking, or sliding on one edge)
      const double om = simulate(s, &sim_mode);
      // the contact mode (PU-2) against the simulation: the same mode, and ω* in the sticking bracket
      {
        const Push_contact pc = push_contact_mode(model, *scene.pusher, Rational(1, 1000000));
        double om_s = 0;
        sim_contact(s, om_s);  // the sticking candidate's ω
        if (pc.mode != Push_mode::undecided) ++modes_decided;
        if (pc.mode != Push_mode::undecided && sim_mode != 2) {
          const int mode = pc.mode == Push_mode::sticks ? 0 : pc.mode == Push_mode::slides_left ? 1 : pc.mode == Push_mode::slides_right ? -1 : 3;
          ASSERT_EQ(mode, sim_mode) << "seed " << seed << " distribution " << d << ": the engine says "
                                    << push_mode_name(pc.mode) << "\nscene: " << text;
          if ((pc.mode == Push_mode::slides_left || pc.mode == Push_mode::slides_right) && !std::isnan(om)) {
            // the body's sliding motion (PU-2 §5): the simulation's rate in the certified bracket
            if (pc.has_motion) {
              ++sliding_checked;
              const double lo = pc.motion_lo.get_d(), hi = pc.motion_hi.get_d(), slack = 1e-7 * (1 + std::fabs(om));
              ASSERT_TRUE(lo - slack <= om && om <= hi + slack)
                  << "seed " << seed << ": the simulated sliding rate " << om << " outside [" << lo << ", " << hi
                  << "]\nscene: " << text;
            } else {
              ++sliding_unbracketed;
            }
          }
          if (pc.mode == Push_mode::sticks) {
            ++sticking_checked;
            const double lo = pc.omega_lo.get_d(), hi = pc.omega_hi.get_d(), slack = 1e-9 * (1 + std::fabs(om_s));
            ASSERT_TRUE(lo - slack <= om_s && om_s <= hi + slack)
                << "seed " << seed << ": omega* " << om_s << " outside [" << lo << ", " << hi << "]\nscene: " << text;
          }
        }
      }
      // the oracle abstains near a tie of its own doubles (the exact tests cover ties)
      double dsum = 0;
      for (double w : s.w) dsum += w;
      const double scale = dsum * 40 * std::hypot(nx, ny) * 2;
      bool near_tie = std::isnan(om) || std::fabs(om) < 1e-7;
      for (const Push_vote& v : a.votes) near_tie |= std::fabs(v.value.lower.get_d()) < 1e-9 * scale;
      if (near_tie) continue;
      ++decided;
      const Rotation want = om > 0 ? Rotation::ccw : Rotation::cw;
      ASSERT_EQ(a.rotation, want) << "seed " << seed << " distribution " << d << ": the simulation turns the body "
                                  << (om > 0 ? "ccw" : "cw") << " (omega " << om << "), the rule says "
                                  << rotation_name(a.rotation) << " (" << a.why << ")\nscene: " << text;
      if (d == 0) {  // the pipeline's certificate, checked (the contact mode's too), on one distribution per scene
        Push_query with_contact;
        with_contact.contact = true;
        const Push_item item = answer_push(text, "test", Request{}, with_contact);
        ASSERT_EQ(item.status, Status::answered) << item.message << "\n" << text;
        ++certified;
      }
    }
  }
  EXPECT_GE(decided, cases * 9 / 10) << decided << " of " << cases << " decided by the simulation";
  EXPECT_GE(twin_certain, cases * 9 / 10) << "the twin decided " << twin_certain << " of " << cases;
  std::printf("[ push oracle ] %d scenes x %d distributions: %d cases, %d decided by the simulation, all agree; %d "
              "certificates checked; the float twin certain on %d, all equal to the exact rule; contact mode decided on "
              "%d (as simulated), omega* bracketed on %d sticking; the sliding motion's rate bracketed on %d (as "
              "simulated), not bracketed on %d\n", scenes, per_scene,
              cases, decided, certified, twin_certain, modes_decided, sticking_checked, sliding_checked,
              sliding_unbracketed);
  EXPECT_GT(sliding_checked, scenes);
  EXPECT_GT(certified, scenes / 2);
}

}  // namespace
}  // namespace wrenchkit

namespace wrenchkit {
namespace {

// Over the admissible distributions: supports whose forces are not given (the weight and the centre of pressure of a
// random distribution), with different coefficients, so that c moves. The engine's answer for all of F against the
// simulation at random distributions of F (convex combinations of its vertices) and, for depends, at its witnesses.
TEST(PushOracle, OverTheAdmissibleDistributions) {
  const char* env = std::getenv("WRENCHKIT_PUSH_ORACLE_SCENES");
  const int scenes = env ? std::atoi(env) / 2 : 150;
  std::mt19937_64 rng(202611292);
  std::uniform_int_distribution<int> coord(-10, 10), force(0, 10), tenth(1, 10), small(-5, 5), count(3, 6);
  std::uniform_real_distribution<double> unit01(0, 1);
  int checked = 0, answers[5] = {0, 0, 0, 0, 0};
  for (int sc = 0; sc < scenes; ++sc) {
    const std::uint64_t seed = rng();
    std::mt19937_64 r(seed);
    const int k = count(r);
    std::vector<int> X(k), Y(k), M(k), F(k);
    int W = 0, mx = 0, my = 0;
    for (int i = 0; i < k; ++i) X[i] = coord(r), Y[i] = coord(r), M[i] = tenth(r), F[i] = force(r);
    for (int i = 0; i < k; ++i) W += F[i], mx += F[i] * X[i], my += F[i] * Y[i];
    if (W == 0) continue;
    int nx = small(r), ny = small(r);
    if (nx == 0 && ny == 0) ny = 1;
    const int px = coord(r), py = coord(r), mup = tenth(r) - 1;
    int vx = small(r), vy = small(r);
    if (vx * nx + vy * ny <= 0) vx += 6 * nx, vy += 6 * ny;
    if (vx * nx + vy * ny <= 0) continue;
    std::ostringstream t;
    t << R"({"wrenchkit": 1, "support": {"weight": )" << W << R"(, "pressure_center": [")" << mx << "/" << W << R"(", ")"
      << my << "/" << W << R"("], "points": [)";
    for (int i = 0; i < k; ++i)
      t << (i ? ", " : "") << R"({"at": [)" << X[i] << ", " << Y[i] << R"(], "mu": ")" << M[i] << "/10\"}";
    t << R"(]}, "pusher": {"at": [)" << px << ", " << py << R"(], "normal": [)" << nx << ", " << ny << R"(], "mu": ")"
      << mup << R"(/10", "velocity": [)" << vx << ", " << vy << "]}}";
    const std::string text = t.str();
    const Push_item item = push(text);
    ASSERT_EQ(item.status, Status::answered) << item.message << "\n" << text;
    const Push_answer& a = item.push;
    ++answers[static_cast<int>(a.rotation)];
    const Scene scene = read_scene(text, Input_limits{});
    const Support_model model(scene);
    const std::vector<std::vector<Rational>>& V = model.extreme();
    Sim s;
    s.px = px, s.py = py, s.nx = nx, s.ny = ny, s.mu = mup / 10.0, s.vx = vx, s.vy = vy;
    for (int i = 0; i < k; ++i) s.x.push_back(X[i]), s.y.push_back(Y[i]);
    const auto simulate_at = [&](const std::vector<double>& f) -> double {
      s.w.clear();
      for (int i = 0; i < k; ++i) s.w.push_back(M[i] / 10.0 * f[i]);
      // the votes in doubles, to leave near ties to the exact tests
      double D = 0, cx = 0, cy = 0;
      for (int i = 0; i < k; ++i) D += s.w[i], cx += s.w[i] * X[i], cy += s.w[i] * Y[i];
      cx /= D, cy /= D;
      const double nn = std::hypot(nx, ny), ux = nx / nn, uy = ny / nn;
      const double dirs[3][2] = {{ux - s.mu * uy, uy + s.mu * ux}, {ux + s.mu * uy, uy - s.mu * ux}, {double(vx), double(vy)}};
      for (const auto& d : dirs)
        if (std::fabs(cross2(px - cx, py - cy, d[0], d[1])) < 1e-6 * (40 * std::hypot(d[0], d[1]))) return NAN;
      const double om = simulate(s);
      return std::fabs(om) < 1e-7 ? NAN : om;
    };
    if (a.rotation == Rotation::ccw || a.rotation == Rotation::cw) {
      for (int d = 0; d < 20; ++d) {
        std::vector<double> f(k, 0.0);
        double total = 0;
        for (int j = 0; j < 3; ++j) {
          const double w = unit01(r);
          total += w;
          const std::vector<Rational>& v = V[std::uniform_int_distribution<std::size_t>(0, V.size() - 1)(r)];
          for (int i = 0; i < k; ++i) f[i] += w * v[i].get_d();
        }
        for (double& x : f) x /= total;
        const double om = simulate_at(f);
        if (std::isnan(om)) continue;
        ++checked;
        ASSERT_EQ(om > 0 ? Rotation::ccw : Rotation::cw, a.rotation)
            << "seed " << seed << ": a distribution of F turns the body " << (om > 0 ? "ccw" : "cw") << " (omega " << om
            << "), the answer for every distribution is " << rotation_name(a.rotation) << "\nscene: " << text;
      }
    } else if (a.rotation == Rotation::depends) {
      for (int side = 0; side < 2; ++side) {
        const std::vector<Rational>& w = side == 0 ? a.turns_ccw : a.turns_cw;
        std::vector<double> f;
        for (const Rational& x : w) f.push_back(x.get_d());
        const double om = simulate_at(f);
        if (std::isnan(om)) continue;
        ++checked;
        ASSERT_EQ(om > 0, side == 0) << "seed " << seed << ": the witness that turns the body "
                                     << (side == 0 ? "ccw" : "cw") << " is simulated turning it the other way\nscene: " << text;
      }
    }
  }
  std::printf("[ push oracle over F ] %d scenes: ccw %d, cw %d, none %d, depends %d, undecided %d; %d distributions "
              "simulated, all agree\n", scenes, answers[0], answers[1], answers[2], answers[3], answers[4], checked);
  EXPECT_GT(checked, scenes * 5);
  EXPECT_GT(answers[3], 0);  // the family reaches depends
}

}  // namespace
}  // namespace wrenchkit
