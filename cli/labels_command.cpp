// wrenchkit labels | dual | reuleaux: the graphical statics of Mason ch. 5–6 (exact/statics/moment_labels.h,
// exact/statics/force_dual.h). --mode hybrid (default) decides the cone's signs with the float twin first and
// exactly where it is uncertain, and constructs exactly: the answer is the exact one. --mode exact never
// uses floating point. --mode float is the float twin alone (float/labels_twin.h): coordinates as numbers
// with certified bounds, exit 3 when it cannot decide.
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cli/common.h"
#include "cli/float_json.h"
#include "exact/certificates/certificates.h"
#include "exact/pipeline/answer_json.h"
#include "exact/pipeline/labels_answer.h"
#include "exact/statics/force_dual.h"
#include "exact/io/json_writer.h"

namespace wrenchkit::cli {

namespace {

std::string pt(const Vec2& p) { return vec_text(p); }

std::string region_text(const Region& r) {
  const auto texts = [](const std::vector<Vec2>& x) {
    std::vector<std::string> s;
    for (const Vec2& p : x) s.push_back(pt(p));
    return s;
  };
  return region_sentence(shape_name(r.shape), texts(r.vertices), texts(r.directions));
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


// "mode", "decided_by", "predicates", "exact_predicates" of the answer (--mode float: decided by the twin).
void write_mode(Json_writer& w, const Labels_item& s) {
  if (s.mode == Mode::float_only) {
    w.member("mode", "float").member("decided_by", "float");
    return;
  }
  const Wrench_cone& c = s.labels.cone;
  w.member("mode", mode_name(s.mode)).member("decided_by", arithmetic_name(decided_by(s.mode, c.predicates, c.exact_predicates)));
  w.member("predicates", c.predicates).member("exact_predicates", c.exact_predicates);
}

// "rank", then CLOSED (force_closure or form_closure), then the labels' members (the twin's under --mode float).
void write_labels_members(Json_writer& w, const Labels_item& s, const char* closed) {
  if (s.mode == Mode::float_only) w.member("rank", 3);
  else w.member("rank", s.labels.cone.rank);
  w.member(closed, s.closed());
  if (s.mode != Mode::float_only) {
    write_labels(w, s.labels);
    return;
  }
  write_float_region(w.key("plus"), s.twin.plus);
  write_float_region(w.key("minus"), s.twin.minus);
  w.key("both").array().end_array();
  write_float_infinity(w.key("infinity"), s.twin.infinity);
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
void write_load(Json_writer& w, const Labels_item& s) {
  if (!s.load) return;
  w.key("load").object().key("wrench").rationals(*s.load);
  write_approx(w, "wrench", {(*s.load)[0], (*s.load)[1], (*s.load)[2]});
  w.member("balanced", *s.load_balanced).end_object();
}

// labels: the optional --resultant query (its numbers read where the options are parsed).
Labels_query labels_query(const Options& o) {
  Labels_query q;
  if (o.resultant) q.resultant = *o.resultant;
  return q;
}

}  // namespace

Labels_query reuleaux_query(const Options& o) {
  const int queries = o.center.has_value() + o.direction.has_value() + o.twist.has_value();
  if (queries > 1) throw Usage_error("give at most one of --center, --direction, --twist");
  if (o.sense && !o.center) throw Usage_error("--sense goes with --center");
  Labels_query q;
  q.question = Labels_question::reuleaux;
  if (o.center) q.motion = rotation_twist({(*o.center)[0], (*o.center)[1]}, o.sense.value_or(1));
  else if (o.direction) q.motion = translation_twist({(*o.direction)[0], (*o.direction)[1]});
  else if (o.twist) q.motion = *o.twist;
  return q;
}

namespace {

Labels_query dual_query(const Options&) {
  Labels_query q;
  q.question = Labels_question::dual;
  return q;
}

// The labels-family answer of one scene through the pipeline; a failure unwinds as the CLI's Failure.
Labels_item label(const Options& o, const Labels_query& q, const std::string& text, const std::string& source) {
  return answered(answer_labels(text, source, request_of(o), q));
}

void write_resultant(Json_writer& w, const Labels_query& q, const Labels_item& s) {
  if (!q.resultant) return;
  w.key("resultant").object().key("wrench").rationals(*q.resultant);
  w.member("possible", *s.resultant_possible).end_object();
}

void write_labels_answer(Json_writer& w, const Labels_item& s, const Labels_query& q) {
  w.member("command", "labels").member("name", s.scene.name).member("reading", "friction");
  write_mode(w, s);
  write_labels_members(w, s, "force_closure");
  write_resultant(w, q, s);
  write_load(w, s);
}

// The generators' members of dual: [{"contact", "edge", "dual": DUAL POINT}, …].
template <class Point>
void write_generators(Json_writer& w, const Labels_item& s, const std::vector<Point>& duals,
                      void (*write_dual)(Json_writer&, const Point&)) {
  w.key("generators").array();
  for (std::size_t i = 0; i < s.generators.size(); ++i) {
    w.object().member("contact", s.generators[i].contact).member("edge", edge_name(s.generators[i].edge));
    write_dual(w.key("dual"), duals[i]);
    w.end_object();
  }
  w.end_array();
}

void write_dual_answer(Json_writer& w, const Labels_item& s) {
  const Force_dual& d = *s.dual;
  const auto pts = [&w](const std::vector<Vec2>& v) {
    w.array();
    for (const Vec2& p : v) write_point(w, p);
    w.end_array();
  };
  w.member("command", "dual").member("name", s.scene.name);
  write_mode(w, s);
  w.member("covers_all", d.covers_all);
  w.key("plus_sheet");
  pts(d.plus_sheet.vertices);
  w.key("minus_sheet");
  pts(d.minus_sheet.vertices);
  write_infinity(w.key("infinity"), d.infinity);
  write_region(w.key("plus_region"), d.plus_sheet);
  write_region(w.key("minus_region"), d.minus_sheet);
  write_generators(w, s, d.generators, write_dual_point);
  w.key("reference");
  if (d.reference) {
    write_point(w.object().key("point"), *d.reference);
    write_region(w.key("polygon"), d.about_reference);
    w.end_object();
  } else {
    w.null();
  }
  if (s.load) {
    const Vec3q& x = *s.load;
    write_dual_point(w.key("load").object().key("antipode"), dual_point({-x[0], -x[1], -x[2]}));
    w.member("balanced", *s.load_balanced).end_object();
  }
}

void write_float_dual_answer(Json_writer& w, const Labels_item& s) {
  const fl::Dual_twin& d = *s.twin_dual;
  const auto pts = [&w](const fl::Region2& r) {
    w.array();
    for (const fl::Point2& p : r.vertices) write_float_point(w, p);
    w.end_array();
  };
  w.member("command", "dual").member("name", s.scene.name);
  write_mode(w, s);
  w.member("covers_all", d.covers_all);
  w.key("plus_sheet");
  pts(d.plus_sheet);
  w.key("minus_sheet");
  pts(d.minus_sheet);
  write_float_infinity(w.key("infinity"), d.infinity);
  write_float_region(w.key("plus_region"), d.plus_sheet);
  write_float_region(w.key("minus_region"), d.minus_sheet);
  write_generators(w, s, s.twin_dual_points, write_float_dual_point);
  w.key("reference").null();  // the reference-point picture is exact only
  if (s.load) {
    write_float_dual_point(w.key("load").object().key("antipode"), *s.twin_antipode);
    w.member("balanced", *s.load_balanced).end_object();
  }
}

// The "query" member of reuleaux with a motion (every mode).
void write_query(Json_writer& w, const Labels_query& q, const Labels_item& s) {
  if (!q.motion) return;
  const Mode_answer& m = *s.modes;
  w.key("query").object();
  write_twist(w, primitive_vec({(*q.motion)[0], (*q.motion)[1], (*q.motion)[2]}));  // a direction: small integers
  w.member("feasible", m.feasible).member("marginal", m.marginal).key("modes").array();
  for (std::size_t i = 0; i < m.modes.size(); ++i)
    w.object().member("contact", i).member("mode", mode_name(m.modes[i])).end_object();
  w.end_array().end_object();
}

void write_reuleaux_answer(Json_writer& w, const Labels_item& s, const Labels_query& q) {
  w.member("command", "reuleaux").member("name", s.scene.name).member("reading", "frictionless");
  write_mode(w, s);
  write_labels_members(w, s, "form_closure");
  write_query(w, q, s);
}

std::string decided_line(const Labels_item& s) {
  if (s.mode == Mode::float_only)
    return "decided by: the float twin alone (every sign certified; each coordinate within the bound shown of the "
           "exact one)\n";
  const Wrench_cone& c = s.labels.cone;
  if (s.mode == Mode::exact) return "decided by: exact arithmetic\n";
  return "decided by: " + std::string(c.exact_predicates == 0 ? "float" : "hybrid") + " (" +
         std::to_string(c.exact_predicates) + " of " + std::to_string(c.predicates) +
         " predicates in exact arithmetic; every coordinate exact)\n";
}

std::string human_labels(const Labels_item& s) {
  return s.mode == Mode::float_only ? float_labels_human(s.twin) : labels_human(s.labels);
}

// The force-closure line: closure ⇔ nothing is labeled, infinity included (theory.md §5.5); when something is,
// what.
std::string closure_line(const Labels_item& s) {
  if (s.closed()) return "force closure: yes (nothing labeled, infinity included)\n";
  const bool fm = s.mode == Mode::float_only;
  std::vector<std::string> parts;
  if (fm ? s.twin.plus.shape != fl::Region2::Shape::empty : !s.labels.plus.empty()) parts.push_back("the + region");
  if (fm ? s.twin.minus.shape != fl::Region2::Shape::empty : !s.labels.minus.empty()) parts.push_back("the - region");
  if (!fm && s.labels.both.kind != Both_set::Kind::none) parts.push_back("the +- set");
  if (fm ? s.twin.infinity.shape != fl::Arc2::Shape::zero : s.labels.infinity.shape != Cone2::Shape::zero)
    parts.push_back("points at infinity");
  std::string labeled;
  for (std::size_t i = 0; i < parts.size(); ++i)
    labeled += (i == 0 ? "" : i + 1 == parts.size() ? " and " : ", ") + parts[i];
  return "force closure: no (labeled: " + labeled + "; closure needs nothing labeled, infinity included)\n";
}

// The scene's load read on the labels (theory.md §5.5): balanced ⇔ minus the load is a contact resultant.
std::string load_line(const Labels_item& s) {
  if (!s.load) return "";
  const Vec3q& w = *s.load;
  return "load " + vec_text(w) + ": " +
         (*s.load_balanced ? "balanced (minus the load is a possible contact resultant)"
                           : "not balanced (minus the load is not a possible contact resultant)") +
         "\n";
}

}  // namespace

Scene_answer prepare_labels_json(const Options& o) {
  return [o, q = labels_query(o)](Json_writer& w, const std::string& text, const std::string& source) {
    write_labels_answer(w, label(o, q, text, source), q);
  };
}

Scene_answer prepare_dual_json(const Options& o) {
  return [o, q = dual_query(o)](Json_writer& w, const std::string& text, const std::string& source) {
    const Labels_item s = label(o, q, text, source);
    if (s.mode == Mode::float_only) write_float_dual_answer(w, s);
    else write_dual_answer(w, s);
  };
}

Scene_answer prepare_reuleaux_json(const Options& o) {
  return [o, q = reuleaux_query(o)](Json_writer& w, const std::string& text, const std::string& source) {
    write_reuleaux_answer(w, label(o, q, text, source), q);
  };
}

namespace {

std::string labels_text(const Labels_item& s, const Labels_query& q, const std::string& source) {
  std::ostringstream out;
  out << scene_line(s.scene, source) << "moment labels of the contact wrench cone (with friction"
      << (s.mode == Mode::float_only ? "" : "; exact") << "):\n"
      << human_labels(s) << closure_line(s);
  if (q.resultant)
    out << "resultant " << vec_text(*q.resultant) << ": "
        << (*s.resultant_possible ? "possible" : "not possible") << "\n";
  return out.str() + load_line(s) + decided_line(s);
}

std::string dual_text(const Labels_item& s, const std::string& source) {
  const bool fm = s.mode == Mode::float_only;
  std::ostringstream out;
  out << scene_line(s.scene, source) << "force dual of the contact wrench cone (D(w) = (-fy, fx, m)"
      << (fm ? "" : "; exact") << "):\n";
  const auto sheets = [&](bool covers_all, const std::string& plus, const std::string& minus, const std::string& inf) {
    out << "covers the whole two-sided plane: " << (covers_all ? "yes (force closure)" : "no") << "\n"
        << "+ sheet (m > 0): " << plus << "\n"
        << "- sheet (m < 0): " << minus << "\n"
        << "at infinity (m = 0): " << inf << "\n";
  };
  if (fm) {
    const fl::Dual_twin& d = *s.twin_dual;
    sheets(d.covers_all, float_region_text(d.plus_sheet), float_region_text(d.minus_sheet),
           float_infinity_text(d.infinity));
  } else {
    const Force_dual& d = *s.dual;
    sheets(d.covers_all, region_text(d.plus_sheet), region_text(d.minus_sheet), infinity_text(d.infinity));
    if (d.reference)
      out << "about the reference point " << pt(*d.reference) << " (inside the + region of the labels) the dual is "
          << region_text(d.about_reference) << "\n";
  }
  return out.str() + decided_line(s);
}

std::string reuleaux_text(const Labels_item& s, const Labels_query& q, const std::string& source) {
  std::ostringstream out;
  out << scene_line(s.scene, source) << "Reuleaux's method: the contacts read frictionless\n" << human_labels(s)
      << "first-order form closure: " << (s.closed() ? "yes (no feasible rotation centre or translation)" : "no")
      << "\n";
  if (q.motion) {
    const Mode_answer& m = *s.modes;
    const Vec3q t{(*q.motion)[0], (*q.motion)[1], (*q.motion)[2]};
    out << "twist " << twist_text(t) << " (" << motion_text(t) << "): "
        << (m.feasible ? (m.marginal ? "feasible, marginal (keeps some contacts to first order)" : "feasible")
                       : "infeasible (penetrates)")
        << "\n";
    for (std::size_t i = 0; i < m.modes.size(); ++i)
      out << "  contact " << i << (s.scene.contacts[i].name.empty() ? "" : " (" + s.scene.contacts[i].name + ")") << ": "
          << mode_name(m.modes[i]) << "\n";
  }
  return out.str() + decided_line(s);
}

}  // namespace

int run_labels(const Options& o, const std::string& text, const std::string& source) {
  const Labels_query q = labels_query(o);
  const Labels_item s = label(o, q, text, source);
  const auto json = [&](Json_writer& w) { write_labels_answer(w, s, q); };
  return write_answer(o, json, [&] { return labels_text(s, q, source); });
}

int run_dual(const Options& o, const std::string& text, const std::string& source) {
  const Labels_item s = label(o, dual_query(o), text, source);
  const auto json = [&](Json_writer& w) {
    s.mode == Mode::float_only ? write_float_dual_answer(w, s) : write_dual_answer(w, s);
  };
  return write_answer(o, json, [&] { return dual_text(s, source); });
}

int run_reuleaux(const Options& o, const std::string& text, const std::string& source) {
  const Labels_query q = reuleaux_query(o);
  const Labels_item s = label(o, q, text, source);
  const auto json = [&](Json_writer& w) { write_reuleaux_answer(w, s, q); };
  return write_answer(o, json, [&] { return reuleaux_text(s, q, source); });
}

}  // namespace wrenchkit::cli
