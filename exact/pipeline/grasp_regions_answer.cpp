#include "exact/pipeline/grasp_regions_answer.h"

#include "exact/certificates/certificates.h"
#include "exact/io/input_error.h"
#include "exact/io/outline.h"
#include "exact/io/scene_writer.h"
#include "exact/pipeline/quality_answer.h"

#include <algorithm>

namespace wrenchkit {

namespace {

// The outline's area centroid (exact): the moments' point when the part has no body.com.
Vec2 area_centroid(const std::vector<Vec2>& V) {
  Rational a2 = 0, cx = 0, cy = 0;
  for (std::size_t k = 0; k < V.size(); ++k) {
    const Vec2 &p = V[k], &q = V[(k + 1) % V.size()];
    const Rational c = cross(p, q);
    a2 += c, cx += (p.x + q.x) * c, cy += (p.y + q.y) * c;
  }
  return {cx / (3 * a2), cy / (3 * a2)};
}

void rank(Grasp_regions_item& r, const Grasp_regions_query& query, const Request& request) {
  const Grasp_regions& g = r.regions;
  r.rank_asked = query.rank_asked;
  const auto add = [&](std::vector<std::size_t> edges, const auto& box, const Rational& side) {
    if (side < query.min_side) return;
    Ranked_placement p;
    p.edges = std::move(edges);
    for (const auto& iv : box) p.at.push_back((iv[0] + iv[1]) / 2);
    p.side = side;
    r.ranked.push_back(std::move(p));
  };
  for (const Pair_region& p : g.pairs)
    if (p.box) add({p.i, p.j}, *p.box, Rational((*p.box)[0][1] - (*p.box)[0][0]));
  for (const Triple_region& t : g.triples)
    if (t.box) add({t.edges[0], t.edges[1], t.edges[2]}, *t.box, t.side);
  Quality_query q;  // ε at a placement: L1, unit-normal, about body.com else the outline's area centroid
  q.critical_mu = false;
  if (query.rank_epsilon) q.about = r.scene.body.com ? *r.scene.body.com : area_centroid(r.scene.body.outline);
  if (query.rank_epsilon) {
    Request quiet = request;
    quiet.certify = false;
    for (Ranked_placement& p : r.ranked) {
      const Scene s = with_fingers(r.scene, g.mu, p.edges, p.at);
      const Quality_item e = answer_quality(s, write_scene(s), quiet, q);
      if (e.status != Status::answered) throw Input_error("--rank epsilon: " + e.message);
      p.epsilon = std::array<Rational, 2>{e.answer.lower, e.answer.upper};
    }
  }
  std::stable_sort(r.ranked.begin(), r.ranked.end(), [](const Ranked_placement& a, const Ranked_placement& b) {
    if (a.epsilon && b.epsilon && (*a.epsilon)[0] != (*b.epsilon)[0]) return (*a.epsilon)[0] > (*b.epsilon)[0];
    return a.side > b.side;
  });
  if (query.rank_epsilon && !r.ranked.empty() && request.certify) {  // the best one's ε, certified on its own scene
    const Ranked_placement& best = r.ranked.front();
    const Scene s = with_fingers(r.scene, g.mu, best.edges, best.at);
    r.best_scene = one_line(write_scene(s));
    const Quality_item e = answer_quality(s, r.best_scene, request, q);
    if (e.status != Status::answered) {
      r.status = e.status, r.message = e.message;
      return;
    }
    r.best_certificate = e.certificate;
  }
}

}  // namespace


Grasp_regions_item answer_grasp_regions(std::string_view text, std::string_view source, const Request& request,
                                        const Grasp_regions_query& query) {
  return answer_into_item<Grasp_regions_item>(text, source, request.limits, [&](Grasp_regions_item& r) {
    r.mode = request.mode;
    const std::optional<Rational> mu = query.mu ? query.mu : r.scene.mu;
    if (!mu) throw Input_error("--mu: missing (the fingers' friction coefficient: give --mu M, or \"mu\" in the scene)");
    r.regions = query.fingers == 3 ? three_finger_regions(r.scene, *mu, query.edges)
                                    : two_finger_regions(r.scene, *mu, query.edges);
    if (request.certify) {
      r.certificate = grasp_regions_certificate(r.regions);
      check_into(r, text, {r.certificate}, request);
      if (r.status != Status::answered) return;
    }
    rank(r, query, request);
  });
}

}  // namespace wrenchkit
