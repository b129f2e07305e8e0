#include "exact/io/scene_writer.h"

#include <optional>

#include "exact/io/json.h"

namespace wrenchkit {

namespace {

std::string q(const Rational& r) { return json::quote(to_string(r)); }
std::string pt(const Vec2& p) { return "[" + q(p.x) + ", " + q(p.y) + "]"; }

}  // namespace

std::string write_scene(const Scene& s) {
  std::string o = "{\"wrenchkit\": 1";
  if (!s.name.empty()) o += ", \"name\": " + json::quote(s.name);
  // the scene's own "mu" when no point contact or pusher takes it as its default (each of those writes its μ): a
  // part's fingers' μ (grasp-regions) is kept, and the canonical text measures what the scene does (its budget,
  // exact/io/scene_budget.h, counts that "mu" once either way)
  bool takes = s.pusher.has_value();
  for (const Contact& c : s.contacts) takes = takes || c.kind == Contact::Kind::point;
  if (s.mu && !takes) o += ", \"mu\": " + q(*s.mu);
  if (!s.body.outline.empty() || s.body.com) {
    o += ", \"body\": {";
    std::string sep;
    if (!s.body.outline.empty()) {
      o += "\"outline\": [";
      for (std::size_t i = 0; i < s.body.outline.size(); ++i) o += (i ? ", " : "") + pt(s.body.outline[i]);
      o += "]";
      sep = ", ";
    }
    if (s.body.com) o += sep + "\"com\": " + pt(*s.body.com);
    o += "}";
  }
  o += ",\n \"contacts\": [";
  for (std::size_t i = 0; i < s.contacts.size(); ++i) {
    std::optional<Contact> built;
    if (s.contacts[i].exact_pending) built = exact_contact(s.contacts[i]);
    const Contact& c = built ? *built : s.contacts[i];
    o += i ? ",\n  " : "\n  ";
    if (c.kind == Contact::Kind::wrench)
      o += "{\"wrench\": [" + q(c.wrench[0]) + ", " + q(c.wrench[1]) + ", " + q(c.wrench[2]) + "]";
    else
      o += "{\"at\": " + pt(c.at) + ", \"normal\": " + pt(c.normal) + ", \"mu\": " + q(c.mu);
    if (!c.name.empty()) o += ", \"name\": " + json::quote(c.name);
    o += "}";
  }
  o += "]";
  if (s.load) {
    const Load& l = *s.load;
    o += ",\n \"load\": ";
    switch (l.kind) {
      case Load::Kind::force: o += "{\"force\": " + pt(l.force) + ", \"at\": " + pt(l.at) + "}"; break;
      case Load::Kind::wrench:
        o += "{\"wrench\": [" + q(l.wrench[0]) + ", " + q(l.wrench[1]) + ", " + q(l.wrench[2]) + "]}";
        break;
      case Load::Kind::gravity: o += "{\"gravity\": " + q(l.weight) + "}"; break;
    }
  }
  if (s.support) {
    o += ",\n \"support\": {";
    if (s.support->mu) o += "\"mu\": " + q(*s.support->mu) + ", ";
    if (s.support->weight) o += "\"weight\": " + q(*s.support->weight) + ", ";
    if (s.support->pressure_center) o += "\"pressure_center\": " + pt(*s.support->pressure_center) + ", ";
    std::string sep;
    if (!s.support->points.empty() || s.support->regions.empty()) {
      o += "\"points\": [";
      for (std::size_t i = 0; i < s.support->points.size(); ++i) {
        const Support_point& p = s.support->points[i];
        o += (i ? ", " : "") + std::string("{\"at\": ") + pt(p.at);
        if (p.force) o += ", \"force\": " + q(*p.force);
        if (p.mu) o += ", \"mu\": " + q(*p.mu);
        o += "}";
      }
      o += "]";
      sep = ", ";
    }
    if (!s.support->regions.empty()) {
      // As written: the outline and holes in their own order and orientation, the pressure in its own form.
      const auto ring = [&](const std::vector<Vec2>& r) {
        std::string t = "[";
        for (std::size_t i = 0; i < r.size(); ++i) t += (i ? ", " : "") + pt(r[i]);
        return t + "]";
      };
      o += sep + "\"regions\": [";
      for (std::size_t k = 0; k < s.support->regions.size(); ++k) {
        const Support_region& r = s.support->regions[k];
        o += (k ? ",\n   " : "\n   ") + std::string("{\"outline\": ") + ring(r.outline);
        if (!r.holes.empty()) {
          o += ", \"holes\": [";
          for (std::size_t j = 0; j < r.holes.size(); ++j) o += (j ? ", " : "") + ring(r.holes[j]);
          o += "]";
        }
        if (r.uniform) o += ", \"pressure\": \"uniform\", \"force\": " + q(r.force);
        else o += ", \"pressure\": {\"linear\": [" + q(r.linear[0]) + ", " + q(r.linear[1]) + ", " + q(r.linear[2]) + "]}";
        if (r.mu) o += ", \"mu\": " + q(*r.mu);
        o += "}";
      }
      o += "]";
    }
    o += "}";
  }
  if (s.pusher) {  // as a point contact at its place (a placed pusher's point and normal written out)
    const Contact& c = s.pusher->contact;
    o += ",\n \"pusher\": {" +
         (s.pusher->end ? "\"segment\": [" + pt(c.at) + ", " + pt(*s.pusher->end) + "]" : "\"at\": " + pt(c.at)) +
         ", \"normal\": " + pt(c.normal) + ", \"mu\": " + q(c.mu) + ", \"velocity\": " + pt(s.pusher->velocity);
    if (s.pusher->end && s.pusher->omega != 0) o += ", \"omega\": " + q(s.pusher->omega);
    if (!c.name.empty()) o += ", \"name\": " + json::quote(c.name);
    o += "}";
  }
  return o + "}\n";
}

std::string one_line(const std::string& canonical) {
  std::string s;
  for (std::size_t i = 0; i < canonical.size(); ++i) {
    if (canonical[i] != '\n') {
      s += canonical[i];
      continue;
    }
    while (i + 1 < canonical.size() && canonical[i + 1] == ' ') ++i;
    if (!s.empty() && s.back() == ',') s += ' ';
  }
  return s;
}

}  // namespace wrenchkit
