// proofs/checker/json.h - the checker's own strict JSON reader (RFC 8259), internal to the checker.
//
// A pull reader: the scene and certificate readers walk the document in order and ask for exactly
// the values they expect, so no tree is built and memory stays proportional to the kept text.
// Strictness: UTF-8 only (no BOM, no overlong forms, no encoded or escaped lone surrogates), no
// unescaped control characters, no duplicate keys, no trailing commas or trailing data, nesting at
// most `max_depth` containers deep. Nothing recurses, so no input can exhaust the stack.
// Speed: no allocation per value once a depth has been visited (its frame and key list are reused;
// strings without escapes are views of the text), and paths are built only for messages.
#pragma once

#include <cstddef>
#include <deque>
#include <string>
#include <string_view>
#include <unordered_set>
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

  Reader(std::string_view text, std::size_t max_depth) : text_(text), max_depth_(max_depth) { stack_.reserve(8); }  // a scene nests 5 deep

  Kind peek();  // kind of the next value; a syntax error if there is none
  void begin_object();
  // The next member's key (decoded; a view valid as long as the reader), or false (and the object is
  // closed) at '}'.
  bool next_key(std::string_view& key);
  void begin_array();
  bool next_item();           // true before each element, false (array closed) at ']'
  std::string string();       // a string value, decoded to UTF-8
  // The same string, validated alike, as a view: of the text itself when it has no escape (the usual
  // case, no copy), else of a decoded copy the reader keeps. Valid as long as the reader.
  std::string_view string_view();
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
    bool inside = false;    // a member or element is being read
    std::size_t count = 0;  // members or elements started so far
    std::string_view key;   // the current member's key (objects)
    // Keys seen (objects), to reject duplicates: few[0..count) compared one by one while there are at
    // most kFewKeys, then all of them in the hash set `many`.
    static constexpr std::size_t kFewKeys = 8;
    std::string_view few[kFewKeys];
    std::unordered_set<std::string_view> many;
  };
  void space();
  bool eat(char c);
  bool digits();
  void open(char c, bool object);
  bool close(char c, const char* after);
  void read_string(std::string& out);  // decoded into out (replaced)
  std::string_view read_string_view();  // decoded: a view of the text, or of a copy in decoded_
  unsigned hex4();
  std::size_t utf8_sequence() const;
  Frame& top() { return stack_[depth_ - 1]; }

  std::string_view text_;
  std::size_t max_depth_;
  std::size_t pos_ = 0;
  std::vector<Frame> stack_;  // stack_[0..depth_) are open; deeper frames are kept for reuse
  std::size_t depth_ = 0;
  std::string scratch_;               // a string being decoded
  std::deque<std::string> decoded_;   // string_view()'s decoded strings
};

// The next value, an object (an array): opened; else the failure `otherwise`, at its path.
template <class Message>
void begin_object(Reader& r, const Message& otherwise) {
  if (r.peek() != Reader::Kind::object) r.fail(otherwise);
  r.begin_object();
}
template <class Message>
void begin_array(Reader& r, const Message& otherwise) {
  if (r.peek() != Reader::Kind::array) r.fail(otherwise);
  r.begin_array();
}

// An array of exactly n values; item(k) reads the k-th.
template <class Item>
void read_fixed(Reader& r, std::size_t n, const std::string& what, Item item) {
  if (r.peek() != Reader::Kind::array) r.fail("expected " + what);
  r.begin_array();
  std::size_t k = 0;
  while (r.next_item()) {
    if (k == n) r.fail("expected " + what, true);
    item(k++);
  }
  if (k != n) r.fail("expected " + what);
}

}  // namespace wrenchkit_checker::detail
