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
#include "exact/pipeline/labels_answer.h"
#include "exact/statics/force_dual.h"
#include "exact/io/json.h"

namespace wrenchkit::cli {

namespace {

std::string pt(const Vec2& p) { return "(" + to_string(p.x) + ", " + to_string(p.y) + ")"; }

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

std::string wrench_json(const Vec3& w) {
  return "[" + json::quote(to_string(w[0])) + ", " + json::quote(to_string(w[1])) + ", " + json::quote(to_string(w[2])) + "]";
}

// "mode", "decided_by", "predicates", "exact_predicates" of an exact or hybrid answer.
std::string mode_fields(const Labels_item& s) {
  const Wrench_cone& c = s.labels.cone;
  const char* by = decided_by(s.mode, c.predicates, c.exact_predicates);
  return std::string(", \"mode\": \"") + mode_name(s.mode) + "\", \"decided_by\": \"" + by +
         "\", \"predicates\": " + std::to_string(c.predicates) +
         ", \"exact_predicates\": " + std::to_string(c.exact_predicates);
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
std::string load_json(const Labels_item& s) {
  if (!s.load) return "";
  return ", \"load\": {\"wrench\": " + wrench_json(*s.load) + ", \"balanced\": " + (*s.load_balanced ? "true" : "false") +
         "}";
}

// labels: the optional --resultant query (its numbers read where the options are parsed).
Labels_query labels_query(const Options& o) {
  Labels_query q;
  if (o.resultant) q.resultant = *o.resultant;
  return q;
}

// reuleaux: the optional motion (--center [--sense], --direction or --twist).
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

Labels_query dual_query(const Options&) {
  Labels_query q;
  q.question = Labels_question::dual;
  return q;
}

// The labels-family answer of one scene through the pipeline; a failure unwinds as the CLI's Failure.
Labels_item label(const Options& o, const Labels_query& q, const std::string& text, const std::string& source) {
  return answered(answer_labels(text, source, request_of(o), q));
}

const char* kFloatMode = ", \"mode\": \"float\", \"decided_by\": \"float\"";

std::string resultant_json(const Labels_query& q, const Labels_item& s) {
  if (!q.resultant) return "";
  return ", \"resultant\": {\"wrench\": " + wrench_json(*q.resultant) + ", \"possible\": " +
         (*s.resultant_possible ? "true" : "false") + "}";
}

std::string labels_json(const Labels_item& s, const Labels_query& q) {
  const bool fm = s.mode == Mode::float_only;
  return "{\"command\": \"labels\", \"name\": " + json::quote(s.scene.name) + ", \"reading\": \"friction\"" +
         (fm ? std::string(kFloatMode) : mode_fields(s)) + ", \"rank\": " +
         (fm ? std::string("3") : std::to_string(s.labels.cone.rank)) + ", \"force_closure\": " +
         (s.closed() ? "true" : "false") + ", " + (fm ? float_labels_fields(s.twin) : labels_json_fields(s.labels)) +
         resultant_json(q, s) + load_json(s) + "}";
}

std::string dual_json(const Labels_item& s) {
  const Force_dual& d = *s.dual;
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
  for (std::size_t i = 0; i < s.generators.size(); ++i)
    j << (i ? ", " : "") << "{\"contact\": " << s.generators[i].contact << ", \"edge\": \""
      << edge_name(s.generators[i].edge) << "\", \"dual\": " << dual_point_json(d.generators[i]) << "}";
  j << "], \"reference\": ";
  if (d.reference)
    j << "{\"point\": " << point_json(*d.reference) << ", \"polygon\": " << region_json(d.about_reference) << "}";
  else
    j << "null";
  if (s.load) {
    const Vec3& w = *s.load;
    j << ", \"load\": {\"antipode\": " << dual_point_json(dual_point({-w[0], -w[1], -w[2]}))
      << ", \"balanced\": " << (*s.load_balanced ? "true" : "false") << "}";
  }
  j << "}";
  return j.str();
}

std::string float_dual_json(const Labels_item& s) {
  const fl::Dual_twin& d = *s.twin_dual;
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
  for (std::size_t i = 0; i < s.generators.size(); ++i)
    j << (i ? ", " : "") << "{\"contact\": " << s.generators[i].contact << ", \"edge\": \""
      << edge_name(s.generators[i].edge) << "\", \"dual\": " << float_dual_point_json(s.twin_dual_points[i]) << "}";
  j << "], \"reference\": null";  // the reference-point picture is exact only
  if (s.load)
    j << ", \"load\": {\"antipode\": " << float_dual_point_json(*s.twin_antipode) << ", \"balanced\": "
      << (*s.load_balanced ? "true" : "false") << "}";
  j << "}";
  return j.str();
}

// ', "query": {…}' of reuleaux with a motion (every mode).
std::string query_json(const Labels_query& q, const Labels_item& s) {
  if (!q.motion) return "";
  const Mode_answer& m = *s.modes;
  const std::array<Rational, 3> ta = {(*q.motion)[0], (*q.motion)[1], (*q.motion)[2]};
  std::string j = ", \"query\": {" + twist_json(ta) + ", \"feasible\": " + (m.feasible ? "true" : "false") +
                  ", \"marginal\": " + (m.marginal ? "true" : "false") + ", \"modes\": [";
  for (std::size_t i = 0; i < m.modes.size(); ++i)
    j += (i ? ", " : "") + std::string("{\"contact\": ") + std::to_string(i) + ", \"mode\": \"" + mode_name(m.modes[i]) +
         "\"}";
  return j + "]}";
}

std::string reuleaux_json(const Labels_item& s, const Labels_query& q) {
  const bool fm = s.mode == Mode::float_only;
  std::string j = "{\"command\": \"reuleaux\", \"name\": " + json::quote(s.scene.name) +
                  ", \"reading\": \"frictionless\"" + (fm ? std::string(kFloatMode) : mode_fields(s)) + ", \"rank\": " +
                  (fm ? std::string("3") : std::to_string(s.labels.cone.rank)) + ", \"form_closure\": " +
                  (s.closed() ? "true" : "false") + ", " +
                  (fm ? float_labels_fields(s.twin) : labels_json_fields(s.labels));
  return j + query_json(q, s) + "}";
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

}  // namespace

Scene_answer prepare_labels_json(const Options& o) {
  return [o, q = labels_query(o)](const std::string& text, const std::string& source) {
    return labels_json(label(o, q, text, source), q);
  };
}

Scene_answer prepare_dual_json(const Options& o) {
  return [o, q = dual_query(o)](const std::string& text, const std::string& source) {
    const Labels_item s = label(o, q, text, source);
    return s.mode == Mode::float_only ? float_dual_json(s) : dual_json(s);
  };
}

Scene_answer prepare_reuleaux_json(const Options& o) {
  return [o, q = reuleaux_query(o)](const std::string& text, const std::string& source) {
    return reuleaux_json(label(o, q, text, source), q);
  };
}

namespace {

std::string labels_text(const Labels_item& s, const Labels_query& q, const std::string& source) {
  std::ostringstream out;
  out << scene_line(s.scene.name, source) << "moment labels of the contact wrench cone (with friction"
      << (s.mode == Mode::float_only ? "" : "; exact") << "):\n"
      << human_labels(s) << "force closure: " << (s.closed() ? "yes" : "no") << " (nothing labeled, infinity included)\n";
  if (q.resultant)
    out << "resultant " << vec_text({(*q.resultant)[0], (*q.resultant)[1], (*q.resultant)[2]}) << ": "
        << (*s.resultant_possible ? "possible" : "not possible") << "\n";
  return out.str() + decided_line(s);
}

std::string dual_text(const Labels_item& s, const std::string& source) {
  const bool fm = s.mode == Mode::float_only;
  std::ostringstream out;
  out << scene_line(s.scene.name, source) << "force dual of the contact wrench cone (D(w) = (-fy, fx, m)"
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
  out << scene_line(s.scene.name, source) << "Reuleaux's method: the contacts read frictionless\n" << human_labels(s)
      << "first-order form closure: " << (s.closed() ? "yes (no feasible rotation centre or translation)" : "no")
      << "\n";
  if (q.motion) {
    const Mode_answer& m = *s.modes;
    out << "twist " << vec_text({(*q.motion)[0], (*q.motion)[1], (*q.motion)[2]}) << ": "
        << (m.feasible ? (m.marginal ? "feasible, marginal (keeps some contacts to first order)" : "feasible")
                       : "infeasible (penetrates)")
        << "\n";
    for (std::size_t i = 0; i < m.modes.size(); ++i) out << "  contact " << i << ": " << mode_name(m.modes[i]) << "\n";
  }
  return out.str() + decided_line(s);
}

}  // namespace

int run_labels(const Options& o, const std::string& text, const std::string& source) {
  const Labels_query q = labels_query(o);
  const Labels_item s = label(o, q, text, source);
  return write_answer(o, [&] { return labels_json(s, q); }, [&] { return labels_text(s, q, source); });
}

int run_dual(const Options& o, const std::string& text, const std::string& source) {
  const Labels_item s = label(o, dual_query(o), text, source);
  return write_answer(
      o, [&] { return s.mode == Mode::float_only ? float_dual_json(s) : dual_json(s); },
      [&] { return dual_text(s, source); });
}

int run_reuleaux(const Options& o, const std::string& text, const std::string& source) {
  const Labels_query q = reuleaux_query(o);
  const Labels_item s = label(o, q, text, source);
  return write_answer(o, [&] { return reuleaux_json(s, q); }, [&] { return reuleaux_text(s, q, source); });
}

}  // namespace wrenchkit::cli
