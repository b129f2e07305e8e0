// wrenchkit hold: can the contacts, together with the support's friction, hold the body against the scene's load
// (docs/fixtures.md, exact/fixture/hold.h)? With a checked certificate either way.
#include <iostream>
#include <sstream>
#include <string>

#include "cli/common.h"
#include "exact/io/support_check.h"
#include "exact/certificates/certificates.h"
#include "exact/io/json_writer.h"
#include "exact/pipeline/hold_answer.h"

namespace wrenchkit::cli {

namespace {

const char* support_kind(const Hold_answer& a) { return !a.has_support ? "none" : a.unknown ? "unknown" : "known"; }

// The motion a failing twist describes: {"twist", "kind": "rotation", "center", "sense"} or
// {"twist", "kind": "translation", "direction"} (the velocity's direction), and the words.
// The twist is a direction here: its primitive integer multiple (the certificate keeps the value its checks need).
void write_motion(Json_writer& w, const Vec3q& twist) {
  const Vec3q t = primitive_vec(twist);
  w.object().key("twist").rationals(t);
  if (t[2] != 0) {
    const Rational cx = -t[1] / t[2], cy = t[0] / t[2];
    w.member("kind", "rotation").key("center").array().rational(cx).rational(cy).end_array();
    write_approx(w, "center", {cx, cy});
    w.member("sense", t[2] > 0 ? "counter-clockwise" : "clockwise");
  } else {
    const std::array<Integer, 2> d = primitive(t[0], t[1]);
    w.member("kind", "translation").key("direction").array().rational(d[0]).rational(d[1]).end_array();
  }
  w.member("text", motion_words(t)).end_object();
}

// "holds": true or false, or the word ("impending", "depends", "undecided").
void write_holds(Json_writer& w, Hold_verdict v) {
  if (v == Hold_verdict::holds || v == Hold_verdict::fails) w.boolean(v == Hold_verdict::holds);
  else w.string(hold_word(v));
}

void write_contact_forces(Json_writer& w, const Scene& scene, const Hold_witness& h) {
  write_combination(w.key("contact_forces"), h.combination);
  write_forces(w, contact_forces(scene, h.combination));
}

}  // namespace

void write_hold(Json_writer& w, const Hold_item& r) {
  const Hold_answer& a = r.answer;
  w.member("command", "hold").member("name", r.scene.name).member("mode", mode_name(r.mode));
  write_holds(w.key("holds"), a.verdict);
  w.member("decided_by", decided_by_text(a));
  w.key("load").array().rational(a.load[0]).rational(a.load[1]).rational(a.load[2]).end_array();
  write_approx(w, "load", {a.load[0], a.load[1], a.load[2]});
  w.member("generators", a.generators).member("support", support_kind(a));
  if (a.rounds) w.member("lp_rounds", a.rounds);
  if (a.has_support && !r.scene.support->regions.empty())
    w.member("regions", r.scene.support->regions.size()).member("region_cells", a.cells);
  if (a.unknown) {
    w.key("extreme_distributions").array();
    for (const auto& f : a.extreme) w.rationals(f);
    w.end_array().key("per_extreme_distribution").array();
    for (const Hold_verdict v : a.per_vertex) w.string(hold_word(v));
    w.end_array();
  }
  switch (a.verdict) {
    case Hold_verdict::holds:
      if (a.holding) {
        write_contact_forces(w, r.scene, *a.holding);
        if (a.has_support) write_support_forces(w, a.holding->support.forces);
      }
      break;
    case Hold_verdict::impending:  // just held; the motion it may slip with (its power meets the friction's)
      if (a.impending) {
        write_contact_forces(w, r.scene, a.impending->holding);
        if (a.has_support) write_support_forces(w, a.impending->holding.support.forces);
      }
      write_motion(w.key("motion"), a.impending ? a.impending->twist.twist : a.failing->twist);
      break;
    case Hold_verdict::fails:
      write_motion(w.key("motion"), a.failing->twist);
      break;
    case Hold_verdict::depends:
      write_holds(w.key("witnesses").object().key("holds").object().key("holds"), a.held_as);
      w.key("distribution").rationals(a.holding->support.distribution);
      write_holds(w.end_object().key("fails").object().key("holds"), a.moved_as);
      w.key("distribution").rationals(a.failing->distribution);
      write_motion(w.key("motion"), a.failing->twist);
      w.end_object().end_object();
      break;
    case Hold_verdict::undecided:
      w.member("undecided_why", a.undecided_why);
      break;
  }
  if (!r.certificate.empty()) w.member("certificate_checked", true).key("certificate").raw(r.certificate);
}

namespace {

std::string forces_text(const Scene& scene, const Hold_witness& h, bool support) {
  std::ostringstream s;
  if (h.combination.empty()) s << "no contact force";
  else s << "contact forces " << contact_forces_text(contact_forces(scene, h.combination));
  if (support && !h.support.forces.empty()) {
    std::size_t carrying = 0;
    for (const Vec2& g : h.support.forces) carrying += !is_zero(g);
    s << "; support friction at " << carrying << " of " << h.support.forces.size() << " point(s)";
  }
  return s.str();
}

}  // namespace

std::string hold_human(const Hold_item& r) {
  const Hold_answer& a = r.answer;
  std::ostringstream s;
  s << "load: the wrench " << vec_text(a.load) << " on the body (force, moment about the origin)"
    << (gravity_across_support(r.scene) ? "; gravity " + number_text(r.scene.load->weight) +
                                              " at body.com presses the body on the support (its total normal force), "
                                              "nothing in the plane"
                                        : std::string())
    << "\n"
    << "contacts: " << a.generators << " generator(s) of their wrench cone; support: ";
  if (!a.has_support) s << "none (hold is equilibrium)";
  else if (!a.unknown) {
    s << r.scene.support->points.size() << " point(s), every force given";
    if (!r.scene.support->regions.empty()) s << ", and " << r.scene.support->regions.size() << " region(s)";
  }
  else
    s << r.scene.support->points.size() << " point(s), forces not all given: " << a.extreme.size()
      << " extreme admissible distribution(s)";
  s << "\n";
  // Who carries the load: the contacts, the support's friction, or both (the book's words for each).
  const std::string carriers = !a.has_support ? "the contacts" : a.generators == 0 ? "the support's friction"
                                                                                  : "the contacts and the support's friction";
  switch (a.verdict) {
    case Hold_verdict::holds:
      s << "holds: yes — " << carriers << " balance the load with margin";
      if (a.unknown) s << " under every admissible distribution (every extreme one holds)";
      s << "\n";
      if (a.holding) s << "  " << forces_text(r.scene, *a.holding, a.has_support) << " cancel the load exactly\n";
      if (a.holding && !a.holding->support.regions.empty())
        s << "  with the regions' friction as forces on " << a.cells << " cells, each in its disc at the cell's pressure centroid\n";
      break;
    case Hold_verdict::impending:
      s << "holds: impending — " << carriers << " can just balance the load";
      if (a.unknown) s << " under every admissible distribution (every extreme one holds it at the limit)";
      s << ", with no margin: it may start to slip in " << motion_text(a.impending ? a.impending->twist.twist : a.failing->twist)
        << " (twist " << twist_text(a.impending ? a.impending->twist.twist : a.failing->twist)
        << "; every contact allows it, and the load's power meets the friction's exactly)\n";
      if (a.impending) s << "  " << forces_text(r.scene, a.impending->holding, a.has_support) << " cancel the load exactly\n";
      break;
    case Hold_verdict::fails:
      s << "holds: no — the body moves: " << motion_text(a.failing->twist) << " (twist "
        << twist_text(a.failing->twist) << ")";
      if (a.unknown) s << " under every admissible distribution";
      s << (a.has_support ? "\n  every contact allows it, and the load drives it harder than the support's friction can resist\n"
                          : "\n  every contact allows it, and the load drives it (the contacts cannot resist it)\n");
      if (!a.failing->regions.empty())
        s << "  (the regions' friction bounded by speed bounds at the vertices of " << a.cells << " cells)\n";
      break;
    case Hold_verdict::depends:
      s << "holds: depends on the distribution — it "
        << (a.held_as == Hold_verdict::holds ? "holds" : "is just held (impending)") << " with f = "
        << distribution_text(a.holding->support.distribution) << " and "
        << (a.moved_as == Hold_verdict::fails ? "fails" : "is just held (impending)") << " with f = "
        << distribution_text(a.failing->distribution) << " (then " << motion_text(a.failing->twist)
        << (a.moved_as == Hold_verdict::fails ? "" : " is admitted") << ")\n";
      break;
    case Hold_verdict::undecided:
      s << "holds: undecided — " << a.undecided_why << "\n";
      break;
  }
  s << "decided by: " << decided_by_text(a) << " (" << mode_name(r.mode) << " mode)\n";
  if (!r.certificate.empty()) s << "certificate accepted by the independent checker (exact arithmetic)\n";
  return s.str();
}

Scene_answer prepare_hold_json(const Options& o) {
  return [request = request_of(o)](Json_writer& w, const std::string& text, const std::string& source) {
    write_hold(w, answered(answer_hold(text, source, request)));
  };
}

int run_hold(const Options& o, const std::string& scene_text, const std::string& source) {
  const Hold_item r = answered(answer_hold(scene_text, source, request_of(o)));
  if (!o.certificate_file.empty()) {
    if (r.certificate.empty())
      throw Failure(Status::undecided, "hold is undecided: no certificate to write (" + r.answer.undecided_why + ")" +
                                           undecided_advice(o.mode));
    write_file(o.certificate_file, r.certificate + "\n");
  }
  return write_answer(o, [&](Json_writer& w) { write_hold(w, r); },
                      [&] { return scene_line(r.scene, source) + frictionless_note(r.scene) + hold_human(r); },
                      r.answer.verdict == Hold_verdict::undecided);
}

}  // namespace wrenchkit::cli
