// wrenchkit push: which way a pushed body turns, whatever its pressure distribution — Mason's voting theorem over the
// support's admissible distributions, exact, with a checked certificate (docs/pushing.md, exact/sliding/pushing.h).
#include <cstdio>
#include <sstream>
#include <string>

#include "cli/common.h"
#include "exact/certificates/certificates.h"
#include "exact/numbers/decimal.h"

namespace wrenchkit::cli {

namespace {

const char* vote_word(const Push_vote& v) {
  const std::optional<int> s = v.sign();
  if (!s) return "varies";
  return *s > 0 ? "ccw" : *s < 0 ? "cw" : "through";
}

std::string vote_sentence(const Push_vote& v) {
  const std::optional<int> s = v.sign();
  if (!s) return "changes with the distribution (its side of the centre of friction is not the same for all)";
  if (*s > 0) return "ccw (the centre of friction is on its left)";
  if (*s < 0) return "cw (the centre of friction is on its right)";
  return "passes through the centre of friction";
}

// The rotation centres over every distribution (PU-4): per sense the three pieces' half-planes and polygons.
void write_locus(Json_writer& w, const Push_answer& a) {
  const Push_locus& g = *a.locus;
  w.key("locus");
  if (!g.friction_centre) {
    w.object().member("why", g.why).end_object();
    return;
  }
  w.object().member("R2", g.R2).member("R_hi", g.R_hi);
  if (g.T) w.member("alpha_hi", g.alpha_hi).member("T", *g.T);
  for (int k = 0; k < 2; ++k) {
    w.key(k == 0 ? "ccw" : "cw");
    if (!g.side[k].possible) {
      w.null();
      continue;
    }
    w.array();
    for (const Locus_piece& piece : g.side[k].pieces) {
      w.object().member("mode", locus_mode_name(piece.mode)).key("halfplanes").array();
      for (const Locus_halfplane& h : piece.halfplanes) {
        w.object().member("why", locus_bound_name(h.why));
        w.key("a").array().rational(h.h.a.x).rational(h.h.a.y).end_array().member("b", h.h.b).end_object();
      }
      w.end_array().member("bounded", piece.bounded).key("polygon").array();
      std::vector<Rational> flat;
      for (const Vec2& v : piece.polygon) {
        w.array().rational(v.x).rational(v.y).end_array();
        flat.push_back(v.x), flat.push_back(v.y);
      }
      w.end_array();
      write_approx(w, "polygon", flat);
      w.end_object();
    }
    w.end_array();
  }
  w.key("box").array();
  for (const Vec2& v : g.box) w.array().rational(v.x).rational(v.y).end_array();
  w.end_array();
  if (g.arm_hi) {
    w.member("arm_hi", *g.arm_hi);
    write_approx(w, "arm_hi", {*g.arm_hi});
  } else {
    w.member("arm_why", g.arm_why);
  }
  if (a.slowest) {  // a distribution that turns this slowly: the slowest turn's arm is at least arm_lo
    w.member("arm_lo", a.slowest->arm_lo);
    write_approx(w, "arm_lo", {a.slowest->arm_lo});
    w.key("slowest").object().key("forces").rationals(a.slowest->contact.forces);
    w.member("mode", push_mode_name(a.slowest->contact.mode)).end_object();
  }
  w.end_object();
}

std::string locus_text(const Push_answer& a) {
  const Push_locus& g = *a.locus;
  std::ostringstream s;
  if (!g.friction_centre) return "rotation centres: not answered — " + g.why + "\n";
  s << "rotation centres over every distribution (an outer bound: the body turns about a point of these pieces";
  if (g.T) s << "; tip line T = " << number_text(*g.T);
  s << "):\n";
  for (int k = 0; k < 2; ++k) {
    const char* sense = k == 0 ? "ccw" : "cw";
    if (!g.side[k].possible) {
      s << "  " << sense << ": none (the rotation is certain)\n";
      continue;
    }
    for (const Locus_piece& piece : g.side[k].pieces) {
      s << "  " << sense << ", " << locus_mode_name(piece.mode) << ": ";
      if (piece.polygon.empty()) {
        s << (piece.bounded ? "none" : "none within the box") << "\n";
        continue;
      }
      s << (piece.bounded ? "" : "unbounded; within the box ")
        << (piece.polygon.size() == 1 ? "the point" : piece.polygon.size() == 2 ? "the segment" : "the polygon");
      for (const Vec2& v : piece.polygon) s << " (" << decimal_text(v.x, 6) << ", " << decimal_text(v.y, 6) << ")";
      s << "\n";
    }
  }
  if (g.arm_hi)
    s << "  slowest turn: the centre is within " << number_text(*g.arm_hi) << " of the pusher's normal line — the body "
      << "turns at least 1 radian per " << number_text(*g.arm_hi) << " the pusher advances along its normal\n";
  else
    s << "  slowest turn: not bounded — " << g.arm_why << "\n";
  if (a.slowest)
    s << "  a slow distribution: under the forces " << vec_text(a.slowest->contact.forces) << " it "
      << push_mode_name(a.slowest->contact.mode) << " about a centre at least " << number_text(a.slowest->arm_lo)
      << " from the normal line — the slowest turn's arm is at least that\n";
  return s.str();
}

}  // namespace

void write_push(Json_writer& w, const Push_item& r) {
  const Push_answer& a = r.push;
  w.member("command", "push").member("name", r.scene.name);
  const Pusher& pu = *r.scene.pusher;
  w.key("pusher").object();
  if (pu.line()) {
    w.key("segment").array().array().rational(a.at.x).rational(a.at.y).end_array();
    w.array().rational(pu.end->x).rational(pu.end->y).end_array().end_array();
  } else {
    w.key("at").array().rational(a.at.x).rational(a.at.y).end_array();
  }
  w.key("normal").array().rational(a.normal.x).rational(a.normal.y).end_array();
  w.member("mu", a.mu);
  w.key("velocity").array().rational(a.velocity.x).rational(a.velocity.y).end_array();
  if (pu.line()) w.member("omega", pu.omega);
  w.end_object();
  w.member("distribution", a.known ? "known" : "unknown");
  if (a.center) {
    w.key("center_of_friction").array().rational(a.center->x).rational(a.center->y).end_array();
    write_approx(w, "center_of_friction", {a.center->x, a.center->y});
  } else {
    w.key("center_of_friction").null();
  }
  if (a.by_twin) w.member("decided_by", "float twin");
  w.key("votes").array();
  for (const Push_vote& v : a.votes) {
    if (!a.votes_known) break;
    w.object().member("line", push_line_name(v.line));
    w.key("direction").array().rational(v.direction.x).rational(v.direction.y).end_array();
    w.member("vote", vote_word(v)).end_object();
  }
  w.end_array();
  w.member("rotation", rotation_name(a.rotation)).member("why", a.why);
  if (a.rotation == Rotation::depends)
    w.key("witnesses").object().key("ccw").rationals(a.turns_ccw).key("cw").rationals(a.turns_cw).end_object();
  if (a.stable) {  // a line pusher (PU-3)
    const Stable_push& st = *a.stable;
    w.key("stable").object().member("verdict", stability_name(st.verdict)).member("why", st.why);
    if (st.centre) {
      w.key("rotation_centre").array().rational(st.centre->x).rational(st.centre->y).end_array();
      write_approx(w, "rotation_centre", {st.centre->x, st.centre->y});
    }
    if (st.verdict == Stability::stable && st.sense == 0) {  // the facets the load is on (its boundary), exact
      w.key("boundary").array();
      for (int k = 0; k < 4; ++k)
        if (sgn(st.values[k]) == 0) w.string(cone_facet_name(static_cast<Cone_facet>(k)));
      w.end_array();
    }
    if (st.verdict == Stability::unstable) {
      w.member("facet", cone_facet_name(st.facet));
      if (st.sense != 0) {
        w.key("witness").object().key("points").array();
        for (const Vec2& x : st.points) w.array().rational(x.x).rational(x.y).end_array();
        w.end_array().key("weights").rationals(st.weights).end_object();
      }
    }
    w.end_object();
  }
  if (a.region && !a.region->friction_centre) w.key("stable_region").null();  // (c moves: the verdict's why says so)
  if (a.region && a.region->friction_centre) {  // the stable region (PU-3 §6): half-planes a·q ≤ b per sense, their
    // polygon within the box
    const Stable_region& g = *a.region;
    w.key("stable_region").object();
    for (int k = 0; k < 2; ++k) {
      const Stable_region_side& side = g.side[k];
      w.key(k == 0 ? "ccw" : "cw");
      if (!side.possible) {
        w.null();
        continue;
      }
      w.object().key("halfplanes").array();
      for (int f = 0; f < 4; ++f) {
        const Halfplane& h = side.halfplanes[f];
        w.object().member("facet", cone_facet_name(static_cast<Cone_facet>(f)));
        w.key("a").array().rational(h.a.x).rational(h.a.y).end_array().member("b", h.b).end_object();
      }
      w.end_array().member("T", side.T).key("polygon").array();
      for (const Vec2& v : side.polygon) w.array().rational(v.x).rational(v.y).end_array();
      w.end_array();
      std::vector<Rational> flat;
      for (const Vec2& v : side.polygon) flat.push_back(v.x), flat.push_back(v.y);
      write_approx(w, "polygon", flat);
      w.end_object();
    }
    w.key("box").array();
    for (const Vec2& v : g.box) w.array().rational(v.x).rational(v.y).end_array();
    w.end_array().key("translations");
    if (g.translations) {
      w.array();
      for (const Vec2& v : *g.translations) w.array().rational(v.x).rational(v.y).end_array();
      w.end_array();
    } else {
      w.null();
    }
    w.end_object();
  }
  if (a.contact) {
    const Push_contact& c = *a.contact;
    w.key("contact").object().member("mode", push_mode_name(c.mode));
    if (c.mode == Push_mode::depends) {  // two distributions of F whose certified modes differ
      w.key("witnesses").array();
      for (const Push_contact& k : c.witnesses)
        w.object().key("forces").rationals(k.forces).member("mode", push_mode_name(k.mode)).end_object();
      w.end_array();
    }
    if (c.mode == Push_mode::sticks || c.mode == Push_mode::impending) {
      // the body moves with the pusher: its twist (vx + ω py, vy − ω px, ω) for ω in the bracket
      w.key("omega").array().rational(c.omega_lo).rational(c.omega_hi).end_array();
      write_approx(w, "omega", {c.omega_lo, c.omega_hi});
      if (c.pivot) {  // sticking about that support point (PU-2 §7): ω exact, a force of its facet inside the cone
        w.member("pivot", *c.pivot);
        w.key("force").array().rational(c.force->x).rational(c.force->y).end_array();
      }
    }
    if ((c.mode == Push_mode::slides_left || c.mode == Push_mode::slides_right)) {
      // the body's velocity at the pusher v + slip·rot90(n), its rate ω, both certified brackets (PU-2 §5)
      if (c.pivot) {  // the sticking motion is the rotation about that support point; its facet's forces all beyond the edge
        w.member("sticking_pivot", *c.pivot);
        w.key("sticking_omega").array().rational(c.omega_lo).rational(c.omega_hi).end_array();
      }
      if (c.has_motion) {
        if (c.motion_pivot) w.member("pivot", *c.motion_pivot);  // rotating about that support point (exact slip and rate)
        w.key("slip").array().rational(c.slip_lo).rational(c.slip_hi).end_array();
        write_approx(w, "slip", {c.slip_lo, c.slip_hi});
        w.key("omega").array().rational(c.motion_lo).rational(c.motion_hi).end_array();
        write_approx(w, "omega", {c.motion_lo, c.motion_hi});
      } else {
        w.member("motion_why", c.motion_why);
      }
    }
    if (c.mode == Push_mode::undecided) w.member("why", c.why);
    w.end_object();
  }
  if (a.locus) write_locus(w, a);
  if (!r.certificate.empty()) w.member("certificate_checked", true).key("certificate").raw(r.certificate);
}

namespace {

std::string push_human(const Push_item& r, const std::string& source) {
  const Push_answer& a = r.push;
  std::ostringstream s;
  s << scene_line(r.scene, source);
  const Pusher& pu = *r.scene.pusher;
  if (pu.line()) {
    s << "pusher along " << vec_text(a.at) << " – " << vec_text(*pu.end) << ", inward normal " << vec_text(a.normal)
      << ", mu = " << number_text(a.mu) << ", moving " << vec_text(a.velocity) << " at its middle";
    if (sgn(pu.omega) == 0) s << ", translating\n";
    else s << ", turning at " << number_text(pu.omega) << " about " << vec_text(*a.stable->centre) << "\n";
  } else {
    s << "pusher at " << vec_text(a.at) << ", inward normal " << vec_text(a.normal) << ", mu = " << number_text(a.mu)
      << ", moving " << vec_text(a.velocity) << "\n";
  }
  if (a.stable) {
    const Stable_push& st = *a.stable;
    if (a.center) s << "centre of friction: " << vec_text(*a.center) << "\n";
    s << "stable: " << stability_name(st.verdict) << " — " << st.why << "\n";
    if (st.verdict == Stability::unstable && st.sense != 0) {
      s << "  the distribution:";
      for (std::size_t k = 0; k < st.points.size(); ++k)
        s << (k ? "," : "") << " weight " << number_text(st.weights[k]) << " at " << vec_text(st.points[k]);
      s << "\n";
    }
    s << "rotation: " << rotation_name(a.rotation) << " — " << a.why << "\n";
    if (a.region && !a.region->friction_centre) s << "stable region: not answered — " << a.region->why << "\n";
    if (a.region && a.region->friction_centre) {
      const Stable_region& g = *a.region;
      s << "stable region (the pusher's motions certified stable for every distribution; a motion outside may be "
           "stable too):\n";
      for (int k = 0; k < 2; ++k) {
        const Stable_region_side& side = g.side[k];
        s << "  turning " << (k == 0 ? "ccw" : "cw") << " about q: ";
        if (!side.possible) {
          s << "none certified (the tip end is the centre of friction)\n";
          continue;
        }
        static const char* const what[4] = {"left edge", "right edge", "", ""};
        for (int f = 0; f < 4; ++f) {
          const Halfplane& h = side.halfplanes[f];
          s << (f ? "; " : "") << vec_text(h.a) << "·q <= " << number_text(h.b) << " ("
            << (f < 2 ? what[f] : static_cast<std::size_t>(f - 2) == side.tip ? "tip line of end " : "bisector of end ")
            << (f < 2 ? "" : std::to_string(f - 2)) << ")";
        }
        s << "\n    within the box " << vec_text(g.box[0]) << " – " << vec_text(g.box[1]) << ": ";
        if (side.polygon.empty()) {
          s << "empty\n";
        } else {
          s << "the polygon";
          for (const Vec2& v : side.polygon)
            s << " (" << decimal_text(v.x, 6) << ", " << decimal_text(v.y, 6) << ")";
          s << "\n";
        }
      }
      s << "  translating: ";
      if (g.translations)
        s << "every velocity from " << vec_text((*g.translations)[0]) << " counter-clockwise to " << vec_text((*g.translations)[1]) << "\n";
      else
        s << "none\n";
    }
    if (!r.certificate.empty()) s << "certificate accepted by the independent checker (exact arithmetic)\n";
    return s.str();
  }
  if (a.by_twin || !a.votes_known)
    s << "centre of friction: not computed (the float twin decides the votes' signs without it)\n";
  else if (a.center)
    s << "centre of friction: " << vec_text(*a.center)
      << (a.known ? "" : " (the centre of pressure: the same for every distribution, every coefficient being equal)") << "\n";
  else
    s << "centre of friction: moves with the distribution (the support's coefficients differ and some forces are not given)\n";
  if (a.votes_known) {
    s << "votes (the side of the centre of friction each directed line through the pusher passes):\n";
    for (const Push_vote& v : a.votes)
      s << "  " << push_line_name(v.line) << " " << vec_text(v.direction) << ": " << vote_sentence(v) << "\n";
  }
  s << "rotation: " << rotation_name(a.rotation) << " — " << a.why << "\n";
  if (a.rotation == Rotation::depends)
    s << "  turns ccw under the forces " << vec_text(a.turns_ccw) << "\n  turns cw under the forces "
      << vec_text(a.turns_cw) << "\n";
  if (a.contact) {
    const Push_contact& c = *a.contact;
    s << "contact: " << push_mode_name(c.mode);
    if (c.mode == Push_mode::depends) {
      s << " — the distributions of the support's forces do not all do one thing:";
      for (std::size_t k = 0; k < c.witnesses.size(); ++k)
        s << (k ? ";" : "") << " under the forces " << vec_text(c.witnesses[k].forces) << " it "
          << push_mode_name(c.witnesses[k].mode);
      s << " (each certified)\n";
    } else if (c.mode == Push_mode::sticks || c.mode == Push_mode::impending) {
      s << (c.mode == Push_mode::sticks ? " — the body moves with the pusher" : " — the force on a cone edge exactly");
      if (c.pivot) {
        const Support_point& sp = r.scene.support->points[*c.pivot];
        s << ", turning at " << number_text(c.omega_lo) << " about the support point " << *c.pivot << " at "
          << vec_text(sp.at) << " (a pivot: a facet of the limit surface; the pusher's force may be along "
          << vec_text(*c.force) << ")\n";
      } else if (c.omega_lo == c.omega_hi) {
        s << ", translating along the pusher's velocity (no rotation)\n";
      } else {
        s << ", turning at a rate in [" << decimal_text(c.omega_lo, 10) << ", " << decimal_text(c.omega_hi, 10)
          << "] for the pusher's velocity " << vec_text(a.velocity);
        if (sgn(c.omega_lo) == sgn(c.omega_hi)) {  // about a centre p + rot90(v)/ω, on a segment
          const auto centre = [&](const Rational& w) {
            const Vec2 x = rotation_centre(a.at, a.velocity, w);
            return "(" + decimal_text(x.x, 6) + ", " + decimal_text(x.y, 6) + ")";
          };
          s << ", about a centre between " << centre(c.omega_lo) << " and " << centre(c.omega_hi);
        }
        s << "\n";
      }
    } else if (c.mode == Push_mode::undecided) {
      s << " — " << c.why << "\n";
    } else {
      s << " — the contact slides, the pusher's force on the friction cone's " << (c.mode == Push_mode::slides_left ? "left" : "right")
        << " edge";
      if (c.pivot) {
        const Support_point& sp = r.scene.support->points[*c.pivot];
        s << " (moving with the pusher the body would turn about the support point " << *c.pivot << " at "
          << vec_text(sp.at) << ", and every force of that facet of the limit surface through the pusher is beyond the "
          << (c.mode == Push_mode::slides_left ? "left" : "right") << " edge)";
      }
      if (!c.has_motion) {
        s << "; the body's motion: " << c.motion_why << "\n";
      } else {
        const Vec2 t{-a.normal.y, a.normal.x};
        s << "; the body's velocity at the pusher is v + τ" << vec_text(t) << " (it slips along the pusher) with τ ";
        if (c.slip_lo == c.slip_hi) s << "= " << number_text(c.slip_lo);
        else s << "in [" << decimal_text(c.slip_lo, 10) << ", " << decimal_text(c.slip_hi, 10) << "]";
        if (c.motion_pivot) {
          const Support_point& sp = r.scene.support->points[*c.motion_pivot];
          s << ", turning at " << number_text(c.motion_lo) << " about the support point " << *c.motion_pivot << " at "
            << vec_text(sp.at) << " (a pivot: a facet of the limit surface)\n";
        } else if (c.motion_lo == c.motion_hi) {
          s << ", translating (no rotation)\n";
        } else {
          s << ", turning at a rate in [" << decimal_text(c.motion_lo, 10) << ", " << decimal_text(c.motion_hi, 10) << "]";
          if (sgn(c.motion_lo) == sgn(c.motion_hi)) {  // about p + rot90(u)/ω, u the velocity at p (midpoints)
            const Rational tau = (c.slip_lo + c.slip_hi) / 2;
            const Vec2 x = rotation_centre(a.at, {a.velocity.x + tau * t.x, a.velocity.y + tau * t.y},
                                           (c.motion_lo + c.motion_hi) / 2);
            char buf[96];
            std::snprintf(buf, sizeof buf, "(%.6g, %.6g)", x.x.get_d(), x.y.get_d());
            s << ", about a centre near " << buf;
          }
          s << "\n";
        }
      }
    }
  }
  if (a.locus) s << locus_text(a);
  if (!r.certificate.empty()) s << "certificate accepted by the independent checker (exact arithmetic)\n";
  return s.str();
}

}  // namespace

Push_query push_query(const Options& o) {
  Push_query q = o.push;
  if (o.tolerance) q.tolerance = *o.tolerance;
  return q;
}

Scene_answer prepare_push_json(const Options& o) {
  return [request = request_of(o), query = push_query(o)](Json_writer& w, const std::string& text,
                                                          const std::string& source) {
    write_push(w, answered(answer_push(text, source, request, query)));
  };
}

int run_push(const Options& o, const std::string& scene_text, const std::string& source) {
  const Push_item r = answered(answer_push(scene_text, source, request_of(o), push_query(o)));
  if (!o.certificate_file.empty() && !r.certificate.empty()) write_file(o.certificate_file, r.certificate + "\n");
  // (a line pusher answers whether its motion is stable: undecided when that is)
  const bool undecided = r.push.stable ? r.push.stable->verdict == Stability::undecided
                                       : r.push.rotation == Rotation::undecided ||
                                             (r.push.contact && r.push.contact->mode == Push_mode::undecided);
  return write_answer(o, [&](Json_writer& w) { write_push(w, r); }, [&] { return push_human(r, source); }, undecided);
}

}  // namespace wrenchkit::cli
