// proofs/checker/json.h - the checker's own strict JSON reader (RFC 8259), internal to the checker.
//
// A pull reader: the scene and certificate readers walk the document in order and ask for exactly
// the values they expect, so no tree is built and memory stays proportional to the kept text.
// Strictness: UTF-8 only (no BOM, no overlong forms, no encoded or escaped lone surrogates), no
// unescaped control characters, no duplicate keys, no trailing commas or trailing data, nesting at
// most `max_depth` containers deep. Nothing recurses, so no input can exhaust the stack.
#pragma once

#include <cstddef>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace wrenchkit_checker::detail {

// Any problem with an input, syntax or meaning; check() turns it into a Result.
struct Failure {
  std::string message;
};

// `text` as a JSON string literal: quotes added, '"', '\\' and control characters escaped.
std::string escape(std::string_view text);
// The same for messages, cut after 40 bytes (between UTF-8 characters) with "...", so that a huge
// value never makes a huge message.
std::string quote(std::string_view text);

class Reader {
 public:
  enum class Kind { null, boolean, number, string, array, object };

  Reader(std::string_view text, std::size_t max_depth) : text_(text), max_depth_(max_depth) {}

  Kind peek();  // kind of the next value; a syntax error if there is none
  void begin_object();
  bool next_key(std::string& key);  // next member's key, or false (and the object is closed) at '}'
  void begin_array();
  bool next_item();           // true before each element, false (array closed) at ']'
  std::string string();       // a string value, decoded to UTF-8
  std::string_view number();  // a JSON number, as its exact source text
  bool boolean();
  void skip();    // any value, fully validated (duplicate keys included)
  void finish();  // nothing but whitespace may follow the top-level value

  // Path of the value being read, e.g. "contacts[2].normal"; `container` leaves out the innermost
  // member or element, to name the object or array itself.
  std::string path(bool container = false) const;
  [[noreturn]] void fail(const std::string& what, bool container = false) const;  // "<path>: what"
  [[noreturn]] void syntax(const std::string& what) const;  // "<line>:<column>: invalid JSON: what"

 private:
  struct Frame {
    bool object = false;
    bool inside = false;         // a member or element is being read
    std::size_t count = 0;       // members or elements started so far
    std::string key;             // current member's key (objects)
    std::set<std::string> keys;  // keys seen (objects), to reject duplicates
  };
  void space();
  bool eat(char c);
  bool digits();
  void open(char c, bool object);
  bool close(char c, const char* after);
  std::string read_string();
  unsigned hex4();
  std::size_t utf8_sequence() const;

  std::string_view text_;
  std::size_t max_depth_;
  std::size_t pos_ = 0;
  std::vector<Frame> stack_;
};

}  // namespace wrenchkit_checker::detail
