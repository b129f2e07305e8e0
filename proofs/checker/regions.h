// proofs/checker/regions.h - support regions, certificate-format.md §6.4 (proofs/notes/RG-1, RG-2): a region of
// the scene's support (read and checked as the scene is read), and the checks of a certificate's region blocks.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "proofs/checker/numbers.h"

namespace wrenchkit_checker::detail {

struct Block;  // a certificate's block (certificate.h)

// A support region (docs/scene-format.md "Support regions"; proofs/notes/RG-1-regions.md): a polygon with
// holes and the pressure p = c0 + c1 x + c2 y >= 0. Checked here by the checker's own exact geometry (no CGAL):
// every ring simple (no repeated vertex, non-adjacent edges apart, adjacent ones meeting only at their common
// vertex), holes strictly inside the outline and apart from each other and from it, p >= 0 at the outline's
// vertices, a positive total force. The rings are oriented (outline counter-clockwise, holes clockwise) and the
// force W_R and moment M_R = integral of r p are computed exactly, by fan triangles from the origin.
struct P2 {
  Q x, y;
};
struct Region {
  std::string path;
  std::vector<std::vector<P2>> rings;  // as read; oriented by settle_region
  bool uniform = true, has_mu = false;
  Q force, linear[3], mu;
  Q c[3];          // the pressure's coefficients
  Q W, M[2];       // integral of p, of r p
};

Region read_region(Reader& r, const Limits& lim, std::size_t& vertices);  // as written (vertices: counted in all)
void settle_region(Region& g);  // validated, oriented, with W and M
Q pressure(const Q (&c)[3], const P2& r);

// A stick block: each cell's force in its friction disc (open with `strict`, closed without); adds the cells'
// wrenches to `sum` and calls friction(c_k) at each cell's pressure centroid where there is friction. Returns whether
// every force is strictly inside its disc.
bool add_stick_block(const Region& g, const Block& b, std::array<Q, 3>& sum,
                     const std::function<void(const Q&, const Q&)>& friction, bool strict);
// A slide block: speed bounds at its vertices for the twist q; returns its bound on the region's frictional power.
Q slide_block_bound(const Region& g, const Block& b, const Q (&q)[3]);

// The two conditions of §6.2 on a support point (support_witnesses.h) and of §6.4 on a cell or a vertex of a block:
// a friction force g in its disc of radius rho = mu f >= 0, open (`strict`: a stick, with g = 0 where rho = 0) or
// closed (a hold); a speed bound u >= 0 with u^2 >= |v|^2, v = (q0 - q2 y, q1 + q2 x) the velocity of the point
// (x, y) under the twist q. Else the Failure "<path>[<i>]: ...", naming the bound `mu_f` or the velocity `v`.
// in_disc returns whether g is strictly inside (open: the condition `strict` asks for).
bool in_disc(const Q& gx, const Q& gy, const Q& rho, bool strict, const std::string& path, std::size_t i,
             const char* mu_f);
void speed_bound(const Q& u, const Q (&q)[3], const Q& x, const Q& y, const std::string& path, std::size_t i,
                 const char* v);

}  // namespace wrenchkit_checker::detail
