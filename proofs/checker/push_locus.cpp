// proofs/checker/push_locus.cpp - certificate-format.md §8.4: a point pusher's rotation centres over every distribution
// (proofs/notes/PU-4-rotation-centres.md): the member "locus" and its check, beside push.cpp's §8.
//
// For each sense the certified rotation allows, the centres of each contact mode lie in an intersection of half-planes
// the checker derives from the scene itself (PU-4 §2–§5): the bisector |q - p| >= |q - c|, the tip line
// (c - p).(q - c) <= T, the contact advancing sigma (p - q) x n >= 0, and the mode's own — sticks: on the line
// (p - q).v = 0 with the load inside the cone; slides left/right: the load along that edge, the body slipping
// against it. A piece claimed bounded has no direction of recession, and every vertex of the intersection (the
// boundary lines' crossings that satisfy every half-plane) lies in the claimed polygon; "arm_hi" bounds every such
// vertex's distance from the pusher's normal line.
#include "proofs/checker/certificate.h"

#include <algorithm>

namespace wrenchkit_checker::detail {

namespace {

using Pt = std::array<Q, 2>;
struct Half {
  Q a[2], b;  // a.q <= b
};

Q cross(const Q& ax, const Q& ay, const Q& bx, const Q& by) { return ax * by - ay * bx; }

bool satisfies(const std::vector<Half>& hs, const Pt& q) {
  return std::all_of(hs.begin(), hs.end(), [&](const Half& h) { return h.a[0] * q[0] + h.a[1] * q[1] <= h.b; });
}

// A direction u != 0 with a.u <= 0 for every half-plane, if any: a recession cone other than {0} and the plane has a
// boundary ray on some line a.u = 0.
bool recedes(const std::vector<Half>& hs, Pt& dir) {
  for (const Half& h : hs)
    for (int s : {1, -1}) {
      const Pt u = {-s * h.a[1], s * h.a[0]};
      if (sgn(u[0]) == 0 && sgn(u[1]) == 0) continue;
      if (std::all_of(hs.begin(), hs.end(), [&](const Half& g) { return sgn(Q(g.a[0] * u[0] + g.a[1] * u[1])) <= 0; })) {
        dir = u;
        return true;
      }
    }
  return false;
}

std::vector<Pt> corners(const std::vector<Half>& hs) {
  std::vector<Pt> out;
  for (std::size_t i = 0; i < hs.size(); ++i)
    for (std::size_t j = i + 1; j < hs.size(); ++j) {
      const Q det = cross(hs[i].a[0], hs[i].a[1], hs[j].a[0], hs[j].a[1]);
      if (sgn(det) == 0) continue;
      const Pt q = {(hs[i].b * hs[j].a[1] - hs[j].b * hs[i].a[1]) / det,
                    (hs[i].a[0] * hs[j].b - hs[j].a[0] * hs[i].b) / det};
      if (satisfies(hs, q)) out.push_back(q);
    }
  return out;
}

// x in the polygon read as counter-clockwise and convex: left of (or on) every edge; two vertices a segment, one a point.
bool inside(const std::vector<Pt>& poly, const Pt& x) {
  const std::size_t m = poly.size();
  if (m == 0) return false;
  if (m == 1) return poly[0] == x;
  if (m == 2) {
    const Pt &a = poly[0], &b = poly[1];
    const Q t = (x[0] - a[0]) * (b[0] - a[0]) + (x[1] - a[1]) * (b[1] - a[1]);
    return sgn(cross(b[0] - a[0], b[1] - a[1], x[0] - a[0], x[1] - a[1])) == 0 && sgn(t) >= 0 &&
           t <= (b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]);
  }
  for (std::size_t i = 0; i < m; ++i) {
    const Pt &a = poly[i], &b = poly[(i + 1) % m];
    if (sgn(cross(b[0] - a[0], b[1] - a[1], x[0] - a[0], x[1] - a[1])) < 0) return false;
  }
  return true;
}

const char* const kModes[3] = {"sticks", "slides left", "slides right"};

}  // namespace

void read_locus_member(Reader& r, Push_part& p) {
  p.has_locus = true;
  begin_object(r, "expected an object {\"R_hi\", \"alpha_hi\"?, \"T\"?, \"ccw\", \"cw\", \"arm_hi\"?}");
  std::string_view k;
  unsigned seen = 0;
  while (r.next_key(k)) {
    if (k == "R_hi") {
      seen |= 1, p.locus_R_hi = read_rational(r);
    } else if (k == "alpha_hi") {
      seen |= 8, p.locus_alpha_hi = read_rational(r);
    } else if (k == "T") {
      seen |= 16, p.locus_T = read_rational(r);
    } else if (k == "arm_hi") {
      p.has_arm = true, p.arm_hi = read_rational(r);
    } else if (k == "arm_lo") {
      seen |= 32, p.arm_lo = read_rational(r);
    } else if (k == "slowest") {  // checked in push.cpp with the contact modes (§8.2)
      seen |= 64;
      read_contact(r, *(p.slowest = std::make_unique<Push_part>()), true);
    } else if (k == "ccw" || k == "cw") {
      const int s = k == "ccw" ? 0 : 1;
      seen |= s == 0 ? 2 : 4;
      if (r.peek() == Reader::Kind::null) {
        r.skip();
        continue;
      }
      p.has_sense[s] = true;
      begin_array(r, "expected the three pieces [{\"mode\", \"bounded\", \"polygon\"}, …] or null");
      while (r.next_item()) {
        if (p.pieces[s].size() == 3) r.fail("a sense has three pieces (sticks, slides left, slides right)");
        Push_part::Piece& piece = p.pieces[s].emplace_back();
        begin_object(r, "expected an object {\"mode\", \"bounded\", \"polygon\"}");
        std::string_view j;
        unsigned got = 0;
        while (r.next_key(j)) {
          if (j == "mode") {
            got |= 1;
            if (r.peek() != Reader::Kind::string) r.fail("expected \"sticks\", \"slides left\" or \"slides right\"");
            piece.mode = r.string_view();
            if (std::find(std::begin(kModes), std::end(kModes), piece.mode) == std::end(kModes))
              r.fail("expected \"sticks\", \"slides left\" or \"slides right\"");
          } else if (j == "bounded") {
            got |= 2;
            if (r.peek() != Reader::Kind::boolean) r.fail("expected true or false");
            piece.bounded = r.boolean();
          } else if (j == "polygon") {
            got |= 4;
            begin_array(r, "expected an array of points [x, y]");
            while (r.next_item()) {
              Pt& x = piece.polygon.emplace_back();
              read_fixed(r, 2, "a point [x, y]", [&](std::size_t m) { x[m] = read_rational(r); });
            }
          } else {
            r.fail("unknown key " + quote(j), true);
          }
        }
        if (got != 7) r.fail("a piece needs \"mode\", \"bounded\" and \"polygon\"");
      }
    } else {
      r.fail("unknown key " + quote(k), true);
    }
  }
  if ((seen & 7) != 7) r.fail("a locus needs \"R_hi\", \"ccw\" and \"cw\"");
  if ((seen & 24) != 0 && (seen & 24) != 24) r.fail("the tip line's bounds are \"alpha_hi\" and \"T\" together");
  if ((seen & 96) != 0 && (seen & 96) != 96) r.fail("\"arm_lo\" and \"slowest\" go together");
  p.has_tip = (seen & 24) == 24;
}

void check_locus(const Push_part& p, const Scene& scene, const Limits& lim) {
  const std::vector<Q> pn = contact_numbers(scene.pusher->contact, lim);  // x, y, nx, ny, mu
  const Q P[2] = {pn[0], pn[1]}, n[2] = {pn[2], pn[3]}, &mu = pn[4];
  const Q(&v)[2] = scene.pusher->velocity;
  const Q eL[2] = {n[0] - mu * n[1], n[1] + mu * n[0]}, eR[2] = {n[0] + mu * n[1], n[1] - mu * n[0]};
  Q c[2];
  std::vector<Pt> S;
  const Q R2 = friction_disc(scene, lim, "locus", c, S);
  const Q& R = p.locus_R_hi;
  if (sgn(R) < 0 || R * R < R2) throw Failure{"locus.R_hi: not an upper bound of R (R^2 = " + show(R2) + ")"};
  const Q a[2] = {c[0] - P[0], c[1] - P[1]};
  if (p.has_tip) {  // PU-3 §5 at y = p: beyond a.(q - c) = T the load's moment about p is not 0
    const Q &al = p.locus_alpha_hi, &T = p.locus_T;
    if (sgn(al) <= 0 || al * al < a[0] * a[0] + a[1] * a[1]) throw Failure{"locus.alpha_hi: not an upper bound of |c - p|"};
    if (sgn(T) <= 0 || T / al <= R) throw Failure{"locus.T: T/alpha_hi is not more than R_hi"};
    if (T < R2 + tip_correction(R, T / al, al))
      throw Failure{"locus.T: " + show(T) + " is below R^2 + E(T/alpha_hi) = " + show(Q(R2 + tip_correction(R, T / al, al)))};
  }
  const auto extent = [&](const Q (&e)[2], int s, bool hi) {  // max (hi) or min of s x.e over S
    Q best = s * (S[0][0] * e[0] + S[0][1] * e[1]);
    for (const Pt& x : S) {
      const Q t = s * (x[0] * e[0] + x[1] * e[1]);
      best = hi ? std::max(best, t) : std::min(best, t);
    }
    return best;
  };
  const Q pv = P[0] * v[0] + P[1] * v[1];
  Q H = 0;  // the largest sigma (p - q) x n over the pieces' vertices
  bool all_bounded = true;
  for (int k = 0; k < 2; ++k) {
    const int s = k == 0 ? 1 : -1;
    const std::string path = std::string("locus.") + (k == 0 ? "ccw" : "cw");
    if (!p.has_sense[k]) {
      if (p.rotation != (k == 0 ? "cw" : "ccw") && p.rotation != "none")
        throw Failure{path + ": null, but the rotation \"" + std::string(p.rotation) + "\" does not exclude this sense"};
      continue;
    }
    if (p.pieces[k].size() != 3) throw Failure{path + ": three pieces (sticks, slides left, slides right)"};
    for (int m = 0; m < 3; ++m) {
      const Push_part::Piece& piece = p.pieces[k][m];
      const std::string at = path + "[" + std::to_string(m) + "]";
      if (piece.mode != kModes[m]) throw Failure{at + ".mode: expected \"" + std::string(kModes[m]) + "\""};
      std::vector<Half> hs = {{{2 * (P[0] - c[0]), 2 * (P[1] - c[1])}, P[0] * P[0] + P[1] * P[1] - c[0] * c[0] - c[1] * c[1]},
                              {{s * n[1], -s * n[0]}, s * cross(P[0], P[1], n[0], n[1])}};
      if (p.has_tip) hs.push_back({{a[0], a[1]}, p.locus_T + a[0] * c[0] + a[1] * c[1]});
      if (m == 0) {  // sticks
        hs.push_back({{-s * eL[0], -s * eL[1]}, -extent(eL, s, false)});
        hs.push_back({{s * eR[0], s * eR[1]}, extent(eR, s, true)});
        hs.push_back({{v[0], v[1]}, pv});
        hs.push_back({{-v[0], -v[1]}, -pv});
      } else {  // slides along e, slipping against it
        const Q(&e)[2] = m == 1 ? eL : eR;
        const int t = m == 1 ? s : -s;
        hs.push_back({{e[0], e[1]}, extent(e, 1, true)});
        hs.push_back({{-e[0], -e[1]}, -extent(e, 1, false)});
        hs.push_back({{-t * v[0], -t * v[1]}, -t * pv});
      }
      if (!piece.bounded) {
        all_bounded = false;
        continue;
      }
      Pt dir;
      if (recedes(hs, dir))
        throw Failure{at + ": claimed bounded, but its half-planes recede along " + show(dir[0], dir[1])};
      for (const Pt& q : corners(hs)) {
        if (!inside(piece.polygon, q))
          throw Failure{at + ".polygon: the vertex " + show(q[0], q[1]) + " of the centres' bound is outside it"};
        H = std::max(H, Q(s * cross(P[0] - q[0], P[1] - q[1], n[0], n[1])));
      }
    }
  }
  if (!p.has_arm) return;
  if (!all_bounded) throw Failure{"locus.arm_hi: a piece is unbounded (no arm bounds the centres)"};
  if (sgn(p.arm_hi) < 0 || p.arm_hi * p.arm_hi * (n[0] * n[0] + n[1] * n[1]) < H * H)
    throw Failure{"locus.arm_hi: " + show(p.arm_hi) + " is below a possible centre's distance from the pusher's normal "
                  "line (sigma (p - q) x n = " + show(H) + ")"};
}

}  // namespace wrenchkit_checker::detail
