// tests/checker_test.cpp - the independent certificate checker (proofs/checker/), format v1.
//
// Layers: every worked example in proofs/examples/ (valid ones accepted, invalid ones rejected for the
// reason listed in invalid-reasons.tsv); bad scenes (exact messages naming the JSON path); malformed
// certificates; mutations of every valid certificate that are invalid by construction, or valid by
// invariance; and a seeded random byte-mutation run that must never crash (run it under ASan/UBSan).
#include "proofs/checker/checker.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <random>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace {

using wrenchkit_checker::check;
using wrenchkit_checker::Limits;
using wrenchkit_checker::Outcome;
using wrenchkit_checker::Result;
namespace fs = std::filesystem;

const fs::path examples = fs::path(WRENCHKIT_SOURCE_DIR) / "proofs" / "examples";

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  EXPECT_TRUE(in) << "cannot open " << p;
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Certificate files ending in `suffix`, sorted, with the text of their scene (by name prefix).
struct Example {
  std::string file, scene, cert;
};
std::vector<Example> load_examples(const std::string& suffix) {
  std::vector<Example> out;
  for (const auto& entry : fs::directory_iterator(examples)) {
    const std::string f = entry.path().filename().string();
    if (f.size() < suffix.size() || f.compare(f.size() - suffix.size(), suffix.size(), suffix) != 0) continue;
    out.push_back({f, slurp(examples / (f.substr(0, f.find('.')) + ".scene.json")), slurp(entry.path())});
  }
  std::sort(out.begin(), out.end(), [](const Example& a, const Example& b) { return a.file < b.file; });
  return out;
}

// ---------------------------------------------------------------------------------------------
// Worked examples

TEST(CheckerExamples, ValidCertificatesAreAccepted) {
  const auto valid = load_examples(".valid.json");
  EXPECT_GE(valid.size(), 16u);
  for (const Example& e : valid) {
    const Result r = check(e.scene, e.cert);
    EXPECT_EQ(r.outcome, Outcome::accepted) << e.file << ": " << r.message;
    EXPECT_EQ(r.message, "accepted") << e.file;
  }
}

TEST(CheckerExamples, InvalidCertificatesAreRejectedForTheirReason) {
  std::map<std::string, std::string> reason;  // file -> text the message must contain
  std::istringstream tsv(slurp(examples / "invalid-reasons.tsv"));
  for (std::string line; std::getline(tsv, line);)
    if (!line.empty() && line[0] != '#') reason[line.substr(0, line.find('\t'))] = line.substr(line.find('\t') + 1);
  const auto invalid = load_examples(".invalid.json");
  EXPECT_GE(invalid.size(), 20u);
  EXPECT_EQ(invalid.size(), reason.size());
  for (const Example& e : invalid) {
    const Result r = check(e.scene, e.cert);
    EXPECT_EQ(r.outcome, Outcome::rejected) << e.file << ": " << r.message;
    ASSERT_TRUE(reason.count(e.file)) << e.file << " is not listed in invalid-reasons.tsv";
    EXPECT_NE(r.message.find(reason[e.file]), std::string::npos) << e.file << ": " << r.message;
  }
}

TEST(CheckerExamples, ScenesAreValid) {
  for (const auto& entry : fs::directory_iterator(examples)) {
    const std::string f = entry.path().filename().string();
    if (f.size() > 11 && f.substr(f.size() - 11) == ".scene.json") {
      EXPECT_NE(check(slurp(entry.path()), "{}").outcome, Outcome::bad_scene) << f;
    }
  }
}

// The two certificates printed in certificate-format.md §5, verbatim.
const char* const block_corner =
    R"({"wrenchkit": 1, "contacts": [{"at": [0,0], "normal": [0,1]}, {"at": [1,0], "normal": [0,1]},
        {"at": [0,0], "normal": [1,0]}, {"at": [0,1], "normal": [1,0]}]})";
const char* const square =
    R"({"wrenchkit": 1, "contacts": [{"at": ["3/2",0], "normal": [0,1]}, {"at": ["1/2",2], "normal": [0,-1]},
        {"at": [0,"3/2"], "normal": [1,0]}, {"at": [2,"1/2"], "normal": [-1,0]}]})";

const std::string negative_head = R"({"wrenchkit_certificate": 1, "property": "force_closure", "holds": false, )";
const std::string positive_head = R"({"wrenchkit_certificate": 1, "property": "form_closure", "holds": true, )";

TEST(CheckerExamples, SpecSection5) {
  const std::string negative =
      R"({"wrenchkit_certificate": 1, "property": "force_closure", "holds": false,
       "twist": ["0", "1", "0"], "reading": {"label": "infinity", "direction": ["-1", "0"]}})";
  EXPECT_EQ(check(block_corner, negative).outcome, Outcome::accepted);
  const std::string down = std::regex_replace(negative, std::regex(R"("0", "1", "0")"), R"("0", "-1", "0")");
  const Result r = check(block_corner, down);
  EXPECT_EQ(r.outcome, Outcome::rejected);
  EXPECT_EQ(r.message, "twist: power -1 against contacts[0] edge normal");

  const std::string positive = R"({"wrenchkit_certificate": 1, "property": "form_closure", "holds": true,
 "combination": [{"contact": 0, "edge": "normal", "weight": "1"},
                 {"contact": 1, "edge": "normal", "weight": "1"},
                 {"contact": 2, "edge": "normal", "weight": "1"},
                 {"contact": 3, "edge": "normal", "weight": "1"}],
 "independent": [{"contact": 0, "edge": "normal"}, {"contact": 1, "edge": "normal"},
                 {"contact": 2, "edge": "normal"}]})";
  EXPECT_EQ(check(square, positive).outcome, Outcome::accepted);
}

// ---------------------------------------------------------------------------------------------
// Bad scenes: Outcome::bad_scene, and the message names the JSON path

std::string scene_error(const std::string& scene, const Limits& limits = {}) {
  const Result r = check(scene, "{}", limits);
  EXPECT_EQ(r.outcome, Outcome::bad_scene) << scene.substr(0, 200) << " -> " << r.message;
  return r.message;
}
// A scene whose only contact is `contact`.
std::string one(const std::string& contact) { return R"({"wrenchkit": 1, "contacts": [)" + contact + "]}"; }
// A scene whose first contact is at (x, 0): to try the number grammar.
std::string at_x(const std::string& x) { return one(R"({"at": [)" + x + R"(, 0], "normal": [0, 1]})"); }

TEST(CheckerBadScene, PinnedMessages) {
  EXPECT_EQ(scene_error(R"({"wrenchkit": 1, "contacts": [{"at": [0,0], "normal": [0,1]},
                           {"at": [0,0], "normal": ["0", "0/5"]}]})"),
            "contacts[1].normal: zero vector");
  EXPECT_EQ(scene_error(one(R"({"at": [0,0], "normal": [0,1], "mu": "-1/2"})")),
            R"(contacts[0].mu: "-1/2" is negative)");
  EXPECT_EQ(scene_error(one(R"({"at": [0,0], "normal": [0,1], "mu": -0.1})")), R"(contacts[0].mu: "-0.1" is negative)");
  EXPECT_EQ(scene_error(at_x(R"("1/0")")), R"(contacts[0].at[0]: "1/0" has a zero denominator)");
  EXPECT_EQ(scene_error(at_x(R"("-7/000")")), R"(contacts[0].at[0]: "-7/000" has a zero denominator)");
  EXPECT_EQ(scene_error(one(R"({"at": [0, "NaN"], "normal": [0,1]})")), R"(contacts[0].at[1]: "NaN" is not a number)");
  EXPECT_EQ(scene_error(one(R"({"wrench": [0, 0, "0/3"]})")), "contacts[0].wrench: zero wrench");
  EXPECT_EQ(scene_error(R"({"wrenchkit": 1, "foo": 1})"), R"(unknown key "foo")");
  EXPECT_EQ(scene_error(one(R"({"at": [0,0], "normal": [0,1], "friction": 1})")),
            R"(contacts[0]: unknown key "friction")");
  EXPECT_EQ(scene_error(one(R"({"at": [0,0], "at": [0,0], "normal": [0,1]})")), R"(contacts[0]: duplicate key "at")");
  EXPECT_EQ(scene_error(R"({"wrenchkit": 1, "wrenchkit": 1})"), R"(duplicate key "wrenchkit")");
  EXPECT_EQ(scene_error(R"({"wrenchkit": 1, "body": {"com": [0, 0], "com": [1, 1]}})"), R"(body: duplicate key "com")");
  EXPECT_EQ(scene_error(R"({"wrenchkit": 1, "body": {"outline": [{"x": 1, "x": 2}]}})"),
            R"(body.outline[0]: duplicate key "x")");
  EXPECT_EQ(scene_error(R"({"wrenchkit": 2})"), "wrenchkit: expected 1 (the scene format version)");
  EXPECT_EQ(scene_error(R"({"contacts": []})"), R"(missing required key "wrenchkit")");
  EXPECT_EQ(scene_error(R"({"wrenchkit": 1, "contacts": {}})"), "contacts: expected an array");
  EXPECT_EQ(scene_error(R"({"wrenchkit": 1, "body": []})"), "body: expected an object");
  EXPECT_EQ(scene_error(R"({"wrenchkit": 1, "name": 3})"), "name: expected a string");
  EXPECT_EQ(scene_error(R"([1])"), "a scene must be a JSON object");
  EXPECT_EQ(scene_error(one(R"({"at": [0,0]})")), R"(contacts[0]: missing required key "normal")");
  EXPECT_EQ(scene_error(one(R"({"normal": [0,1]})")), R"(contacts[0]: missing required key "at")");
  EXPECT_EQ(scene_error(one(R"({"name": "x"})")),
            R"(contacts[0]: expected "at" and "normal" (a point contact) or "wrench")");
  EXPECT_EQ(scene_error(one(R"({"at": [0,0], "normal": [0,1], "wrench": [1,0,0]})")),
            R"(contacts[0]: a contact has either "at", "normal" and "mu" (a point contact) or "wrench", not both)");
  EXPECT_EQ(scene_error(one(R"({"at": [0,0,0], "normal": [0,1]})")), "contacts[0].at: expected an array of 2 numbers");
  EXPECT_EQ(scene_error(one(R"({"at": [0], "normal": [0,1]})")), "contacts[0].at: expected an array of 2 numbers");
  EXPECT_EQ(scene_error(one(R"({"wrench": [1, 0]})")), "contacts[0].wrench: expected an array of 3 numbers");
  EXPECT_EQ(scene_error(one(R"({"at": [0, null], "normal": [0,1]})")),
            "contacts[0].at[1]: expected a number (a JSON number or a number string)");
  EXPECT_EQ(scene_error(one("7")),
            R"(contacts[0]: expected an object {"at", "normal", "mu"?, "name"?} or {"wrench", "name"?})");
  EXPECT_EQ(scene_error(one(R"({"wrench": [1,0,0], "name": ["x"]})")), "contacts[0].name: expected a string");
}

TEST(CheckerBadScene, NumberLimits) {
  const std::string d10000(10000, '7'), d10001(10001, '7');
  EXPECT_NE(check(at_x(d10000), "{}").outcome, Outcome::bad_scene);
  EXPECT_NE(check(at_x('"' + d10000 + '"'), "{}").outcome, Outcome::bad_scene);
  EXPECT_EQ(scene_error(at_x(d10001)), "contacts[0].at[0]: number with 10001 digits (limit 10000)");
  EXPECT_EQ(scene_error(at_x('"' + d10001 + '"')), "contacts[0].at[0]: number with 10001 digits (limit 10000)");
  EXPECT_EQ(scene_error(at_x("\"1/" + d10000 + '"')), "contacts[0].at[0]: number with 10001 digits (limit 10000)");
  Limits wide;
  wide.max_digits = 20000;
  EXPECT_NE(check(at_x(d10001), "{}", wide).outcome, Outcome::bad_scene);

  EXPECT_NE(check(at_x("1e9999"), "{}").outcome, Outcome::bad_scene);
  EXPECT_NE(check(at_x("\"-.5E-9997\""), "{}").outcome, Outcome::bad_scene);  // -5/10^9998: 10000 digits
  // The value written out counts as the engine's reader counts it (its canonical "p/q" must read back).
  EXPECT_EQ(scene_error(at_x("1e10000")), "contacts[0].at[0]: number with 10001 digits written out (limit 10000)");
  EXPECT_EQ(scene_error(at_x("\"-.5E-9998\"")),
            "contacts[0].at[0]: number with 10001 digits written out (limit 10000)");
  EXPECT_EQ(scene_error(at_x("1e10001")), "contacts[0].at[0]: exponent 10001 out of range (limit 10000)");
  EXPECT_EQ(scene_error(at_x("\"1e-10001\"")), "contacts[0].at[0]: exponent -10001 out of range (limit 10000)");
  // no overflow: a 30-digit exponent, a 2^64 exponent, and leading zeros that hide a small one
  EXPECT_EQ(scene_error(at_x("1e999999999999999999999999999999")),
            "contacts[0].at[0]: exponent 999999999999999999999999999999 out of range (limit 10000)");
  EXPECT_EQ(scene_error(at_x("1e18446744073709551617")),
            "contacts[0].at[0]: exponent 18446744073709551617 out of range (limit 10000)");
  EXPECT_NE(check(at_x("1e000000000000000000000000000001"), "{}").outcome, Outcome::bad_scene);
  Limits low;
  low.max_exponent = 3;
  EXPECT_EQ(scene_error(at_x("1e4"), low), "contacts[0].at[0]: exponent 4 out of range (limit 3)");
}

TEST(CheckerBadScene, NumberGrammar) {
  for (const char* ok : {"0", "-0", "1.5", "1E+3", "\"+1\"", "\"-.5\"", "\"5.\"", "\"007\"", "\"3/6\"", "\"-0/7\"",
                         "\"1e-0\"", "\"+2/3\"", "\"0.0e0\""})
    EXPECT_NE(check(at_x(ok), "{}").outcome, Outcome::bad_scene) << ok;
  for (const char* bad : {"\"\"",        "\" 1\"",    "\"1 \"",  "\"0x10\"",     "\"Infinity\"",  "\"1/-2\"",
                          "\"1//2\"",    "\"1.2/3\"", "\"1e\"",  "\"e1\"",       "\".\"",         "\"+\"",
                          "\"1/2/3\"",   "\"1,5\"",   "\"/2\"",  "\"1/\"",       "\"1e1.5\"",     "\"--1\"",
                          "\"\\u0661\"", "\"1/2e3\"", "\".e1\"", "\"1\\u0000\"", "\"1\\u00002\"", "\"1e\\u00001\""})
    EXPECT_NE(scene_error(at_x(bad)).find("is not a number"), std::string::npos) << bad;
  // JSON's own number grammar is stricter than number strings: these are not JSON
  for (const char* bad : {"+1", ".5", "5.", "01", "1e", "NaN", "Infinity", "0x10", "-"})
    EXPECT_NE(scene_error(at_x(bad)).find("invalid JSON"), std::string::npos) << bad;
}

TEST(CheckerBadScene, JsonStrictness) {
  EXPECT_EQ(scene_error(""), "1:1: invalid JSON: unexpected end of input");
  EXPECT_EQ(scene_error("{\"wrenchkit\": 1} x"), "1:18: invalid JSON: unexpected data after the JSON value");
  EXPECT_EQ(scene_error("{\"wrenchkit\": 1,\n \"body\": {\"outline\": [1,]}}"),
            "2:25: invalid JSON: unexpected character ']'");
  EXPECT_EQ(scene_error("{\"wrenchkit\": 1,}"), "1:17: invalid JSON: expected a string as object key");
  EXPECT_EQ(scene_error("{\"wrenchkit\" 1}"), "1:14: invalid JSON: expected ':' after an object key");
  EXPECT_EQ(scene_error("{\"wrenchkit\": 1 \"name\": \"x\"}"),
            "1:17: invalid JSON: expected ',' or '}' after an object member");
  EXPECT_NE(scene_error("\xEF\xBB\xBF{\"wrenchkit\": 1}").find("invalid JSON: unexpected byte 0xef"),
            std::string::npos);
  auto named = [](const std::string& name) { return "{\"wrenchkit\": 1, \"name\": \"" + name + "\"}"; };
  EXPECT_NE(check(named("caf\xC3\xA9 \xF0\x9F\x98\x80 \\u00e9 \\ud83d\\ude00 \\\" \\/ \\u0000"), "{}").outcome,
            Outcome::bad_scene);
  for (const char* bad_utf8 : {"\xC3\x28", "\xC0\xAF", "\xE0\x80\xAF", "\xED\xA0\x80", "\xF4\x90\x80\x80",
                               "\xF8\x88\x80\x80\x80", "\x80", "\xE2\x82", "\xFF"})
    EXPECT_NE(scene_error(named(bad_utf8)).find("invalid JSON: invalid UTF-8"), std::string::npos);
  for (const char* lone : {"\\ud800", "\\udc00", "\\ud800\\u0041", "\\ud800x", "\\ud83d\\ud83d"})
    EXPECT_NE(scene_error(named(lone)).find("lone surrogate"), std::string::npos) << lone;
  EXPECT_EQ(scene_error(named("a\tb")), "1:28: invalid JSON: unescaped control character in a string");
  EXPECT_NE(scene_error(named("\\x")).find("invalid escape"), std::string::npos);
  EXPECT_NE(scene_error(named("\\u12G4")).find("four hex digits"), std::string::npos);
  EXPECT_NE(scene_error("{\"wrenchkit\": 1, \"body\": {\"outline\": [tru]}}").find("invalid literal"), std::string::npos);
  EXPECT_NE(scene_error("{\"wrenchkit\": 1, \"body\": {\"outline\": [nul]}}").find("invalid literal"), std::string::npos);
}

TEST(CheckerBadScene, Depth) {
  // top-level object (1) + body (2) + n arrays (body.outline's points are not interpreted: any JSON inside)
  auto nested = [](std::size_t n) {
    return "{\"wrenchkit\": 1, \"body\": {\"outline\": " + std::string(n, '[') + std::string(n, ']') + "}}";
  };
  EXPECT_NE(check(nested(62), "{}").outcome, Outcome::bad_scene);
  EXPECT_EQ(scene_error(nested(63)), "1:100: invalid JSON: nested deeper than 64 levels");
  EXPECT_NE(scene_error(nested(1000000)).find("nested deeper than 64 levels"), std::string::npos);
  Limits deep;  // the reader does not recurse: a million levels do not overflow the stack
  deep.max_depth = 2000000;
  EXPECT_NE(check(nested(1000000), "{}", deep).outcome, Outcome::bad_scene);
  // the limit applies to certificates too (format v1 certificates are at most 3 deep)
  Limits shallow;
  shallow.max_depth = 2;
  const std::string cert =
      negative_head + R"("twist": ["0", "1", "0"], "reading": {"label": "+", "point": ["0", "0"]}})";
  EXPECT_EQ(check(R"({"wrenchkit": 1, "contacts": []})", cert, shallow).message,
            "1:136: invalid JSON: nested deeper than 2 levels");
}

TEST(CheckerBadScene, ContactCount) {
  std::string scene = R"({"wrenchkit": 1, "contacts": [)";
  for (int i = 0; i < 100000; ++i) scene += R"({"wrench": [1, 0, 0]},)";
  const std::string cert = R"({"wrenchkit_certificate": 1, "property": "force_closure", "holds": false,
                              "twist": ["1", "0", "0"]})";
  EXPECT_EQ(check(scene + R"({"wrench": [0, 1, 0]}]})", cert).outcome, Outcome::bad_scene);
  EXPECT_EQ(check(scene + R"({"wrench": [0, 1, 0]}]})", cert).message, "contacts: more than 100000 contacts");
  scene.pop_back();
  EXPECT_EQ(check(scene + "]}", cert).outcome, Outcome::accepted);  // 100000 generators, all power 1
  Limits few;
  few.max_contacts = 2;
  EXPECT_EQ(scene_error(block_corner, few), "contacts: more than 2 contacts");
}

// ---------------------------------------------------------------------------------------------
// Numbers are read exactly

TEST(CheckerExactness, SceneNumbersAreExact) {
  // Six wrench generators, in opposite pairs written differently; weights 1 sum to zero only if every
  // pair is read as exactly opposite values.
  auto scene = [](const std::string& a, const std::string& b) {
    return R"({"wrenchkit": 1, "contacts": [{"wrench": [)" + a + R"(, 0, 0]}, {"wrench": [)" + b +
           R"(, 0, 0]}, {"wrench": [0, "25e-2", 0]}, {"wrench": [0, "-1/4", 0]},
           {"wrench": [0, 0, 1.5]}, {"wrench": [0, 0, "-3/2"]}]})";
  };
  const std::string cert = R"({"wrenchkit_certificate": 1, "property": "form_closure", "holds": true,
    "combination": [{"contact": 0, "edge": "wrench", "weight": "1"}, {"contact": 1, "edge": "wrench", "weight": "1"},
                    {"contact": 2, "edge": "wrench", "weight": "1"}, {"contact": 3, "edge": "wrench", "weight": "1"},
                    {"contact": 4, "edge": "wrench", "weight": "1"}, {"contact": 5, "edge": "wrench", "weight": "1"}],
    "independent": [{"contact": 0, "edge": "wrench"}, {"contact": 2, "edge": "wrench"},
                    {"contact": 4, "edge": "wrench"}]})";
  for (const auto& [a, b] : std::vector<std::pair<std::string, std::string>>{
           {"0.1", "\"-1/10\""},
           {"\"1e-9998\"", "\"-0.0001e-9994\""},
           {"\"010\"", "-10"},  // decimal, not octal
           {"\"3/6\"", "\"-.5\""},
           {"12345678901234567890123456789", "\"-12345678901234567890123456789e0\""},
           {"\"1.\"", "\"-1/1\""}})
    EXPECT_EQ(check(scene(a, b), cert).outcome, Outcome::accepted) << a << " " << b;
  for (const auto& [a, b] : std::vector<std::pair<std::string, std::string>>{
           {"0.1", "\"-1/11\""}, {"\"010\"", "-8"}, {"\"1e-9998\"", "\"-1e-9997\""}, {"0.30000000000000004", "-0.3"}})
    EXPECT_EQ(check(scene(a, b), cert).message.rfind("combination: the weighted sum", 0), 0u) << a << " " << b;
}

// ---------------------------------------------------------------------------------------------
// Malformed certificates: Outcome::rejected with a precise reason

std::string rejection(const std::string& scene, const std::string& cert) {
  const Result r = check(scene, cert);
  EXPECT_EQ(r.outcome, Outcome::rejected) << cert << " -> " << r.message;
  return r.message;
}
const std::string square_independent =
    R"("independent": [{"contact": 0, "edge": "normal"}, {"contact": 1, "edge": "normal"}, {"contact": 2, "edge": "normal"}])";
// The square's positive certificate with the first term's contact index written as `index`.
std::string square_with_index(const std::string& index) {
  return positive_head + R"("combination": [{"contact": )" + index + R"(, "edge": "normal", "weight": "1"},
    {"contact": 1, "edge": "normal", "weight": "1"}, {"contact": 2, "edge": "normal", "weight": "1"},
    {"contact": 3, "edge": "normal", "weight": "1"}], )" +
         square_independent + "}";
}

TEST(CheckerMalformed, TruncatedCertificatesAreRejected) {
  for (const Example& e : load_examples(".valid.json")) {
    const std::size_t end = e.cert.rfind('}');
    for (std::size_t n = 0; n < end; ++n) {
      const Result r = check(e.scene, e.cert.substr(0, n));
      ASSERT_EQ(r.outcome, Outcome::rejected) << e.file << " cut at " << n;
      ASSERT_NE(r.message.find("invalid JSON"), std::string::npos) << e.file << " cut at " << n << ": " << r.message;
    }
  }
}

TEST(CheckerMalformed, ContactIndices) {
  EXPECT_EQ(check(square, square_with_index("0")).outcome, Outcome::accepted);
  const std::string not_integer =
      "combination[0].contact: expected a contact index: a JSON integer without sign, fraction or exponent, not ";
  EXPECT_EQ(rejection(square, square_with_index("1e2")), not_integer + "1e2");
  EXPECT_EQ(rejection(square, square_with_index("0e0")), not_integer + "0e0");
  EXPECT_EQ(rejection(square, square_with_index("-1")), not_integer + "-1");
  EXPECT_EQ(rejection(square, square_with_index("-0")), not_integer + "-0");
  EXPECT_EQ(rejection(square, square_with_index("0.0")), not_integer + "0.0");
  EXPECT_EQ(rejection(square, square_with_index("\"0\"")),
            "combination[0].contact: expected a contact index (a JSON integer)");
  EXPECT_NE(rejection(square, square_with_index("00")).find("invalid JSON"), std::string::npos);
  EXPECT_EQ(rejection(square, square_with_index("4")),
            "combination[0].contact: index 4 is out of range (the scene has 4 contacts)");
  for (const char* big : {"18446744073709551615", "18446744073709551616", "999999999999999999", "1000000000000000000"})
    EXPECT_EQ(rejection(square, square_with_index(big)),
              "combination[0].contact: index " + std::string(big) + " is out of range (the scene has 4 contacts)");
  const std::string huge = "9" + std::string(5000, '0');
  EXPECT_EQ(rejection(square, square_with_index(huge)),
            "combination[0].contact: index " + huge.substr(0, 40) +
                "... (5001 characters) is out of range (the scene has 4 contacts)");
}

TEST(CheckerMalformed, KeysAndTypes) {
  const std::string twist = R"("twist": ["0", "1", "0"])";
  EXPECT_EQ(check(block_corner, negative_head + twist + "}").outcome, Outcome::accepted);
  EXPECT_EQ(rejection(block_corner, "[]"), "a certificate must be a JSON object");
  EXPECT_EQ(rejection(block_corner, "{}"), R"(missing required key "wrenchkit_certificate")");
  EXPECT_EQ(rejection(block_corner, R"({"wrenchkit_certificate": 1, "property": "force_closure", )" + twist + "}"),
            R"(missing required key "holds")");
  EXPECT_EQ(rejection(block_corner, R"({"wrenchkit_certificate": 1, "holds": false, )" + twist + "}"),
            R"(missing required key "property")");
  for (const char* version : {"7", "0", "2.0", "1.0", "1e0", "\"1\"", "true"})
    EXPECT_EQ(rejection(block_corner, R"({"wrenchkit_certificate": )" + std::string(version) +
                                          R"(, "property": "force_closure", "holds": false, )" + twist + "}"),
              "wrenchkit_certificate: expected the integer 1, 2, 3, 4, 5 or 6");
  // Format 6 is property "push" (§8) and nothing else.
  EXPECT_EQ(rejection(block_corner, R"({"wrenchkit_certificate": 6, "property": "force_closure", "holds": false, )" + twist + "}"),
            R"(wrenchkit_certificate: format 6 is property "push" only)");
  // Format 5 is property "grasp_regions" (§3.6) and nothing else.
  EXPECT_EQ(rejection(block_corner, R"({"wrenchkit_certificate": 5, "property": "force_closure", "holds": false, )" + twist + "}"),
            R"(wrenchkit_certificate: format 5 is property "grasp_regions" only)");
  // Format 4 adds property "quality" (§3.4) and nothing else.
  EXPECT_EQ(rejection(block_corner, R"({"wrenchkit_certificate": 4, "property": "force_closure", "holds": false, )" + twist + "}"),
            R"(wrenchkit_certificate: format 4 is properties "quality" and "critical_mu" only (expected 1, 2 or 3))");
  // Format 3 names the boundary of motion and hold only: a closure certificate reads the same in 1, 2 and 3.
  for (const char* version : {"1", "2", "3"})
    EXPECT_EQ(check(block_corner, R"({"wrenchkit_certificate": )" + std::string(version) +
                                      R"(, "property": "force_closure", "holds": false, )" + twist + "}")
                  .outcome,
              Outcome::accepted)
        << version;
  EXPECT_EQ(
      rejection(block_corner, R"({"wrenchkit_certificate": 1, "property": "closure", "holds": false, )" + twist + "}"),
      R"(property: expected "force_closure", "form_closure", "equilibrium", "motion", "hold", "quality", "critical_mu", "grasp_regions" or "push")");
  EXPECT_EQ(rejection(block_corner,
                      R"({"wrenchkit_certificate": 1, "property": "force_closure", "holds": "false", )" + twist + "}"),
            R"(holds: expected true or false (or "impending" or "depends" for property "hold"))");
  EXPECT_EQ(rejection(block_corner, negative_head + twist + R"(, "holds": false})"), R"(duplicate key "holds")");
  EXPECT_EQ(rejection(block_corner, negative_head + twist + R"(, "Twist": 1})"), R"(unknown key "Twist")");
  EXPECT_EQ(rejection(block_corner, negative_head + R"("reading": {"label": "+", "point": ["0", "0"]}})"),
            R"(missing required key "twist")");
  EXPECT_EQ(rejection(block_corner, negative_head + twist + R"(, "combination": []})"),
            R"(combination: expected a non-empty array of {"contact", "edge", "weight"})");
  EXPECT_EQ(rejection(block_corner, negative_head + twist + R"(, "independent": [{"contact": 0, "edge": "normal"},
            {"contact": 1, "edge": "normal"}, {"contact": 2, "edge": "normal"}]})"),
            R"(key "independent" is not allowed when "holds" is false)");
  EXPECT_EQ(rejection(square, positive_head + square_independent + "}"), R"(missing required key "combination")");
  EXPECT_EQ(rejection(square, positive_head + R"("reading": {"label": "infinity", "direction": ["1", "0"]},
            "combination": [{"contact": 0, "edge": "normal", "weight": "1"}], )" +
                                  square_independent + "}"),
            R"(key "reading" is not allowed when "holds" is true)");
  EXPECT_EQ(rejection(square, positive_head + R"("combination": [{"contact": 0, "edge": "normal", "weight": 1}], )" +
                                  square_independent + "}"),
            R"(combination[0].weight: expected a rational as a JSON string, such as "-3/4")");
  EXPECT_EQ(rejection(square,
                      positive_head + R"("combination": [{"contact": 0, "weight": "1"}], )" + square_independent + "}"),
            R"(combination[0]: missing required key "edge")");
  EXPECT_EQ(rejection(square, positive_head +
                                  R"("combination": [{"contact": 0, "edge": "normal", "weight": "1", "x": 0}], )" +
                                  square_independent + "}"),
            R"(combination[0]: unknown key "x")");
  EXPECT_EQ(rejection(square, positive_head + R"("combination": [{"contact": 0, "edge": "normal", "weight": "1"}],
            "independent": [{"contact": 0, "edge": "normal", "weight": "1"}]})"),
            R"(independent[0]: unknown key "weight")");
  EXPECT_EQ(rejection(square, positive_head + R"("combination": [{"contact": 0, "edge": "normal", "weight": "1"}],
            "independent": [{"contact": 0, "edge": "normal"}]})"),
            R"(independent: expected an array of three {"contact", "edge"})");
  EXPECT_EQ(rejection(block_corner, negative_head + R"("twist": ["0", "1"]})"),
            "twist: expected an array of three rationals [vx, vy, w]");
  EXPECT_EQ(rejection(block_corner, negative_head + R"("twist": ["0", "1", "0", "0"]})"),
            "twist: expected an array of three rationals [vx, vy, w]");
  EXPECT_EQ(rejection(block_corner, negative_head + R"("twist": "0 1 0"})"),
            "twist: expected an array of three rationals [vx, vy, w]");
  EXPECT_EQ(rejection(block_corner, negative_head + twist + R"(, "reading": {"label": "up", "point": ["0", "0"]}})"),
            R"(reading.label: expected "+", "-" or "infinity")");
  EXPECT_EQ(
      rejection(block_corner, negative_head + twist + R"(, "reading": {"label": "infinity", "point": ["0", "0"]}})"),
      R"(reading: label "infinity" needs "direction" and no "point")");
  EXPECT_EQ(rejection(block_corner, negative_head + twist + R"(, "reading": {"label": "+", "direction": ["0", "0"]}})"),
            R"(reading: label "+" needs "point" and no "direction")");
  EXPECT_EQ(rejection(block_corner, negative_head + twist + R"(, "reading": {"direction": ["-1", "0"]}})"),
            R"(reading: missing required key "label")");
  EXPECT_EQ(rejection(block_corner, negative_head + twist +
                                        R"(, "reading": {"label": "infinity", "direction": ["-1", "0"], "z": 0}})"),
            R"(reading: unknown key "z")");
}

TEST(CheckerMalformed, Rationals) {
  auto with_vx = [](const std::string& vx) { return negative_head + R"("twist": [)" + vx + R"(, "1", "0"]})"; };
  for (const char* ok : {"\"0\"", "\"-0\"", "\"0/5\"", "\"-0/5\"", "\"\\u0030\""})
    EXPECT_EQ(check(block_corner, with_vx(ok)).outcome, Outcome::accepted) << ok;
  for (const char* bad :
       {"\"00\"", "\"+0\"", "\"01\"", "\"1/01\"", "\"1/0\"", "\"1/-2\"", "\"-/2\"", "\" 0\"", "\"0 \"", "\"0.0\"",
        "\"1e0\"", "\"\"", "\"-\"", "\"1/\"", "\"/1\"", "\"1/2/3\"", "\"0x0\"", "\"--0\""})
    EXPECT_NE(rejection(block_corner, with_vx(bad)).find("is not a rational of the form"), std::string::npos) << bad;
  EXPECT_EQ(rejection(block_corner, with_vx("0")), R"(twist[0]: expected a rational as a JSON string, such as "-3/4")");
  const std::string long_ok = "\"0/1" + std::string(99997, '0') + "\"";  // 100000 characters
  EXPECT_EQ(check(block_corner, with_vx(long_ok)).outcome, Outcome::accepted);
  const std::string too_long = "\"0/1" + std::string(99998, '0') + "\"";
  EXPECT_EQ(rejection(block_corner, with_vx(too_long)), "twist[0]: rational of 100001 characters (limit 100000)");
}

TEST(CheckerConditions, PinnedMessages) {
  // a scene with a fifth contact, so that `independent` can name a generator outside `combination`
  const std::string five = R"({"wrenchkit": 1, "contacts": [{"at": ["3/2",0], "normal": [0,1]}, {"at": ["1/2",2],
      "normal": [0,-1]}, {"at": [0,"3/2"], "normal": [1,0]}, {"at": [2,"1/2"], "normal": [-1,0]},
      {"at": [1, 1], "normal": [1, 1], "mu": "1/3"}]})";
  const std::string comb = R"("combination": [{"contact": 0, "edge": "normal", "weight": "1"},
      {"contact": 1, "edge": "normal", "weight": "1"}, {"contact": 2, "edge": "normal", "weight": "1"},
      {"contact": 3, "edge": "normal", "weight": "1"}], )";
  EXPECT_EQ(check(five, positive_head + comb + square_independent + "}").outcome, Outcome::accepted);
  EXPECT_EQ(rejection(five, positive_head + comb + R"("independent": [{"contact": 0, "edge": "normal"},
      {"contact": 1, "edge": "normal"}, {"contact": 4, "edge": "normal"}]})"),
            "independent[2]: contacts[4] edge normal is not in combination");
  EXPECT_EQ(rejection(five, positive_head + comb + R"("independent": [{"contact": 0, "edge": "normal"},
      {"contact": 1, "edge": "normal"}, {"contact": 4, "edge": "left"}]})"),
            R"(independent[2].edge: contacts[4] has no edge "left" under the frictionless reading (it has "normal"))");
  // friction reading of the fifth contact: n = (1,1), mu = 1/3 at p = (1,1); left edge (2/3, 4/3), moment 2/3
  const std::string friction_head = R"({"wrenchkit_certificate": 1, "property": "force_closure", "holds": false, )";
  EXPECT_EQ(rejection(five, friction_head + R"("twist": ["0", "0", "-1"]})"),
            "twist: power -3/2 against contacts[0] edge normal");
  EXPECT_EQ(rejection(five, friction_head + R"("twist": ["0", "1", "0"]})"),
            "twist: power -1 against contacts[1] edge normal");
  EXPECT_EQ(rejection(five, friction_head + R"("twist": ["1", "0", "0"]})"),
            "twist: power -1 against contacts[3] edge normal");
  EXPECT_EQ(rejection(block_corner,
                      negative_head + R"("twist": ["0", "1", "-2"], "reading": {"label": "-", "point": ["1", "0"]}})"),
            "twist: power -1 against contacts[1] edge normal");
  // a reading's direction must be a positive multiple, not any parallel vector
  const std::string up = negative_head + R"("twist": ["0", "3", "0"], "reading": {"label": "infinity", "direction": )";
  EXPECT_EQ(check(block_corner, up + R"(["-1/7", "0"]}})").outcome, Outcome::accepted);
  EXPECT_EQ(rejection(block_corner, up + R"(["1", "0"]}})"),
            "reading.direction: (1, 0) is not a positive multiple of (-vy, vx) = (-3, 0)");
  EXPECT_EQ(rejection(block_corner, up + R"(["0", "0"]}})"),
            "reading.direction: (0, 0) is not a positive multiple of (-vy, vx) = (-3, 0)");
  EXPECT_EQ(rejection(block_corner, up + R"(["-1", "1/1000"]}})"),
            "reading.direction: (-1, 1/1000) is not a positive multiple of (-vy, vx) = (-3, 0)");
}

// ---------------------------------------------------------------------------------------------
// Equilibrium (certificate-format.md §3.3): the scene's load, and the certificate's conditions

// `scene` (a JSON object) with `members` added at its end.
std::string plus(const std::string& scene, const std::string& members) {
  return scene.substr(0, scene.rfind('}')) + ", " + members + "}";
}
const std::string equilibrium_true = R"({"wrenchkit_certificate": 1, "property": "equilibrium", "holds": true, )";
const std::string equilibrium_false = R"({"wrenchkit_certificate": 1, "property": "equilibrium", "holds": false, )";

TEST(CheckerLoad, BadLoadsAndBodies) {
  const std::string v1 = R"({"wrenchkit": 1})";
  const std::string com = R"("body": {"com": [0, 0]})";
  // the four required ones
  EXPECT_EQ(scene_error(plus(v1, R"("load": {"x": 1})")), R"(load: unknown key "x")");
  EXPECT_EQ(scene_error(plus(v1, R"("load": {"gravity": 1})")),
            "load.gravity: needs body.com (the point where the weight acts)");
  EXPECT_EQ(scene_error(plus(v1, com + R"(, "load": {"gravity": 0})")),
            R"(load.gravity: "0" is not positive (a weight must be > 0))");
  EXPECT_EQ(scene_error(plus(v1, R"("load": [0, -1])")),
            R"(load: expected an object {"force", "at"}, {"wrench"} or {"gravity"})");
  // more of them
  EXPECT_EQ(scene_error(plus(v1, R"("body": {"outline": []}, "load": {"gravity": 1})")),
            "load.gravity: needs body.com (the point where the weight acts)");
  EXPECT_EQ(scene_error(plus(v1, R"("load": {"gravity": "0/5"})")),
            R"(load.gravity: "0/5" is not positive (a weight must be > 0))");
  EXPECT_EQ(scene_error(plus(v1, com + R"(, "load": {"gravity": "-1/2"})")),
            R"(load.gravity: "-1/2" is not positive (a weight must be > 0))");
  EXPECT_EQ(scene_error(plus(v1, com + R"(, "load": {"gravity": 1, "x": 1})")), R"(load: unknown key "x")");
  EXPECT_EQ(scene_error(plus(v1, R"("load": "gravity")")),
            R"(load: expected an object {"force", "at"}, {"wrench"} or {"gravity"})");
  EXPECT_EQ(scene_error(plus(v1, R"("load": {})")),
            R"(load: expected one of {"force", "at"}, {"wrench"} or {"gravity"})");
  // mixed forms: gravity, else wrench, else force and at (as the engine reads them); the rest is unknown
  EXPECT_EQ(scene_error(plus(v1, com + R"(, "load": {"wrench": [0, 0, 1], "gravity": 1})")),
            R"(load: unknown key "wrench")");
  EXPECT_EQ(scene_error(plus(v1, R"("load": {"at": [0, 0], "wrench": [0, 0, 1]})")), R"(load: unknown key "at")");
  EXPECT_EQ(scene_error(plus(v1, R"("load": {"force": [0, 1]})")), R"(load: missing required key "at")");
  EXPECT_EQ(scene_error(plus(v1, R"("load": {"at": [0, 1]})")), R"(load: missing required key "force")");
  EXPECT_EQ(scene_error(plus(v1, R"("load": {"gravity": 1, "gravity": 2})")), R"(load: duplicate key "gravity")");
  // numbers: the scene grammar and limits
  EXPECT_EQ(scene_error(plus(v1, R"("load": {"wrench": [0, 0]})")), "load.wrench: expected an array of 3 numbers");
  EXPECT_EQ(scene_error(plus(v1, R"("load": {"force": [0, "x"], "at": [0, 0]})")),
            R"(load.force[1]: "x" is not a number)");
  EXPECT_EQ(scene_error(plus(v1, R"("load": {"force": [0, 1], "at": [0, null]})")),
            "load.at[1]: expected a number (a JSON number or a number string)");
  EXPECT_EQ(scene_error(plus(v1, com + R"(, "load": {"gravity": "1e10001"})")),
            "load.gravity: exponent 10001 out of range (limit 10000)");
  EXPECT_EQ(scene_error(plus(v1, R"("load": {"gravity": 1}, "body": {"com": ["1/0", 0]})")),
            R"(body.com[0]: "1/0" has a zero denominator)");
  // body: outline (not interpreted beyond its type) and com; nothing else
  EXPECT_EQ(scene_error(plus(v1, R"("body": {"mass": 1})")), R"(body: unknown key "mass")");
  EXPECT_EQ(scene_error(plus(v1, R"("body": {"com": [0, 0, 0]})")), "body.com: expected an array of 2 numbers");
  EXPECT_EQ(scene_error(plus(v1, R"("body": {"outline": {}})")), "body.outline: expected an array of points");
  // valid loads, in any member order (body after load)
  for (const char* ok : {R"("load": {"force": [0, -1], "at": ["1/2", 0.5]})",
                         R"("load": {"at": [0, 0], "force": [0, 0]})", R"("load": {"wrench": [0, 0, 0]})",
                         R"("load": {"gravity": "1e-9998"}, "body": {"com": [0, 0]})",
                         R"("body": {"outline": [[0, 0], [1, 0], [0, 1]], "com": [0, 0]}, "load": {"gravity": 1})"})
    EXPECT_NE(check(plus(v1, ok), "{}").outcome, Outcome::bad_scene) << ok;
}

// Gravity beside a support is the weight pressing the body on it: W and c = body.com, read as the engine reads them
// (exact/io/support_check.h); a conflict is a bad scene, agreeing values are a good one.
TEST(CheckerLoad, GravityBesideASupportSetsItsWeight) {
  const std::string base = R"({"wrenchkit": 1, "body": {"com": [0, 0]}, "load": {"gravity": 2}, "support": {"mu": 1, )";
  const std::string pts = R"("points": [{"at": [0, 1]}, {"at": [0, -1]}]}})";
  EXPECT_EQ(check(base + pts, "{}").outcome == Outcome::bad_scene, false);
  EXPECT_EQ(check(base + R"("weight": 2, "pressure_center": [0, 0], )" + pts, "{}").outcome == Outcome::bad_scene, false);
  EXPECT_EQ(scene_error(base + R"("weight": 3, )" + pts), "load.gravity: the weight 2 is not support.weight 3");
  EXPECT_EQ(scene_error(base + R"("pressure_center": [0, "1/2"], )" + pts),
            "support.pressure_center: (0, 1/2) is not body.com (0, 0), where the weight acts");
  // Given forces: they carry the weight at body.com, or the scene is refused.
  EXPECT_NE(scene_error(base + R"("points": [{"at": [0, 1], "force": 1}, {"at": [0, -1], "force": "1/2"}]}})"), "");
  EXPECT_NE(scene_error(base + R"("points": [{"at": [0, 1], "force": 2}]}})"), "");
  EXPECT_EQ(check(base + R"("points": [{"at": [0, 1], "force": 1}, {"at": [0, -1], "force": 1}]}})", "{}").outcome ==
                Outcome::bad_scene,
            false);
}

TEST(CheckerLoad, ClosureIgnoresTheLoad) {
  // force_closure / form_closure certificates are checked exactly as without a load
  const std::string negative = negative_head + R"("twist": ["0", "1", "0"]})";
  const std::string positive = positive_head + R"("combination": [{"contact": 0, "edge": "normal", "weight": "1"},
      {"contact": 1, "edge": "normal", "weight": "1"}, {"contact": 2, "edge": "normal", "weight": "1"},
      {"contact": 3, "edge": "normal", "weight": "1"}], )" + square_independent + "}";
  for (const char* load : {R"("load": {"wrench": [1, 2, 3]})", R"("load": {"gravity": 5}, "body": {"com": [9, 9]})"}) {
    EXPECT_EQ(check(plus(block_corner, load), negative).outcome, Outcome::accepted) << load;
    EXPECT_EQ(check(plus(square, load), positive).outcome, Outcome::accepted) << load;
    EXPECT_EQ(rejection(plus(block_corner, load), negative_head + R"("twist": ["0", "-1", "0"]})"),
              "twist: power -1 against contacts[0] edge normal");
  }
}

TEST(CheckerEquilibrium, TheLoadWrench) {
  // Four wrench generators that positively span R^3: -w_ext = (0, 2, 6) = 2 g1 + 6 g2 for each of these
  // loads, all w_ext = (0, -2, -6): a force (0,-2) at (3,5) has moment 3*(-2) - 5*0 = -6; gravity 2
  // at com (3,7) is (0, -2, -2*3) (com_y plays no part); and the wrench itself.
  const std::string gens =
      R"({"wrenchkit": 1, "contacts": [{"wrench": [1, 0, 0]}, {"wrench": [0, 1, 0]}, {"wrench": [0, 0, 1]},
          {"wrench": [-1, -1, -1]}]})";
  auto cert = [](const std::string& w1, const std::string& w2) {
    return equilibrium_true + R"("combination": [{"contact": 1, "edge": "wrench", "weight": ")" + w1 +
           R"("}, {"contact": 2, "edge": "wrench", "weight": ")" + w2 + R"("}]})";
  };
  for (const char* load : {R"("load": {"force": [0, "-2"], "at": [3, "5.0"]})",
                           R"("load": {"at": [3, 5], "force": [0, -2]})",
                           R"("load": {"gravity": "2"}, "body": {"com": ["3", 7]})",
                           R"("body": {"com": ["30e-1", -7]}, "load": {"gravity": 2})",
                           R"("load": {"wrench": [0, -2, "-6"]})"}) {
    const std::string scene = plus(gens, load);
    EXPECT_EQ(check(scene, cert("2", "6")).outcome, Outcome::accepted) << load;
    EXPECT_EQ(check(scene, cert("4/2", "12/2")).outcome, Outcome::accepted) << load;
    EXPECT_EQ(rejection(scene, cert("2", "-6")), R"(combination[1].weight: "-6" is not strictly positive)") << load;
    EXPECT_EQ(rejection(scene, cert("2", "5")),
              "combination: the weighted sum of the generators plus the load is (0, 0, -1), not (0, 0, 0)")
        << load;
    EXPECT_EQ(rejection(scene, cert("20", "60")),
              "combination: the weighted sum of the generators plus the load is (0, 18, 54), not (0, 0, 0)")
        << load;
  }
  // gravity acts at com, not at the origin: with com (0, 7) the load is (0, -2, 0)
  EXPECT_EQ(rejection(plus(gens, R"("load": {"gravity": 2}, "body": {"com": [0, 7]})"), cert("2", "6")),
            "combination: the weighted sum of the generators plus the load is (0, 0, 6), not (0, 0, 0)");
}

TEST(CheckerEquilibrium, EdgeCases) {
  const std::string empty = equilibrium_true + R"("combination": []})";
  // an empty combination balances exactly the zero load
  EXPECT_EQ(check(R"({"wrenchkit": 1, "load": {"wrench": [0, 0, 0]}})", empty).outcome, Outcome::accepted);
  EXPECT_EQ(check(plus(block_corner, R"("load": {"force": [0, 0], "at": [7, 7]})"), empty).outcome, Outcome::accepted);
  EXPECT_EQ(rejection(plus(block_corner, R"("load": {"force": [0, -1], "at": ["1/2", "1/2"]})"), empty),
            "combination: the weighted sum of the generators plus the load is (0, -1, -1/2), not (0, 0, 0)");
  EXPECT_EQ(rejection(R"({"wrenchkit": 1, "load": {"wrench": [0, 0, "1e-9998"]}})", empty),
            "combination: the weighted sum of the generators plus the load is "
            "(0, 0, 1/10000000000000000000000000000000000000... (10001 characters)), not (0, 0, 0)");
  // "property" may come after an empty combination; other properties still need a non-empty one
  EXPECT_EQ(check(R"({"wrenchkit": 1, "load": {"wrench": [0, 0, 0]}})",
                  R"({"combination": [], "wrenchkit_certificate": 1, "holds": true, "property": "equilibrium"})")
                .outcome,
            Outcome::accepted);
  const std::string non_empty = R"(combination: expected a non-empty array of {"contact", "edge", "weight"})";
  EXPECT_EQ(rejection(square, R"({"combination": [], "wrenchkit_certificate": 1, "holds": true,
                                  "property": "form_closure", )" + square_independent + "}"),
            non_empty);
  EXPECT_EQ(rejection(square, R"({"wrenchkit_certificate": 1, "holds": true, "combination": []})"), non_empty);
  EXPECT_EQ(rejection(square, positive_head + R"("combination": [], )" + square_independent + "}"), non_empty);
  EXPECT_EQ(rejection(square, equilibrium_true + R"("combination": {}})"),
            R"(combination: expected an array of {"contact", "edge", "weight"})");

  // holds = false: the twist must drive the load with positive power
  const std::string frictionless = plus(block_corner, R"("load": {"wrench": [0, 0, 1]})");
  EXPECT_EQ(rejection(frictionless, equilibrium_false + R"("twist": ["0", "1", "0"]})"),
            "twist: power against the load is 0, not > 0");  // powers 1, 1, 0, 0 against the contacts
  const std::string gravity = plus(block_corner, R"("load": {"gravity": 1}, "body": {"com": ["1/2", "1/2"]})");
  EXPECT_EQ(rejection(gravity, equilibrium_false + R"("twist": ["0", "1/2", "0"]})"),
            "twist: power against the load is -1/2, not > 0");
  const std::string lifted = plus(block_corner, R"("load": {"force": [0, 1], "at": ["1/2", "1/2"]})");
  EXPECT_EQ(check(lifted, equilibrium_false + R"("twist": ["0", "1/2", "0"]})").outcome, Outcome::accepted);
  const std::string up = equilibrium_false + R"("twist": ["0", "1", "0"], "reading": {"label": "infinity", )";
  EXPECT_EQ(check(lifted, up + R"("direction": ["-1", "0"]}})").outcome, Outcome::accepted);
  EXPECT_EQ(rejection(lifted, up + R"("direction": ["1", "0"]}})"),
            "reading.direction: (1, 0) is not a positive multiple of (-vy, vx) = (-1, 0)");
  EXPECT_EQ(rejection(lifted, equilibrium_false + R"("twist": ["0", "0", "0"]})"),
            "twist: the zero twist proves nothing");
  // a generator with negative power is reported before the load
  EXPECT_EQ(rejection(lifted, equilibrium_false + R"("twist": ["0", "-1", "0"]})"),
            "twist: power -1 against contacts[0] edge normal");

  // no load: no equilibrium claim, either way
  EXPECT_EQ(rejection(square, equilibrium_true + R"("combination": [{"contact": 0, "edge": "normal", "weight": "1"},
      {"contact": 1, "edge": "normal", "weight": "1"}, {"contact": 2, "edge": "normal", "weight": "1"},
      {"contact": 3, "edge": "normal", "weight": "1"}]})"),
            R"(property: "equilibrium" needs a scene with a load)");
  EXPECT_EQ(rejection(block_corner, equilibrium_false + R"("twist": ["0", "1", "0"]})"),
            R"(property: "equilibrium" needs a scene with a load)");
  EXPECT_EQ(rejection(R"({"wrenchkit": 1})", empty), R"(property: "equilibrium" needs a scene with a load)");

  // keys
  const std::string three = R"("independent": [{"contact": 0, "edge": "normal"}, {"contact": 1, "edge": "normal"},
      {"contact": 2, "edge": "normal"}])";
  EXPECT_EQ(rejection(gravity, equilibrium_true + R"("combination": [], )" + three + "}"),
            R"(key "independent" is not allowed when "property" is "equilibrium")");
  EXPECT_EQ(rejection(gravity, equilibrium_false + R"("twist": ["0", "1", "0"], )" + three + "}"),
            R"(key "independent" is not allowed when "property" is "equilibrium")");
  EXPECT_EQ(rejection(gravity, equilibrium_true + R"("twist": ["0", "1", "0"], "combination": []})"),
            R"(key "twist" is not allowed when "holds" is true)");
  EXPECT_EQ(rejection(gravity,
                      equilibrium_true + R"("combination": [], "reading": {"label": "+", "point": ["0", "0"]}})"),
            R"(key "reading" is not allowed when "holds" is true)");
  EXPECT_EQ(rejection(gravity, equilibrium_false + R"("twist": ["0", "1", "0"], "combination": []})"),
            R"(key "combination" is not allowed when "holds" is false)");
  EXPECT_EQ(rejection(gravity, equilibrium_true + R"("reading": {"label": "+", "point": ["0", "0"]}})"),
            R"(missing required key "combination")");
  EXPECT_EQ(rejection(gravity, equilibrium_false + R"("combination": []})"), R"(missing required key "twist")");

  // the friction reading, references and duplicates as in §3.1
  const std::string rough = R"({"wrenchkit": 1, "contacts": [{"at": [0, 0], "normal": [0, 1], "mu": 1}],
      "load": {"force": [0, -2], "at": [0, 0]}})";  // left (-1,1,0), right (1,1,0): -w_ext = left + right
  EXPECT_EQ(check(rough, equilibrium_true + R"("combination": [{"contact": 0, "edge": "left", "weight": "1"},
      {"contact": 0, "edge": "right", "weight": "1"}]})").outcome,
            Outcome::accepted);
  EXPECT_EQ(rejection(rough, equilibrium_true + R"("combination": [{"contact": 0, "edge": "normal", "weight": "2"}]})"),
            R"(combination[0].edge: contacts[0] has no edge "normal" under the friction reading )"
            R"((it has "left" or "right"))");
  EXPECT_EQ(rejection(rough, equilibrium_true + R"("combination": [{"contact": 0, "edge": "left", "weight": "1/2"},
      {"contact": 0, "edge": "right", "weight": "1"}, {"contact": 0, "edge": "left", "weight": "1/2"}]})"),
            "combination[2]: contacts[0] edge left appears twice (also at combination[0])");
  EXPECT_EQ(rejection(rough, equilibrium_true + R"("combination": [{"contact": 1, "edge": "left", "weight": "1"}]})"),
            "combination[0].contact: index 1 is out of range (the scene has 1 contacts)");
  EXPECT_EQ(rejection(rough, equilibrium_true + R"("combination": [{"contact": 0, "edge": "left", "weight": "0"},
      {"contact": 0, "edge": "right", "weight": "1"}]})"),
            R"(combination[0].weight: "0" is not strictly positive)");
}

TEST(CheckerExamples, EquilibriumExamples) {
  // the block in a corner of theory.md §9 under its loads, and the invalid certificates of the list
  int valid = 0, invalid = 0;
  for (const Example& e : load_examples(".valid.json")) valid += e.cert.find(R"("equilibrium")") != std::string::npos;
  for (const Example& e : load_examples(".invalid.json"))
    invalid += e.cert.find(R"("equilibrium")") != std::string::npos;
  EXPECT_GE(valid, 8);
  EXPECT_GE(invalid, 7);
  for (const char* f : {"block_corner_mu_1_2_gravity.equilibrium.valid.json",
                        "block_corner_mu_1_2_push.equilibrium.valid.json",
                        "block_corner_mu_1_2_pull.not_balanced_translation.valid.json",
                        "block_corner_mu_1_2_torque.zero_power_against_load.invalid.json",
                        "square_crossed_couples.equilibrium_without_load.invalid.json"})
    EXPECT_TRUE(fs::exists(examples / f)) << f;
}

// ---------------------------------------------------------------------------------------------
// Mutations of every valid certificate

// Replaces the text of the n-th match of `re`'s first group in `s`.
std::string replace_group(const std::string& s, const std::regex& re, std::size_t n, const std::string& with) {
  auto it = std::sregex_iterator(s.begin(), s.end(), re);
  std::advance(it, static_cast<std::ptrdiff_t>(n));
  const auto pos = static_cast<std::size_t>(it->position(1));
  return s.substr(0, pos) + with + s.substr(pos + static_cast<std::size_t>(it->length(1)));
}
// The certificate rational r times 10: a '0' after the numerator (0 stays 0).
std::string times10(const std::string& r) {
  const std::size_t slash = std::min(r.find('/'), r.size());
  if (r == "0" || r == "-0" || r.rfind("0/", 0) == 0 || r.rfind("-0/", 0) == 0) return r;
  return r.substr(0, slash) + "0" + r.substr(slash);
}
std::string negated(const std::string& r) { return r[0] == '-' ? r.substr(1) : "-" + r; }

const std::regex weight_re(R"re("weight": "([^"]*)")re");
const std::regex twist_re(R"re("twist": \[("[^"]*", "[^"]*", "[^"]*")\])re");
const std::regex component_re(R"re("([^"]*)")re");

TEST(CheckerMutations, PositiveCertificates) {
  // Sum_k l_k g_k (+ w_ext) = 0 and every generator is nonzero (normals and friction edges
  // n +- mu rot90(n) are nonzero, and so are wrench generators), so changing one weight by d != 0
  // leaves the sum d g_k != 0: every single-weight change is invalid. Scaling all weights by 10 keeps a
  // closure certificate valid; an equilibrium certificate's sum becomes -9 w_ext, not zero (every
  // example's load is nonzero), so it is rejected: the load is part of the sum.
  int tried = 0, equilibria = 0;
  for (const Example& e : load_examples(".valid.json")) {
    const auto count = static_cast<std::size_t>(
        std::distance(std::sregex_iterator(e.cert.begin(), e.cert.end(), weight_re), std::sregex_iterator()));
    std::string all10 = e.cert;
    for (std::size_t k = 0; k < count; ++k) {
      auto it = std::sregex_iterator(e.cert.begin(), e.cert.end(), weight_re);
      std::advance(it, static_cast<std::ptrdiff_t>(k));
      const std::string weight = it->str(1);
      for (const std::string& mutated : {std::string("0"), negated(weight), times10(weight), weight + "1"}) {
        const Result r = check(e.scene, replace_group(e.cert, weight_re, k, mutated));
        EXPECT_EQ(r.outcome, Outcome::rejected) << e.file << " weight " << k << " -> " << mutated;
        ++tried;
      }
      all10 = replace_group(all10, weight_re, k, times10(weight));
    }
    if (count > 0 && e.cert.find(R"("property": "equilibrium")") != std::string::npos) {
      ++equilibria;
      const std::string prefix = "combination: the weighted sum of the generators plus the load is ";
      const std::string m = check(e.scene, all10).message;  // (nested in a critical_mu certificate: after its path)
      EXPECT_TRUE(m.rfind(prefix, 0) == 0 || m.rfind("above.certificate: " + prefix, 0) == 0) << e.file << " all weights x10";
    } else if (count > 0 && e.cert.find(R"("property": "hold")") != std::string::npos) {
      const std::string prefix = "combination: the contact forces";  // a hold's sum has the load in it too
      EXPECT_EQ(check(e.scene, all10).message.rfind(prefix, 0), 0u) << e.file << " all weights x10";
    } else if (count > 0) {
      EXPECT_EQ(check(e.scene, all10).outcome, Outcome::accepted) << e.file << " all weights x10";
    }
  }
  EXPECT_GE(tried, 100);
  EXPECT_GE(equilibria, 5);
}

TEST(CheckerMutations, NegativeCertificates) {
  // Negating the twist (and dropping the reading, which would then be wrong) stays valid exactly when
  // every power is zero; these are the examples where that holds (checked by hand: the rotations about
  // G = (1,1) of the triangle are first-order motions that keep all three frictionless contacts, and the
  // two fingers' normals are both horizontal, so a vertical translation has power 0 against both).
  const std::set<std::string> all_powers_zero = {"triangle_mu_1_10.form_rotation_about_G.valid.json",
                                                 "triangle_mu_1_10.form_rotation_about_G_clockwise.valid.json",
                                                 "two_finger_mu_1_2.form_translate_up.valid.json",
                                                 "two_fingers_mu0.quality_zero.valid.json"};
  const std::regex reading_re(R"re(,\s*"reading": \{[^}]*\})re");
  int negatives = 0;
  std::set<std::string> seen;
  for (const Example& e : load_examples(".valid.json")) {
    std::smatch m;
    if (e.cert.find(R"("property": "motion")") != std::string::npos) continue;  // sliding: CheckerMotion*
    if (e.cert.find(R"("property": "hold")") != std::string::npos) continue;    // the speed bounds scale too: CheckerHold*
    if (!std::regex_search(e.cert, m, twist_re)) continue;
    ++negatives;
    const std::string twist = m.str(1);
    std::vector<std::string> t;
    for (auto it = std::sregex_iterator(twist.begin(), twist.end(), component_re); it != std::sregex_iterator(); ++it)
      t.push_back(it->str(1));
    ASSERT_EQ(t.size(), 3u);
    auto with = [&](const std::string& a, const std::string& b, const std::string& c) {
      return replace_group(e.cert, twist_re, 0, "\"" + a + "\", \"" + b + "\", \"" + c + "\"");
    };
    EXPECT_EQ(check(e.scene, with("0", "0", "0")).outcome, Outcome::rejected) << e.file;
    // positive scaling keeps every sign, the rotation centre and the direction of a translation
    EXPECT_EQ(check(e.scene, with(times10(t[0]), times10(t[1]), times10(t[2]))).outcome, Outcome::accepted) << e.file;
    const std::string minus = with(negated(t[0]), negated(t[1]), negated(t[2]));
    if (minus.find("\"reading\"") != std::string::npos) {
      EXPECT_EQ(check(e.scene, minus).outcome, Outcome::rejected) << e.file << ": the reading no longer matches";
    }
    const Outcome expected = all_powers_zero.count(e.file) ? Outcome::accepted : Outcome::rejected;
    EXPECT_EQ(check(e.scene, std::regex_replace(minus, reading_re, "")).outcome, expected) << e.file << " negated";
    if (all_powers_zero.count(e.file)) seen.insert(e.file);
  }
  EXPECT_GE(negatives, 7);
  EXPECT_EQ(seen, all_powers_zero);
}

// ---------------------------------------------------------------------------------------------
// Fixed width against GMP. The integer checks run on fixed-width integers first and again on GMP integers
// whenever a result overflows them (Limits::fixed_width); the two must agree, message
// included, on every example, on mutations of examples and scenes, and on random scenes whose numbers
// have mixed numbers of digits (different denominators) and sizes around and past 64 bits, with valid
// certificates and invalid ones.

using Q = mpq_class;

Result check_gmp_only(const std::string& scene, const std::string& cert) {
  Limits l;
  l.fixed_width = false;
  return check(scene, cert, l);
}
// The fixed-width result; fails the test if GMP alone says otherwise.
Result expect_same(const std::string& scene, const std::string& cert, const std::string& what) {
  const Result fixed = check(scene, cert), gmp = check_gmp_only(scene, cert);
  EXPECT_EQ(fixed.outcome, gmp.outcome) << what << "\nscene: " << scene << "\ncertificate: " << cert;
  EXPECT_EQ(fixed.message, gmp.message) << what << "\nscene: " << scene << "\ncertificate: " << cert;
  return fixed;
}

// text with one random digit replaced by a random digit (the text itself if it has none)
std::string mutate_digit(std::string text, std::mt19937_64& rng) {
  std::vector<std::size_t> at;
  for (std::size_t i = 0; i < text.size(); ++i)
    if (text[i] >= '0' && text[i] <= '9') at.push_back(i);
  if (!at.empty()) text[at[rng() % at.size()]] = static_cast<char>('0' + rng() % 10);
  return text;
}

TEST(CheckerFixedWidth, ExamplesAndMutations) {
  std::mt19937_64 rng(19);
  int checked = 0, accepted = 0;
  for (const std::string suffix : {".valid.json", ".invalid.json"})
    for (const Example& e : load_examples(suffix)) {
      accepted += expect_same(e.scene, e.cert, e.file).outcome == Outcome::accepted;
      for (int k = 0; k < 30; ++k) {
        expect_same(e.scene, mutate_digit(e.cert, rng), e.file + ": a digit of the certificate changed");
        expect_same(mutate_digit(e.scene, rng), e.cert, e.file + ": a digit of the scene changed");
        checked += 2;
      }
    }
  EXPECT_GE(checked, 2000);
  EXPECT_GE(accepted, 20);
}

// A random decimal with `digits` digits after the point and up to `whole` digits before it, as text and
// value; sometimes a fraction p/q.
struct Number {
  std::string text;
  Q value;
};
Number random_number(std::mt19937_64& rng, int whole, int digits) {
  std::string t = rng() % 2 ? "-" : "";
  if (rng() % 5 == 0) {  // a fraction
    const std::string p = std::to_string(1 + rng() % 1000000), q = std::to_string(1 + rng() % 999983);
    t += p + "/" + q;
    Q v(t);
    v.canonicalize();
    return {"\"" + t + "\"", v};
  }
  unsigned long long bound = 1;
  for (int k = 0; k < whole; ++k) bound *= 10;
  t += std::to_string(rng() % bound);  // no leading zero (JSON)
  std::string frac;
  for (int k = 0; k < digits; ++k) frac += static_cast<char>('0' + rng() % 10);
  Q v(mpz_class(t + frac, 10), 1);
  mpz_class ten;
  mpz_ui_pow_ui(ten.get_mpz_t(), 10, static_cast<unsigned long>(digits));
  v /= ten;
  return {t + (digits > 0 ? "." + frac : ""), v};
}

// the digits of a scene or certificate number for a test scenario: short (6), mixed (1 to 9), long (12 to
// 20, past 64 bits) or very long (30)
int digits_for(int scenario, std::mt19937_64& rng) {
  switch (scenario % 4) {
    case 0: return 6;
    case 1: return 1 + static_cast<int>(rng() % 9);
    case 2: return 12 + static_cast<int>(rng() % 9);
    default: return 30;
  }
}

TEST(CheckerFixedWidth, RandomPositiveCertificates) {
  // Vec3q contacts g1, g2, g3 and g4 = -(a1 g1 + a2 g2 + a3 g3) / a4: the weights a are a valid
  // combination (when g1, g2, g3 are independent); one weight changed is not.
  std::mt19937_64 rng(1919);
  int accepted = 0;
  for (int scenario = 0; scenario < 400; ++scenario) {
    const int digits = digits_for(scenario, rng);
    Number g[3][3];
    for (auto& w : g)
      for (auto& x : w) x = random_number(rng, scenario % 2 ? 3 : 1, digits);
    Q a[4];
    std::string a_text[4];
    for (int k = 0; k < 4; ++k) {
      a_text[k] = std::to_string(1 + rng() % (scenario % 2 ? 1000000000 : 1000)) +
                  (rng() % 3 == 0 ? "/" + std::to_string(1 + rng() % 9) : "");
      if (scenario % 4 == 3) a_text[k] = "1234567890123456789012345" + std::to_string(rng() % 100);
      a[k] = Q(a_text[k]);
      a[k].canonicalize();
    }
    std::string contacts;
    for (const auto& w : g) contacts += R"({"wrench": [)" + w[0].text + ", " + w[1].text + ", " + w[2].text + "]}, ";
    Q g4[3];
    for (int i = 0; i < 3; ++i) g4[i] = -(a[0] * g[0][i].value + a[1] * g[1][i].value + a[2] * g[2][i].value) / a[3];
    if (g4[0] == 0 && g4[1] == 0 && g4[2] == 0) continue;
    contacts += R"({"wrench": [")" + g4[0].get_str() + R"(", ")" + g4[1].get_str() + R"(", ")" + g4[2].get_str() + "\"]}";
    const std::string scene = R"({"wrenchkit": 1, "contacts": [)" + contacts + "]}";
    auto cert = [&](const std::string (&w)[4]) {
      std::string c = R"({"wrenchkit_certificate": 1, "property": "force_closure", "holds": true, "combination": [)";
      for (int k = 0; k < 4; ++k)
        c += (k ? ", " : "") + std::string(R"({"contact": )") + std::to_string(k) + R"(, "edge": "wrench", "weight": ")" +
             w[k] + "\"}";
      return c + R"(], "independent": [{"contact": 0, "edge": "wrench"}, {"contact": 1, "edge": "wrench"}, )"
                 R"({"contact": 2, "edge": "wrench"}]})";
    };
    const std::string what = "scenario " + std::to_string(scenario);
    accepted += expect_same(scene, cert(a_text), what).outcome == Outcome::accepted;
    std::string changed[4] = {a_text[0], a_text[1], a_text[2], a_text[3]};
    changed[rng() % 4] += "1";
    EXPECT_EQ(expect_same(scene, cert(changed), what + ", a weight changed").outcome, Outcome::rejected);
  }
  EXPECT_GE(accepted, 350);
}

TEST(CheckerFixedWidth, RandomNegativeCertificates) {
  // Point contacts whose friction edges all have power >= 0 against a random twist (a contact is dropped,
  // or its normal flipped, to make it so): the twist with its reading is valid; a reading moved, or the
  // twist negated, is not.
  std::mt19937_64 rng(2019);
  int accepted = 0;
  for (int scenario = 0; scenario < 400; ++scenario) {
    const int digits = digits_for(scenario, rng);
    Number t[3];
    for (auto& x : t) x = random_number(rng, 2, scenario % 4 == 3 ? 25 : 0);
    if (scenario % 5 == 0) t[2] = {"0", Q(0)};  // a translation: the reading is a direction
    if (t[0].value == 0 && t[1].value == 0 && t[2].value == 0) continue;
    std::string contacts;
    int kept = 0;
    for (int c = 0; c < 6; ++c) {
      Number x[5];
      for (int k = 0; k < 4; ++k) x[k] = random_number(rng, 1, digits);
      if (x[2].value == 0 && x[3].value == 0) continue;
      x[4] = random_number(rng, 1, 3);
      x[4].text = x[4].text[0] == '-' ? x[4].text.substr(1) : x[4].text;  // mu >= 0
      if (x[4].text[0] == '"') x[4].text = "\"" + x[4].text.substr(x[4].text[1] == '-' ? 2 : 1);
      x[4].value = abs(x[4].value);
      // power of the force f at p against t: vx fx + vy fy + w (px fy - py fx)
      auto power = [&](const Q& fx, const Q& fy) -> Q {
        return t[0].value * fx + t[1].value * fy + t[2].value * (x[0].value * fy - x[1].value * fx);
      };
      const Q &nx = x[2].value, &ny = x[3].value, &mu = x[4].value;
      const Q left = power(nx - mu * ny, ny + mu * nx), right = power(nx + mu * ny, ny - mu * nx);
      std::string n0 = x[2].text, n1 = x[3].text;
      if (left < 0 && right < 0) {
        auto minus = [](const std::string& text) {  // the number text negated, as written otherwise
          const std::size_t at = text[0] == '"' ? 1 : 0;
          return text[at] == '-' ? text.substr(0, at) + text.substr(at + 1) : text.substr(0, at) + "-" + text.substr(at);
        };
        n0 = minus(n0), n1 = minus(n1);
      } else if (left < 0 || right < 0) {
        continue;
      }
      contacts += std::string(kept++ ? ", " : "") + R"({"at": [)" + x[0].text + ", " + x[1].text + R"(], "normal": [)" +
                  n0 + ", " + n1 + R"(], "mu": )" + x[4].text + "}";
    }
    const std::string scene = R"({"wrenchkit": 1, "contacts": [)" + contacts + "]}";
    const Q &vx = t[0].value, &vy = t[1].value, &w = t[2].value;
    std::string reading;
    Q where[2];
    if (w != 0) {
      where[0] = -vy / w, where[1] = vx / w;
      reading = std::string(R"({"label": ")") + (w > 0 ? "+" : "-") + R"(", "point": [")";
    } else {
      where[0] = -vy * 3, where[1] = vx * 3;
      reading = R"({"label": "infinity", "direction": [")";
    }
    auto cert = [&](const Q (&tw)[3], const Q (&p)[2]) {
      return R"({"wrenchkit_certificate": 1, "property": "force_closure", "holds": false, "twist": [")" +
             tw[0].get_str() + R"(", ")" + tw[1].get_str() + R"(", ")" + tw[2].get_str() + R"("], "reading": )" +
             reading + p[0].get_str() + R"(", ")" + p[1].get_str() + "\"]}}";
    };
    const std::string what = "scenario " + std::to_string(scenario);
    const Q twist[3] = {t[0].value, t[1].value, t[2].value};
    accepted += expect_same(scene, cert(twist, where), what).outcome == Outcome::accepted;
    const Q moved[2] = {where[0] + Q(1, 3), where[1]};
    const Outcome moved_outcome = expect_same(scene, cert(twist, moved), what + ", the reading moved").outcome;
    if (w != 0) {  // (a direction may stay parallel)
      EXPECT_EQ(moved_outcome, Outcome::rejected) << what;
    }
    const Q minus[3] = {-twist[0], -twist[1], -twist[2]};
    expect_same(scene, cert(minus, where), what + ", the twist negated");
  }
  EXPECT_GE(accepted, 350);
}

// ---------------------------------------------------------------------------------------------
// Sliding (certificate-format.md §6): the support in the scene, and property "motion"

// support = {...}: a scene with only this support (and, if com, body.com).
std::string with_support(const std::string& support, const std::string& com = "") {
  return R"({"wrenchkit": 1, )" + (com.empty() ? "" : R"("body": {"com": )" + com + "}, ") + R"("support": )" + support +
         "}";
}
const std::string table_points = R"("points": [{"at": [1, 1]}, {"at": [-1, 1]}, {"at": [-1, -1]}, {"at": [1, -1]}])";

TEST(CheckerSupport, BadSupports) {
  auto bad = [](const std::string& support, const std::string& com = "") { return scene_error(with_support(support, com)); };
  EXPECT_EQ(bad(R"({"mu": 1, "points": []})"), "support.points: empty (a support needs at least one point or region)");
  EXPECT_EQ(bad(R"({"mu": 1})"), R"(support: missing required key "points" (a support needs points or regions))");
  EXPECT_EQ(bad(R"({"mu": 1, "points": [{"at": [0, 0], "force": 1}], "extra": 1})"), R"(support: unknown key "extra")");
  EXPECT_EQ(bad(R"({"mu": 1, "points": [{"at": [0, 0], "force": 1, "name": "x"}]})"),
            R"(support.points[0]: unknown key "name")");
  EXPECT_EQ(bad(R"({"mu": 1, "points": [{"force": 1}]})"), R"(support.points[0]: missing required key "at")");
  EXPECT_EQ(bad(R"({"points": [{"at": [0, 0], "force": 1, "mu": 1}, {"at": [1, 0], "force": 1}]})"),
            R"(support.points[1]: missing key "mu" (and support.mu gives no default))");
  EXPECT_EQ(bad(R"({"mu": "-1/2", "points": [{"at": [0, 0], "force": 1}]})"), R"(support.mu: "-1/2" is negative)");
  EXPECT_EQ(bad(R"({"mu": 1, "points": [{"at": [0, 0], "force": 1, "mu": -1}]})"),
            R"(support.points[0].mu: "-1" is negative)");
  EXPECT_EQ(bad(R"({"mu": 1, "points": [{"at": [0, 0], "force": "-1e-3"}]})"),
            R"(support.points[0].force: "-1e-3" is negative)");
  EXPECT_EQ(bad(R"({"mu": 1, "points": [{"at": [0, 0], "force": 0}, {"at": [1, 0], "force": "0/3"}]})"),
            "support.points: all forces are zero");
  EXPECT_EQ(bad(R"({"mu": 1, "points": [{"at": [0, "x"], "force": 1}]})"),
            R"(support.points[0].at[1]: "x" is not a number)");
  EXPECT_EQ(bad(R"({"mu": 1, "points": [{"at": [0, )" + std::string(10001, '7') + R"(], "force": 1}]})"),
            "support.points[0].at[1]: number with 10001 digits (limit 10000)");
  EXPECT_EQ(bad(R"({"mu": 1, "points": [{"at": [0, 0], "force": 1e10001}]})"),
            "support.points[0].force: exponent 10001 out of range (limit 10000)");
  EXPECT_EQ(bad(R"({"mu": 1, "weight": 0, )" + table_points + "}"),
            R"(support.weight: "0" is not positive (a weight must be > 0))");
  EXPECT_EQ(bad("[]"), "support: expected an object");
  Limits few;
  few.max_contacts = 3;
  EXPECT_EQ(scene_error(with_support(R"({"mu": 1, "weight": 1, )" + table_points + "}", "[0, 0]"), few),
            "support.points: more than 3 points");
  // unknown forces need W and c
  EXPECT_EQ(bad(R"({"mu": 1, "pressure_center": [0, 0], )" + table_points + "}"),
            R"(support: missing key "weight" (required when a point has no "force"))");
  EXPECT_EQ(bad(R"({"mu": 1, "weight": 1, )" + table_points + "}"),
            R"(support: missing key "pressure_center" (required when a point has no "force" and body.com is not given))");
  // every force given: weight and pressure_center must agree exactly
  const std::string barbell = R"("points": [{"at": [0, -1], "force": "1/4"}, {"at": [0, 1], "force": "3/4"}])";
  EXPECT_EQ(bad(R"({"mu": 1, "weight": "1.1", )" + barbell + "}"), "support.weight: 11/10 is not the sum 1 of the given forces");
  EXPECT_EQ(bad(R"({"mu": 1, "pressure_center": [0, 0], )" + barbell + "}"),
            "support.pressure_center: (0, 0) is not the centre of pressure (0, 1/2) of the given forces");
  EXPECT_NE(check(with_support(R"({"mu": 1, "weight": 1, "pressure_center": [0, 0.5], )" + barbell + "}", "[9, 9]"), "{}")
                .outcome,
            Outcome::bad_scene);  // body.com is not the centre of pressure of a known distribution
}

TEST(CheckerSupport, EmptyAdmissibleSetHasAReason) {
  const std::string none = "support: no admissible distribution: ";
  auto bad = [](const std::string& support, const std::string& com = "") { return scene_error(with_support(support, com)); };
  EXPECT_EQ(bad(R"({"mu": 1, "weight": 1, "pressure_center": [2, 0], )" + table_points + "}"),
            none + "the centre of pressure (2, 0) is outside the convex hull of the support points (the body would tip over)");
  EXPECT_EQ(bad(R"({"mu": 1, "weight": 1, )" + table_points + "}", R"(["1.5", "-1/2"])"),
            none + "the centre of pressure (3/2, -1/2) is outside the convex hull of the support points (the body would "
                   "tip over)");
  // known forces: too heavy; the whole weight, off centre; the rest outside the hull of the others
  EXPECT_EQ(bad(R"({"mu": 1, "weight": 1, "pressure_center": [0, 0], "points": [{"at": [1, 1], "force": 2}, {"at": [-1, -1]}]})"),
            none + "the given forces sum to 2, more than support.weight 1");
  EXPECT_EQ(bad(R"({"mu": 1, "weight": 1, "pressure_center": [0, 0], "points": [{"at": [1, 1], "force": 1}, {"at": [-1, -1]}]})"),
            none + "the given forces carry the whole weight 1, but their centre of pressure (1, 1) is not the centre of "
                   "pressure (0, 0)");
  EXPECT_EQ(bad(R"({"mu": 1, "weight": 1, "pressure_center": [0, 0], "points": [{"at": [1, 1], "force": "1/2"},
                 {"at": [1, -1]}, {"at": [2, 0]}]})"),
            none + "the points without a given force must carry the remaining weight 1/2 with its centre at (-1, -1), which "
                   "is outside their convex hull");
  // degenerate hulls: a point, a segment (collinear, coincident points), c on an edge or at a vertex
  const std::vector<std::pair<std::string, bool>> cases = {
      {R"([{"at": [1, 1]}, {"at": [1, 1]}], "pressure_center": [1, 1])", true},
      {R"([{"at": [1, 1]}, {"at": [1, 1]}], "pressure_center": [1, "1.0001"])", false},
      {R"([{"at": [0, 0]}, {"at": [1, 1]}, {"at": [2, 2]}, {"at": [2, 2]}], "pressure_center": ["3/2", "3/2"])", true},
      {R"([{"at": [0, 0]}, {"at": [1, 1]}, {"at": [2, 2]}], "pressure_center": [3, 3])", false},
      {R"([{"at": [0, 0]}, {"at": [1, 1]}, {"at": [2, 2]}], "pressure_center": [-1, -1])", false},
      {R"([{"at": [0, 0]}, {"at": [1, 1]}, {"at": [2, 2]}], "pressure_center": [1, "1/1000000"])", false},
      {R"([{"at": [1, 1]}, {"at": [-1, 1]}, {"at": [-1, -1]}, {"at": [1, -1]}], "pressure_center": [1, 0])", true},
      {R"([{"at": [1, 1]}, {"at": [-1, 1]}, {"at": [-1, -1]}, {"at": [1, -1]}], "pressure_center": [-1, -1])", true},
      {R"([{"at": [1, 1]}, {"at": [-1, 1]}, {"at": [-1, -1]}, {"at": [1, -1]}], "pressure_center": ["-1.001", 0])", false},
      {R"([{"at": [0, 0]}, {"at": [4, 0]}, {"at": [0, 4]}, {"at": [1, 1]}], "pressure_center": [2, 2])", true},
      {R"([{"at": [0, 0]}, {"at": [4, 0]}, {"at": [0, 4]}, {"at": [1, 1]}], "pressure_center": [2, "2.01"])", false},
      {R"([{"at": [3, 0]}, {"at": [0, 0]}, {"at": [1, 0]}, {"at": [0, 3]}, {"at": [0, 1]}], "pressure_center": [1, 1])", true},
  };
  for (const auto& [rest, admissible] : cases) {
    const Result r = check(with_support(R"({"mu": 1, "weight": 2, "points": )" + rest + "}"), "{}");
    EXPECT_EQ(r.outcome != Outcome::bad_scene, admissible) << rest << " -> " << r.message;
    if (!admissible) {
      EXPECT_EQ(r.message.rfind(none, 0), 0u) << r.message;
    }
  }
}

const std::string table_scene =
    with_support(R"({"mu": 1, "weight": 1, "pressure_center": [0, 0], )" + table_points + "}");
const std::string motion_head = R"({"wrenchkit_certificate": 1, "property": "motion", )";

TEST(CheckerMotion, KeysAndScenes) {
  const std::string sticks = motion_head + R"("load": ["0", "0", "0"], "motion": "sticks", )";
  EXPECT_EQ(rejection(block_corner, sticks + R"("support_forces": []})"),
            R"(property: "motion" needs a scene with a support)");
  EXPECT_EQ(rejection(table_scene, motion_head + R"("motion": "sticks", "vertices": []})"), R"(missing required key "load")");
  EXPECT_EQ(rejection(table_scene, motion_head + R"("load": ["0", "0", "0"], "vertices": []})"),
            R"(missing required key "motion")");
  EXPECT_EQ(rejection(table_scene, sticks + R"("vertices": [], "holds": true})"),
            R"(key "holds" is not allowed when "property" is "motion")");
  EXPECT_EQ(rejection(table_scene, sticks + R"("support_forces": []})"),
            R"(key "support_forces" is not allowed when "motion" is "sticks" and some support force is unknown)");
  EXPECT_EQ(rejection(table_scene, sticks + R"("vertices": [], "dual": ["0", "0", "0"]})"),
            R"(key "dual" is not allowed when "motion" is "sticks" and some support force is unknown)");
  EXPECT_EQ(rejection(table_scene, sticks + R"("vertices": [{"distribution": [], "support_forces": [], "x": 1}]})"),
            R"(vertices[0]: unknown key "x")");
  EXPECT_EQ(rejection(table_scene, sticks + R"("vertices": [{"distribution": []}]})"),
            R"(vertices[0]: missing required key "support_forces")");
  EXPECT_EQ(rejection(table_scene, sticks + R"("vertices": [{"distribution": ["1/2", "0", "1/2"], "support_forces": []}]})"),
            "vertices[0].distribution: 3 entries, but the support has 4 points");
  EXPECT_EQ(rejection(table_scene, sticks + R"("vertices": [{"distribution": ["1/2", "0", "1/2", 0], "support_forces": []}]})"),
            R"(vertices[0].distribution[3]: expected a rational as a JSON string, such as "-3/4")");
  EXPECT_EQ(rejection(table_scene, motion_head + R"("load": ["0", "0", "0"], "motion": "stops", "vertices": []})"),
            R"(motion: expected "sticks", "impending", "slides" or "depends")");
  EXPECT_EQ(rejection(table_scene, motion_head + R"("load": ["0", "0"], "motion": "sticks", "vertices": []})"),
            "load: expected an array of three rationals [fx, fy, m]");
  EXPECT_EQ(rejection(table_scene, sticks + R"("vertices": []})"),
            "vertices: the vertex (1/2, 0, 1/2, 0) of the admissible distributions has no witness");
  // motion keys in other properties
  EXPECT_EQ(rejection(block_corner, negative_head + R"("twist": ["0", "1", "0"], "load": ["0", "0", "0"]})"),
            R"(key "load" is not allowed when "property" is "force_closure")");
  // a distribution outside F, entry by entry
  const std::string depends = motion_head + R"("load": ["0", "0", "0"], "motion": "depends", "sliding": )"
                              R"({"distribution": ["1/2", "0", "1/2", "0"], "twist": ["0", "0", "0"], "speed_bounds": ["0", "0", "0", "0"]}, )";
  auto sticking = [&](const std::string& d) {
    return depends + R"("sticking": {"distribution": [)" + d + R"(], "support_forces": [["0", "0"], ["0", "0"], ["0", "0"], ["0", "0"]]}})";
  };
  EXPECT_EQ(rejection(table_scene, sticking(R"("1", "-1/2", "1", "-1/2")")), "sticking.distribution[1]: -1/2 is negative");
  EXPECT_EQ(rejection(table_scene, sticking(R"("1/2", "0", "1/4", "0")")),
            "sticking.distribution: the forces sum to 3/4, not the weight 1");
  EXPECT_EQ(rejection(table_scene, sticking(R"("1/2", "0", "1/2", "0")")),
            "sliding.twist: the zero twist");
  const std::string mixed =
      with_support(R"({"mu": 1, "weight": 1, "pressure_center": [0, 0], "points": [{"at": [1, 1], "force": "1/4"},
                   {"at": [-1, 1]}, {"at": [-1, -1]}, {"at": [1, -1]}]})");
  EXPECT_EQ(rejection(mixed, sticking(R"("1/2", "0", "1/2", "0")")),
            "sticking.distribution[0]: 1/2 is not the given force 1/4 of support.points[0]");
}

TEST(CheckerMotion, InteriorSticksBoundarySlides) {
  // A load sticks when it is in the interior of LS(f), slides on or past its boundary (theory.md §11, SL-1 §3).
  const std::string barbell = with_support(R"({"mu": "1/2", "points": [{"at": [0, -1], "force": "1/2"}, {"at": [0, 1], "force": "1/2"}]})");
  auto sticks = [&](const std::string& load, const std::string& g) {
    return motion_head + R"("load": )" + load + R"(, "motion": "sticks", "support_forces": )" + g + "}";
  };
  auto slides = [&](const std::string& load, const std::string& q) {
    return motion_head + R"("load": )" + load + R"(, "motion": "slides", "twist": )" + q + R"(, "speed_bounds": ["1", "1"]})";
  };
  EXPECT_EQ(check(barbell, sticks(R"(["1/2", "0", "0"])", R"([["1/4", "0"], ["1/4", "0"]])")).message,
            "support_forces[0]: |g|^2 = 1/16 is not less than (mu f)^2 = 1/16");  // g on its circle
  EXPECT_EQ(check(barbell, sticks(R"(["1/2", "0", "0"])", R"([["1/5", "0"], ["3/10", "0"]])")).message,
            "support_forces[1]: |g|^2 = 9/100 is not less than (mu f)^2 = 1/16");
  EXPECT_EQ(check(barbell, sticks(R"(["1/2", "0", "0"])", R"([["1/5", "0"], ["1/5", "0"]])")).message,
            "support_forces: the support forces give the load (2/5, 0, 0), not (1/2, 0, 0)");
  EXPECT_EQ(check(barbell, sticks(R"(["2/5", "0", "0"])", R"([["1/5", "0"], ["1/5", "0"]])")).outcome, Outcome::accepted);
  // the same load (1/2, 0, 0) is on the surface: q = (1, 0, 0) gives q.p = 1/2 = the bound, so it slides
  EXPECT_EQ(check(barbell, slides(R"(["1/2", "0", "0"])", R"(["1", "0", "0"])")).outcome, Outcome::accepted);
  EXPECT_EQ(check(barbell, slides(R"(["49/100", "0", "0"])", R"(["1", "0", "0"])")).message,
            "twist: power q.p = 49/100 is less than sum mu_i f_i u_i = 1/2");
  EXPECT_EQ(check(barbell, slides(R"(["1", "0", "0"])", R"(["0", "0", "0"])")).message, "twist: the zero twist");
  EXPECT_EQ(check(barbell, slides(R"(["0", "0", "0"])", R"(["0", "0", "0"])")).message, "twist: the zero twist");
  // friction at fewer than two distinct points: LS(f) is flat, no load is inside it, whatever the forces
  const std::string no = "support_forces: friction acts at fewer than two distinct points, so the limit surface is flat and no "
                         "load is inside it";
  const std::string zero_load = R"(["0", "0", "0"])", zero_g = R"([["0", "0"], ["0", "0"]])";
  EXPECT_EQ(check(with_support(R"({"mu": 1, "points": [{"at": [1, 2], "force": 1}, {"at": [1, 2], "force": 3}]})"),
                  sticks(zero_load, zero_g)).message, no);  // coincident points
  EXPECT_EQ(check(with_support(R"({"mu": 1, "points": [{"at": [0, 0], "force": 1}, {"at": [1, 0], "force": 0}]})"),
                  sticks(zero_load, zero_g)).message, no);  // no force at the second point
  EXPECT_EQ(check(with_support(R"({"points": [{"at": [0, 0], "force": 1, "mu": 1}, {"at": [1, 0], "force": 1, "mu": 0}]})"),
                  sticks(zero_load, zero_g)).message, no);  // no friction at the second point
  EXPECT_EQ(check(with_support(R"({"points": [{"at": [0, 0], "force": 1, "mu": 1}, {"at": [1, 0], "force": 1, "mu": 0}]})"),
                  sticks(zero_load, R"([["0", "0"], ["1/2", "0"]])")).message,
            "support_forces[1]: |g|^2 = 1/4 is not less than (mu f)^2 = 0 (no friction there: g must be 0)");
  EXPECT_EQ(check(with_support(R"({"mu": 1, "points": [{"at": [0, 0], "force": 1}, {"at": [1, 0], "force": "1/100"}]})"),
                  sticks(zero_load, zero_g)).outcome, Outcome::accepted);  // any two distinct points will do
  // unknown forces: the centre of pressure on a leg makes F = {all the weight there}, a flat vertex
  const std::string on_leg = with_support(R"({"mu": 1, "weight": 1, "pressure_center": [1, 1], )" + table_points + "}");
  EXPECT_EQ(check(on_leg, motion_head + R"("load": ["0", "0", "0"], "motion": "sticks", "vertices": [{"distribution": ["1", "0", "0", "0"], )"
                                        R"("support_forces": [["0", "0"], ["0", "0"], ["0", "0"], ["0", "0"]]}]})").message,
            "vertices[0].support_forces: friction acts at fewer than two distinct points, so the limit surface is flat and no "
            "load is inside it");
}

TEST(CheckerMotion, NumbersTooLargeToKeep) {
  // Coordinates and mu of 101 digits are kept as text and read again when needed (as for contacts):
  // the table scaled by 10^100, mu = 10^-100 from support.mu, the same certificate with moments scaled.
  const std::string big = with_support(R"({"mu": "1e-100", "weight": 1, "pressure_center": [0, 0], "points": [
      {"at": ["1e100", "1e100"]}, {"at": ["-1e100", "1e100"]}, {"at": ["-1e100", "-1e100"]}, {"at": ["1e100", "-1e100"]}]})");
  const std::string g = "1/4" + std::string(100, '0');  // 1/(4 * 10^100)
  const std::string cert = motion_head + R"("load": ["1/2)" + std::string(100, '0') + R"(", "0", "0"], "motion": "sticks", "vertices": [
      {"distribution": ["1/2", "0", "1/2", "0"], "support_forces": [[")" + g + R"(", "0"], ["0", "0"], [")" + g + R"(", "0"], ["0", "0"]]},
      {"distribution": ["0", "1/2", "0", "1/2"], "support_forces": [["0", "0"], [")" + g + R"(", "0"], ["0", "0"], [")" + g + R"(", "0"]]}]})";
  EXPECT_EQ(check(big, cert).outcome, Outcome::accepted) << check(big, cert).message;
  std::string over = cert;
  over.replace(over.find(g), g.size(), "1/1" + std::string(100, '0'));  // 10^-100 > mu f = 10^-100 / 2
  EXPECT_EQ(check(big, over).message.rfind("vertices[0].support_forces[0]: |g|^2 = ", 0), 0u) << check(big, over).message;
}

TEST(CheckerMotion, TooLargeToCheck) {
  Limits small;
  small.max_vertex_bases = 13;  // the table has 4 + 6 + 4 = 14 candidate bases
  const std::string cert = slurp(examples / "table_four_legs.sticks_for_every.valid.json");
  EXPECT_EQ(check(table_scene, cert).outcome, Outcome::accepted);
  EXPECT_EQ(check(table_scene, cert, small).message,
            "vertices: too large to check: 4 points without a given force give 14 candidate bases (limit 13)");
  // 300 unknown points: refused at once, not enumerated (300 + C(300, 2) + C(300, 3) = 4500250)
  std::string points;
  for (int i = 0; i < 300; ++i) points += std::string(i ? ", " : "") + R"({"at": [)" + std::to_string(i % 17) + ", " + std::to_string(i / 17) + "]}";
  const std::string many = with_support(R"({"mu": 1, "weight": 1, "pressure_center": [1, 1], "points": [)" + points + "]}");
  EXPECT_EQ(check(many, motion_head + R"("load": ["0", "0", "0"], "motion": "sticks", "vertices": []})").message,
            "vertices: too large to check: 300 points without a given force give 4500250 candidate bases (limit 2000000)");
}

// Random supports (fixed seed): an independent brute force builds certificates, the checker must accept
// them, and tampered ones must be rejected.
struct Point {
  Q x, y, mu;
  bool known = false;
  Q f;  // the given force, or the force of the distribution f0 that made F
};
struct Random_support {
  std::vector<Point> p;
  Q W, c[2];
  std::string scene;
};
std::string str(const Q& q) { return q.get_str(); }
std::string rationals(const std::vector<Q>& v) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", \"" : "\"") + str(v[i]) + "\"";
  return s + "]";
}

// flat: 1 puts every point where the first one is, 2 leaves a force only at the first point (known forces).
Random_support random_support(std::mt19937& rng, bool all_known, int flat = 0) {
  auto small = [&](int lo, int hi, int den) {
    Q q(static_cast<long>(lo + static_cast<int>(rng() % static_cast<unsigned>(hi - lo + 1))), 1 + static_cast<long>(rng() % static_cast<unsigned>(den)));
    q.canonicalize();
    return q;
  };
  Random_support s;
  const std::size_t k = 4 + rng() % 5;
  const bool collinear = rng() % 6 == 0;
  for (std::size_t i = 0; i < k; ++i) {
    Point pt;
    pt.x = small(-2, 2, 1);  // a small grid: coincident and collinear points are common
    pt.y = collinear ? Q(pt.x * 2 - 1) : small(-2, 2, 2);
    pt.mu = small(1, 8, 4);
    pt.f = rng() % 4 == 0 ? Q(0) : small(1, 5, 3);
    pt.known = all_known || rng() % 3 == 0;
    if (flat == 1 && i > 0) pt.x = s.p[0].x, pt.y = s.p[0].y;
    if (flat == 2 && i > 0) pt.f = 0;
    s.p.push_back(pt);
  }
  if (!all_known) s.p[rng() % k].known = false;
  Q W = 0, M[2] = {0, 0};
  for (const Point& pt : s.p) W += pt.f, M[0] += pt.f * pt.x, M[1] += pt.f * pt.y;
  if (W == 0) s.p[0].f = 1, W = 1, M[0] = s.p[0].x, M[1] = s.p[0].y;
  s.W = W, s.c[0] = M[0] / W, s.c[1] = M[1] / W;
  std::string pts;
  for (std::size_t i = 0; i < k; ++i)
    pts += std::string(i ? ", " : "") + R"({"at": [")" + str(s.p[i].x) + R"(", ")" + str(s.p[i].y) + R"("], "mu": ")" +
           str(s.p[i].mu) + "\"" + (s.p[i].known ? R"(, "force": ")" + str(s.p[i].f) + "\"" : std::string()) + "}";
  s.scene = all_known ? with_support(R"({"points": [)" + pts + "]}")
                      : with_support(R"({"weight": ")" + str(W) + R"(", "pressure_center": [")" + str(s.c[0]) + R"(", ")" +
                                     str(s.c[1]) + R"("], "points": [)" + pts + "]}");
  return s;
}

// The vertices of F by brute force: every set S of at most three unknown points on which the three rows
// (1, x, y) have a unique, strictly positive solution (Gauss-Jordan elimination).
std::vector<std::vector<Q>> brute_vertices(const Random_support& s) {
  std::vector<std::size_t> unknown;
  std::vector<Q> base;
  Q b[3] = {s.W, Q(s.W * s.c[0]), Q(s.W * s.c[1])};
  for (std::size_t i = 0; i < s.p.size(); ++i) {
    base.push_back(s.p[i].known ? s.p[i].f : Q(0));
    if (!s.p[i].known) unknown.push_back(i);
    else b[0] -= s.p[i].f, b[1] -= s.p[i].f * s.p[i].x, b[2] -= s.p[i].f * s.p[i].y;
  }
  std::vector<std::vector<Q>> out;
  const std::size_t n = unknown.size();
  for (unsigned mask = 0; mask < (1u << n); ++mask) {
    std::vector<std::size_t> S;
    for (std::size_t j = 0; j < n; ++j)
      if (mask >> j & 1) S.push_back(unknown[j]);
    if (S.size() > 3) continue;
    std::vector<std::vector<Q>> A(3, std::vector<Q>(S.size() + 1));
    for (std::size_t j = 0; j < S.size(); ++j) A[0][j] = 1, A[1][j] = s.p[S[j]].x, A[2][j] = s.p[S[j]].y;
    for (int r = 0; r < 3; ++r) A[r][S.size()] = b[r];
    bool ok = true;
    for (std::size_t col = 0; col < S.size() && ok; ++col) {
      std::size_t piv = col;
      while (piv < 3 && A[piv][col] == 0) ++piv;
      if (piv == 3) { ok = false; break; }
      std::swap(A[col], A[piv]);
      const Q d = A[col][col];
      for (Q& v : A[col]) v /= d;
      for (std::size_t r = 0; r < 3; ++r)
        if (r != col && A[r][col] != 0) {
          const Q m = A[r][col];
          for (std::size_t j = 0; j <= S.size(); ++j) A[r][j] -= m * A[col][j];
        }
    }
    for (std::size_t r = S.size(); r < 3 && ok; ++r) ok = A[r][S.size()] == 0;
    for (std::size_t j = 0; j < S.size() && ok; ++j) ok = A[j][S.size()] > 0;
    if (!ok) continue;
    std::vector<Q> f = base;
    for (std::size_t j = 0; j < S.size(); ++j) f[S[j]] = A[j][S.size()];
    out.push_back(f);
  }
  return out;
}

// A rational u >= sqrt(s) (s >= 0), within 1/1000.
Q upper_sqrt(const Q& s) {
  mpz_class t = s.get_num() * s.get_den() * 1000000, r;
  mpz_sqrt(r.get_mpz_t(), t.get_mpz_t());
  Q u(mpz_class(r + 1), mpz_class(s.get_den() * 1000));
  u.canonicalize();
  return u;
}
// A rational l <= sqrt(s) (s >= 0).
Q lower_sqrt(const Q& s) {
  mpz_class t = s.get_num() * s.get_den() * 1000000, r;
  mpz_sqrt(r.get_mpz_t(), t.get_mpz_t());
  Q l(r, mpz_class(s.get_den() * 1000));
  l.canonicalize();
  return l;
}

// Support forces g_i = f_i (t + s rot90(r_i - c)) for a distribution f: they sum to (W t, W c x t + s J),
// J = sum f_i |r_i - c|^2 (SL-1 §5); the stick witness's JSON, or "" if some g_i is not strictly inside its
// disc |g_i| < mu_i f_i (g_i = 0 where f_i = 0).
std::string forces_json(const Random_support& s, const std::vector<Q>& f, const Q (&t)[2], const Q& spin) {
  std::string out = "[";
  for (std::size_t i = 0; i < f.size(); ++i) {
    const Q gx = f[i] * (t[0] - spin * (s.p[i].y - s.c[1])), gy = f[i] * (t[1] + spin * (s.p[i].x - s.c[0]));
    if (f[i] != 0 && gx * gx + gy * gy >= s.p[i].mu * f[i] * s.p[i].mu * f[i]) return "";
    out += std::string(i ? ", " : "") + "[\"" + str(gx) + "\", \"" + str(gy) + "\"]";
  }
  return out + "]";
}
// Whether friction acts at two distinct points under f (mu_i f_i > 0): LS(f) is then three-dimensional
// and a load strictly inside every disc is in its interior; otherwise no load sticks (SL-1 §3).
bool two_friction_points(const Random_support& s, const std::vector<Q>& f) {
  for (std::size_t i = 0; i < f.size(); ++i)
    for (std::size_t j = i + 1; j < f.size(); ++j)
      if (s.p[i].mu * f[i] > 0 && s.p[j].mu * f[j] > 0 && (s.p[i].x != s.p[j].x || s.p[i].y != s.p[j].y)) return true;
  return false;
}
const std::string flat = "friction acts at fewer than two distinct points";

Q second_moment(const Random_support& s, const std::vector<Q>& f) {
  Q J = 0;
  for (std::size_t i = 0; i < f.size(); ++i)
    J += f[i] * ((s.p[i].x - s.c[0]) * (s.p[i].x - s.c[0]) + (s.p[i].y - s.c[1]) * (s.p[i].y - s.c[1]));
  return J;
}

TEST(CheckerMotionProperties, SticksForEveryDistribution) {
  std::mt19937 rng(20261124);
  int accepted = 0, rank_deficient = 0, flat_vertex = 0;
  for (int round = 0; round < 150; ++round) {
    const Random_support s = random_support(rng, false);
    ASSERT_NE(check(s.scene, "{}").outcome, Outcome::bad_scene) << s.scene;
    const auto vertices = brute_vertices(s);
    ASSERT_FALSE(vertices.empty()) << s.scene;
    // a common load: translation part t and moment m0, shrunk until every vertex's forces fit their discs
    Q t[2] = {Q(static_cast<long>(rng() % 7) - 3, 4), Q(static_cast<long>(rng() % 7) - 3, 4)}, m0(static_cast<long>(rng() % 9) - 4, 5);
    for (const auto& f : vertices)
      if (second_moment(s, f) == 0) m0 = 0;
    std::vector<std::string> witnesses;
    for (int shrink = 0; shrink < 40; ++shrink) {
      witnesses.clear();
      for (const auto& f : vertices) {
        const Q J = second_moment(s, f);
        const std::string g = forces_json(s, f, t, J == 0 ? Q(0) : Q(m0 / J));
        if (g.empty()) break;
        witnesses.push_back(R"({"distribution": )" + rationals(f) + R"(, "support_forces": )" + g + "}");
      }
      if (witnesses.size() == vertices.size()) break;
      t[0] /= 2, t[1] /= 2, m0 /= 2;
    }
    ASSERT_EQ(witnesses.size(), vertices.size()) << s.scene;
    const std::vector<Q> load = {Q(s.W * t[0]), Q(s.W * t[1]), Q(s.W * (s.c[0] * t[1] - s.c[1] * t[0]) + m0)};
    auto cert = [&](const std::vector<Q>& p, const std::vector<std::string>& w) {
      std::string list;
      for (std::size_t k = 0; k < w.size(); ++k) list += (k ? ", " : "") + w[k];
      return motion_head + R"("load": )" + rationals(p) + R"(, "motion": "sticks", "vertices": [)" + list + "]}";
    };
    std::vector<std::string> shuffled = witnesses;
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    const Result r = check(s.scene, cert(load, shuffled));
    bool flat_somewhere = false;
    for (const auto& f : vertices) flat_somewhere = flat_somewhere || !two_friction_points(s, f);
    if (flat_somewhere) {  // a vertex whose limit surface is flat: no load is inside it, so no "sticks"
      EXPECT_EQ(r.outcome, Outcome::rejected) << s.scene;
      EXPECT_NE(r.message.find(flat), std::string::npos) << s.scene << "\n" << r.message;
      ++flat_vertex;
      continue;
    }
    ASSERT_EQ(r.outcome, Outcome::accepted) << s.scene << "\n" << cert(load, shuffled) << "\n" << r.message;
    ++accepted;
    std::size_t unknown = 0;
    for (const Point& pt : s.p) unknown += pt.known ? 0 : 1;
    if (vertices.size() > 0 && unknown >= 3) {
      // rank < 3 somewhere: some three unknown points collinear, or two coincident
      for (std::size_t i = 0; i < s.p.size(); ++i)
        for (std::size_t j = i + 1; j < s.p.size(); ++j)
          if (!s.p[i].known && !s.p[j].known && s.p[i].x == s.p[j].x && s.p[i].y == s.p[j].y) ++rank_deficient, i = j = s.p.size();
    }
    // tampering: each vertex left out, the load moved, one distribution entry moved
    for (std::size_t k = 0; k < witnesses.size(); ++k) {
      std::vector<std::string> fewer = witnesses;
      fewer.erase(fewer.begin() + static_cast<std::ptrdiff_t>(k));
      EXPECT_EQ(check(s.scene, cert(load, fewer)).message.rfind("vertices: the vertex ", 0), 0u) << s.scene;
    }
    std::vector<Q> moved = load;
    moved[rng() % 3] += Q(1, 1000);
    EXPECT_EQ(check(s.scene, cert(moved, witnesses)).outcome, Outcome::rejected) << s.scene;
    std::vector<Q> f = vertices[0];
    f[rng() % f.size()] += Q(1, 7);
    std::vector<std::string> off = witnesses;
    off[0] = R"({"distribution": )" + rationals(f) + witnesses[0].substr(witnesses[0].find(R"(, "support_forces")"));
    EXPECT_EQ(check(s.scene, cert(load, off)).outcome, Outcome::rejected) << s.scene;
  }
  EXPECT_GE(accepted, 120);
  EXPECT_GE(flat_vertex, 3);
  EXPECT_EQ(accepted + flat_vertex, 150);
  EXPECT_GE(rank_deficient, 5);
}

// A slide witness for twist q: speeds u_i >= |v_i(q)|.
std::vector<Q> speed_bounds(const Random_support& s, const Q (&q)[3]) {
  std::vector<Q> u;
  for (const Point& pt : s.p) {
    const Q vx = q[0] - q[2] * pt.y, vy = q[1] + q[2] * pt.x;
    u.push_back(upper_sqrt(Q(vx * vx + vy * vy)));
  }
  return u;
}

TEST(CheckerMotionProperties, SlidesForEveryDistribution) {
  std::mt19937 rng(20261125);
  for (int round = 0; round < 200; ++round) {
    const Random_support s = random_support(rng, false);
    Q q[3];
    do
      for (Q& x : q) x = static_cast<long>(rng() % 7) - 3;
    while (q[0] == 0 && q[1] == 0 && q[2] == 0);
    std::vector<Q> u = speed_bounds(s, q);
    // a dual: random (yx, yy), and y0 as small as the unknown points allow
    const Q yx(static_cast<long>(rng() % 5) - 2, 3), yy(static_cast<long>(rng() % 5) - 2, 3);
    Q y0, bound = 0, rest_w = s.W, rest_m[2] = {Q(s.W * s.c[0]), Q(s.W * s.c[1])};
    bool first = true;
    for (std::size_t i = 0; i < s.p.size(); ++i) {
      const Point& pt = s.p[i];
      if (pt.known) {
        bound += pt.mu * pt.f * u[i], rest_w -= pt.f, rest_m[0] -= pt.f * pt.x, rest_m[1] -= pt.f * pt.y;
      } else {
        const Q need = pt.mu * u[i] - yx * pt.x - yy * pt.y;
        if (first || need > y0) y0 = need, first = false;
      }
    }
    bound += y0 * rest_w + yx * rest_m[0] + yy * rest_m[1];
    // a load along a random direction d with q.d > 0, just past the bound
    Q d[3];
    do
      for (Q& x : d) x = static_cast<long>(rng() % 7) - 3;
    while (q[0] * d[0] + q[1] * d[1] + q[2] * d[2] == 0);
    const Q qd = q[0] * d[0] + q[1] * d[1] + q[2] * d[2];
    auto load_at = [&](const Q& power) { return std::vector<Q>{Q(d[0] * power / qd), Q(d[1] * power / qd), Q(d[2] * power / qd)}; };
    auto cert = [&](const std::vector<Q>& p, const std::vector<Q>& speeds, const Q& y0_, bool zero_twist = false) {
      return motion_head + R"("load": )" + rationals(p) + R"(, "motion": "slides", "twist": )" +
             (zero_twist ? rationals({0, 0, 0}) : rationals({q[0], q[1], q[2]})) +
             R"(, "speed_bounds": )" + rationals(speeds) + R"(, "dual": )" + rationals({y0_, yx, yy}) + "}";
    };
    const std::vector<Q> p = load_at(Q(bound + Q(1, 1 + static_cast<long>(rng() % 50))));
    const Result r = check(s.scene, cert(p, u, y0));
    ASSERT_EQ(r.outcome, Outcome::accepted) << s.scene << "\n" << cert(p, u, y0) << "\n" << r.message;
    // exactly at the bound: p is not in the interior of any LS(f), so it slides (on the surface); just below: rejected
    EXPECT_EQ(check(s.scene, cert(load_at(bound), u, y0)).outcome, Outcome::accepted) << s.scene;
    EXPECT_EQ(check(s.scene, cert(load_at(Q(bound - Q(1, 1000))), u, y0)).message,
              "twist: power q.p = " + str(Q(bound - Q(1, 1000))) + " is less than the dual bound " + str(bound))
        << s.scene;
    // the zero twist proves nothing, whatever the bound (every dual constraint holds for u = speeds of q = 0)
    EXPECT_EQ(check(s.scene, cert(load_at(Q(bound + 1)), std::vector<Q>(u.size(), Q(0)), Q(0), true)).message,
              "twist: the zero twist") << s.scene;
    // y0 lowered: the tightest unknown point's constraint fails
    EXPECT_EQ(check(s.scene, cert(p, u, Q(y0 - Q(1, 1000)))).message.rfind("dual: mu_i u_i = ", 0), 0u) << s.scene;
    // a speed bound below the speed
    for (std::size_t i = 0; i < u.size(); ++i) {
      if (u[i] * u[i] <= Q(1, 1000000)) continue;
      std::vector<Q> low = u;
      low[i] = lower_sqrt(Q(u[i] * u[i] - Q(1, 1000)));
      const Q vx = q[0] - q[2] * s.p[i].y, vy = q[1] + q[2] * s.p[i].x;
      if (low[i] * low[i] >= vx * vx + vy * vy) continue;
      EXPECT_EQ(check(s.scene, cert(p, low, y0)).message.find("speed_bounds[" + std::to_string(i) + "]: u^2 = "), 0u);
      break;
    }
  }
}

TEST(CheckerMotionProperties, KnownDistributions) {
  std::mt19937 rng(20261126);
  int slides = 0, flat_support = 0;
  for (int round = 0; round < 200; ++round) {
    const Random_support s = random_support(rng, true, round % 10 == 0 ? 1 + round / 10 % 2 : 0);
    ASSERT_NE(check(s.scene, "{}").outcome, Outcome::bad_scene) << s.scene;
    // random rational g_i strictly inside the discs |g_i| < mu_i f_i (0 where mu_i f_i = 0): with friction at
    // two distinct points, p = sum (g_i, r_i x g_i) is in the interior of LS(f) and sticks
    Q p[3] = {0, 0, 0};
    std::string forces = "[";
    for (std::size_t i = 0; i < s.p.size(); ++i) {
      Q gx(static_cast<long>(rng() % 11) - 5, 5), gy(static_cast<long>(rng() % 11) - 5, 5);
      const Q cap = s.p[i].mu * s.p[i].f;
      if (cap == 0) gx = gy = 0;
      while (cap != 0 && gx * gx + gy * gy >= cap * cap) gx /= 2, gy /= 2;
      p[0] += gx, p[1] += gy, p[2] += s.p[i].x * gy - s.p[i].y * gx;
      forces += std::string(i ? ", " : "") + "[\"" + str(gx) + "\", \"" + str(gy) + "\"]";
    }
    forces += "]";
    const std::string stick = motion_head + R"("load": )" + rationals({p[0], p[1], p[2]}) +
                              R"(, "motion": "sticks", "support_forces": )" + forces + "}";
    std::vector<Q> given;
    for (const Point& pt : s.p) given.push_back(pt.f);
    if (!two_friction_points(s, given)) {  // LS(f) is flat (a disc or nothing): no load is in its interior
      EXPECT_EQ(check(s.scene, stick).message, "support_forces: " + flat +
                                                   ", so the limit surface is flat and no load is inside it") << s.scene;
      ++flat_support;
      continue;
    }
    ASSERT_EQ(check(s.scene, stick).outcome, Outcome::accepted) << s.scene << "\n" << stick << "\n" << check(s.scene, stick).message;
    // one force pushed onto its circle, or just outside it: rejected there (the forces before it are fine);
    // where there is no friction (mu f = 0), any nonzero force
    const std::size_t i = rng() % s.p.size();
    const Q cap = s.p[i].mu * s.p[i].f;
    for (const Q& x : {cap, Q(cap + Q(1, 1000))}) {
      if (x == 0) continue;
      std::string bad = stick;
      std::size_t at = bad.find(R"("support_forces": [)") + 19;
      for (std::size_t k = 0; k < i; ++k) at = bad.find("], [", at) + 3;
      bad.replace(at, bad.find(']', at) + 1 - at, "[\"0\", \"" + str(x) + "\"]");
      EXPECT_EQ(check(s.scene, bad).message, "support_forces[" + std::to_string(i) + "]: |g|^2 = " + str(x * x) +
                                                 " is not less than (mu f)^2 = " + str(cap * cap) +
                                                 (cap == 0 ? " (no friction there: g must be 0)" : ""));
    }
    // the stick load scaled past a slide witness: q = the load's own direction as a twist (q.p > 0 unless p = 0)
    const Q qp = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
    if (qp == 0) continue;
    const Q q[3] = {p[0], p[1], p[2]};
    const std::vector<Q> u = speed_bounds(s, q);
    Q h = 0;
    for (std::size_t k = 0; k < s.p.size(); ++k) h += s.p[k].mu * s.p[k].f * u[k];
    const Q lambda = h / qp + Q(1, 100);  // lambda q.p = h + qp/100 > h
    const std::vector<Q> scaled = {Q(lambda * p[0]), Q(lambda * p[1]), Q(lambda * p[2])};
    const std::string slide = motion_head + R"("load": )" + rationals(scaled) + R"(, "motion": "slides", "twist": )" +
                              rationals({q[0], q[1], q[2]}) + R"(, "speed_bounds": )" + rationals(u) + "}";
    ASSERT_EQ(check(s.scene, slide).outcome, Outcome::accepted) << s.scene << "\n" << slide;
    ++slides;
    // scaled onto the bound (lambda q.p = h): the witness shows p is not in the interior, so it slides
    const Q on = h / qp;
    const std::string boundary = motion_head + R"("load": )" + rationals({Q(on * p[0]), Q(on * p[1]), Q(on * p[2])}) +
                                 R"(, "motion": "slides", "twist": )" + rationals({q[0], q[1], q[2]}) +
                                 R"(, "speed_bounds": )" + rationals(u) + "}";
    EXPECT_EQ(check(s.scene, boundary).outcome, Outcome::accepted) << s.scene << "\n" << boundary;
    // the same witness for the sticking load itself: q.p = |p|^2 < h_f(q) <= h, since p is in the interior of LS(f)
    const std::string unscaled = motion_head + R"("load": )" + rationals({p[0], p[1], p[2]}) + R"(, "motion": "slides", "twist": )" +
                                 rationals({q[0], q[1], q[2]}) + R"(, "speed_bounds": )" + rationals(u) + "}";
    EXPECT_EQ(check(s.scene, unscaled).message.find("twist: power q.p = "), 0u) << s.scene;
  }
  EXPECT_GE(slides, 120);
  EXPECT_GE(flat_support, 20);
}

TEST(CheckerMotionProperties, Depends) {
  // Two vertices f1, f2 of F; p = (0, 0, m) a pure moment. It sticks under f1 with g_i = f1_i s rot90(r_i - c)
  // when |s| |r_i - c| <= mu_i (moment s J1), and slides under f2 with q = rotation about c when
  // m > sum mu_i f2_i u_i, u_i >= |r_i - c|: whenever s J1 exceeds that sum, "depends" has a certificate.
  std::mt19937 rng(20261127);
  int found = 0;
  for (int round = 0; round < 400 && found < 40; ++round) {
    const Random_support s = random_support(rng, false);
    const auto vertices = brute_vertices(s);
    if (vertices.size() < 2) continue;
    const Q q[3] = {s.c[1], Q(-s.c[0]), 1};  // v_i = (vx - y_i, vy + x_i) = rot90(r_i - c)
    const std::vector<Q> u = speed_bounds(s, q);
    for (std::size_t a = 0; a < vertices.size(); ++a)
      for (std::size_t b = 0; b < vertices.size(); ++b) {
        if (a == b) continue;
        const auto &f1 = vertices[a], &f2 = vertices[b];
        Q spin = -1, h2 = 0;  // spin: the largest s in our grid with |s| |r_i - c| <= mu_i where f1_i > 0
        for (std::size_t i = 0; i < f1.size(); ++i) {
          h2 += s.p[i].mu * f2[i] * u[i];
          const Q r2 = (s.p[i].x - s.c[0]) * (s.p[i].x - s.c[0]) + (s.p[i].y - s.c[1]) * (s.p[i].y - s.c[1]);
          if (f1[i] == 0 || r2 == 0) continue;
          const Q cap = lower_sqrt(Q(s.p[i].mu * s.p[i].mu / r2));
          if (spin < 0 || cap < spin) spin = cap;
        }
        if (spin <= 0 || !two_friction_points(s, f1)) continue;
        spin *= Q(999, 1000);  // strictly inside the discs (lower_sqrt may be exact: |g_i| = mu_i f1_i)
        const Q m = spin * second_moment(s, f1);
        if (!(m > h2)) continue;
        const Q zero[2] = {0, 0};
        const std::string g = forces_json(s, f1, zero, spin);
        ASSERT_FALSE(g.empty());
        const std::string cert = motion_head + R"("load": ["0", "0", ")" + str(m) + R"("], "motion": "depends", "sticking": )" +
                                 R"({"distribution": )" + rationals(f1) + R"(, "support_forces": )" + g + R"(}, "sliding": )" +
                                 R"({"distribution": )" + rationals(f2) + R"(, "twist": )" + rationals({q[0], q[1], q[2]}) +
                                 R"(, "speed_bounds": )" + rationals(u) + "}}";
        const Result r = check(s.scene, cert);
        ASSERT_EQ(r.outcome, Outcome::accepted) << s.scene << "\n" << cert << "\n" << r.message;
        // swapped roles: f2 cannot carry the moment (h2 < m bounds its limit surface) and f1 does not slide
        const std::string swapped = motion_head + R"("load": ["0", "0", ")" + str(m) + R"("], "motion": "depends", "sticking": )" +
                                    R"({"distribution": )" + rationals(f2) + R"(, "support_forces": )" + g + R"(}, "sliding": )" +
                                    R"({"distribution": )" + rationals(f1) + R"(, "twist": )" + rationals({q[0], q[1], q[2]}) +
                                    R"(, "speed_bounds": )" + rationals(u) + "}}";
        EXPECT_EQ(check(s.scene, swapped).outcome, Outcome::rejected) << s.scene;
        ++found;
        a = b = vertices.size();
      }
  }
  EXPECT_GE(found, 20);
}

TEST(CheckerExamples, SlidingExamples) {
  for (const char* f : {"table_four_legs.sticks_for_every.valid.json", "table_four_legs.slides_for_every.valid.json",
                        "table_four_legs.depends.valid.json", "barbell_known.sticks.valid.json",
                        "barbell_known.slides.valid.json", "barbell_known.slides_on_surface.valid.json",
                        "barbell_known.power_below_bound.invalid.json", "barbell_known.g_on_circle.invalid.json",
                        "table_four_legs.missing_vertex.invalid.json",
                        "table_four_legs.dual_violated.invalid.json", "barbell_known.depends_on_known.invalid.json"})
    EXPECT_TRUE(fs::exists(examples / f)) << f;
  // The load (1/2, 1/2, 0.9) of theory-sliding.md §6 depends: one diagonal sticks, the other slides.
  const std::string depends = slurp(examples / "table_four_legs.depends.valid.json");
  EXPECT_EQ(check(table_scene, depends).outcome, Outcome::accepted);
  // check_all reads the scene once and answers each certificate as check() does
  const std::vector<std::string> certs = {depends, slurp(examples / "table_four_legs.missing_vertex.invalid.json"),
                                          slurp(examples / "table_four_legs.slides_for_every.valid.json"), "{}"};
  const std::vector<std::string_view> views(certs.begin(), certs.end());
  const std::vector<Result> all = wrenchkit_checker::check_all(table_scene, views);
  ASSERT_EQ(all.size(), certs.size());
  for (std::size_t k = 0; k < certs.size(); ++k) {
    EXPECT_EQ(all[k].outcome, check(table_scene, certs[k]).outcome) << k;
    EXPECT_EQ(all[k].message, check(table_scene, certs[k]).message) << k;
  }
  EXPECT_EQ(all[0].outcome, Outcome::accepted);
  EXPECT_EQ(all[1].outcome, Outcome::rejected);
}

// ---------------------------------------------------------------------------------------------
// Random byte mutations: never crash, always a well-formed one-line message

bool one_line_utf8(const std::string& s) {
  for (std::size_t i = 0; i < s.size();) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (c < 0x20 || c == 0x7F) return false;
    std::size_t n = c < 0x80 ? 1 : c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : c >= 0xC2 ? 2 : 0;
    if (n == 0 || i + n > s.size()) return false;
    for (std::size_t k = 1; k < n; ++k)
      if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return false;
    i += n;
  }
  return true;
}

TEST(CheckerFuzz, RandomMutationsNeverCrash) {
  unsigned seed = 20240611;
  if (const char* env = std::getenv("WRENCHKIT_SEED")) seed = static_cast<unsigned>(std::strtoul(env, nullptr, 10));
  std::mt19937 rng(seed);
  const auto valid = load_examples(".valid.json");
  const std::string alphabet = "{}[]\",:0123456789-+./eE \\u\x01\x80\xC3\xA9\xED\xF0 trufalsn";
  auto mutate = [&](std::string s) {
    const int edits = 1 + static_cast<int>(rng() % 4);
    for (int k = 0; k < edits && !s.empty(); ++k) {
      const std::size_t at = rng() % s.size();
      switch (rng() % 4) {
        case 0: s[at] = alphabet[rng() % alphabet.size()]; break;
        case 1: s.insert(at, 1, alphabet[rng() % alphabet.size()]); break;
        case 2: s.erase(at, 1 + rng() % 8); break;
        default: s.insert(at, s.substr(rng() % s.size(), rng() % 16)); break;
      }
    }
    return s;
  };
  for (int round = 0; round < 3000; ++round) {
    const Example& e = valid[rng() % valid.size()];
    const bool scene_side = rng() % 2 == 0;
    const Result r = scene_side ? check(mutate(e.scene), e.cert) : check(e.scene, mutate(e.cert));
    ASSERT_FALSE(r.message.empty()) << "seed " << seed << " round " << round;
    ASSERT_TRUE(one_line_utf8(r.message)) << "seed " << seed << " round " << round << ": " << r.message;
    if (!scene_side) {
      ASSERT_NE(r.outcome, Outcome::bad_scene) << "seed " << seed << " round " << round;
    }
  }
}

}  // namespace

// A hold witness's combination terms are named by their full path (the witness's, then "combination[k]") in a
// rejection, as the top-level combination's are: the reader keeps each term's place, not its path text.
TEST(CheckerHoldProperties, WitnessTermsNameTheirPath) {
  const std::string pushed = slurp(examples / "table_pinned_pushed.scene.json");
  const std::string nudged = slurp(examples / "table_pinned_nudged.scene.json");
  const std::string far = R"("combination": [{"contact": 99, "edge": "left", "weight": "1"}])";
  auto with_far_term = [&](std::string cert) {
    const std::size_t at = cert.find(R"("combination": [])");
    EXPECT_NE(at, std::string::npos);
    return cert.replace(at, std::string(R"("combination": [])").size(), far);
  };
  EXPECT_EQ(rejection(pushed, with_far_term(slurp(examples / "table_pinned_pushed.depends.valid.json"))),
            "holding.combination[0].contact: index 99 is out of range (the scene has 1 contacts)");
  EXPECT_EQ(rejection(nudged, with_far_term(slurp(examples / "table_pinned_nudged.holds_for_every.valid.json"))),
            "vertices[0].combination[0].contact: index 99 is out of range (the scene has 1 contacts)");
}
