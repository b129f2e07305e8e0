// wrenchkit equilibrium: can the contacts balance the scene's load? With a checked certificate.
#include <array>
#include <iostream>
#include <sstream>
#include <string>

#include "cli/common.h"
#include "exact/io/json_writer.h"
#include "exact/io/streaming_scene_reader.h"

namespace wrenchkit::cli {

void write_equilibrium(Json_writer& w, const Options& o, const Equilibrium_item& r, const char* command) {
  const Vec3q& l = r.answer.load;
  w.member("command", command).member("name", r.name).member("mode", mode_name(o.mode));
  w.member("decided_by", arithmetic_name(r.answer.decided_by())).member("balanced", r.answer.balanced);
  w.key("load").array().rational(l[0]).rational(l[1]).rational(l[2]).end_array();
  write_approx(w, "load", {l[0], l[1], l[2]});
  w.member("generators", r.answer.generators);
  if (r.answer.balanced) write_forces(w, r.forces);
  w.member("certificate_checked", true).key("certificate").raw(r.certificate);
}

std::string equilibrium_human(const Equilibrium_item& r) {
  const Equilibrium_answer& a = r.answer;
  std::ostringstream s;
  s << "load: the wrench " << vec_text(a.load) << " (force, moment about the origin)\n"
    << "balanced: " << (a.balanced ? "yes" : "no") << "\n    certificate: ";
  if (a.balanced) {
    if (a.certificate.combination.empty()) s << "the load is zero";
    else s << "the contact forces " << contact_forces_text(r.forces) << " cancel the load exactly (weights on the "
           << "friction cones' edges in the certificate)";
  } else {
    const Twist_reading tr = read_twist(a.certificate.twist);
    s << "the twist " << twist_text(a.certificate.twist)
      << " has power >= 0 against every contact wrench and > 0 against the load";
    if (tr.label == 'i')
      s << " (a translation toward direction " << vec_text(Vec2{tr.point[0], tr.point[1]}) << " at infinity)";
    else
      s << " (a " << (tr.label == '+' ? "counter-clockwise" : "clockwise") << " rotation about "
        << vec_text(Vec2{tr.point[0], tr.point[1]}) << ")";
    s << ": the load drives a motion the contacts allow";
  }
  s << "\n";
  return s.str();
}

Scene_answer prepare_equilibrium_json(const Options& o) {
  return [o, request = request_of(o)](Json_writer& w, const std::string& text, const std::string& source) {
    thread_local Scene scratch;
    write_equilibrium(w, o, answered(answer_equilibrium(text, source, request, scratch)), "equilibrium");
  };
}

int run_equilibrium(const Options& o, const std::string& scene_text, const std::string& source) {
  Scene scene;
  const Equilibrium_item r = answered(answer_equilibrium(scene_text, source, request_of(o), scene));
  if (!o.certificate_file.empty()) write_file(o.certificate_file, r.certificate + "\n");
  if (o.json) {
    std::cout << json_answer([&](Json_writer& w) { write_equilibrium(w, o, r, "equilibrium"); }) << "\n";
  } else {
    std::cout << scene_line(scene, source) << frictionless_note(scene)
              << equilibrium_human(r) << "certificate accepted by the independent checker (exact arithmetic)\n";
  }
  return kAnswered;
}

}  // namespace wrenchkit::cli
