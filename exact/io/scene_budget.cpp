#include "exact/io/scene_budget.h"

#include <cstddef>
#include <string>

#include "exact/io/input_error.h"
#include "exact/io/json.h"
#include "exact/numbers/rational.h"

namespace wrenchkit {
namespace {

// Where a value stands in the scene format (docs/scene-format.md "Keys"): only these places are walked,
// every other value is skipped without looking inside.
enum class Place {
  other,     // not a place of the format: skipped
  root,      // {"wrenchkit", "body", "contacts", "load", "support", …}
  number,    // a number: counted
  numbers,   // an array of numbers ([x, y], [fx, fy, m])
  body,      // {"outline", "com"}
  outline,   // an array of points
  contacts,  // an array of contacts (entries)
  contact,   // {"at", "normal", "mu", "wrench"}
  load,      // {"force", "at", "wrench", "gravity"}
  support,   // {"mu", "weight", "pressure_center", "points", "regions"}
  points,    // an array of support points (entries)
  point,     // {"at", "force", "mu"}
  regions,   // an array of support regions (not entries: their rings are bounded by --max-region-vertices)
  region,    // {"outline", "holes", "pressure", "force", "mu"}
  holes,     // an array of rings (each as an outline)
  pressure,  // {"linear": [a, b, c]} (the string "uniform" holds no number)
};

bool is_object(Place p) {
  return p == Place::root || p == Place::body || p == Place::contact || p == Place::load || p == Place::support ||
         p == Place::point || p == Place::region || p == Place::pressure;
}

Place member(Place object, std::string_view key) {
  switch (object) {
    case Place::root:
      return key == "wrenchkit" || key == "mu" ? Place::number
             : key == "body"     ? Place::body
             : key == "contacts" ? Place::contacts
             : key == "load"     ? Place::load
             : key == "support"  ? Place::support
             : key == "pusher"   ? Place::contact  // (with its "velocity", below)
                                 : Place::other;
    case Place::body: return key == "outline" ? Place::outline : key == "com" ? Place::numbers : Place::other;
    case Place::contact:
      return key == "at" || key == "normal" || key == "wrench" || key == "velocity" ? Place::numbers
             : key == "mu" || key == "omega"                   ? Place::number
             : key == "segment"                                ? Place::outline  // (a line pusher's two points)
                                                               : Place::other;
    case Place::load:
      return key == "force" || key == "at" || key == "wrench" ? Place::numbers
             : key == "gravity"                               ? Place::number
                                                              : Place::other;
    case Place::support:
      return key == "mu" || key == "weight" ? Place::number
             : key == "pressure_center"     ? Place::numbers
             : key == "points"              ? Place::points
             : key == "regions"             ? Place::regions
                                            : Place::other;
    case Place::point:
      return key == "at" ? Place::numbers : key == "force" || key == "mu" ? Place::number : Place::other;
    case Place::region:
      return key == "outline"                 ? Place::outline
             : key == "holes"                 ? Place::holes
             : key == "pressure"              ? Place::pressure
             : key == "force" || key == "mu" ? Place::number
                                              : Place::other;
    case Place::pressure: return key == "linear" ? Place::numbers : Place::other;
    default: return Place::other;
  }
}

Place item(Place array) {
  switch (array) {
    case Place::numbers: return Place::number;
    case Place::outline: return Place::numbers;
    case Place::contacts: return Place::contact;
    case Place::points: return Place::point;
    case Place::regions: return Place::region;
    case Place::holes: return Place::outline;
    default: return Place::other;
  }
}

struct Stop {};  // the text is not JSON here: the measures so far stand

class Walker {
 public:
  Walker(std::string_view s, const Input_limits& limits) : s_(s), limits_(limits) {}

  Budget_tally run() {
    try {
      value(Place::root);
    } catch (const Stop&) {
    }
    return tally_;
  }

 private:
  std::string_view s_;
  const Input_limits& limits_;
  std::size_t i_ = 0;
  Budget_tally tally_;
  std::string decoded_;

  int peek() {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\n' || s_[i_] == '\r')) ++i_;
    if (i_ >= s_.size()) throw Stop{};
    return static_cast<unsigned char>(s_[i_]);
  }

  // A string's value: a view of the text when it is plain ASCII without escapes, else decoded by json.cpp.
  std::string_view string() {
    try {
      return json::string_view_at(s_, i_, decoded_, limits_, "scene");
    } catch (const Input_error&) {
      throw Stop{};
    }
  }

  void count(std::string_view text, bool json_number) {
    std::size_t d = 0;
    if (!number_digits(text, json_number, limits_, d)) return;
    tally_.total = tally_.total + d < tally_.total ? static_cast<std::size_t>(-1) : tally_.total + d;
    if (d > tally_.longest) tally_.longest = d;
  }

  // Any value, without looking inside: strings and brackets only (no recursion).
  void skip() {
    std::size_t depth = 0;
    do {
      const int c = peek();
      if (c == '"') {
        for (++i_; i_ < s_.size() && s_[i_] != '"'; ++i_)
          if (s_[i_] == '\\') ++i_;
        if (i_ >= s_.size()) throw Stop{};
        ++i_;
      } else if (c == '{' || c == '[') {
        ++depth, ++i_;
      } else if (c == '}' || c == ']') {
        if (depth == 0) throw Stop{};
        --depth, ++i_;
      } else if (c == ',' || c == ':') {
        if (depth == 0) throw Stop{};
        ++i_;
      } else {  // a number or a literal: up to the next delimiter
        const std::size_t start = i_;
        while (i_ < s_.size() && s_[i_] != ',' && s_[i_] != '}' && s_[i_] != ']' && s_[i_] != ' ' &&
               s_[i_] != '\t' && s_[i_] != '\n' && s_[i_] != '\r' && s_[i_] != '"' && s_[i_] != '{' && s_[i_] != '[')
          ++i_;
        if (i_ == start) throw Stop{};
      }
    } while (depth > 0);
  }

  void value(Place p) {
    const int c = peek();
    if (p == Place::number && c == '"') {
      const std::string_view text = string();
      count(text, false);
    } else if (p == Place::number && (c == '-' || (c >= '0' && c <= '9'))) {
      const std::size_t start = i_;
      if (!json::skip_number(s_, i_)) throw Stop{};
      count(s_.substr(start, i_ - start), true);
    } else if (c == '{' && is_object(p)) {
      ++i_;
      bool mu = false, wrench = false;  // a contact without both: a point contact whose mu is "0"
      const auto close = [&] {
        if (p == Place::contact && !mu && !wrench) count("0", true);
      };
      if (peek() == '}') {
        ++i_;
        return close();
      }
      for (;;) {
        if (peek() != '"') throw Stop{};
        const std::string_view key = string();
        mu |= key == "mu";
        wrench |= key == "wrench";
        const Place m = member(p, key);  // the key view lives until the next string: used at once
        if (peek() != ':') throw Stop{};
        ++i_;
        value(m);
        const int d = peek();
        ++i_;
        if (d == '}') return close();
        if (d != ',') throw Stop{};
      }
    } else if (c == '[' && item(p) != Place::other) {
      ++i_;
      if (peek() == ']') return void(++i_);
      const Place q = item(p);
      for (;;) {
        if (p == Place::contacts || p == Place::points) ++tally_.entries;
        value(q);
        const int d = peek();
        ++i_;
        if (d == ']') return;
        if (d != ',') throw Stop{};
      }
    } else {
      skip();
    }
  }
};

}  // namespace

Budget_tally measure_scene(std::string_view json_text, const Input_limits& limits) {
  return Walker(json_text, limits).run();
}

std::string budget_problem(const Budget_tally& m, const Input_limits& l) {
  if (m.total > l.max_total_digits)
    return "scene: its numbers have " + std::to_string(m.total) + " digits in all, more than the budget of " +
           std::to_string(l.max_total_digits) + " (--max-total-digits)";
  if (m.digits_times_contacts() > l.max_digits_times_contacts)
    return "scene: its longest number has " + std::to_string(m.longest) + " digits and it has " +
           std::to_string(m.entries) + " contacts and support points, " + std::to_string(m.digits_times_contacts()) +
           " digits times contacts, more than the budget of " + std::to_string(l.max_digits_times_contacts) +
           " (--max-digits-times-contacts)";
  return std::string();
}

}  // namespace wrenchkit
