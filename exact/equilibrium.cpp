#include "exact/equilibrium.h"

#include "exact/cone_lp.h"
#include "exact/input_error.h"

namespace wrenchkit {

Wrench load_wrench(const Scene& scene) {
  const Load& l = *scene.load;
  switch (l.kind) {
    case Load::Kind::wrench:
      return l.wrench;
    case Load::Kind::gravity:  // weight w at the centre of mass, acting in −y
      return wrench_at(*scene.body.com, Vec2{Rational(0), Rational(-l.weight)});
    case Load::Kind::force:
      break;
  }
  return wrench_at(l.at, l.force);
}

Equilibrium_answer decide_equilibrium(const Scene& scene) {
  if (!scene.load) throw Input_error("load: the scene has no load (equilibrium needs one)");
  Equilibrium_answer a;
  a.load = load_wrench(scene);
  const std::vector<Generator> gens = generators(scene, Reading::friction);
  a.generators = gens.size();
  std::vector<Wrench> ws;
  ws.reserve(gens.size());
  for (const Generator& g : gens) ws.push_back(g.w);
  const Wrench target{-a.load.fx, -a.load.fy, -a.load.m};
  const Cone_membership m = cone_membership(ws, target);
  a.balanced = m.member;
  a.certificate.holds = m.member;
  if (m.member) {
    for (std::size_t i = 0; i < gens.size(); ++i)
      if (m.weights[i] != 0) a.certificate.combination.push_back({{gens[i].contact, gens[i].edge}, m.weights[i]});
  } else {
    const Rational in[3] = {m.twist[0], m.twist[1], m.twist[2]};
    Integer out[3];
    primitive(in, out);
    a.certificate.twist = {Rational(out[0]), Rational(out[1]), Rational(out[2])};
  }
  return a;
}

std::string certificate_json(const Equilibrium_certificate& c) {
  const std::string s = "{\"wrenchkit_certificate\": 1, \"property\": \"equilibrium\", \"holds\": ";
  if (c.holds) return s + "true, \"combination\": " + combination_json(c.combination) + "}";
  return s + "false, " + twist_json(c.twist) + "}";
}

}  // namespace wrenchkit
