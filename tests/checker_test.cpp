// tests/checker_test.cpp - the independent certificate checker (proofs/checker/), format v1.
//
// Layers: every worked example in proofs/examples/ (valid ones accepted, invalid ones rejected for the
// reason listed in invalid-reasons.tsv); bad scenes (exact messages naming the JSON path); malformed
// certificates; mutations of every valid certificate that are invalid by construction, or valid by
// invariance; and a seeded random byte-mutation run that must never crash (run it under ASan/UBSan).
#include "proofs/checker/checker.h"

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
  EXPECT_EQ(scene_error(R"({"wrenchkit": 1, "support": {"a b": {"x": 1, "x": 2}}})"),
            R"(support["a b"]: duplicate key "x")");
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
  EXPECT_EQ(scene_error("{\"wrenchkit\": 1,\n \"support\": {\"a\": [1,]}}"),
            "2:22: invalid JSON: unexpected character ']'");
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
  EXPECT_NE(scene_error("{\"wrenchkit\": 1, \"support\": {\"a\": tru}}").find("invalid literal"), std::string::npos);
  EXPECT_NE(scene_error("{\"wrenchkit\": 1, \"support\": {\"a\": nul}}").find("invalid literal"), std::string::npos);
}

TEST(CheckerBadScene, Depth) {
  // top-level object (1) + support (2) + n arrays (support is not interpreted: any JSON inside)
  auto nested = [](std::size_t n) {
    return "{\"wrenchkit\": 1, \"support\": {\"a\": " + std::string(n, '[') + std::string(n, ']') + "}}";
  };
  EXPECT_NE(check(nested(62), "{}").outcome, Outcome::bad_scene);
  EXPECT_EQ(scene_error(nested(63)), "1:97: invalid JSON: nested deeper than 64 levels");
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
  for (const char* version : {"2", "1.0", "1e0", "\"1\"", "true"})
    EXPECT_EQ(rejection(block_corner, R"({"wrenchkit_certificate": )" + std::string(version) +
                                          R"(, "property": "force_closure", "holds": false, )" + twist + "}"),
              "wrenchkit_certificate: expected the integer 1");
  EXPECT_EQ(
      rejection(block_corner, R"({"wrenchkit_certificate": 1, "property": "closure", "holds": false, )" + twist + "}"),
      R"(property: expected "force_closure", "form_closure" or "equilibrium")");
  EXPECT_EQ(rejection(block_corner,
                      R"({"wrenchkit_certificate": 1, "property": "force_closure", "holds": "false", )" + twist + "}"),
            "holds: expected true or false");
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
                                                 "two_finger_mu_1_2.form_translate_up.valid.json"};
  const std::regex reading_re(R"re(,\s*"reading": \{[^}]*\})re");
  int negatives = 0;
  std::set<std::string> seen;
  for (const Example& e : load_examples(".valid.json")) {
    std::smatch m;
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
