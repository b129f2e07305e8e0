// A strict JSON reader (RFC 8259) that keeps every number's text, for exact reading.
//
// Rejects: malformed JSON, trailing data, duplicate keys, invalid UTF-8, unescaped control
// characters, lone surrogates, nesting deeper than the limit. Errors name the line and column.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "exact/numbers/limits.h"

namespace wrenchkit::json {

enum class Type { null, boolean, number, string, array, object };

struct Value {
  Type type = Type::null;
  bool boolean = false;
  std::string text;  // number: its exact text; string: its decoded UTF-8 value
  std::vector<Value> items;                         // array
  std::vector<std::pair<std::string, Value>> members;  // object, in input order

  const Value* find(std::string_view key) const {
    for (const auto& m : members)
      if (m.first == key) return &m.second;
    return nullptr;
  }
};

const char* type_name(Type t);

// Parses a whole document. Throws Input_error("SOURCE:LINE:COL: invalid JSON: …").
Value parse(std::string_view text, const Input_limits& limits, std::string_view source);

// Reads `text` as JSON lines (one document per line; blank lines and a trailing \r are skipped) and calls
// fn(line, where, raw, object) for each, with `where` = "SOURCE:LINE" and `raw` the line's text. A line that is not valid JSON is bad input
// named "SOURCE:LINE:COL"; one that is not an object "SOURCE:LINE: <what> must be a JSON object, not a …".
void for_each_object_line(std::string_view text, const Input_limits& limits, const std::string& source,
                          std::string_view what,
                          const std::function<void(std::size_t line, const std::string& where, std::string_view raw, Value& object)>& fn);

// Moves `pos` over the JSON number token (RFC 8259 grammar) that starts at text[pos]; false when it is
// malformed, with `pos` at the offending character. parse() and the streaming scene reader
// (exact/io/streaming_scene_reader.cpp) tokenize numbers with it.
bool skip_number(std::string_view text, std::size_t& pos);

// Decodes the JSON string literal whose opening quote is text[pos], exactly as parse() decodes
// strings (escapes, surrogate pairs, UTF-8 validation), and moves `pos` past the closing quote.
// Throws the Input_error parse() would throw there. For readers that scan JSON themselves
// (exact/io/streaming_scene_reader.cpp), so that they and parse() agree on every string.
std::string decode_string(std::string_view text, std::size_t& pos, const Input_limits& limits,
                          std::string_view source);

// The value of the JSON string literal whose opening quote is text[pos], `pos` moved past it: a view of the
// text when it is ASCII without escapes (no copy), else decode_string's value, kept in `scratch`. Throws
// decode_string's Input_error on a malformed or unterminated literal. For the one-pass readers (the streaming
// scene reader, the budget's measure).
std::string_view string_view_at(std::string_view text, std::size_t& pos, std::string& scratch,
                                const Input_limits& limits, std::string_view source);

// Writes `s` as a JSON string literal (with quotes), escaping as RFC 8259 requires: quote returns it,
// append_quoted appends it to `out` (Json_writer, exact/io/json_writer.h, writes every string with it).
std::string quote(std::string_view s);
void append_quoted(std::string& out, std::string_view s);

// The JSON text of a parsed value, numbers with their original text (so exact values survive a
// round trip): how the CLI and the tests hand a certificate read from a file to the checker.
std::string text_of(const Value& v);

}  // namespace wrenchkit::json
