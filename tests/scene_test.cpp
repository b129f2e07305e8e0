// Scene parser: exact numbers, strict JSON, and every bad-input class of docs/scene-format.md with the
// message text pinned (the message names the JSON path and the offending text).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>

#include "exact/io/input_error.h"
#include "exact/numbers/decimal.h"
#include "exact/numbers/rational.h"
#include "exact/io/scene.h"
#include "exact/io/streaming_scene_reader.h"
#include "fuzz/scene_checks.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {

Rational exact(const std::string& text, bool json_number) {
  std::string why;
  auto q = parse_rational(text, json_number, Input_limits{}, why);
  EXPECT_TRUE(q.has_value()) << text << ": " << why;
  return q ? *q : Rational(-999);
}

TEST(Numbers, DecimalTextIsReadExactly) {
  EXPECT_EQ(exact("0.1", true), Rational(1, 10));
  EXPECT_EQ(exact("-2.5e-3", false), Rational(-1, 400));
  EXPECT_EQ(exact("1E+3", true), 1000);
  EXPECT_EQ(exact("-0", true), 0);
  EXPECT_EQ(exact("3/6", false), Rational(1, 2));
  EXPECT_EQ(exact("-4/3", false), Rational(-4, 3));
  EXPECT_EQ(exact("+.5", false), Rational(1, 2));
  EXPECT_EQ(exact("5.", false), 5);
  EXPECT_EQ(exact("0.000e99", true), 0);
  EXPECT_EQ(exact("1e-40", true), Rational(Integer(1), Integer("1" + std::string(40, '0'))));
  EXPECT_EQ(exact("123456789012345678901234567890", true), Rational(Integer("123456789012345678901234567890")));
  // 0.1 is not the double 0.1000000000000000055511151231257827…
  EXPECT_NE(exact("0.1", true), Rational(0.1));
}

TEST(Numbers, FastAndGeneralPathsAgreeOnRandomDecimals) {
  // Random digit strings around the 18-digit / 10^±18 boundary of the 64-bit fast path, checked
  // against an independent construction: Integer(all digits) · 10^(exponent − fraction digits).
  std::mt19937_64 rng(3);
  for (int t = 0; t < 20000; ++t) {
    const int n_int = std::uniform_int_distribution<int>(0, 12)(rng);
    const int n_frac = std::uniform_int_distribution<int>(n_int == 0 ? 1 : 0, 12)(rng);
    const int lead_zeros = std::uniform_int_distribution<int>(0, 3)(rng);
    std::string ip = std::string(lead_zeros, '0'), fp;
    for (int i = 0; i < n_int; ++i) ip += char('0' + std::uniform_int_distribution<int>(0, 9)(rng));
    for (int i = 0; i < n_frac; ++i) fp += char('0' + std::uniform_int_distribution<int>(0, 9)(rng));
    const int e = std::uniform_int_distribution<int>(-25, 25)(rng);
    const bool neg = rng() & 1;
    const std::string text = std::string(neg ? "-" : "") + ip + (fp.empty() ? "" : "." + fp) + "e" + std::to_string(e);
    Integer m((ip + fp).empty() ? "0" : ip + fp, 10);
    const long scale = e - long(fp.size());
    Integer p;
    mpz_ui_pow_ui(p.get_mpz_t(), 10, static_cast<unsigned long>(scale < 0 ? -scale : scale));
    Rational want = scale >= 0 ? Rational(m * p) : Rational(m, p);
    want.canonicalize();
    if (neg) want = -want;
    ASSERT_EQ(exact(text, false), want) << text;
    // The certified double computed from the digits [FL-4] contains the exact value.
    std::string why;
    fl::Bounded b;
    ASSERT_TRUE(parse_rational(text, false, Input_limits{}, why, &b).has_value());
    ASSERT_TRUE(b.e == fl::Bounded::kInf || abs(want - Rational(b.v)) <= Rational(b.e))
        << text << ": v = " << b.v << ", e = " << b.e;
    if (b.e == 0) {
      ASSERT_EQ(Rational(b.v), want) << text;
    }
  }
}

TEST(Numbers, BadTextIsRejectedWithAReason) {
  const Input_limits lim;
  std::string why;
  for (const char* bad : {"", "abc", "1/0", "NaN", "nan", "Infinity", "-inf", "0x10", "1 ", " 1", "1/-2",
                          "1/2/3", "1.5/2", "e5", "1e", "--1", "/2", "1/", ".", "+", "1e+"}) {
    EXPECT_FALSE(parse_rational(bad, false, lim, why).has_value()) << bad;
  }
  // JSON grammar is stricter than the string grammar.
  for (const char* bad : {"+1", ".5", "5.", "01", "1/2"}) {
    EXPECT_FALSE(parse_rational(bad, true, lim, why).has_value()) << bad;
  }
  EXPECT_FALSE(parse_rational("1/0", false, lim, why).has_value());
  EXPECT_EQ(why, "has a zero denominator");
}

TEST(Numbers, LimitsOnDigitsAndExponents) {
  const Input_limits lim;
  std::string why;
  EXPECT_TRUE(parse_rational(std::string(10000, '7'), true, lim, why).has_value());
  EXPECT_FALSE(parse_rational(std::string(10001, '7'), true, lim, why).has_value());
  // The value written out counts too (exact/scene_writer's "p/q" must read back under the same
  // limits): 10^9999 has 10000 digits, 1/10^9998 has 1 + 9999; one more is too many.
  EXPECT_TRUE(parse_rational("1e9999", true, lim, why).has_value());
  EXPECT_TRUE(parse_rational("1e-9998", true, lim, why).has_value());
  EXPECT_TRUE(parse_rational("0.00e10000", true, lim, why).has_value());  // zero is short
  EXPECT_FALSE(parse_rational("1e10000", true, lim, why).has_value());
  EXPECT_EQ(why, "has more digits than the digit limit when written out exactly");
  EXPECT_FALSE(parse_rational("1e-9999", true, lim, why).has_value());
  EXPECT_FALSE(parse_rational("10e9999", true, lim, why).has_value());
  EXPECT_FALSE(parse_rational("1e10001", true, lim, why).has_value());
  EXPECT_EQ(why, "has an exponent beyond the exponent limit");
  EXPECT_FALSE(parse_rational("1e99999999999999999999999999", true, lim, why).has_value());
  EXPECT_TRUE(parse_rational("1e000000000000000000000000005", true, lim, why).has_value());
  // Every digit of the text counts, exponent and denominator included (the checker agrees).
  EXPECT_TRUE(parse_rational(std::string(9997, '9') + "e1", true, lim, why).has_value());
  EXPECT_FALSE(parse_rational(std::string(9998, '9') + "e10", true, lim, why).has_value());
  // A decimal's fraction digits count twice written out: 0.99…9 with 4999 nines is 99…9/10^4999.
  EXPECT_TRUE(parse_rational("0." + std::string(4999, '9'), true, lim, why).has_value());
  EXPECT_FALSE(parse_rational("0." + std::string(5000, '9'), true, lim, why).has_value());
  EXPECT_TRUE(parse_rational(std::string(5000, '9') + "/" + std::string(5000, '7'), false, lim, why).has_value());
  EXPECT_FALSE(parse_rational(std::string(5000, '9') + "/" + std::string(5001, '7'), false, lim, why).has_value());
  Input_limits raised;
  raised.max_digits = 20000;
  EXPECT_TRUE(parse_rational(std::string(10001, '7'), true, raised, why).has_value());
}

// Every reader (read_scene eager and lazy, the streaming reader fresh and into a reused scene) must
// give the same answer: the same message here.
Scene reused_eager, reused_lazy;

std::string error_of(const std::string& text, const Input_limits& lim = {}) {
  EXPECT_EQ(readers_disagree(text, lim, reused_eager, reused_lazy), "") << text.substr(0, 200);
  try {
    read_scene(text, lim, "s.json");
  } catch (const Input_error& e) {
    return e.what();
  }
  return "(accepted)";
}

// The one primitive-vector helper: the positive multiple with coprime integer entries; zero is a bug.
TEST(Numbers, PrimitiveVectors) {
  using Z3 = std::array<Integer, 3>;
  using Q3 = std::array<Rational, 3>;
  EXPECT_EQ(primitive(Z3{Integer(6), Integer(-4), Integer(0)}), (Z3{Integer(3), Integer(-2), Integer(0)}));
  EXPECT_EQ(primitive(Z3{Integer(0), Integer(0), Integer(-7)}), (Z3{Integer(0), Integer(0), Integer(-1)}));
  EXPECT_EQ(primitive(Q3{Rational(1, 2), Rational(-1, 3), Rational(5, 6)}), (Z3{Integer(3), Integer(-2), Integer(5)}));
  EXPECT_EQ(primitive(Q3{Rational(-4, 9), Rational(0), Rational(2, 3)}), (Z3{Integer(-2), Integer(0), Integer(3)}));
  EXPECT_EQ(primitive(Rational(-3, 4), Rational(9, 8)), (std::array<Integer, 2>{Integer(-2), Integer(3)}));
  EXPECT_EQ(primitive(Rational(0), Rational(-5, 7)), (std::array<Integer, 2>{Integer(0), Integer(-1)}));
  // 10^30 · (2, 4, 6) / 10^30 keeps its direction and loses its common factor.
  const Integer big("1000000000000000000000000000000");
  EXPECT_EQ(primitive(Q3{Rational(2 * big), Rational(4 * big), Rational(6, big)}),
            (Z3{Integer(big * big), Integer(2 * big * big), Integer(3)}));
  EXPECT_THROW(primitive(Z3{Integer(0), Integer(0), Integer(0)}), std::logic_error);
  EXPECT_THROW(primitive(Q3{Rational(0), Rational(0), Rational(0)}), std::logic_error);
  EXPECT_THROW(primitive(Rational(0), Rational(0)), std::logic_error);
}

// decimal_text: the decimal people read beside an exact value, correctly rounded in integers: against glibc's printf
// %.Ng (exact on a double's binary value, ties to even) on random doubles, and beyond the doubles' range.
TEST(Numbers, DecimalTextIsCorrectlyRoundedWithoutOverflow) {
  EXPECT_EQ(decimal_text(Rational(1, 7)), "0.142857");
  EXPECT_EQ(decimal_text(Rational(-1, 3)), "-0.333333");
  EXPECT_EQ(decimal_text(Rational(0)), "0");
  EXPECT_EQ(decimal_text(Rational(5)), "5");
  EXPECT_EQ(decimal_text(Rational(1, 10000)), "0.0001");
  EXPECT_EQ(decimal_text(Rational(1, 100000)), "1e-05");
  EXPECT_EQ(decimal_text(Rational(1999999, 2)), "1e+06");  // a tie to the even 1000000
  EXPECT_EQ(decimal_text(Rational(1999997, 2)), "999998");  // a tie to the even 999998
  Integer big;
  mpz_ui_pow_ui(big.get_mpz_t(), 10, 400);
  EXPECT_EQ(decimal_text(Rational(big, 3)), "3.33333e+399");
  EXPECT_EQ(decimal_text(Rational(Integer(-2), big)), "-2e-400");
  EXPECT_EQ(decimal_text(Rational(2, 3), 12), "0.666666666667");
  std::mt19937_64 rng(20261128);
  for (int i = 0; i < 6000; ++i) {
    double x;
    const std::uint64_t bits = rng();
    std::memcpy(&x, &bits, sizeof x);
    if (!std::isfinite(x)) continue;
    for (const int digits : {1, 6, 12, 17}) {
      char text[64];
      std::snprintf(text, sizeof text, "%.*g", digits, x);
      EXPECT_EQ(decimal_text(Rational(x), digits), x == 0 ? std::string("0") : std::string(text)) << x;
    }
  }
}

// nearest_double: correctly rounded (ties to even), against glibc's strtod (correctly rounded) on decimals
// and against its definition (no double is nearer; a tie goes to the even one) on fractions, with the
// cases where mpq_get_d (truncation) is wrong, halfway cases, subnormals and the ends of the range.
TEST(Numbers, NearestDoubleIsCorrectlyRounded) {
  const auto nearest = [](const Rational& q) { return nearest_double(q).value_or(-12345.0); };
  const Rational two53 = Rational(Integer(1) << 53);
  EXPECT_EQ(nearest(two53 + 1), 9007199254740992.0);  // halfway: to the even 2^53
  EXPECT_EQ(nearest(two53 + 3), 9007199254740996.0);  // halfway: to the even 2^53 + 4
  const Rational below_one(Integer((Integer(1) << 54) - 1), Integer(1) << 54);
  EXPECT_EQ(nearest(below_one), 1.0);
  EXPECT_LT(below_one.get_d(), 1.0);  // mpq_get_d truncates: this is why nearest_double exists
  EXPECT_EQ(nearest(Rational(2, 3)), 2.0 / 3.0);
  EXPECT_EQ(nearest(Rational(-1, 10)), -0.1);
  EXPECT_EQ(nearest(Rational(0)), 0.0);
  const Rational tiny(Integer(1), Integer(1) << 1075);  // half the smallest subnormal: ties to even 0
  EXPECT_EQ(nearest(tiny), 0.0);
  EXPECT_EQ(nearest(tiny * 3), 2 * std::numeric_limits<double>::denorm_min());  // 1.5 ulp: to the even 2
  EXPECT_EQ(nearest(tiny * Rational(101, 100)), std::numeric_limits<double>::denorm_min());
  const Rational max(Integer(std::numeric_limits<double>::max()));
  EXPECT_EQ(nearest(max), std::numeric_limits<double>::max());
  const Rational half_ulp_above = max + Rational(Integer(1) << 970);  // halfway to 2^1024: overflows
  EXPECT_FALSE(nearest_double(half_ulp_above).has_value());
  EXPECT_EQ(nearest(half_ulp_above - 1), std::numeric_limits<double>::max());
  std::mt19937_64 rng(20261124);
  for (int i = 0; i < 4000; ++i) {
    char text[64];
    std::snprintf(text, sizeof text, "%s%llu.%llue%d", rng() % 2 ? "-" : "", static_cast<unsigned long long>(rng() % 100000000000ull),
                  static_cast<unsigned long long>(rng()), static_cast<int>(rng() % 620) - 340);
    EXPECT_EQ(nearest(exact(text, false)), std::strtod(text, nullptr)) << text;
  }
  for (int i = 0; i < 4000; ++i) {
    const Integer p = Integer(static_cast<unsigned long>(rng() >> 1)) * static_cast<unsigned long>(rng() | 1) - Integer(static_cast<unsigned long>(rng()));
    const Integer q = (Integer(static_cast<unsigned long>(rng() | 1)) << static_cast<unsigned>(rng() % 200));
    const Rational x(p, q * static_cast<unsigned long>(rng() % 1000 + 1));
    const Rational v(nearest(x));
    const Rational up(std::nextafter(v.get_d(), HUGE_VAL)), down(std::nextafter(v.get_d(), -HUGE_VAL));
    const Rational e = abs(x - v);
    EXPECT_LE(e, abs(x - up)) << x;
    EXPECT_LE(e, abs(x - down)) << x;
    if (e == abs(x - up) || e == abs(x - down)) {  // a tie: the even significand
      int exp2 = 0;
      EXPECT_EQ(std::fmod(std::ldexp(std::frexp(v.get_d(), &exp2), 53), 2.0), 0.0) << x;
    }
  }
}

TEST(SceneErrors, MessagesNameThePathAndTheValue) {
  const std::string ok = R"("wrenchkit": 1, )";
  EXPECT_EQ(error_of(R"({"wrenchkit": 1, "contacts": [{"at": [0,0], "normal": [1,0]}, {"at": [0,0], "normal": [1,0]},
      {"at": [1,2], "normal": [0, "0.0"]}]})"), "contacts[2].normal: zero vector");
  EXPECT_EQ(error_of(R"({"wrenchkit": 1, "support": {"mu": 1, "points": [{"at": [0,0], "force": "abc"}]}})"),
            "support.points[0].force: \"abc\" is not a number");
  EXPECT_EQ(error_of("{" + ok + R"("contacts": [{"at": [0,0], "normal": [1,0], "mu": "-1/2"}]})"),
            "contacts[0].mu: \"-1/2\" is negative (must be >= 0)");
  EXPECT_EQ(error_of("{" + ok + R"("contacts": [{"at": [0,0], "nromal": [1,0]}]})"),
            "contacts[0]: unknown key \"nromal\" (did you mean \"normal\"?)");
  EXPECT_EQ(error_of("{" + ok + R"("contacts": [{"at": [0,0]}]})"), "contacts[0]: missing key \"normal\"");
  EXPECT_EQ(error_of("{" + ok + R"("contacts": [{"at": [0,0,1], "normal": [1,0]}]})"),
            "contacts[0].at: expected an array of 2 numbers, got an array of 3");
  EXPECT_EQ(error_of("{" + ok + R"("contacts": [{"at": "here", "normal": [1,0]}]})"),
            "contacts[0].at: expected an array of 2 numbers, got a string");
  EXPECT_EQ(error_of("{" + ok + R"("contacts": [{"at": [true, 0], "normal": [1,0]}]})"),
            "contacts[0].at[0]: expected a number, got a boolean");
  EXPECT_EQ(error_of("{" + ok + R"("contacts": [{"at": [0, "1/0"], "normal": [1,0]}]})"),
            "contacts[0].at[1]: \"1/0\" has a zero denominator");
  EXPECT_EQ(error_of("{" + ok + R"("contacts": [{"at": [0, "NaN"], "normal": [1,0]}]})"),
            "contacts[0].at[1]: \"NaN\" is not a number");
  EXPECT_EQ(error_of("{" + ok + R"("contacts": [{"wrench": [0, 0, "0/5"]}]})"), "contacts[0].wrench: zero wrench");
  EXPECT_EQ(error_of("{" + ok + R"("contacts": [{"wrench": [1, 0, 0], "mu": 1}]})"),
            "contacts[0]: unknown key \"mu\"");
  EXPECT_EQ(error_of(R"({"wrenchkit": 2})"), "wrenchkit: 2 is not a supported format version (only 1)");
  EXPECT_EQ(error_of(R"({"contacts": []})"), "scene: missing key \"wrenchkit\" (the format version, 1)");
  EXPECT_EQ(error_of(R"({"wrenchkit": 1, "contact": []})"), "scene: unknown key \"contact\" (did you mean \"contacts\"?)");
  EXPECT_EQ(error_of(R"([1, 2])"), "scene: expected an object, got an array");
  EXPECT_EQ(error_of("{" + ok + R"("support": {"mu": 1, "points": [{"at": [0,0], "force": 0}]}})"),
            "support.points: all forces are zero");
  EXPECT_EQ(error_of("{" + ok + R"("support": {"mu": 1, "points": [{"at": [0,0], "force": -1}]}})"),
            "support.points[0].force: -1 is negative (must be >= 0)");
  EXPECT_EQ(error_of("{" + ok + R"("support": {"points": [{"at": [0,0], "force": 1}]}})"),
            "support.points[0]: missing key \"mu\" (and support.mu gives no default)");
  EXPECT_EQ(error_of("{" + ok + R"("load": {"gravity": 1}})"),
            "load.gravity: needs body.com (the point where the weight acts)");
  EXPECT_EQ(error_of("{" + ok + R"("body": {"com": [0,0]}, "load": {"gravity": "0"}})"),
            "load.gravity: \"0\" is not positive (a weight must be > 0)");
  EXPECT_EQ(error_of("{" + ok + R"("load": {"force": [0,1]}})"), "load: missing key \"at\"");
  EXPECT_EQ(error_of("{" + ok + R"("load": {"gravity": 1, "wrench": [0,0,1]}})"), "load: unknown key \"wrench\"");
  EXPECT_EQ(error_of("{" + ok + R"("load": {}})"),
            "load: expected one of {\"force\", \"at\"}, {\"wrench\"} or {\"gravity\"}");
}

// The likely fix in a message (an unknown key's likely meaning, how to write a direction), the same from every
// reader (error_of compares them).
TEST(SceneErrors, MessagesNameTheLikelyFix) {
  const std::string ok = R"("wrenchkit": 1, )";
  EXPECT_EQ(error_of("{" + ok + R"("contacts": [{"position": [0,0], "normal": [1,0]}]})"),
            "contacts[0]: unknown key \"position\" (did you mean \"at\"?)");
  EXPECT_EQ(error_of("{" + ok + R"("contacts": [{"at": [0,0], "normal": [1,0], "coefficient": 1}]})"),
            "contacts[0]: unknown key \"coefficient\" (did you mean \"mu\"?)");
  EXPECT_EQ(error_of("{" + ok + R"("contacts": [{"wrench": [1,0,0], "name": "w", "nmae": 1}]})"),
            "contacts[0]: unknown key \"nmae\" (did you mean \"name\"?)");
  EXPECT_EQ(error_of("{" + ok + R"("body": {"cog": [0,0]}})"), "body: unknown key \"cog\" (did you mean \"com\"?)");
  EXPECT_EQ(error_of("{" + ok + R"("support": {"mu": 1, "regions": [{"outline": [[0,0],[1,0],[0,1]], "presure": "uniform"}]}})"),
            "support.regions[0]: unknown key \"presure\" (did you mean \"pressure\"?)");
  const std::string advice =
      " (a normal is a direction [dx, dy] of any length, not an angle: for 30\u00b0 write [0.866025, 0.5], or give an "
      "exact direction such as [4, 3])";
  EXPECT_EQ(error_of("{" + ok + R"("contacts": [{"at": [0,0], "normal": 30}]})"),
            "contacts[0].normal: expected an array of 2 numbers, got a number" + advice);
  EXPECT_EQ(error_of("{" + ok + R"("contacts": [{"at": [0,0], "normal": "1/2"}]})"),
            "contacts[0].normal: expected an array of 2 numbers, got a string" + advice);
  EXPECT_EQ(error_of("{" + ok + R"("contacts": [{"at": [0,0], "normal": {}}]})"),
            "contacts[0].normal: expected an array of 2 numbers, got an object");
}

TEST(SceneErrors, LimitsAreEnforcedAndNamed) {
  const std::string big(10001, '9');
  EXPECT_EQ(error_of(R"({"wrenchkit": 1, "contacts": [{"at": [0, )" + big + R"(], "normal": [1,0]}]})"),
            "contacts[0].at[1]: 9999999999999999999999999999999999999999… (10001 characters) has more than "
            "10000 digits (--max-digits)");
  EXPECT_EQ(error_of(R"({"wrenchkit": 1, "contacts": [{"at": [0, "1e10000"], "normal": [1,0]}]})"),
            "contacts[0].at[1]: \"1e10000\" has more than 10000 digits written out as an exact integer or fraction "
            "(--max-digits)");
  EXPECT_EQ(error_of(R"({"wrenchkit": 1, "contacts": [{"at": [0, "1e10001"], "normal": [1,0]}]})"),
            "contacts[0].at[1]: \"1e10001\" has an exponent beyond ±10000 (--max-exponent)");
  Input_limits small;
  small.max_file_bytes = 10;
  EXPECT_EQ(error_of(R"({"wrenchkit": 1})", small), "s.json: larger than the size limit of 10 bytes (--max-file-size)");
  small = Input_limits{};
  small.max_contacts = 1;
  EXPECT_EQ(error_of(R"({"wrenchkit": 1, "contacts": [{"wrench": [1,0,0]}, {"wrench": [1,0,0]}]})", small),
            "contacts: has 2 entries, more than the limit 1 (--max-contacts)");
}

TEST(SceneErrors, MalformedJsonNamesLineAndColumn) {
  EXPECT_EQ(error_of("{\"wrenchkit\": 1,\n  \"name\": \"x\" \"body\": {}}"),
            "s.json:2:15: invalid JSON: expected ',' or '}' after an object member");
  EXPECT_EQ(error_of(R"({"wrenchkit": 1, "wrenchkit": 1})"), "s.json:1:18: invalid JSON: duplicate key \"wrenchkit\"");
  EXPECT_EQ(error_of(R"({"wrenchkit": 1} x)"), "s.json:1:18: invalid JSON: unexpected data after the JSON value");
  EXPECT_EQ(error_of(R"({"wrenchkit": NaN})"), "s.json:1:15: invalid JSON: unexpected character, expected a value");
  EXPECT_EQ(error_of(R"({"wrenchkit": 01})"), "s.json:1:16: invalid JSON: expected ',' or '}' after an object member");
  EXPECT_EQ(error_of("{\"wrenchkit\": 1, \"name\": \"a\xff\"}"), "s.json:1:28: invalid JSON: invalid UTF-8");
  EXPECT_EQ(error_of("{\"wrenchkit\": 1, \"name\": \"\\ud800\"}"),
            "s.json:1:33: invalid JSON: lone high surrogate in \\u escape");
  EXPECT_EQ(error_of(""), "s.json:1:1: invalid JSON: unexpected end of input, expected a value");
  EXPECT_EQ(error_of(std::string(65, '[') + std::string(65, ']')),
            "s.json:1:65: invalid JSON: nesting deeper than 64 levels");
  // Deep nesting far beyond the limit is refused without recursion trouble.
  EXPECT_NE(error_of(std::string(1000000, '[')).find("nesting deeper"), std::string::npos);
}

// The lazy reading (batch) must accept and reject exactly what the eager one does, with the same
// messages, and give the same rationals on demand.
TEST(SceneModel, LazyReadingMatchesTheEagerOne) {
  const std::vector<std::string> texts = {
      R"({"wrenchkit": 1, "contacts": [{"at": [0.1, "1/3"], "normal": [1, "-2.5e-3"], "mu": "0.5"}, {"wrench": [0, 0, 1]}]})",
      R"({"wrenchkit": 1, "contacts": [{"at": [0,0], "normal": [0, "0.000"]}]})",
      R"({"wrenchkit": 1, "contacts": [{"at": [0,0], "normal": [1,0], "mu": "-0.0"}]})",
      R"({"wrenchkit": 1, "contacts": [{"at": [0,0], "normal": [1,0], "mu": "-1e-30"}]})",
      R"({"wrenchkit": 1, "contacts": [{"at": [0,0,1], "normal": [1,0]}]})",
      R"({"wrenchkit": 1, "contacts": [{"at": [0,"x"], "normal": [1,0]}]})",
      R"({"wrenchkit": 1, "contacts": [{"wrench": [0, "0/7", "0e5"]}]})",
      R"({"wrenchkit": 1, "contacts": [{"wrench": [0, 0]}]})",
      R"({"wrenchkit": 1, "contacts": [{"at": [0, "1/0"], "normal": [1,0]}]})",
      R"({"wrenchkit": 1, "contacts": [{"at": [0, 1e10001], "normal": [1,0]}]})",
      R"({"wrenchkit": 1, "contacts": [{"at": [0, 123456789012345678901234567890.5], "normal": [1e-300, 0], "mu": 1e300}]})",
      R"({"wrenchkit": 1, "contacts": [{"normal": [1,0]}]})",
  };
  for (const std::string& t : texts) {
    SCOPED_TRACE(t);
    std::string eager_error, lazy_error;
    Scene eager, lazy;
    try { eager = read_scene(t, Input_limits{}, "s"); } catch (const Input_error& e) { eager_error = e.what(); }
    try { lazy = read_scene(t, Input_limits{}, "s", true); } catch (const Input_error& e) { lazy_error = e.what(); }
    EXPECT_EQ(eager_error, lazy_error);
    if (!eager_error.empty()) continue;
    ASSERT_EQ(eager.contacts.size(), lazy.contacts.size());
    for (std::size_t i = 0; i < eager.contacts.size(); ++i) {
      const Contact a = eager.contacts[i], b = exact_contact(lazy.contacts[i]);
      EXPECT_TRUE(lazy.contacts[i].exact_pending);
      EXPECT_EQ(a.at.x, b.at.x);
      EXPECT_EQ(a.at.y, b.at.y);
      EXPECT_EQ(a.normal.x, b.normal.x);
      EXPECT_EQ(a.normal.y, b.normal.y);
      EXPECT_EQ(a.mu, b.mu);
      EXPECT_EQ(a.wrench[2], b.wrench[2]);
      EXPECT_EQ(a.twin.frictional, lazy.contacts[i].twin.frictional);
      for (int k = 0; k < 3; ++k) {  // the same certified doubles
        const fl::Bounded* x[] = {&a.twin.ax, &a.twin.nx, &a.twin.mu};
        const fl::Bounded* y[] = {&lazy.contacts[i].twin.ax, &lazy.contacts[i].twin.nx, &lazy.contacts[i].twin.mu};
        EXPECT_EQ(x[k]->v, y[k]->v);
        EXPECT_EQ(x[k]->e, y[k]->e);
      }
    }
  }
}

// The streaming reader (batch) against read_scene: valid scenes in every form the schema allows
// (keys in any order, escapes, UTF-8 names, numbers as strings, every load and support form, odd
// whitespace, tight depth and count limits) and the bad-input classes of the command-line tests; each
// through every reader, fresh and into a scene reused from the previous text.
TEST(StreamingReader, AgreesWithReadSceneOnValidAndInvalidScenes) {
  const std::vector<std::string> texts = {
      R"({"wrenchkit": 1})",
      "  {\"wrenchkit\":1 ,\"contacts\":[ ]}\r\n\t",
      R"({"contacts": [{"mu": 0.5, "normal": [1, 0], "at": [0.25, "1/3"]}], "wrenchkit": "1/1", "name": "n"})",
      R"({"wrenchkit": 1.0e0, "contacts": [{"at": [1, 2], "normal": ["+.5", "-2.5e-3"], "name": "caf\u00e9 \"x\""}]})",
      "{\"wrenchkit\": 1, \"name\": \"\xc3\xa9\\n\\ud83d\\ude00\", \"contacts\": [{\"wrench\": [0, 0, \"1e-3\"], \"name\": \"\"}]}",
      R"({"w\u0072enchkit": 1, "contacts": [{"\u0061t": [0, 0], "normal": [0, 1]}]})",
      R"({"wrenchkit": 1, "contacts": [{"wrench": [1, 0, 0]}, {"at": [0, 0], "normal": [1, 0], "mu": 0}]})",
      R"({"wrenchkit": 1, "contacts": [{"at": [0, 123456789012345678901234567890.5], "normal": [1e-300, 0], "mu": 1e300}]})",
      R"({"wrenchkit": 1, "contacts": [{"at": [0, 0], "normal": [1, 0], "mu": "-0.0"}]})",
      R"({"wrenchkit": 1, "body": {"outline": [[0,0],[1,0],[1,1]], "com": ["1/2", 0.5]}, "load": {"gravity": 2}})",
      R"({"load": {"gravity": 2}, "body": {"com": [0, 0]}, "wrenchkit": 1})",
      R"({"wrenchkit": 1, "body": {}, "load": {"wrench": [0, 0, 1]}})",
      R"({"wrenchkit": 1, "body": {"outline": []}, "load": {"at": [1, 1], "force": [0, -1]}})",
      R"({"wrenchkit": 1, "support": {"points": [{"at": [0, 0], "force": 1, "mu": 0.5}, {"force": 0, "at": [1, 0], "mu": 1}]}})",
      R"({"wrenchkit": 1, "support": {"points": [{"at": [0, 0], "force": 1}], "mu": "1/2"}})",
      // invalid
      R"({"wrenchkit": 1, "support": {"points": [{"at": [0, 0], "force": 1}, {"at": [0, 0], "force": 1, "mu": 1}]}})",
      R"({"wrenchkit": 1, "support": {"mu": 1, "points": []}})",
      R"({"wrenchkit": 1, "support": {"mu": 1}})",
      R"({"wrenchkit": 1, "load": {"gravity": 2}})",
      R"({"wrenchkit": 1, "load": {"force": [0, 1]}})",
      R"({"wrenchkit": 1, "load": {"force": [0, 1], "at": [0, 0], "wrench": [1, 0, 0]}})",
      R"({"wrenchkit": 1, "load": {"gravity": -1}, "body": {"com": [0, 0]}})",
      R"({"wrenchkit": 1, "contacts": [{"at": [0, 0], "normal": [1, 0], "wrench": [1, 0, 0]}]})",
      R"({"wrenchkit": 1, "contacts": [{"wrench": [1, 0, 0], "at": [0, 0]}]})",
      R"({"wrenchkit": 1, "contacts": [{"at": [0, 0], "normal": [1, 0], "at": [0, 0]}]})",
      R"({"wrenchkit": 1, "contacts": [{"at": [0, 0], "normal": [1, 0]},]})",
      R"({"wrenchkit": 1, "contacts": [{"at": [0, 0], "normal": [1, 0], "mu": -0.5}]})",
      R"({"wrenchkit": 1, "contacts": [{"at": [0, 0], "normal": [1, 0], "name": 3}]})",
      R"({"wrenchkit": 1, "contacts": [{"at": [0, 00], "normal": [1, 0]}]})",
      R"({"wrenchkit": 1, "contacts": [{"at": [0, -], "normal": [1, 0]}]})",
      R"({"wrenchkit": 1, "contacts": [{"at": [0, 1.], "normal": [1, 0]}]})",
      R"({"wrenchkit": 1, "contacts": [{"at": [0, 1e], "normal": [1, 0]}]})",
      R"({"wrenchkit": 1, "contacts": [{"at": [0, "1"], "normal": [1, "\u0030"]}]})",
      R"({"wrenchkit": 1, "contacts": [{"at": [0, "1\u0000"], "normal": [1, 0]}]})",
      R"({"wrenchkit": 1, "name": "\ud800"})",
      "{\"wrenchkit\": 1, \"name\": \"a\xff\"}",
      "{\"wrenchkit\": 1, \"name\": \"tab\there\"}",
      R"({"wrenchkit": 1, "name": "x"} {})",
      R"({"wrenchkit": 2})",
      R"({"wrenchkit": 1, "wrenchkit": 1})",
      R"({"wrenchkit": 1, "body": {"com": [0, 0], "com": [0, 0]}})",
      R"({"wrenchkit": true})",
      R"({"wrenchkit": 1, "contacts": null})",
      R"({"wrenchkit": 1, "contacts": [{"at": [0, 0], "normal": [1, 0]}])",
      R"({"wrenchkit": 1, "contacts": [{"at": [0, 0], "normal": [1, 0]}]}})",
      "\xef\xbb\xbf{\"wrenchkit\": 1}",
      "",
      "[]",
      // the bad-input classes of tests/cli_test.cpp
      "{\"wrenchkit\": 1,",
      R"({"wrenchkit": 1, "contacts": {}})",
      R"({"wrenchkit": 1, "extra": 1})",
      R"({"contacts": []})",
      R"({"wrenchkit": 1, "contacts": [{"at": [0,0], "normal": [0,0]}]})",
      R"({"wrenchkit": 1, "support": {"mu": 1, "points": [{"at": [0,0], "force": -2}]}})",
      R"({"wrenchkit": 1, "support": {"mu": 1, "points": [{"at": [0,0], "force": 0}]}})",
      R"({"wrenchkit": 1, "contacts": [{"at": [0,"1/0"], "normal": [0,1]}]})",
      R"({"wrenchkit": 1, "contacts": [{"at": [0,"Infinity"], "normal": [0,1]}]})",
      R"({"wrenchkit": 1, "contacts": [{"at": [0,1e10001], "normal": [0,1]}]})",
      R"({"wrenchkit": 1, "contacts": [{"at": [0,)" + std::string(10001, '1') + R"(], "normal": [0,1]}]})",
  };
  Scene eager, lazy;
  int accepted = 0;
  for (const std::string& t : texts) {
    EXPECT_EQ(readers_disagree(t, Input_limits{}, eager, lazy), "") << t;
    try {
      read_scene(t, Input_limits{});
      ++accepted;
    } catch (const Input_error&) {
    }
  }
  EXPECT_EQ(accepted, 16);  // the valid ones above really are valid
  // Tight limits: nesting (support.points[i].at is 5 deep), contacts, digits, size.
  const std::string deep = texts[13];
  for (std::size_t depth = 0; depth <= 6; ++depth) {
    Input_limits lim;
    lim.max_depth = depth;
    EXPECT_EQ(readers_disagree(deep, lim, eager, lazy), "") << depth;
    EXPECT_EQ(readers_disagree(texts[9], lim, eager, lazy), "") << depth;
  }
  for (std::size_t n = 0; n <= 3; ++n) {
    Input_limits lim;
    lim.max_contacts = n;
    EXPECT_EQ(readers_disagree(texts[6], lim, eager, lazy), "") << n;
    lim.max_file_bytes = 10 * n;
    EXPECT_EQ(readers_disagree(texts[0], lim, eager, lazy), "") << n;
  }
  Input_limits few_digits;
  few_digits.max_digits = 3;
  few_digits.max_exponent = 2;
  for (const std::string& t : texts) EXPECT_EQ(readers_disagree(t, few_digits, eager, lazy), "") << t;
}

// Random byte mutations of valid scenes (fixed seed; WRENCHKIT_SEED overrides): whatever the bytes,
// the streaming reader accepts exactly what read_scene accepts, with the same scene or message.
TEST(StreamingReader, AgreesWithReadSceneOnMutatedScenes) {
  const std::uint64_t seed = test::seed(20261207);
  std::mt19937_64 rng(seed);
  const std::vector<std::string> bases = {
      R"({"wrenchkit": 1, "name": "g", "contacts": [{"at": [0.664303, 0.747463], "normal": [-0.455843, -0.589199], "mu": 0.228}, {"wrench": [1, "-2/3", 0]}]})",
      R"({"wrenchkit": 1, "body": {"outline": [[0,0],[1,0]], "com": ["1/2", 0.5]}, "load": {"gravity": 2}, "contacts": [{"at": [0, 0], "normal": [0, 1], "mu": "1/2"}]})",
      R"({"wrenchkit": 1, "load": {"force": [0, -1], "at": [1, 2]}, "support": {"mu": 0.5, "points": [{"at": [0, -1], "force": "1/2"}, {"at": [0, 1], "force": 0, "mu": 2}]}})",
  };
  const std::string alphabet = "{}[]\",:.-+/e0123456789 \\u\xc3\xa9" "atnormlucewhgiyfpsbd";
  Scene eager, lazy;
  int valid = 0;
  for (int t = 0; t < 6000; ++t) {
    std::string s = bases[static_cast<std::size_t>(t) % bases.size()];
    const int edits = 1 + static_cast<int>(rng() % 3);
    for (int e = 0; e < edits; ++e) {
      const std::size_t at = rng() % (s.size() + 1);
      const char c = alphabet[rng() % alphabet.size()];
      switch (rng() % 3) {
        case 0: if (at < s.size()) s[at] = c; break;
        case 1: s.insert(at, 1, c); break;
        default: if (at < s.size()) s.erase(at, 1); break;
      }
    }
    const std::string d = readers_disagree(s, Input_limits{}, eager, lazy);
    if (!d.empty()) {
      ADD_FAILURE() << "seed " << seed << ", case " << t << ": " << d << "\n"
                    << s << "\ndumped to " << test::dump_failure(s, "streaming_reader_mutation");
      break;
    }
    try {
      read_scene(s, Input_limits{});
      ++valid;
    } catch (const Input_error&) {
    }
  }
  EXPECT_GT(valid, 200);  // mutations that stay valid scenes (other numbers, names, spacing): about 250
}

TEST(SceneModel, ReadsEveryField) {
  const Scene s = read_scene(R"({
    "wrenchkit": 1, "name": "corner \u00e9",
    "body": {"outline": [[0,0],[1,0],[1,1]], "com": ["1/2", 0.5]},
    "contacts": [{"at": [0,0], "normal": [0,1], "mu": "1/2", "name": "floor"}, {"wrench": [0, 0, "1e-3"]}],
    "load": {"force": [0,-1], "at": ["1/2","1/2"]},
    "support": {"mu": "1/2", "points": [{"at": [0,-1], "force": "1/2"}, {"at": [0,1], "force": 0, "mu": 2}]}
  })", Input_limits{});
  EXPECT_EQ(s.name, "corner \xc3\xa9");
  EXPECT_EQ(s.body.outline.size(), 3u);
  EXPECT_EQ(s.body.com->x, Rational(1, 2));
  EXPECT_EQ(s.body.com->y, Rational(1, 2));
  ASSERT_EQ(s.contacts.size(), 2u);
  EXPECT_EQ(s.contacts[0].mu, Rational(1, 2));
  EXPECT_EQ(s.contacts[0].name, "floor");
  EXPECT_EQ(s.contacts[1].kind, Contact::Kind::wrench);
  EXPECT_EQ(s.contacts[1].wrench[2], Rational(1, 1000));
  EXPECT_EQ(s.load->kind, Load::Kind::force);
  EXPECT_EQ(s.support->points[1].mu, Rational(2));
}

}  // namespace
}  // namespace wrenchkit

namespace wrenchkit {
namespace {

// The scene-wide "mu" (docs/scene-format.md "Friction"): every point contact's coefficient unless it writes its own,
// wherever the key stands; eager, lazy and streaming reading agree; the checker reads it the same.
TEST(SceneMu, SceneWideDefaultForContactsWithoutTheirOwn) {
  const std::string text = R"({"wrenchkit": 1, "contacts": [{"at": [0, 0], "normal": [0, 1]},
      {"at": [1, 0], "normal": [0, 1], "mu": 0}, {"wrench": [0, 0, 1]}], "mu": "1/3"})";
  for (const bool lazy : {false, true}) {
    const Scene s = read_scene(text, Input_limits{}, "s", lazy);
    const Contact c0 = s.contacts[0].exact_pending ? exact_contact(s.contacts[0]) : s.contacts[0];
    const Contact c1 = s.contacts[1].exact_pending ? exact_contact(s.contacts[1]) : s.contacts[1];
    EXPECT_EQ(c0.mu, Rational(1, 3)) << lazy;
    EXPECT_TRUE(s.contacts[0].mu_given);
    EXPECT_EQ(c1.mu, 0);
    EXPECT_TRUE(s.contacts[1].twin.frictional == false);
    EXPECT_TRUE(s.contacts[0].twin.frictional);
  }
  // Without it, a contact without mu is frictionless and known to be so by default.
  const Scene plain = read_scene(R"({"wrenchkit": 1, "contacts": [{"at": [0, 0], "normal": [0, 1]}]})", Input_limits{}, "s");
  EXPECT_EQ(plain.contacts[0].mu, 0);
  EXPECT_FALSE(plain.contacts[0].mu_given);
  EXPECT_EQ(error_of(R"({"wrenchkit": 1, "mu": "-1/2", "contacts": []})"), "mu: \"-1/2\" is negative (must be >= 0)");
  EXPECT_EQ(readers_disagree(text, Input_limits{}, reused_eager, reused_lazy), "");
}

}  // namespace
}  // namespace wrenchkit
