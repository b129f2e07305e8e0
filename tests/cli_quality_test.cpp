// `wrenchkit quality` end to end: the two fingers of proofs/examples (ε² = 1/3 by hand, L1; 2/3, Linf; an irrational
// bracket with unit forces), an open grasp (ε = 0), the certificate file accepted by `wrenchkit check`, float mode's
// exit 3, bad options' exit 2, batch, and every golden scene answered alike in hybrid and exact modes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "tests/test_support.h"

namespace wrenchkit {
namespace {

namespace fs = std::filesystem;
using test::Cli_result;

Cli_result run(const std::string& args, const std::string& stdin_text = "") {
  return test::run_cli(WRENCHKIT_CLI, "", args, stdin_text, "cli_quality_test");
}
std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}
std::string example(const std::string& name) { return test::source_dir() + "/proofs/examples/" + name + ".scene.json"; }

TEST(CliQuality, TwoFingersByHand) {
  const Cli_result r = run("quality " + example("two_fingers_mu1"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("force closure: yes"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("epsilon^2 = 1/3 (≈ 0.333333333333333), exactly; epsilon ≈ 0.577350269189626"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("nearest facet: the left edge of c0 (left finger)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("certificates accepted by the independent checker"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("force closure: mu* = 0 exactly"), std::string::npos) << r.out;  // the fingers face each other
  const Cli_result linf = run("quality --json --norm Linf " + example("two_fingers_mu1"));
  ASSERT_EQ(linf.code, 0) << linf.err;
  EXPECT_NE(linf.out.find(R"("squared": "2/3")"), std::string::npos) << linf.out;
  EXPECT_NE(linf.out.find(R"("normal": ["-2", "1", "-1"])"), std::string::npos) << linf.out;
}

TEST(CliQuality, UnitForceIsABracket) {
  const Cli_result r = run("quality --json --normalize unit-force --tolerance 1/1000 " + example("two_fingers_mu1"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.find("\"squared\""), std::string::npos) << r.out;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"re("epsilon": \{[^}]*"lower_approx": ([0-9.e-]+), "upper_approx": ([0-9.e-]+))re")));
  const double lo = std::stod(m.str(1)), hi = std::stod(m.str(2)), eps = 1 / std::sqrt(6.0);
  EXPECT_LE(lo, eps);
  EXPECT_GE(hi, eps);
  EXPECT_LE(hi - lo, 1e-3 * lo);
}

TEST(CliQuality, OpenGraspIsZero) {
  const Cli_result r = run("quality " + example("two_fingers_mu0"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("epsilon = 0: the grasp is not in force closure"), std::string::npos) << r.out;
}

TEST(CliQuality, CertificateFileIsChecked) {
  const std::string cert = (fs::path(test::scratch_dir("cli_quality_test")) / "q.cert.json").string();
  ASSERT_EQ(run("quality --norm Linf --normalize unit-force --certificate " + cert + " " + example("two_fingers_mu1")).code, 0);
  const Cli_result c = run("check " + example("two_fingers_mu1") + " " + cert);
  EXPECT_EQ(c.code, 0) << c.out << c.err;
  EXPECT_NE(c.out.find("accepted"), std::string::npos);
  // the same certificate does not prove anything about the open grasp
  EXPECT_EQ(run("check " + example("two_fingers_mu0") + " " + cert).code, 1);
}

TEST(CliQuality, FloatModeHasNoTwinForEpsilon) {
  const Cli_result closed = run("quality --only epsilon --mode float " + example("two_fingers_mu1"));
  EXPECT_EQ(closed.code, 3);
  EXPECT_NE(closed.err.find("the float twin certifies it only without a certificate"), std::string::npos) << closed.err;
  EXPECT_EQ(run("quality --only epsilon --mode float " + example("two_fingers_mu0")).code, 0);  // ε = 0, by the twist
  const Cli_result mu = run("quality --mode float " + example("two_fingers_mu0"));  // μ* is asked by default
  EXPECT_EQ(mu.code, 3);
  EXPECT_NE(mu.err.find("critical friction coefficient has no float twin"), std::string::npos) << mu.err;
}

TEST(CliQuality, BadOptionsNameTheOption) {
  for (const char* bad : {"--norm L3", "--torque-scale 0", "--torque-scale -1/2", "--normalize unit", "--tolerance 0",
                          "--about 1"}) {
    const Cli_result r = run(std::string("quality ") + bad + " " + example("two_fingers_mu1"));
    EXPECT_EQ(r.code, 2) << bad;
    EXPECT_NE(r.err.find(std::string(bad).substr(0, std::string(bad).find(' '))), std::string::npos) << bad << ": " << r.err;
    EXPECT_EQ(r.out, "") << bad;
  }
}

TEST(CliQuality, Presets) {
  const Cli_result g = run("quality --only epsilon --preset graspit " + example("square_side_middles"));
  ASSERT_EQ(g.code, 0) << g.err;
  EXPECT_NE(g.out.find("moments about (0, 0) times 1/sqrt(2) ≈ 0.707106781"), std::string::npos) << g.out;
  EXPECT_NE(g.out.find("epsilon ≈ 0.0707106781186548"), std::string::npos) << g.out;
  const Cli_result no_com = run("quality --preset dexnet " + example("two_fingers_mu1"));
  EXPECT_EQ(no_com.code, 2);
  EXPECT_NE(no_com.err.find("body.com"), std::string::npos) << no_com.err;
  const Cli_result clash = run("quality --preset graspit --about 0,0 " + example("square_side_middles"));
  EXPECT_EQ(clash.code, 2);
  EXPECT_NE(clash.err.find("--preset graspit"), std::string::npos) << clash.err;
}

// Bounded work: thirty contacts on three rings pressing toward the centre — the critical friction is refused past 24
// point contacts with the reason and the way out; ε alone answers, and analyze.
TEST(CliQuality, WorkIsBounded) {
  std::string scene = R"({"wrenchkit": 1, "contacts": [)";
  const int pts[][2] = {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3}, {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
  for (int i = 0; i < 30; ++i) {
    const auto& p = pts[i % 12];
    const int k = 1 + i / 12;
    scene += (i ? ", " : "") + std::string("{\"at\": [") + std::to_string(k * p[0]) + ", " + std::to_string(k * p[1]) +
             "], \"normal\": [" + std::to_string(-p[0]) + ", " + std::to_string(-p[1]) + "], \"mu\": \"1/2\"}";
  }
  scene += "]}";
  const std::string file = (fs::path(test::scratch_dir("cli_quality_test")) / "thirty.json").string();
  std::ofstream(file) << scene;
  const Cli_result mu = run("quality " + file);
  EXPECT_EQ(mu.code, 2);
  EXPECT_NE(mu.err.find("more than 24"), std::string::npos) << mu.err;
  EXPECT_NE(mu.err.find("--only epsilon"), std::string::npos) << mu.err;
  EXPECT_EQ(mu.out, "");
  EXPECT_EQ(run("quality --only epsilon " + file).code, 0);
  EXPECT_EQ(run("analyze " + file).code, 0);
}

// Contact margins worked by hand (moments about the origin, torque scale 1): three frictionless contacts whose
// wrenches (1, 0, 0), (1, 0, −1), (0, 1, 1) have determinant 1 and squared lengths 1, 2, 2 — 1/4 for each; a
// frictional contact at the origin (its plane: W = (0, 1, 0), (−1, 0, 0)) and a frictionless one at (1, 0) pushing up
// ((0, 1, 1)) — 1/2; the second moved to (0, 1) pushing down: its line passes through the first contact — 0.
TEST(CliQuality, ContactMarginsByHand) {
  const auto margins = [](const std::string& contacts, const std::string& extra = "") {
    const std::string file = (fs::path(test::scratch_dir("cli_quality_test")) / "margins.json").string();
    std::ofstream(file) << R"({"wrenchkit": 1, "contacts": [)" + contacts + "]}";
    return run("quality --json --only epsilon --contact-margins" + extra + " " + file);
  };
  const Cli_result a = margins(R"({"at": [0, 0], "normal": [1, 0]}, {"at": [0, 1], "normal": [1, 0]}, {"at": [1, 0], "normal": [0, 1]})");
  ASSERT_EQ(a.code, 0) << a.err;
  EXPECT_EQ(count(a.out, R"("squared": "1/4")"), 3u) << a.out;
  EXPECT_NE(a.out.find(R"("relative_volume_approx": 0.5,)"), std::string::npos) << a.out;
  const Cli_result b = margins(R"({"at": [0, 0], "normal": [0, 1], "mu": 1}, {"at": [1, 0], "normal": [0, 1]})");
  ASSERT_EQ(b.code, 0) << b.err;
  EXPECT_EQ(count(b.out, R"("squared": "1/2")"), 2u) << b.out;
  const Cli_result c = margins(R"({"at": [0, 0], "normal": [0, 1], "mu": 1}, {"at": [0, 1], "normal": [0, -1]})");
  ASSERT_EQ(c.code, 0) << c.err;
  EXPECT_EQ(count(c.out, R"("squared": "0", "relative_volume_approx": 0,)"), 2u) << c.out;
  EXPECT_EQ(count(c.out, R"("degenerate_triples": 1)"), 2u) << c.out;
  const Cli_result text = run("quality --only critical-mu --contact-margins " + example("two_fingers_mu1"));
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("contact margins (the least relative volume"), std::string::npos) << text.out;
  // bounded: 49 frictional contacts are 98 edges
  std::string many;
  for (int i = 0; i < 49; ++i) many += (i ? ", " : "") + std::string(R"({"at": [)") + std::to_string(i) + R"(, 0], "normal": [0, 1], "mu": 1})";
  const Cli_result big = margins(many);
  EXPECT_EQ(big.code, 2);
  EXPECT_NE(big.err.find("more than 96"), std::string::npos) << big.err;
  EXPECT_EQ(big.out, "");
}

TEST(CliQuality, Batch) {
  std::ifstream a(example("two_fingers_mu1")), b(example("two_fingers_mu0"));
  std::string sa((std::istreambuf_iterator<char>(a)), {}), sb((std::istreambuf_iterator<char>(b)), {});
  for (std::string* s : {&sa, &sb}) s->erase(std::remove(s->begin(), s->end(), '\n'), s->end());
  const Cli_result r = run("batch quality", sa + "\n" + sb + "\n");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find(R"("line": 1, "command": "quality")"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(R"("line": 2, "command": "quality")"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(R"("squared": "1/3")"), std::string::npos) << r.out;
}

// Every golden scene with contacts: the same answer in hybrid and exact mode (only "mode" and "decided_by" differ).
TEST(CliQuality, GoldenScenesAgreeAcrossModes) {
  const std::regex mode_re(R"re("mode": "[a-z]+"|"decided_by": "[a-z]+")re");
  int scenes = 0;
  for (const std::string& f : test::scene_files("tests/golden")) {
    const Cli_result h = run("quality --json " + f), e = run("quality --json --mode exact " + f);
    if (h.code == 2) {  // no contacts
      EXPECT_EQ(e.code, 2) << f;
      continue;
    }
    ASSERT_EQ(h.code, 0) << f << h.err;
    ASSERT_EQ(e.code, 0) << f << e.err;
    EXPECT_EQ(std::regex_replace(h.out, mode_re, ""), std::regex_replace(e.out, mode_re, "")) << f;
    ++scenes;
  }
  EXPECT_GE(scenes, 20);
}

}  // namespace
}  // namespace wrenchkit
