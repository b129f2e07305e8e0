// wrenchkit labels | dual | reuleaux: the graphical statics of Mason ch. 5–6 (exact/statics/moment_labels.h,
// exact/statics/force_dual.h). --mode hybrid (default) decides the cone's signs with the float twin first and
// exactly where it is uncertain, and constructs exactly: the answer is the exact one. --mode exact never
// uses floating point. --mode float is the float twin alone (float/labels_twin.h): coordinates as numbers
// with certified bounds, exit 3 when it cannot decide.
#include <iostream>
#include <optional>
#include <sstream>
#include <string>

#include "cli/common.h"
#include "cli/float_json.h"
#include "exact/statics/force_dual.h"
#include "exact/io/json.h"
#include "exact/io/streaming_scene_reader.h"
#include "exact/io/to_float.h"
#include "float/labels_twin.h"

namespace wrenchkit::cli {

namespace {

std::string pt(const Vec2& p) { return "(" + to_string(p.x) + ", " + to_string(p.y) + ")"; }

std::string points_text(const std::vector<Vec2>& v) {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + pt(v[i]);
  return s;
}

std::string region_text(const Region& r) {
  using S = Region::Shape;
  switch (r.shape) {
    case S::empty: return "empty";
    case S::point: return "the single point " + pt(r.vertices[0]);
    case S::segment: return "the segment " + points_text(r.vertices);
    case S::polygon: return "the polygon " + points_text(r.vertices) + " (counter-clockwise)";
    case S::ray: return "the ray from " + pt(r.vertices[0]) + " toward " + pt(r.directions[0]);
    case S::wedge:
      return "the wedge at " + pt(r.vertices[0]) + " between directions " + pt(r.directions[0]) + " and " +
             pt(r.directions[1]);
    case S::unbounded_polygon:
      return "the unbounded polygon with corners " + points_text(r.vertices) + ", running off toward " +
             points_text(r.directions);
    case S::line: return "the line through " + pt(r.vertices[0]) + " along " + pt(r.directions[0]);
    case S::strip:
      return "the strip between the lines through " + pt(r.vertices[0]) + " and " + pt(r.vertices[1]) + " along " +
             pt(r.directions[0]);
    case S::half_plane:
      return "the half-plane bounded by the line through " + pt(r.vertices[0]) + " along " + pt(r.directions[0]) +
             ", on the side of " + pt(r.directions[1]);
    case S::plane: return "the whole plane";
  }
  return "?";
}

std::string infinity_text(const Cone2& c) {
  using S = Cone2::Shape;
  switch (c.shape) {
    case S::zero: return "none";
    case S::ray: return "the direction " + pt(c.extreme[0]);
    case S::line: return "the opposite directions " + pt(c.extreme[0]) + " and " + pt(c.extreme[1]);
    case S::wedge: return "the arc from " + pt(c.extreme[0]) + " counter-clockwise to " + pt(c.extreme[1]);
    case S::half_plane: return "the half-circle from " + pt(c.extreme[0]) + " counter-clockwise to " + pt(c.extreme[2]);
    case S::plane: return "every direction";
  }
  return "?";
}

std::string both_text(const Both_set& b) {
  switch (b.kind) {
    case Both_set::Kind::none: return "none";
    case Both_set::Kind::point: return "the point " + pt(b.point) + " (every line of force passes through it)";
    case Both_set::Kind::line: return "the line through " + pt(b.point) + " along " + pt(b.direction);
    case Both_set::Kind::plane: return "the whole plane (no contact wrench at all)";
  }
  return "?";
}

std::string labels_human(const Moment_labels& l) {
  std::ostringstream s;
  s << "+ (counter-clockwise rotation centres): " << region_text(l.plus) << "\n"
    << "- (clockwise rotation centres):         " << region_text(l.minus) << "\n"
    << "+- (every moment zero):                 " << both_text(l.both) << "\n"
    << "labeled points at infinity (translations): " << infinity_text(l.infinity) << "\n";
  return s.str();
}

std::string wrench_json(const Vec3& w) {
  return "[" + json::quote(to_string(w[0])) + ", " + json::quote(to_string(w[1])) + ", " + json::quote(to_string(w[2])) + "]";
}

struct Labelled_scene {
  Scene scene;
  std::vector<Generator> gens;
  std::vector<Wrench> wrenches;
  Moment_labels labels;
  Mode mode = Mode::hybrid;
};

Labelled_scene label(const Options& o, const std::string& text, const std::string& source, Reading reading) {
  Labelled_scene s{read_scene_streaming(text, o.limits, source), {}, {}, {}, o.mode};
  s.gens = generators(s.scene, reading);
  for (const Generator& g : s.gens) s.wrenches.push_back(g.w);
  if (s.mode == Mode::hybrid) {
    const std::vector<fl::Bounded3> twin = fl::generators(to_bounded(s.scene), reading);
    s.labels = moment_labels(s.wrenches, Mode::hybrid, &twin);
  } else {
    s.labels = moment_labels(s.wrenches, Mode::exact);
  }
  return s;
}

// "mode", "decided_by", "predicates", "exact_predicates" of an exact or hybrid answer.
std::string mode_fields(const Labelled_scene& s) {
  const Wrench_cone& c = s.labels.cone;
  const char* by = s.mode == Mode::exact || c.exact_predicates == c.predicates
                       ? "exact"
                       : (c.exact_predicates == 0 ? "float" : "hybrid");
  return std::string(", \"mode\": \"") + mode_name(s.mode) + "\", \"decided_by\": \"" + by +
         "\", \"predicates\": " + std::to_string(c.predicates) +
         ", \"exact_predicates\": " + std::to_string(c.exact_predicates);
}

// --mode float: the twin alone.
struct Float_labelled {
  Scene scene;
  std::vector<Generator> gens;
  std::vector<fl::Bounded_contact> contacts;
  std::vector<fl::Bounded3> g;
  Dual_cone dc;
  fl::Labels_twin labels;
};

Float_labelled label_float(const Options& o, const std::string& text, const std::string& source, Reading reading) {
  Float_labelled s;
  s.scene = read_scene_streaming(text, o.limits, source);
  s.gens = generators(s.scene, reading);
  s.contacts = to_bounded(s.scene);
  s.g = fl::generators(s.contacts, reading);
  s.dc = compute_dual_cone(fl::Float_kernel(s.g));
  s.labels = fl::moment_labels(s.g, s.dc);
  if (!s.labels.decided())
    throw Undecided(std::string("the float twin could not decide the labels: ") + fl::status_name(s.labels.status) +
                    " (use --mode hybrid for the exact answer)");
  return s;
}

fl::Bounded3 twin_of(const Vec3& w) { return {to_bounded(w[0]), to_bounded(w[1]), to_bounded(w[2])}; }

// A certified membership from the twin, or exit 3.
bool float_in_cone(const fl::Labels_twin& l, const Vec3& w, const char* what) {
  const fl::Truth t = fl::in_cone(l, twin_of(w));
  if (t == fl::Truth::uncertain)
    throw Undecided(std::string("the float twin could not decide ") + what + " (use --mode hybrid for the exact answer)");
  return t == fl::Truth::yes;
}

std::string float_labels_fields(const fl::Labels_twin& l) {
  return "\"plus\": " + float_region_json(l.plus) + ", \"minus\": " + float_region_json(l.minus) +
         ", \"both\": [], \"infinity\": " + float_infinity_json(l.infinity);
}

std::string float_labels_human(const fl::Labels_twin& l) {
  std::ostringstream s;
  s << "+ (counter-clockwise rotation centres): " << float_region_text(l.plus) << "\n"
    << "- (clockwise rotation centres):         " << float_region_text(l.minus) << "\n"
    << "+- (every moment zero):                 none (the cone has rank 3)\n"
    << "labeled points at infinity (translations): " << float_infinity_text(l.infinity) << "\n";
  return s.str();
}

// The scene's load read on the labels: balanced ⇔ −w ∈ W (theory.md §5.5).
std::string load_json(const Labelled_scene& s) {
  if (!s.scene.load) return "";
  const Vec3 w = as_vec(load_wrench(s.scene));
  const bool balanced = in_cone(s.labels.cone, {-w[0], -w[1], -w[2]});
  return ", \"load\": {\"wrench\": " + wrench_json(w) + ", \"balanced\": " + (balanced ? "true" : "false") + "}";
}

// labels: the optional --resultant query.
struct Labels_query {
  bool resultant = false;
  Vec3 w;
};

Labels_query labels_query(const Options& o) {
  Labels_query q;
  if (o.resultant) {
    q.resultant = true;
    q.w = *o.resultant;
  }
  return q;
}

std::string labels_json(const Labelled_scene& s, const Labels_query& q) {
  std::string query;
  if (q.resultant)
    query = ", \"resultant\": {\"wrench\": " + wrench_json(q.w) + ", \"possible\": " +
            (in_cone(s.labels.cone, q.w) ? "true" : "false") + "}";
  return "{\"command\": \"labels\", \"name\": " + json::quote(s.scene.name) + ", \"reading\": \"friction\"" +
         mode_fields(s) + ", \"rank\": " + std::to_string(s.labels.cone.rank) + ", \"force_closure\": " +
         (s.labels.cone.force_closure() ? "true" : "false") + ", " + labels_json_fields(s.labels) + query +
         load_json(s) + "}";
}

std::string dual_json(const Labelled_scene& s) {
  const Force_dual d = force_dual(s.labels, s.wrenches);
  std::ostringstream j;
  const auto pts = [](const std::vector<Vec2>& v) {
    std::string r = "[";
    for (std::size_t i = 0; i < v.size(); ++i) r += (i ? ", " : "") + point_json(v[i]);
    return r + "]";
  };
  j << "{\"command\": \"dual\", \"name\": " << json::quote(s.scene.name) << mode_fields(s) << ", \"covers_all\": "
    << (d.covers_all ? "true" : "false") << ", \"plus_sheet\": " << pts(d.plus_sheet.vertices)
    << ", \"minus_sheet\": " << pts(d.minus_sheet.vertices) << ", \"infinity\": " << infinity_json(d.infinity)
    << ", \"plus_region\": " << region_json(d.plus_sheet) << ", \"minus_region\": " << region_json(d.minus_sheet)
    << ", \"generators\": [";
  for (std::size_t i = 0; i < s.gens.size(); ++i)
    j << (i ? ", " : "") << "{\"contact\": " << s.gens[i].contact << ", \"edge\": \"" << edge_name(s.gens[i].edge)
      << "\", \"dual\": " << dual_point_json(d.generators[i]) << "}";
  j << "], \"reference\": ";
  if (d.reference)
    j << "{\"point\": " << point_json(*d.reference) << ", \"polygon\": " << region_json(d.about_reference) << "}";
  else
    j << "null";
  if (s.scene.load) {
    const Vec3 w = as_vec(load_wrench(s.scene));
    j << ", \"load\": {\"antipode\": " << dual_point_json(dual_point({-w[0], -w[1], -w[2]}))
      << ", \"balanced\": " << (in_cone(s.labels.cone, {-w[0], -w[1], -w[2]}) ? "true" : "false") << "}";
  }
  j << "}";
  return j.str();
}

// reuleaux: the optional motion (--center [--sense], --direction or --twist).
struct Reuleaux_query {
  bool given = false;
  Vec3 t;
};

Reuleaux_query reuleaux_query(const Options& o) {
  const int queries = o.center.has_value() + o.direction.has_value() + o.twist.has_value();
  if (queries > 1) throw Usage_error("give at most one of --center, --direction, --twist");
  if (o.sense && !o.center) throw Usage_error("--sense goes with --center");
  Reuleaux_query q;
  q.given = queries > 0;
  if (o.center) q.t = rotation_twist({(*o.center)[0], (*o.center)[1]}, o.sense.value_or(1));
  else if (o.direction) q.t = translation_twist({(*o.direction)[0], (*o.direction)[1]});
  else if (o.twist) q.t = *o.twist;
  return q;
}

// ', "query": {…}' of reuleaux with a motion (both modes).
std::string query_json(const Reuleaux_query& q, const Mode_answer& m) {
  if (!q.given) return "";
  const std::array<Rational, 3> ta = {q.t[0], q.t[1], q.t[2]};
  std::string j = ", \"query\": {" + twist_json(ta) + ", \"feasible\": " + (m.feasible ? "true" : "false") +
                  ", \"marginal\": " + (m.marginal ? "true" : "false") + ", \"modes\": [";
  for (std::size_t i = 0; i < m.modes.size(); ++i)
    j += (i ? ", " : "") + std::string("{\"contact\": ") + std::to_string(i) + ", \"mode\": \"" + mode_name(m.modes[i]) +
         "\"}";
  return j + "]}";
}

std::string reuleaux_json(const Labelled_scene& s, const Reuleaux_query& q, const Mode_answer& m) {
  std::string j = "{\"command\": \"reuleaux\", \"name\": " + json::quote(s.scene.name) +
                  ", \"reading\": \"frictionless\"" + mode_fields(s) + ", \"rank\": " + std::to_string(s.labels.cone.rank) +
                  ", \"form_closure\": " + (s.labels.cone.force_closure() ? "true" : "false") + ", " +
                  labels_json_fields(s.labels);
  return j + query_json(q, m) + "}";
}

// ---- --mode float ----

std::string float_load_json(const Float_labelled& s) {
  if (!s.scene.load) return "";
  const Vec3 w = as_vec(load_wrench(s.scene));
  const bool balanced = float_in_cone(s.labels, {-w[0], -w[1], -w[2]}, "whether the load is balanced");
  return ", \"load\": {\"wrench\": " + wrench_json(w) + ", \"balanced\": " + (balanced ? "true" : "false") + "}";
}

const char* kFloatMode = ", \"mode\": \"float\", \"decided_by\": \"float\"";

std::string float_labels_json(const Float_labelled& s, const Labels_query& q) {
  std::string query;
  if (q.resultant)
    query = ", \"resultant\": {\"wrench\": " + wrench_json(q.w) + ", \"possible\": " +
            (float_in_cone(s.labels, q.w, "whether the resultant is possible") ? "true" : "false") + "}";
  return "{\"command\": \"labels\", \"name\": " + json::quote(s.scene.name) + ", \"reading\": \"friction\"" +
         kFloatMode + ", \"rank\": 3, \"force_closure\": " + (s.labels.nothing_labeled() ? "true" : "false") + ", " +
         float_labels_fields(s.labels) + query + float_load_json(s) + "}";
}

fl::Dual_twin float_dual(const Float_labelled& s) {
  const fl::Dual_twin d = fl::force_dual(s.g, s.dc);
  if (!d.decided())
    throw Undecided(std::string("the float twin could not decide the force dual: ") + fl::status_name(d.status) +
                    " (use --mode hybrid for the exact answer)");
  return d;
}

std::string float_dual_json(const Float_labelled& s) {
  const fl::Dual_twin d = float_dual(s);
  std::ostringstream j;
  const auto pts = [](const fl::Region2& r) {
    std::string x = "[";
    for (std::size_t i = 0; i < r.vertices.size(); ++i) x += (i ? ", " : "") + float_point_json(r.vertices[i]);
    return x + "]";
  };
  j << "{\"command\": \"dual\", \"name\": " << json::quote(s.scene.name) << kFloatMode
    << ", \"covers_all\": " << (d.covers_all ? "true" : "false") << ", \"plus_sheet\": " << pts(d.plus_sheet)
    << ", \"minus_sheet\": " << pts(d.minus_sheet) << ", \"infinity\": " << float_infinity_json(d.infinity)
    << ", \"plus_region\": " << float_region_json(d.plus_sheet)
    << ", \"minus_region\": " << float_region_json(d.minus_sheet) << ", \"generators\": [";
  for (std::size_t i = 0; i < s.gens.size(); ++i) {
    const fl::Dual_point_twin p = fl::dual_point(s.g[i]);
    if (p.sheet == '?') throw Undecided("the float twin could not place a generator's dual point (use --mode hybrid)");
    j << (i ? ", " : "") << "{\"contact\": " << s.gens[i].contact << ", \"edge\": \"" << edge_name(s.gens[i].edge)
      << "\", \"dual\": " << float_dual_point_json(p) << "}";
  }
  j << "], \"reference\": null";  // the reference-point picture is exact only
  if (s.scene.load) {
    const Vec3 w = as_vec(load_wrench(s.scene));
    const fl::Dual_point_twin a = fl::dual_point(twin_of({-w[0], -w[1], -w[2]}));
    if (a.sheet == '?') throw Undecided("the float twin could not place the load's antipode (use --mode hybrid)");
    j << ", \"load\": {\"antipode\": " << float_dual_point_json(a) << ", \"balanced\": "
      << (float_in_cone(s.labels, {-w[0], -w[1], -w[2]}, "whether the load is balanced") ? "true" : "false") << "}";
  }
  j << "}";
  return j.str();
}

// Reuleaux's modes from certified signs (exact/statics/moment_labels.h's contact_modes, in floating point).
Mode_answer float_contact_modes(const Float_labelled& s, const Vec3& t) {
  Mode_answer a;
  const fl::Bounded3 bt = twin_of(t);
  for (const fl::Bounded_contact& c : s.contacts) {
    const fl::Contact_motion m = fl::contact_motion(c, bt);
    if (m.power == Sign::uncertain || (!c.is_wrench && m.power == Sign::zero && m.speed == Sign::uncertain))
      throw Undecided("the float twin could not decide a contact's mode (use --mode hybrid for the exact answer)");
    Contact_mode mode = Contact_mode::none;
    if (!c.is_wrench)
      mode = m.power == Sign::positive   ? Contact_mode::breaks
             : m.power == Sign::negative ? Contact_mode::penetrates
             : m.speed == Sign::zero     ? Contact_mode::sticks
                                         : Contact_mode::slides;
    a.feasible &= m.power != Sign::negative;
    a.marginal |= m.power == Sign::zero;
    a.modes.push_back(mode);
  }
  a.marginal &= a.feasible;
  return a;
}

std::string float_reuleaux_json(const Float_labelled& s, const Reuleaux_query& q, const Mode_answer& m) {
  std::string j = "{\"command\": \"reuleaux\", \"name\": " + json::quote(s.scene.name) +
                  ", \"reading\": \"frictionless\"" + kFloatMode + ", \"rank\": 3, \"form_closure\": " +
                  (s.labels.nothing_labeled() ? "true" : "false") + ", " + float_labels_fields(s.labels);
  return j + query_json(q, m) + "}";
}

bool float_mode(const Options& o) { return o.mode == Mode::float_only; }

}  // namespace

Scene_answer prepare_labels_json(const Options& o) {
  return [o, q = labels_query(o)](const std::string& text, const std::string& source) {
    if (float_mode(o)) return float_labels_json(label_float(o, text, source, Reading::friction), q);
    return labels_json(label(o, text, source, Reading::friction), q);
  };
}

Scene_answer prepare_dual_json(const Options& o) {
  return [o](const std::string& text, const std::string& source) {
    if (float_mode(o)) return float_dual_json(label_float(o, text, source, Reading::friction));
    return dual_json(label(o, text, source, Reading::friction));
  };
}

Scene_answer prepare_reuleaux_json(const Options& o) {
  return [o, q = reuleaux_query(o)](const std::string& text, const std::string& source) {
    if (float_mode(o)) {
      const Float_labelled s = label_float(o, text, source, Reading::frictionless);
      return float_reuleaux_json(s, q, q.given ? float_contact_modes(s, q.t) : Mode_answer{});
    }
    const Labelled_scene s = label(o, text, source, Reading::frictionless);
    return reuleaux_json(s, q, q.given ? contact_modes(s.scene, q.t) : Mode_answer{});
  };
}

namespace {

std::string decided_line(const Labelled_scene& s) {
  const Wrench_cone& c = s.labels.cone;
  if (s.mode == Mode::exact) return "decided by: exact arithmetic\n";
  return "decided by: " + std::string(c.exact_predicates == 0 ? "float" : "hybrid") + " (" +
         std::to_string(c.exact_predicates) + " of " + std::to_string(c.predicates) +
         " predicates in exact arithmetic; every coordinate exact)\n";
}

const char* kFloatNote = "decided by: the float twin alone (every sign certified; each coordinate within the bound shown "
                         "of the exact one)\n";

int run_labels_float(const Options& o, const Labels_query& q, const std::string& text, const std::string& source) {
  const Float_labelled s = label_float(o, text, source, Reading::friction);
  if (o.json) {
    std::cout << float_labels_json(s, q) << "\n";
    return kAnswered;
  }
  std::string resultant;
  if (q.resultant)
    resultant = "resultant " + vec_text({q.w[0], q.w[1], q.w[2]}) + ": " +
                (float_in_cone(s.labels, q.w, "whether the resultant is possible") ? "possible" : "not possible") + "\n";
  std::cout << "scene: " << (s.scene.name.empty() ? source : s.scene.name) << "\n"
            << "moment labels of the contact wrench cone (with friction):\n"
            << float_labels_human(s.labels) << "force closure: " << (s.labels.nothing_labeled() ? "yes" : "no")
            << " (nothing labeled, infinity included)\n"
            << resultant << kFloatNote;
  return kAnswered;
}

}  // namespace

int run_labels(const Options& o, const std::string& text, const std::string& source) {
  const Labels_query q = labels_query(o);
  if (float_mode(o)) return run_labels_float(o, q, text, source);
  const Labelled_scene s = label(o, text, source, Reading::friction);
  if (o.json) {
    std::cout << labels_json(s, q) << "\n";
    return kAnswered;
  }
  std::cout << "scene: " << (s.scene.name.empty() ? source : s.scene.name) << "\n"
            << "moment labels of the contact wrench cone (with friction; exact):\n"
            << labels_human(s.labels)
            << "force closure: " << (s.labels.cone.force_closure() ? "yes" : "no") << " (nothing labeled, infinity included)\n";
  if (q.resultant)
    std::cout << "resultant " << vec_text({q.w[0], q.w[1], q.w[2]}) << ": "
              << (in_cone(s.labels.cone, q.w) ? "possible" : "not possible") << "\n";
  std::cout << decided_line(s);
  return kAnswered;
}

int run_dual(const Options& o, const std::string& text, const std::string& source) {
  if (float_mode(o)) {
    const Float_labelled f = label_float(o, text, source, Reading::friction);
    if (o.json) {
      std::cout << float_dual_json(f) << "\n";
      return kAnswered;
    }
    const fl::Dual_twin d = float_dual(f);
    std::cout << "scene: " << (f.scene.name.empty() ? source : f.scene.name) << "\n"
              << "force dual of the contact wrench cone (D(w) = (-fy, fx, m)):\n"
              << "covers the whole two-sided plane: " << (d.covers_all ? "yes (force closure)" : "no") << "\n"
              << "+ sheet (m > 0): " << float_region_text(d.plus_sheet) << "\n"
              << "- sheet (m < 0): " << float_region_text(d.minus_sheet) << "\n"
              << "at infinity (m = 0): " << float_infinity_text(d.infinity) << "\n"
              << kFloatNote;
    return kAnswered;
  }
  const Labelled_scene s = label(o, text, source, Reading::friction);
  if (o.json) {
    std::cout << dual_json(s) << "\n";
    return kAnswered;
  }
  const Force_dual d = force_dual(s.labels, s.wrenches);
  std::cout << "scene: " << (s.scene.name.empty() ? source : s.scene.name) << "\n"
            << "force dual of the contact wrench cone (D(w) = (-fy, fx, m); exact):\n"
            << "covers the whole two-sided plane: " << (d.covers_all ? "yes (force closure)" : "no") << "\n"
            << "+ sheet (m > 0): " << region_text(d.plus_sheet) << "\n"
            << "- sheet (m < 0): " << region_text(d.minus_sheet) << "\n"
            << "at infinity (m = 0): " << infinity_text(d.infinity) << "\n";
  if (d.reference)
    std::cout << "about the reference point " << pt(*d.reference) << " (inside the + region of the labels) the dual is "
              << region_text(d.about_reference) << "\n";
  std::cout << decided_line(s);
  return kAnswered;
}

int run_reuleaux(const Options& o, const std::string& text, const std::string& source) {
  const Reuleaux_query q = reuleaux_query(o);
  const bool fm = float_mode(o);
  std::optional<Labelled_scene> exact;
  std::optional<Float_labelled> twin;
  if (fm) twin = label_float(o, text, source, Reading::frictionless);
  else exact = label(o, text, source, Reading::frictionless);
  Mode_answer m;
  if (q.given) m = fm ? float_contact_modes(*twin, q.t) : contact_modes(exact->scene, q.t);
  if (o.json) {
    std::cout << (fm ? float_reuleaux_json(*twin, q, m) : reuleaux_json(*exact, q, m)) << "\n";
    return kAnswered;
  }
  const Scene& scene = fm ? twin->scene : exact->scene;
  const bool closed = fm ? twin->labels.nothing_labeled() : exact->labels.cone.force_closure();
  std::cout << "scene: " << (scene.name.empty() ? source : scene.name) << "\n"
            << "Reuleaux's method: the contacts read frictionless\n"
            << (fm ? float_labels_human(twin->labels) : labels_human(exact->labels))
            << "first-order form closure: " << (closed ? "yes (no feasible rotation centre or translation)" : "no")
            << "\n";
  if (q.given) {
    std::cout << "twist " << vec_text({q.t[0], q.t[1], q.t[2]}) << ": "
              << (m.feasible ? (m.marginal ? "feasible, marginal (keeps some contacts to first order)" : "feasible")
                             : "infeasible (penetrates)")
              << "\n";
    for (std::size_t i = 0; i < m.modes.size(); ++i)
      std::cout << "  contact " << i << ": " << mode_name(m.modes[i]) << "\n";
  }
  std::cout << (fm ? std::string(kFloatNote) : decided_line(*exact));
  return kAnswered;
}

}  // namespace wrenchkit::cli
