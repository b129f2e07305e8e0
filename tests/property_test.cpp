// Property tests (RapidCheck; seed fixed by CTest through RC_PARAMS, overridable): closure is
// exactly invariant under rational rotations, translations and positive scalings; adding a
// contact never breaks closure; every certificate passes the independent checker. A failing case
// dumps its scene to failures/ (see test_support.h).
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include "exact/certificates/certificates.h"
#include "exact/statics/closure.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {

struct C {
  Rational ax, ay, nx, ny, mu;
};

rc::Gen<Rational> small_rational() {
  return rc::gen::apply([](int p, int q) { return Rational(p, q); }, rc::gen::inRange(-6, 7),
                        rc::gen::inRange(1, 4));
}

rc::Gen<C> contact_gen() {
  return rc::gen::apply(
      [](Rational ax, Rational ay, int nx, int ny, int mu_index) {
        static const Rational mus[] = {Rational(0), Rational(1, 4), Rational(1, 2), Rational(1), Rational(2)};
        if (nx == 0 && ny == 0) nx = 1;
        return C{ax, ay, Rational(nx), Rational(ny), mus[mu_index]};
      },
      small_rational(), small_rational(), rc::gen::inRange(-3, 4), rc::gen::inRange(-3, 4), rc::gen::inRange(0, 5));
}

rc::Gen<std::vector<C>> scene_gen() {
  return rc::gen::container<std::vector<C>>(*rc::gen::inRange<std::size_t>(0, 7).as("contacts"), contact_gen());
}

std::string text_of(const std::vector<C>& cs) {
  std::vector<test::Contact_spec> specs;
  for (const C& c : cs)
    specs.push_back({to_string(c.ax), to_string(c.ay), to_string(c.nx), to_string(c.ny), to_string(c.mu), ""});
  return test::scene_json(specs);
}

std::pair<bool, bool> verdicts(const std::string& text) {
  const Scene s = read_scene(text, Input_limits{});
  return {decide_closure(s, Property::force_closure).holds, decide_closure(s, Property::form_closure).holds};
}

// Rigid motion p ↦ R p + t, n ↦ R n with R = [[c, −s], [s, c]], c² + s² = 1 exactly.
std::vector<C> moved(std::vector<C> cs, const Rational& c, const Rational& s, const Rational& tx, const Rational& ty) {
  for (C& k : cs) {
    const Rational ax = c * k.ax - s * k.ay + tx, ay = s * k.ax + c * k.ay + ty;
    const Rational nx = c * k.nx - s * k.ny, ny = s * k.nx + c * k.ny;
    k.ax = ax;
    k.ay = ay;
    k.nx = nx;
    k.ny = ny;
  }
  return cs;
}

void same_verdicts(const std::string& a, const std::string& b, const char* what) {
  const auto va = verdicts(a), vb = verdicts(b);
  if (va != vb) {
    const std::string pa = test::dump_failure(a, std::string("property_") + what + "_original");
    const std::string pb = test::dump_failure(b, std::string("property_") + what + "_transformed");
    RC_FAIL(std::string(what) + " changed the verdict; scenes dumped to " + pa + " and " + pb);
  }
}

RC_GTEST_PROP(ClosureProperties, InvariantUnderRationalRotationsAndTranslations, ()) {
  const auto cs = *scene_gen().as("scene");
  const Rational tx = *small_rational().as("tx"), ty = *small_rational().as("ty");
  same_verdicts(text_of(cs), text_of(moved(cs, Rational(3, 5), Rational(4, 5), tx, ty)), "rotation_3_4_5");
  same_verdicts(text_of(cs), text_of(moved(cs, Rational(119, 169), Rational(-120, 169), tx, ty)), "rotation_119_120_169");
}

// Huge and tiny scales and 40-digit rotations: the same exact answers (exact means exact).
RC_GTEST_PROP(ClosureProperties, InvariantAtExtremeScalesAnd40DigitRotations, ()) {
  const auto cs = *scene_gen().as("scene");
  const Integer a("12345678901234567891"), b("98765432109876543211");  // Pythagorean: (a²−b², 2ab, a²+b²)
  const Rational c(a * a - b * b, a * a + b * b), s(2 * a * b, a * a + b * b);
  const Rational big(Integer("1000000000000000000")), tiny(Integer(1), Integer("100000000000000000000"));
  for (const Rational& k : {big, tiny}) {
    auto scaled = moved(cs, c, s, k * 3, -k / 7);
    for (C& x : scaled) {
      x.ax *= k;
      x.ay *= k;
    }
    same_verdicts(text_of(cs), text_of(scaled), k > 1 ? "scale_1e18_rotation_40_digits" : "scale_1e-20_rotation_40_digits");
  }
}

RC_GTEST_PROP(ClosureProperties, InvariantUnderPositiveScaling, ()) {
  auto cs = *scene_gen().as("scene");
  const int num = *rc::gen::inRange(1, 1000).as("scale numerator");
  const int den = *rc::gen::inRange(1, 1000).as("scale denominator");
  const Rational k(num, den);
  auto scaled = cs;
  for (C& c : scaled) {
    c.ax *= k;
    c.ay *= k;
    c.nx *= Rational(den, num) * 7;  // a normal's length does not matter
    c.ny *= Rational(den, num) * 7;
  }
  same_verdicts(text_of(cs), text_of(scaled), "scaling");
}

RC_GTEST_PROP(ClosureProperties, AddingAContactNeverBreaksClosure, ()) {
  auto cs = *scene_gen().as("scene");
  const auto before = verdicts(text_of(cs));
  cs.push_back(*contact_gen().as("added contact"));
  const auto after = verdicts(text_of(cs));
  if ((before.first && !after.first) || (before.second && !after.second))
    RC_FAIL("closure lost by adding a contact; scene dumped to " + test::dump_failure(text_of(cs), "property_monotone"));
}

RC_GTEST_PROP(ClosureProperties, EveryCertificatePassesTheChecker, ()) {
  const std::string text = text_of(*scene_gen().as("scene"));
  const Scene s = read_scene(text, Input_limits{});
  for (Property p : {Property::force_closure, Property::form_closure}) {
    const auto ok = test::checker_accepts(text, certificate_json(decide_closure(s, p).certificate));
    if (!ok) RC_FAIL(std::string(ok.message()) + "\nscene dumped to " + test::dump_failure(text, "property_certificate"));
  }
}

}  // namespace
}  // namespace wrenchkit
