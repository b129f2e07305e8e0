// proofs/certificate-format.md §3.5: the critical friction coefficient μ* — "always" (the property at μ = 0), "never"
// (a twist orthogonal to the tangent wrenches, or the property failing beyond every minor's roots), or a value: the
// property failing at `below.mu` and holding at `above.mu`, each by a certificate of §3.1–§3.3 for the scene at that
// common μ, and, when μ* is exact, the minors' constant signs beside it. The checker's side:
// proofs/checker/critical_mu.cpp.
#include "exact/certificates/certificates.h"

namespace wrenchkit {

namespace {

void write_side(Json_writer& w, const char* key, const Rational& mu, const Critical_mu& c, bool closure, bool holds) {
  w.key(key).object().member("mu", mu).key("certificate");
  if (closure) write_certificate(w, holds ? c.above_closure : c.below_closure);
  else write_certificate(w, holds ? c.above_balance : c.below_balance);
  w.end_object();
}

}  // namespace

std::string critical_mu_certificate(const Critical_mu& c, bool closure) {
  Json_writer w(1024);
  w.object().member("wrenchkit_certificate", 4).member("property", "critical_mu");
  w.member("of", closure ? "force_closure" : "equilibrium");
  if (c.scaling == Friction_scaling::proportional) w.member("scaling", "proportional");
  switch (c.kind) {
    case Critical_kind::always:
      w.member("critical_mu", "always");
      write_side(w, "above", 0, c, closure, true);
      break;
    case Critical_kind::never:
      w.member("critical_mu", "never");
      if (c.limit_twist) w.key("limit_twist").rationals(*c.limit_twist);
      else write_side(w, "below", *c.below_mu, c, closure, false), w.member("constant_beyond", true);
      break;
    case Critical_kind::value:
      w.key("critical_mu").object().member("lower", c.lower).member("upper", c.upper).end_object();
      write_side(w, "below", *c.below_mu, c, closure, false);
      write_side(w, "above", *c.above_mu, c, closure, true);
      if (c.constant) w.member("constant", true);
      break;
  }
  w.end_object();
  return w.take();
}

}  // namespace wrenchkit
