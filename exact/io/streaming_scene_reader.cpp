#include "exact/io/streaming_scene_reader.h"

#include "exact/io/outline.h"
#include "exact/io/support_check.h"

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include "exact/io/input_error.h"
#include "exact/io/json.h"
#include "exact/io/region.h"
#include "exact/numbers/rational.h"

namespace wrenchkit {
namespace {

// Thrown (never outside this file) when the fast path does not accept the text: read_scene decides.
struct Defer {};

// Element k of v, reusing what is there (k ≤ v.size(): elements are visited in order).
template <class T>
T& slot(std::vector<T>& v, std::size_t k) {
  if (k == v.size()) {
    // A reallocation copies every element (Rational's move may allocate, so it is not noexcept and the
    // vector copies): room for 16 at once (a fixture's support points), then doubling.
    if (v.size() == v.capacity()) v.reserve(std::max<std::size_t>(16, 2 * v.capacity()));
    v.emplace_back();
  }
  return v[k];
}

void zero(Rational& q) {
  if (sgn(q) != 0) q = 0;
}

// A reused contact back to the state of a default-constructed one (no allocation).
void reset(Contact& c) {
  c.kind = Contact::Kind::point;
  for (Rational* q : {&c.at.x, &c.at.y, &c.normal.x, &c.normal.y, &c.mu, &c.wrench[0], &c.wrench[1], &c.wrench[2]})
    zero(*q);
  c.name.clear();
  c.edge.reset();
  c.twin = fl::Bounded_contact{};
  c.has_twin = false;
  c.exact_pending = c.from_doubles = false;
  for (std::string& t : c.number_text) t.clear();
  c.number_is_json.fill(false);
}

// A number's text: a JSON number token or a JSON string's decoded value.
struct Number_text {
  std::string_view text;
  bool json;
};

class Stream {
 public:
  Stream(std::string_view s, const Input_limits& limits, std::string_view source, bool lazy)
      : s_(s), limits_(limits), source_(source), lazy_(lazy) {}

  void scene(Scene& out) {
    if (s_.size() > limits_.max_file_bytes) defer();
    enum : unsigned {
      kVersion = 1, kName = 2, kBody = 4, kContacts = 8, kLoad = 16, kSupport = 32, kSceneMu = 64, kPusher = 128
    };
    unsigned seen = 0;
    std::size_t contacts = 0;
    int scene_mu_sign = 0;
    without_mu_.clear();
    out.name.clear();
    object(0, [&](std::string_view key) {
      const unsigned bit = key == "contacts" ? kContacts
                           : key == "wrenchkit" ? kVersion
                           : key == "name"      ? kName
                           : key == "body"      ? kBody
                           : key == "load"      ? kLoad
                           : key == "support"   ? kSupport
                           : key == "mu"        ? kSceneMu
                           : key == "pusher"    ? kPusher
                                                : 0u;
      if (bit == 0 || (seen & bit)) defer();  // unknown or duplicate key (a scene-wide "mu" too: read_scene_tree)
      seen |= bit;
      switch (bit) {
        case kVersion: version(); break;
        case kName: out.name.assign(string_value()); break;
        case kBody: body(out.body); break;
        case kContacts:
          array(1, [&](std::size_t k) {
            if (k >= limits_.max_contacts || !tally_.add_entry(limits_)) defer();
            Contact& c = slot(out.contacts, k);
            contact(c, 2);
            if (c.kind == Contact::Kind::point && !c.mu_given) without_mu_.push_back(k);
            contacts = k + 1;
          });
          break;
        case kLoad: load(out.load ? *out.load : out.load.emplace()); break;
        case kSupport: support(out.support ? *out.support : out.support.emplace()); break;
        case kPusher: {  // a point contact with its velocity (scene.cpp's pusher(): read eagerly)
          Pusher& p = out.pusher ? *out.pusher : out.pusher.emplace();
          if (!contact(p.contact, 2, &p)) defer();
          if (lazy_) p.contact = exact_contact(p.contact);
          break;
        }
        case kSceneMu:  // the scene-wide μ (read_scene_tree's message when negative)
          scene_mu_sign = contact_number(scene_mu_, 4, scene_mu_.mu, scene_mu_.twin.mu);
          if (scene_mu_sign < 0) defer();
          break;
      }
    });
    if (!(seen & kVersion)) defer();
    if (peek() != kEnd) defer();  // data after the scene
    out.mu.reset();
    if (seen & kSceneMu) {  // the scene's own, exact (a lazy reading kept its text)
      std::string why;
      if (!lazy_) out.mu = scene_mu_.mu;
      else if (!(out.mu = parse_rational(scene_mu_.number_text[4], scene_mu_.number_is_json[4], limits_, why))) defer();
    }
    if (seen & kSceneMu)  // every point contact without its own mu takes the scene's (wherever the key stood)
      for (const std::size_t k : without_mu_) {
        Contact& c = out.contacts[k];
        c.mu = scene_mu_.mu;
        c.twin.mu = scene_mu_.twin.mu;
        c.twin.frictional = scene_mu_sign != 0;
        c.number_text[4] = scene_mu_.number_text[4];
        c.number_is_json[4] = scene_mu_.number_is_json[4];
        c.mu_given = true;
      }
    if (!(seen & kPusher)) {
      out.pusher.reset();
    } else {
      Contact& c = out.pusher->contact;
      if (!c.mu_given && out.mu) c.mu = *out.mu, c.mu_given = true, c.twin.mu = to_bounded(*out.mu);
      c.twin.frictional = c.mu != 0;
      c.exact_pending = false;
      if (sgn(dot(out.pusher->velocity, c.normal)) <= 0) defer();  // read_scene_tree says why
      if (out.pusher->end && (is_zero(minus(*out.pusher->end, c.at)) || dot(minus(*out.pusher->end, c.at), c.normal) != 0))
        defer();  // (a line pusher: two ends, the normal perpendicular to its segment)
    }
    if (!(seen & kBody)) {
      out.body.outline.clear();
      out.body.com.reset();
      out.body.outline_ccw = true, out.body.outline_convex = false;
    }
    out.contacts.resize(contacts);
    if (!(seen & kLoad)) out.load.reset();
    else if (out.load->kind == Load::Kind::gravity && !out.body.com) defer();
    if (!(seen & kSupport)) out.support.reset();
    else if (!support_inadmissible(out).empty()) defer();  // read_scene_tree gives the reason
  }

 private:
  static constexpr int kEnd = -1;
  std::string_view s_;
  const Input_limits& limits_;
  std::string_view source_;
  bool lazy_;
  std::size_t i_ = 0;
  std::string why_;      // the number readers' reason (unused: any failure defers)
  Contact scene_mu_;                    // the scene-wide "mu", read into its mu slot as a contact's mu is
  std::vector<std::size_t> without_mu_;  // the point contacts without their own mu, in this scene
  Budget_tally tally_;   // [BUDGET] the scene's measures so far: over budget defers (read_scene_tree says why)
  std::string decoded_;  // a string with escapes or non-ASCII, decoded by json::decode_string

  [[noreturn]] static void defer() { throw Defer{}; }

  // The next character after whitespace (as json.cpp skips it), or kEnd.
  int peek() {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\n' || s_[i_] == '\r')) ++i_;
    return i_ < s_.size() ? static_cast<unsigned char>(s_[i_]) : kEnd;
  }

  void expect(char c) {
    if (peek() != static_cast<unsigned char>(c)) defer();
    ++i_;
  }

  // A container opened inside `level` others: json.cpp refuses it at level ≥ max_depth.
  void open(char c, std::size_t level) {
    if (level >= limits_.max_depth) defer();
    expect(c);
  }

  // {"key": value, …}: member(key) reads each value (the key view lives until the next string).
  template <class Member>
  void object(std::size_t level, Member member) {
    open('{', level);
    if (peek() == '}') {
      ++i_;
      return;
    }
    for (;;) {
      const std::string_view key = string_token();
      expect(':');
      member(key);
      const int c = peek();
      ++i_;
      if (c == ',') continue;
      if (c == '}') return;
      defer();
    }
  }

  // [value, …]: item(k) reads the k-th value.
  template <class Item>
  void array(std::size_t level, Item item) {
    open('[', level);
    if (peek() == ']') {
      ++i_;
      return;
    }
    for (std::size_t k = 0;; ++k) {
      item(k);
      const int c = peek();
      ++i_;
      if (c == ',') continue;
      if (c == ']') return;
      defer();
    }
  }

  // A JSON string's value: a view of the text when it has no escape and is ASCII, else decoded by
  // json.cpp (the one decoder; it throws Input_error on a malformed string, which defers).
  std::string_view string_token() {
    if (peek() != '"') defer();
    return json::string_view_at(s_, i_, decoded_, limits_, source_);
  }

  std::string_view string_value() { return string_token(); }

  // A JSON number token, by json.cpp's grammar.
  std::string_view number_token() {
    const std::size_t start = i_;
    if (!json::skip_number(s_, i_)) defer();
    return s_.substr(start, i_ - start);
  }

  // A scene number: a JSON number or a number string (docs/scene-format.md "Numbers").
  Number_text number_text() {
    const int c = peek();
    if (c == '"') return {string_token(), false};
    if (c == '-' || (c >= '0' && c <= '9')) return {number_token(), true};
    defer();
  }

  // An exact number (eager), with its certified double when `approx` is given.
  void exact(Rational& out, fl::Bounded* approx = nullptr) {
    const Number_text t = number_text();
    if (!parse_rational_into(t.text, t.json, limits_, why_, out, approx, &tally_)) defer();
  }

  void nonnegative(Rational& out, fl::Bounded* approx = nullptr) {
    exact(out, approx);
    if (sgn(out) < 0) defer();
  }

  // [x, y]
  void vec2(Vec2& v, std::size_t level) {
    open('[', level);
    exact(v.x);
    expect(',');
    exact(v.y);
    expect(']');
  }

  // [fx, fy, m]
  void wrench3(Vec3q& w, std::size_t level) {
    open('[', level);
    exact(w[0]);
    expect(',');
    exact(w[1]);
    expect(',');
    exact(w[2]);
    expect(']');
  }

  void version() {
    const Number_text t = number_text();
    fl::Bounded v;
    int sign = 0;
    // The certified double of an exact 1 is {1, 0}, and e = 0 means v is the exact value.
    if (!scan_number(t.text, t.json, limits_, why_, v, sign, &tally_) || v.v != 1.0 || v.e != 0) defer();
  }

  void body(Body& b) {
    enum : unsigned { kOutline = 1, kCom = 2 };
    unsigned seen = 0;
    std::size_t points = 0;
    object(1, [&](std::string_view key) {
      const unsigned bit = key == "outline" ? kOutline : key == "com" ? kCom : 0u;
      if (bit == 0 || (seen & bit)) defer();
      seen |= bit;
      if (bit == kOutline) {
        array(2, [&](std::size_t k) {
          if (k >= limits_.max_contacts) defer();
          vec2(slot(b.outline, k), 3);
          points = k + 1;
        });
      } else {
        vec2(b.com ? *b.com : b.com.emplace(), 2);
      }
    });
    b.outline.resize(points);
    if (!(seen & kCom)) b.com.reset();
  }

  // One number of a contact (slot: at x, at y, normal x, normal y, mu; wrench: fx, fy, m) into the
  // rational (eager) or the kept text (lazy), and its certified double; returns its exact sign.
  int contact_number(Contact& c, int slot, Rational& exact_out, fl::Bounded& approx) {
    if (!lazy_) {
      exact(exact_out, &approx);
      return sgn(exact_out);
    }
    const Number_text t = number_text();
    int sign = 0;
    if (!scan_number(t.text, t.json, limits_, why_, approx, sign, &tally_)) defer();
    c.number_text[static_cast<std::size_t>(slot)].assign(t.text);
    c.number_is_json[static_cast<std::size_t>(slot)] = t.json;
    return sign;
  }

  // [a, b] or [a, b, c] of contact numbers from `first_slot` on; true if all are zero.
  bool contact_numbers(Contact& c, std::size_t level, int first_slot, Rational* const* exact_out,
                       fl::Bounded* const* approx, int n) {
    open('[', level);
    bool all_zero = true;
    for (int k = 0; k < n; ++k) {
      if (k) expect(',');
      all_zero &= contact_number(c, first_slot + k, *exact_out[k], *approx[k]) == 0;
    }
    expect(']');
    return all_zero;
  }

  // A point contact {at, normal, mu?, name?} or a wrench generator {wrench, name?} (scene.cpp's
  // contact() and lazy_contact()); with `velocity`, the pusher's point contact and its "velocity" (required; false
  // for a wrench or without it).
  bool contact(Contact& c, std::size_t level, Pusher* pusher = nullptr) {
    reset(c);
    Vec2* velocity = pusher ? &pusher->velocity : nullptr;
    if (pusher) pusher->end.reset(), zero(pusher->omega);
    enum : unsigned { kAt = 1, kNormal = 2, kMu = 4, kWrench = 8, kName = 16, kVelocity = 32, kSegment = 64, kOmega = 128 };
    unsigned seen = 0;
    int mu_sign = 0;
    bool zero_normal = false, zero_wrench = false;
    object(level, [&](std::string_view key) {
      const unsigned bit = key == "at"       ? kAt
                           : key == "normal" ? kNormal
                           : key == "mu"     ? kMu
                           : key == "wrench" ? kWrench
                           : key == "name"   ? kName
                           : key == "velocity" && velocity ? kVelocity
                           : key == "segment" && pusher ? kSegment  // a line pusher: its first end is the contact's point
                           : key == "omega" && pusher ? kOmega
                                             : 0u;
      if (bit == 0 || (seen & bit)) defer();
      seen |= bit;
      if ((seen & kWrench) && (seen & (kAt | kNormal | kMu))) defer();  // a key of the other kind
      if ((seen & kSegment) && (seen & (kAt | kWrench))) defer();        // read_scene_tree says why
      switch (bit) {
        case kSegment: {
          open('[', level + 1);
          Rational* q[] = {&c.at.x, &c.at.y};
          fl::Bounded* b[] = {&c.twin.ax, &c.twin.ay};
          contact_numbers(c, level + 2, 0, q, b, 2);
          expect(',');
          vec2(pusher->end.emplace(), level + 2);
          expect(']');
          break;
        }
        case kOmega: exact(pusher->omega); break;
        case kAt: {
          Rational* q[] = {&c.at.x, &c.at.y};
          fl::Bounded* b[] = {&c.twin.ax, &c.twin.ay};
          contact_numbers(c, level + 1, 0, q, b, 2);
          break;
        }
        case kNormal: {
          Rational* q[] = {&c.normal.x, &c.normal.y};
          fl::Bounded* b[] = {&c.twin.nx, &c.twin.ny};
          zero_normal = contact_numbers(c, level + 1, 2, q, b, 2);
          break;
        }
        case kMu: mu_sign = contact_number(c, 4, c.mu, c.twin.mu); break;
        case kWrench: {
          Rational* q[] = {&c.wrench[0], &c.wrench[1], &c.wrench[2]};
          fl::Bounded* b[] = {&c.twin.fx, &c.twin.fy, &c.twin.m};
          zero_wrench = contact_numbers(c, level + 1, 0, q, b, 3);
          break;
        }
        case kName: c.name.assign(string_value()); break;
        case kVelocity: vec2(*velocity, level + 1); break;
      }
    });
    c.has_twin = true;
    c.exact_pending = lazy_;
    if (velocity && (!(seen & kVelocity) || (seen & kWrench))) return false;
    if ((seen & kOmega) && !(seen & kSegment)) defer();
    if (seen & kSegment) seen |= kAt;
    if (seen & kWrench) {
      if (zero_wrench) defer();
      c.kind = Contact::Kind::wrench;
      c.twin.is_wrench = true;
      return true;
    }
    if ((seen & (kAt | kNormal)) != (kAt | kNormal) || zero_normal || mu_sign < 0) defer();
    c.mu_given = (seen & kMu) != 0;
    if (!(seen & kMu) && !tally_.add_number(1, limits_)) defer();  // an absent mu counts as its "0"
    if (lazy_ && !(seen & kMu)) {  // lazy_contact() keeps "0" for an absent mu
      c.number_text[4] = "0";
      c.number_is_json[4] = true;
      c.twin.mu = fl::Bounded::exact(0);
    }
    c.twin.frictional = mu_sign != 0;
    return true;
  }

  // Exactly one of {"force", "at"}, {"wrench"}, {"gravity"} (scene.cpp's load(); gravity's body.com
  // is checked once the whole scene is read).
  void load(Load& l) {
    enum : unsigned { kForce = 1, kAt = 2, kWrench = 4, kGravity = 8 };
    unsigned seen = 0;
    for (Rational* q : {&l.force.x, &l.force.y, &l.at.x, &l.at.y, &l.wrench[0], &l.wrench[1], &l.wrench[2], &l.weight})
      zero(*q);
    object(1, [&](std::string_view key) {
      const unsigned bit = key == "force"     ? kForce
                           : key == "at"      ? kAt
                           : key == "wrench"  ? kWrench
                           : key == "gravity" ? kGravity
                                              : 0u;
      if (bit == 0 || (seen & bit)) defer();
      seen |= bit;
      switch (bit) {
        case kForce: vec2(l.force, 2); break;
        case kAt: vec2(l.at, 2); break;
        case kWrench: wrench3(l.wrench, 2); break;
        case kGravity: exact(l.weight); break;
      }
    });
    if (seen == kGravity) {
      if (sgn(l.weight) <= 0) defer();
      l.kind = Load::Kind::gravity;
    } else if (seen == kWrench) {
      l.kind = Load::Kind::wrench;
    } else if (seen == (kForce | kAt)) {
      l.kind = Load::Kind::force;
    } else {
      defer();
    }
  }

  // {"mu"?, "weight"?, "pressure_center"?, "points"?: [{"at", "force"?, "mu"?}, …], "regions"?: […]} (scene.cpp's
  // support()).
  void support(Support& s) {
    enum : unsigned { kMu = 1, kPoints = 2, kWeight = 4, kCenter = 8, kRegions = 16 };
    unsigned seen = 0;
    std::size_t points = 0, regions = 0, region_vertices = 0;
    bool any_force = false, any_without_mu = false, all_given = true;
    object(1, [&](std::string_view key) {
      const unsigned bit = key == "mu"                ? kMu
                           : key == "points"          ? kPoints
                           : key == "regions"         ? kRegions
                           : key == "weight"          ? kWeight
                           : key == "pressure_center" ? kCenter
                                                      : 0u;
      if (bit == 0 || (seen & bit)) defer();
      seen |= bit;
      if (bit == kMu) {
        nonnegative(s.mu ? *s.mu : s.mu.emplace());
        return;
      }
      if (bit == kWeight) {
        Rational& w = s.weight ? *s.weight : s.weight.emplace();
        exact(w);
        if (sgn(w) <= 0) defer();
        return;
      }
      if (bit == kCenter) {
        vec2(s.pressure_center ? *s.pressure_center : s.pressure_center.emplace(), 2);
        return;
      }
      if (bit == kRegions) {
        array(2, [&](std::size_t k) {
          region(slot(s.regions, k), region_vertices, any_without_mu);
          regions = k + 1;
        });
        return;
      }
      array(2, [&](std::size_t k) {
        if (k >= limits_.max_contacts || !tally_.add_entry(limits_)) defer();
        Support_point& p = slot(s.points, k);
        points = k + 1;
        enum : unsigned { kAt = 1, kForce = 2, kPointMu = 4 };
        unsigned point_seen = 0;
        object(3, [&](std::string_view point_key) {
          const unsigned b = point_key == "at" ? kAt : point_key == "force" ? kForce : point_key == "mu" ? kPointMu : 0u;
          if (b == 0 || (point_seen & b)) defer();
          point_seen |= b;
          if (b == kAt) vec2(p.at, 4);
          else if (b == kForce) nonnegative(p.force ? *p.force : p.force.emplace());
          else nonnegative(p.mu ? *p.mu : p.mu.emplace());
        });
        if (!(point_seen & kAt)) defer();
        if (!(point_seen & kForce)) p.force.reset();
        if (!(point_seen & kPointMu)) {
          p.mu.reset();
          any_without_mu = true;
        }
        any_force |= p.force && sgn(*p.force) > 0;
        all_given &= p.force.has_value();
      });
    });
    if (!(seen & kRegions)) regions = 0;
    if ((!(seen & kPoints) || points == 0) && regions == 0) defer();
    if (all_given && !any_force && regions == 0) defer();
    if (!(seen & kMu)) {
      if (any_without_mu) defer();
      s.mu.reset();
    }
    if (!(seen & kWeight)) s.weight.reset();
    if (!(seen & kCenter)) s.pressure_center.reset();
    s.points.resize(points);
    s.regions.resize(regions);
    for (std::size_t k = 0; k < regions; ++k) settle_region(s.regions[k], "support.regions[" + std::to_string(k) + "]");
  }

  // A ring [[x, y], …] into `out` (reused), counting its vertices against the regions' limit.
  void ring(std::vector<Vec2>& out, std::size_t level, std::size_t& vertices) {
    std::size_t n = 0;
    array(level, [&](std::size_t k) {
      if (++vertices > limits_.max_region_vertices) defer();
      vec2(slot(out, k), level + 1);
      n = k + 1;
    });
    out.resize(n);
  }

  // {"outline", "holes"?, "pressure": "uniform" | {"linear": [a, b, c]}, "force"?, "mu"?} (scene.cpp's region());
  // settled by settle_region once the whole support is read (support.mu may follow).
  void region(Support_region& r, std::size_t& vertices, bool& any_without_mu) {
    enum : unsigned { kOutline = 1, kHoles = 2, kPressure = 4, kForce = 8, kMu = 16 };
    unsigned seen = 0;
    std::size_t holes = 0;
    bool uniform = false, linear = false;
    object(3, [&](std::string_view key) {
      const unsigned bit = key == "outline"    ? kOutline
                           : key == "holes"    ? kHoles
                           : key == "pressure" ? kPressure
                           : key == "force"    ? kForce
                           : key == "mu"       ? kMu
                                               : 0u;
      if (bit == 0 || (seen & bit)) defer();
      seen |= bit;
      switch (bit) {
        case kOutline: ring(r.outline, 4, vertices); break;
        case kHoles:
          array(4, [&](std::size_t k) {
            ring(slot(r.holes, k), 5, vertices);
            holes = k + 1;
          });
          break;
        case kPressure:
          if (peek() == '"') {
            if (string_value() != "uniform") defer();
            uniform = true;
          } else {
            bool has_linear = false;
            object(4, [&](std::string_view k) {
              if (k != "linear" || has_linear) defer();
              has_linear = true;
              Vec3q w;
              wrench3(w, 5);
              r.linear = std::move(w);
            });
            if (!has_linear) defer();
            linear = true;
          }
          break;
        case kForce: exact(r.force); break;
        case kMu: nonnegative(r.mu ? *r.mu : r.mu.emplace()); break;
      }
    });
    if (!(seen & kOutline) || !(seen & kPressure)) defer();
    if (uniform && !(seen & kForce)) defer();
    if (linear && (seen & kForce)) defer();
    if (!(seen & kHoles)) holes = 0;
    r.holes.resize(holes);
    r.uniform = uniform;
    if (linear) zero(r.force);
    if (uniform)
      for (Rational& q : r.linear) zero(q);
    if (!(seen & kMu)) {
      r.mu.reset();
      any_without_mu = true;
    }
  }
};

}  // namespace

bool read_scene_into(Scene& scene, std::string_view text, const Input_limits& limits, std::string_view source,
                     bool lazy) {
  try {
    Stream(text, limits, source, lazy).scene(scene);
  } catch (const Defer&) {
    scene = read_scene_tree(text, limits, source, lazy);
    return false;
  } catch (const Input_error&) {  // a malformed string: read_scene_tree reports it in its place
    scene = read_scene_tree(text, limits, source, lazy);
    return false;
  }
  check_outline(scene, limits.lenient);  // (the tree reader checks its own)
  return true;
}

Scene read_scene(std::string_view text, const Input_limits& limits, std::string_view source, bool lazy) {
  Scene s;
  read_scene_into(s, text, limits, source, lazy);
  return s;
}

}  // namespace wrenchkit
