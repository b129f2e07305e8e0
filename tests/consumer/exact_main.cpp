// Checks a grasp with the installed wrenchkit::exact (repository-style includes) and has the
// installed independent checker (wrenchkit::checker) accept the certificate. Exit 0 on success.
#include <cstdio>
#include <string>

#include "exact/certificates/certificates.h"
#include "exact/statics/closure.h"
#include "exact/statics/equilibrium.h"
#include "exact/io/scene.h"
#include "proofs/checker/checker.h"
#include "wrenchkit/exact/numbers/limits.h"  // the same headers under wrenchkit/ work too

int main() {
  // Two fingers at (0, 1/2) and (1, 1/2) with mu = 1/10: force closure, not form closure.
  const std::string text =
      "{\"wrenchkit\": 1, \"contacts\": [{\"at\": [0, \"1/2\"], \"normal\": [1, 0], \"mu\": \"0.1\"},"
      " {\"at\": [1, \"1/2\"], \"normal\": [-1, 0], \"mu\": \"0.1\"}], \"load\": {\"wrench\": [0, -1, 0]}}";
  const wrenchkit::Scene scene = wrenchkit::read_scene(text, wrenchkit::Input_limits{});
  const auto fc = wrenchkit::decide_closure(scene, wrenchkit::Property::force_closure);
  const auto fo = wrenchkit::decide_closure(scene, wrenchkit::Property::form_closure);
  const auto eq = wrenchkit::decide_equilibrium(scene);
  const auto checked = wrenchkit_checker::check(text, wrenchkit::certificate_json(fc.certificate));
  std::printf("exact: force closure %s, form closure %s, balanced %s, certificate %s\n", fc.holds ? "yes" : "no",
              fo.holds ? "yes" : "no", eq.balanced ? "yes" : "no", checked.message.c_str());
  const bool ok = fc.holds && !fo.holds && eq.balanced && checked.outcome == wrenchkit_checker::Outcome::accepted;
  return ok ? 0 : 1;
}
