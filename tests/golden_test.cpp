// Golden textbook scenes (theory.md §7–9, §14.3): tests/golden/NAME.scene.json with the verdicts of
// NAME.expected.json (written by tests/golden/make_golden.py, which re-derives each with its own
// brute force). Every certificate is re-checked by the independent checker.
#include <gtest/gtest.h>

#include <regex>

#include "cli/demo_scene.h"
#include "exact/certificates/certificates.h"
#include "exact/statics/closure.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {

bool expected_bool(const std::string& expected, const std::string& key) {
  std::smatch m;
  const std::regex re("\"" + key + "\": (true|false)");
  if (!std::regex_search(expected, m, re)) throw std::runtime_error("no " + key);
  return m[1] == "true";
}

int expected_rank(const std::string& expected, const std::string& key) {
  std::smatch m;
  const std::regex re("\"" + key + "\": ([0-3])");
  if (!std::regex_search(expected, m, re)) throw std::runtime_error("no rank " + key);
  return std::stoi(m[1]);
}

TEST(Golden, EveryTextbookSceneHasItsExpectedVerdictAndACheckedCertificate) {
  int count = 0;
  for (const std::string& file : test::scene_files("tests/golden")) {
    SCOPED_TRACE(file);
    const std::string text = test::read_text(file);
    const std::string expected = test::expected_of(file);
    const Scene s = read_scene(text, Input_limits{});
    const Closure_answer fc = decide_closure(s, Property::force_closure);
    const Closure_answer fo = decide_closure(s, Property::form_closure);
    EXPECT_EQ(fc.holds, expected_bool(expected, "force_closure"));
    EXPECT_EQ(fo.holds, expected_bool(expected, "form_closure"));
    EXPECT_EQ(fc.rank, expected_rank(expected, "force"));
    EXPECT_EQ(fo.rank, expected_rank(expected, "form"));
    EXPECT_TRUE(test::checker_accepts(text, certificate_json(fc.certificate)));
    EXPECT_TRUE(test::checker_accepts(text, certificate_json(fo.certificate)));
    ++count;
  }
  EXPECT_GE(count, 36);
}

TEST(Golden, DemoSceneIsTheGoldenExample3) {
  const std::string golden =
      test::read_text(test::source_dir() + "/tests/golden/triangle_example3_mu_1_10.scene.json");
  const Scene a = read_scene(golden, Input_limits{});
  const Scene b = read_scene(cli::kDemoScene, Input_limits{});
  ASSERT_EQ(a.contacts.size(), b.contacts.size());
  for (std::size_t i = 0; i < a.contacts.size(); ++i) {
    EXPECT_EQ(a.contacts[i].at.x, b.contacts[i].at.x);
    EXPECT_EQ(a.contacts[i].at.y, b.contacts[i].at.y);
    EXPECT_EQ(a.contacts[i].normal.x, b.contacts[i].normal.x);
    EXPECT_EQ(a.contacts[i].normal.y, b.contacts[i].normal.y);
    EXPECT_EQ(a.contacts[i].mu, b.contacts[i].mu);
  }
  EXPECT_EQ(a.name, b.name);
}

}  // namespace
}  // namespace wrenchkit
