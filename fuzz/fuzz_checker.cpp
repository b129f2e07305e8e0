// libFuzzer target: any bytes as "SCENE\0CERTIFICATE". The checker must never crash, and must never
// accept a certificate whose claim is false: whenever it accepts, the exact engine must agree with
// the claim (soundness, differential against the engine).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string_view>

#include "exact/closure.h"
#include "exact/equilibrium.h"
#include "exact/input_error.h"
#include "exact/scene.h"
#include "proofs/checker/checker.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view all(reinterpret_cast<const char*>(data), size);
  const std::size_t cut = all.find('\0');
  if (cut == std::string_view::npos) return 0;
  const std::string_view scene_text = all.substr(0, cut), cert = all.substr(cut + 1);
  wrenchkit_checker::Limits cl;
  cl.max_digits = 200;
  cl.max_exponent = 200;
  cl.max_contacts = 64;
  const auto r = wrenchkit_checker::check(scene_text, cert, cl);
  if (r.outcome != wrenchkit_checker::Outcome::accepted) return 0;
  wrenchkit::Input_limits limits;
  limits.max_digits = cl.max_digits;
  limits.max_exponent = cl.max_exponent;
  limits.max_contacts = cl.max_contacts;
  wrenchkit::Scene scene;
  try {
    scene = wrenchkit::read_scene(scene_text, limits, "fuzz");
  } catch (const wrenchkit::Input_error& e) {
    return 0;  // the checker reads only what it needs; the engine's schema is stricter
  }
  const bool claims_holds = cert.find("\"holds\": true") != std::string_view::npos ||
                            cert.find("\"holds\":true") != std::string_view::npos;
  const bool form = cert.find("form_closure") != std::string_view::npos;
  const bool equilibrium = cert.find("equilibrium") != std::string_view::npos;
  if (equilibrium && !scene.load) {
    std::cerr << "checker accepted an equilibrium claim on a scene without load\n";
    std::abort();
  }
  const bool holds =
      equilibrium ? wrenchkit::decide_equilibrium(scene).balanced
                  : wrenchkit::decide_closure(scene, form ? wrenchkit::Property::form_closure
                                                          : wrenchkit::Property::force_closure)
                        .holds;
  if (holds != claims_holds) {
    std::cerr << "checker accepted a false claim\n";
    std::abort();
  }
  return 0;
}
