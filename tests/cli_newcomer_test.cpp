// What a newcomer hits first, end to end through the `wrenchkit` command: messages that name the likely fix (a
// misspelt or synonymous scene key, command or option; an angle where a direction goes), the labels' text, batch
// reading files, and pictures whose labels do not overprint.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <utility>
#include <vector>

#include "tests/test_support.h"

namespace wrenchkit {
namespace {

namespace fs = std::filesystem;

using test::Cli_result;

fs::path scratch() { return test::scratch_dir("cli_newcomer_test"); }

Cli_result run(const std::string& args, const std::string& stdin_text = "") {
  return test::run_cli(WRENCHKIT_CLI, "", args, stdin_text, "cli_newcomer_test");
}

std::string write(const std::string& name, const std::string& text) {
  const fs::path p = scratch() / name;
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

std::string golden(const std::string& name) { return test::source_dir() + "/tests/golden/" + name + ".scene.json"; }

// The one stderr line of a bad scene, without "wrenchkit: error: " and the newline; exit 2 and nothing on stdout.
std::string scene_error(const std::string& scene) {
  const Cli_result r = run("closure '" + write("bad.json", scene) + "'");
  EXPECT_EQ(r.code, 2) << scene;
  EXPECT_EQ(r.out, "");
  const std::string prefix = "wrenchkit: error: ";
  EXPECT_EQ(r.err.rfind(prefix, 0), 0u) << r.err;
  return r.err.size() > prefix.size() ? r.err.substr(prefix.size(), r.err.size() - prefix.size() - 1) : r.err;
}

// The one stderr line of a usage error, without "wrenchkit: usage error: "; exit 2 and nothing on stdout.
std::string usage_error(const std::string& args) {
  const Cli_result r = run(args);
  EXPECT_EQ(r.code, 2) << args;
  EXPECT_EQ(r.out, "");
  const std::string prefix = "wrenchkit: usage error: ";
  EXPECT_EQ(r.err.rfind(prefix, 0), 0u) << r.err;
  return r.err.size() > prefix.size() ? r.err.substr(prefix.size(), r.err.size() - prefix.size() - 1) : r.err;
}

TEST(Newcomer, AnUnknownSceneKeySaysWhichKeyItLikelyMeans) {
  const std::string c = R"({"wrenchkit": 1, "contacts": [)";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {c + R"({"position": [0, 0], "normal": [1, 0]}]})", "contacts[0]: unknown key \"position\" (did you mean \"at\"?)"},
      {c + R"({"at": [0, 0], "direction": [1, 0]}]})", "contacts[0]: unknown key \"direction\" (did you mean \"normal\"?)"},
      {c + R"({"at": [0, 0], "normal": [1, 0], "friction": 1}]})",
       "contacts[0]: unknown key \"friction\" (did you mean \"mu\"?)"},
      {c + R"({"at": [0, 0], "nromal": [1, 0]}]})", "contacts[0]: unknown key \"nromal\" (did you mean \"normal\"?)"},
      {c + R"({"at": [0, 0], "Normal": [1, 0]}]})", "contacts[0]: unknown key \"Normal\" (did you mean \"normal\"?)"},
      {R"({"wrenchkit": 1, "body": {"center_of_mass": [0, 0]}})",
       "body: unknown key \"center_of_mass\" (did you mean \"com\"?)"},
      {R"({"wrenchkit": 1, "body": {"centre_of_mass": [0, 0]}})",
       "body: unknown key \"centre_of_mass\" (did you mean \"com\"?)"},
      {R"({"wrenchkit": 1, "contact": []})", "scene: unknown key \"contact\" (did you mean \"contacts\"?)"},
      {R"({"version": 1})", "scene: unknown key \"version\" (did you mean \"wrenchkit\"?)"},
      {R"({"wrenchkit": 1, "support": {"mu": 1, "point": []}})", "support: unknown key \"point\" (did you mean \"points\"?)"},
      {R"({"wrenchkit": 1, "support": {"mu": 1, "points": [{"position": [0, 0]}]}})",
       "support.points[0]: unknown key \"position\" (did you mean \"at\"?)"},
      {R"({"wrenchkit": 1, "support": {"mu": 1, "points": [{"at": [0, 0], "force": 1}], "pressure_centre": [0, 0]}})",
       "support: unknown key \"pressure_centre\" (did you mean \"pressure_center\"?)"},
      {R"({"wrenchkit": 1, "load": {"force": [0, 1], "point": [0, 0]}})", "load: unknown key \"point\" (did you mean \"at\"?)"},
      {R"({"wrenchkit": 1, "load": {"weight": 1}})", "load: unknown key \"weight\" (did you mean \"gravity\"?)"},
      {R"({"wrenchkit": 1, "load": {"wrench": [0, 0, 1], "at": [0, 0]}})", "load: unknown key \"at\""},
      {R"({"wrenchkit": 1, "comment": "a grasp"})", "scene: unknown key \"comment\""},
      {c + R"({"wrench": [1, 0, 0], "mu": 1}]})", "contacts[0]: unknown key \"mu\""},
  };
  for (const auto& [scene, message] : cases) EXPECT_EQ(scene_error(scene), message);
}

TEST(Newcomer, AnAngleWhereANormalGoesSaysHowToWriteADirection) {
  const std::string advice =
      " (a normal is a direction [dx, dy] of any length, not an angle: for 30\u00b0 write [0.866025, 0.5], or give an "
      "exact direction such as [4, 3])";
  EXPECT_EQ(scene_error(R"({"wrenchkit": 1, "contacts": [{"at": [0, 0], "normal": 30}]})"),
            "contacts[0].normal: expected an array of 2 numbers, got a number" + advice);
  EXPECT_EQ(scene_error(R"({"wrenchkit": 1, "contacts": [{"at": [0, 0], "normal": "30deg"}]})"),
            "contacts[0].normal: expected an array of 2 numbers, got a string" + advice);
  // Not where no direction goes, and not for an array of the wrong length.
  EXPECT_EQ(scene_error(R"({"wrenchkit": 1, "contacts": [{"at": 30, "normal": [1, 0]}]})"),
            "contacts[0].at: expected an array of 2 numbers, got a number");
  EXPECT_EQ(scene_error(R"({"wrenchkit": 1, "contacts": [{"at": [0, 0], "normal": [1, 0, 0]}]})"),
            "contacts[0].normal: expected an array of 2 numbers, got an array of 3");
}

TEST(Newcomer, BatchLinesGiveTheSameMessages) {
  const std::string scene = R"({"wrenchkit": 1, "contacts": [{"position": [0, 0], "normal": [1, 0]}]})";
  const Cli_result r = run("batch closure", scene + "\n");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out,
            "{\"line\": 1, \"error\": \"contacts[0]: unknown key \\\"position\\\" (did you mean \\\"at\\\"?)\", "
            "\"exit_code\": 2}\n");
}

TEST(Newcomer, AnUnknownCommandOrOptionSaysWhichItLikelyMeans) {
  EXPECT_EQ(usage_error("closre x.json"), "unknown command \"closre\" (did you mean \"closure\"? try wrenchkit --help)");
  EXPECT_EQ(usage_error("label x.json"), "unknown command \"label\" (did you mean \"labels\"? try wrenchkit --help)");
  EXPECT_EQ(usage_error("frobnicate x.json"), "unknown command \"frobnicate\" (try wrenchkit --help)");
  EXPECT_EQ(usage_error("reuleaux --centre 1,1 x.json"), "unknown option --centre (did you mean --center?)");
  EXPECT_EQ(usage_error("closure --jsno x.json"), "unknown option --jsno (did you mean --json?)");
  EXPECT_EQ(usage_error("closure --no-such-option x.json"), "unknown option --no-such-option");
  EXPECT_EQ(usage_error("batch closre").rfind("batch: \"closre\" is not a command that answers per scene (did you mean "
                                              "\"closure\"?): wrenchkit batch ",
                                              0),
            0u);
}

TEST(Newcomer, LabelsSaysWhatIsLabeledAndReadsTheLoad) {
  const Cli_result closed = run("labels '" + golden("triangle_example3_mu_1_10") + "'");
  ASSERT_EQ(closed.code, 0) << closed.err;
  EXPECT_NE(closed.out.find("\nforce closure: yes (nothing labeled, infinity included)\n"), std::string::npos) << closed.out;
  const Cli_result walls = run("labels '" + golden("vertical_walls_squeeze") + "'");
  ASSERT_EQ(walls.code, 0) << walls.err;
  EXPECT_NE(walls.out.find("\nforce closure: no (labeled: points at infinity; closure needs nothing labeled, infinity "
                           "included)\n"),
            std::string::npos)
      << walls.out;
  const Cli_result corner = run("labels '" + golden("equilibrium/block_corner_mu_1_2_gravity") + "'");
  ASSERT_EQ(corner.code, 0) << corner.err;
  EXPECT_NE(corner.out.find("\nforce closure: no (labeled: the + region, the - region and points at infinity; closure "
                            "needs nothing labeled, infinity included)\n"),
            std::string::npos)
      << corner.out;
  EXPECT_NE(corner.out.find("\nload (0, -1, -1/2) ≈ (0, -1, -0.5): balanced (minus the load is a possible contact resultant)\n"),
            std::string::npos)
      << corner.out;
  const Cli_result ladder = run("labels '" + golden("equilibrium/ladder_mu_1_8_gravity") + "'");
  ASSERT_EQ(ladder.code, 0) << ladder.err;
  EXPECT_NE(ladder.out.find(": not balanced (minus the load is not a possible contact resultant)\n"), std::string::npos)
      << ladder.out;
  // The same in --mode float, read on the twin's labels.
  const Cli_result fl = run("labels --mode float '" + golden("equilibrium/block_corner_mu_1_2_gravity") + "'");
  ASSERT_EQ(fl.code, 0) << fl.err;
  EXPECT_NE(fl.out.find("\nforce closure: no (labeled: the + region, the - region and points at infinity; closure"),
            std::string::npos)
      << fl.out;
  EXPECT_NE(fl.out.find(": balanced (minus the load"), std::string::npos) << fl.out;
  // Without a load, no load line.
  EXPECT_EQ(closed.out.find("\nload "), std::string::npos) << closed.out;
}

TEST(Newcomer, BatchReadsFilesInOrderAsStandardInputWouldBe) {
  const std::string a = test::read_text(golden("two_finger_y1_2_mu1_10")), b = test::read_text(golden("single_force"));
  const auto line = [](std::string t) {
    for (char& ch : t)
      if (ch == '\n') ch = ' ';
    return t;
  };
  const std::string first = line(a) + "\n" + "{not json\n", second = line(b);  // the second file without a last newline
  const Cli_result in = run("batch closure --jobs 2", first + second + "\n");
  ASSERT_EQ(in.code, 0) << in.err;
  const Cli_result files = run("batch closure --jobs 2 '" + write("one.jsonl", first) + "' '" + write("two.jsonl", second) + "'");
  ASSERT_EQ(files.code, 0) << files.err;
  EXPECT_EQ(files.out, in.out);
  EXPECT_NE(files.out.find("{\"line\": 3, \"command\": \"closure\""), std::string::npos) << files.out;
  // - is standard input, between files.
  const Cli_result mixed = run("batch closure '" + write("one.jsonl", first) + "' -", second);
  EXPECT_EQ(mixed.out, in.out);
  // A file that cannot be read: exit 2 before any line, nothing on stdout.
  const Cli_result missing = run("batch closure '" + write("one.jsonl", first) + "' /nonexistent/scenes.jsonl");
  EXPECT_EQ(missing.code, 2);
  EXPECT_EQ(missing.out, "");
  EXPECT_NE(missing.err.find("/nonexistent/scenes.jsonl: cannot open"), std::string::npos) << missing.err;
  const Cli_result dir = run("batch closure '" + scratch().string() + "'");
  EXPECT_EQ(dir.code, 2);
  EXPECT_EQ(dir.out, "");
}

// The <text> elements of an SVG: (x, y, text).
struct Svg_text {
  double x, y;
  std::string text;
};
std::vector<Svg_text> texts_of(const std::string& svg) {
  std::vector<Svg_text> out;
  const std::regex re("<text x=\"([-0-9.]+)\" y=\"([-0-9.]+)\"[^>]*>([^<]*)</text>");
  for (std::sregex_iterator i(svg.begin(), svg.end(), re), end; i != end; ++i)
    out.push_back({std::atof((*i)[1].str().c_str()), std::atof((*i)[2].str().c_str()), (*i)[3].str()});
  return out;
}
const Svg_text* find_text(const std::vector<Svg_text>& t, const std::string& s) {
  for (const Svg_text& x : t)
    if (x.text == s) return &x;
  return nullptr;
}
// Two labels of one line of text overprint when their baselines are within a line's height and their starts
// within the first one's width (13px text, about 8px a character).
bool overprint(const Svg_text& a, const Svg_text& b) {
  const double width = 8.0 * static_cast<double>(a.x <= b.x ? a.text.size() : b.text.size());
  return std::abs(a.y - b.y) < 13 && std::abs(a.x - b.x) < width;
}

TEST(Newcomer, PicturesPlaceLabelsApart) {
  const auto render = [](const std::string& what, const std::string& scene) {
    const Cli_result r = run("render --what " + what + " '" + scene + "'");
    EXPECT_EQ(r.code, 0) << r.err;
    return texts_of(r.out);
  };
  // Example 3 in closure: both sheets cover the plane, their captions at one centroid.
  const std::vector<Svg_text> dual = render("dual", golden("triangle_example3_mu_1_10"));
  const Svg_text *plus = find_text(dual, "+ sheet"), *minus = find_text(dual, "\u2212 sheet");
  ASSERT_TRUE(plus && minus);
  EXPECT_FALSE(overprint(*plus, *minus)) << plus->x << "," << plus->y << " " << minus->x << "," << minus->y;
  for (const Svg_text& t : dual) {
    if (&t == plus || &t == minus || t.y >= 720) continue;  // below the disc: the legend and captions
    EXPECT_FALSE(overprint(*plus, t)) << t.text;
    EXPECT_FALSE(overprint(*minus, t)) << t.text;
  }
  // A block in a corner: contacts 0 and 2 at one point.
  const std::vector<Svg_text> corner = render("labels", golden("equilibrium/block_corner_mu_1_2_gravity"));
  const Svg_text *c0 = find_text(corner, "c0"), *c2 = find_text(corner, "c2");
  ASSERT_TRUE(c0 && c2);
  EXPECT_FALSE(overprint(*c0, *c2)) << c0->x << "," << c0->y << " " << c2->x << "," << c2->y;
  // The hold picture: the pin's name and the rotation centre at it.
  const std::vector<Svg_text> hold = render("hold", test::source_dir() + "/proofs/examples/fixture_pin_lift.scene.json");
  const Svg_text* pin = find_text(hold, "c0");
  ASSERT_TRUE(pin);
  std::size_t centres = 0;
  for (const Svg_text& t : hold) {
    if (t.text.find("rotation centre") == std::string::npos) continue;
    EXPECT_FALSE(overprint(*pin, t)) << t.text;
    ++centres;
  }
  EXPECT_EQ(centres, 1u);
}

TEST(Newcomer, TheDualsLegendNamesTheBlackDotsOnTheRim) {
  // A contact at the origin: its generators' moments are zero, their dual points at infinity (black dots on the rim).
  const std::string at_origin = write("origin.json", R"({"wrenchkit": 1, "contacts": [
      {"at": [0, 0], "normal": [1, 0], "mu": "1/2"}, {"at": [1, 1], "normal": [0, -1], "mu": "1/2"}]})");
  const Cli_result r = run("render --what dual '" + at_origin + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find(">black dots on the rim: generators through O (m = 0), their dual points at infinity</text>"),
            std::string::npos);
  const Cli_result none = run("render --what dual '" + golden("triangle_example3_mu_1_10") + "'");
  ASSERT_EQ(none.code, 0) << none.err;
  EXPECT_EQ(none.out.find("black dots on the rim"), std::string::npos);
}

// A support-only scene: analyze says there are no contacts instead of an empty closure; sliding and limit-surface
// asked nothing say what the scene allows to ask (and nothing of it when a question is given).
TEST(CliNewcomer, SupportScenesSayWhatToAsk) {
  const std::string barbell = test::source_dir() + "/docs/quickstart/barbell.json";
  const Cli_result a = run("analyze '" + barbell + "'");
  ASSERT_EQ(a.code, 0) << a.err;
  EXPECT_NE(a.out.find("contacts: none (closure and equilibrium are questions about contacts; the support's friction "
                       "is below)"), std::string::npos) << a.out;
  EXPECT_EQ(a.out.find("force closure:"), std::string::npos) << a.out;
  for (const char* command : {"sliding", "limit-surface"}) {
    const Cli_result bare = run(std::string(command) + " '" + barbell + "'");
    ASSERT_EQ(bare.code, 0) << bare.err;
    EXPECT_NE(bare.out.find("to ask: --load fx,fy,m"), std::string::npos) << command << ": " << bare.out;
    const Cli_result asked = run(std::string(command) + " '" + barbell + "' --twist 0,0,1");
    EXPECT_EQ(asked.out.find("to ask:"), std::string::npos) << command << ": " << asked.out;
  }
  // A contact without "mu" is frictionless by default, and the text says so once (not for a contact with mu).
  const Cli_result pin = run("hold '" + test::source_dir() + "/docs/quickstart/pinned_part.json'");
  EXPECT_NE(pin.out.find("note: c0 (pin) has no \"mu\": frictionless"), std::string::npos) << pin.out;
  const Cli_result fingers = run("closure '" + test::source_dir() + "/docs/quickstart/two_finger.json'");
  EXPECT_EQ(fingers.out.find("note:"), std::string::npos) << fingers.out;
  // A scene-wide "mu" is every point contact's coefficient unless it writes its own: the same answers and certificates
  // as writing it on each contact, the checker reading it the same, and no frictionless note.
  const std::string wide = write("scene_mu.json", R"({"wrenchkit": 1, "contacts": [{"at": [-1, 0], "normal": [1, 0]},
      {"at": [1, 0], "normal": [-1, 0]}, {"at": [0, 1], "normal": [0, -1], "mu": 0}], "mu": "1/2"})");
  const std::string each = write("each_mu.json", R"({"wrenchkit": 1, "contacts": [{"at": [-1, 0], "normal": [1, 0],
      "mu": "1/2"}, {"at": [1, 0], "normal": [-1, 0], "mu": "1/2"}, {"at": [0, 1], "normal": [0, -1], "mu": 0}]})");
  for (const char* mode : {"hybrid", "exact", "float"}) {
    const Cli_result w = run(std::string("closure --json --mode ") + mode + " '" + wide + "'");
    ASSERT_EQ(w.code, 0) << w.err;
    EXPECT_EQ(w.out, run(std::string("closure --json --mode ") + mode + " '" + each + "'").out) << mode;
  }
  EXPECT_EQ(run("closure '" + wide + "'").out.find("note:"), std::string::npos);
  const Cli_result cert = run("closure '" + wide + "' --certificate '" + (scratch() / "wide.cert.json").string() + "'");
  ASSERT_EQ(cert.code, 0) << cert.err;
  EXPECT_EQ(run("check '" + wide + "' '" + (scratch() / "wide.cert.json").string() + "'").code, 0);
  const std::string negative = write("scene_mu_negative.json", R"({"wrenchkit": 1, "mu": "-1", "contacts": []})");
  const Cli_result bad = run("closure '" + negative + "'");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("mu: \"-1\" is negative (must be >= 0)"), std::string::npos) << bad.err;
  // Each contact's force, named, exact and in decimals (equilibrium and hold).
  const Cli_result e = run("equilibrium '" + test::source_dir() + "/docs/quickstart/block_in_corner.json'");
  EXPECT_NE(e.out.find("c0 (floor, left) (1/4, 1/2) ≈ (0.25, 0.5); c1 (floor, right) (-1/4, 1/2) ≈ (-0.25, 0.5)"),
            std::string::npos) << e.out;
}

// Issue 30: a decimal beside every fraction a person reads in text (6 significant digits, from the exact value), JSON's
// `_approx` siblings, twists that are directions as primitive integers, and closure's certificate as named forces.
namespace decimals {

std::string qs(const std::string& name) { return test::source_dir() + "/docs/quickstart/" + name + ".json"; }
std::string eq_golden(const std::string& name) {
  return test::source_dir() + "/tests/golden/equilibrium/" + name + ".scene.json";
}
void has(const Cli_result& r, const std::string& text) {
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find(text), std::string::npos) << "missing: " << text << "\nin:\n" << r.out;
}

TEST(Newcomer, ClosureTextGivesNamedForcesAndCentresWithDecimals) {
  has(run("closure " + qs("two_finger")),
      "certificate: the contact forces c0 (left finger) (2, 0); c1 (right finger) (-2, 0) sum to the zero wrench");
  const Cli_result r = run("closure " + eq_golden("pipe_clamp_mu_1_2_d_3"));
  EXPECT_EQ(r.out.find("·c0"), std::string::npos) << r.out;  // no weights on cone edges in the text any more
  has(r, "rotation about (0, 1/2) ≈ (0, 0.5)");
  // The certificate JSON keeps its weights on the edges.
  has(run("closure --json " + qs("two_finger")), R"("combination": [{"contact": 0, "edge": "left", "weight": "1"})");
}

TEST(Newcomer, EquilibriumHoldAndLabelsShowDecimalsBesideFractions) {
  has(run("equilibrium " + qs("block_in_corner")), "load: the wrench (0, -1, -1/2) ≈ (0, -1, -0.5) (force");
  has(run("equilibrium --json " + qs("block_in_corner")), R"("load": ["0", "-1", "-1/2"], "load_approx": [0, -1, -0.5])");
  has(run("hold " + qs("pinned_part")), "load: the wrench (-1, 1/4, 1/4) ≈ (-1, 0.25, 0.25) on the body");
  const std::string push = eq_golden("block_corner_mu_1_2_push_down_at_3_1");
  has(run("hold " + push), "the body moves: a clockwise rotation about (4/3, -2/3) ≈ (1.33333, -0.666667) (twist (2, 4, -3))");
  has(run("hold --json " + push), R"("center": ["4/3", "-2/3"], "center_approx": [1.3333333333333333, -0.66666666666666663])");
  has(run("labels " + golden("square_aligned")), "the single point (1/2, 1) ≈ (0.5, 1)");
  has(run("labels --json " + qs("block_in_corner")), R"("wrench": ["0", "-1", "-1/2"], "wrench_approx": [0, -1, -0.5])");
}

TEST(Newcomer, SupportAnswersShowDecimalsAndTwistsAsSmallIntegers) {
  // The table's translation slip was (2, 0, 0) and the plate's (13, 0, 0): a direction, so (1, 0, 0) in text and JSON.
  has(run("limit-surface " + qs("table") + " --load 1,0,0"), "the twist (1, 0, 0), a translation along (1, 0)");
  has(run("limit-surface " + qs("plate") + " --load 1,0,0"), "the twist (1, 0, 0), a translation along (1, 0)");
  has(run("limit-surface --json " + qs("table") + " --load 1,0,0"), R"("impending_twist": ["1", "0", "0"])");
  has(run("limit-surface " + qs("barbell") + " --load 1/3,1/7,1/5"),
      "load (1/3, 1/7, 1/5) ≈ (0.333333, 0.142857, 0.2): sticks");
  has(run("limit-surface " + qs("barbell") + " --load 1/2,0,1/2"), "lambda^2 = 28297631961/28574521561 (≈ 0.99031)");
  has(run("limit-surface " + qs("plate") + " --load 0,0,0.5"),
      "sticks with f = (1/2, 0, 0, 0, 1/2, 0, 0, 0, 0) ≈ (0.5, 0, 0, 0, 0.5, 0, 0, 0, 0)");
  has(run("sliding " + qs("pinned_part") + " --twist 2,0,1"), "mu*f0 = 1/2 (≈ 0.5), friction centroid (0, 0)");
  has(run("analyze " + qs("barbell")), "lambda^2 = 28297631961/28574521561 (≈ 0.99031), inner");
  // A queried Reuleaux motion about (1/2, 1/3): the twist (1/3, -1/2, 1) as (2, -3, 6), the centre with decimals.
  has(run("reuleaux " + qs("two_finger") + " --center 1/2,1/3"),
      "twist (2, -3, 6) (a counter-clockwise rotation about (1/2, 1/3) ≈ (0.5, 0.333333)): infeasible");
  has(run("reuleaux --json " + qs("two_finger") + " --center 1/2,1/3"), R"("query": {"twist": ["2", "-3", "6"])");
}

}  // namespace decimals

}  // namespace
}  // namespace wrenchkit
