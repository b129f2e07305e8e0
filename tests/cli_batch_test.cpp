// End-to-end tests of `wrenchkit batch COMMAND` for every command that answers per scene: each output
// line is exactly the single command's --json answer with "line" first (or its error, with the same
// message), in input order, byte-identical for any --jobs; usage errors stop before any line.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "exact/io/json.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {

using test::Cli_result;

Cli_result run(const std::string& args, const std::string& stdin_text = "") {
  return test::run_cli(WRENCHKIT_CLI, "", args, stdin_text, "cli_batch_test");
}

std::string one_line(std::string text) {
  text.erase(std::remove(text.begin(), text.end(), '\n'), text.end());
  return text;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> v;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) v.push_back(l);
  return v;
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t p = 0; (p = s.find(from, p)) != std::string::npos; p += to.size()) s.replace(p, from.size(), to);
  return s;
}

// What `batch` must print for line n, from the single command run on the same text (standard input):
// its --json answer with "line" first, or its error message (the source "<stdin>" named "line n").
std::string expected_line(const std::string& command_and_options, const std::string& text, std::size_t n) {
  const Cli_result single = run(command_and_options + " --json -", text);
  if (single.code == 0) {
    EXPECT_EQ(single.out.back(), '\n');
    return "{\"line\": " + std::to_string(n) + ", " + single.out.substr(1, single.out.size() - 2);
  }
  EXPECT_EQ(single.out, "") << command_and_options;
  const std::string prefix = single.code == 3 ? "wrenchkit: undecided: " : "wrenchkit: error: ";
  EXPECT_EQ(single.err.rfind(prefix, 0), 0u) << single.err;
  const std::string message = replace_all(single.err.substr(prefix.size(), single.err.size() - prefix.size() - 1),
                                          "<stdin>", "line " + std::to_string(n));
  return "{\"line\": " + std::to_string(n) + ", \"" + (single.code == 3 ? "undecided" : "error") + "\": " +
         json::quote(message) + ", \"exit_code\": " + std::to_string(single.code) + "}";
}

std::vector<std::string> golden(const std::string& folder) {
  std::vector<std::string> texts;
  for (const std::string& f : test::scene_files(folder)) texts.push_back(one_line(test::read_text(f)));
  return texts;
}

// Bad lines of every class (tests/cli_test.cpp's), mixed into every command's input.
const std::vector<std::string> kBadLines = {
    "not json",
    "",
    "{\"wrenchkit\": 1,",
    R"({"wrenchkit": 1, "contacts": {}})",
    R"({"wrenchkit": 1, "extra": 1})",
    R"({"wrenchkit": 1, "wrenchkit": 1})",
    R"({"contacts": []})",
    R"({"wrenchkit": 1, "contacts": [{"at": [0,0], "normal": [0,0]}]})",
    R"({"wrenchkit": 1, "contacts": [{"at": [0,0], "normal": [0,1], "mu": -1}]})",
    R"({"wrenchkit": 1, "support": {"mu": 1, "points": [{"at": [0,0], "force": -2}]}})",
    R"({"wrenchkit": 1, "support": {"mu": 1, "points": [{"at": [0,0], "force": 0}]}})",
    R"({"wrenchkit": 1, "contacts": [{"at": [0,"1/0"], "normal": [0,1]}]})",
    R"({"wrenchkit": 1, "contacts": [{"at": [0,"Infinity"], "normal": [0,1]}]})",
    R"({"wrenchkit": 1, "contacts": [{"at": [0,1e10001], "normal": [0,1]}]})",
    "{\"wrenchkit\": 1, \"name\": \"a\xff\"}",
};

struct Case {
  std::string command;  // with its options
  std::vector<std::string> scenes;
};

TEST(CliBatch, EveryCommandAnswersEachLineAsItsSingleCommandDoes) {
  const std::vector<std::string> top = golden("tests/golden"), eq = golden("tests/golden/equilibrium"),
                                  ls = golden("tests/golden/limit_surface"), ex = golden("proofs/examples");
  const auto some = [](const std::vector<std::string>& v, std::size_t n) {
    return std::vector<std::string>(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(std::min(n, v.size())));
  };
  std::vector<std::string> mixed = some(top, 4);
  for (const std::string& s : some(eq, 3)) mixed.push_back(s);
  for (const std::string& s : ls) mixed.push_back(s);
  const std::vector<Case> cases = {
      {"closure", top},
      {"closure --mode exact", some(top, 8)},
      {"equilibrium", eq},
      {"equilibrium --mode float", some(eq, 8)},
      {"labels --resultant 0,1,0", some(mixed, 12)},
      {"dual", some(top, 10)},
      {"reuleaux --center 1,1 --sense cw", some(top, 10)},
      {"analyze", mixed},
      {"limit-surface --sides 8 --twist 0,0,1 --load 0,0,1/2", ls},
      {"limit-surface --tolerance 1/10 --list", ls},
      {"sliding --twist 3,4,0", ls},
      {"sliding --sides 16 --twist -1,0,1", ls},
      {"hold", ex},
      {"hold --mode float", ex},
      {"hold --mode exact", some(ex, 12)},
      {"push", golden("docs/pushing")},
      {"push --mode float", golden("docs/pushing")},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.command);
    std::vector<std::string> texts;  // the scenes with a bad line after every second one
    std::size_t b = 0;
    for (std::size_t s = 0; s < c.scenes.size(); ++s) {
      texts.push_back(c.scenes[s]);
      if (s % 2 == 1 && b < kBadLines.size()) texts.push_back(kBadLines[b++]);
    }
    while (b < kBadLines.size()) texts.push_back(kBadLines[b++]);
    std::string input;
    for (const std::string& t : texts) input += t + "\n";
    const Cli_result one = run("batch " + c.command + " --jobs 1", input);
    ASSERT_EQ(one.code, 0) << one.err;
    EXPECT_EQ(one.err, "");
    const std::vector<std::string> got = lines_of(one.out);
    ASSERT_EQ(got.size(), texts.size());
    for (std::size_t i = 0; i < texts.size(); ++i)
      EXPECT_EQ(got[i], expected_line(c.command, texts[i], i + 1)) << "line " << i + 1 << ": " << texts[i].substr(0, 80);
    // The same bytes on several threads (windows of 256 lines per thread: the 3-job run also crosses
    // window boundaries with the input repeated).
    const Cli_result three = run("batch " + c.command + " --jobs 3", input);
    EXPECT_EQ(three.code, 0);
    EXPECT_EQ(three.out, one.out);
  }
}

TEST(CliBatch, OutputIsByteIdenticalForAnyJobsAcrossManyWindows) {
  // 2 000 lines (several windows of 256 lines per thread), scenes and bad lines mixed.
  const std::vector<std::string> top = golden("tests/golden");
  std::string input;
  for (int i = 0; i < 2000; ++i)
    input += (i % 11 == 5 ? kBadLines[static_cast<std::size_t>(i) % kBadLines.size()]
                          : top[static_cast<std::size_t>(i) % top.size()]) + "\n";
  const Cli_result one = run("batch closure --jobs 1", input);
  ASSERT_EQ(one.code, 0) << one.err;
  EXPECT_EQ(lines_of(one.out).size(), 2000u);
  for (const char* jobs : {"2", "3", "8"}) {
    const Cli_result r = run(std::string("batch closure --jobs ") + jobs, input);
    EXPECT_EQ(r.code, 0) << jobs;
    EXPECT_TRUE(r.out == one.out) << "--jobs " << jobs << " changed the output";
  }
  const Cli_result v1 = run("batch closure --verdict-only --jobs 1", input), v3 = run("batch closure --verdict-only --jobs 3", input);
  EXPECT_EQ(v1.code, 0);
  EXPECT_TRUE(v1.out == v3.out);
  // Without a final newline the last line is still a line.
  const Cli_result last = run("batch closure --verdict-only", top[0] + "\n" + top[1]);
  EXPECT_EQ(lines_of(last.out).size(), 2u);
  EXPECT_NE(last.out.find("{\"line\": 2, \"command\": \"closure\""), std::string::npos);
}

TEST(CliBatch, UsageErrorsStopBeforeAnyLine) {
  const std::string input = golden("tests/golden")[0] + "\n";
  for (const char* args : {"batch", "batch render", "batch check", "batch demo", "batch frobnicate",
                           "batch closure --certificate c.json",
                           "batch closure --center 1,1", "batch labels --verdict-only", "batch labels --twist 0,0,1",
                           "batch reuleaux --center 1", "batch reuleaux --sense cw", "batch sliding --twist 0,0,0",
                           "batch sliding --sides 7", "batch limit-surface --off x.off", "batch limit-surface --ply x.ply", "batch limit-surface --exact-coordinates", "batch limit-surface --sides 3",
                           "batch limit-surface --sides 8 --tolerance 0.1", "batch equilibrium --resultant 1,0,0",
                           "batch hold --certificate c.json", "batch hold --sides 8",
                           "batch closure --jobs 0", "batch closure --mode fast"}) {
    const Cli_result r = run(args, input);
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_EQ(r.out, "") << args;
    EXPECT_EQ(r.err.rfind("wrenchkit: usage error: ", 0), 0u) << args << ": " << r.err;
  }
  // A scene file that cannot be read is bad input, before any line too (batch reads its files, not only stdin).
  const Cli_result missing = run("batch closure scene.json", input);
  EXPECT_EQ(missing.code, 2);
  EXPECT_EQ(missing.out, "");
  EXPECT_EQ(missing.err, "wrenchkit: error: scene.json: cannot open (No such file or directory)\n");
  const Cli_result help = run("batch --help");
  EXPECT_EQ(help.code, 0);
  for (const char* c : {"closure", "equilibrium", "labels", "dual", "reuleaux", "limit-surface", "sliding", "hold", "analyze"})
    EXPECT_NE(help.out.find(c), std::string::npos) << c;
  // An option that cannot apply to one scene (too many candidate normals) is that line's error.
  const std::string dir = test::source_dir() + "/tests/golden/limit_surface/";
  const Cli_result big = run("batch limit-surface --sides 4096",
                             one_line(test::read_text(dir + "ten_points.scene.json")) + "\n" +
                                 one_line(test::read_text(dir + "single_point.scene.json")) + "\n");
  EXPECT_EQ(big.code, 0) << big.err;
  const std::vector<std::string> lines = lines_of(big.out);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].rfind("{\"line\": 1, \"error\": \"sides 4096 with 10 distinct support points needs", 0), 0u)
      << lines[0];
  EXPECT_EQ(lines[1].rfind("{\"line\": 2, \"command\": \"limit-surface\"", 0), 0u) << lines[1].substr(0, 80);
}

}  // namespace
}  // namespace wrenchkit
