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

#include <charconv>
#include <cstddef>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include "exact/numbers/rational.h"

namespace wrenchkit {

class Json_writer {
 public:
  // Writes into `buffer` (cleared, its capacity kept: a caller reusing one string per line pays no
  // allocation once warm); `reserve` bytes are reserved up front.
  explicit Json_writer(std::size_t reserve = 256, std::string buffer = std::string()) : out_(std::move(buffer)) {
    out_.clear();
    out_.reserve(reserve);
  }

  Json_writer& object() { return open('{'); }
  Json_writer& end_object() { return close('}'); }
  Json_writer& array() { return open('['); }
  Json_writer& end_array() { return close(']'); }
  // A member's key (escaped as a string); its value comes next.
  Json_writer& key(std::string_view k);
  Json_writer& string(std::string_view s);  // escaped as json::quote does (RFC 8259)
  Json_writer& boolean(bool b) { return raw(b ? "true" : "false"); }
  Json_writer& null() { return raw("null"); }
  template <class Int, class = std::enable_if_t<std::is_integral_v<Int> && !std::is_same_v<Int, bool>>>
  Json_writer& integer(Int n) {
    separate();
    char b[24];
    out_.append(b, static_cast<std::size_t>(std::to_chars(b, b + sizeof b, n).ptr - b));
    return *this;
  }
  // An exact number as its quoted lowest-terms text: "p/q", or "p" when q = 1 (to_string's text).
  Json_writer& rational(const Rational& q);
  Json_writer& rational(const Integer& z);
  // An already written JSON value (a certificate, a number formatted by the caller), as is.
  Json_writer& raw(std::string_view json) {
    separate();
    out_.append(json);
    return *this;
  }
  // Shorthands for the commonest shapes: key(k) then the value.
  Json_writer& member(std::string_view k, std::string_view s) { return key(k).string(s); }
  Json_writer& member(std::string_view k, const char* s) { return key(k).string(s); }
  Json_writer& member(std::string_view k, bool b) { return key(k).boolean(b); }
  Json_writer& member(std::string_view k, const Rational& q) { return key(k).rational(q); }
  template <class Int, class = std::enable_if_t<std::is_integral_v<Int> && !std::is_same_v<Int, bool>>>
  Json_writer& member(std::string_view k, Int n) {
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
  void separate() {
    if (after_key_) after_key_ = false;
    else if (!out_.empty() && out_.back() != '[' && out_.back() != '{') out_ += ", ";
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

}  // namespace wrenchkit
