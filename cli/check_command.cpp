// wrenchkit check SCENE CERT: the independent checker of proofs/.
#include <iostream>
#include <string>

#include "cli/common.h"
#include "exact/io/input_error.h"

namespace wrenchkit::cli {

int run_check(const Options& o) {
  if (o.positional[0] == "-" && o.positional[1] == "-")
    throw Usage_error("check: SCENE.json and CERT.json cannot both be standard input");
  const std::string scene = read_input(o.positional[0], o.limits.max_file_bytes);
  const std::string cert = read_input(o.positional[1], o.limits.max_file_bytes);
  const auto r = wrenchkit_checker::check(scene, cert, checker_limits(o.limits));
  using wrenchkit_checker::Outcome;
  if (r.outcome == Outcome::bad_scene) throw Input_error(o.positional[0] + ": " + r.message);
  const bool ok = r.outcome == Outcome::accepted;
  if (o.json)
    std::cout << json_answer([&](Json_writer& w) { w.member("accepted", ok).member("reason", ok ? "" : r.message); })
              << "\n";
  else
    std::cout << (ok ? "accepted" : "rejected: " + r.message) << "\n";
  return ok ? kAnswered : kRejected;
}

}  // namespace wrenchkit::cli
