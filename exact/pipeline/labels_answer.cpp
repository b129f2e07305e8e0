#include "exact/pipeline/labels_answer.h"

#include "exact/io/to_float.h"
#include "exact/statics/equilibrium.h"

namespace wrenchkit {

namespace {

fl::Bounded3 twin_of(const Vec3q& w) { return {to_bounded(w[0]), to_bounded(w[1]), to_bounded(w[2])}; }

// A certified membership from the twin, or undecided.
bool twin_in_cone(const fl::Labels_twin& l, const Vec3q& w, const char* what) {
  const fl::Truth t = fl::in_cone(l, twin_of(w));
  if (t == fl::Truth::uncertain) throw Undecided_error(std::string("the float twin could not decide ") + what);
  return t == fl::Truth::yes;
}

// Reuleaux's modes from certified signs (moment_labels.h's contact_modes, in floating point).
Mode_answer twin_contact_modes(const Scene& scene, const Vec3q& t) {
  Mode_answer a;
  const fl::Bounded3 bt = twin_of(t);
  for (const fl::Bounded_contact& c : to_bounded(scene)) {
    const fl::Contact_motion m = fl::contact_motion(c, bt);
    if (m.power == Sign::uncertain || (!c.is_wrench && m.power == Sign::zero && m.speed == Sign::uncertain))
      throw Undecided_error("the float twin could not decide a contact's mode");
    Contact_mode mode = Contact_mode::none;
    if (!c.is_wrench)
      mode = m.power == Sign::positive   ? Contact_mode::breaks
             : m.power == Sign::negative ? Contact_mode::penetrates
             : m.speed == Sign::zero     ? Contact_mode::sticks
                                         : Contact_mode::slides;
    a.feasible &= m.power != Sign::negative;
    a.marginal |= m.power == Sign::zero;
    a.modes.push_back(mode);
  }
  a.marginal &= a.feasible;
  return a;
}

Vec3q negated(const Vec3q& w) { return {-w[0], -w[1], -w[2]}; }

void decide_exactly(Labels_item& s, const Labels_query& q) {
  if (s.mode == Mode::hybrid && q.question != Labels_question::dual) {
    // No rational generators: the cone from the scene's integer rows when it can (moment_labels.h).
    s.labels = moment_labels(s.scene, s.reading, Mode::hybrid);
  } else {
    s.generators = generators(s.scene, s.reading);
    s.wrenches.reserve(s.generators.size());
    for (const Generator& g : s.generators) s.wrenches.push_back(g.w);
    if (s.mode == Mode::hybrid) {
      const std::vector<fl::Bounded3> twin = fl::generators(to_bounded(s.scene), s.reading);
      s.labels = moment_labels(s.wrenches, Mode::hybrid, &twin);
    } else {
      s.labels = moment_labels(s.wrenches, Mode::exact);
    }
  }
  if (q.resultant) s.resultant_possible = in_cone(s.labels.cone, *q.resultant);
  if (q.question == Labels_question::dual) s.dual = force_dual(s.labels, s.wrenches);
  if (s.load) s.load_balanced = in_cone(s.labels.cone, negated(*s.load));
  if (q.motion) s.modes = contact_modes(s.scene, *q.motion);
}

void decide_by_twin(Labels_item& s, const Labels_query& q) {
  if (q.question == Labels_question::dual) s.generators = generators(s.scene, s.reading);  // their names
  s.twin_generators = fl::generators(to_bounded(s.scene), s.reading);
  const Dual_cone dc = compute_dual_cone(fl::Float_kernel(s.twin_generators));
  s.twin = fl::moment_labels(s.twin_generators, dc);
  if (!s.twin.decided())
    throw Undecided_error(std::string("the float twin could not decide the labels: ") + fl::status_name(s.twin.status));
  if (q.resultant) s.resultant_possible = twin_in_cone(s.twin, *q.resultant, "whether the resultant is possible");
  if (q.question == Labels_question::dual) {
    s.twin_dual = fl::force_dual(s.twin_generators, dc);
    if (!s.twin_dual->decided())
      throw Undecided_error(std::string("the float twin could not decide the force dual: ") +
                            fl::status_name(s.twin_dual->status));
    for (const fl::Bounded3& g : s.twin_generators) {
      s.twin_dual_points.push_back(fl::dual_point(g));
      if (s.twin_dual_points.back().sheet == '?')
        throw Undecided_error("the float twin could not place a generator's dual point");
    }
    if (s.load) {
      s.twin_antipode = fl::dual_point(twin_of(negated(*s.load)));
      if (s.twin_antipode->sheet == '?') throw Undecided_error("the float twin could not place the load's antipode");
    }
  }
  if (s.load) s.load_balanced = twin_in_cone(s.twin, negated(*s.load), "whether the load is balanced");
  if (q.motion) s.modes = twin_contact_modes(s.scene, *q.motion);
}

void decide_labels(Labels_item& s, const Request& r, const Labels_query& q) {
  s.mode = r.mode;
  s.reading = q.question == Labels_question::reuleaux ? Reading::frictionless : Reading::friction;
  // The load is read on the labels of the friction cone only (Reuleaux's reading has no load).
  if (s.scene.load && q.question != Labels_question::reuleaux) s.load = load_wrench(s.scene);
  if (s.mode == Mode::float_only) decide_by_twin(s, q);
  else decide_exactly(s, q);
}

}  // namespace

Labels_item answer_labels(std::string_view text, std::string_view source, const Request& r, const Labels_query& q) {
  return answer_into_item<Labels_item>(text, source, r.limits, [&](Labels_item& item) { decide_labels(item, r, q); });
}

Labels_item answer_labels(const Scene& scene, const Request& r, const Labels_query& q) {
  return answer_into_item<Labels_item>(scene, r.limits, [&](Labels_item& item) { decide_labels(item, r, q); });
}

}  // namespace wrenchkit
