// proofs/checker/json.cpp - strict JSON pull reader (see json.h).
#include "proofs/checker/json.h"

#include <algorithm>

namespace wrenchkit_checker::detail {

std::string escape(std::string_view s) {
  static const char hex[] = "0123456789abcdef";
  std::string out = "\"";
  for (const char ch : s) {
    const unsigned char c = static_cast<unsigned char>(ch);
    if (c == '"' || c == '\\')
      out += {'\\', ch};
    else if (c < 0x20 || c == 0x7F)
      out += {'\\', 'u', '0', '0', hex[c >> 4], hex[c & 15]};
    else
      out += ch;
  }
  return out + "\"";
}

std::string quote(std::string_view s) {
  std::size_t n = std::min<std::size_t>(s.size(), 40);
  while (n < s.size() && n > 0 && (static_cast<unsigned char>(s[n]) & 0xC0) == 0x80) --n;  // between characters
  return escape(s.substr(0, n)) + (n < s.size() ? "..." : "");
}

void Reader::space() {
  while (pos_ < text_.size() &&
         (text_[pos_] == ' ' || text_[pos_] == '\t' || text_[pos_] == '\n' || text_[pos_] == '\r'))
    ++pos_;
}

namespace {

// The bytes a string holds as they are (printable ASCII but '"' and '\\'): one table look-up per byte.
struct Plain_bytes {
  bool plain[256];
  constexpr Plain_bytes() : plain() {
    for (int c = 0x20; c < 0x80; ++c) plain[c] = c != '"' && c != '\\';
  }
  bool operator()(char c) const { return plain[static_cast<unsigned char>(c)]; }
};
constexpr Plain_bytes is_plain;

}  // namespace

bool Reader::eat(char c) { return pos_ < text_.size() && text_[pos_] == c ? (++pos_, true) : false; }

bool Reader::digits() {
  const std::size_t begin = pos_;
  while (pos_ < text_.size() && text_[pos_] >= '0' && text_[pos_] <= '9') ++pos_;
  return pos_ > begin;
}

Reader::Kind Reader::peek() {
  space();
  if (pos_ == text_.size()) syntax("unexpected end of input");
  const char c = text_[pos_];
  switch (c) {
    case '{': return Kind::object;
    case '[': return Kind::array;
    case '"': return Kind::string;
    case 't':
    case 'f': return Kind::boolean;
    case 'n': return Kind::null;
    default: break;
  }
  if (c == '-' || (c >= '0' && c <= '9')) return Kind::number;
  const unsigned char u = static_cast<unsigned char>(c);
  if (u > 0x20 && u < 0x7F) syntax(std::string("unexpected character '") + c + "'");
  static const char hex[] = "0123456789abcdef";
  syntax(std::string("unexpected byte 0x") + hex[u >> 4] + hex[u & 15]);
}

void Reader::open(char c, bool object) {
  space();
  if (pos_ >= text_.size() || text_[pos_] != c) syntax(std::string("expected '") + c + "'");
  if (depth_ >= max_depth_) syntax("nested deeper than " + std::to_string(max_depth_) + " levels");
  ++pos_;
  if (depth_ == stack_.size()) stack_.emplace_back();
  Frame& f = stack_[depth_++];
  f.object = object, f.inside = false, f.count = 0;
  if (!f.many.empty()) f.many.clear();
}

void Reader::begin_object() { open('{', true); }
void Reader::begin_array() { open('[', false); }

// Moves to the next member or element of the innermost container; false (container closed) at c.
bool Reader::close(char c, const char* after) {
  Frame& f = top();
  f.inside = false;
  space();
  const bool comma = f.count > 0 && eat(',');
  if (!comma && eat(c)) {  // the closing bracket, not after a comma
    --depth_;
    return false;
  }
  if (f.count > 0 && !comma) syntax(std::string("expected ',' or '") + c + "' after " + after);
  space();
  return true;
}

bool Reader::next_key(std::string_view& key) {
  if (!close('}', "an object member")) return false;
  Frame& f = top();
  if (pos_ >= text_.size() || text_[pos_] != '"') syntax("expected a string as object key");
  key = read_string_view();
  space();
  if (!eat(':')) syntax("expected ':' after an object key");
  bool duplicate = false;
  if (f.count < Frame::kFewKeys) {
    for (std::size_t k = 0; k < f.count && !duplicate; ++k) duplicate = f.few[k] == key;
    if (!duplicate) f.few[f.count] = key;
  } else {
    if (f.many.empty()) f.many.insert(f.few, f.few + Frame::kFewKeys);
    duplicate = !f.many.insert(key).second;
  }
  if (duplicate) fail("duplicate key " + quote(key));
  f.key = key;
  f.inside = true, ++f.count;
  return true;
}

bool Reader::next_item() {
  if (!close(']', "an array element")) return false;
  top().inside = true, ++top().count;
  return true;
}

std::string Reader::string() {
  space();
  if (pos_ >= text_.size() || text_[pos_] != '"') syntax("expected a string");
  std::string out;
  read_string(out);
  return out;
}

std::string_view Reader::string_view() {
  space();
  if (pos_ >= text_.size() || text_[pos_] != '"') syntax("expected a string");
  return read_string_view();
}

std::string_view Reader::read_string_view() {
  const std::size_t begin = pos_ + 1;
  std::size_t end = begin;  // plain ASCII up to the closing quote: the text itself
  while (end < text_.size() && is_plain(text_[end])) ++end;
  if (end < text_.size() && text_[end] == '"') {
    pos_ = end + 1;
    return text_.substr(begin, end - begin);
  }
  read_string(scratch_);  // validated and decoded
  // Without an escape the decoded string is the text between the quotes (UTF-8 is copied as is).
  if (pos_ - 1 - begin == scratch_.size()) return text_.substr(begin, scratch_.size());
  decoded_.push_back(scratch_);
  return decoded_.back();
}

// The length of the well-formed UTF-8 sequence at pos_ (Unicode Table 3-7), or 0.
std::size_t Reader::utf8_sequence() const {
  auto byte = [this](std::size_t k) -> unsigned {
    return pos_ + k < text_.size() ? static_cast<unsigned char>(text_[pos_ + k]) : 0u;
  };
  const unsigned c = byte(0);
  const std::size_t n = c >= 0xC2 && c <= 0xDF ? 2 : c >= 0xE0 && c <= 0xEF ? 3 : c >= 0xF0 && c <= 0xF4 ? 4 : 0;
  if (n == 0) return 0;
  // range of the second byte: no overlong forms (E0, F0), no surrogates D800-DFFF (ED), nothing above U+10FFFF (F4)
  const unsigned lo = c == 0xE0 ? 0xA0 : c == 0xF0 ? 0x90 : 0x80, hi = c == 0xED ? 0x9F : c == 0xF4 ? 0x8F : 0xBF;
  if (byte(1) < lo || byte(1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k)
    if ((byte(k) & 0xC0) != 0x80) return 0;
  return n;
}

unsigned Reader::hex4() {
  unsigned v = 0;
  for (int k = 0; k < 4; ++k, ++pos_) {
    const char c = pos_ < text_.size() ? text_[pos_] : '\0';
    const bool dec = c >= '0' && c <= '9', lower = c >= 'a' && c <= 'f', upper = c >= 'A' && c <= 'F';
    if (!dec && !lower && !upper) syntax("expected four hex digits after \\u");
    v = v * 16 + static_cast<unsigned>(dec ? c - '0' : lower ? c - 'a' + 10 : c - 'A' + 10);
  }
  return v;
}

void Reader::read_string(std::string& out) {
  ++pos_;  // the opening quote, checked by the caller
  out.clear();
  for (;;) {
    if (pos_ >= text_.size()) syntax("unterminated string");
    const unsigned char c = static_cast<unsigned char>(text_[pos_]);
    if (c == '"') return void(++pos_);
    if (c >= 0x20 && c < 0x80 && c != '\\') {  // a run of plain ASCII, copied at once
      std::size_t end = pos_ + 1;
      while (end < text_.size() && is_plain(text_[end])) ++end;
      out.append(text_.data() + pos_, end - pos_);
      pos_ = end;
      continue;
    }
    if (c < 0x20) syntax("unescaped control character in a string");
    if (c >= 0x80) {
      const std::size_t n = utf8_sequence();
      if (n == 0) syntax("invalid UTF-8");
      out.append(text_.substr(pos_, n)), pos_ += n;
      continue;
    }
    ++pos_;
    if (c != '\\') {
      out += static_cast<char>(c);
      continue;
    }
    const char e = pos_ < text_.size() ? text_[pos_++] : '\0';
    switch (e) {
      case '"':
      case '\\':
      case '/': out += e; continue;
      case 'b': out += '\b'; continue;
      case 'f': out += '\f'; continue;
      case 'n': out += '\n'; continue;
      case 'r': out += '\r'; continue;
      case 't': out += '\t'; continue;
      case 'u': break;
      default: --pos_; syntax("invalid escape in a string");
    }
    unsigned cp = hex4();
    if (cp >= 0xDC00 && cp <= 0xDFFF) syntax("lone surrogate in a \\u escape");
    if (cp >= 0xD800 && cp <= 0xDBFF) {  // must be followed by the low half of the pair
      if (!eat('\\') || !eat('u')) syntax("lone surrogate in a \\u escape");
      const unsigned low = hex4();
      if (low < 0xDC00 || low > 0xDFFF) syntax("lone surrogate in a \\u escape");
      cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
    }
    if (cp < 0x80) {  // UTF-8: 1 to 4 bytes
      out += static_cast<char>(cp);
      continue;
    }
    static const unsigned lead[] = {0, 0xC0, 0xE0, 0xF0};  // 110xxxxx, 1110xxxx, 11110xxx
    const int tail = cp < 0x800 ? 1 : cp < 0x10000 ? 2 : 3;
    out += static_cast<char>(lead[tail] | (cp >> (6 * tail)));
    for (int k = tail - 1; k >= 0; --k) out += static_cast<char>(0x80 | ((cp >> (6 * k)) & 0x3F));
  }
}

// number := '-'? ('0' | [1-9][0-9]*) ('.' [0-9]+)? ([eE] [+-]? [0-9]+)?
std::string_view Reader::number() {
  space();
  const std::size_t begin = pos_;
  eat('-');
  if (!eat('0')) {
    if (pos_ >= text_.size() || text_[pos_] < '1' || text_[pos_] > '9') syntax("invalid number");
    digits();
  }
  if (eat('.') && !digits()) syntax("expected a digit after '.' in a number");
  if (eat('e') || eat('E')) {
    if (!eat('+')) eat('-');
    if (!digits()) syntax("expected a digit in the exponent of a number");
  }
  return text_.substr(begin, pos_ - begin);
}

bool Reader::boolean() {
  space();
  if (text_.substr(pos_, 4) == "true") return pos_ += 4, true;
  if (text_.substr(pos_, 5) != "false") syntax("invalid literal");
  return pos_ += 5, false;
}

// Iterative, so that the depth limit, not the call stack, bounds nesting.
void Reader::skip() {
  const std::size_t base = depth_;
  std::string_view key;
  for (;;) {
    switch (peek()) {
      case Kind::object: begin_object(); break;
      case Kind::array: begin_array(); break;
      case Kind::string: read_string(scratch_); break;
      case Kind::number: number(); break;
      case Kind::boolean: boolean(); break;
      case Kind::null:
        if (text_.substr(pos_, 4) != "null") syntax("invalid literal");
        pos_ += 4;
        break;
    }
    for (;;) {  // close finished containers until the next value to read, or the end of this one
      if (depth_ == base) return;
      if (top().object ? next_key(key) : next_item()) break;
    }
  }
}

void Reader::finish() {
  space();
  if (pos_ != text_.size()) syntax("unexpected data after the JSON value");
}

std::string Reader::path(bool container) const {
  std::string p;
  const std::size_t n = depth_ - (container && depth_ > 0 ? 1 : 0);
  for (std::size_t i = 0; i < n && stack_[i].inside; ++i) {
    const Frame& f = stack_[i];
    if (!f.object) {
      p += "[" + std::to_string(f.count - 1) + "]";
      continue;
    }
    const std::string_view key = f.key;
    bool plain = !key.empty();
    for (const char c : key)
      plain = plain && ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_');
    p += plain ? (p.empty() ? "" : ".") + std::string(key) : "[" + quote(key) + "]";
  }
  return p;
}

void Reader::fail(const std::string& what, bool container) const {
  const std::string p = path(container);
  throw Failure{p.empty() ? what : p + ": " + what};
}

void Reader::syntax(const std::string& what) const {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < pos_ && i < text_.size(); ++i) column = text_[i] == '\n' ? (++line, 1) : column + 1;
  throw Failure{std::to_string(line) + ":" + std::to_string(column) + ": invalid JSON: " + what};
}

}  // namespace wrenchkit_checker::detail
