// wrenchkit quality: how good is the grasp — the Ferrari–Canny ε of the contacts with their friction (docs/quality.md,
// exact/statics/quality.h), exact or in a certified bracket, with a checked certificate.
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "cli/common.h"
#include "cli/float_json.h"
#include "exact/numbers/decimal.h"
#include "exact/pipeline/quality_answer.h"

namespace wrenchkit::cli {

namespace {


// "the left edge of c0 (its name)", "c2's normal", "the wrench c3".
std::string generator_name(const Scene& scene, const Generator_ref& g) {
  const std::string& name = scene.contacts[g.contact].name;
  const std::string c = "c" + std::to_string(g.contact) + (name.empty() ? "" : " (" + name + ")");
  switch (g.edge) {
    case Edge::left: return "the left edge of " + c;
    case Edge::right: return "the right edge of " + c;
    case Edge::normal: return "the normal of " + c;
    case Edge::wrench: return "the wrench " + c;
  }
  return c;
}

// Closure in the mode, then ε and μ* in exact arithmetic: hybrid when the closure was the twin's alone.
Arithmetic decided_by(const Quality_item& r) {
  const Quality_answer& a = r.answer;
  if (!r.epsilon) return r.mode == Mode::exact ? Arithmetic::exact : Arithmetic::hybrid;  // μ* only
  const bool exact_part = a.closure.holds || r.critical;
  return exact_part ? wrenchkit::decided_by(a.closure.decided_by(), Arithmetic::exact) : a.closure.decided_by();
}

// The wrench space in words: "L1 (the contacts' normal forces sum to at most 1)", its normalisation and moments.
std::string space_text(const Quality_answer& a) {
  std::ostringstream s;
  s << (a.query.norm == Quality_norm::l1 ? "L1: the hull of the friction-cone edges (normal forces summing to at most 1)"
                                         : "Linf: the sum of the contacts' cones (each normal force at most 1)")
    << "; forces " << normalization_name(a.query.normalize) << ", moments about " << vec_text(a.about) << " times "
    << (a.query.torque_radius_squared && a.torque_scale_error != 0
            ? "1/sqrt(" + human_number(*a.query.torque_radius_squared) + ") ≈ " + decimal_text(a.query.torque_scale, 9)
            : number_text(a.query.torque_scale));
  return s.str();
}

// A facet normal: small integers as they are, else a unit vector in decimals.
std::string normal_text(const Vec3q& n) {
  const Vec3q p = primitive_vec(n);
  if (to_string(p[0]).size() + to_string(p[1]).size() + to_string(p[2]).size() <= 24) return twist_text(p);
  const double x = p[0].get_d(), y = p[1].get_d(), z = p[2].get_d(), len = std::sqrt(x * x + y * y + z * z);
  char b[96];
  std::snprintf(b, sizeof b, "≈ (%.6g, %.6g, %.6g) (unit length)", x / len, y / len, z / len);
  return b;
}

void write_critical(Json_writer& w, const Critical_mu& c, const std::string& certificate) {
  w.object().member("kind", critical_kind_name(c.kind));
  if (c.kind == Critical_kind::value) {
    w.member("lower", c.lower).member("upper", c.upper);
    w.key("lower_approx").raw(float_number(c.lower.get_d())).key("upper_approx").raw(float_number(c.upper.get_d()));
    w.member("exact", c.exact());
    if (c.exact()) w.member("holds_at_critical", c.holds_at_critical);
  }
  w.member("decisions", c.decisions).member("certificate_checked", true).key("certificate").raw(certificate).end_object();
}

std::string critical_text(const Critical_mu& c, bool closure) {
  std::ostringstream s;
  const char* property = closure ? "closed" : "balanced";
  switch (c.kind) {
    case Critical_kind::always:
      s << "always — " << property << " even without friction (mu = 0), so for every mu";
      break;
    case Critical_kind::never:
      s << "never — no friction coefficient makes it " << property;
      if (c.limit_twist)
        s << ": every contact allows " << motion_text(*c.limit_twist) << " (twist " << twist_text(*c.limit_twist)
          << ") whatever mu" << (closure ? "" : ", and the load drives it");
      else s << ": only an infinite mu would balance the load";
      break;
    case Critical_kind::value:
      if (c.exact())
        s << "mu* = " << number_text(c.lower) << " exactly — "
          << (closure                ? "not closed at mu*, closed for every mu above it"
              : c.holds_at_critical ? "balanced at mu* and above, not below"
                                    : "balanced for every mu above mu*, not at mu* itself (nor below)");
      else
        s << "mu* ≈ " << decimal_text(c.lower, 12) << ", certified in [" << human_number(c.lower) << ", " << human_number(c.upper)
          << "] (not a rational of small height: its bracket)";
      break;
  }
  return s.str();
}

std::string margin_text(const Critical_mu& c) {
  switch (c.kind) {
    case Critical_kind::always: return "closed even without friction: any t";
    case Critical_kind::never: return "never closed, whatever t: " + critical_text(c, true).substr(8);
    case Critical_kind::value: break;
  }
  std::ostringstream s;
  const std::string t = c.exact() ? "t* = " + number_text(c.lower) + " exactly" : "t* ≈ " + decimal_text(c.lower, 12) + " (bracketed)";
  s << t << " — closed for every t above it; ";
  if (c.upper == 0) s << "any friction at all keeps the grasp closed";
  else if (c.upper < 1)
    s << "margin: every mu may shrink to just above " << decimal_text(c.upper, 6) << " of its value and the grasp stays closed";
  else if (c.lower >= 1) s << "the scene's friction (t = 1) is not enough: every mu must grow past " << decimal_text(c.lower, 6) << " times its value";
  else s << "the scene's friction is at the threshold";
  return s.str();
}

}  // namespace

void write_quality(Json_writer& w, const Quality_item& r) {
  const Quality_answer& a = r.answer;
  w.member("command", "quality").member("name", r.scene.name).member("mode", mode_name(r.mode));
  if (r.critical) {
    w.key("critical_mu").object().key("closure");
    write_critical(w, r.critical->closure, r.closure_mu_certificate);
    if (r.critical->equilibrium) write_critical(w.key("equilibrium"), *r.critical->equilibrium, r.balance_mu_certificate);
    w.end_object();
    if (r.critical->margin) write_critical(w.key("friction_margin"), *r.critical->margin, r.margin_certificate);
  }
  if (r.contact_margins) {
    const Contact_margins& m = *r.contact_margins;
    w.key("contact_margins").object().member("exact", m.exact).member("torque_scale", m.torque_scale);
    w.key("about").rationals(std::array<Rational, 2>{m.about.x, m.about.y});
    w.key("contacts").array();
    for (const Contact_margin& c : m.contacts) {
      w.object().member("contact", c.contact).member("name", r.scene.contacts[c.contact].name);
      if (c.squared) {
        w.member("squared", *c.squared).key("relative_volume_approx").raw(float_number(std::sqrt(c.squared->get_d())));
        w.key("nearest").array();
        for (const Generator_ref& g : c.nearest)
          w.object().member("contact", g.contact).member("edge", edge_name(g.edge)).end_object();
        w.end_array();
      }
      w.member("degenerate_triples", c.zeros).member("triples", c.triples).end_object();
    }
    w.end_array().end_object();
  }
  if (!r.epsilon) return;  // ε not asked
  w.member("force_closure", a.closure.holds);
  w.key("epsilon").object().member("lower", a.lower).member("upper", a.upper);
  if (a.exact) w.member("squared", a.squared);
  w.key("lower_approx").raw(float_number(a.lower.get_d())).key("upper_approx").raw(float_number(a.upper.get_d()));
  w.member("norm", quality_norm_name(a.query.norm)).member("normalize", normalization_name(a.query.normalize));
  w.member("torque_scale", a.query.torque_scale);
  if (a.query.torque_radius_squared) w.member("torque_radius_squared", *a.query.torque_radius_squared);
  if (a.torque_scale_error != 0) w.member("torque_scale_error", a.torque_scale_error);
  w.key("about").rationals(std::array<Rational, 2>{a.about.x, a.about.y});
  w.end_object();
  if (a.closure.holds) {
    w.key("nearest_facet").object();
    if (a.query.norm == Quality_norm::l1) {
      w.key("generators").array();
      for (std::size_t k : a.nearest)
        w.object().member("contact", a.refs[k].contact).member("edge", edge_name(a.refs[k].edge)).end_object();
      w.end_array();
    }
    w.key("normal").rationals(primitive(a.normal));
    const double nx = a.normal[0].get_d(), ny = a.normal[1].get_d(), nz = a.normal[2].get_d(), len = std::sqrt(nx * nx + ny * ny + nz * nz);
    w.key("normal_approx").array().raw(float_number(nx / len)).raw(float_number(ny / len)).raw(float_number(nz / len)).end_array();
    w.end_object();
    w.member("generators", a.refs.size());
    if (a.query.norm == Quality_norm::l1) w.member("hull_points", a.hull_points).member("hull_triangles", a.boundary.size());
  }
  w.member("decided_by", arithmetic_name(decided_by(r)));
  if (!r.certificate.empty()) w.member("certificate_checked", true).key("certificate").raw(r.certificate);
}

// The answers without the command's frame (its closure line, decided by, certificates): what analyze shows too.
std::string quality_body(const Quality_item& r) {
  const Quality_answer& a = r.answer;
  std::ostringstream s;
  const auto critical = [&] {
    if (!r.critical) return;
    s << "critical friction (one mu for every point contact):\n";
    s << "  force closure: " << critical_text(r.critical->closure, true) << "\n";
    if (r.critical->equilibrium) s << "  equilibrium of the load: " << critical_text(*r.critical->equilibrium, false) << "\n";
    if (r.critical->margin) s << "friction margin (every contact's own mu times one factor t): " << margin_text(*r.critical->margin) << "\n";
  };
  const auto margins = [&] {
    if (!r.contact_margins) return;
    const Contact_margins& m = *r.contact_margins;
    s << "contact margins (the least relative volume |det|/(|u||v||w|) of three edges holding the contact's own; 0: "
         "degenerate now; moments about "
      << vec_text(m.about) << " times " << (m.exact ? number_text(m.torque_scale) : "≈ " + decimal_text(m.torque_scale, 9))
      << "):\n";
    for (const Contact_margin& c : m.contacts) {
      const std::string& name = r.scene.contacts[c.contact].name;
      s << "  c" << c.contact << (name.empty() ? "" : " (" + name + ")") << ": ";
      if (!c.squared) {
        s << "no three edges to measure\n";
        continue;
      }
      if (*c.squared == 0) s << "0 — degenerate: " << c.zeros << " of its " << c.triples << " triples are coplanar, e.g. ";
      else s << "≈ " << decimal_text(Rational(c.squared->get_d() > 0 ? std::sqrt(c.squared->get_d()) : 0.0), 6)
             << " (squared " << human_number(*c.squared) << (m.exact ? ", exactly" : "") << "), nearest: ";
      for (std::size_t k = 0; k < 3; ++k) s << (k ? ", " : "") << generator_name(r.scene, c.nearest[k]);
      s << "\n";
    }
  };
  if (!r.epsilon) {
    critical();
    margins();
    return s.str();
  }
  s << "quality epsilon (" << space_text(a) << "):\n";
  if (!a.closure.holds) {
    s << "  epsilon = 0: the grasp is not in force closure (the twist " << twist_text(a.closure.certificate.twist)
      << " is allowed by every contact: " << motion_text(a.closure.certificate.twist) << ")\n";
  } else {
    if (a.lower == a.upper) s << "  epsilon = " << human_number(a.lower) << " (≈ " << decimal_text(a.lower, 15) << "), exactly\n";
    else if (a.exact)
      s << "  epsilon^2 = " << human_number(a.squared) << " (≈ " << decimal_text(a.squared, 15) << "), exactly; epsilon ≈ "
        << decimal_text(a.lower, 15) << "\n";
    else
      s << "  epsilon ≈ " << decimal_text(a.lower, 15) << " (irrational with these scales; certified within "
        << decimal_text(Rational(a.upper - a.lower), 2) << " in a rational bracket, given with --json)\n";
    if (a.query.norm == Quality_norm::l1) {
      s << "  nearest facet: ";
      for (std::size_t k = 0; k < 3; ++k) s << (k ? ", " : "") << generator_name(r.scene, a.refs[a.nearest[k]]);
      s << "; outward normal " << normal_text(a.normal) << "\n";
      s << "  the wrench space: " << a.refs.size() << " edges, " << a.hull_points << " on its boundary ("
        << a.boundary.size() << " triangles)\n";
    } else {
      s << "  nearest facet: outward normal " << normal_text(a.normal) << "\n";
    }
    s << "  every wrench of size up to epsilon is resisted with normal contact forces "
      << (a.query.norm == Quality_norm::l1 ? "summing to at most 1" : "each at most 1") << "\n";
  }
  critical();
  margins();
  return s.str();
}

std::string quality_human(const Quality_item& r) {
  std::ostringstream s;
  if (r.epsilon) s << "force closure: " << (r.answer.closure.holds ? "yes" : "no") << "\n";
  s << quality_body(r);
  if (r.epsilon) s << "decided by: " << arithmetic_name(decided_by(r)) << " (" << mode_name(r.mode) << " mode)\n";
  s << (r.critical ? "certificates" : "certificate") << " accepted by the independent checker (exact arithmetic)\n";
  return s.str();
}

Quality_query quality_query(const Options& o) {
  Quality_query q = o.quality;
  if (o.tolerance) q.tolerance = *o.tolerance;
  if (q.preset == Quality_preset::graspit && (q.about || q.torque_scale != 1))
    throw Usage_error("--preset graspit sets the moments' point (body.com) and their scale (1/maxRadius): drop --about and --torque-scale");
  if (q.preset == Quality_preset::dexnet && q.about) throw Usage_error("--preset dexnet takes moments about body.com: drop --about");
  return q;
}

Scene_answer prepare_quality_json(const Options& o) {
  return [request = request_of(o), query = quality_query(o)](Json_writer& w, const std::string& text, const std::string& source) {
    write_quality(w, answered(answer_quality(text, source, request, query)));
  };
}

int run_quality(const Options& o, const std::string& scene_text, const std::string& source) {
  const Quality_item r = answered(answer_quality(scene_text, source, request_of(o), quality_query(o)));
  if (!o.certificate_file.empty()) {
    if (!r.epsilon) throw Usage_error("--certificate: epsilon was not asked (--only critical-mu): no certificate of it");
    write_file(o.certificate_file, r.certificate + "\n");
  }
  return write_answer(o, [&](Json_writer& w) { write_quality(w, r); },
                      [&] {  // (the scene's μ matter to ε, not to μ*)
                        return scene_line(r.scene, source) + (r.epsilon ? frictionless_note(r.scene) : "") +
                               quality_human(r);
                      });
}

}  // namespace wrenchkit::cli
