#include "exact/io/json.h"

#include <cstdint>
#include <unordered_set>

#include "exact/io/input_error.h"
#include "exact/io/json_writer.h"

namespace wrenchkit::json {
namespace {

class Parser {
 public:
  Parser(std::string_view s, const Input_limits& limits, std::string_view source)
      : s_(s), limits_(limits), source_(source) {}

  Value document() {
    Value v = value(0);
    skip_ws();
    if (i_ != s_.size()) fail("unexpected data after the JSON value");
    return v;
  }

  std::string string_at(std::size_t& pos) {
    i_ = pos;
    std::string out = string();
    pos = i_;
    return out;
  }

 private:
  std::string_view s_;
  const Input_limits& limits_;
  std::string_view source_;
  std::size_t i_ = 0;

  [[noreturn]] void fail(const std::string& what) const {
    std::size_t line = 1, col = 1;
    for (std::size_t k = 0; k < i_ && k < s_.size(); ++k) {
      if (s_[k] == '\n') {
        ++line;
        col = 1;
      } else {
        ++col;
      }
    }
    throw Input_error(std::string(source_) + ":" + std::to_string(line) + ":" +
                      std::to_string(col) + ": invalid JSON: " + what);
  }

  void skip_ws() {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\n' || s_[i_] == '\r'))
      ++i_;
  }

  bool literal(std::string_view word) {
    if (s_.substr(i_, word.size()) == word) {
      i_ += word.size();
      return true;
    }
    return false;
  }

  Value value(std::size_t depth) {
    skip_ws();
    if (i_ >= s_.size()) fail("unexpected end of input, expected a value");
    Value v;
    const char c = s_[i_];
    if (c == '{' || c == '[') {
      if (depth >= limits_.max_depth)
        fail("nesting deeper than " + std::to_string(limits_.max_depth) + " levels");
      return c == '{' ? object(depth + 1) : array(depth + 1);
    }
    if (c == '"') {
      v.type = Type::string;
      v.text = string();
      return v;
    }
    if (c == '-' || (c >= '0' && c <= '9')) {
      v.type = Type::number;
      v.text = number();
      return v;
    }
    if (literal("true")) {
      v.type = Type::boolean;
      v.boolean = true;
      return v;
    }
    if (literal("false")) {
      v.type = Type::boolean;
      return v;
    }
    if (literal("null")) return v;
    fail("unexpected character, expected a value");
  }

  Value object(std::size_t depth) {
    Value v;
    v.type = Type::object;
    std::unordered_set<std::string> seen;  // keys, once the object has 16 members
    v.members.reserve(4);                   // scene objects are small: one allocation
    ++i_;  // {
    skip_ws();
    if (i_ < s_.size() && s_[i_] == '}') {
      ++i_;
      return v;
    }
    for (;;) {
      skip_ws();
      if (i_ >= s_.size() || s_[i_] != '"') fail("expected a string key");
      const std::size_t key_pos = i_;
      std::string key = string();
      // Duplicate keys: a linear scan while the object is small, a hash set beyond (O(1) each).
      bool duplicate = false;
      if (v.members.size() < 16) {
        for (const auto& m : v.members) duplicate |= m.first == key;
      } else {
        if (seen.empty())
          for (const auto& m : v.members) seen.insert(m.first);
        duplicate = !seen.insert(key).second;
      }
      if (duplicate) {
        i_ = key_pos;
        fail("duplicate key " + quote(key));
      }
      skip_ws();
      if (i_ >= s_.size() || s_[i_] != ':') fail("expected ':' after an object key");
      ++i_;
      Value member = value(depth);
      v.members.emplace_back(std::move(key), std::move(member));
      skip_ws();
      if (i_ < s_.size() && s_[i_] == ',') {
        ++i_;
        continue;
      }
      if (i_ < s_.size() && s_[i_] == '}') {
        ++i_;
        return v;
      }
      fail("expected ',' or '}' after an object member");
    }
  }

  Value array(std::size_t depth) {
    Value v;
    v.type = Type::array;
    v.items.reserve(3);  // points and wrenches: one allocation
    ++i_;  // [
    skip_ws();
    if (i_ < s_.size() && s_[i_] == ']') {
      ++i_;
      return v;
    }
    for (;;) {
      v.items.push_back(value(depth));
      skip_ws();
      if (i_ < s_.size() && s_[i_] == ',') {
        ++i_;
        continue;
      }
      if (i_ < s_.size() && s_[i_] == ']') {
        ++i_;
        return v;
      }
      fail("expected ',' or ']' after an array element");
    }
  }

  std::string number() {
    const std::size_t start = i_;
    if (!skip_number(s_, i_)) fail("malformed number");
    return std::string(s_.substr(start, i_ - start));
  }

  unsigned hex4() {
    if (i_ + 4 > s_.size()) fail("truncated \\u escape");
    unsigned u = 0;
    for (int k = 0; k < 4; ++k) {
      const char c = s_[i_++];
      u <<= 4;
      if (c >= '0' && c <= '9') u |= unsigned(c - '0');
      else if (c >= 'a' && c <= 'f') u |= unsigned(c - 'a' + 10);
      else if (c >= 'A' && c <= 'F') u |= unsigned(c - 'A' + 10);
      else fail("invalid \\u escape");
    }
    return u;
  }

  static void put_utf8(std::string& out, std::uint32_t cp) {
    if (cp < 0x80) {
      out += char(cp);
    } else if (cp < 0x800) {
      out += char(0xC0 | (cp >> 6));
      out += char(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
      out += char(0xE0 | (cp >> 12));
      out += char(0x80 | ((cp >> 6) & 0x3F));
      out += char(0x80 | (cp & 0x3F));
    } else {
      out += char(0xF0 | (cp >> 18));
      out += char(0x80 | ((cp >> 12) & 0x3F));
      out += char(0x80 | ((cp >> 6) & 0x3F));
      out += char(0x80 | (cp & 0x3F));
    }
  }

  // One UTF-8 sequence starting at i_ (first byte >= 0x80), validated and copied.
  void utf8(std::string& out) {
    const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s_[k]); };
    const unsigned char c = b(i_);
    std::size_t len;
    std::uint32_t cp;
    if (c >= 0xC2 && c <= 0xDF) { len = 2; cp = c & 0x1F; }
    else if (c >= 0xE0 && c <= 0xEF) { len = 3; cp = c & 0x0F; }
    else if (c >= 0xF0 && c <= 0xF4) { len = 4; cp = c & 0x07; }
    else fail("invalid UTF-8");
    if (i_ + len > s_.size()) fail("invalid UTF-8");
    for (std::size_t k = 1; k < len; ++k) {
      if ((b(i_ + k) & 0xC0) != 0x80) fail("invalid UTF-8");
      cp = (cp << 6) | (b(i_ + k) & 0x3F);
    }
    if ((len == 3 && cp < 0x800) || (len == 4 && (cp < 0x10000 || cp > 0x10FFFF)) ||
        (cp >= 0xD800 && cp <= 0xDFFF))
      fail("invalid UTF-8");
    out.append(s_.substr(i_, len));
    i_ += len;
  }

  std::string string() {
    ++i_;  // opening quote
    std::string out;
    for (;;) {
      if (i_ >= s_.size()) fail("unterminated string");
      const char c = s_[i_];
      if (c == '"') {
        ++i_;
        return out;
      }
      if (static_cast<unsigned char>(c) < 0x20) fail("control character in a string");
      if (static_cast<unsigned char>(c) >= 0x80) {
        utf8(out);
        continue;
      }
      if (c != '\\') {
        out += c;
        ++i_;
        continue;
      }
      ++i_;
      if (i_ >= s_.size()) fail("unterminated string");
      const char e = s_[i_++];
      switch (e) {
        case '"': out += '"'; break;
        case '\\': out += '\\'; break;
        case '/': out += '/'; break;
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'n': out += '\n'; break;
        case 'r': out += '\r'; break;
        case 't': out += '\t'; break;
        case 'u': {
          std::uint32_t cp = hex4();
          if (cp >= 0xDC00 && cp <= 0xDFFF) fail("lone low surrogate in \\u escape");
          if (cp >= 0xD800 && cp <= 0xDBFF) {
            if (i_ + 2 > s_.size() || s_[i_] != '\\' || s_[i_ + 1] != 'u')
              fail("lone high surrogate in \\u escape");
            i_ += 2;
            const std::uint32_t lo = hex4();
            if (lo < 0xDC00 || lo > 0xDFFF) fail("lone high surrogate in \\u escape");
            cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
          }
          put_utf8(out, cp);
          break;
        }
        default: fail("invalid escape in a string");
      }
    }
  }
};

}  // namespace

const char* type_name(Type t) {
  switch (t) {
    case Type::null: return "null";
    case Type::boolean: return "a boolean";
    case Type::number: return "a number";
    case Type::string: return "a string";
    case Type::array: return "an array";
    case Type::object: return "an object";
  }
  return "?";
}

Value parse(std::string_view text, const Input_limits& limits, std::string_view source) {
  return Parser(text, limits, source).document();
}

bool skip_number(std::string_view s, std::size_t& i) {
  auto digit = [&](std::size_t k) { return k < s.size() && s[k] >= '0' && s[k] <= '9'; };
  if (i < s.size() && s[i] == '-') ++i;
  if (!digit(i)) return false;
  if (s[i] == '0') {
    ++i;
  } else {
    while (digit(i)) ++i;
  }
  if (i < s.size() && s[i] == '.') {
    ++i;
    if (!digit(i)) return false;
    while (digit(i)) ++i;
  }
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    if (!digit(i)) return false;
    while (digit(i)) ++i;
  }
  return true;
}

std::string decode_string(std::string_view text, std::size_t& pos, const Input_limits& limits,
                          std::string_view source) {
  return Parser(text, limits, source).string_at(pos);
}

std::string_view string_view_at(std::string_view text, std::size_t& pos, std::string& scratch,
                                const Input_limits& limits, std::string_view source) {
  for (std::size_t i = pos + 1; i < text.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c == '"') {
      const std::string_view value = text.substr(pos + 1, i - pos - 1);
      pos = i + 1;
      return value;
    }
    if (c == '\\' || c < 0x20 || c >= 0x80) break;
  }
  scratch = decode_string(text, pos, limits, source);  // escapes, non-ASCII, or unterminated (it throws)
  return scratch;
}

void append_quoted(std::string& out, std::string_view s) {
  out += '"';
  std::size_t plain = 0;  // start of the run of bytes copied as they are
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (c != '"' && c != '\\' && static_cast<unsigned char>(c) >= 0x20) continue;
    out.append(s.data() + plain, i - plain);
    plain = i + 1;
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      case '\b': out += "\\b"; break;
      case '\f': out += "\\f"; break;
      default: {
        static const char* hex = "0123456789abcdef";
        out += "\\u00";
        out += hex[(c >> 4) & 0xF];
        out += hex[c & 0xF];
      }
    }
  }
  out.append(s.data() + plain, s.size() - plain);
  out += '"';
}

std::string quote(std::string_view s) {
  std::string out;
  out.reserve(s.size() + 2);
  append_quoted(out, s);
  return out;
}

namespace {
void write_value(Json_writer& w, const Value& v) {
  switch (v.type) {
    case Type::null: w.null(); break;
    case Type::boolean: w.boolean(v.boolean); break;
    case Type::number: w.raw(v.text); break;
    case Type::string: w.string(v.text); break;
    case Type::array:
      w.array();
      for (const Value& x : v.items) write_value(w, x);
      w.end_array();
      break;
    case Type::object:
      w.object();
      for (const auto& [k, x] : v.members) write_value(w.key(k), x);
      w.end_object();
      break;
  }
}
}  // namespace

std::string text_of(const Value& v) {
  Json_writer w;
  write_value(w, v);
  return w.take();
}

void for_each_object_line(std::string_view text, const Input_limits& limits, const std::string& source,
                          std::string_view what,
                          const std::function<void(std::size_t line, const std::string& where, std::string_view raw, Value& object)>& fn) {
  std::size_t start = 0, line = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    ++line;
    std::string_view l = text.substr(start, end - start);
    start = end + 1;
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    if (l.find_first_not_of(" \t") == std::string_view::npos) continue;
    const std::string where = source + ":" + std::to_string(line);
    Value v;
    try {
      v = parse(l, limits, source);
    } catch (const Input_error& x) {  // "SOURCE:1:COL: invalid JSON: …" → "SOURCE:LINE:COL: …"
      std::string m = x.what();
      const std::string prefix = source + ":1:";
      if (m.compare(0, prefix.size(), prefix) == 0) m = where + ":" + m.substr(prefix.size());
      throw Input_error(m);
    }
    if (v.type != Type::object)
      throw Input_error(where + ": " + std::string(what) + " must be a JSON object, not a " + type_name(v.type));
    fn(line, where, l, v);
  }
}

}  // namespace wrenchkit::json
