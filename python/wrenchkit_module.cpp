// The Python bindings' native part (`wrenchkit._core`, pybind11): scenes from JSON text, and every
// exact answer as Python objects — fractions.Fraction for every exact number, bool for verdicts,
// certificates as dicts and as the JSON text the independent checker accepts. The package
// (python/wrenchkit/__init__.py) builds scene JSON from Python values and documents the API
// (docs/python.md). Errors: Input_error → wrenchkit.InputError (a ValueError) with the CLI's message.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

#include "cli/command_table.h"
#include "cli/common.h"
#include "conformance/compare.h"
#include "conformance/corpus.h"
#include "core/mode.h"
#include "exact/certificates/certificates.h"
#include "exact/pipeline/hold_answer.h"
#include "exact/pipeline/labels_answer.h"
#include "exact/pipeline/pipeline.h"
#include "exact/pipeline/support_answer.h"
#include "exact/statics/closure.h"
#include "exact/statics/equilibrium.h"
#include "exact/statics/force_dual.h"
#include "exact/io/input_error.h"
#include "exact/io/json.h"
#include "exact/sliding/limit_surface.h"
#include "exact/statics/moment_labels.h"
#include "exact/io/scene_writer.h"
#include "exact/sliding/sliding.h"
#include "proofs/checker/checker.h"
#include "python/convert.h"

namespace py = pybind11;
using namespace wrenchkit;

namespace {

// The exception classes are created in Python (wrenchkit/__init__.py passes them in at import).
py::object g_input_error, g_internal_error, g_undecided_error;

struct Undecided_exception {
  std::string message;
};

}  // namespace

namespace wrenchkit::python {

py::object fraction(const Rational& q) {
  static py::object F = py::module_::import("fractions").attr("Fraction");
  return F(py::str(to_string(q)));
}
py::tuple point(const Vec2& p) { return py::make_tuple(fraction(p.x), fraction(p.y)); }
py::tuple triple(const Rational& a, const Rational& b, const Rational& c) {
  return py::make_tuple(fraction(a), fraction(b), fraction(c));
}
py::tuple triple(const Vec3q& v) { return triple(v[0], v[1], v[2]); }

// A scene as read by the engine, with the canonical text the checker is given.
struct Py_scene {
  Scene scene;
  std::string text;    // canonical (exact/io/scene_writer.h)
  std::string source;  // names the input in messages
  Input_limits limits;  // read within these; its questions (and the checker) keep them
};

Input_limits limits_of(const py::dict& l) {
  Input_limits x;
  if (l.contains("max_digits")) x.max_digits = l["max_digits"].cast<std::size_t>();
  if (l.contains("max_exponent")) x.max_exponent = l["max_exponent"].cast<long>();
  if (l.contains("max_file_size")) x.max_file_bytes = l["max_file_size"].cast<std::size_t>();
  if (l.contains("max_contacts")) x.max_contacts = l["max_contacts"].cast<std::size_t>();
  if (l.contains("max_total_digits")) x.max_total_digits = l["max_total_digits"].cast<std::size_t>();
  if (l.contains("max_digits_times_contacts"))
    x.max_digits_times_contacts = l["max_digits_times_contacts"].cast<std::size_t>();
  if (l.contains("max_region_vertices")) x.max_region_vertices = l["max_region_vertices"].cast<std::size_t>();
  if (l.contains("max_work")) x.max_work = l["max_work"].cast<std::size_t>();
  if (l.contains("max_certificate_size")) x.max_certificate_bytes = l["max_certificate_size"].cast<std::size_t>();
  if (l.contains("lenient")) x.lenient = l["lenient"].cast<bool>();
  return x;
}

Py_scene read_text(const std::string& text, const std::string& source, const py::dict& limits) {
  const Input_limits l = limits_of(limits);
  if (text.size() > l.max_file_bytes)
    throw Input_error(source + ": larger than the size limit of " + std::to_string(l.max_file_bytes) +
                      " bytes (max_file_size)");
  Py_scene s{read_scene(text, l, source), "", source, l};
  s.text = write_scene(s.scene);
  return s;
}

// The request of a question asked in `mode` (parsed once, here: an unknown mode is a ValueError).
Request request_of(const std::string& mode, const Input_limits& limits = {}) {
  Request r;
  r.limits = limits;
  const std::optional<Mode> m = parse_mode(mode);
  if (!m) throw Input_error("mode: \"" + mode + "\" " + kModeChoices);
  r.mode = *m;
  return r;
}

// A pipeline answer that did not end in `answered` as the Python exception of its status: the one place
// the bindings turn statuses into exceptions.
void raise_unless_answered(Status s, const std::string& message) {
  switch (s) {
    case Status::answered: return;
    case Status::bad_input: throw Input_error(message);
    case Status::undecided: throw Undecided_exception{message + "; use mode hybrid or exact"};
    case Status::check_failed: throw std::runtime_error(message + " (a bug, please report)");
    case Status::internal_error: throw std::runtime_error(message);
  }
}

Rational number(const std::string& text, const std::string& what) {
  std::string why;
  const auto q = parse_rational(text, false, Input_limits{}, why);
  if (!q) throw Input_error(what + ": \"" + text + "\" " + why);
  return *q;
}
Vec3q vec3(const std::vector<std::string>& t, const std::string& what) {
  if (t.size() != 3) throw Input_error(what + ": needs 3 numbers, got " + std::to_string(t.size()));
  return {number(t[0], what + "[0]"), number(t[1], what + "[1]"), number(t[2], what + "[2]")};
}

py::dict reading_dict(const std::array<Rational, 3>& twist) {
  const Twist_reading r = read_twist(twist);
  py::dict d;
  if (r.label == 'i') {
    d["label"] = "infinity";
    d["direction"] = py::make_tuple(fraction(r.point[0]), fraction(r.point[1]));
  } else {
    d["label"] = std::string(1, r.label);
    d["point"] = py::make_tuple(fraction(r.point[0]), fraction(r.point[1]));
  }
  return d;
}

py::list combination_list(const std::vector<std::pair<Generator_ref, Rational>>& c) {
  py::list l;
  for (const auto& [ref, w] : c) {
    py::dict t;
    t["contact"] = ref.contact;
    t["edge"] = edge_name(ref.edge);
    t["weight"] = fraction(w);
    l.append(t);
  }
  return l;
}

py::dict closure_certificate(const Closure_certificate& c) {
  py::dict d;
  d["wrenchkit_certificate"] = 1;
  d["property"] = property_name(c.property);
  d["holds"] = c.holds;
  if (c.holds) {
    d["combination"] = combination_list(c.combination);
    py::list ind;
    for (const Generator_ref& r : c.independent) {
      py::dict t;
      t["contact"] = r.contact;
      t["edge"] = edge_name(r.edge);
      ind.append(t);
    }
    d["independent"] = ind;
  } else {
    d["twist"] = triple(c.twist[0], c.twist[1], c.twist[2]);
    d["reading"] = reading_dict(c.twist);
  }
  return d;
}

py::dict equilibrium_certificate(const Equilibrium_certificate& a) {
  py::dict c;
  c["wrenchkit_certificate"] = 1;
  c["property"] = "equilibrium";
  c["holds"] = a.holds;
  if (a.holds) c["combination"] = combination_list(a.combination);
  else {
    c["twist"] = triple(a.twist[0], a.twist[1], a.twist[2]);
    c["reading"] = reading_dict(a.twist);
  }
  return c;
}

}  // namespace wrenchkit::python

namespace {

using namespace wrenchkit::python;

py::dict closure(const Py_scene& s, const std::string& mode) {
  const Closure_item r = answer_closure(s.scene, s.text, request_of(mode, s.limits));
  raise_unless_answered(r.status, r.message);
  py::dict d;
  d["force_closure"] = r.force.holds;
  d["form_closure"] = r.form.holds;
  py::dict rank, gens;
  rank["force"] = r.force.rank;
  rank["form"] = r.form.rank;
  gens["force"] = r.force.generators;
  gens["form"] = r.form.generators;
  d["rank"] = rank;
  d["generators"] = gens;
  d["mode"] = mode;
  d["decided_by"] = arithmetic_name(r.decided_by());
  d["certificate"] = closure_certificate(r.force.certificate);
  d["form_certificate"] = closure_certificate(r.form.certificate);
  d["certificate_json"] = r.force_certificate;
  d["form_certificate_json"] = r.form_certificate;
  return d;
}

// Each contact's force under a certificate's weights, as `--json` writes "forces": [{"contact", "name", "force"}].
py::list forces_list(const std::vector<Contact_force>& forces) {
  py::list out;
  for (const Contact_force& f : forces) {
    py::dict d;
    d["contact"] = f.contact;
    d["name"] = f.name;
    d["force"] = py::make_tuple(fraction(f.wrench[0]), fraction(f.wrench[1]));
    out.append(d);
  }
  return out;
}

py::dict equilibrium(const Py_scene& s, const std::string& mode) {
  const Equilibrium_item r = answer_equilibrium(s.scene, s.text, request_of(mode, s.limits));
  raise_unless_answered(r.status, r.message);
  const Equilibrium_answer& a = r.answer;
  py::dict d;
  d["balanced"] = a.balanced;
  d["load"] = triple(a.load[0], a.load[1], a.load[2]);
  d["generators"] = a.generators;
  d["mode"] = mode;
  d["decided_by"] = arithmetic_name(a.decided_by());
  if (a.balanced) d["forces"] = forces_list(r.forces);
  d["certificate"] = equilibrium_certificate(a.certificate);
  d["certificate_json"] = r.certificate;
  return d;
}

// The motion of a failing twist: {"twist", "kind": "rotation", "center", "sense"} or {"twist", "kind":
// "translation", "direction"} (the velocity's direction), as `wrenchkit hold --json` writes it.
py::dict motion_dict(const std::array<Rational, 3>& t) {
  py::dict d;
  d["twist"] = triple(t[0], t[1], t[2]);
  if (t[2] != 0) {
    d["kind"] = "rotation";
    d["center"] = py::make_tuple(fraction(Rational(-t[1] / t[2])), fraction(Rational(t[0] / t[2])));
    d["sense"] = t[2] > 0 ? "counter-clockwise" : "clockwise";
  } else {
    const std::array<Integer, 2> v = primitive(t[0], t[1]);
    d["kind"] = "translation";
    d["direction"] = py::make_tuple(fraction(Rational(v[0])), fraction(Rational(v[1])));
  }
  d["text"] = motion_words(t);
  return d;
}

py::list distribution_list(const std::vector<Rational>& f) {
  py::list l;
  for (const Rational& x : f) l.append(fraction(x));
  return l;
}

// [HD-1] Can the contacts and the support's friction hold the body against the load? The same answer as
// `wrenchkit hold --json`, with Fractions.
py::dict hold(const Py_scene& s, const std::string& mode) {
  const Hold_item r = answer_hold(s.scene, s.text, request_of(mode, s.limits));
  raise_unless_answered(r.status, r.message);
  const Hold_answer& a = r.answer;
  py::dict d;
  if (a.verdict == Hold_verdict::holds || a.verdict == Hold_verdict::fails) d["holds"] = a.verdict == Hold_verdict::holds;
  else d["holds"] = hold_word(a.verdict);
  d["load"] = triple(a.load[0], a.load[1], a.load[2]);
  d["generators"] = a.generators;
  d["support"] = !a.has_support ? "none" : a.unknown ? "unknown" : "known";
  d["mode"] = mode;
  d["decided_by"] = decided_by_text(a);
  if (a.has_support && !s.scene.support->regions.empty()) {
    d["regions"] = s.scene.support->regions.size();
    d["region_cells"] = a.cells;
  }
  if (a.unknown) {
    py::list ext, per;
    for (const auto& f : a.extreme) ext.append(distribution_list(f));
    for (const Hold_verdict v : a.per_vertex) per.append(hold_word(v));
    d["extreme_distributions"] = ext;
    d["per_extreme_distribution"] = per;
  }
  if (a.holding) {
    d["contact_forces"] = combination_list(a.holding->combination);
    d["forces"] = forces_list(contact_forces(r.scene, a.holding->combination));
    py::list g;
    for (const Vec2& f : a.holding->support.forces) g.append(point(f));
    d["support_forces"] = g;
    if (a.unknown) d["holding_distribution"] = distribution_list(a.holding->support.distribution);
  }
  if (a.impending) {  // just held: its forces, and the motion it may start (its power meets the friction's)
    d["contact_forces"] = combination_list(a.impending->holding.combination);
    d["forces"] = forces_list(contact_forces(r.scene, a.impending->holding.combination));
    py::list g;
    for (const Vec2& f : a.impending->holding.support.forces) g.append(point(f));
    d["support_forces"] = g;
    d["motion"] = motion_dict(a.impending->twist.twist);
  }
  if (a.failing && a.verdict != Hold_verdict::holds) {
    d["motion"] = motion_dict(a.failing->twist);
    if (a.verdict == Hold_verdict::depends) {
      d["failing_distribution"] = distribution_list(a.failing->distribution);
      d["holding_as"] = a.held_as == Hold_verdict::holds ? py::object(py::bool_(true)) : py::object(py::str("impending"));
      d["failing_as"] = a.moved_as == Hold_verdict::fails ? py::object(py::bool_(false)) : py::object(py::str("impending"));
    }
  }
  if (a.verdict == Hold_verdict::undecided) d["undecided_why"] = a.undecided_why;
  d["certificate_json"] = r.certificate;
  return d;
}

py::dict region(const Region& r) {
  py::dict d;
  d["empty"] = r.empty();
  d["shape"] = shape_name(r.shape);
  py::list v, dirs;
  for (const Vec2& p : r.vertices) v.append(point(p));
  for (const Vec2& p : r.directions) dirs.append(point(p));
  d["vertices"] = v;
  d["directions"] = dirs;
  return d;
}

py::list infinity(const Cone2& c) {
  py::list l;
  const auto arc = [&](py::tuple from, py::tuple to, bool full) {
    py::dict x;
    x["from"] = from;
    x["to"] = to;
    if (full) x["full"] = true;
    l.append(x);
  };
  using S = Cone2::Shape;
  switch (c.shape) {
    case S::zero: break;
    case S::ray:
    case S::line:
      for (const Vec2& d : c.extreme) {
        py::dict x;
        x["direction"] = point(d);
        l.append(x);
      }
      break;
    case S::wedge: arc(point(c.extreme[0]), point(c.extreme[1]), false); break;
    case S::half_plane: arc(point(c.extreme[0]), point(c.extreme[2]), false); break;
    case S::plane: arc(py::make_tuple(fraction(1), fraction(0)), py::make_tuple(fraction(1), fraction(0)), true); break;
  }
  return l;
}

py::list both(const Both_set& b) {
  py::list l;
  py::dict x;
  switch (b.kind) {
    case Both_set::Kind::none: return l;
    case Both_set::Kind::point: x["point"] = point(b.point); break;
    case Both_set::Kind::line: {
      py::dict line;
      line["through"] = point(b.point);
      line["direction"] = point(b.direction);
      x["line"] = line;
      break;
    }
    case Both_set::Kind::plane: x["plane"] = true; break;
  }
  l.append(x);
  return l;
}

Reading reading_of_text(const std::string& r) {
  if (r == "friction") return Reading::friction;
  if (r == "frictionless") return Reading::frictionless;
  throw Input_error("reading: \"" + r + "\" is not one of friction, frictionless");
}

// The bindings offer exact and hybrid (the same exact answer) for the constructions; the float twin's
// bounded values are the CLI's and the C++ API's (float/).
Request exact_request(const std::string& mode, const char* what, const Input_limits& limits) {
  const Request r = request_of(mode, limits);
  if (r.mode == Mode::float_only)
    throw Input_error(std::string("mode: \"float\" is not offered by wrenchkit.") + what +
                      " (the float twin's bounded values are in `wrenchkit " + what + " --mode float --json`); use "
                      "\"hybrid\" or \"exact\"");
  return r;
}

// The labels of a reading as wrenchkit.labels returns them (wrenchkit.reuleaux adds its query).
py::dict labels_dict(const Labels_item& r, Reading rd, const std::string& reading, const std::string& mode) {
  const Moment_labels& l = r.labels;
  py::dict d;
  d["reading"] = reading;
  d["mode"] = mode;
  d["rank"] = l.cone.rank;
  d[rd == Reading::friction ? "force_closure" : "form_closure"] = r.closed();
  d["plus"] = region(l.plus);
  d["minus"] = region(l.minus);
  d["both"] = both(l.both);
  d["infinity"] = infinity(l.infinity);
  if (r.load) {
    py::dict ld;
    ld["wrench"] = triple(*r.load);
    ld["balanced"] = *r.load_balanced;
    d["load"] = ld;
  }
  return d;
}

py::dict labels(const Py_scene& s, const std::string& reading, const std::string& mode) {
  const Reading rd = reading_of_text(reading);
  Labels_query q;
  q.question = rd == Reading::friction ? Labels_question::labels : Labels_question::reuleaux;
  const Labels_item r = answer_labels(s.scene, exact_request(mode, "labels", s.limits), q);
  raise_unless_answered(r.status, r.message);
  return labels_dict(r, rd, reading, mode);
}

// A command's options from the words of its command line, by the command line's own table (its validation and
// messages: a usage error is an InputError), within the scene's limits.
cli::Options command_options(const std::string& command, const std::vector<std::string>& words, const Input_limits& limits) {
  try {
    cli::Options o = cli::parse_options(command, words);
    o.limits = limits;
    return o;
  } catch (const cli::Usage_error& e) {
    throw Input_error(e.what());
  }
}

// Reuleaux's method (`wrenchkit reuleaux`): the frictionless reading's labels and form closure, and with a motion
// (the words --center x,y [--sense ccw|cw], --direction dx,dy or --twist vx,vy,w) its "query": the twist, its
// reading, feasible, marginal and each contact's mode.
py::dict reuleaux(const Py_scene& s, const std::vector<std::string>& words, const std::string& mode) {
  Labels_query q;
  try {
    q = cli::reuleaux_query(command_options("reuleaux", words, s.limits));
  } catch (const cli::Usage_error& e) {
    throw Input_error(e.what());
  }
  const Labels_item r = answer_labels(s.scene, exact_request(mode, "reuleaux", s.limits), q);
  raise_unless_answered(r.status, r.message);
  py::dict d = labels_dict(r, Reading::frictionless, "frictionless", mode);
  if (q.motion) {
    const std::array<Rational, 3> t = {(*q.motion)[0], (*q.motion)[1], (*q.motion)[2]};
    py::dict query;
    query["twist"] = triple(*q.motion);
    query["reading"] = reading_dict(t);
    query["feasible"] = r.modes->feasible;
    query["marginal"] = r.modes->marginal;
    py::list modes;
    for (std::size_t i = 0; i < r.modes->modes.size(); ++i) {
      py::dict m;
      m["contact"] = i;
      m["mode"] = mode_name(r.modes->modes[i]);
      modes.append(m);
    }
    query["modes"] = modes;
    d["query"] = query;
  }
  return d;
}

// `wrenchkit render` (--what, --sides in `words`): the SVG text.
std::string render(const Py_scene& s, const std::vector<std::string>& words) {
  const cli::Options o = command_options("render", words, s.limits);
  try {
    return cli::render_svg(o, s.text, s.source);
  } catch (const cli::Usage_error& e) {
    throw Input_error(e.what());
  } catch (const cli::Failure& e) {
    raise_unless_answered(e.status, e.what());
    throw;
  }
}

// `wrenchkit quality --json` (its options in `words`): the answer's JSON text, written by the command's one writer.
std::string quality(const Py_scene& s, const std::vector<std::string>& words, const std::string& mode) {
  Quality_query q;
  try {
    q = cli::quality_query(command_options("quality", words, s.limits));
  } catch (const cli::Usage_error& e) {
    throw Input_error(e.what());
  }
  const Quality_item r = answer_quality(s.scene, s.text, request_of(mode, s.limits), q);
  raise_unless_answered(r.status, r.message);
  return cli::json_answer([&](Json_writer& w) { cli::write_quality(w, r); });
}

// `wrenchkit grasp-regions --json` (--mu, --edges, --fingers in `words`): the answer's JSON text.
std::string grasp_regions(const Py_scene& s, const std::vector<std::string>& words) {
  cli::Options o;
  try {
    o = command_options("grasp-regions", words, s.limits);
  } catch (const cli::Usage_error& e) {
    throw Input_error(e.what());
  }
  const Grasp_regions_item r = answer_grasp_regions(s.text, s.source, request_of("hybrid", s.limits), o.regions);
  raise_unless_answered(r.status, r.message);
  return cli::json_answer([&](Json_writer& w) { cli::write_grasp_regions(w, r); });
}

// `wrenchkit push --json`: the answer's JSON text ("rotation": "undecided" is an answer here; the command exits 3).
std::string push(const Py_scene& s, bool contact, bool region, bool locus) {
  Push_query q;
  q.contact = contact;
  q.region = region;
  q.locus = locus;
  const Push_item r = answer_push(s.text, s.source, request_of("hybrid", s.limits), q);
  raise_unless_answered(r.status, r.message);
  return cli::json_answer([&](Json_writer& w) { cli::write_push(w, r); });
}

// `wrenchkit compare --json` (its options in `words`, CORPUS and ANSWERS last): the report's JSON text.
std::string compare(const std::vector<std::string>& words) {
  const cli::Options o = command_options("compare", words, Input_limits{});
  if (o.positional.size() != 2) throw Input_error("compare needs CORPUS and ANSWERS");
  Compare_options c = o.compare;
  c.tolerance = o.tolerance, c.tolerance_text = o.tolerance_text;
  c.limits = o.limits;
  c.json = true;
  const Compare_report report = compare_answers(o.positional[0], o.positional[1], c, cli::read_input);
  return report.text;
}

py::object dual_point_obj(const Dual_point& p) {
  py::dict d;
  if (p.sheet == 'i') {
    d["sheet"] = "infinity";
    d["direction"] = point(p.at);
  } else if (p.sheet == '0') {
    d["sheet"] = "zero";
  } else {
    d["sheet"] = std::string(1, p.sheet);
    d["point"] = point(p.at);
  }
  return d;
}

py::dict dual(const Py_scene& s, const std::string& mode) {
  Labels_query q;
  q.question = Labels_question::dual;
  const Labels_item r = answer_labels(s.scene, exact_request(mode, "dual", s.limits), q);
  raise_unless_answered(r.status, r.message);
  const Force_dual& f = *r.dual;
  const std::vector<Generator>& gens = r.generators;
  py::dict d;
  d["covers_all"] = f.covers_all;
  d["plus_region"] = region(f.plus_sheet);
  d["minus_region"] = region(f.minus_sheet);
  d["infinity"] = infinity(f.infinity);
  py::list g;
  for (std::size_t i = 0; i < gens.size(); ++i) {
    py::dict x;
    x["contact"] = gens[i].contact;
    x["edge"] = edge_name(gens[i].edge);
    x["dual"] = dual_point_obj(f.generators[i]);
    g.append(x);
  }
  d["generators"] = g;
  if (f.reference) {
    py::dict r;
    r["point"] = point(*f.reference);
    r["polygon"] = region(f.about_reference);
    d["reference"] = r;
  } else {
    d["reference"] = py::none();
  }
  return d;
}

py::dict face(const Ls_face& f) {
  py::dict d;
  d["dimension"] = f.dimension;
  py::list v;
  for (const Vec3q& x : f.vertices) v.append(triple(x));
  d["vertices"] = v;
  return d;
}

py::dict polytope(const Ls_polytope& P) {
  py::dict d;
  d["dimension"] = P.dimension;
  d["facets"] = P.facets.size();
  d["vertices"] = P.vertices.size();
  d["edges"] = P.edges;
  return d;
}

int checked_sides(int sides) {
  if (sides < 4 || sides % 2 != 0 || sides > kMaxSides)
    throw Input_error("sides: " + std::to_string(sides) + " must be even and between 4 and " + std::to_string(kMaxSides));
  return sides;
}

Vec3q nonzero_twist(const std::vector<std::string>& t) {
  const Vec3q q = vec3(t, "twist");
  if (q[0] == 0 && q[1] == 0 && q[2] == 0) throw Input_error("twist: the zero twist (no motion, no load)");
  return q;
}

py::tuple distribution(const std::vector<Rational>& f) {
  py::list l;
  for (const Rational& x : f) l.append(fraction(x));
  return py::tuple(l);
}

// The support's regions: [{area, force, mu, center_of_pressure, pressure, pressure_coefficients, second_moments}, …].
py::list region_list(const Support& sup) {
  py::list regions;
  for (const Support_region& g : sup.regions) {
    py::dict x;
    x["area"] = fraction(g.area);
    x["force"] = fraction(g.total);
    x["mu"] = fraction(sup.mu_of(g));
    x["center_of_pressure"] = point({g.moment.x / g.total, g.moment.y / g.total});
    x["pressure"] = g.uniform ? "uniform" : "linear";
    x["pressure_coefficients"] = triple(g.pressure[0], g.pressure[1], g.pressure[2]);
    x["second_moments"] = triple(g.second[0], g.second[1], g.second[2]);
    regions.append(x);
  }
  return regions;
}

// A load's motion, whatever the support: "motion", "motion_decided_by", on the surface the twist it may slip with
// ("impending_twist": every distribution's over F), and why undecided.
void motion_fields(py::dict& d, const Motion_answer& m) {
  d["motion"] = motion_name(m.motion);
  d["motion_decided_by"] = decided_by_name(m.decided_by);
  if (m.motion == Motion::impending) d["impending_twist"] = triple(m.impending ? m.impending->twist.twist : m.sliding->twist);
  if (!m.undecided_why.empty()) d["undecided_why"] = m.undecided_why;
}

// A support with unknown forces (limit_surface and sliding alike): the admissible set, the power of a twist
// over it, and whether a load sticks for every distribution, slides for every one, or depends.
py::dict unknown_distribution(const Support_item& r, const std::string& mode, const Support_query& q) {
  py::dict d;
  d["mode"] = mode;
  d["distribution"] = "unknown";
  d["unknown_points"] = r.admissible->unknown;
  d["weight"] = fraction(r.weight);
  d["pressure_center"] = point(r.pressure_center);
  py::list v;
  for (const auto& f : r.vertices) v.append(distribution(f));
  d["extreme_distributions"] = v;
  if (r.power) {
    d["twist"] = triple(*q.twist);
    d["power"] = py::make_tuple(fraction(r.power->lower), fraction(r.power->upper));
    d["min_distribution"] = distribution(r.power->min_distribution);
    d["max_distribution"] = distribution(r.power->max_distribution);
  }
  if (r.regions) {  // [RG-3] regions beside points without a force: given in F; their bracket is inside "power"
    d["regions"] = region_list(*r.scene.support);
    if (r.regions->has_twist) d["regions_power_bracket"] = py::make_tuple(fraction(r.regions->h_lo), fraction(r.regions->h_hi));
  }
  if (r.motion) {
    const Motion_answer& m = *r.motion;
    d["load"] = triple(*q.load);
    motion_fields(d, m);
    if (m.motion == Motion::depends) {
      py::dict w;
      w["sticks"] = distribution(m.sticking->distribution);
      w["slides"] = distribution(m.sliding->distribution);
      w["sticks_motion"] = motion_name(m.held_as);  // sticks, or impending (on its surface)
      w["slides_motion"] = motion_name(m.moved_as);  // slides, or impending
      d["witnesses"] = w;
    }
    if (m.motion == Motion::slides) d["separating_twist"] = triple(m.sliding->twist);
    if (r.regions) d["certificate_json"] = r.certificate;  // format 2 (checked)
  }
  return d;
}

// The polygonal surfaces' power bounds and loads of a twist (limit_surface and sliding alike).
void polygonal_twist_fields(py::dict& d, const Sliding_answer& a) {
  d["h_inner"] = fraction(a.h_inner);
  d["h_outer"] = fraction(a.h_outer);
  d["inner_load"] = face(a.inner_face);
  d["outer_load"] = face(a.outer_face);
}

// A support with regions [RG-1] (limit_surface and sliding alike): the exact statics, the twist's certified power
// and load, the load's motion with its (checked) certificate.
py::dict regions_dict(const Support_item& r, const std::string& mode, const Support_query& q) {
  const Support& sup = *r.scene.support;
  const Region_sliding& a = *r.regions;
  py::dict d;
  d["mode"] = mode;
  d["regions"] = region_list(sup);
  d["total_force"] = fraction(a.total_force);
  d["center_of_friction"] = point(a.center_of_pressure);
  d["friction_centroid"] = point(a.friction_centroid);
  d["mu_f0"] = fraction(a.mu_f0);
  if (a.has_twist) {
    d["twist"] = triple(a.twist[0], a.twist[1], a.twist[2]);
    d["motion"] = a.translation ? "translation" : "rotation";
    if (a.translation) {
      d["load_direction"] = triple(a.load_direction[0], a.load_direction[1], a.load_direction[2]);
      d["speed_squared"] = fraction(a.speed_squared);
      d["load"] = a.load ? py::object(triple((*a.load)[0], (*a.load)[1], (*a.load)[2])) : py::object(py::none());
    } else {
      d["rotation_center"] = point(a.rotation_center);
    }
    d["power_bracket"] = py::make_tuple(fraction(a.h_lo), fraction(a.h_hi));
    d["tolerance_met"] = a.met;
    d["load_box"] = py::make_tuple(triple(a.load_lo[0], a.load_lo[1], a.load_lo[2]),
                                   triple(a.load_hi[0], a.load_hi[1], a.load_hi[2]));
  }
  if (r.motion) {
    const Motion_answer& m = *r.motion;
    d["load"] = triple((*q.load)[0], (*q.load)[1], (*q.load)[2]);
    motion_fields(d, m);
    d["certificate_json"] = r.certificate;
  }
  return d;
}

std::optional<Rational> positive_tolerance(const std::optional<std::string>& tolerance) {
  if (!tolerance) return std::nullopt;
  const Rational e = number(*tolerance, "tolerance");
  if (e <= 0) throw Input_error("tolerance: \"" + *tolerance + "\" must be > 0");
  return e;
}

py::dict limit_surface(const Py_scene& s, int sides, const std::optional<std::string>& tolerance,
                       const std::optional<std::vector<std::string>>& twist,
                       const std::optional<std::vector<std::string>>& load, const std::string& mode) {
  Support_query q;
  if (twist) q.twist = nonzero_twist(*twist);
  if (load) q.load = vec3(*load, "load");
  const bool regions = s.scene.support && !s.scene.support->regions.empty();
  if (regions) {  // no polytopes: tolerance is the power's relative width
    q.tolerance = positive_tolerance(tolerance);
  } else if (tolerance) {
    const Rational e = number(*tolerance, "tolerance");
    if (e <= 0) throw Input_error("tolerance: \"" + *tolerance + "\" must be > 0");
    sides = smallest_sides(e, kMaxSides);
    if (sides == 0)
      throw Input_error("tolerance: " + *tolerance + " needs more than " + std::to_string(kMaxSides) + " sides");
  }
  if (!regions) q.sides = checked_sides(sides);
  const Support_item r = answer_support(s.scene, s.text, s.source, exact_request(mode, "limit_surface", s.limits), q);
  raise_unless_answered(r.status, r.message);
  if (r.kind == Support_kind::unknown) return unknown_distribution(r, mode, q);  // with regions too (their statics)
  if (r.kind == Support_kind::regions) return regions_dict(r, mode, q);
  const Sliding_answer& sa = r.sliding;
  py::dict d;
  d["mode"] = mode;
  d["sides"] = sides;
  d["lambda_squared"] = fraction(r.model->directions().lambda_sq);
  d["dimension"] = r.model->dimension();
  d["center_of_friction"] = point(sa.center_of_friction);
  d["mu_f0"] = fraction(sa.mu_f0);
  d["inner"] = polytope(r.in);
  d["outer"] = polytope(r.out);
  if (q.twist) {
    d["twist"] = triple(*q.twist);
    polygonal_twist_fields(d, sa);
  }
  if (q.load) {
    d["load"] = triple(*q.load);
    motion_fields(d, *r.motion);
    py::dict g;
    g["inner"] = r.gauge_in ? fraction(*r.gauge_in) : py::none();
    g["outer"] = r.gauge_out ? fraction(*r.gauge_out) : py::none();
    d["gauge"] = g;
  }
  return d;
}

py::dict sliding(const Py_scene& s, const std::optional<std::vector<std::string>>& twist, int sides,
                 const std::string& mode, const std::optional<std::string>& tolerance) {
  Support_query q;
  q.question = Support_question::sliding;
  q.sides = checked_sides(sides);
  q.tolerance = positive_tolerance(tolerance);
  if (twist) q.twist = nonzero_twist(*twist);
  const Support_item r = answer_support(s.scene, s.text, s.source, exact_request(mode, "sliding", s.limits), q);
  raise_unless_answered(r.status, r.message);
  if (r.kind == Support_kind::unknown) return unknown_distribution(r, mode, q);  // with regions too (their statics)
  if (r.kind == Support_kind::regions) return regions_dict(r, mode, q);
  py::dict d;
  d["mode"] = mode;
  const Sliding_answer& a = r.sliding;
  d["center_of_friction"] = point(a.center_of_friction);
  d["friction_centroid"] = point(a.friction_centroid);
  d["mu_f0"] = fraction(a.mu_f0);
  if (a.has_twist) {
    const char* kinds[] = {"facet", "vertex", "smooth"};
    d["twist"] = triple(a.twist);
    d["motion"] = a.translation ? "translation" : "rotation";
    if (a.translation) {
      d["load_direction"] = triple(a.load_direction);
      d["speed_squared"] = fraction(a.speed_squared);
      d["load"] = a.load ? py::object(triple(*a.load)) : py::object(py::none());
    } else {
      d["rotation_center"] = point(a.rotation_center);
    }
    d["true_surface"] = kinds[static_cast<int>(a.cls.kind)];
    d["true_surface_text"] = a.cls.text;
    d["sides"] = sides;
    d["lambda_squared"] = fraction(r.model->directions().lambda_sq);
    d["power_bracket"] = py::make_tuple(fraction(a.h_lo), fraction(a.h_hi));
    d["load_box"] = py::make_tuple(triple(a.load_lo), triple(a.load_hi));
    polygonal_twist_fields(d, a);
  }
  return d;
}

py::dict check(const Py_scene& s, const std::string& certificate) {
  const auto r = wrenchkit_checker::check(s.text, certificate, checker_limits(s.limits));
  if (r.outcome == wrenchkit_checker::Outcome::bad_scene) throw Input_error(r.message);
  py::dict d;
  d["accepted"] = r.outcome == wrenchkit_checker::Outcome::accepted;
  d["reason"] = r.outcome == wrenchkit_checker::Outcome::accepted ? std::string() : r.message;
  return d;
}

// wrenchkit.reference(scenes, out, sides): the corpus of the user's own scenes, the same C++ as
// `wrenchkit reference --scenes PATH --out DIR` (conformance/corpus.h). Returns
// {"scenes": n, "certificates_checked": n, "bytes": n}.
py::dict reference(const std::string& scenes, const std::string& out, int sides) {
  if (sides < 4 || sides > 64 || sides % 2) throw Input_error("sides: " + std::to_string(sides) + " is not even in 4..64");
  if (const std::string why = corpus_dir_problem(out); !why.empty()) throw Input_error("out: " + why);
  const Reference_corpus corpus = user_corpus(scenes, sides);
  raise_unless_answered(corpus.status, corpus.message);
  const std::size_t bytes = write_corpus(out, corpus.ids, corpus.items, user_manifest(scenes, sides, corpus.ids.size()));
  py::dict d;
  d["scenes"] = corpus.ids.size();
  d["certificates_checked"] = corpus.certificates;
  d["bytes"] = bytes;
  return d;
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "wrenchkit's native engine (use the wrenchkit package, not this module)";
  use_throwing_gmp_allocation();  // out of memory: InternalError, never an abort of the interpreter
  m.def("_set_exceptions", [](py::object input, py::object internal, py::object undecided) {
    g_input_error = input;
    g_internal_error = internal;
    g_undecided_error = undecided;
  });
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const Input_error& e) {
      PyErr_SetString(g_input_error.ptr(), e.what());
    } catch (const Undecided_exception& e) {
      PyErr_SetString(g_undecided_error.ptr(), e.message.c_str());
    } catch (const std::invalid_argument& e) {
      PyErr_SetString(g_input_error.ptr(), e.what());
    } catch (const std::length_error& e) {
      PyErr_SetString(g_input_error.ptr(), e.what());
    } catch (const std::runtime_error& e) {
      PyErr_SetString(g_internal_error.ptr(), e.what());
    } catch (const std::logic_error& e) {
      PyErr_SetString(g_internal_error.ptr(), (std::string("internal error (please report): ") + e.what()).c_str());
    }
  });
  py::class_<Py_scene>(m, "_Scene")
      .def_readonly("text", &Py_scene::text)
      .def_readonly("source", &Py_scene::source)
      .def_property_readonly("name", [](const Py_scene& s) { return s.scene.name; })
      .def_property_readonly("warnings", [](const Py_scene& s) { return s.scene.warnings; })
      .def_property_readonly("contacts", [](const Py_scene& s) { return s.scene.contacts.size(); })
      .def_property_readonly("has_load", [](const Py_scene& s) { return s.scene.load.has_value(); })
      .def_property_readonly("has_support", [](const Py_scene& s) { return s.scene.support.has_value(); });
  m.def("read", &read_text, py::arg("text"), py::arg("source"), py::arg("limits"));
  m.def("closure", &closure);
  m.def("equilibrium", &equilibrium);
  m.def("hold", &hold);
  m.def("labels", &labels);
  m.def("reuleaux", &reuleaux);
  m.def("render", &render);
  m.def("compare", &compare);
  m.def("quality", &quality);
  m.def("grasp_regions", &grasp_regions);
  m.def("push", &push);
  m.def("dual", &dual);
  m.def("limit_surface", &limit_surface);
  m.def("sliding", &sliding);
  m.def("check", &check);
  m.def("reference", &reference);
  register_arrays(m);
  register_batch(m);
}
