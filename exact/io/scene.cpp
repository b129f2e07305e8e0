#include "exact/io/scene.h"

#include "exact/io/outline.h"
#include "exact/io/support_check.h"

#include <algorithm>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <utility>

#include "exact/io/input_error.h"
#include "exact/io/region.h"
#include "exact/io/json.h"
#include "exact/io/scene_budget.h"
#include "exact/io/suggest.h"

namespace wrenchkit {
namespace {

using json::Type;
using json::Value;

class Reader {
 public:
  Reader(const Input_limits& limits, bool lazy) : limits_(limits), lazy_(lazy) {}

  Scene scene(const Value& root) {
    expect(root, Type::object, "scene", "an object");
    keys(root, "", {"wrenchkit", "name", "body", "contacts", "load", "support", "mu", "pusher"});
    const Value* version = root.find("wrenchkit");
    if (!version) fail("scene", "missing key \"wrenchkit\" (the format version, 1)");
    if (number(*version, "wrenchkit") != 1)
      fail("wrenchkit", display(*version) + " is not a supported format version (only 1)");
    Scene s;
    if (const Value* v = root.find("name")) {
      expect(*v, Type::string, "name", "a string");
      s.name = v->text;
    }
    if (const Value* v = root.find("body")) s.body = body(*v);
    outline_ = &s.body.outline;
    // The scene-wide μ: every point contact's coefficient unless it writes its own (docs/scene-format.md).
    scene_mu_ = root.find("mu");
    if (scene_mu_) s.mu = nonnegative(*scene_mu_, "mu");
    if (const Value* v = root.find("contacts")) {
      expect(*v, Type::array, "contacts", "an array");
      if (v->items.size() > limits_.max_contacts)
        fail("contacts", "has " + std::to_string(v->items.size()) + " entries, more than the limit " +
                             std::to_string(limits_.max_contacts) + " (--max-contacts)");
      s.contacts.reserve(v->items.size());  // no reallocation: Contact's rationals would be copied
      for (std::size_t i = 0; i < v->items.size(); ++i)
        s.contacts.push_back(contact(v->items[i], "contacts[" + std::to_string(i) + "]"));
    }
    if (const Value* v = root.find("load")) s.load = load(*v, s.body);
    if (const Value* v = root.find("support")) s.support = support(*v);
    if (const Value* v = root.find("pusher")) s.pusher = pusher(*v);
    const std::string why = support_inadmissible(s);
    if (!why.empty()) throw Input_error(why);
    check_outline(s, limits_.lenient);
    return s;
  }

 private:
  const Input_limits& limits_;
  bool lazy_;
  const Value* scene_mu_ = nullptr;  // the scene-wide "mu", while its contacts are read
  const std::vector<Vec2>* outline_ = nullptr;  // body.outline (read before the contacts)

  [[noreturn]] static void fail(const std::string& path, const std::string& what) {
    throw Input_error(path + ": " + what);
  }

  static std::string join(const std::string& path, const char* key) {
    return path.empty() ? std::string(key) : path + "." + key;
  }

  // The offending text as the user wrote it, shortened.
  static std::string display(const Value& v) {
    std::string t;
    switch (v.type) {
      case Type::string: t = json::quote(v.text); break;
      case Type::number: t = v.text; break;
      default: return json::type_name(v.type);
    }
    if (t.size() > 48) t = t.substr(0, 40) + "… (" + std::to_string(t.size()) + " characters)";
    return t;
  }

  static void expect(const Value& v, Type t, const std::string& path, const char* what) {
    if (v.type != t) fail(path, std::string("expected ") + what + ", got " + json::type_name(v.type));
  }

  static void keys(const Value& obj, const std::string& path, std::initializer_list<const char*> allowed) {
    keys(obj, path, allowed, allowed);
  }

  // Every key of obj is one of `allowed`; an unknown key's message suggests the key of `known` (the object's
  // keys, those of its other forms included) that it likely means.
  static void keys(const Value& obj, const std::string& path, std::initializer_list<const char*> allowed,
                   std::initializer_list<const char*> known) {
    for (const auto& m : obj.members) {
      bool ok = false;
      for (const char* a : allowed) ok |= m.first == a;
      if (!ok) fail(path.empty() ? "scene" : path, "unknown key " + json::quote(m.first) + did_you_mean(likely_key(m.first, known)));
    }
  }

  // The key of `known` an unknown key likely means: by the synonyms people write (position → at, direction →
  // normal, friction → mu, center_of_mass → com, ...) when that key is known here, else the closest spelling.
  static std::string likely_key(const std::string& key, std::initializer_list<const char*> known) {
    static const std::pair<const char*, const char*> synonyms[] = {
        {"position", "at"}, {"point", "at"}, {"location", "at"}, {"pos", "at"}, {"where", "at"}, {"contact_point", "at"},
        {"direction", "normal"}, {"dir", "normal"}, {"inward_normal", "normal"}, {"normal_direction", "normal"},
        {"friction", "mu"}, {"coefficient", "mu"}, {"friction_coefficient", "mu"}, {"coefficient_of_friction", "mu"},
        {"μ", "mu"}, {"centre_of_mass", "com"}, {"center_of_mass", "com"}, {"centre_of_gravity", "com"},
        {"center_of_gravity", "com"}, {"cog", "com"}, {"cm", "com"}, {"mass_center", "com"}, {"mass_centre", "com"},
        {"centroid", "com"}, {"polygon", "outline"}, {"vertices", "outline"}, {"shape", "outline"},
        {"boundary", "outline"}, {"weight", "gravity"}, {"mass", "gravity"}, {"normal_force", "force"},
        {"center_of_pressure", "pressure_center"}, {"centre_of_pressure", "pressure_center"},
        {"cop", "pressure_center"}, {"version", "wrenchkit"}, {"format", "wrenchkit"}, {"title", "name"},
        {"label", "name"}, {"fingers", "contacts"}, {"grasp", "contacts"}, {"external_load", "load"},
        {"external_wrench", "load"}, {"table", "support"}, {"friction_support", "support"}};
    std::vector<std::string> names(known.begin(), known.end());
    for (const auto& [word, meant] : synonyms)
      if (key == word && std::find(names.begin(), names.end(), meant) != names.end()) return meant;
    return closest_word(key, names);
  }

  static const Value& required(const Value& obj, const std::string& path, const char* key) {
    const Value* v = obj.find(key);
    if (!v) fail(path, std::string("missing key \"") + key + "\"");
    return *v;
  }

  Rational number(const Value& v, const std::string& path, fl::Bounded* approx = nullptr) const {
    if (v.type != Type::number && v.type != Type::string)
      fail(path, std::string("expected a number, got ") + json::type_name(v.type));
    std::string why;
    auto q = parse_rational(v.text, v.type == Type::number, limits_, why, approx);
    if (!q) {
      if (why == "has more digits than the digit limit")
        why = "has more than " + std::to_string(limits_.max_digits) + " digits (--max-digits)";
      else if (why == "has more digits than the digit limit when written out exactly")
        why = "has more than " + std::to_string(limits_.max_digits) +
              " digits written out as an exact integer or fraction (--max-digits)";
      else if (why == "has an exponent beyond the exponent limit")
        why = "has an exponent beyond ±" + std::to_string(limits_.max_exponent) + " (--max-exponent)";
      fail(path, display(v) + " " + why);
    }
    return std::move(*q);
  }

  // Lazy reading of one contact number: validated and turned into a certified double and an exact
  // sign from its digits; its text is kept for exact_contact().
  int lazy_number(const Value& v, const std::string& path, Contact& c, int slot, fl::Bounded& approx) const {
    if (v.type != Type::number && v.type != Type::string)
      fail(path, std::string("expected a number, got ") + json::type_name(v.type));
    std::string why;
    int sign = 0;
    if (!scan_number(v.text, v.type == Type::number, limits_, why, approx, sign)) {
      number(v, path);  // the same message as the exact reading
    }
    c.number_text[slot] = v.text;
    c.number_is_json[slot] = v.type == Type::number;
    return sign;
  }

  // An array of n numbers was expected at path and v is not one: "expected an array of N numbers[ NAMES], got
  // …", and where a direction is expected and a number or a string came, how to write one (angles are a common
  // first guess).
  [[noreturn]] static void not_an_array(const Value& v, const std::string& path, std::size_t n, const std::string& names) {
    std::string what = "expected an array of " + std::to_string(n) + " numbers" + names + ", got " +
                       (v.type == Type::array ? "an array of " + std::to_string(v.items.size())
                                              : std::string(json::type_name(v.type)));
    const std::string tail = ".normal";
    const bool direction = path.size() > tail.size() && path.compare(path.size() - tail.size(), tail.size(), tail) == 0;
    if (direction && (v.type == Type::number || v.type == Type::string))
      what += " (a normal is a direction [dx, dy] of any length, not an angle: for 30\u00b0 write [0.866025, 0.5], "
              "or give an exact direction such as [4, 3])";
    fail(path, what);
  }

  const Value& pair_item(const Value& v, const std::string& path, std::size_t n, std::size_t i) const {
    if (v.type != Type::array || v.items.size() != n) not_an_array(v, path, n, n == 2 ? "" : " [fx, fy, m]");
    return v.items[i];
  }

  Rational nonnegative(const Value& v, const std::string& path, fl::Bounded* approx = nullptr) const {
    Rational q = number(v, path, approx);
    if (q < 0) fail(path, display(v) + " is negative (must be >= 0)");
    return q;
  }

  Vec2 vec2(const Value& v, const std::string& path, fl::Bounded* approx2 = nullptr) const {
    if (v.type != Type::array || v.items.size() != 2) not_an_array(v, path, 2, "");
    return {number(v.items[0], path + "[0]", approx2), number(v.items[1], path + "[1]", approx2 ? approx2 + 1 : nullptr)};
  }

  Vec3q wrench3(const Value& v, const std::string& path, fl::Bounded* approx3 = nullptr,
                 const char* names = "[fx, fy, m]") const {
    if (v.type != Type::array || v.items.size() != 3) not_an_array(v, path, 3, std::string(" ") + names);
    return {number(v.items[0], path + "[0]", approx3), number(v.items[1], path + "[1]", approx3 ? approx3 + 1 : nullptr),
            number(v.items[2], path + "[2]", approx3 ? approx3 + 2 : nullptr)};
  }

  Body body(const Value& v) const {
    expect(v, Type::object, "body", "an object");
    keys(v, "body", {"outline", "com"});
    Body b;
    if (const Value* o = v.find("outline")) {
      expect(*o, Type::array, "body.outline", "an array of points");
      if (o->items.size() > limits_.max_contacts)
        fail("body.outline", "has " + std::to_string(o->items.size()) + " points, more than the limit " +
                                 std::to_string(limits_.max_contacts) + " (--max-contacts)");
      for (std::size_t i = 0; i < o->items.size(); ++i)
        b.outline.push_back(vec2(o->items[i], "body.outline[" + std::to_string(i) + "]"));
    }
    if (const Value* c = v.find("com")) b.com = vec2(*c, "body.com");
    return b;
  }

  Contact contact(const Value& v, const std::string& path, bool eager = false) const {
    expect(v, Type::object, path, "an object");
    Contact c;
    if (const Value* n = v.find("name")) {
      expect(*n, Type::string, path + ".name", "a string");
      c.name = n->text;
    }
    if (v.find("edge") || v.find("s")) return placed_contact(v, path, std::move(c));
    if (lazy_ && !eager) return lazy_contact(v, path, std::move(c));
    if (v.find("wrench")) {
      keys(v, path, {"wrench", "name"});
      c.kind = Contact::Kind::wrench;
      fl::Bounded w[3];
      c.wrench = wrench3(*v.find("wrench"), path + ".wrench", w);
      if (c.wrench[0] == 0 && c.wrench[1] == 0 && c.wrench[2] == 0)
        fail(path + ".wrench", "zero wrench");
      c.twin.is_wrench = true;
      c.twin.fx = w[0];
      c.twin.fy = w[1];
      c.twin.m = w[2];
      c.has_twin = true;
      return c;
    }
    keys(v, path, {"at", "normal", "mu", "name"});
    c.kind = Contact::Kind::point;
    fl::Bounded at[2], n[2];
    c.at = vec2(required(v, path, "at"), path + ".at", at);
    c.normal = vec2(required(v, path, "normal"), path + ".normal", n);
    if (c.normal.x == 0 && c.normal.y == 0) fail(path + ".normal", "zero vector");
    const Value* own = v.find("mu");
    if (const Value* mu = own ? own : scene_mu_) c.mu = nonnegative(*mu, own ? path + ".mu" : "mu", &c.twin.mu);
    c.mu_given = own || scene_mu_;
    c.twin.ax = at[0];
    c.twin.ay = at[1];
    c.twin.nx = n[0];
    c.twin.ny = n[1];
    c.twin.frictional = c.mu != 0;  // decided exactly
    c.has_twin = true;
    return c;
  }

  // The pusher: a point contact (at or {edge, s}; normal; mu, else the scene's) with "velocity", which pushes into
  // the body. Read eagerly (one contact).
  Pusher pusher(const Value& v) const {
    expect(v, Type::object, "pusher", "an object");
    if (v.find("wrench"))
      fail("pusher", "is a point contact {\"at\", \"normal\", \"mu\", \"velocity\"}, not a wrench");
    Value rest = v;  // the contact's own keys (velocity, and a line contact's segment and omega, read here)
    rest.members.erase(std::remove_if(rest.members.begin(), rest.members.end(),
                                      [](const auto& m) {
                                        return m.first == "velocity" || m.first == "segment" || m.first == "omega";
                                      }),
                       rest.members.end());
    Pusher p;
    const Value& vel = required(v, "pusher", "velocity");
    const Value* seg = v.find("segment");
    if (v.find("omega") && !seg)
      fail("pusher.omega", "is a line contact's rotation rate: give \"segment\": [[x1, y1], [x2, y2]] (a point pusher "
                           "moves with its velocity alone)");
    if (seg) {  // a line contact (PU-3): its first end stands as the contact's point, read with its normal and mu
      if (v.find("at") || v.find("edge") || v.find("s"))
        fail("pusher", "give either \"segment\" (a line contact) or \"at\" / {\"edge\", \"s\"} (a point contact), not both");
      if (seg->type != Type::array || seg->items.size() != 2)
        fail("pusher.segment", "expected an array of two points [[x1, y1], [x2, y2]] (the ends of the line contact)");
      rest.members.emplace_back("at", seg->items[0]);
      p.contact = contact(rest, "pusher", /*eager=*/true);
      p.end = vec2(seg->items[1], "pusher.segment[1]");
      const Vec2 first = vec2(seg->items[0], "pusher.segment[0]");
      const Vec2 along = minus(*p.end, first);
      if (is_zero(along)) fail("pusher.segment", "its two ends are the same point: a point pusher is {\"at\": [x, y], …}");
      if (dot(along, p.contact.normal) != 0)
        fail("pusher.normal", "(" + p.contact.normal.x.get_str() + ", " + p.contact.normal.y.get_str() +
                                  ") is not perpendicular to the segment (the line contact's inward normal is "
                                  "perpendicular to its edge)");
      if (const Value* w = v.find("omega")) p.omega = number(*w, "pusher.omega");
    } else if (v.find("edge") || v.find("s")) {
      Contact c;
      if (const Value* n = v.find("name")) {
        expect(*n, Type::string, "pusher.name", "a string");
        c.name = n->text;
      }
      p.contact = placed_contact(rest, "pusher", std::move(c));
    } else {
      p.contact = contact(rest, "pusher", /*eager=*/true);
    }
    p.velocity = vec2(vel, "pusher.velocity");  // (a line contact's: at the middle of its segment)
    const Rational push = dot(p.velocity, p.contact.normal);
    const auto point_text = [](const Vec2& a) { return "(" + a.x.get_str() + ", " + a.y.get_str() + ")"; };
    if (push <= 0)
      fail("pusher.velocity", point_text(p.velocity) + (push == 0 ? " is tangent to the contact (velocity · normal = 0)"
                                                                  : " moves away from the body (velocity · normal < 0)") +
                                  ": a pusher moves into the body, along its inward normal " +
                                  point_text(p.contact.normal) + " — flip the velocity or the normal?");
    return p;
  }

  // A point contact placed on body.outline: {"edge": i, "s": t, "normal"?, "mu"?, "name"?} (exact/io/outline.h) —
  // its point v_i + t·(v_{i+1} − v_i) and, unless given, the edge's inward normal, exact (also when lazy).
  Contact placed_contact(const Value& v, const std::string& path, Contact c) const {
    if (v.find("at")) fail(path, "give either \"at\" or {\"edge\", \"s\"} (a place on body.outline), not both");
    keys(v, path, {"edge", "s", "normal", "mu", "name"});
    const std::size_t n = outline_ ? outline_->size() : 0;
    const Value& ev = required(v, path, "edge");
    if (n == 0) fail(path + ".edge", "needs body.outline (edge i is its side from vertex i to vertex i + 1)");
    const Rational e = number(ev, path + ".edge");
    if (e.get_den() != 1 || e < 0 || e >= static_cast<long>(n))
      fail(path + ".edge", display(ev) + " is not an edge of body.outline (an integer from 0 to " + std::to_string(n - 1) +
                               ": edge i runs from vertex i to vertex i + 1)");
    const Value& sv = required(v, path, "s");
    const Rational t = number(sv, path + ".s");
    if (t < 0 || t > 1) fail(path + ".s", display(sv) + " is not in [0, 1] (the place along the edge: 0 at its first vertex, 1 at its last)");
    c.kind = Contact::Kind::point;
    c.edge = static_cast<std::size_t>(e.get_num().get_ui());
    c.s = t;
    c.at = edge_point(*outline_, *c.edge, t);
    if (const Value* nv = v.find("normal")) {
      c.normal = vec2(*nv, path + ".normal");
      if (c.normal.x == 0 && c.normal.y == 0) fail(path + ".normal", "zero vector");
    } else {
      const int orientation = outline_orientation(*outline_);
      if (orientation == 0) fail("body.outline", "has zero area: no inward normal for " + path);
      c.normal = edge_inward_normal(*outline_, *c.edge, orientation);
    }
    const Value* own = v.find("mu");
    if (const Value* mu = own ? own : scene_mu_) c.mu = nonnegative(*mu, own ? path + ".mu" : "mu");
    c.mu_given = own || scene_mu_;
    c.twin.ax = to_bounded(c.at.x);
    c.twin.ay = to_bounded(c.at.y);
    c.twin.nx = to_bounded(c.normal.x);
    c.twin.ny = to_bounded(c.normal.y);
    c.twin.mu = to_bounded(c.mu);
    c.twin.frictional = c.mu != 0;
    c.has_twin = true;
    return c;
  }

  // The lazy twin of contact(): the same checks in the same order, on exact signs.
  Contact lazy_contact(const Value& v, const std::string& path, Contact c) const {
    c.exact_pending = true;
    c.has_twin = true;
    if (v.find("wrench")) {
      keys(v, path, {"wrench", "name"});
      c.kind = Contact::Kind::wrench;
      c.twin.is_wrench = true;
      const Value& w = *v.find("wrench");
      const std::string wp = path + ".wrench";
      fl::Bounded* out[3] = {&c.twin.fx, &c.twin.fy, &c.twin.m};
      int nonzero = 0;
      for (int i = 0; i < 3; ++i)
        nonzero |= lazy_number(pair_item(w, wp, 3, i), wp + "[" + std::to_string(i) + "]", c, i, *out[i]);
      if (!nonzero) fail(wp, "zero wrench");
      return c;
    }
    keys(v, path, {"at", "normal", "mu", "name"});
    c.kind = Contact::Kind::point;
    c.mu_given = v.find("mu") || scene_mu_;
    const Value& at = required(v, path, "at");
    const std::string ap = path + ".at";
    lazy_number(pair_item(at, ap, 2, 0), ap + "[0]", c, 0, c.twin.ax);
    lazy_number(pair_item(at, ap, 2, 1), ap + "[1]", c, 1, c.twin.ay);
    const Value& n = required(v, path, "normal");
    const std::string np = path + ".normal";
    const int sx = lazy_number(pair_item(n, np, 2, 0), np + "[0]", c, 2, c.twin.nx);
    const int sy = lazy_number(pair_item(n, np, 2, 1), np + "[1]", c, 3, c.twin.ny);
    if (sx == 0 && sy == 0) fail(np, "zero vector");
    int smu = 0;
    c.number_text[4] = "0";
    c.number_is_json[4] = true;
    c.twin.mu = fl::Bounded::exact(0);
    const Value* own = v.find("mu");
    if (const Value* mu = own ? own : scene_mu_) {
      smu = lazy_number(*mu, own ? path + ".mu" : "mu", c, 4, c.twin.mu);
      if (smu < 0) fail(own ? path + ".mu" : "mu", display(*mu) + " is negative (must be >= 0)");
    }
    c.twin.frictional = smu != 0;
    return c;
  }

  Load load(const Value& v, const Body& body) const {
    expect(v, Type::object, "load", "an object");
    Load l;
    if (v.find("gravity")) {
      keys(v, "load", {"gravity"});
      const Value& g = *v.find("gravity");
      l.kind = Load::Kind::gravity;
      l.weight = number(g, "load.gravity");
      if (l.weight <= 0) fail("load.gravity", display(g) + " is not positive (a weight must be > 0)");
      if (!body.com) fail("load.gravity", "needs body.com (the point where the weight acts)");
    } else if (v.find("wrench")) {
      keys(v, "load", {"wrench"});
      l.kind = Load::Kind::wrench;
      l.wrench = wrench3(*v.find("wrench"), "load.wrench");
    } else if (v.find("force") || v.find("at")) {
      keys(v, "load", {"force", "at"});
      l.kind = Load::Kind::force;
      l.force = vec2(required(v, "load", "force"), "load.force");
      l.at = vec2(required(v, "load", "at"), "load.at");
    } else {
      keys(v, "load", {}, {"force", "at", "wrench", "gravity"});
      fail("load", "expected one of {\"force\", \"at\"}, {\"wrench\"} or {\"gravity\"}");
    }
    return l;
  }

  Support support(const Value& v) const {
    expect(v, Type::object, "support", "an object");
    keys(v, "support", {"mu", "points", "regions", "weight", "pressure_center"});
    Support s;
    if (const Value* mu = v.find("mu")) s.mu = nonnegative(*mu, "support.mu");
    if (const Value* w = v.find("weight")) {
      s.weight = number(*w, "support.weight");
      if (*s.weight <= 0) fail("support.weight", display(*w) + " is not positive (a total normal force must be > 0)");
    }
    if (const Value* c = v.find("pressure_center")) s.pressure_center = vec2(*c, "support.pressure_center");
    const Value* regions = v.find("regions");
    if (regions) {
      expect(*regions, Type::array, "support.regions", "an array");
      s.regions.reserve(regions->items.size());
      std::size_t vertices = 0;
      for (std::size_t i = 0; i < regions->items.size(); ++i)
        s.regions.push_back(
            region(regions->items[i], "support.regions[" + std::to_string(i) + "]", s.mu.has_value(), vertices));
    }
    const Value* pts = v.find("points");
    if (!pts && s.regions.empty()) fail("support", "missing key \"points\" (a support needs points or regions)");
    if (pts) expect(*pts, Type::array, "support.points", "an array");
    if (pts && pts->items.empty() && s.regions.empty())
      fail("support.points", "empty (a support needs at least one point or region)");
    if (pts && pts->items.size() > limits_.max_contacts)
      fail("support.points", "has more entries than the limit " +
                                 std::to_string(limits_.max_contacts) + " (--max-contacts)");
    bool any_force = !s.regions.empty(), all_given = true;
    const std::size_t n = pts ? pts->items.size() : 0;
    s.points.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      const std::string path = "support.points[" + std::to_string(i) + "]";
      const Value& p = pts->items[i];
      expect(p, Type::object, path, "an object");
      keys(p, path, {"at", "force", "mu"});
      Support_point sp;
      sp.at = vec2(required(p, path, "at"), path + ".at");
      if (const Value* f = p.find("force")) sp.force = nonnegative(*f, path + ".force");
      if (const Value* mu = p.find("mu")) sp.mu = nonnegative(*mu, path + ".mu");
      if (!sp.mu && !s.mu) fail(path, "missing key \"mu\" (and support.mu gives no default)");
      any_force |= sp.force && *sp.force > 0;
      all_given &= sp.force.has_value();
      s.points.push_back(std::move(sp));
    }
    if (all_given && !any_force) fail("support.points", "all forces are zero");
    return s;
  }

  // {"outline": [[x, y], …], "holes"?: [[[x, y], …], …], "pressure": "uniform", "force": F, "mu"?} or
  // {"outline", "holes"?, "pressure": {"linear": [a, b, c]}, "mu"?} (docs/scene-format.md, "Support regions"); its
  // geometry is checked and settled by settle_region (exact/io/region.h), as the streaming reader does.
  Support_region region(const Value& v, const std::string& path, bool support_mu, std::size_t& vertices) const {
    expect(v, Type::object, path, "an object");
    keys(v, path, {"outline", "holes", "pressure", "force", "mu"});
    Support_region r;
    r.outline = ring(required(v, path, "outline"), path + ".outline", vertices);
    if (const Value* h = v.find("holes")) {
      expect(*h, Type::array, path + ".holes", "an array of rings");
      for (std::size_t j = 0; j < h->items.size(); ++j)
        r.holes.push_back(ring(h->items[j], path + ".holes[" + std::to_string(j) + "]", vertices));
    }
    const Value& p = required(v, path, "pressure");
    const std::string pp = path + ".pressure";
    if (p.type == Type::string) {
      if (p.text != "uniform") fail(pp, display(p) + " is not \"uniform\" (or {\"linear\": [a, b, c]})");
      const Value* f = v.find("force");
      if (!f) fail(path, "missing key \"force\" (a uniform pressure needs the region's force)");
      r.uniform = true;
      r.force = number(*f, path + ".force");
    } else if (p.type == Type::object) {
      keys(p, pp, {"linear"});
      const Vec3q w = wrench3(required(p, pp, "linear"), pp + ".linear", nullptr, "[a, b, c]");
      if (v.find("force"))
        fail(path + ".force", "not allowed with a linear pressure (the region's force is the pressure's integral)");
      r.uniform = false;
      r.linear = w;
    } else {
      fail(pp, std::string("expected \"uniform\" or {\"linear\": [a, b, c]}, got ") + json::type_name(p.type));
    }
    if (const Value* mu = v.find("mu")) r.mu = nonnegative(*mu, path + ".mu");
    if (!r.mu && !support_mu) fail(path, "missing key \"mu\" (and support.mu gives no default)");
    settle_region(r, path);
    return r;
  }

  // A ring of points, counted with the regions' other rings against --max-region-vertices.
  std::vector<Vec2> ring(const Value& v, const std::string& path, std::size_t& vertices) const {
    expect(v, Type::array, path, "an array of points");
    vertices += v.items.size();
    if (vertices > limits_.max_region_vertices)
      fail(path, "the support's regions have more than " + std::to_string(limits_.max_region_vertices) +
                     " vertices in all (--max-region-vertices)");
    std::vector<Vec2> out;
    out.reserve(v.items.size());
    for (std::size_t i = 0; i < v.items.size(); ++i) out.push_back(vec2(v.items[i], path + "[" + std::to_string(i) + "]"));
    return out;
  }
};

}  // namespace

const Scene& exact_contacts(const Scene& s, std::optional<Scene>& storage) {
  for (std::size_t i = 0; i < s.contacts.size(); ++i)
    if (s.contacts[i].exact_pending) {
      if (!storage) storage = s;
      storage->contacts[i] = exact_contact(s.contacts[i]);
    }
  return storage ? *storage : s;
}

Contact exact_contact(const Contact& c) {
  if (!c.exact_pending) return c;
  Contact e = c;
  if (c.from_doubles) {  // mpq_set_d: the double's exact binary value
    e.at = {Rational(c.twin.ax.v), Rational(c.twin.ay.v)};
    e.normal = {Rational(c.twin.nx.v), Rational(c.twin.ny.v)};
    e.mu = Rational(c.twin.mu.v);
    e.exact_pending = e.from_doubles = false;
    return e;
  }
  Input_limits unlimited;  // the texts were validated against the caller's limits already
  unlimited.max_digits = static_cast<std::size_t>(-1);
  unlimited.max_exponent = std::numeric_limits<long>::max();
  auto q = [&](int slot) {
    std::string why;
    auto r = parse_rational(c.number_text[slot], c.number_is_json[slot], unlimited, why);
    if (!r) throw std::logic_error("exact_contact: a validated number no longer parses");
    return *r;
  };
  if (c.kind == Contact::Kind::wrench) {
    e.wrench = {q(0), q(1), q(2)};
  } else {
    e.at = {q(0), q(1)};
    e.normal = {q(2), q(3)};
    e.mu = q(4);
  }
  e.exact_pending = false;
  return e;
}

void set_point_contact(Contact& c, double ax, double ay, double nx, double ny, double mu) {
  c.kind = Contact::Kind::point;
  c.name.clear();
  c.twin = fl::Bounded_contact{};
  c.twin.ax = fl::Bounded::exact(ax);
  c.twin.ay = fl::Bounded::exact(ay);
  c.twin.nx = fl::Bounded::exact(nx);
  c.twin.ny = fl::Bounded::exact(ny);
  c.twin.mu = fl::Bounded::exact(mu);
  c.twin.frictional = mu != 0;  // exact: the double is the value
  c.has_twin = c.exact_pending = c.from_doubles = true;
}

Scene read_scene_tree(std::string_view json_text, const Input_limits& limits, std::string_view source, bool lazy) {
  if (json_text.size() > limits.max_file_bytes)
    throw Input_error(std::string(source) + ": larger than the size limit of " +
                      std::to_string(limits.max_file_bytes) + " bytes (--max-file-size)");
  // [BUDGET] Measured on the text before any number is built and before the JSON tree is.
  const std::string over = budget_problem(measure_scene(json_text, limits), limits);
  if (!over.empty()) throw Input_error(over);
  const json::Value root = json::parse(json_text, limits, source);
  return Reader(limits, lazy).scene(root);
}

}  // namespace wrenchkit
