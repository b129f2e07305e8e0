#include "conformance/corpus.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>

#include "exact/io/input_error.h"
#include "exact/io/json.h"
#include "exact/io/scene_writer.h"
#include "exact/pipeline/answer_json.h"
#include "exact/pipeline/hold_answer.h"
#include "exact/certificates/certificates.h"
#include "exact/pipeline/grasp_regions_answer.h"
#include "exact/pipeline/push_answer.h"
#include "exact/pipeline/quality_answer.h"
#include "exact/pipeline/support_answer.h"
#include "exact/sliding/limit_surface.h"
#include "exact/sliding/sliding.h"
#include "exact/statics/boundary_distance.h"
#include "exact/statics/moment_labels.h"

namespace wrenchkit {

namespace {

void write_double(Json_writer& w, double d) {  // a double for reading, as a JSON number
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", d);
  w.raw(b);
}
void write_double(Json_writer& w, const std::optional<double>& d) { d ? write_double(w, *d) : void(w.null()); }
// A text, or null when it is empty.
void write_text_or_null(Json_writer& w, const std::string& s) { s.empty() ? void(w.null()) : void(w.string(s)); }


void write_flip(Json_writer& w, const std::optional<Friction_flip>& f) {
  if (!f) {
    w.null();
    return;
  }
  w.object().key("flips_between").array().rational(f->lo).rational(f->hi).end_array();
  write_double(w.key("distance"), f->distance);
  w.end_object();
}

// One verdict's own distance [RF-1]: its reading's smallest deciding determinant and, where friction
// decides it, its friction scale; the smaller one, which one, and the reading's exact zeros.
void write_field_distance(Json_writer& w, const Predicate_margin& m, const std::optional<Friction_flip>& flip) {
  std::optional<double> d = m.min_relative;
  const char* nearest = d ? "determinant" : nullptr;
  if (flip && (!d || flip->distance < *d)) d = flip->distance, nearest = "friction_scale";
  w.object();
  write_double(w.key("distance"), d);
  nearest ? void(w.member("nearest", nearest)) : void(w.key("nearest").null());
  w.member("exact_zero_determinants", m.exact_zeros).end_object();
}

// `hold_measured`: the scene has a load and no support, where hold is equilibrium ([HD-1]: LS = {0}) and has its
// distance; over a support hold has no boundary measure (like motion).
void write_boundary(Json_writer& w, const Boundary_distance& b, const std::string& epsilon, bool load,
                    bool hold_measured) {
  w.object().key("epsilon");
  epsilon.empty() ? w.null() : w.raw(epsilon);
  write_double(w.key("distance"), b.distance);
  write_text_or_null(w.key("nearest"), b.nearest);
  w.member("exact_zero_determinants", b.exact_zeros());
  write_double(w.key("min_relative_determinant").object().key("force_closure"), b.force.min_relative);
  write_double(w.key("form_closure"), b.form.min_relative);
  if (load) write_double(w.key("equilibrium"), b.equilibrium.min_relative);
  write_flip(w.end_object().key("friction_scale").object().key("force_closure"), b.closure_flip);
  if (load) write_flip(w.key("equilibrium"), b.equilibrium_flip);
  w.end_object().key("fields").object();
  write_field_distance(w.key("force_closure"), b.force, b.closure_flip);
  write_field_distance(w.key("form_closure"), b.form, std::nullopt);
  if (load) write_field_distance(w.key("equilibrium"), b.equilibrium, b.equilibrium_flip);
  if (hold_measured) write_field_distance(w.key("hold"), b.equilibrium, b.equilibrium_flip);
  w.end_object().end_object();
}

// The twists at which the power is bracketed: translations along x and y, a rotation about the
// origin, a generic twist, and a rotation about the first support point (a facet of the true LS).
std::vector<Vec3q> reference_twists(const Scene& scene) {
  std::vector<Vec3q> t = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 2, 3}};
  if (!scene.support->known()) {  // the first point, unmerged (the merge needs every force)
    const Vec2& p = scene.support->points.front().at;
    if (p.x != 0 || p.y != 0) t.push_back({p.y, -p.x, 1});
    return t;
  }
  const Ls_support s = merge_support(*scene.support);
  if (!s.points.empty()) t.push_back({s.points[0].at.y, -s.points[0].at.x, 1});
  return t;
}

// A known distribution: the polygonal limit surfaces and the power brackets (docs/reference-format.md §3).
void write_limit_surface(Json_writer& w, const Scene& scene, int sides) {
  const Polygonal_ls model(merge_support(*scene.support), make_directions(sides));
  if (model.candidate_count() > kMaxCandidates)
    throw Input_error("support: too many candidate normals for the corpus' " + std::to_string(sides) + "-gons");
  const Ls_polytope in = model.build(Side::inner), out = model.build(Side::outer);
  const Sliding_answer base = compute_sliding(model, std::nullopt);
  w.object().member("sides", sides).member("lambda_squared", model.directions().lambda_sq);
  w.member("dimension", model.dimension()).key("center_of_friction").array();
  w.rational(base.center_of_friction.x).rational(base.center_of_friction.y).end_array().member("mu_f0", base.mu_f0);
  w.key("inner").object().member("facets", in.facets.size()).member("vertices", in.vertices.size()).end_object();
  w.key("outer").object().member("facets", out.facets.size()).member("vertices", out.vertices.size()).end_object();
  const char* kinds[] = {"facet", "vertex", "smooth"};
  w.key("twists").array();
  for (const Vec3q& t : reference_twists(scene)) {
    const Sliding_answer a = compute_sliding(model, t);
    w.object().key("twist").rationals(t);
    w.member("h_inner", a.h_inner).member("h_outer", a.h_outer);
    w.key("power_bracket").array().rational(a.h_lo).rational(a.h_hi).end_array();
    w.member("true_surface", kinds[static_cast<int>(a.cls.kind)]).end_object();
  }
  w.end_array().end_object();
}

// An unknown distribution (a point without "force"; regions beside the points count as given, RG-3): for each twist
// the range of the power over every admissible distribution, through the pipeline (answer_support, `wrenchkit
// sliding`; with regions, the points' range plus the regions' certified bracket).
void write_unknown_limit_surface(Json_writer& w, const Scene& scene, std::string_view text, int sides) {
  Request request;
  request.mode = Mode::exact;
  w.object().member("sides", sides).member("distribution", "unknown").key("twists").array();
  for (const Vec3q& t : reference_twists(scene)) {
    Support_query q;
    q.question = Support_question::sliding;
    q.sides = sides;
    q.twist = t;
    if (!scene.support->regions.empty()) q.tolerance = Rational("1/1000000000000000");  // as the regions' brackets
    const Support_item r = answer_support(scene, text, "", request, q);
    if (r.status != Status::answered || !r.power) throw Input_error(r.message);
    w.object().key("twist").rationals(t);
    w.key("power_range").array().rational(r.power->lower).rational(r.power->upper).end_array().end_object();
  }
  w.end_array().end_object();
}

// A support with regions [RG-1] [RG-2] (docs/regions.md): the exact statics and, for each twist, a certified
// bracket of the power, through the pipeline (answer_support, `wrenchkit sliding`). No polygons: the regions'
// limit surface is strictly convex. A question the engine refuses (regions with points whose force is not
// given) is written as the refusal: returns its message (the caller writes null), else "".
std::string write_region_limit_surface(Json_writer& w, const Scene& scene, std::string_view text) {
  Request request;
  request.mode = Mode::exact;
  Support_query q;
  q.question = Support_question::sliding;
  q.tolerance = Rational("1/1000000000000000");  // the brackets' relative width: 10^-15, within compare's --rtol 1e-9
  std::vector<Vec3q> twists = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 2, 3}};
  if (!scene.support->points.empty()) {  // a rotation about the first point: its disc is a facet
    const Vec2& p = scene.support->points.front().at;
    if (p.x != 0 || p.y != 0) twists.push_back({p.y, -p.x, 1});
  }
  std::vector<Support_item> items;
  for (const Vec3q& t : twists) {
    q.twist = t;
    items.push_back(answer_support(scene, text, "", request, q));
    if (items.back().status == Status::bad_input) return items.back().message;
    if (items.back().status != Status::answered || !items.back().regions) throw Input_error(items.back().message);
  }
  const Region_sliding& s = *items.front().regions;
  w.object().member("distribution", "regions").member("total_force", s.total_force);
  w.key("center_of_friction").array().rational(s.center_of_pressure.x).rational(s.center_of_pressure.y).end_array();
  w.member("mu_f0", s.mu_f0).key("twists").array();
  for (std::size_t i = 0; i < twists.size(); ++i) {
    const Region_sliding& r = *items[i].regions;
    w.object().key("twist").rationals(twists[i]);
    w.key("power_bracket").array().rational(r.h_lo).rational(r.h_hi).end_array().end_object();
  }
  w.end_array().end_object();
  return "";
}

// Can the contacts and the support's friction hold the body against the scene's load (`wrenchkit hold`,
// exact/fixture/hold.h)? In hybrid mode; only a verdict whose certificate the independent checker accepted is
// written ("true", "false", "depends"), else null and why: undecided, or a question the engine refuses (then its
// message; e.g. a support with regions and a point whose force is not given).
struct Hold_result {
  std::string verdict, certificate, why;
  bool check_failed = false;
};
Hold_result hold_of(const Scene& scene, std::string_view text) {
  Request request;
  request.mode = Mode::hybrid;
  const Hold_item r = answer_hold(scene, text, request);
  Hold_result h;
  h.check_failed = r.status == Status::check_failed;
  if (r.status != Status::answered) h.why = r.message;
  else if (r.certificate.empty()) h.why = r.answer.undecided_why.empty() ? "undecided" : r.answer.undecided_why;
  else {
    h.verdict = hold_word(r.answer.verdict);
    h.certificate = r.certificate;
  }
  return h;
}

// Does the body stick on its support under the scene's load (`wrenchkit limit-surface --load`)? In
// hybrid mode (the certified search on the true surface, then the polygons); only a verdict whose
// certificate the independent checker accepted is written, else null and why.
struct Motion_result {
  std::string motion, certificate, why;
  bool check_failed = false;  // the independent checker rejected our certificate: a bug
};
Motion_result motion_of(const Scene& scene, std::string_view text, int sides) {
  Request request;
  request.mode = Mode::hybrid;
  Support_query q;
  q.question = Support_question::limit_surface;
  q.sides = sides;
  q.polytopes = false;
  q.load = load_wrench(scene);
  const Support_item r = answer_support(scene, text, "", request, q);
  Motion_result m;
  m.check_failed = r.status == Status::check_failed;
  if (r.status != Status::answered) m.why = r.message;
  else if (r.certificate.empty()) m.why = r.motion->uncertified.empty() ? "undecided" : r.motion->uncertified;
  else {
    m.motion = motion_name(r.motion->motion);
    m.certificate = r.certificate;
  }
  return m;
}

bool valid_id(const std::string& id) {
  if (id.empty() || id.size() > 200 || id[0] == '.') return false;
  for (char c : id)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '.' && c != '-') return false;
  return true;
}

std::string read_file_text(const std::filesystem::path& p, const Input_limits& limits) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw Input_error(p.string() + ": cannot open");
  std::string s((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (s.size() > limits.max_file_bytes)
    throw Input_error(p.string() + ": larger than the size limit of " + std::to_string(limits.max_file_bytes) + " bytes");
  return s;
}

void write_text(const std::filesystem::path& p, const std::string& text) {
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out << text;
  out.flush();
  if (!out) throw Input_error(p.string() + ": cannot write");
}

}  // namespace

void write_shortest(Json_writer& w, double d) {
  char b[32];
  const auto r = std::to_chars(b, b + sizeof b, d);
  w.raw(std::string_view(b, static_cast<std::size_t>(r.ptr - b)));
}

void write_approx(Json_writer& w, const json::Value& v) {
  const auto number = [&](bool json_number) {
    std::string why;
    const std::optional<Rational> q = parse_rational(v.text, json_number, Input_limits{}, why);
    if (!q) return false;
    const std::optional<double> d = nearest_double(*q);
    d ? write_shortest(w, *d) : void(w.null());
    return true;
  };
  switch (v.type) {
    case json::Type::number:
      if (!number(true)) w.raw(v.text);
      break;
    case json::Type::string:
      if (!number(false)) w.string(v.text);
      break;
    case json::Type::array:
      w.array();
      for (const json::Value& x : v.items) write_approx(w, x);
      w.end_array();
      break;
    case json::Type::object:
      w.object();
      for (const auto& [k, x] : v.members) {
        w.key(k);
        if (k == "name" && x.type == json::Type::string) w.string(x.text);
        else write_approx(w, x);
      }
      w.end_object();
      break;
    default:
      w.raw(json::text_of(v));
  }
}

Reference_item reference_item(const Reference_scene& e, int sides) {
  Reference_item b;
  const std::string where = e.where.empty() ? e.id : e.where;
  guarded(b, Input_limits{}, [&] {
    Request request;
    request.mode = Mode::exact;
    const Scene parsed = read_scene(e.text, request.limits, where);
    b.canonical = write_scene(parsed);
    const std::string text = one_line(b.canonical);
    if (write_scene(read_scene(text, request.limits, e.id)) != b.canonical) {
      b.status = Status::check_failed;
      b.message = e.id + ": the one-line scene does not read back to the canonical scene";
      return;
    }
    // Closure and equilibrium through the commands' own checked path: every certificate is accepted by
    // the independent checker (on `text`, the bytes written) before we go on.
    const Closure_item c = answer_closure(parsed, text, request);
    if (c.status != Status::answered) {
      b.status = c.status, b.message = c.message;
      return;
    }
    std::optional<Equilibrium_item> eq;
    if (parsed.load) {
      eq = answer_equilibrium(parsed, text, request);
      if (eq->status != Status::answered) {
        b.status = eq->status, b.message = eq->message;
        return;
      }
      b.balanced = eq->answer.balanced;
    }
    b.force_closure = c.force.holds, b.form_closure = c.form.holds;
    b.rank_force = c.force.rank, b.rank_form = c.form.rank;
    const Moment_labels labels = moment_labels(parsed, Reading::friction);
    const Boundary_distance bd = boundary_distance(parsed);

    Json_writer w(8192);
    w.object().member("id", e.id).member("family", e.family);
    write_text_or_null(w.key("epsilon"), e.epsilon);
    write_text_or_null(w.key("side"), e.side);
    write_text_or_null(w.key("seed"), e.seed);
    write_text_or_null(w.key("source"), e.source);
    w.member("scene_file", "scenes/" + e.id + ".json").key("scene").raw(text);
    w.member("force_closure", c.force.holds).member("form_closure", c.form.holds);
    w.key("rank").object().member("force", c.force.rank).member("form", c.form.rank).end_object();
    if (eq) {
      const Vec3q& l = eq->answer.load;
      w.member("equilibrium", eq->answer.balanced);
      w.key("load").array().rational(l[0]).rational(l[1]).rational(l[2]).end_array();
    }
    write_labels(w.key("labels").object(), labels);
    w.end_object();
    Motion_result motion;
    if (parsed.support) {
      if (!parsed.support->regions.empty() && parsed.support->known()) {
        Json_writer ls(1024);
        const std::string refused = write_region_limit_surface(ls, parsed, text);
        w.key("limit_surface");
        refused.empty() ? void(w.raw(ls.str())) : void(w.null().member("limit_surface_refused", refused));
      } else if (parsed.support->known()) {
        write_limit_surface(w.key("limit_surface"), parsed, sides);
      } else {
        write_unknown_limit_surface(w.key("limit_surface"), parsed, text, sides);
      }
      if (parsed.load) {
        motion = motion_of(parsed, text, sides);
        if (motion.check_failed) {
          b.status = Status::check_failed, b.message = motion.why;
          return;
        }
        w.key("motion");
        motion.motion.empty() ? void(w.null()) : void(w.string(motion.motion));
        if (!motion.why.empty()) w.member("motion_uncertified", motion.why);
      }
    }
    Hold_result hold;
    if (parsed.load) {
      hold = hold_of(parsed, text);
      if (hold.check_failed) {
        b.status = Status::check_failed, b.message = hold.why;
        return;
      }
      w.key("hold");
      if (hold.verdict == "true" || hold.verdict == "false") w.boolean(hold.verdict == "true");
      else hold.verdict.empty() ? void(w.null()) : void(w.string(hold.verdict));
      if (!hold.why.empty()) w.member("hold_uncertified", hold.why);
    }
    // The grasp's quality ε (docs/quality.md) in the default conventions — L1, unit-normal edges, moments about
    // body.com (else the origin) with torque scale 1 —, exact or bracketed to 10^-12, certified; refused past the
    // work bound (the line says why).
    Quality_item quality;
    if (!parsed.contacts.empty()) {
      Quality_query q;
      q.critical_mu = false;
      quality = answer_quality(parsed, text, request, q);
      if (quality.status == Status::check_failed) {
        b.status = quality.status, b.message = quality.message;
        return;
      }
      if (quality.status == Status::answered) {
        const Quality_answer& a = quality.answer;
        w.key("quality").object().key("epsilon").object().member("lower", a.lower).member("upper", a.upper);
        if (a.exact) w.member("squared", a.squared);
        w.member("norm", quality_norm_name(a.query.norm)).member("normalize", normalization_name(a.query.normalize));
        w.member("torque_scale", a.query.torque_scale).key("about").rationals(std::array<Rational, 2>{a.about.x, a.about.y});
        w.end_object().end_object();
      } else {
        w.key("quality").null().member("quality_refused", quality.message);
      }
    }
    // Which way a pushed body turns (docs/pushing.md), for a scene with a pusher on a support: the rotation for every
    // admissible distribution, certified (the line says why when undecided or refused); and whether the contact
    // sticks or slides (PU-2; undecided, with why, for regions and forces not given); a line pusher: whether its
    // motion is stable for every distribution (PU-3).
    Push_item push;
    if (parsed.pusher && parsed.support) {
      Push_query contact;
      contact.contact = !parsed.pusher->line();  // (a line pusher answers whether its motion is stable)
      push = answer_push(text, e.id, request, contact);
      if (push.status == Status::check_failed) {
        b.status = push.status, b.message = push.message;
        return;
      }
      if (push.status == Status::answered) {
        w.key("push").object().member("rotation", rotation_name(push.push.rotation));
        if (push.push.center)
          w.key("center_of_friction").array().rational(push.push.center->x).rational(push.push.center->y).end_array();
        if (push.push.rotation == Rotation::undecided) w.member("why", push.push.why);
        if (const std::optional<Push_contact>& k = push.push.contact) {
          w.key("contact").object().member("mode", push_mode_name(k->mode));
          if (k->mode == Push_mode::undecided) w.member("why", k->why);
          w.end_object();
        }
        if (const std::optional<Stable_push>& st = push.push.stable) {  // a line pusher (PU-3)
          w.key("stable").object().member("verdict", stability_name(st->verdict));
          if (st->verdict == Stability::undecided) w.member("why", st->why);
          w.end_object();
        }
        w.end_object();
      } else {
        w.key("push").null().member("push_refused", push.message);
      }
    }
    // Where two and three fingers may go (docs/grasp-regions.md), for a part with an outline and a scene "mu": every
    // edge pair's exact region and, up to 12 edges, every edge triple's certified cube or "never" (GR-1, GR-2).
    Grasp_regions_item two, three;
    if (parsed.body.outline.size() >= 3 && parsed.mu) {
      Grasp_regions_query q;
      q.mu = parsed.mu;  // (the canonical text writes μ into each contact, not at the top)
      two = answer_grasp_regions(text, e.id, request, q);
      if (parsed.body.outline.size() <= 12 && two.status == Status::answered) {
        q.fingers = 3;
        three = answer_grasp_regions(text, e.id, request, q);
      }
      for (const Grasp_regions_item* g : {&two, &three})
        if (g->status == Status::check_failed) {
          b.status = g->status, b.message = g->message;
          return;
        }
      if (two.status == Status::answered) {
        w.key("grasp_regions").object().member("mu", two.regions.mu);
        write_region_pairs(w, two.regions);
        if (three.status == Status::answered) write_region_triples(w, three.regions);
        w.end_object();
      } else {
        w.key("grasp_regions").null().member("grasp_regions_refused", two.message);
      }
    }
    w.key("certificates").object().key("force_closure").raw(c.force_certificate);
    if (!two.certificate.empty()) w.key("grasp_regions").raw(two.certificate);
    if (!three.certificate.empty()) w.key("grasp_regions_three").raw(three.certificate);
    if (!push.certificate.empty()) w.key("push").raw(push.certificate);
    if (!quality.certificate.empty()) w.key("quality").raw(quality.certificate);
    w.key("form_closure").raw(c.form_certificate);
    if (eq) w.key("equilibrium").raw(eq->certificate);
    if (!motion.certificate.empty()) w.key("motion").raw(motion.certificate);
    if (!hold.certificate.empty()) w.key("hold").raw(hold.certificate);
    write_boundary(w.end_object().key("boundary"), bd, e.epsilon, eq.has_value(), eq && !parsed.support);
    // Every exact number of the answers again as its nearest double (docs/reference-format.md §2).
    const json::Value line = json::parse(w.str() + "}", Input_limits{}, e.id);
    w.key("approx").object();
    for (const char* k : {"scene", "load", "labels", "limit_surface", "quality", "grasp_regions"})
      if (const json::Value* x = line.find(k)) write_approx(w.key(k), *x);
    const json::Value& fs = *line.find("boundary")->find("friction_scale");
    w.key("friction_scale").object();
    for (const auto& [k, x] : fs.members) {
      w.key(k);
      x.type == json::Type::null ? void(w.null()) : write_approx(w, *x.find("flips_between"));
    }
    w.end_object().end_object();
    b.line = w.end_object().take();
    b.certificates = (eq ? 3 : 2) + !motion.certificate.empty() + !hold.certificate.empty() + !quality.certificate.empty() +
                     !push.certificate.empty() + !two.certificate.empty() + !three.certificate.empty();
    b.csv = e.id + "," + (c.force.holds ? "true" : "false") + "," + (c.form.holds ? "true" : "false") + "," +
            (eq ? (eq->answer.balanced ? "true" : "false") : "") + "," + hold.verdict;
  });
  if (b.status == Status::bad_input && b.message.compare(0, where.size(), where) != 0)
    b.message = where + ": " + b.message;
  return b;
}

bool Reference_corpus::add(const std::string& id, Reference_item item) {
  if (item.status != Status::answered) {
    status = item.status, message = std::move(item.message);
    return false;
  }
  ids.push_back(id);
  certificates += item.certificates;
  items.push_back(std::move(item));
  return true;
}

Reference_corpus user_corpus(const std::string& path, int sides) {
  Reference_corpus corpus;
  for (const Reference_scene& e : read_user_scenes(path, Input_limits{}))
    if (!corpus.add(e.id, reference_item(e, sides))) break;
  return corpus;
}

std::vector<Reference_scene> read_user_scenes(const std::string& path, const Input_limits& limits) {
  namespace fs = std::filesystem;
  std::vector<Reference_scene> out;
  std::set<std::string> ids;
  const auto add = [&](Reference_scene s, const std::string& where) {
    if (!valid_id(s.id))
      throw Input_error(where + ": id: " + json::quote(s.id) +
                        " is not a corpus id (letters, digits, _ . -, at most 200, not starting with .)");
    if (!ids.insert(s.id).second) throw Input_error(where + ": id: " + json::quote(s.id) + " appears twice");
    s.where = where;
    out.push_back(std::move(s));
  };
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    std::vector<fs::path> files;
    for (auto it = fs::recursive_directory_iterator(path, ec); !ec && it != fs::recursive_directory_iterator();
         it.increment(ec))
      if (it->is_regular_file() && it->path().extension() == ".json") files.push_back(it->path());
    if (ec) throw Input_error(path + ": cannot read the directory (" + ec.message() + ")");
    std::sort(files.begin(), files.end());
    for (const fs::path& f : files) {
      const fs::path rel = fs::relative(f, path);
      std::string id = rel.parent_path().empty() ? "" : rel.parent_path().generic_string() + "/";
      id += rel.stem().string();
      std::string family = rel.parent_path().empty() ? "user" : rel.parent_path().generic_string();
      for (char& c : id) c = c == '/' ? '.' : c;
      for (char& c : family) c = c == '/' ? '.' : c;
      add({id, family, rel.generic_string(), "", "", "", read_file_text(f, limits), ""}, f.string());
    }
    if (out.empty()) throw Input_error(path + ": no scene files (*.json) in the directory");
    return out;
  }
  const std::string text = read_file_text(path, limits);
  json::for_each_object_line(text, limits, path, "a scene line", [&](std::size_t line, const std::string& where,
                                                                     std::string_view raw, json::Value& v) {
    Reference_scene s{"line." + std::to_string(line), "user", where, "", "", "", "", ""};
    if (const json::Value* scene = v.find("scene")) {
      for (const auto& [k, x] : v.members) {
        if (k == "id" || k == "family") {
          if (x.type != json::Type::string) throw Input_error(where + ": " + k + ": " + json::text_of(x) + " is not a string");
          (k == "id" ? s.id : s.family) = x.text;
        } else if (k != "scene" && (k.empty() || k[0] != '_')) {
          throw Input_error(where + ": " + json::quote(k) +
                            ": unknown field (known: id, family, scene; fields starting with _ are ignored)");
        }
      }
      if (s.family.empty()) throw Input_error(where + ": family: empty");
      s.text = json::text_of(*scene);
    } else {
      s.text = std::string(raw);
    }
    add(std::move(s), where);
  });
  if (out.empty()) throw Input_error(path + ": no scenes (one scene per line, or {\"id\", \"scene\"})");
  return out;
}

std::string corpus_dir_problem(const std::string& d) {
  namespace fs = std::filesystem;
  const fs::path dir(d);
  std::error_code ec;
  if (!fs::exists(dir, ec)) return "";
  if (!fs::is_directory(dir, ec)) return d + " exists and is not a directory";
  if (fs::is_empty(dir, ec)) return "";
  std::ifstream m(dir / "manifest.json");
  std::string head(64, '\0');
  m.read(head.data(), 64);
  if (head.find("\"wrenchkit_reference\"") == std::string::npos)
    return d + " is not empty and holds no wrenchkit reference corpus (manifest.json); refusing to replace it";
  return "";
}

std::size_t write_corpus(const std::string& out_dir, const std::vector<std::string>& ids,
                         const std::vector<Reference_item>& items, const std::string& manifest) {
  namespace fs = std::filesystem;
  const fs::path dir(out_dir);
  // Everything goes to a temporary sibling first, then replaces DIR in one rename.
  const fs::path tmp = dir.string() + ".tmp-wrenchkit";
  std::error_code ec;
  fs::remove_all(tmp, ec);
  fs::create_directories(tmp / "scenes", ec);
  if (ec) throw Input_error(out_dir + ": cannot create (" + ec.message() + ")");
  std::string jsonl, csv = "id,force_closure,form_closure,equilibrium,hold\n";
  for (std::size_t i = 0; i < ids.size(); ++i) {
    jsonl += items[i].line + "\n";
    csv += items[i].csv + "\n";
    write_text(tmp / "scenes" / (ids[i] + ".json"), items[i].canonical);
  }
  write_text(tmp / "reference.jsonl", jsonl);
  write_text(tmp / "expected.csv", csv);
  write_text(tmp / "manifest.json", manifest);
  fs::remove_all(dir, ec);
  fs::rename(tmp, dir, ec);
  if (ec) throw Input_error(out_dir + ": cannot write (" + ec.message() + ")");
  return jsonl.size();
}

std::string user_manifest(const std::string& scenes_from, int sides, std::size_t scenes) {
  Json_writer m(512);
  m.object().member("wrenchkit_reference", kReferenceFormat).member("generator", "wrenchkit 0.1.0");
  m.member("format", "docs/reference-format.md").member("scenes_from", scenes_from).member("sides", sides);
  m.member("scenes", scenes).key("files").object().member("corpus", "reference.jsonl");
  m.member("scenes", "scenes/").member("verdicts", "expected.csv").end_object().end_object();
  return m.take() + "\n";
}

}  // namespace wrenchkit
