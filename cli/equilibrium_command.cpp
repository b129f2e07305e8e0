// wrenchkit equilibrium: can the contacts balance the scene's load? With a checked certificate.
#include <array>
#include <iostream>
#include <sstream>
#include <string>

#include "cli/common.h"
#include "exact/io/json.h"
#include "exact/io/streaming_scene_reader.h"

namespace wrenchkit::cli {

Equilibrium_result compute_equilibrium(const Options& o, const Scene& scene, const std::string& scene_text) {
  Equilibrium_result r{decide_equilibrium(scene, o.mode), ""};
  if (!r.a.decided)
    throw Undecided("the float twin could not certify equilibrium of this scene (a predicate is within its "
                    "error bound of zero, or the contact wrenches have rank < 3); use --mode hybrid or exact");
  r.cert = certificate_json(r.a.certificate);
  const auto c = wrenchkit_checker::check(scene_text, r.cert, checker_limits(o.limits));
  if (c.outcome != wrenchkit_checker::Outcome::accepted)
    throw Self_check_failure("the independent checker rejected our own certificate: " + c.message +
                             "\ncertificate: " + r.cert);
  return r;
}

std::string equilibrium_json(const Options& o, const Scene& scene, const Equilibrium_result& r, const char* command) {
  const Wrench& l = r.a.load;
  return "{\"command\": \"" + std::string(command) + "\", \"name\": " + json::quote(scene.name) +
         ", \"mode\": \"" + mode_name(o.mode) + "\", \"decided_by\": \"" + r.a.decided_by() + "\", \"balanced\": " +
         (r.a.balanced ? "true" : "false") + ", \"load\": [" + json::quote(to_string(l.fx)) + ", " +
         json::quote(to_string(l.fy)) + ", " + json::quote(to_string(l.m)) + "], \"generators\": " +
         std::to_string(r.a.generators) + ", \"certificate_checked\": true, \"certificate\": " + r.cert + "}";
}

std::string equilibrium_human(const Equilibrium_result& r) {
  const Equilibrium_answer& a = r.a;
  const std::array<Rational, 3> load = {a.load.fx, a.load.fy, a.load.m};
  std::ostringstream s;
  s << "load: the wrench " << vec_text(load) << " (force, moment about the origin)\n"
    << "balanced: " << (a.balanced ? "yes" : "no") << "\n    certificate: ";
  if (a.balanced) {
    if (a.certificate.combination.empty()) s << "the load is zero";
    else s << "the contact wrenches";
    for (const auto& [ref, w] : a.certificate.combination)
      s << " " << to_string(w) << "·c" << ref.contact << "." << edge_name(ref.edge);
    if (!a.certificate.combination.empty()) s << " cancel the load exactly";
  } else {
    const Twist_reading tr = read_twist(a.certificate.twist);
    s << "the twist " << vec_text(a.certificate.twist)
      << " has power >= 0 against every contact wrench and > 0 against the load";
    if (tr.label == 'i')
      s << " (a translation toward direction (" << to_string(tr.point[0]) << ", " << to_string(tr.point[1])
        << ") at infinity)";
    else
      s << " (a " << (tr.label == '+' ? "counter-clockwise" : "clockwise") << " rotation about ("
        << to_string(tr.point[0]) << ", " << to_string(tr.point[1]) << "))";
    s << ": the load drives a motion the contacts allow";
  }
  s << "\n";
  return s.str();
}

Scene_answer prepare_equilibrium_json(const Options& o) {
  return [o](const std::string& text, const std::string& source) {
    const Scene scene = read_scene_streaming(text, o.limits, source);
    return equilibrium_json(o, scene, compute_equilibrium(o, scene, text), "equilibrium");
  };
}

int run_equilibrium(const Options& o, const std::string& scene_text, const std::string& source) {
  const Scene scene = read_scene(scene_text, o.limits, source);
  const Equilibrium_result r = compute_equilibrium(o, scene, scene_text);
  if (!o.certificate_file.empty()) write_file(o.certificate_file, r.cert + "\n");
  if (o.json) {
    std::cout << equilibrium_json(o, scene, r, "equilibrium") << "\n";
  } else {
    std::cout << "scene: " << (scene.name.empty() ? source : scene.name) << "\n"
              << equilibrium_human(r) << "certificate accepted by the independent checker (exact arithmetic)\n";
  }
  return kAnswered;
}

}  // namespace wrenchkit::cli
