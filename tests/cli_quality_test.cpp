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
  EXPECT_NE(closed.err.find("no float twin"), std::string::npos) << closed.err;
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
