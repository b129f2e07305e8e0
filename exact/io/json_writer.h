// The one JSON writer of the engine and the command (every answer, certificate and report): a
// document streamed into one string in the project's single layout — ", " between members and
// between elements, ": " after a key, nothing inside the brackets, no newline — so every producer
// writes the same bytes for the same values (docs/cli.md). Exact numbers are the quoted lowest-terms
// text "p/q" ("p" for integers) that read back exactly.
//
// A value (or key) written after another in the same object or array gets its ", " by itself: the
// writer looks at the last byte written (a value never ends in '[' or '{'), so there is no stack
// and a function can write members into an object its caller opened (the continue-an-open-object
// pattern: `void write_x(Json_writer&, …)` writes keys and values, the caller opens and closes).
// The writer checks no grammar; each producer writes well-formed JSON, as the tests read back.
#pragma once

#include <cassert>
#include <charconv>
#include <cstddef>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include "exact/io/json.h"
#include "exact/numbers/rational.h"

namespace wrenchkit {

class Json_writer {
 public:
  // Writes into `buffer` (cleared, its capacity kept: a caller reusing one string per line pays no
  // allocation once warm); `reserve` bytes are reserved up front.
  explicit Json_writer(std::size_t reserve = 256, std::string buffer = std::string()) : out_(std::move(buffer)) {
    out_.clear();
    if (out_.capacity() < reserve) out_.reserve(reserve);  // never a shrinking request
  }

  Json_writer& object() { return open('{'); }
  Json_writer& end_object() { return close('}'); }
  Json_writer& array() { return open('['); }
  Json_writer& end_array() { return close(']'); }
  // A member's key (escaped as a string); its value comes next. A key written as a string literal
  // (every key of the formats: plain identifiers) is copied as it is, without the scan for escapes:
  // batch writes some twenty keys per line.
  Json_writer& key(std::string_view k) {
    separate();
    quoted(k);
    out_.append(": ", 2);
    after_key_ = true;
    return *this;
  }
  template <std::size_t N>
  Json_writer& key(const char (&k)[N]) {
    assert(std::string_view(k).find_first_of("\"\\") == std::string_view::npos);
    char b[N + 5];  // [", "] "key": — one append
    std::size_t n = 0;
    if (needs_comma()) {
      b[n++] = ',';
      b[n++] = ' ';
    }
    b[n++] = '"';
    std::memcpy(b + n, k, N - 1);
    n += N - 1;
    std::memcpy(b + n, "\": ", 3);
    n += 3;
    out_.append(b, n);
    after_key_ = true;
    return *this;
  }
  Json_writer& string(std::string_view s) {  // escaped as json::quote does (RFC 8259)
    separate();
    quoted(s);
    return *this;
  }
  Json_writer& boolean(bool b) { return raw(b ? "true" : "false"); }
  Json_writer& null() { return raw("null"); }
  template <class Int, class = std::enable_if_t<std::is_integral_v<Int> && !std::is_same_v<Int, bool>>>
  Json_writer& integer(Int n) {
    separate();
    char b[24];
    out_.append(b, static_cast<std::size_t>(std::to_chars(b, b + sizeof b, n).ptr - b));
    return *this;
  }
  // An exact number as its quoted text, to_string's: "p/q", or "p" when q = 1 (lowest terms: the engine
  // keeps every Rational canonical).
  Json_writer& rational(const Rational& q);
  Json_writer& rational(const Integer& z);
  // An array of exact numbers (a vector's coordinates: Rational or Integer).
  template <class Numbers>
  Json_writer& rationals(const Numbers& xs) {
    array();
    for (const auto& x : xs) rational(x);
    return end_array();
  }
  // An already written JSON value (a certificate, a number formatted by the caller), as is.
  Json_writer& raw(std::string_view json) {
    separate();
    out_.append(json);
    return *this;
  }
  // Shorthands for the commonest shapes: key(k) then the value.
  template <class K>
  Json_writer& member(const K& k, std::string_view s) {
    return key(k).string(s);
  }
  template <class K>
  Json_writer& member(const K& k, const char* s) {
    return key(k).string(s);
  }
  template <class K>
  Json_writer& member(const K& k, bool b) {
    return key(k).boolean(b);
  }
  template <class K>
  Json_writer& member(const K& k, const Rational& q) {
    return key(k).rational(q);
  }
  template <class K, class Int, class = std::enable_if_t<std::is_integral_v<Int> && !std::is_same_v<Int, bool>>>
  Json_writer& member(const K& k, Int n) {
    return key(k).integer(n);
  }

  const std::string& str() const { return out_; }
  std::string take() { return std::move(out_); }
  void clear() {
    out_.clear();
    after_key_ = false;
  }

 private:
  // ", " before a value or key unless it is the first in its object/array (or the document), or
  // the value of the key just written.
  bool needs_comma() const { return !after_key_ && !out_.empty() && out_.back() != '[' && out_.back() != '{'; }
  void separate() {
    if (needs_comma()) out_.append(", ", 2);
    after_key_ = false;
  }
  // `s` quoted: copied at once when nothing in it needs escaping (keys, names, numbers' texts: the
  // common case, inline), else by json::append_quoted.
  void quoted(std::string_view s) {
    std::size_t i = 0;
    while (i < s.size() && s[i] != '"' && s[i] != '\\' && static_cast<unsigned char>(s[i]) >= 0x20) ++i;
    if (i < s.size()) return json::append_quoted(out_, s);
    out_ += '"';
    out_.append(s.data(), s.size());
    out_ += '"';
  }
  Json_writer& open(char c) {
    separate();
    out_ += c;
    return *this;
  }
  Json_writer& close(char c) {
    out_ += c;
    return *this;
  }

  std::string out_;
  bool after_key_ = false;
};

// The text of one value that `write` writes (the string forms of the write_* functions: certificate_json,
// region_json, …).
template <class T>
std::string json_text(void (*write)(Json_writer&, const T&), const T& x, std::size_t reserve = 256) {
  Json_writer w(reserve);
  write(w, x);
  return w.take();
}

}  // namespace wrenchkit
