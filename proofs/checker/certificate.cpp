// proofs/checker/certificate.cpp - reading the certificate object (certificate-format.md §2 numbers, §3 keys,
// §6.1, §6.4 blocks, §7.1): every key known, every value of its type; which keys a claim needs is checked by
// check_keys() (§3, §3.3) or by the motion and hold checks, which know the scene's support.
#include "proofs/checker/certificate.h"

#include <set>

namespace wrenchkit_checker::detail {

const Motion_part& members(const Certificate& c) {
  static const Motion_part none;
  return c.motion_members ? *c.motion_members : none;
}

// A certificate rational's text (a JSON string, its grammar checked; a view valid while the reader is).
std::string_view read_rational_text(Reader& r) {  // (certificate.h)
  if (r.peek() != Kind::string) r.fail("expected a rational as a JSON string, such as \"-3/4\"");
  const std::string_view s = r.string_view();
  if (!rational_grammar(s)) not_a_rational(s, r.path());
  return s;
}
Q read_rational(Reader& r) { return rational_value(read_rational_text(r)); }

std::size_t read_index(Reader& r, const char* what) {
  if (r.peek() != Kind::number) r.fail(std::string("expected a ") + what + " (a JSON integer)");
  const std::string t(r.number());
  if (t.find_first_not_of("0123456789") != std::string::npos || t.size() > 18)
    r.fail(std::string("expected a ") + what + ": a JSON integer without sign, fraction or exponent, not " + clip(t));
  unsigned long long v = 0;
  for (const char d : t) v = v * 10 + static_cast<unsigned>(d - '0');
  return v < SIZE_MAX ? static_cast<std::size_t>(v) : SIZE_MAX;
}

// The members of property "quality" (§3.4): "epsilon" {"lower", "upper", "squared"?}, "scales" [{"scale", "error",
// "bound"}, …], index triples.
void read_epsilon(Reader& r, Quality_part& q) {
  begin_object(r, "expected an object {\"lower\", \"upper\", \"squared\"}");
  bool lower = false, upper = false;
  std::string_view key;
  while (r.next_key(key)) {
    if (key == "lower") lower = true, q.lower = read_rational(r);
    else if (key == "upper") upper = true, q.upper = read_rational(r);
    else if (key == "squared") q.has_squared = true, q.squared = read_rational(r);
    else r.fail("unknown key " + quote(key), true);
  }
  if (!lower) r.fail("missing required key \"lower\"");
  if (!upper) r.fail("missing required key \"upper\"");
}
void read_scales(Reader& r, Quality_part& q) {
  begin_array(r, "expected an array of {\"scale\", \"error\", \"bound\"}, one per contact");
  while (r.next_item()) {
    Quality_part::Scale& s = q.scales.emplace_back();
    begin_object(r, "expected an object {\"scale\", \"error\", \"bound\"}");
    unsigned keys = 0;
    std::string_view key;
    while (r.next_key(key)) {
      if (key == "scale") keys |= 1, s.scale = read_rational(r);
      else if (key == "error") keys |= 2, s.error = read_rational(r);
      else if (key == "bound") keys |= 4, s.bound = read_rational(r);
      else if (key == "moment_bound") s.has_moment_bound = true, s.moment_bound = read_rational(r);
      else r.fail("unknown key " + quote(key), true);
    }
    if (keys != 7) r.fail("expected the keys \"scale\", \"error\" and \"bound\"");
  }
}
void read_triple(Reader& r, std::array<std::size_t, 3>& t) {
  read_fixed(r, 3, "an array of three generator indices [i, j, k]", [&](std::size_t k) { t[k] = read_index(r, "generator index"); });
}

// {"contact": i, "edge": E} and, if weighted, "weight": "p/q".
Term read_term(Reader& r, bool weighted, const char* list, std::size_t item) {
  Term t;
  t.ref.list = list, t.ref.item = item;
  begin_object(r, weighted ? "expected an object {\"contact\", \"edge\", \"weight\"}" : "expected an object {\"contact\", \"edge\"}");
  enum : unsigned { kContact = 1, kEdge = 2, kWeight = 4 };
  unsigned keys = 0;  // the keys present
  std::string_view key;
  while (r.next_key(key)) {
    if (key == "contact") {
      keys |= kContact;
      if (r.peek() != Kind::number) r.fail("expected a contact index (a JSON integer)");
      t.ref.index = r.number();
      if (t.ref.index.find_first_not_of("0123456789") != std::string::npos)
        r.fail("expected a contact index: a JSON integer without sign, fraction or exponent, not " +
               clip(std::string(t.ref.index)));
      if (t.ref.index.size() <= 18) {  // no overflow; a longer index is out of range anyway
        unsigned long long v = 0;
        for (const char d : t.ref.index) v = v * 10 + static_cast<unsigned>(d - '0');
        t.ref.contact = v < SIZE_MAX ? static_cast<std::size_t>(v) : SIZE_MAX;
      }
    } else if (key == "edge") {
      keys |= kEdge;
      if (r.peek() != Kind::string) r.fail("expected a string");
      t.ref.edge = r.string_view();
    } else if (key == "weight" && weighted) {
      keys |= kWeight;
      t.weight = read_rational_text(r);
    } else {
      r.fail("unknown key " + quote(key), true);
    }
  }
  if (!(keys & kContact)) r.fail("missing required key \"contact\"");
  if (!(keys & kEdge)) r.fail("missing required key \"edge\"");
  if (weighted && !(keys & kWeight)) r.fail("missing required key \"weight\"");
  return t;
}

// An array of rationals, or of [x, y] pairs of rationals, of any length.
template <class T>
std::vector<T> read_list(Reader& r) {
  begin_array(r, std::is_same_v<T, Q> ? "expected an array of rationals" : "expected an array of [gx, gy] pairs of rationals");
  std::vector<T> out;
  out.reserve(16);  // (a reallocation copies the rationals: room for 16 at once, then doubling)
  while (r.next_item()) {
    if constexpr (std::is_same_v<T, Q>) out.push_back(read_rational(r));
    else read_fixed(r, 2, "an array of two rationals [gx, gy]", [&, &p = out.emplace_back()](std::size_t k) { p[k] = read_rational(r); });
  }
  return out;
}

// A stick witness {"distribution", "support_forces"} or (slide) a slide witness {"distribution",
// "twist", "speed_bounds"}: exactly these keys; a stick witness may also hold "combination" (a hold witness,
// §7: which keys a property allows is checked once the property is known).
Block read_block(Reader& r);

Witness read_witness(Reader& r, bool slide) {
  Witness w;
  w.path = r.path();
  const char* const what = slide ? "expected an object {\"distribution\", \"twist\", \"speed_bounds\"}"
                                 : "expected an object {\"distribution\", \"support_forces\"}";
  begin_object(r, what);
  std::set<std::string> keys;
  std::string_view key;
  while (r.next_key(key)) {
    keys.insert(std::string(key));
    if (key == "distribution") {
      w.distribution = read_list<Q>(r);
    } else if (key == "support_forces" && !slide) {
      w.forces = read_list<Pair>(r);
    } else if (key == "combination" && !slide) {
      begin_array(r, "expected an array of {\"contact\", \"edge\", \"weight\"}");
      while (r.next_item()) {
        w.combination.push_back(read_term(r, true, "combination", w.combination.size()));
        w.combination.back().ref.owner = w.path + ".";
      }
      w.has_combination = true;
    } else if (key == "twist" && slide) {
      read_fixed(r, 3, "an array of three rationals [vx, vy, w]", [&](std::size_t k) { w.twist[k] = read_rational(r); });
    } else if (key == "speed_bounds" && slide) {
      w.speeds = read_list<Q>(r);
    } else if (key == "regions") {  // format 2 only (§6.5, §7.5: checked with the scene)
      begin_array(r, "expected an array of region blocks (one per support region)");
      while (r.next_item()) w.regions.push_back(read_block(r));
      w.has_regions = true;
    } else {
      r.fail("unknown key " + quote(key), true);
    }
  }
  for (const char* k : slide ? std::vector<const char*>{"distribution", "twist", "speed_bounds"}
                             : std::vector<const char*>{"distribution", "support_forces"})
    if (!keys.count(k)) r.fail(std::string("missing required key \"") + k + "\"");
  return w;
}

// {"vertices": [[x, y], ...], "triangles": [[i, j, k], ...], "forces": [[gx, gy], ...]} or with "speed_bounds":
// [u, ...] instead of "forces" (§6.4), or both (§6.6: which a claim needs is checked with it); indices are JSON
// integers without sign, fraction or exponent.
Block read_block(Reader& r) {
  Block b;
  b.path = r.path();
  begin_object(r, "expected an object {\"vertices\", \"triangles\", \"forces\" or \"speed_bounds\"}");
  std::set<std::string> keys;
  std::string_view key;
  while (r.next_key(key)) {
    keys.insert(std::string(key));
    if (key == "vertices") {
      for (const Pair& v : read_list<Pair>(r)) b.vertices.push_back({v[0], v[1]});
    } else if (key == "triangles") {
      begin_array(r, "expected an array of [i, j, k] vertex indices");
      while (r.next_item()) {
        b.triangles.emplace_back();
        read_fixed(r, 3, "an array of three vertex indices [i, j, k]", [&](std::size_t k) {
          b.triangles.back()[k] = read_index(r, "vertex index");
        });
      }
    } else if (key == "forces") {
      b.forces = read_list<Pair>(r);
      b.has_forces = true;
    } else if (key == "speed_bounds") {
      b.speeds = read_list<Q>(r);
      b.has_speeds = true;
    } else {
      r.fail("unknown key " + quote(key), true);
    }
  }
  for (const char* k : {"vertices", "triangles"})
    if (!keys.count(k)) r.fail(std::string("missing required key \"") + k + "\"");
  if (!b.has_forces && !b.has_speeds)
    r.fail("expected \"forces\" (sticks), \"speed_bounds\" (slides), or both (a load on the limit surface, format 3)");
  return b;
}

// {"label": "+" | "-", "point": [x, y]} or {"label": "infinity", "direction": [dx, dy]}
void read_reading(Reader& r, Certificate& c) {
  begin_object(r, "expected an object {\"label\", \"point\"} or {\"label\", \"direction\"}");
  bool label = false, point = false, direction = false;  // the keys present
  std::string_view key;
  while (r.next_key(key)) {
    if (key == "label") {
      label = true;
      c.label = r.peek() == Kind::string ? r.string_view() : "";
      if (c.label != "+" && c.label != "-" && c.label != "infinity") r.fail("expected \"+\", \"-\" or \"infinity\"");
    } else if (key == "point" || key == "direction") {
      (key == "point" ? point : direction) = true;
      read_fixed(r, 2, "an array of two rationals", [&](std::size_t k) { c.where[k] = read_rational_text(r); });
    } else {
      r.fail("unknown key " + quote(key), true);
    }
  }
  if (!label) r.fail("missing required key \"label\"");
  const bool infinite = c.label == "infinity";
  if (infinite ? point || !direction : !point || direction)
    r.fail(infinite ? "label \"infinity\" needs \"direction\" and no \"point\""
                    : "label " + quote(c.label) + " needs \"point\" and no \"direction\"");
}

Certificate read_certificate(Reader& r) {
  Certificate c;
  begin_object(r, "a certificate must be a JSON object");
  // An empty combination is allowed for "equilibrium" only; if "property" comes after
  // "combination", that is decided once the whole object is read.
  const std::string non_empty = "expected a non-empty array of {\"contact\", \"edge\", \"weight\"}";
  bool empty_combination = false;
  std::string_view key;
  while (r.next_key(key)) {
    c.keys.insert(key);
    if (key == "wrenchkit_certificate") {
      const std::string_view v = r.peek() == Kind::number ? r.number() : "";
      if (v != "1" && v != "2" && v != "3" && v != "4" && v != "5" && v != "6")
        r.fail("expected the integer 1, 2, 3, 4, 5 or 6");
      c.version = v[0] - '0';
    } else if (key == "property") {
      const std::string_view p = r.peek() == Kind::string ? r.string_view() : "";
      if (p != "force_closure" && p != "form_closure" && p != "equilibrium" && p != "motion" && p != "hold" &&
          p != "quality" && p != "critical_mu" && p != "grasp_regions" && p != "push")
        r.fail("expected \"force_closure\", \"form_closure\", \"equilibrium\", \"motion\", \"hold\", \"quality\", "
               "\"critical_mu\", \"grasp_regions\" or \"push\"");
      c.property = p;
      c.reading = p == "form_closure" ? Reading::frictionless : Reading::friction;
      c.equilibrium = p == "equilibrium";
      c.motion = p == "motion";
      c.hold = p == "hold";
      c.quality = p == "quality";
      c.critical = p == "critical_mu";
      c.regions = p == "grasp_regions";
      c.push = p == "push";
    } else if (key == "fingers" || key == "mu" || key == "edges" || key == "pairs" || key == "triples") {
      read_region_member(r, key, c);
    } else if (key == "rotation" || key == "friction" || key == "votes" || key == "center" || key == "turns" ||
               key == "contact" || key == "stable" || key == "region" || key == "locus") {
      read_push_member(r, key, c);
    } else if (key == "holds") {
      if (r.peek() == Kind::string) {  // property "hold" only (checked once the property is known)
        const std::string_view v = r.string_view();
        if (v != "depends" && v != "impending")
          r.fail("expected true or false (or \"impending\" or \"depends\" for property \"hold\")");
        (v == "depends" ? c.depends : c.impending) = true;
      } else {
        if (r.peek() != Kind::boolean) r.fail("expected true or false");
        c.holds = r.boolean();
      }
    } else if (key == "combination") {
      if (r.peek() != Kind::array)
        r.fail(c.equilibrium ? "expected an array of {\"contact\", \"edge\", \"weight\"}" : non_empty);
      r.begin_array();
      c.combination.reserve(8);
      while (r.next_item()) c.combination.push_back(read_term(r, true, "combination", c.combination.size()));
      if (c.combination.empty() && c.keys.count("property") && !c.equilibrium && !c.hold) r.fail(non_empty);
      empty_combination = c.combination.empty();
    } else if (key == "independent") {
      read_fixed(r, 3, "an array of three {\"contact\", \"edge\"}",
                 [&](std::size_t k) { c.independent.push_back(read_term(r, false, "independent", k).ref); });
    } else if (key == "twist") {
      read_fixed(r, 3, "an array of three rationals [vx, vy, w]",
                 [&](std::size_t k) { c.twist[k] = read_rational_text(r); });
    } else if (key == "reading") {
      read_reading(r, c);
    } else if (key == "load") {
      read_fixed(r, 3, "an array of three rationals [fx, fy, m]", [&](std::size_t k) { c.m().load[k] = read_rational(r); });
    } else if (key == "motion") {
      c.claim = r.peek() == Kind::string ? r.string_view() : "";
      if (c.claim != "sticks" && c.claim != "impending" && c.claim != "slides" && c.claim != "depends")
        r.fail("expected \"sticks\", \"impending\", \"slides\" or \"depends\"");
    } else if (key == "support_forces") {
      c.m().support_forces = read_list<Pair>(r);
    } else if (key == "speed_bounds") {
      c.m().speed_bounds = read_list<Q>(r);
    } else if (key == "dual") {
      read_fixed(r, 3, "an array of three rationals [y0, yx, yy]", [&](std::size_t k) { c.m().dual[k] = read_rational(r); });
    } else if (key == "vertices") {
      begin_array(r, "expected an array of {\"distribution\", \"support_forces\"}");
      while (r.next_item()) c.m().vertices.push_back(read_witness(r, false));
    } else if (key == "sticking") {
      c.m().sticking = read_witness(r, false);
    } else if (key == "sliding") {
      c.m().sliding = read_witness(r, true);
    } else if (key == "holding") {
      c.m().holding = read_witness(r, false);
    } else if (key == "failing") {
      c.m().failing = read_witness(r, true);
    } else if (key == "regions") {
      begin_array(r, "expected an array of region blocks (one per support region)");
      while (r.next_item()) c.m().regions.push_back(read_block(r));
    } else if (key == "norm" || key == "normalize") {
      const std::string_view v = r.peek() == Kind::string ? r.string_view() : "";
      if (key == "norm" ? v != "L1" && v != "Linf" : v != "unit-normal" && v != "unit-force" && v != "as-given")
        r.fail(key == "norm" ? "expected \"L1\" or \"Linf\"" : "expected \"unit-normal\", \"unit-force\" or \"as-given\"");
      (key == "norm" ? c.q().norm : c.q().normalize) = v;
    } else if (key == "torque_scale") {
      c.q().torque_scale = read_rational(r);
    } else if (key == "torque_radius_squared") {
      c.q().has_radius = true, c.q().radius_squared = read_rational(r);
    } else if (key == "torque_scale_error") {
      c.q().torque_error = read_rational(r);
    } else if (key == "about") {
      read_fixed(r, 2, "an array of two rationals [x, y]", [&](std::size_t k) { c.q().about[k] = read_rational(r); });
    } else if (key == "scales") {
      read_scales(r, c.q());
    } else if (key == "epsilon") {
      read_epsilon(r, c.q());
    } else if (key == "boundary") {
      begin_array(r, "expected an array of [i, j, k] generator indices");
      while (r.next_item()) read_triple(r, c.q().boundary.emplace_back());
    } else if (key == "nearest") {
      read_triple(r, c.q().nearest);
    } else if (key == "of") {
      const std::string_view v = r.peek() == Kind::string ? r.string_view() : "";
      if (v != "force_closure" && v != "equilibrium") r.fail("expected \"force_closure\" or \"equilibrium\"");
      c.cm().of = v;
    } else if (key == "scaling") {
      const std::string_view v = r.peek() == Kind::string ? r.string_view() : "";
      if (v != "common" && v != "proportional") r.fail("expected \"common\" or \"proportional\"");
      c.cm().proportional = v == "proportional";
    } else if (key == "critical_mu") {
      if (r.peek() == Kind::string) {
        c.cm().word = r.string_view();
        if (c.cm().word != "always" && c.cm().word != "never")
          r.fail("expected \"always\", \"never\" or an object {\"lower\", \"upper\"}");
      } else {
        begin_object(r, "expected \"always\", \"never\" or an object {\"lower\", \"upper\"}");
        unsigned keys = 0;
        std::string_view k;
        while (r.next_key(k)) {
          if (k == "lower") keys |= 1, c.cm().lower = read_rational(r);
          else if (k == "upper") keys |= 2, c.cm().upper = read_rational(r);
          else r.fail("unknown key " + quote(k), true);
        }
        if (keys != 3) r.fail("expected the keys \"lower\" and \"upper\"");
      }
    } else if (key == "below" || key == "above") {
      Critical_part::Side& side = key == "below" ? c.cm().below : c.cm().above;
      side.present = true;
      begin_object(r, "expected an object {\"mu\", \"certificate\"}");
      unsigned keys = 0;
      std::string_view k;
      while (r.next_key(k)) {
        if (k == "mu") keys |= 1, side.mu = read_rational(r);
        else if (k == "certificate") keys |= 2, side.certificate = std::make_unique<Certificate>(read_certificate(r));
        else r.fail("unknown key " + quote(k), true);
      }
      if (keys != 3) r.fail("expected the keys \"mu\" and \"certificate\"");
    } else if (key == "constant" || key == "constant_beyond") {
      if (r.peek() != Kind::boolean || !r.boolean()) r.fail("expected true (or leave the key out)");
      (key == "constant" ? c.cm().constant : c.cm().constant_beyond) = true;
    } else if (key == "limit_twist") {
      c.cm().has_limit_twist = true;
      read_fixed(r, 3, "an array of three rationals [vx, vy, w]", [&](std::size_t k) { c.cm().limit_twist[k] = read_rational(r); });
    } else if (key == "normal") {
      read_fixed(r, 3, "an array of three rationals [a, b, c]", [&](std::size_t k) { c.q().normal[k] = read_rational(r); });
    } else {
      r.fail("unknown key " + quote(key), true);
    }
  }
  if (empty_combination && !c.equilibrium && !c.hold) throw Failure{"combination: " + non_empty};
  return c;
}

// The keys that must, and must not, be present (certificate-format.md §3, §3.3).
void check_keys(const Certificate& c) {
  auto need = [&c](const char* key) {
    if (!c.keys.count(key)) throw Failure{std::string("missing required key \"") + key + "\""};
  };
  auto ban = [&c](const char* key) {
    if (c.keys.count(key))
      throw Failure{std::string("key \"") + key + "\" is not allowed when \"holds\" is " +
                    (c.holds ? "true" : "false")};
  };
  auto no_independent = [&c, &ban] {  // "equilibrium" never uses it
    if (!c.equilibrium) return ban("independent");
    if (c.keys.count("independent"))
      throw Failure{"key \"independent\" is not allowed when \"property\" is \"equilibrium\""};
  };
  need("wrenchkit_certificate"), need("property");
  static const char* const push_keys[] = {"rotation", "friction", "votes", "center", "turns", "contact", "stable",
                                          "region", "locus"};
  if ((c.version == 6) != c.push)
    throw Failure{c.push ? "wrenchkit_certificate: property \"push\" is format 6 (expected the integer 6)"
                         : "wrenchkit_certificate: format 6 is property \"push\" only"};
  if (c.push) {
    if (c.keys.count("stable")) need("center");  // a line pusher (§8.3): its rotation only when stable
    else need("rotation"), need("friction");
    static const char* const others[] = {
        "holds", "combination", "independent", "twist", "reading", "load", "motion", "support_forces", "speed_bounds",
        "dual", "vertices", "sticking", "sliding", "holding", "failing", "regions", "norm", "normalize", "torque_scale",
        "about", "scales", "epsilon", "boundary", "nearest", "normal", "of", "critical_mu", "below", "above", "constant",
        "constant_beyond", "limit_twist", "scaling", "torque_radius_squared", "torque_scale_error", "fingers", "mu",
        "edges", "pairs", "triples"};
    static const std::uint64_t others_mask = Key_set::mask(others);
    if (c.keys.any(others_mask))
      for (const char* key : others)
        if (c.keys.count(key)) throw Failure{"key " + quote(key) + " is not allowed when \"property\" is \"push\""};
    return;  // check_push() decides which of "votes" and "turns" its claim needs
  }
  if (c.keys.any(Key_set::mask(push_keys)))
    for (const char* key : push_keys)
      if (c.keys.count(key))
        throw Failure{std::string("key \"") + key + "\" is not allowed when \"property\" is " + quote(c.property)};
  if ((c.version == 5) != c.regions)
    throw Failure{c.regions ? "wrenchkit_certificate: property \"grasp_regions\" is format 5 (expected the integer 5)"
                            : "wrenchkit_certificate: format 5 is property \"grasp_regions\" only"};
  static const char* const region_keys[] = {"fingers", "mu", "edges", "pairs", "triples"};
  if (c.regions) {
    need("fingers"), need("mu");
    if (c.keys.count("pairs") == c.keys.count("triples"))
      throw Failure{"grasp_regions: expected one of \"pairs\" (two fingers) and \"triples\" (three)"};
    for (const std::string_view key : {"holds", "combination", "independent", "twist", "reading"})
      if (c.keys.count(key)) throw Failure{"key " + quote(key) + " is not allowed when \"property\" is \"grasp_regions\""};
    return;
  }
  if (c.keys.any(Key_set::mask(region_keys)))
    for (const char* key : region_keys)
      if (c.keys.count(key))
        throw Failure{std::string("key \"") + key + "\" is not allowed when \"property\" is " + quote(c.property)};
  if ((c.version == 4) != (c.quality || c.critical))
    throw Failure{c.quality || c.critical ? "wrenchkit_certificate: property " + quote(c.property) + " is format 4 (expected the integer 4)"
                            : "wrenchkit_certificate: format 4 is properties \"quality\" and \"critical_mu\" only (expected 1, 2 or 3)"};
  if (c.quality || c.critical) return;  // check_quality() and check_critical_mu() decide which keys their claims need
  static const char* const quality_keys[] = {"norm",   "normalize", "torque_scale", "about",    "scales",
                                             "epsilon", "boundary", "nearest",     "normal",   "of",
                                             "critical_mu", "below", "above", "constant", "constant_beyond",
                                             "limit_twist", "scaling", "torque_radius_squared",
                                             "torque_scale_error"};
  static const std::uint64_t quality_mask = Key_set::mask(quality_keys);
  if (c.keys.any(quality_mask))
    for (const char* key : quality_keys)
      if (c.keys.count(key))
        throw Failure{std::string("key \"") + key + "\" is not allowed when \"property\" is " + quote(c.property)};
  if ((c.depends || c.impending) && !c.hold)
    throw Failure{std::string("holds: ") + (c.depends ? "\"depends\"" : "\"impending\"") +
                  " is only a claim of property \"hold\" (expected true or false)"};
  if (c.motion || c.hold) return;  // check_motion() and check_hold() decide, knowing the scene's support
  static const char* const motion_keys[] = {"load",    "motion",   "support_forces", "speed_bounds",
                                            "dual",    "vertices", "sticking",       "sliding",
                                            "holding", "failing",  "regions"};
  static const std::uint64_t motion_mask = Key_set::mask(motion_keys);
  if (c.keys.any(motion_mask))  // (one test for the usual certificate; the loop names the key)
    for (const char* key : motion_keys)
      if (c.keys.count(key))
        throw Failure{std::string("key \"") + key + "\" is not allowed when \"property\" is " + quote(c.property)};
  need("holds");
  if (c.holds) {
    need("combination");
    if (c.equilibrium)
      no_independent();
    else
      need("independent");
    ban("twist"), ban("reading");
  } else {
    need("twist"), ban("combination"), no_independent();
  }
}
}  // namespace wrenchkit_checker::detail
