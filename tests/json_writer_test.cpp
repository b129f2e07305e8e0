// Json_writer (exact/io/json_writer.h): the one layout every answer is written in, pinned byte by byte;
// strings escaped exactly as json::quote and read back by the strict reader; exact numbers as the
// lowest-terms text to_string gives.
#include <gtest/gtest.h>

#include <array>
#include <climits>
#include <random>
#include <string>
#include <vector>

#include "exact/io/json.h"
#include "exact/io/json_writer.h"
#include "exact/numbers/rational.h"

namespace wrenchkit {
namespace {

TEST(JsonWriter, TheOneLayout) {
  Json_writer w;
  w.object().member("command", "closure").member("holds", true).member("rank", 3).key("empty").array().end_array();
  w.key("none").object().end_object().key("x").null();
  w.key("list").array().integer(-1).rational(Rational(-3, 2)).raw("2.5e-3").string("a").array().end_array().end_array();
  w.key("nested").object().key("a").object().member("b", false).end_object().end_object();
  w.key("v").rationals(std::array<Rational, 2>{Rational(1, 3), Rational(-2)}).key("z").rationals(std::vector<Integer>{});
  w.end_object();
  EXPECT_EQ(w.str(),
            "{\"command\": \"closure\", \"holds\": true, \"rank\": 3, \"empty\": [], \"none\": {}, \"x\": null, "
            "\"list\": [-1, \"-3/2\", 2.5e-3, \"a\", []], \"nested\": {\"a\": {\"b\": false}}, "
            "\"v\": [\"1/3\", \"-2\"], \"z\": []}");
}

// A function writing members into an object its caller opened, and a writer reusing a caller's string.
void members(Json_writer& w) { w.member("p", Rational(4)).key("q").rational(Integer("-123456789012345678901234567890")); }

TEST(JsonWriter, ContinuesAnOpenObjectAndReusesItsString) {
  std::string buffer = "left over";
  buffer.reserve(1000);
  const char* storage = buffer.data();
  Json_writer w(16, std::move(buffer));
  w.object().member("line", std::size_t{7});
  members(w);
  w.end_object();
  EXPECT_EQ(w.str(), "{\"line\": 7, \"p\": \"4\", \"q\": \"-123456789012345678901234567890\"}");
  EXPECT_EQ(w.str().data(), storage);  // no new allocation
  w.clear();
  w.object();
  members(w);
  EXPECT_EQ(w.end_object().take(), "{\"p\": \"4\", \"q\": \"-123456789012345678901234567890\"}");
}

TEST(JsonWriter, IntegersAtTheirLimits) {
  Json_writer w;
  w.array().integer(LLONG_MIN).integer(ULLONG_MAX).integer(0).integer(INT_MIN).end_array();
  EXPECT_EQ(w.str(), "[" + std::to_string(LLONG_MIN) + ", " + std::to_string(ULLONG_MAX) + ", 0, " +
                         std::to_string(INT_MIN) + "]");
}

TEST(JsonWriter, StringsAndKeysEscapedAsQuoteAndReadBack) {
  std::mt19937 rng(20261124);
  for (int k = 0; k < 2000; ++k) {
    std::string s(rng() % 12, ' ');
    for (char& c : s) c = static_cast<char>(rng() % 3 ? 0x20 + rng() % 95 : rng() % 0x20);  // printable ASCII or control
    if (k % 7 == 0) s += "\xc3\xa9";                                                        // UTF-8 passes as it is
    Json_writer w;
    w.object().member(std::string_view(s), s).end_object();
    EXPECT_EQ(w.str(), "{" + json::quote(s) + ": " + json::quote(s) + "}");
    const json::Value v = json::parse(w.str(), Input_limits{}, "test");
    ASSERT_EQ(v.members.size(), 1u);
    EXPECT_EQ(v.members[0].first, s);
    EXPECT_EQ(v.members[0].second.text, s);
  }
  EXPECT_EQ(json::quote("a\"b\\c\n\x01\x1f"), "\"a\\\"b\\\\c\\n\\u0001\\u001f\"");
}

TEST(JsonWriter, RationalsAsToStringInLowestTerms) {
  std::mt19937_64 rng(7);
  for (int k = 0; k < 2000; ++k) {
    Integer p(static_cast<long>(rng() >> 1)), q(static_cast<long>((rng() >> 2) + 1));
    if (k % 3 == 0) p *= p * p;  // beyond 64 bits
    if (k % 2) p = -p;
    Rational x(p, q);
    x.canonicalize();
    Json_writer w;
    w.array().rational(x).rational(x.get_num()).end_array();
    EXPECT_EQ(w.str(), "[\"" + to_string(x) + "\", \"" + x.get_num().get_str() + "\"]");
  }
}

// The 128-bit fast path (numbers below 2^128 written without GMP) against GMP's own text, at the edges of
// its ranges: 0, powers of ten and of two around 2^64 and 2^128, each ± 1, signed, as numerators and
// denominators (seeded random factors between them).
TEST(JsonWriter, RationalsAroundTwoToThe128WrittenAsGmpDoes) {
  std::vector<Integer> edges = {Integer(0), Integer(1), Integer(9), Integer(10)};
  for (unsigned e : {18u, 19u, 20u, 38u, 39u, 40u}) {
    Integer t;
    mpz_ui_pow_ui(t.get_mpz_t(), 10, e);
    for (int d = -1; d <= 1; ++d) edges.push_back(Integer(t + d));
  }
  for (unsigned e : {63u, 64u, 65u, 127u, 128u, 129u}) {
    Integer t = 1;
    t <<= e;
    for (int d = -1; d <= 1; ++d) edges.push_back(Integer(t + d));
  }
  std::mt19937_64 rng(128);
  for (int k = 0; k < 200; ++k) {
    Integer r(static_cast<unsigned long>(rng()));
    r <<= static_cast<unsigned>(rng() % 70);
    r += static_cast<unsigned long>(rng());
    edges.push_back(r);
  }
  for (const Integer& p : edges)
    for (const Integer& q : {edges[1], edges[5], edges[edges.size() / 2], edges.back()})
      for (const int sign : {1, -1}) {
        if (q == 0) continue;
        Rational x(Integer(sign * p), q);
        x.canonicalize();
        const Integer z(sign * p);
        Json_writer w;
        w.array().rational(x).rational(z).end_array();
        EXPECT_EQ(w.str(), "[\"" + to_string(x) + "\", \"" + z.get_str() + "\"]");
      }
}

// json::text_of (the reader's values written back) goes through the same writer: the same bytes.
TEST(JsonWriter, TextOfAParsedValueKeepsItsNumbersAndTheLayout) {
  const std::string text = "{\"a\": [1, 2.50, -0e3, \"x\\ty\"], \"b\": {\"c\": null, \"d\": true}, \"e\": []}";
  EXPECT_EQ(json::text_of(json::parse(text, Input_limits{}, "test")), text);
}

}  // namespace
}  // namespace wrenchkit
