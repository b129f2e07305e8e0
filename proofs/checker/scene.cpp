// proofs/checker/scene.cpp - reading the scene (docs/scene-format.md): contacts, body, load (§3.3), support and
// its admissible distributions F (§6), regions (§6.4, in regions.cpp); a bad scene is a Failure with the reason.
#include "proofs/checker/scene.h"

#include <algorithm>
#include <set>

namespace wrenchkit_checker::detail {

constexpr std::size_t kKeptLimbs = 4;
bool small(const Q& q) {
  return mpz_size(q.get_num_mpz_t()) <= kKeptLimbs && mpz_size(q.get_den_mpz_t()) <= kKeptLimbs;
}

std::string read_string(Reader& r) {
  if (r.peek() != Kind::string) r.fail("expected a string");
  return r.string();
}

// A scene number: a JSON number or a number string.
Q read_number(Reader& r, const Limits& lim, std::string* text) {
  const Kind k = r.peek();
  if (k != Kind::number && k != Kind::string) r.fail("expected a number (a JSON number or a number string)");
  std::string s = k == Kind::number ? std::string(r.number()) : r.string();
  Q q;
  try {  // the path only for the message (building it for every number costs more than the number)
    q = scene_number(s, lim, "", Tally::reading);
  } catch (const Failure& f) {
    throw Failure{r.path() + f.message};
  }
  if (text) *text = std::move(s);
  return q;
}

// A contact's number as read: its text (a view, valid while the reader is), its sign, and its value
// when it fits a Small.
struct Read_number {
  std::string_view text = "0";
  bool zero = true, negative = false, fits = true;
  Small value;
};
// A JSON number (its grammar checked by the reader) without an exponent and of at most 18 digits, the usual
// contact number: what number_text(), is_zero() and small_value() make of it, in one pass; false for any
// other text and whenever a limit could be in question (then those functions decide, and name it).
bool short_json_decimal(std::string_view s, const Limits& lim, Read_number& n, std::size_t& counted) {
  std::size_t i = s[0] == '-' ? 1 : 0, whole = 0, frac = 0;
  unsigned long long m = 0;
  for (; i < s.size() && is_digit(s[i]); ++i, ++whole) m = m * 10 + static_cast<unsigned>(s[i] - '0');
  if (i < s.size() && s[i] == '.')
    for (++i; i < s.size() && is_digit(s[i]); ++i, ++frac) m = m * 10 + static_cast<unsigned>(s[i] - '0');
  if (i != s.size() || whole + frac > 18 || lim.max_exponent < 0) return false;  // an exponent, or long
  // As number_text(): the digits, or the value written out when larger (significant + |scale| + 1).
  std::size_t significant = 0;
  for (unsigned long long v = m; v != 0; v /= 10) ++significant;
  counted = whole + frac;
  if (significant > 0) counted = std::max(counted, significant + frac + (frac > 0 ? 1 : 0));
  if (counted > lim.max_digits) return false;
  n.zero = m == 0;
  n.negative = s[0] == '-' && !n.zero;
  n.fits = true;  // as small_value(): m < 10^18 over 10^frac (1 when m is zero)
  n.value.num = s[0] == '-' ? -static_cast<long long>(m) : static_cast<long long>(m);
  unsigned long long p = 1;
  if (m != 0)
    for (std::size_t j = 0; j < frac; ++j) p *= 10;
  n.value.den = static_cast<long long>(p);
  return true;
}

Read_number read_contact_number(Reader& r, const Limits& lim) {
  const Kind k = r.peek();
  if (k != Kind::number && k != Kind::string) r.fail("expected a number (a JSON number or a number string)");
  Read_number n;
  n.text = k == Kind::number ? r.number() : r.string_view();
  std::size_t counted = 0;
  if (k == Kind::number && short_json_decimal(n.text, lim, n, counted)) {
    try {
      if (Tally::reading) Tally::reading->number(counted, lim);
    } catch (const Failure& f) {
      throw Failure{r.path() + f.message};
    }
    return n;
  }
  Number_text t;
  try {  // the path only for the message, as read_number(); counted in the budget as there
    t = number_text(n.text, lim, "");
    if (Tally::reading) Tally::reading->number(t.counted, lim);
  } catch (const Failure& f) {
    throw Failure{r.path() + f.message};
  }
  n.zero = is_zero(t);
  n.negative = t.negative && !n.zero;
  n.fits = small_value(t, n.value);
  return n;
}

// "an array of n numbers" (built once for the usual sizes: every contact asks).
const std::string& numbers_text(std::size_t n) {
  static const std::string two = "an array of 2 numbers", three = "an array of 3 numbers";
  thread_local std::string other;
  if (n == 2) return two;
  if (n == 3) return three;
  other = "an array of " + std::to_string(n) + " numbers";
  return other;
}

// n numbers into out[0..n); true if all are zero.
bool read_numbers(Reader& r, const Limits& lim, std::size_t n, Read_number* out) {
  bool zero = true;
  read_fixed(r, n, numbers_text(n), [&](std::size_t k) {
    out[k] = read_contact_number(r, lim);
    zero = out[k].zero && zero;
  });
  return zero;
}

// The values to keep with a contact: all of them if all are small, else none.
std::vector<Q> kept(std::vector<Q> values) {
  for (const Q& q : values)
    if (!small(q)) return {};
  return values;
}

// A contact of these numbers (validated): their Smalls if all fit, else their texts (and values).
Contact make_contact(bool wrench, const Read_number* n, std::size_t count, const Limits& lim) {
  Contact c;
  c.wrench = wrench;
  c.frictional = !wrench && !n[4].zero;
  c.fixed = true;
  for (std::size_t k = 0; k < count; ++k) c.fixed = c.fixed && n[k].fits;
  if (c.fixed) {
    for (std::size_t k = 0; k < count; ++k) c.small[k] = n[k].value;
    return c;
  }
  std::vector<Q> values;
  for (std::size_t k = 0; k < count; ++k) {
    c.text.emplace_back(n[k].text);
    values.push_back(scene_number(n[k].text, lim, "contacts"));  // valid: read before
  }
  c.value = kept(std::move(values));
  return c;
}

// A point contact placed on body.outline, {"edge": i, "s": t, "normal"?, "mu"?, "name"?} (docs/scene-format.md,
// "The outline"): its point v_i + t (v_{i+1} - v_i) and, unless given, the edge's inward normal are made once the
// whole scene is read (the outline may come after the contacts).
struct Placed {
  std::size_t index = 0;
  Q edge, s;
  bool has_normal = false, has_mu = false;
  Read_number normal[2], mu;
};

// {at, normal, mu?, name?} (normal != 0, mu >= 0) or {wrench, name?} (wrench != 0), or placed (*placed set; the
// contact returned is a stand-in). A point contact without mu leaves its numbers in *no_mu (when given): the
// scene-wide "mu", which may come later, replaces its "0".
void read_vector(Reader& r, const Limits& lim, std::size_t n, Q* out);

// The pusher's contact (`pusher` given) reads its "velocity" too (pusher->has_velocity tells whether it was there),
// and a line contact's "segment" (its first end the contact's point) and "omega".
Contact read_contact(Reader& r, const Limits& lim, std::optional<std::array<Read_number, 5>>* no_mu = nullptr,
                     std::optional<Placed>* placed = nullptr, Pusher* pusher = nullptr) {
  begin_object(r, "expected an object {\"at\", \"normal\", \"mu\"?, \"name\"?} or {\"wrench\", \"name\"?}");
  Read_number point[5], wrench[3];  // x, y, nx, ny, mu ("0" if absent); fx, fy, m
  std::string_view key;
  enum : unsigned { kAt = 1, kNormal = 2, kMu = 4, kWrench = 8, kEdge = 16, kS = 32 };
  unsigned keys = 0;  // the keys present (a bit set: cheaper than a set of strings, read per contact)
  Q edge, s;
  while (r.next_key(key)) {
    if ((key == "edge" || key == "s") && placed) {
      keys |= key == "edge" ? kEdge : kS;
      (key == "edge" ? edge : s) = read_number(r, lim);
    } else if (key == "at") {
      keys |= kAt;
      read_numbers(r, lim, 2, point);
    } else if (key == "normal") {
      keys |= kNormal;
      if (read_numbers(r, lim, 2, point + 2)) r.fail("zero vector");
    } else if (key == "mu") {
      keys |= kMu;
      point[4] = read_contact_number(r, lim);
      if (point[4].negative) r.fail(quote(point[4].text) + " is negative");
    } else if (key == "wrench") {
      keys |= kWrench;
      if (read_numbers(r, lim, 3, wrench)) r.fail("zero wrench");
    } else if (key == "name") {
      read_string(r);
    } else if (key == "velocity" && pusher) {
      read_vector(r, lim, 2, pusher->velocity);
      pusher->has_velocity = true;
    } else if (key == "segment" && pusher) {
      keys |= kAt;
      pusher->line = true;
      read_fixed(r, 2, "an array of two points [[x1, y1], [x2, y2]]", [&](std::size_t k) {
        if (k == 0) read_numbers(r, lim, 2, point);
        else read_vector(r, lim, 2, pusher->end);
      });
    } else if (key == "omega" && pusher) {
      pusher->has_omega = true;
      pusher->omega = read_number(r, lim);
    } else {
      r.fail("unknown key " + quote(key), true);
    }
  }
  if (keys & (kEdge | kS)) {
    if (keys & (kAt | kWrench)) r.fail("a placed contact has \"edge\" and \"s\", not \"at\" or \"wrench\"");
    if (!(keys & kEdge) || !(keys & kS)) r.fail("a placed contact needs both \"edge\" and \"s\"");
    Placed& p = placed->emplace();
    p.edge = edge, p.s = s;
    p.has_normal = keys & kNormal, p.has_mu = keys & kMu;
    p.normal[0] = point[2], p.normal[1] = point[3], p.mu = point[4];
    return Contact{};
  }
  const bool is_point = keys & (kAt | kNormal | kMu);
  if (keys & kWrench) {
    if (is_point) r.fail("a contact has either \"at\", \"normal\" and \"mu\" (a point contact) or \"wrench\", not both");
    return make_contact(true, wrench, 3, lim);
  }
  if (!(keys & (kAt | kNormal)))
    r.fail("expected \"at\" and \"normal\" (a point contact) or \"wrench\"");
  if (!(keys & kAt)) r.fail("missing required key \"at\"");
  if (!(keys & kNormal)) r.fail("missing required key \"normal\"");
  if (!(keys & kMu) && Tally::reading) {  // an absent mu counts as its "0" (docs/scene-format.md "Limits")
    try {
      Tally::reading->number(1, lim);
    } catch (const Failure& f) {
      r.fail(f.message.substr(2));
    }
  }
  if (!(keys & kMu) && no_mu) *no_mu = std::array<Read_number, 5>{point[0], point[1], point[2], point[3], point[4]};
  return make_contact(false, point, 5, lim);
}

// n numbers, read exactly into out[0..n).
void read_vector(Reader& r, const Limits& lim, std::size_t n, Q* out) {
  read_fixed(r, n, numbers_text(n),
             [&](std::size_t k) { out[k] = read_number(r, lim); });
}

// {"outline"?: [points], "com"?: [x, y]}. com is used by a gravity load, the outline by placed contacts (the
// engine checks the outline and every contact against it; the checker draws nothing).
void read_body(Reader& r, const Limits& lim, bool& has_com, Q (&com)[2], std::vector<std::array<Q, 2>>& outline,
               bool& outline_valid) {
  begin_object(r, "expected an object");
  std::string_view key;
  while (r.next_key(key)) {
    if (key == "outline") {  // limited and counted in the budget like every point; kept for placed contacts
      begin_array(r, "expected an array of points");
      outline.clear();
      outline_valid = true;
      for (std::size_t points = 0; r.next_item(); ++points) {
        if (points == lim.max_contacts)
          throw Failure{"body.outline: more than " + std::to_string(lim.max_contacts) + " points"};
        if (r.peek() != Kind::array) {
          r.skip();
          outline_valid = false;
          continue;
        }
        r.begin_array();
        std::vector<Q> xy;
        while (r.next_item()) {
          const Kind k = r.peek();
          if (k != Kind::number && k != Kind::string) {
            r.skip();
            outline_valid = false;
            continue;
          }
          const std::string_view s = k == Kind::number ? r.number() : r.string_view();
          Number_text t;
          try {  // a valid number counts (the engine refuses an invalid one; the checker ignores it)
            t = number_text(s, lim, "");
          } catch (const Failure&) {
            outline_valid = false;
            continue;
          }
          try {
            if (Tally::reading) Tally::reading->number(t.counted, lim);
          } catch (const Failure& f) {
            throw Failure{r.path() + f.message};
          }
          xy.push_back(scene_number(s, lim, ""));
        }
        if (xy.size() == 2) outline.push_back({xy[0], xy[1]});
        else outline_valid = false;
      }
    } else if (key == "com") {
      read_vector(r, lim, 2, com);
      has_com = true;
    } else {
      r.fail("unknown key " + quote(key), true);
    }
  }
}

// The scene's load as written; its wrench w_ext is computed once the whole scene is read (gravity
// acts at body.com, and "body" may come after "load").
struct Load {
  enum class Form { none, force, wrench, gravity } form = Form::none;
  Q force[2], at[2], wrench[3], weight;
};

// Exactly one of {"force": [fx, fy], "at": [x, y]}, {"wrench": [fx, fy, m]}, {"gravity": w} with w > 0.
// Which form is meant is decided as the engine does (gravity, else wrench, else force/at); any other
// key, including one of another form, is an unknown key.
Load read_load(Reader& r, const Limits& lim) {
  const char* const forms = "{\"force\", \"at\"}, {\"wrench\"} or {\"gravity\"}";
  if (r.peek() != Kind::object) r.fail(std::string("expected an object ") + forms);
  r.begin_object();
  Load load;
  std::vector<std::string> keys;  // in the order written
  std::string_view key;
  while (r.next_key(key)) {
    keys.emplace_back(key);
    if (key == "force") {
      read_vector(r, lim, 2, load.force);
    } else if (key == "at") {
      read_vector(r, lim, 2, load.at);
    } else if (key == "wrench") {
      read_vector(r, lim, 3, load.wrench);
    } else if (key == "gravity") {
      std::string text;
      load.weight = read_number(r, lim, &text);
      if (load.weight <= 0) r.fail(quote(text) + " is not positive (a weight must be > 0)");
    } else {
      r.fail("unknown key " + quote(key), true);
    }
  }
  // The object is closed: r.fail() now names "load" itself.
  auto has = [&keys](const char* k) { return std::find(keys.begin(), keys.end(), k) != keys.end(); };
  std::set<std::string> form;  // the keys of the form meant
  if (has("gravity"))
    load.form = Load::Form::gravity, form = {"gravity"};
  else if (has("wrench"))
    load.form = Load::Form::wrench, form = {"wrench"};
  else if (has("force") || has("at"))
    load.form = Load::Form::force, form = {"force", "at"};
  else
    r.fail(std::string("expected one of ") + forms);
  for (const std::string& k : keys)
    if (!form.count(k)) r.fail("unknown key " + quote(k));
  for (const std::string& k : form)
    if (!has(k.c_str())) r.fail("missing required key " + quote(k));
  return load;
}

// The point's values: the kept ones (no copy), or read again from their text into `scratch` (valid: read before).
const Point_values& values(const Support_point& p, const Limits& lim, Point_values& scratch) {
  if (p.kept) return p.value;
  auto q = [&](std::size_t k) { return p.text[k].empty() ? Q(0) : scene_number(p.text[k], lim, "support"); };
  scratch = {q(0), q(1), q(2), q(3)};
  return scratch;
}

// {"mu"?, "weight"?, "pressure_center"?, "points": [{"at": [x, y], "force"?: f, "mu"?: mu}, ...]}
// (docs/scene-format.md). Every number is read exactly and checked: forces, weights and mu >= 0.
Support read_support(Reader& r, const Limits& lim) {
  begin_object(r, "expected an object");
  Support s;
  bool has_mu = false, has_points = false;
  std::string mu_text;
  std::string_view key;
  struct Raw {  // what a point needs until support.mu (which may follow) is known
    bool has_mu = false, positive = false;  // positive: a given force > 0
  };
  std::vector<Raw> raw;          // one per point of s.points
  std::string points_path;       // the points' array ("support.points"): point i is points_path + "[i]"
  const auto point_path = [&](std::size_t i) { return points_path + "[" + std::to_string(i) + "]"; };
  while (r.next_key(key)) {
    if (key == "mu") {
      if (read_number(r, lim, &mu_text) < 0) r.fail(quote(mu_text) + " is negative");
      has_mu = true;
    } else if (key == "weight") {
      std::string text;
      s.weight = read_number(r, lim, &text);
      if (s.weight <= 0) r.fail(quote(text) + " is not positive (a weight must be > 0)");
      s.has_weight = true;
    } else if (key == "pressure_center") {
      read_vector(r, lim, 2, s.center);
      s.has_center = true;
    } else if (key == "regions") {
      begin_array(r, "expected an array");
      std::size_t vertices = 0;
      while (r.next_item()) s.regions.push_back(read_region(r, lim, vertices));
    } else if (key == "points") {
      has_points = true;
      begin_array(r, "expected an array");
      while (r.next_item()) {
        if (raw.size() == lim.max_contacts)
          throw Failure{"support.points: more than " + std::to_string(lim.max_contacts) + " points"};
        if (Tally::reading) Tally::reading->entry("support.points", raw.size(), lim);
        Raw p;
        if (raw.empty()) {  // the first point's path ends in "[0]" (json.cpp Reader::path): the array's is before it
          points_path = r.path();
          points_path.resize(points_path.size() - 3);
        }
        begin_object(r, "expected an object {\"at\", \"force\"?, \"mu\"?}");
        std::string_view point_key;
        // x, y, mu, force as read (validated and counted; "0" where absent: mu until support.mu is known)
        Read_number n[4];
        bool has_at = false, has_force = false;
        while (r.next_key(point_key)) {
          if (point_key == "at") {
            read_numbers(r, lim, 2, n);
            has_at = true;
          } else if (point_key == "force") {
            n[3] = read_contact_number(r, lim);
            if (n[3].negative) r.fail(quote(n[3].text) + " is negative");
            has_force = true;
          } else if (point_key == "mu") {
            n[2] = read_contact_number(r, lim);
            if (n[2].negative) r.fail(quote(n[2].text) + " is negative");
            p.has_mu = true;
          } else {
            r.fail("unknown key " + quote(point_key), true);
          }
        }
        if (!has_at) r.fail("missing required key \"at\"");
        Support_point& sp = s.points.emplace_back();
        sp.known = has_force;
        p.positive = has_force && !n[3].zero && !n[3].negative;
        // the values kept if all are small (mu 0 until support.mu is known); the texts only when not
        Q* const value[4] = {&sp.value.x, &sp.value.y, &sp.value.mu, &sp.value.f};
        for (std::size_t k = 0; k < 4; ++k)
          if (n[k].fits) set_small(*value[k], n[k].value);
          else *value[k] = scene_number(n[k].text, lim, "support");  // valid: read before
        sp.kept = small(sp.value.x) && small(sp.value.y) && small(sp.value.mu) && small(sp.value.f);
        if (!sp.kept || !p.has_mu)  // (support.mu, read later, may make the point's values not kept)
          for (std::size_t k = 0; k < 4; ++k)
            if (k != 2 || p.has_mu) sp.text[k] = std::string(k == 3 && !has_force ? std::string_view() : n[k].text);
        raw.push_back(p);
      }
    } else {
      r.fail("unknown key " + quote(key), true);
    }
  }
  if (!has_points && s.regions.empty()) r.fail("missing required key \"points\" (a support needs points or regions)");
  if (raw.empty() && s.regions.empty()) throw Failure{"support.points: empty (a support needs at least one point or region)"};
  const Q support_mu = has_mu ? scene_number(mu_text, lim, "support.mu") : Q(0);
  bool any_force = false;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    const Raw& p = raw[i];
    Support_point& sp = s.points[i];
    if (!p.has_mu && !has_mu) throw Failure{point_path(i) + ": missing key \"mu\" (and support.mu gives no default)"};
    if (!p.has_mu) {
      sp.text[2] = mu_text;
      if (sp.kept) sp.value.mu = support_mu;
      if (!small(support_mu)) sp.kept = false;
    }
    any_force = any_force || p.positive;
    s.unknown += sp.known ? 0 : 1;
  }
  if (s.unknown == 0 && !any_force && s.regions.empty()) throw Failure{"support.points: all forces are zero"};
  for (Region& g : s.regions) {
    if (!g.has_mu && !has_mu) throw Failure{g.path + ": missing key \"mu\" (and support.mu gives no default)"};
    if (!g.has_mu) g.mu = support_mu;
    settle_region(g);
  }
  return s;
}

// The distribution's condition of F once the whole scene is read (body.com may follow support): W and
// c, and an empty F reported in words. F is not empty iff rest_weight >= 0 and the point
// rest_moment / rest_weight lies in the convex hull of the points without a given force (or
// rest_weight = 0 and rest_moment = 0, when they all carry nothing).
void settle_support(Support& s, bool has_com, const Q (&com)[2], const Limits& lim) {
  // Every force given and neither weight nor pressure_center written: nothing to agree with, and W is not needed
  // (only in_f uses it, for a distribution chosen in F: some force unknown).
  if (s.unknown == 0 && !s.has_weight && !s.has_center) return;
  Q sum = 0, moment[2] = {0, 0};
  for (const Support_point& p : s.points) {
    if (!p.known) continue;
    Point_values scratch;
    const Point_values& v = values(p, lim, scratch);
    sum += v.f, moment[0] += v.f * v.x, moment[1] += v.f * v.y;
  }
  for (const Region& g : s.regions) sum += g.W, moment[0] += g.M[0], moment[1] += g.M[1];  // a known pressure
  if (s.unknown == 0) {  // a known distribution: weight and pressure_center, if given, must agree
    s.W = s.has_weight ? s.weight : sum;
    if (s.has_weight && s.weight != sum)
      throw Failure{"support.weight: " + show(s.weight) + " is not the sum " + show(sum) + " of the given forces"};
    if (s.has_center && (s.W * s.center[0] != moment[0] || s.W * s.center[1] != moment[1]))
      throw Failure{"support.pressure_center: " + show(s.center[0], s.center[1]) +
                    " is not the centre of pressure " + show(moment[0] / sum, moment[1] / sum) +
                    " of the given forces"};
    return;
  }
  if (!s.has_weight) throw Failure{"support: missing key \"weight\" (required when a point has no \"force\")"};
  if (!s.has_center && !has_com)
    throw Failure{"support: missing key \"pressure_center\" (required when a point has no \"force\" and body.com "
                  "is not given)"};
  s.W = s.weight;
  for (int k = 0; k < 2; ++k) s.c[k] = s.has_center ? s.center[k] : com[k];
  s.rest_weight = s.W - sum;
  for (int k = 0; k < 2; ++k) s.rest_moment[k] = s.W * s.c[k] - moment[k];
  const std::string none = "support: no admissible distribution: ";
  if (s.rest_weight < 0)
    throw Failure{none + "the given forces sum to " + show(sum) + ", more than support.weight " + show(s.W)};
  if (s.rest_weight == 0) {
    if (s.rest_moment[0] != 0 || s.rest_moment[1] != 0)
      throw Failure{none + "the given forces carry the whole weight " + show(s.W) + ", but their centre of pressure " +
                    show(moment[0] / sum, moment[1] / sum) + " is not the centre of pressure " + show(s.c[0], s.c[1])};
    return;
  }
  // Is 0 in the convex hull of d_i = rest_weight r_i - rest_moment (i unknown)? Equivalently: do the
  // d_i fail to fit in an open half-plane? One pass keeps the smallest cone [R, L] (counter-clockwise
  // from R to L, angle < pi) holding every d_i so far; a d_i that cannot join it with an angle < pi
  // (or d_i = 0) puts 0 in the hull (separation: 0 outside a compact convex set means an open
  // half-plane holds it). Only signs of cross and dot products: exact, no angles.
  auto cross = [](const Q(&a)[2], const Q(&b)[2]) { return sgn(Q(a[0] * b[1] - a[1] * b[0])); };
  auto dot = [](const Q(&a)[2], const Q(&b)[2]) { return sgn(Q(a[0] * b[0] + a[1] * b[1])); };
  bool inside = false, started = false;
  Q R[2], L[2];
  for (std::size_t i = 0; i < s.points.size() && !inside; ++i) {
    if (s.points[i].known) continue;
    Point_values scratch;
    const Point_values& v = values(s.points[i], lim, scratch);
    const Q d[2] = {s.rest_weight * v.x - s.rest_moment[0], s.rest_weight * v.y - s.rest_moment[1]};
    if (d[0] == 0 && d[1] == 0) {
      inside = true;
    } else if (!started) {
      started = true, R[0] = L[0] = d[0], R[1] = L[1] = d[1];
    } else if ((cross(R, d) == 0 && dot(R, d) < 0) || (cross(L, d) == 0 && dot(L, d) < 0)) {
      inside = true;  // opposite to a direction held: 0 on the segment between them
    } else if (cross(R, d) < 0) {  // clockwise of R: R moves to d if the cone stays below pi
      if (cross(d, L) > 0) R[0] = d[0], R[1] = d[1];
      else inside = true;
    } else if (cross(d, L) < 0) {  // counter-clockwise of L
      if (cross(R, d) > 0) L[0] = d[0], L[1] = d[1];
      else inside = true;
    }  // else d is in the cone already
  }
  if (inside) return;
  const Q cx = s.rest_moment[0] / s.rest_weight, cy = s.rest_moment[1] / s.rest_weight;
  if (s.unknown == s.points.size())
    throw Failure{none + "the centre of pressure " + show(cx, cy) +
                  " is outside the convex hull of the support points (the body would tip over)"};
  throw Failure{none + "the points without a given force must carry the remaining weight " + show(s.rest_weight) +
                " with its centre at " + show(cx, cy) + ", which is outside their convex hull"};
}
// A placed contact made: edge i of the outline (an integer 0..n-1), t in [0, 1], the point v_i + t (v_{i+1} - v_i),
// the normal as given or rot90(v_{i+1} - v_i) toward the inside (the outline's signed area tells the side), mu as
// written, else the scene's, else 0 — the engine's rule (exact/io/outline.h).
void place_contact(Contact& c, const Placed& p, const std::vector<std::array<Q, 2>>& V, bool valid,
                   const std::optional<Read_number>& scene_mu, const Limits& lim, const char* name = nullptr) {
  const std::string path = name ? std::string(name) : "contacts[" + std::to_string(p.index) + "]";
  if (V.size() < 3 || !valid) throw Failure{path + ".edge: needs body.outline, a polygon of points"};
  if (p.edge.get_den() != 1 || sgn(p.edge) < 0 || p.edge >= static_cast<long>(V.size()))
    throw Failure{path + ".edge: " + show(p.edge) + " is not an edge of body.outline"};
  if (sgn(p.s) < 0 || p.s > 1) throw Failure{path + ".s: " + show(p.s) + " is not in [0, 1]"};
  const std::size_t i = p.edge.get_num().get_ui(), j = (i + 1) % V.size();
  const Q dx = V[j][0] - V[i][0], dy = V[j][1] - V[i][1];
  std::string text[5] = {Q(V[i][0] + p.s * dx).get_str(), Q(V[i][1] + p.s * dy).get_str(), "", "", "0"};
  if (p.has_normal) {
    text[2] = std::string(p.normal[0].text), text[3] = std::string(p.normal[1].text);
  } else {
    Q area2 = 0;
    for (std::size_t k = 0; k < V.size(); ++k) area2 += V[k][0] * V[(k + 1) % V.size()][1] - V[(k + 1) % V.size()][0] * V[k][1];
    if (sgn(area2) == 0) throw Failure{"body.outline: zero area (no inward normal for " + path + ")"};
    text[2] = Q(sgn(area2) > 0 ? -dy : dy).get_str(), text[3] = Q(sgn(area2) > 0 ? dx : -dx).get_str();
  }
  if (p.has_mu) text[4] = std::string(p.mu.text);
  else if (scene_mu) text[4] = std::string(scene_mu->text);
  Read_number n[5];
  for (int k = 0; k < 5; ++k) {
    const Number_text t = number_text(text[k], lim, path);
    n[k].text = text[k];
    n[k].zero = is_zero(t);
    n[k].negative = t.negative && !n[k].zero;
    n[k].fits = small_value(t, n[k].value);
  }
  if (n[2].zero && n[3].zero) throw Failure{path + ".normal: zero vector"};
  c = make_contact(false, n, 5, lim);
}

// The top-level scene object. body is read for body.com, load for w_ext, support for the sliding
// certificates (§6); an empty admissible set F is a bad scene.
Scene read_scene(Reader& r, const Limits& lim) {
  Scene scene;
  begin_object(r, "a scene must be a JSON object");
  bool has_version = false, has_com = false;
  struct Body {
    Q com[2];
  };
  std::optional<Body> body;  // (rationals only for the members present: each costs an allocation)
  std::optional<Load> load;
  std::optional<Read_number> scene_mu;  // the scene-wide "mu" (docs/scene-format.md)
  std::vector<std::pair<std::size_t, std::array<Read_number, 5>>> without_mu;  // point contacts that take it
  std::vector<Placed> placed;
  std::optional<std::array<Read_number, 5>> pusher_no_mu;
  std::optional<Placed> pusher_place;
  std::vector<std::array<Q, 2>> outline;
  bool outline_valid = false;
  std::string_view key;
  while (r.next_key(key)) {
    if (key == "mu") {
      scene_mu = read_contact_number(r, lim);
      if (scene_mu->negative) r.fail(quote(scene_mu->text) + " is negative");
    } else if (key == "wrenchkit") {
      const Read_number v = read_contact_number(r, lim);
      if (v.fits ? v.value.num != v.value.den : scene_number(v.text, lim, "") != 1)
        r.fail("expected 1 (the scene format version)");
      has_version = true;
    } else if (key == "name") {
      read_string(r);
    } else if (key == "body") {
      read_body(r, lim, has_com, body.emplace().com, outline, outline_valid);
    } else if (key == "load") {
      load = read_load(r, lim);
    } else if (key == "support") {
      scene.support = read_support(r, lim);
    } else if (key == "pusher") {  // a point contact with "velocity" (docs/scene-format.md "The pusher")
      Pusher& p = scene.pusher.emplace();
      p.contact = read_contact(r, lim, &pusher_no_mu, &pusher_place, &p);
      if (!p.has_velocity) r.fail("missing required key \"velocity\"");
      if (p.contact.wrench) r.fail("the pusher is a point contact, not a wrench");
      if (p.has_omega && !p.line) r.fail("\"omega\" is a line contact's (with \"segment\")");
      if (p.line && pusher_place) r.fail("a line contact has \"segment\", not \"edge\" and \"s\"");
    } else if (key == "contacts") {
      begin_array(r, "expected an array");
      while (r.next_item()) {
        if (scene.contacts.size() == lim.max_contacts)
          throw Failure{"contacts: more than " + std::to_string(lim.max_contacts) + " contacts"};
        if (Tally::reading) Tally::reading->entry("contacts", scene.contacts.size(), lim);
        std::optional<std::array<Read_number, 5>> no_mu;
        std::optional<Placed> place;
        scene.contacts.push_back(read_contact(r, lim, &no_mu, &place));
        if (no_mu) without_mu.emplace_back(scene.contacts.size() - 1, *no_mu);
        if (place) place->index = scene.contacts.size() - 1, placed.push_back(std::move(*place));
      }
    } else {
      r.fail("unknown key " + quote(key), true);
    }
  }
  if (!has_version) r.fail("missing required key \"wrenchkit\"");
  if (scene_mu)
    for (auto& [i, numbers] : without_mu) {
      numbers[4] = *scene_mu;
      scene.contacts[i] = make_contact(false, numbers.data(), 5, lim);
    }
  for (const Placed& p : placed) place_contact(scene.contacts[p.index], p, outline, outline_valid, scene_mu, lim);
  if (scene.pusher) {
    if (scene_mu && pusher_no_mu) {
      (*pusher_no_mu)[4] = *scene_mu;
      scene.pusher->contact = make_contact(false, pusher_no_mu->data(), 5, lim);
    }
    if (pusher_place) place_contact(scene.pusher->contact, *pusher_place, outline, outline_valid, scene_mu, lim, "pusher");
  }
  scene.outline = std::move(outline), scene.outline_valid = outline_valid;
  // Gravity beside a support is the weight pressing the body on it (scene-format.md): it sets W and, at body.com,
  // the centre of pressure c, and pushes nothing in the plane. A written weight or pressure_center must agree.
  const bool across = scene.support && load && load->form == Load::Form::gravity;
  if (across) {
    Support& s = *scene.support;
    if (!has_com) throw Failure{"load.gravity: needs body.com (the point where the weight acts)"};
    if (s.has_weight && s.weight != load->weight)
      throw Failure{"load.gravity: the weight " + show(load->weight) + " is not support.weight " + show(s.weight)};
    if (s.has_center && (s.center[0] != body->com[0] || s.center[1] != body->com[1]))
      throw Failure{"support.pressure_center: " + show(s.center[0], s.center[1]) + " is not body.com " +
                    show(body->com[0], body->com[1]) + ", where the weight acts"};
    s.weight = load->weight, s.has_weight = true;
    s.center[0] = body->com[0], s.center[1] = body->com[1], s.has_center = true;
  }
  if (scene.support) {
    if (has_com) settle_support(*scene.support, true, body->com, lim);
    else settle_support(*scene.support, false, Body{}.com, lim);
  }
  if (!load) return scene;
  // w_ext (theory.md §9): W(p, f) = (fx, fy, x*fy - y*fx); gravity w at com is W(com, (0, -w)) = (0, -w, -w*com_x)
  scene.has_load = load->form != Load::Form::none;
  switch (load->form) {
    case Load::Form::none: break;
    case Load::Form::force:
      scene.load = Wrench{load->force[0], load->force[1], load->at[0] * load->force[1] - load->at[1] * load->force[0]};
      break;
    case Load::Form::wrench: scene.load = Wrench{load->wrench[0], load->wrench[1], load->wrench[2]}; break;
    case Load::Form::gravity:
      if (!has_com) throw Failure{"load.gravity: needs body.com (the point where the weight acts)"};
      if (across) scene.load = Wrench{0, 0, 0};  // across the support: nothing in the plane
      else scene.load = Wrench{0, -load->weight, -load->weight * body->com[0]};
      break;
  }
  return scene;
}

// The scene, or the bad_scene result that check() gives for it.
bool read_whole_scene(std::string_view scene_json, const Limits& limits, Scene& scene, Result& bad) {
  Tally tally;  // the scene-wide budget, counted while the scene is read
  struct Counting {
    explicit Counting(Tally& t) { Tally::reading = &t; }
    ~Counting() { Tally::reading = nullptr; }
  } counting(tally);
  try {
    Reader r(scene_json, limits.max_depth);
    scene = read_scene(r, limits);
    r.finish();
    scene.longest = tally.longest;
    return true;
  } catch (const Failure& f) {
    bad = {Outcome::bad_scene, f.message};
  } catch (const std::bad_alloc&) {
    bad = {Outcome::bad_scene, "out of memory while reading the scene"};
  } catch (...) {  // not expected; check() never throws
    bad = {Outcome::bad_scene, "internal error while reading the scene"};
  }
  return false;
}
}  // namespace wrenchkit_checker::detail
