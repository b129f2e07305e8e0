// libFuzzer target: any bytes as a scene. The parser must never crash, hang or allocate without
// bound; when it accepts, closure must answer and the independent checker must accept both of
// its certificates (engine parser and checker parser agree on every scene the engine accepts).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string_view>

#include "exact/closure.h"
#include "exact/input_error.h"
#include "exact/scene.h"
#include "proofs/checker/checker.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  wrenchkit::Input_limits limits;
  limits.max_digits = 200;  // keep big-number work small per input
  limits.max_exponent = 200;
  limits.max_contacts = 64;
  wrenchkit::Scene scene;
  try {
    scene = wrenchkit::read_scene(text, limits, "fuzz");
  } catch (const wrenchkit::Input_error&) {
    return 0;
  }
  wrenchkit_checker::Limits cl;
  cl.max_digits = limits.max_digits;
  cl.max_exponent = limits.max_exponent;
  cl.max_contacts = limits.max_contacts;
  for (auto p : {wrenchkit::Property::force_closure, wrenchkit::Property::form_closure}) {
    const std::string cert = wrenchkit::certificate_json(wrenchkit::decide_closure(scene, p).certificate);
    const auto r = wrenchkit_checker::check(text, cert, cl);
    if (r.outcome != wrenchkit_checker::Outcome::accepted) {
      std::cerr << "checker: " << r.message << "\ncertificate: " << cert << "\n";
      std::abort();
    }
  }
  return 0;
}
