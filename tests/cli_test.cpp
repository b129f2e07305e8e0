// End-to-end tests of the `wrenchkit` command: exit codes (docs/cli.md), messages on stderr,
// nothing on stdout for bad input, certificates written and re-checked, every bad-input class.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "exact/io/json.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {

namespace fs = std::filesystem;

using test::Cli_result;

fs::path scratch() { return test::scratch_dir("cli_test"); }

// Runs the command with `env` (e.g. "VAR=value") in front of it.
Cli_result run_env(const std::string& env, const std::string& args, const std::string& stdin_text = "") {
  return test::run_cli(WRENCHKIT_CLI, env, args, stdin_text, "cli_test");
}

Cli_result run(const std::string& args, const std::string& stdin_text = "") { return run_env("", args, stdin_text); }

std::string write(const std::string& name, const std::string& text) {
  const fs::path p = scratch() / name;
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

std::string golden(const std::string& name) {
  return test::source_dir() + "/tests/golden/" + name + ".scene.json";
}

TEST(Cli, DemoAnswersAndExplains) {
  const Cli_result r = run("demo");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("force closure: yes"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("form closure:  no"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("accepted by the independent checker"), std::string::npos);
  const Cli_result j = run("demo --json");
  EXPECT_EQ(j.code, 0);
  EXPECT_NE(j.out.find("\"force_closure\": true, \"form_closure\": false"), std::string::npos) << j.out;
}

TEST(Cli, ClosureJsonCertificateRoundTripsThroughCheck) {
  const std::string cert = (scratch() / "fc.json").string(), form = (scratch() / "fo.json").string();
  fs::remove(cert);
  fs::remove(form);
  const Cli_result r = run("closure --json --mode exact --certificate '" + cert + "' --form-certificate '" + form + "' '" +
                    golden("two_finger_y1_2_mu1_10") + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"force_closure\": true"), std::string::npos);
  EXPECT_NE(r.out.find("\"mode\": \"exact\""), std::string::npos);
  const Cli_result c = run("check '" + golden("two_finger_y1_2_mu1_10") + "' '" + cert + "'");
  EXPECT_EQ(c.code, 0) << c.out << c.err;
  EXPECT_EQ(c.out, "accepted\n");
  const Cli_result f = run("check --json '" + golden("two_finger_y1_2_mu1_10") + "' '" + form + "'");
  EXPECT_EQ(f.code, 0);
  EXPECT_EQ(f.out, "{\"accepted\": true, \"reason\": \"\"}\n");
  // The same certificate does not prove anything about another scene.
  const Cli_result other = run("check '" + golden("two_finger_y9_10_mu1_4") + "' '" + cert + "'");
  EXPECT_EQ(other.code, 1);
  EXPECT_EQ(other.out.rfind("rejected: ", 0), 0u) << other.out;
}

TEST(Cli, EveryGoldenSceneThroughTheCommandAndTheChecker) {
  int n = 0;
  for (const std::string& file : test::scene_files("tests/golden")) {
    SCOPED_TRACE(file);
    const std::string expected = test::expected_of(file);
    const std::string cert = (scratch() / "g_fc.json").string(), form = (scratch() / "g_fo.json").string();
    const Cli_result r = run("closure --json --certificate '" + cert + "' --form-certificate '" + form + "' '" + file + "'");
    ASSERT_EQ(r.code, 0) << r.err;
    for (const char* key : {"force_closure", "form_closure"}) {
      const bool want = expected.find(std::string("\"") + key + "\": true") != std::string::npos;
      EXPECT_NE(r.out.find(std::string("\"") + key + "\": " + (want ? "true" : "false")), std::string::npos) << key;
    }
    EXPECT_EQ(run("check '" + file + "' '" + cert + "'").code, 0);
    EXPECT_EQ(run("check '" + file + "' '" + form + "'").code, 0);
    ++n;
  }
  EXPECT_GE(n, 36);
}

TEST(Cli, StandardInputAndHumanSummary) {
  const Cli_result r = run("closure -", test::read_text(golden("vertical_walls_squeeze")));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("force closure: no"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("a translation"), std::string::npos) << r.out;
}

TEST(Cli, TamperedCertificateIsRejectedWithExitOne) {
  const std::string scene = golden("square_crossed_couples");
  const std::string bad = write("bad.json",
      R"({"wrenchkit_certificate": 1, "property": "form_closure", "holds": false, "twist": ["0", "0", "1"]})");
  const Cli_result r = run("check '" + scene + "' '" + bad + "'");
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.out.rfind("rejected: ", 0), 0u) << r.out;
  const Cli_result garbage = run("check '" + scene + "' '" + write("garbage.json", "{not json") + "'");
  EXPECT_EQ(garbage.code, 1);
}

TEST(Cli, EveryBadInputClassExitsTwoWithAMessageAndNoOutput) {
  const std::string cert = (scratch() / "never.json").string();
  struct Case { std::string scene, message; };
  const std::vector<Case> cases = {
      {"{\"wrenchkit\": 1,", "invalid JSON"},
      {R"({"wrenchkit": 1, "contacts": {}})", "contacts: expected an array, got an object"},
      {R"({"wrenchkit": 1, "extra": 1})", "scene: unknown key \"extra\""},
      {R"({"wrenchkit": 1, "wrenchkit": 1})", "duplicate key"},
      {R"({"contacts": []})", "missing key \"wrenchkit\""},
      {R"({"wrenchkit": 1, "contacts": [{"at": [0,0], "normal": [0,0]}]})", "contacts[0].normal: zero vector"},
      {R"({"wrenchkit": 1, "contacts": [{"at": [0,0], "normal": [0,1], "mu": -1}]})", "contacts[0].mu: -1 is negative"},
      {R"({"wrenchkit": 1, "support": {"mu": 1, "points": [{"at": [0,0], "force": -2}]}})", "support.points[0].force"},
      {R"({"wrenchkit": 1, "support": {"mu": 1, "points": [{"at": [0,0], "force": 0}]}})", "all forces are zero"},
      {R"({"wrenchkit": 1, "contacts": [{"at": [0,"1/0"], "normal": [0,1]}]})", "zero denominator"},
      {R"({"wrenchkit": 1, "contacts": [{"at": [0,"Infinity"], "normal": [0,1]}]})", "\"Infinity\" is not a number"},
      {R"({"wrenchkit": 1, "contacts": [{"at": [0,1e10001], "normal": [0,1]}]})", "exponent beyond"},
      {R"({"wrenchkit": 1, "contacts": [{"at": [0,)" + std::string(10001, '1') + R"(], "normal": [0,1]}]})",
       "more than 10000 digits"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.scene.substr(0, 80));
    const Cli_result r = run("closure --json --certificate '" + cert + "' '" + write("bad_scene.json", c.scene) + "'");
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err.rfind("wrenchkit: error: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(cert));  // nothing half-written
  }
  const Cli_result big = run("closure --max-file-size 10 '" + golden("no_contacts") + "'");
  EXPECT_EQ(big.code, 2);
  EXPECT_NE(big.err.find("larger than the size limit of 10 bytes"), std::string::npos);
  const Cli_result missing = run("closure /nonexistent/scene.json");
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.err.find("/nonexistent/scene.json: cannot open"), std::string::npos);
  const Cli_result bad_scene_check = run("check '" + write("bad2.json", "[]") + "' '" + write("c.json", "{}") + "'");
  EXPECT_EQ(bad_scene_check.code, 2);
}

TEST(Cli, UsageErrors) {
  EXPECT_EQ(run("").code, 2);
  EXPECT_EQ(run("frobnicate x.json").code, 2);
  EXPECT_EQ(run("closure --no-such-option x.json").code, 2);
  EXPECT_EQ(run("closure").code, 2);
  EXPECT_EQ(run("closure --mode fast x.json").code, 2);
  EXPECT_EQ(run("closure --max-digits abc x.json").code, 2);
  EXPECT_EQ(run("check onlyone.json").code, 2);
  for (const char* h : {"--help", "closure --help", "check --help", "demo --help"}) {
    const Cli_result r = run(h);
    EXPECT_EQ(r.code, 0) << h;
    EXPECT_NE(r.out.find("usage: wrenchkit"), std::string::npos) << h;
  }
}

// The commands of `wrenchkit --help` (generated from the command table): the first word of each
// line of its "commands:" section.
std::vector<std::string> commands_of_help() {
  const Cli_result h = run("--help");
  std::istringstream in(h.out);
  std::vector<std::string> names;
  bool in_list = false;
  for (std::string line; std::getline(in, line);) {
    if (line == "commands:") in_list = true;
    else if (line.empty()) in_list = false;
    else if (in_list && line.size() > 2 && line[2] != ' ') names.push_back(line.substr(2, line.find(' ', 2) - 2));
  }
  return names;
}

// batch's commands, from "COMMAND: a, b, …;" in `wrenchkit batch --help`.
std::vector<std::string> batch_commands_of_help() {
  const std::string out = run("batch --help").out;
  const std::size_t at = out.find("COMMAND: ");
  std::vector<std::string> names;
  if (at == std::string::npos) return names;
  std::string list = out.substr(at + 9, out.find(';', at) - at - 9);
  std::replace(list.begin(), list.end(), '\n', ' ');  // (the help wraps the list)
  std::istringstream in(list);
  for (std::string name; std::getline(in, name, ',');) names.push_back(name.substr(name.find_first_not_of(' ')));
  return names;
}

TEST(Cli, EveryCommandOfTheTableHasHelpAndRefusesAnUnknownMode) {
  const std::vector<std::string> commands = commands_of_help();
  ASSERT_GE(commands.size(), 14u);
  for (const char* c : {"closure", "check", "render", "batch", "reference", "compare", "demo", "limit-surface"})
    EXPECT_NE(std::find(commands.begin(), commands.end(), c), commands.end()) << c;
  const std::vector<std::string> per_scene = batch_commands_of_help();
  EXPECT_EQ(per_scene.size(), 12u);  // hold joined (issue 16), quality (issue 31), grasp-regions (issue 32), push (33)
  std::vector<std::string> lines;  // every command line, batch with each of its commands
  for (const std::string& c : commands) {
    const Cli_result h = run(c + " --help");
    EXPECT_EQ(h.code, 0) << c;
    EXPECT_EQ(h.out.rfind("usage: wrenchkit " + c + " ", 0), 0u) << c << ": " << h.out;
    EXPECT_NE(h.out.find("\noptions:\n  -h [ --help ]"), std::string::npos) << c << ": " << h.out;
    if (c != "batch") lines.push_back(c);
  }
  for (const std::string& c : per_scene) {
    const Cli_result h = run("batch " + c + " --help");
    EXPECT_EQ(h.code, 0) << c;
    EXPECT_EQ(h.out.rfind("usage: wrenchkit batch " + c + " ", 0), 0u) << c << ": " << h.out;
    EXPECT_NE(h.out.find("\n  --jobs N "), std::string::npos) << c << ": " << h.out;
    lines.push_back("batch " + c);
  }
  for (const std::string& c : lines) {
    // The scene argument is a real scene, so that the mode is the only thing wrong.
    const bool takes_mode = run(c + " --help").out.find("\n  --mode ") != std::string::npos;
    const Cli_result r = run(c + " --mode exacto '" + golden("ladder_mu_0") + "'", "");
    EXPECT_EQ(r.code, 2) << c;
    EXPECT_EQ(r.out, "") << c;
    const std::string refused = takes_mode ? "wrenchkit: usage error: --mode: \"exacto\" is not one of exact, hybrid, float\n"
                                           : "wrenchkit: usage error: --mode is not an option of " + c + "\n";
    EXPECT_EQ(r.err, refused) << c;
    if (takes_mode) {  // and a good mode is read by the same parser
      const Cli_result ok = run(c + " --mode exact --help");
      EXPECT_EQ(ok.code, 0) << c << ": " << ok.err;
    }
  }
}

TEST(Cli, OptionsAreValidatedWhereTheyAreParsed) {
  const std::string s = "'" + golden("ladder_mu_0") + "'";
  const struct {
    std::string args, message;
  } cases[] = {
      {"closure --center 1,1 " + s, "--center is not an option of closure"},
      {"closure -o x.svg " + s, "-o is not an option of closure"},
      {"closure --no-such-option " + s, "unknown option --no-such-option"},
      {"closure --mode exact --mode float " + s, "--mode given twice"},
      {"closure --json=yes " + s, "--json takes no value"},
      {"closure --mode", "--mode needs a value"},
      {"closure --max-contacts -3 " + s, "--max-contacts: \"-3\" is not a non-negative integer"},
      {"labels --resultant 1,2 " + s, "--resultant: \"1,2\" is not three numbers fx,fy,m separated by commas"},
      // Exact numbers are read within the limits, whichever comes first on the command line.
      {"labels --resultant 1e30,0,0 --max-exponent 5 " + s, "--resultant: \"1e30\""},
      {"reuleaux --center 1 " + s, "--center: \"1\" is not two numbers x,y separated by commas"},
      {"reuleaux --direction 0,0 " + s, "--direction: the zero vector is no direction"},
      {"reuleaux --sense up --center 0,0 " + s, "--sense: \"up\" is not one of ccw, cw"},
      {"reuleaux --sense cw " + s, "--sense goes with --center"},
      {"reuleaux --center 0,0 --twist 0,0,1 " + s, "give at most one of --center, --direction, --twist"},
      {"render --what pictures " + s, "--what: \"pictures\" is not one of labels, dual, reuleaux, limit-surface"},
      {"render --what labels --sides 8 " + s, "--sides goes with --what limit-surface"},
      {"analyze --tolerance 0 " + s, "--tolerance: \"0\" must be > 0"},
      {"batch closure --jobs 2000", "--jobs: must be between 1 and 1024"},
      {"compare --format xml a b", "--format: \"xml\" is not one of jsonl, csv"},
      {"reference --out x --sides 66", "--sides: 66 must be even and between 4 and 64"},
      {"demo " + s, "demo takes no scene file"},
  };
  for (const auto& c : cases) {
    const Cli_result r = run(c.args);
    EXPECT_EQ(r.code, 2) << c.args;
    EXPECT_EQ(r.out, "") << c.args;
    EXPECT_EQ(r.err.rfind("wrenchkit: usage error: ", 0), 0u) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
  }
  // A value may start with '-' (negative numbers), and --opt=value is the same as --opt value.
  const Cli_result a = run("labels --json --resultant -1,0,1/2 " + s), b = run("labels --json --resultant=-1,0,1/2 " + s);
  EXPECT_EQ(a.code, 0) << a.err;
  EXPECT_EQ(a.out, b.out);
}

TEST(Cli, ModesAgreeAndFloatSaysWhenItCannotDecide) {
  for (const char* mode : {"exact", "hybrid", "float"}) {
    const Cli_result r = run(std::string("closure --json --mode ") + mode + " '" + golden("triangle_example3_mu_1_10") + "'");
    EXPECT_EQ(r.code, 0) << mode << r.err;
    EXPECT_NE(r.out.find("\"force_closure\": true, \"form_closure\": false"), std::string::npos) << mode;
  }
  const Cli_result ex = run("closure --json --mode exact '" + golden("triangle_example3_mu_1_10") + "'");
  EXPECT_NE(ex.out.find("\"decided_by\": \"exact\""), std::string::npos);
  const Cli_result fl = run("closure --json --mode float '" + golden("triangle_example3_mu_1_10") + "'");
  EXPECT_NE(fl.out.find("\"decided_by\": \"float\""), std::string::npos) << fl.out;
  // Concurrent normals written with inexact decimals: the determinant is exactly zero, which no
  // float bound can certify. Float alone exits 3; hybrid answers exactly.
  const std::string s = write("tenths.json", R"({"wrenchkit": 1, "contacts": [
      {"at": [0.1, 0], "normal": [0, 0.1]}, {"at": [0, 0.1], "normal": [0.1, 0]}, {"at": [0.3, 0.3], "normal": [-0.1, -0.1]}]})");
  const Cli_result f = run("closure --mode float '" + s + "'");
  EXPECT_EQ(f.code, 3);
  EXPECT_EQ(f.out, "");
  EXPECT_NE(f.err.find("wrenchkit: undecided: "), std::string::npos) << f.err;
  const Cli_result h = run("closure --json '" + s + "'");
  EXPECT_EQ(h.code, 0) << h.err;
  EXPECT_NE(h.out.find("\"force_closure\": false"), std::string::npos);
  EXPECT_EQ(h.out.find("\"exact_predicates\": {\"force\": 0"), std::string::npos) << h.out;  // some went exact
}

TEST(Cli, BatchAnswersEveryLineInOrderOnManyThreads) {
  // 40 lines: golden scenes interleaved with bad lines; the answers keep the input order.
  const std::vector<std::string> names = test::scene_files("tests/golden");
  std::string input;
  std::vector<int> expect;  // 1 closure true, 0 false, -1 error
  for (int i = 0; i < 40; ++i) {
    if (i % 7 == 3) {
      input += i % 2 ? "{\"wrenchkit\": 1, \"contacts\": [{\"at\": [0,0], \"normal\": [0,0]}]}\n" : "not json\n";
      expect.push_back(-1);
      continue;
    }
    const std::string& f = names[i % names.size()];
    std::string text = test::read_text(f);
    text.erase(std::remove(text.begin(), text.end(), '\n'), text.end());
    input += text + "\n";
    const std::string expected = test::expected_of(f);
    expect.push_back(expected.find("\"force_closure\": true") != std::string::npos);
  }
  for (const char* jobs : {"1", "3"}) {
    const Cli_result r = run(std::string("batch closure --jobs ") + jobs, input);
    ASSERT_EQ(r.code, 0) << r.err;
    std::istringstream out(r.out);
    std::string line;
    for (std::size_t i = 0; i < expect.size(); ++i) {
      ASSERT_TRUE(std::getline(out, line)) << "missing line " << i + 1;
      EXPECT_EQ(line.rfind("{\"line\": " + std::to_string(i + 1) + ", ", 0), 0u) << line;
      if (expect[i] < 0) {
        EXPECT_NE(line.find("\"exit_code\": 2"), std::string::npos) << line;
      } else {
        EXPECT_NE(line.find(std::string("\"force_closure\": ") + (expect[i] ? "true" : "false")), std::string::npos);
        EXPECT_NE(line.find("\"certificates_checked\": true"), std::string::npos);
      }
    }
    EXPECT_FALSE(std::getline(out, line)) << "extra output: " << line;
  }
  const Cli_result v = run("batch closure --verdict-only", input);
  EXPECT_EQ(v.code, 0);
  EXPECT_NE(v.out.find("\"certificates_checked\": false"), std::string::npos);
  EXPECT_EQ(run("batch", input).code, 2);
  EXPECT_EQ(run("batch render", input).code, 2);
  EXPECT_EQ(run("closure --verdict-only '" + golden("no_contacts") + "'").code, 2);
  EXPECT_EQ(run("batch closure --jobs 0", input).code, 2);
  // A line longer than the limit is an error on its line; the stream goes on.
  const Cli_result big = run("batch closure --max-file-size 50", std::string(200, ' ') + "{}\n{\"wrenchkit\": 1}\n");
  EXPECT_EQ(big.code, 0);
  EXPECT_NE(big.out.find("{\"line\": 1, \"error\": \"line larger than the size limit"), std::string::npos) << big.out;
  EXPECT_NE(big.out.find("{\"line\": 2, \"command\": \"closure\""), std::string::npos) << big.out;
}

TEST(Cli, AFailedSelfCheckExitsFourAndWritesNothing) {
  const std::string cert = (scratch() / "never4.json").string();
  fs::remove(cert);
  const Cli_result r = run_env("WRENCHKIT_FAULT_INJECTION=corrupt-certificate",
                               "closure --json --certificate '" + cert + "' '" + golden("square_crossed_couples") + "'");
  EXPECT_EQ(r.code, 4);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("internal error (please report): the independent checker rejected our own certificate"),
            std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(cert));
  const Cli_result b = run_env("WRENCHKIT_FAULT_INJECTION=corrupt-certificate", "batch closure", "{\"wrenchkit\": 1}\n");
  EXPECT_EQ(b.code, 4);
  EXPECT_NE(b.out.find("\"exit_code\": 4"), std::string::npos) << b.out;
}

TEST(Cli, EquilibriumAnswersWithACheckedCertificate) {
  const std::string dir = test::source_dir() + "/tests/golden/equilibrium/";
  const std::string cert = (scratch() / "eq.json").string();
  fs::remove(cert);
  const Cli_result yes = run("equilibrium --json --certificate '" + cert + "' '" + dir + "ladder_mu_1_7_gravity.scene.json'");
  ASSERT_EQ(yes.code, 0) << yes.err;
  EXPECT_NE(yes.out.find("\"balanced\": true"), std::string::npos) << yes.out;
  EXPECT_NE(yes.out.find("\"load\": [\"0\", \"-1\", \"1/2\"]"), std::string::npos) << yes.out;
  EXPECT_EQ(run("check '" + dir + "ladder_mu_1_7_gravity.scene.json' '" + cert + "'").code, 0);
  // The same certificate does not balance the ladder with less friction.
  EXPECT_EQ(run("check '" + dir + "ladder_mu_1_8_gravity.scene.json' '" + cert + "'").code, 1);
  const Cli_result no = run("equilibrium '" + dir + "block_corner_mu_1_2_pull_right_at_0_half.scene.json'");
  EXPECT_EQ(no.code, 0) << no.err;
  EXPECT_NE(no.out.find("balanced: no"), std::string::npos) << no.out;
  const Cli_result none = run("equilibrium '" + golden("square_crossed_couples") + "'");
  EXPECT_EQ(none.code, 2);
  EXPECT_NE(none.err.find("load: the scene has no load"), std::string::npos) << none.err;
  // The ladder at mu = 1/7 is balanced marginally (the COM is a + vertex): an exact zero that the
  // float twin cannot certify from the inexact 1/7, so float alone exits 3; hybrid answers.
  const Cli_result fl = run("equilibrium --mode float '" + dir + "ladder_mu_1_7_gravity.scene.json'");
  EXPECT_EQ(fl.code, 3) << fl.out << fl.err;
  const Cli_result fl2 = run("equilibrium --json --mode float '" + dir + "block_corner_mu_1_2_gravity.scene.json'");
  EXPECT_EQ(fl2.code, 0) << fl2.err;
  EXPECT_NE(fl2.out.find("\"decided_by\": \"float\""), std::string::npos) << fl2.out;
  EXPECT_EQ(run("equilibrium --help").code, 0);
}

TEST(Cli, HoldAnswersWithACheckedCertificateAndTheMotion) {
  const std::string dir = test::source_dir() + "/proofs/examples/";
  const std::string cert = (scratch() / "hold.json").string();
  fs::remove(cert);
  // Held: the pin and the right legs' friction, on their circles.
  const Cli_result yes = run("hold --json --certificate '" + cert + "' '" + dir + "fixture_pin_push.scene.json'");
  ASSERT_EQ(yes.code, 0) << yes.err;
  EXPECT_NE(yes.out.find("\"holds\": true"), std::string::npos) << yes.out;
  EXPECT_NE(yes.out.find("\"certificate_checked\": true"), std::string::npos) << yes.out;
  EXPECT_EQ(run("check '" + dir + "fixture_pin_push.scene.json' '" + cert + "'").code, 0);
  // The same certificate does not hold the lifted part.
  EXPECT_EQ(run("check '" + dir + "fixture_pin_lift.scene.json' '" + cert + "'").code, 1);
  // Not held: the motion, as a rotation centre, in text and JSON.
  const Cli_result no = run("hold '" + dir + "fixture_pin_lift.scene.json'");
  ASSERT_EQ(no.code, 0) << no.err;
  EXPECT_NE(no.out.find("holds: no"), std::string::npos) << no.out;
  EXPECT_NE(no.out.find("rotation about (-1, 0)"), std::string::npos) << no.out;
  const Cli_result nj = run("hold --json --mode exact '" + dir + "fixture_pin_lift.scene.json'");
  ASSERT_EQ(nj.code, 0) << nj.err;
  EXPECT_NE(nj.out.find("\"holds\": false"), std::string::npos) << nj.out;
  EXPECT_NE(nj.out.find("\"kind\": \"rotation\""), std::string::npos) << nj.out;
  EXPECT_NE(nj.out.find("\"sense\": \"counter-clockwise\""), std::string::npos) << nj.out;
  // Every distribution: depends, with both witnesses; float has no LP over F and exits 3.
  const Cli_result dep = run("hold --json '" + dir + "table_pinned_pushed.scene.json'");
  ASSERT_EQ(dep.code, 0) << dep.err;
  EXPECT_NE(dep.out.find("\"holds\": \"depends\""), std::string::npos) << dep.out;
  EXPECT_NE(dep.out.find("\"witnesses\": {\"holds\": {\"holds\": true, \"distribution\""), std::string::npos) << dep.out;
  EXPECT_NE(dep.out.find("\"fails\": {\"holds\": false, \"distribution\""), std::string::npos) << dep.out;
  const Cli_result fl = run("hold --mode float '" + dir + "table_pinned_pushed.scene.json'");
  EXPECT_EQ(fl.code, 3) << fl.out << fl.err;
  EXPECT_EQ(fl.out, "");
  // No load: bad input, nothing written.
  const std::string none_cert = (scratch() / "none.json").string();
  fs::remove(none_cert);
  const Cli_result none = run("hold --certificate '" + none_cert + "' '" + golden("square_crossed_couples") + "'");
  EXPECT_EQ(none.code, 2);
  EXPECT_NE(none.err.find("load: the scene has no load (hold needs one)"), std::string::npos) << none.err;
  EXPECT_FALSE(fs::exists(none_cert));
  // The picture.
  const std::string svg = (scratch() / "hold.svg").string();
  ASSERT_EQ(run("render '" + dir + "fixture_pin_lift.scene.json' --what hold -o '" + svg + "'").code, 0);
  const std::string picture = test::read_text(svg);
  EXPECT_NE(picture.find("rotation centre"), std::string::npos);
  EXPECT_NE(picture.find("hold: does not hold"), std::string::npos);
  EXPECT_EQ(run("hold --help").code, 0);
}

TEST(Cli, AnalyzeAnswersHoldWithContactsASupportAndALoad) {
  const std::string dir = test::source_dir() + "/proofs/examples/";
  const Cli_result j = run("analyze --json '" + dir + "fixture_pin_lift.scene.json'");
  ASSERT_EQ(j.code, 0) << j.err;
  EXPECT_NE(j.out.find("\"equilibrium\": {"), std::string::npos) << j.out;
  EXPECT_NE(j.out.find("\"hold\": {\"command\": \"hold\""), std::string::npos) << j.out;
  const Cli_result t = run("analyze '" + dir + "fixture_pin_push.scene.json'");
  ASSERT_EQ(t.code, 0) << t.err;
  EXPECT_NE(t.out.find("balanced: no"), std::string::npos) << t.out;  // the pin alone cannot
  EXPECT_NE(t.out.find("the load on the support: slides"), std::string::npos) << t.out;  // the legs alone cannot
  EXPECT_NE(t.out.find("holds: yes"), std::string::npos) << t.out;  // together they do
}

TEST(Cli, AnalyzeComputesWhatTheSceneCallsFor) {
  // Contacts only: closure, no equilibrium.
  const Cli_result c = run("analyze --json '" + golden("square_crossed_couples") + "'");
  ASSERT_EQ(c.code, 0) << c.err;
  EXPECT_NE(c.out.find("\"closure\": {"), std::string::npos);
  EXPECT_EQ(c.out.find("\"equilibrium\""), std::string::npos) << c.out;
  EXPECT_NE(c.out.find("\"skipped\": []"), std::string::npos);
  // A load: equilibrium too; a support: listed as skipped, not silently dropped.
  const std::string s = write("analyze.json", R"({"wrenchkit": 1, "body": {"com": [0, 1]},
      "contacts": [{"at": [-1, 0], "normal": [0, 1]}, {"at": [1, 0], "normal": [0, 1]}],
      "load": {"force": [0, -2], "at": [0, 1]}, "support": {"mu": 1, "points": [{"at": [0, 0], "force": 1}]}})");
  const Cli_result e = run("analyze --json '" + s + "'");
  ASSERT_EQ(e.code, 0) << e.err;
  EXPECT_NE(e.out.find("\"equilibrium\": {"), std::string::npos) << e.out;
  EXPECT_NE(e.out.find("\"balanced\": true"), std::string::npos) << e.out;
  EXPECT_NE(e.out.find("\"limit_surface\": {\"sides\": 32"), std::string::npos) << e.out;
  const Cli_result h = run("analyze '" + s + "'");
  EXPECT_NE(h.out.find("balanced: yes"), std::string::npos) << h.out;
  EXPECT_NE(h.out.find("limit surface (32 sides)"), std::string::npos) << h.out;
  EXPECT_EQ(run("analyze --mode float '" + s + "'").code, 3);  // two collinear forces: rank 2, float abstains
  EXPECT_EQ(run("analyze --certificate x.json '" + s + "'").code, 2);
  const Cli_result d = run("demo");
  EXPECT_NE(d.out.find("balanced: yes"), std::string::npos) << d.out;
}

// Gravity beside a support is the weight pressing the body on it (docs/scene-format.md): it sets W and, at body.com, the
// centre of pressure, and pushes nothing in the plane; every command reads it so, and the checker too.
TEST(Cli, GravityOnASupportPressesTheBodyOnIt) {
  const std::string plate = R"("body": {"com": [0, 0]}, "contacts": [{"at": [-1, 0], "normal": [1, 0]}],
      "load": {"gravity": 2}, "support": {"mu": "1/2", )";
  const std::string pts = R"("points": [{"at": [0, 1]}, {"at": [0, -1]}, {"at": [1, 0]}, {"at": [-1, 0]}]}})";
  const std::string s = write("gravity_support.json", "{\"wrenchkit\": 1, " + plate + pts);
  // hold: the in-plane load is zero (not (0, -2)): it holds, the weight W = 2 sets the distributions.
  const Cli_result h = run("hold '" + s + "'");
  ASSERT_EQ(h.code, 0) << h.err;
  EXPECT_NE(h.out.find("load: the wrench (0, 0, 0) on the body"), std::string::npos) << h.out;
  EXPECT_NE(h.out.find("gravity 2 at body.com presses the body on the support"), std::string::npos) << h.out;
  EXPECT_NE(h.out.find("holds: yes"), std::string::npos) << h.out;
  EXPECT_NE(h.out.find("accepted by the independent checker"), std::string::npos) << h.out;
  // limit-surface: W is the weight, c is body.com.
  const Cli_result l = run("limit-surface '" + s + "' --load 0,0,1/10");
  ASSERT_EQ(l.code, 0) << l.err;
  EXPECT_NE(l.out.find("weight 2, centre of pressure (0, 0)"), std::string::npos) << l.out;
  // analyze runs hold and the load's motion instead of skipping them.
  const Cli_result a = run("analyze --json '" + s + "'");
  ASSERT_EQ(a.code, 0) << a.err;
  EXPECT_NE(a.out.find("\"hold\": {"), std::string::npos) << a.out;
  EXPECT_EQ(a.out.find("gravity acts across"), std::string::npos) << a.out;
  // A conflicting weight or pressure centre is refused with both values, by every command.
  const std::string w3 = write("gravity_weight.json", "{\"wrenchkit\": 1, " + plate + "\"weight\": 3, " + pts);
  for (const char* command : {"hold", "analyze", "limit-surface", "sliding", "equilibrium"}) {
    const Cli_result e = run(std::string(command) + " '" + w3 + "'");
    EXPECT_EQ(e.code, 2) << command;
    EXPECT_NE(e.err.find("load.gravity: the weight 2 presses the body on the support, but support.weight is 3"),
              std::string::npos) << command << ": " << e.err;
  }
  const std::string c1 = write("gravity_center.json",
                               "{\"wrenchkit\": 1, " + plate + "\"pressure_center\": [0, \"1/2\"], " + pts);
  const Cli_result c = run("hold '" + c1 + "'");
  EXPECT_EQ(c.code, 2);
  EXPECT_NE(c.err.find("support.pressure_center: (0, 1/2) is not body.com (0, 0)"), std::string::npos) << c.err;
  // Given forces must carry the weight, at body.com.
  const std::string f1 = write("gravity_forces.json", R"({"wrenchkit": 1, "body": {"com": [0, 1]},
      "load": {"gravity": 2}, "support": {"mu": 1, "points": [{"at": [0, 0], "force": 1}]}})");
  const Cli_result f = run("hold '" + f1 + "'");
  EXPECT_EQ(f.code, 2);
  EXPECT_NE(f.err.find("load.gravity: the weight 2 is not the sum of the given forces, 1"), std::string::npos) << f.err;
  const std::string f2 = write("gravity_forces_off.json", R"({"wrenchkit": 1, "body": {"com": [0, 1]},
      "load": {"gravity": 2}, "support": {"mu": 1, "points": [{"at": [0, 0], "force": 2}]}})");
  const Cli_result g = run("limit-surface '" + f2 + "' --load 0,0,0");
  EXPECT_EQ(g.code, 2);
  EXPECT_NE(g.err.find("body.com: the weight's point (0, 1) is not the centre of pressure"), std::string::npos) << g.err;
}

TEST(Cli, LimitsCanBeRaised) {
  const std::string s = write("long.json", R"({"wrenchkit": 1, "contacts": [{"at": [0,)" + std::string(10001, '1') +
                                               R"(], "normal": [0,1]}]})");
  EXPECT_EQ(run("closure '" + s + "'").code, 2);
  const Cli_result r = run("closure --max-digits 20000 '" + s + "'");
  EXPECT_EQ(r.code, 0) << r.err;
}


// A minimal XML well-formedness check of an SVG: one root <svg>, every tag closed in order,
// attributes quoted, no "nan"/"inf" coordinates.
::testing::AssertionResult well_formed_svg(const std::string& svg) {
  if (svg.rfind("<?xml", 0) != 0) return ::testing::AssertionFailure() << "no XML declaration";
  if (svg.find("nan") != std::string::npos || svg.find("inf\"") != std::string::npos)
    return ::testing::AssertionFailure() << "non-finite number";
  std::vector<std::string> open;
  std::size_t i = svg.find("?>") + 2, roots = 0;
  while ((i = svg.find('<', i)) != std::string::npos) {
    const std::size_t end = svg.find('>', i);
    if (end == std::string::npos) return ::testing::AssertionFailure() << "unterminated tag at " << i;
    const std::string tag = svg.substr(i + 1, end - i - 1);
    if (tag.empty()) return ::testing::AssertionFailure() << "empty tag";
    if (std::count(tag.begin(), tag.end(), '"') % 2) return ::testing::AssertionFailure() << "unbalanced quotes: " << tag;
    if (tag[0] == '/') {
      if (open.empty() || open.back() != tag.substr(1)) return ::testing::AssertionFailure() << "mismatched </" << tag;
      open.pop_back();
    } else if (tag.back() != '/') {
      const std::string name = tag.substr(0, tag.find_first_of(" \n"));
      if (open.empty()) ++roots;
      if (open.empty() && name != "svg") return ::testing::AssertionFailure() << "root is " << name;
      open.push_back(name);
    }
    i = end + 1;
  }
  if (!open.empty()) return ::testing::AssertionFailure() << "unclosed <" << open.back();
  if (roots != 1) return ::testing::AssertionFailure() << roots << " roots";
  return ::testing::AssertionSuccess();
}

// The limit-surface picture: one writer behind both entry points, three panels, every golden support.
TEST(Cli, RenderLimitSurfaceOfEverySupport) {
  const std::string file_out = (scratch() / "ls.svg").string();
  int n = 0;
  for (const std::string& file : test::scene_files("tests/golden/limit_surface")) {
    if (test::read_text(file).find("\"support\"") == std::string::npos) continue;
    SCOPED_TRACE(file);
    const Cli_result r = run("render --what limit-surface --sides 8 '" + file + "'");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(well_formed_svg(r.out));
    std::size_t panels = 0;
    for (std::size_t i = r.out.find("<g>"); i != std::string::npos; i = r.out.find("<g>", i + 1)) ++panels;
    EXPECT_EQ(panels, 3u);
    fs::remove(file_out);
    ASSERT_EQ(run("limit-surface --sides 8 --svg '" + file_out + "' '" + file + "'").code, 0);
    EXPECT_EQ(test::read_text(file_out), r.out);
    ++n;
  }
  EXPECT_GE(n, 5);
  // Markup in the name is escaped; one point's slice f_y = 0 is a segment, drawn as its two ends.
  const std::string one = write("one.json", R"({"wrenchkit": 1, "name": "a <b> & \"c\"", "support": {"mu": 1, )"
                                            R"("points": [{"at": [0, 0], "force": 1}]}})");
  const Cli_result r = run("render --what limit-surface --sides 4 '" + one + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(well_formed_svg(r.out));
  EXPECT_NE(r.out.find("Limit surface of a &lt;b&gt; &amp; &quot;c&quot;: 4 sides"), std::string::npos) << r.out;
  const std::size_t slice = r.out.find("<polygon points=\"");
  ASSERT_NE(slice, std::string::npos);
  const std::string points = r.out.substr(slice, r.out.find('"', slice + 17) - slice);
  EXPECT_EQ(std::count(points.begin(), points.end(), ','), 2) << points;
}

TEST(Cli, LabelsAnswerExactlyAndAgreeWithClosure) {
  const Cli_result r = run("labels --json '" + golden("block_corner_mu_0") + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"plus\": {\"empty\": false, \"shape\": \"wedge\", \"vertices\": [[\"0\", \"1\"]], "
                       "\"directions\": [[\"0\", \"1\"], [\"-1\", \"0\"]]}"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"infinity\": [{\"from\": [\"0\", \"1\"], \"to\": [\"-1\", \"0\"]}]"), std::string::npos);
  const Cli_result h = run("labels '" + golden("block_corner_mu_0") + "'");
  EXPECT_NE(h.out.find("the wedge at (0, 1)"), std::string::npos) << h.out;
  // Possible resultants (theory.md §5.5): the upward force through the centre yes; a push to the left
  // at (0, 1/2) (the reaction a pull to the right would need) no.
  EXPECT_NE(run("labels --json --resultant 0,1,1/2 '" + golden("block_corner_mu_0") + "'").out.find("\"possible\": true"),
            std::string::npos);
  EXPECT_NE(run("labels --json --resultant -1,0,1/2 '" + golden("block_corner_mu_0") + "'").out.find("\"possible\": false"),
            std::string::npos);
  for (const std::string& file : test::scene_files("tests/golden")) {
    SCOPED_TRACE(file);
    const bool fc = test::expected_of(file).find("\"force_closure\": true") != std::string::npos;
    const bool fo = test::expected_of(file).find("\"form_closure\": true") != std::string::npos;
    const Cli_result l = run("labels --json '" + file + "'");
    ASSERT_EQ(l.code, 0) << l.err;
    EXPECT_NE(l.out.find(std::string("\"force_closure\": ") + (fc ? "true" : "false")), std::string::npos);
    const Cli_result d = run("dual --json '" + file + "'");
    ASSERT_EQ(d.code, 0) << d.err;
    EXPECT_NE(d.out.find(std::string("\"covers_all\": ") + (fc ? "true" : "false")), std::string::npos);
    const Cli_result u = run("reuleaux --json '" + file + "'");
    ASSERT_EQ(u.code, 0) << u.err;
    EXPECT_NE(u.out.find(std::string("\"form_closure\": ") + (fo ? "true" : "false")), std::string::npos);
  }
}

TEST(Cli, LabelsReadTheLoad) {
  for (const std::string& file : test::scene_files("tests/golden/equilibrium")) {
    SCOPED_TRACE(file);
    const bool balanced = test::expected_of(file).find("\"balanced\": true") != std::string::npos;
    const Cli_result l = run("labels --json '" + file + "'");
    ASSERT_EQ(l.code, 0) << l.err;
    EXPECT_NE(l.out.find(std::string("\"balanced\": ") + (balanced ? "true" : "false")), std::string::npos) << l.out;
  }
}

TEST(Cli, DualAboutAReferencePoint) {
  const Cli_result d = run("dual --json '" + golden("block_corner_mu_0") + "'");
  ASSERT_EQ(d.code, 0) << d.err;
  EXPECT_NE(d.out.find("\"reference\": {\"point\": [\"-1\", \"2\"]"), std::string::npos) << d.out;
  EXPECT_NE(d.out.find("[\"-1/2\", \"0\"]"), std::string::npos) << d.out;
  const Cli_result h = run("dual '" + golden("triangle_example3_mu_1_10") + "'");
  EXPECT_NE(h.out.find("yes (force closure)"), std::string::npos) << h.out;
}

TEST(Cli, ReuleauxModes) {
  const std::string pin = golden("square_pinwheel");
  const Cli_result cw = run("reuleaux --json --center 1,1 --sense cw '" + pin + "'");
  ASSERT_EQ(cw.code, 0) << cw.err;
  EXPECT_NE(cw.out.find("\"feasible\": true"), std::string::npos) << cw.out;
  const Cli_result ccw = run("reuleaux --json --center 1,1 '" + pin + "'");
  EXPECT_NE(ccw.out.find("\"feasible\": false"), std::string::npos) << ccw.out;
  EXPECT_NE(ccw.out.find("\"mode\": \"penetrate\""), std::string::npos) << ccw.out;
  const Cli_result corner = run("reuleaux --center 1/2,1/2 --sense cw '" + pin + "'");
  EXPECT_NE(corner.out.find("feasible, marginal"), std::string::npos) << corner.out;
  EXPECT_NE(corner.out.find(": slide"), std::string::npos) << corner.out;
  for (const char* bad : {"--center 1 ", "--center a,b ", "--center 1,1 --sense up ", "--sense cw ",
                          "--center 1,1 --twist 1,0,0 ", "--twist 0,0,0 ", "--direction 0,0 ", "--what labels "}) {
    const Cli_result b = run(std::string("reuleaux ") + bad + "'" + pin + "'");
    EXPECT_EQ(b.code, 2) << bad;
    EXPECT_TRUE(b.out.empty()) << bad;
    EXPECT_FALSE(b.err.empty()) << bad;
  }
  EXPECT_EQ(run("closure --center 1,1 '" + pin + "'").code, 2);
  EXPECT_EQ(run("labels --resultant 1,2 '" + pin + "'").code, 2);
}

TEST(Cli, RenderDrawsEveryGoldenScene) {
  int n = 0;
  std::vector<std::string> files = test::scene_files("tests/golden");
  for (const std::string& f : test::scene_files("tests/golden/equilibrium")) files.push_back(f);
  for (const std::string& file : files)
    for (const char* what : {"labels", "dual", "reuleaux"}) {
      SCOPED_TRACE(file + " " + what);
      const Cli_result r = run(std::string("render --what ") + what + " '" + file + "'");
      ASSERT_EQ(r.code, 0) << r.err;
      EXPECT_TRUE(well_formed_svg(r.out));
      ++n;
    }
  EXPECT_GE(n, 3 * 60);
  const std::string out = (scratch() / "pic.svg").string();
  fs::remove(out);
  ASSERT_EQ(run("render --what labels -o '" + out + "' '" + golden("ladder_mu_1_7") + "'").code, 0);
  const std::string svg = test::read_text(out);
  EXPECT_TRUE(well_formed_svg(svg));
  for (const char* part : {"<clipPath", "fill=\"#2f6fd0\"", "fill=\"#d0453f\"", "<title>"})
    EXPECT_NE(svg.find(part), std::string::npos) << part;
  fs::remove(out);
  const Cli_result ls = run("render --what limit-surface --sides 8 '" + test::source_dir() +
                            "/tests/golden/limit_surface/barbell.scene.json'");
  ASSERT_EQ(ls.code, 0) << ls.err;
  EXPECT_TRUE(well_formed_svg(ls.out));
  EXPECT_EQ(run("render --what limit-surface --sides 7 '" + golden("ladder_mu_1_7") + "'").code, 2);
  EXPECT_EQ(run("render --what limit-surface '" + golden("ladder_mu_1_7") + "'").code, 2);  // no support
  EXPECT_EQ(run("render --what labels --sides 8 '" + golden("ladder_mu_1_7") + "'").code, 2);
  EXPECT_EQ(run("render --what pictures -o '" + out + "' '" + golden("ladder_mu_1_7") + "'").code, 2);
  EXPECT_EQ(run("render -o '" + out + "' '" + golden("ladder_mu_1_7") + "'").code, 2);
  EXPECT_FALSE(fs::exists(out));
  const std::string bad = write("bad.json", R"({"wrenchkit": 1, "contacts": [{"at": [0, 0], "normal": [0, 0]}]})");
  const Cli_result b = run("render --what labels -o '" + out + "' '" + bad + "'");
  EXPECT_EQ(b.code, 2);
  EXPECT_NE(b.err.find("contacts[0].normal"), std::string::npos) << b.err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace wrenchkit

namespace wrenchkit {
namespace {

// A JSON number's or string's exact value.
Rational exact_of(const json::Value& v) {
  std::string why;
  const std::optional<Rational> q = parse_rational(v.text, v.type == json::Type::number, Input_limits{}, why);
  if (!q) throw std::runtime_error("not a number: " + v.text);
  return *q;
}

// The JSON answer minus its mode bookkeeping ("mode", "decided_by", "predicates", "exact_predicates").
std::string without_mode_fields(const std::string& out) {
  std::string s = out;
  for (const char* key : {"\"mode\": ", "\"decided_by\": ", "\"predicates\": ", "\"exact_predicates\": "}) {
    const std::size_t i = s.find(key);
    if (i == std::string::npos) continue;
    const std::size_t end = s.find(", ", i);
    s.erase(i, end + 2 - i);
  }
  return s;
}

// labels / dual / reuleaux: hybrid answers exactly what exact answers; the float twin either exits 3
// with a reason, or gives the exact shapes with every corner within its stated bound of the exact one.
TEST(CliModes, LabelsDualReuleauxInEveryMode) {
  int float_answers = 0, float_abstentions = 0;
  for (const std::string& file : test::scene_files("tests/golden")) {
    for (const char* command : {"labels", "dual", "reuleaux"}) {
      const Cli_result e = run(std::string(command) + " --json --mode exact '" + file + "'");
      const Cli_result h = run(std::string(command) + " --json '" + file + "'");
      ASSERT_EQ(e.code, 0) << command << " " << file << ": " << e.err;
      ASSERT_EQ(h.code, 0) << command << " " << file << ": " << h.err;
      EXPECT_NE(h.out.find("\"mode\": \"hybrid\""), std::string::npos);
      EXPECT_EQ(without_mode_fields(h.out), without_mode_fields(e.out)) << command << " " << file;
      const Cli_result f = run(std::string(command) + " --json --mode float '" + file + "'");
      if (f.code == 3) {
        ++float_abstentions;
        EXPECT_TRUE(f.out.empty());
        EXPECT_NE(f.err.find("float twin could not"), std::string::npos) << f.err;
        continue;
      }
      ASSERT_EQ(f.code, 0) << command << " " << file << ": " << f.err;
      ++float_answers;
      const json::Value fv = json::parse(f.out, Input_limits{}, "float"), ev = json::parse(e.out, Input_limits{}, "exact");
      const char* regions[2][2] = {{"plus", "minus"}, {"plus_region", "minus_region"}};
      for (const char* key : regions[std::string(command) == "dual"]) {
        const json::Value *fr = fv.find(key), *er = ev.find(key);
        ASSERT_TRUE(fr && er) << key;
        ASSERT_EQ(fr->find("shape")->text, er->find("shape")->text) << command << " " << key << " " << file;
        const auto& fvx = fr->find("vertices")->items;
        const auto& fb = fr->find("vertex_bounds")->items;
        const auto& evx = er->find("vertices")->items;
        ASSERT_EQ(fvx.size(), evx.size());
        if (fr->find("shape")->text == "plane") continue;
        // Every printed corner within its printed bound of the exact corner (bounded regions may start
        // at another corner).
        const std::size_t n = evx.size();
        bool found = n == 0;
        for (std::size_t k = 0; k < (fr->find("directions")->items.empty() ? n : 1) && !found; ++k) {
          bool all = true;
          for (std::size_t i = 0; i < n && all; ++i)
            for (int c = 0; c < 2 && all; ++c)
              all = abs(exact_of(evx[(i + k) % n].items[c]) - exact_of(fvx[i].items[c])) <= exact_of(fb[i].items[c]);
          found = all;
        }
        EXPECT_TRUE(found) << command << " " << key << " " << file << "\n" << f.out << "\n" << e.out;
      }
      for (const char* verdict : {"force_closure", "form_closure", "covers_all"})
        if (ev.find(verdict)) { EXPECT_EQ(fv.find(verdict)->boolean, ev.find(verdict)->boolean) << verdict << " " << file; }
    }
  }
  std::printf("[ stats    ] golden scenes: float answered %d, abstained %d (exit 3)\n", float_answers, float_abstentions);
  EXPECT_GT(float_answers, 20);
  EXPECT_GT(float_abstentions, 0);  // rank < 3 and thresholds ± 10^-40 exist among the goldens
  // Reuleaux's modes in float: the pinwheel's clockwise centre (1, 1) is feasible, its counter-clockwise
  // centre (2, 2) penetrates; the same as exact.
  for (const char* q : {"--center 1,1 --sense cw", "--center 2,2"}) {
    const Cli_result e = run(std::string("reuleaux --json --mode exact ") + q + " '" + golden("square_pinwheel") + "'");
    const Cli_result f = run(std::string("reuleaux --json --mode float ") + q + " '" + golden("square_pinwheel") + "'");
    ASSERT_EQ(f.code, 0) << f.err;
    const json::Value fq = *json::parse(f.out, Input_limits{}, "f").find("query");
    const json::Value eq = *json::parse(e.out, Input_limits{}, "e").find("query");
    EXPECT_EQ(fq.find("feasible")->boolean, eq.find("feasible")->boolean) << q;
    for (std::size_t i = 0; i < eq.find("modes")->items.size(); ++i)
      EXPECT_EQ(fq.find("modes")->items[i].find("mode")->text, eq.find("modes")->items[i].find("mode")->text);
  }
}

// One exit-code rule (issue 29): an undecided answer exits 3 in every output form and mode — text, --json and
// --certificate — for every command that can leave a question undecided; the answer itself (text or JSON) is still
// written, with the reason, and --certificate writes no file. Advice names only what can help: hybrid mode's Newton
// from exact mode, never "use --mode hybrid or exact" outside float mode. Decided answers exit 0.
TEST(Cli, UndecidedExitsThreeInEveryForm) {
  // 1.41421356237309504880 < √2 by 1.7·10^-21: the barbell on the diagonal's pure moment, beyond exact mode's rounds.
  const std::string scene = write("undecided_moment.scene.json",
                                  R"({"wrenchkit": 1, "support": {"mu": 1, "points": [{"at": [1, 1], "force": "1/2"},
      {"at": [-1, -1], "force": "1/2"}]}, "load": {"wrench": [0, 0, "-1.41421356237309504880"]}})");
  const std::string ls = "limit-surface --mode exact --load 0,0,1.41421356237309504880 '" + scene + "'";
  const std::string cert = (scratch() / "undecided.cert.json").string();
  std::filesystem::remove(cert);
  for (const std::string& command : {ls, "hold --mode exact '" + scene + "'", "analyze --mode exact '" + scene + "'"}) {
    const Cli_result text = run(command);
    EXPECT_EQ(text.code, 3) << command << "\n" << text.out << text.err;
    EXPECT_NE(text.out.find("undecided"), std::string::npos) << command << "\n" << text.out;
    EXPECT_NE(text.out.find("hybrid mode adds Newton's method"), std::string::npos) << command << "\n" << text.out;
    EXPECT_EQ(text.out.find("use --mode hybrid or exact"), std::string::npos) << command;
    const Cli_result json = run(command + " --json");
    EXPECT_EQ(json.code, 3) << command << " --json\n" << json.out << json.err;
    EXPECT_NE(json.out.find("\"undecided"), std::string::npos) << json.out;
  }
  for (const std::string& command : {ls, "hold --mode exact '" + scene + "'"}) {
    const Cli_result c = run(command + " --certificate '" + cert + "'");
    EXPECT_EQ(c.code, 3) << command << "\n" << c.err;
    EXPECT_FALSE(std::filesystem::exists(cert)) << command;
    EXPECT_NE(c.err.find("no certificate to write"), std::string::npos) << c.err;
  }
  // Hybrid decides it (Newton in multiple precision): exit 0; float mode cannot and says where to go.
  EXPECT_EQ(run("hold '" + scene + "'").code, 0);
  const Cli_result fl = run("hold --mode float '" + scene + "'");
  EXPECT_EQ(fl.code, 3) << fl.err;
  EXPECT_NE(fl.err.find("use --mode hybrid or exact"), std::string::npos) << fl.err;
  const Cli_result fl_ls = run("limit-surface --mode float --json --load 0,0,1.41421356237309504880 '" + scene + "'");
  EXPECT_EQ(fl_ls.code, 3) << fl_ls.out << fl_ls.err;
}

// The outline as geometry end to end (exact/io/outline.h): an outward normal and an off-outline contact are refused
// with exit 2, the message naming the contact and the fix, nothing on stdout, for every command that reads the scene;
// --lenient answers with the warnings in the text; a placed contact's scene and its certificate pass `check`;
// analyze states the outline.
TEST(Cli, OutlineChecksRefuseOrWarn) {
  const fs::path bad = scratch() / "outline_bad.json", placed = scratch() / "outline_placed.json";
  std::ofstream(bad) << R"({"wrenchkit": 1, "body": {"outline": [[0, 0], [4, 0], [0, 4]]}, "contacts": [
    {"at": [2, 0], "normal": [0, -1], "mu": 1}, {"at": [5, 5], "normal": [-1, -1]}, {"at": [0, 2], "normal": [1, 0]}]})";
  for (const char* command : {"closure", "labels", "quality", "analyze"}) {
    const Cli_result r = run(std::string(command) + " " + bad.string());
    EXPECT_EQ(r.code, 2) << command;
    EXPECT_EQ(r.out, "") << command;
    EXPECT_NE(r.err.find("contacts[0].normal: (0, -1) does not point into the body at edge 0"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("flip its sign?; or pass --lenient"), std::string::npos) << r.err;
  }
  const Cli_result lenient = run("closure --lenient " + bad.string());
  EXPECT_EQ(lenient.code, 0) << lenient.err;
  EXPECT_NE(lenient.out.find("warning: contacts[0].normal: (0, -1) does not point into the body"), std::string::npos) << lenient.out;
  EXPECT_NE(lenient.out.find("warning: contacts[1].at: (5, 5) is not on body.outline"), std::string::npos) << lenient.out;
  EXPECT_NE(lenient.out.find("(kept: --lenient)"), std::string::npos) << lenient.out;
  std::ofstream(placed) << R"({"wrenchkit": 1, "mu": "1/2", "body": {"outline": [[0, 0], [4, 0], [0, 4]]},
    "contacts": [{"edge": 0, "s": "1/2"}, {"edge": 1, "s": "1/2"}, {"edge": 2, "s": "1/4"}]})";
  const fs::path cert = scratch() / "outline_placed.cert.json";
  const Cli_result c = run("closure --certificate " + cert.string() + " " + placed.string());
  EXPECT_EQ(c.code, 0) << c.err;
  EXPECT_NE(c.out.find("force closure: yes"), std::string::npos) << c.out;
  const Cli_result k = run("check " + placed.string() + " " + cert.string());
  EXPECT_EQ(k.code, 0) << k.out << k.err;
  const Cli_result a = run("analyze " + placed.string());
  EXPECT_NE(a.out.find("outline: 3 vertices, counter-clockwise, convex; every contact on it"), std::string::npos) << a.out;
}

// grasp-regions end to end: the JSON a script counts on ("pairs": [{"edges": [i, j], "closed": [[[s, t], …]]}]), the
// certificate written and accepted by `check`, batch, and the refusals (no mu, no outline, an edge out of range,
// three fingers) with exit 2 and nothing on stdout.
// push end to end: JSON with the certificate (written, then accepted by `check`), the contact mode, the picture, the
// float twin's abstention (exit 3), and bad input (exit 2, nothing on stdout).
TEST(Cli, PushJsonCertificateContactPictureAndRefusals) {
  const std::string scene = test::source_dir() + "/docs/pushing/square_apart.json";
  const fs::path cert = scratch() / "push.cert.json";
  const Cli_result r = run("push --json --contact --certificate " + cert.string() + " " + scene);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find(R"("rotation": "ccw")"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(R"("contact": {"mode": "sticks", "omega": [)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(R"("certificate_checked": true)"), std::string::npos) << r.out;
  const Cli_result k = run("check " + scene + " " + cert.string());
  EXPECT_EQ(k.code, 0) << k.out << k.err;
  const Cli_result svg = run("render --what push " + scene);
  EXPECT_EQ(svg.code, 0) << svg.err;
  EXPECT_NE(svg.out.find("centre of friction"), std::string::npos);
  EXPECT_NE(svg.out.find("<svg"), std::string::npos);
  EXPECT_EQ(svg.out.find("rotation centre"), std::string::npos);  // the contact mode only when asked
  // --contact: the body turns ccw with the pusher about p + rot90(v)/omega, omega = 0.53605…: (-1.365, 0.8655)
  const Cli_result moving = run("render --what push --contact " + scene);
  EXPECT_EQ(moving.code, 0) << moving.err;
  EXPECT_NE(moving.out.find("rotation centre"), std::string::npos);
  EXPECT_NE(moving.out.find("contact: sticks \u2014 the body turns ccw about (-1.365, 0.8655)"), std::string::npos) << moving.out;
  const Cli_result pivot = run("render --what push --contact " + test::source_dir() + "/proofs/examples/push_slide_pivot.scene.json");
  EXPECT_NE(pivot.out.find("the facet of support point 0)"), std::string::npos) << pivot.out;
  const Cli_result labels = run("render --what labels --contact " + scene);
  EXPECT_EQ(labels.code, 2);
  EXPECT_NE(labels.err.find("--contact goes with --what push"), std::string::npos) << labels.err;
  const Cli_result tie = run("push --mode float " + test::source_dir() + "/docs/pushing/square_tie.json");
  EXPECT_EQ(tie.code, 3) << tie.out << tie.err;
  EXPECT_NE(tie.out.find("rotation: undecided"), std::string::npos) << tie.out;
  const Cli_result bad = run("push -", R"({"wrenchkit": 1, "support": {"mu": 1, "points": [{"at": [0, 0], "force": 1}]},
      "pusher": {"at": [0, -1], "normal": [0, 1], "velocity": [0, -1]}})");
  EXPECT_EQ(bad.code, 2);
  EXPECT_EQ(bad.out, "");
  EXPECT_NE(bad.err.find("pusher.velocity: (0, -1) moves away from the body"), std::string::npos) << bad.err;
}

// [PU-4] push --locus end to end: the JSON pieces, the certificate written and accepted by `check`, `batch push
// --locus`, the picture, and the refusals (a line pusher; --locus off --what push) with exit 2.
TEST(Cli, PushLocusJsonCertificateBatchPictureAndRefusals) {
  const std::string scene = test::source_dir() + "/docs/pushing/square_apart.json";
  const fs::path cert = scratch() / "locus.cert.json";
  const Cli_result r = run("push --json --locus --certificate " + cert.string() + " " + scene);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find(R"("locus": {"R2": "2")"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(R"("cw": null)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(R"("arm_hi": "1886641/500000")"), std::string::npos) << r.out;
  const Cli_result k = run("check " + scene + " " + cert.string());
  EXPECT_EQ(k.code, 0) << k.out << k.err;
  std::string line_text = test::read_text(scene);  // one scene per line
  std::replace(line_text.begin(), line_text.end(), '\n', ' ');
  const Cli_result b = run("batch push --locus", line_text + "\n");
  EXPECT_EQ(b.code, 0) << b.err;
  EXPECT_NE(b.out.find(R"("arm_hi": "1886641/500000")"), std::string::npos) << b.out;
  const Cli_result svg = run("render --what push --locus " + scene);
  EXPECT_EQ(svg.code, 0) << svg.err;
  EXPECT_NE(svg.out.find("rotation centres: within 3.773 of the pusher's normal line"), std::string::npos) << svg.out;
  const Cli_result labels = run("render --what labels --locus " + scene);
  EXPECT_EQ(labels.code, 2);
  EXPECT_NE(labels.err.find("--locus goes with --what push"), std::string::npos) << labels.err;
  const Cli_result line = run("push --locus " + test::source_dir() + "/proofs/examples/push_fence.scene.json");
  EXPECT_EQ(line.code, 2);
  EXPECT_EQ(line.out, "");
  EXPECT_NE(line.err.find("--locus: the rotation centres are answered for a point pusher"), std::string::npos) << line.err;
}

// [PU-3] A line pusher: is its motion stable — JSON, exit codes (0 when decided, stable or not), the certificate `check`
// accepts, the picture, batch, and the refusals (a slanted normal, --contact).
TEST(Cli, PushALinePusherStableOrNot) {
  const std::string dir = test::source_dir() + "/proofs/examples/";
  const fs::path cert = scratch() / "fence.cert.json";
  const Cli_result r = run("push --json --certificate " + cert.string() + " " + dir + "push_fence_near.scene.json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find(R"("pusher": {"segment": [["-1/2", "-1"], ["1/2", "-1"]], "normal": ["0", "1"], "mu": "1/2", )"
                       R"("velocity": ["0", "1"], "omega": "1/6"})"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(R"("rotation": "ccw")"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(R"("stable": {"verdict": "stable", "why": ")"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(R"("rotation_centre": ["-6", "-1"])"), std::string::npos) << r.out;
  EXPECT_EQ(run("check " + dir + "push_fence_near.scene.json " + cert.string()).code, 0);
  const Cli_result u = run("push --json " + dir + "push_fence_close.scene.json");
  EXPECT_EQ(u.code, 0) << u.err;  // unstable is an answer
  EXPECT_NE(u.out.find(R"("facet": "left edge", "witness": {"points": [["-1", "1"], ["1", "-1"]], "weights": ["1", "1"]})"),
            std::string::npos) << u.out;
  EXPECT_NE(u.out.find(R"("rotation": "undecided")"), std::string::npos) << u.out;
  const Cli_result b = run("push --json " + dir + "push_fence.scene.json");  // translating, strictly inside
  EXPECT_NE(b.out.find(R"("boundary": [])"), std::string::npos) << b.out;
  const Cli_result svg = run("render --what push " + dir + "push_fence_close.scene.json");
  EXPECT_EQ(svg.code, 0) << svg.err;
  EXPECT_NE(svg.out.find("a distribution with the centre of friction that breaks the contact"), std::string::npos);
  EXPECT_NE(svg.out.find("stable: unstable (the pusher turns ccw about (-2, -1))"), std::string::npos) << svg.out;
  const fs::path lines = scratch() / "fences.jsonl";  // batch: one scene per line
  {
    std::ofstream out(lines);
    for (const char* name : {"push_fence", "push_fence_close"}) {
      std::ifstream in(dir + name + ".scene.json");
      std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      std::replace(text.begin(), text.end(), '\n', ' ');
      out << text << "\n";
    }
  }
  const Cli_result batch = run("batch push " + lines.string());
  EXPECT_EQ(batch.code, 0) << batch.err;
  EXPECT_NE(batch.out.find(R"("verdict": "stable")"), std::string::npos) << batch.out;
  EXPECT_NE(batch.out.find(R"("verdict": "unstable")"), std::string::npos) << batch.out;
  const Cli_result contact = run("push --contact " + dir + "push_fence.scene.json");
  EXPECT_EQ(contact.code, 2);
  EXPECT_NE(contact.err.find("--contact: the contact mode is answered for a point pusher"), std::string::npos) << contact.err;
  const Cli_result slanted = run("push -", R"({"wrenchkit": 1, "support": {"mu": 1, "points": [{"at": [0, 0], "force": 1}]},
      "pusher": {"segment": [[0, -1], [1, -1]], "normal": [1, 1], "velocity": [0, 1]}})");
  EXPECT_EQ(slanted.code, 2);
  EXPECT_EQ(slanted.out, "");
  EXPECT_NE(slanted.err.find("pusher.normal: (1, 1) is not perpendicular to the segment"), std::string::npos) << slanted.err;
}

TEST(Cli, GraspRegionsJsonCertificateAndRefusals) {
  const fs::path square = scratch() / "gr_square.json", cert = scratch() / "gr_square.cert.json";
  std::ofstream(square) << R"({"wrenchkit": 1, "body": {"outline": [[0, 0], [1, 0], [1, 1], [0, 1]]}})";
  const Cli_result r = run("grasp-regions --json --fingers 2 --mu 1/2 --certificate " + cert.string() + " " + square.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find(R"("pairs": [{"edges": [0, 1], "closed": []}, {"edges": [0, 2], "closed": [[["1/2", "0"], ["1", "0"], )"
                       R"(["1", "1/2"], ["1/2", "1"], ["0", "1"], ["0", "1/2"]]], "independent": [[)"),
            std::string::npos) << r.out;
  EXPECT_NE(r.out.find(R"("closed_pairs": 2)"), std::string::npos) << r.out;
  const Cli_result k = run("check " + square.string() + " " + cert.string());
  EXPECT_EQ(k.code, 0) << k.out << k.err;
  const Cli_result svg = run("render --what grasp-regions --mu 1/2 " + square.string());
  EXPECT_EQ(svg.code, 0) << svg.err;
  EXPECT_NE(svg.out.find("force closure in (s, t)"), std::string::npos);
  const Cli_result text = run("grasp-regions --mu 1/2 " + square.string());
  EXPECT_NE(text.out.find("for 2 of 6 edge pairs"), std::string::npos) << text.out;
  // three fingers: the JSON's triples, a certificate the `check` command accepts, batch
  const fs::path cert3 = scratch() / "gr3_cert.json";
  const Cli_result three = run("grasp-regions --json --fingers 3 --mu 1/2 --certificate " + cert3.string() + " " + square.string());
  EXPECT_EQ(three.code, 0) << three.err;
  EXPECT_NE(three.out.find(R"("fingers": 3)"), std::string::npos) << three.out;
  EXPECT_NE(three.out.find(R"("triples": [{"edges": [0, 1, 2], "independent": [[)"), std::string::npos) << three.out;
  EXPECT_NE(three.out.find(R"("boxed_triples": 4, "never_triples": 0)"), std::string::npos) << three.out;
  const Cli_result checked3 = run("check " + square.string() + " " + cert3.string());
  EXPECT_EQ(checked3.code, 0) << checked3.out << checked3.err;
  const Cli_result text3 = run("grasp-regions --fingers 3 --mu 0 " + square.string());
  EXPECT_NE(text3.out.find("for 0 of 4 edge triples; no placement closes for 4 triples (frictionless"), std::string::npos) << text3.out;
  // ranked by the grasp's epsilon at each box's centre: best first, the best one's certificate accepted by `check` on
  // its own scene and its epsilon the one `quality` gives there; --min-side filters the boxes ranked
  const fs::path l_part = fs::path(test::source_dir()) / "docs" / "grasp-regions" / "l_part.json";
  const Cli_result ranked = run("grasp-regions --json --rank epsilon " + l_part.string());
  ASSERT_EQ(ranked.code, 0) << ranked.err;
  const json::Value rv = json::parse(ranked.out, Input_limits{}, "ranked");
  const json::Value& list = *rv.find("ranked");
  ASSERT_EQ(list.items.size(), 4u);  // the L part's four closed pairs
  for (std::size_t k = 1; k < list.items.size(); ++k)
    EXPECT_GE(Rational(list.items[k - 1].find("epsilon")->find("lower")->text),
              Rational(list.items[k].find("epsilon")->find("upper")->text)) << k;
  const fs::path best = scratch() / "gr_best.json", best_cert = scratch() / "gr_best.cert.json";
  std::ofstream(best) << json::text_of(*rv.find("best_by_epsilon")->find("scene"));
  std::ofstream(best_cert) << json::text_of(*rv.find("best_by_epsilon")->find("certificate"));
  const Cli_result best_checked = run("check " + best.string() + " " + best_cert.string());
  EXPECT_EQ(best_checked.code, 0) << best_checked.out << best_checked.err;
  const Cli_result q = run("quality --json --only epsilon --about 7/3,11/6 " + best.string());
  ASSERT_EQ(q.code, 0) << q.err;
  EXPECT_EQ(json::parse(q.out, Input_limits{}, "q").find("epsilon")->find("lower")->text,
            list.items[0].find("epsilon")->find("lower")->text);
  const Cli_result robust = run("grasp-regions --json --min-side 1/2 " + l_part.string());
  EXPECT_EQ(json::parse(robust.out, Input_limits{}, "r").find("ranked")->items.size(), 2u) << robust.out;  // edges 1, 5 and 0, 4
  const Cli_result batch = run("batch grasp-regions --mu 2", R"({"wrenchkit": 1, "body": {"outline": [[0, 0], [4, 0], [0, 3]]}})" "\n");
  EXPECT_EQ(batch.code, 0) << batch.err;
  EXPECT_NE(batch.out.find(R"("line": 1, "command": "grasp-regions")"), std::string::npos) << batch.out;
  for (const auto& [args, message] : std::vector<std::pair<std::string, std::string>>{
           {square.string(), "--mu: missing"},
           {"--mu 1 --edges 0,9 " + square.string(), "--edges: 9 is not an edge of body.outline (0 to 3)"},
           {"--mu 1 --fingers 4 " + square.string(), "--fingers: \"4\" is not 2 or 3"},
           {"--mu 1 --rank area " + square.string(), "--rank: \"area\" is not side or epsilon"},
           {"--mu 1 --fingers 3 --edges 0,9 " + square.string(), "--edges: 9 is not an edge of body.outline"},
           {"--mu 1 -", "body.outline: missing"}}) {
    const Cli_result e = run("grasp-regions " + args, R"({"wrenchkit": 1})");
    EXPECT_EQ(e.code, 2) << args;
    EXPECT_EQ(e.out, "") << args;
    EXPECT_NE(e.err.find(message), std::string::npos) << e.err;
  }
}

}  // namespace
}  // namespace wrenchkit
