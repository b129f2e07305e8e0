// [RG-1] The one place the engine uses CGAL: validity and triangulation of a support region's rings, with
// exact predicates (Epeck: filtered predicates on exact rationals; no construction is needed, every vertex of
// the triangulation is an input vertex, carried by index). Linked privately (CMake: wrenchkit_regions); the
// header exact/io/region.h has no CGAL.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <list>
#include <utility>
#include <vector>

#include "exact/io/region.h"

namespace wrenchkit {

namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = K::Point_2;
using Segment = K::Segment_2;

struct Face_info {
  int nesting = -1;  // -1 unvisited; odd: inside the region
};
using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>;
using Fbi = CGAL::Triangulation_face_base_with_info_2<Face_info, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbi>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

Point point(const Vec2& v) { return Point(K::FT(v.x), K::FT(v.y)); }

// Nesting levels of the faces (CGAL's "polygon with holes" triangulation example): from the infinite face,
// crossing a constrained edge adds one level. Faces of odd level are inside the region.
void mark_domains(Cdt& cdt) {
  std::list<std::pair<Cdt::Face_handle, int>> border{{cdt.infinite_face(), 0}};
  while (!border.empty()) {
    const auto [start, level] = border.front();
    border.pop_front();
    if (start->info().nesting != -1) continue;
    std::list<Cdt::Face_handle> queue{start};
    start->info().nesting = level;
    while (!queue.empty()) {
      const Cdt::Face_handle f = queue.front();
      queue.pop_front();
      for (int i = 0; i < 3; ++i) {
        const Cdt::Face_handle n = f->neighbor(i);
        if (n->info().nesting != -1) continue;
        if (cdt.is_constrained(Cdt::Edge(f, i))) {
          border.emplace_back(n, level + 1);
        } else {
          n->info().nesting = level;
          queue.push_back(n);
        }
      }
    }
  }
}

}  // namespace

Ring_check check_and_triangulate(const std::vector<Vec2>& outline, const std::vector<std::vector<Vec2>>& holes) {
  Ring_check out;
  std::vector<const std::vector<Vec2>*> rings{&outline};
  for (const auto& h : holes) rings.push_back(&h);
  std::vector<std::vector<Point>> pts(rings.size());
  for (std::size_t k = 0; k < rings.size(); ++k) {
    const std::vector<Vec2>& ring = *rings[k];
    out.ring = static_cast<int>(k);
    if (ring.size() < 3) {
      out.why = "has " + std::to_string(ring.size()) + " vertices (a polygon needs at least 3)";
      return out;
    }
    for (const Vec2& v : ring) pts[k].push_back(point(v));
    // A repeated vertex (a zero-length edge, or the ring touching itself at a vertex) is not simple.
    std::vector<Point> sorted = pts[k];
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
      out.why = "is not a simple polygon (a vertex is repeated)";
      return out;
    }
    if (!CGAL::is_simple_2(pts[k].begin(), pts[k].end(), K())) {
      out.why = "is not a simple polygon (two of its edges cross, touch or overlap)";
      return out;
    }
    const CGAL::Orientation o = CGAL::orientation_2(pts[k].begin(), pts[k].end(), K());
    if (o == CGAL::COLLINEAR) {  // not reached for a simple polygon, kept as the stated reason
      out.why = "has zero area";
      return out;
    }
    const bool want_ccw = k == 0;
    std::vector<Vec2> oriented = ring;
    if ((o == CGAL::COUNTERCLOCKWISE) != want_ccw) {
      std::reverse(oriented.begin(), oriented.end());
      std::reverse(pts[k].begin(), pts[k].end());
    }
    out.rings.push_back(std::move(oriented));
  }
  // Holes strictly inside the outline and apart from each other: no two edges of different rings meet (box
  // filter, then exact segment tests), and then one vertex per pair tells containment.
  if (rings.size() > 1) {
    using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::pair<int, std::size_t>>;
    std::vector<Box> boxes;
    for (std::size_t k = 0; k < pts.size(); ++k)
      for (std::size_t i = 0; i < pts[k].size(); ++i) {
        const Point &a = pts[k][i], &b = pts[k][(i + 1) % pts[k].size()];
        boxes.emplace_back(a.bbox() + b.bbox(), std::make_pair(static_cast<int>(k), i));
      }
    int bad_a = -1, bad_b = -1;
    const auto segment = [&](const std::pair<int, std::size_t>& e) {
      const auto& r = pts[static_cast<std::size_t>(e.first)];
      return Segment(r[e.second], r[(e.second + 1) % r.size()]);
    };
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& x, const Box& y) {
      if (x.info().first == y.info().first || bad_a >= 0) return;
      if (CGAL::do_intersect(segment(x.info()), segment(y.info()))) {
        bad_a = std::min(x.info().first, y.info().first);
        bad_b = std::max(x.info().first, y.info().first);
      }
    });
    if (bad_a >= 0) {
      out.ring = bad_b;
      out.why = bad_a == 0 ? "meets the outline (a hole must lie strictly inside it)"
                           : "meets holes[" + std::to_string(bad_a - 1) + "] (holes must be disjoint)";
      return out;
    }
    for (std::size_t k = 1; k < pts.size(); ++k) {
      out.ring = static_cast<int>(k);
      if (CGAL::bounded_side_2(pts[0].begin(), pts[0].end(), pts[k][0], K()) != CGAL::ON_BOUNDED_SIDE) {
        out.why = "is not inside the outline (a hole must lie strictly inside it)";
        return out;
      }
      for (std::size_t j = 1; j < pts.size(); ++j)
        if (j != k && CGAL::bounded_side_2(pts[j].begin(), pts[j].end(), pts[k][0], K()) != CGAL::ON_UNBOUNDED_SIDE) {
          out.why = "lies inside holes[" + std::to_string(j - 1) + "] (holes must be disjoint)";
          return out;
        }
    }
  }
  out.ring = 0;
  // A constrained Delaunay triangulation of the rings; the faces of odd nesting level tile the region.
  std::vector<const Vec2*> vertex_of;
  Cdt cdt;
  for (std::size_t k = 0; k < pts.size(); ++k) {
    std::vector<Cdt::Vertex_handle> vh;
    for (std::size_t i = 0; i < pts[k].size(); ++i) {
      vh.push_back(cdt.insert(pts[k][i]));
      vh.back()->info() = vertex_of.size();
      vertex_of.push_back(&out.rings[k][i]);
    }
    for (std::size_t i = 0; i < vh.size(); ++i) cdt.insert_constraint(vh[i], vh[(i + 1) % vh.size()]);
  }
  mark_domains(cdt);
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (f->info().nesting % 2 != 1) continue;
    out.triangles.push_back({*vertex_of[f->vertex(0)->info()], *vertex_of[f->vertex(1)->info()],
                             *vertex_of[f->vertex(2)->info()]});  // CGAL's faces are counter-clockwise
  }
  return out;
}

}  // namespace wrenchkit
