// proofs/checker/checker.cpp - check() and check_all() (checker.h): the scene read once (scene.cpp), each
// certificate read (certificate.cpp) and checked by its property's check (certificate-format.md §3-§7).
#include "proofs/checker/checker.h"

#include <algorithm>
#include <new>

#include "proofs/checker/certificate.h"

namespace wrenchkit_checker {
namespace {

using namespace detail;

// The certificate against an already read scene.
Result check_certificate(const Scene& scene, std::string_view certificate_json, const Limits& limits) {
  if (certificate_json.size() > limits.max_certificate_bytes)  // refused before any of it is read
    return {Outcome::rejected, "certificate: " + std::to_string(certificate_json.size()) +
                                   " bytes, more than the limit of " + std::to_string(limits.max_certificate_bytes) +
                                   " (--max-certificate-size)"};
  certificate_rational_limit = std::max<std::size_t>(100000, scene.longest > (static_cast<std::size_t>(-1) - 64) / 32
                                                                 ? static_cast<std::size_t>(-1)
                                                                 : 32 * scene.longest + 64);
  try {
    Reader r(certificate_json, limits.max_depth);
    const Certificate c = read_certificate(r);
    r.finish();
    check_keys(c);
    if (c.motion) check_motion(c, scene, limits);
    else if (c.hold) check_hold(c, scene, limits);
    else if (c.equilibrium) check_equilibrium(c, scene, limits);
    else if (c.quality) check_quality(c, scene, limits);
    else if (c.critical) check_critical_mu(c, scene, limits);
    else if (c.regions) check_grasp_regions(c, scene, limits);
    else if (c.push) check_push(c, scene, limits);
    else check_closure(c, scene, limits);
    return {Outcome::accepted, "accepted"};
  } catch (const Failure& f) {
    return {Outcome::rejected, f.message};
  } catch (const std::bad_alloc&) {
    return {Outcome::rejected, "out of memory while checking the certificate"};
  } catch (...) {
    return {Outcome::rejected, "internal error while checking the certificate"};
  }
}

}  // namespace

Result check(std::string_view scene_json, std::string_view certificate_json, const Limits& limits) {
  Scene scene;
  Result bad;
  if (!read_whole_scene(scene_json, limits, scene, bad)) return bad;
  return check_certificate(scene, certificate_json, limits);
}

std::vector<Result> check_all(std::string_view scene_json, const std::vector<std::string_view>& certificates,
                              const Limits& limits) {
  Scene scene;
  Result bad;
  if (!read_whole_scene(scene_json, limits, scene, bad)) return std::vector<Result>(certificates.size(), bad);
  std::vector<Result> out;
  out.reserve(certificates.size());
  for (const std::string_view c : certificates) out.push_back(check_certificate(scene, c, limits));
  return out;
}

}  // namespace wrenchkit_checker
