// [CG-2] The limit-surface polytopes as OFF, OBJ and PLY meshes through CGAL's writers (exact/cgal/mesh_io.h).
// CGAL on doubles only (Simple_cartesian<double>: no exact kernel, no GMP or MPFR in this translation unit's code).
#include "exact/cgal/mesh_io.h"

#include <cstdint>
#include <sstream>
#include <vector>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/OBJ.h>
#include <CGAL/Surface_mesh/IO/OFF.h>
#include <CGAL/Surface_mesh/IO/PLY.h>

#include "exact/io/input_error.h"

namespace wrenchkit {

namespace {

using Point = CGAL::Simple_cartesian<double>::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

const CGAL::IO::Color kInner(51, 102, 230, 255);  // opaque blue
const CGAL::IO::Color kOuter(230, 51, 51, 89);    // translucent red

double nearest(const Rational& q) {
  const std::optional<double> d = nearest_double(q);
  if (!d)
    throw Input_error("mesh: the vertex coordinate " + to_string(q) +
                      " is beyond the range of doubles (OFF with exact coordinates holds it exactly; --list lists it)");
  return *d;
}

// Both polytopes in one mesh: the inner one's vertices and faces first. Vertex i of the outer polytope is
// vertex inner.vertices.size() + i.
Mesh both(const Ls_polytope& inner, const Ls_polytope& outer) {
  Mesh m;
  auto color = m.add_property_map<Mesh::Face_index, CGAL::IO::Color>("f:color").first;
  auto which = m.add_property_map<Mesh::Face_index, std::uint8_t>("f:polytope").first;
  std::vector<Mesh::Vertex_index> v, cycle;
  for (const Ls_polytope* P : {&inner, &outer}) {
    v.clear();
    for (const Vec3q& p : P->vertices) v.push_back(m.add_vertex(Point(nearest(p[0]), nearest(p[1]), nearest(p[2]))));
    for (const Ls_facet& f : P->facets) {
      cycle.clear();
      for (const int i : f.vertices) cycle.push_back(v.at(static_cast<std::size_t>(i)));
      const Mesh::Face_index k = m.add_face(cycle);
      if (k == Mesh::null_face()) throw std::logic_error("polytopes_mesh: a facet does not fit the mesh");
      color[k] = P == &inner ? kInner : kOuter;
      which[k] = P == &inner ? 0 : 1;
    }
  }
  return m;
}

// OFF with homogeneous integer coordinates ("4OFF": x = X/W, y = Y/W, z = Z/W, W > 0 the least common
// denominator of the vertex), faces and colours as CGAL's OFF writer writes them.
std::string homogeneous_off(const Ls_polytope& inner, const Ls_polytope& outer) {
  std::ostringstream s;
  s << "4OFF\n# wrenchkit limit-surface: the inner (blue) and outer (red) polygonal limit surfaces; vertices (fx, fy, m)\n"
    << "# of loads (theory.md 1.5), exactly, as homogeneous integers X Y Z W: fx = X/W, fy = Y/W, m = Z/W\n"
    << inner.vertices.size() + outer.vertices.size() << " " << inner.facets.size() + outer.facets.size() << " 0\n";
  for (const Ls_polytope* P : {&inner, &outer})
    for (const Vec3q& p : P->vertices) {
      Integer w = 1;
      for (const Rational& c : p) mpz_lcm(w.get_mpz_t(), w.get_mpz_t(), c.get_den_mpz_t());
      for (const Rational& c : p) s << Integer(c.get_num() * (w / c.get_den())).get_str() << " ";
      s << w.get_str() << "\n";
    }
  std::size_t base = 0;
  for (const Ls_polytope* P : {&inner, &outer}) {
    const CGAL::IO::Color& c = P == &inner ? kInner : kOuter;
    for (const Ls_facet& f : P->facets) {
      s << f.vertices.size() << " ";
      for (const int i : f.vertices) s << " " << base + static_cast<std::size_t>(i);
      s << "  " << int(c.red()) << " " << int(c.green()) << " " << int(c.blue()) << "\n";
    }
    base += P->vertices.size();
  }
  return s.str();
}

}  // namespace

const char* mesh_format_name(Mesh_format f) {
  switch (f) {
    case Mesh_format::off: return "OFF";
    case Mesh_format::obj: return "OBJ";
    case Mesh_format::ply: return "PLY";
  }
  return "?";
}

bool exact_coordinates_possible(Mesh_format f) { return f == Mesh_format::off; }

std::string coordinates_note(Mesh_format f, bool exact_coordinates) {
  if (exact_coordinates && exact_coordinates_possible(f)) return "exact: homogeneous integers X Y Z W (4OFF)";
  const std::string why = f == Mesh_format::off ? "" : std::string(" (") + mesh_format_name(f) + " has no exact numbers)";
  return "nearest doubles" + why;
}

std::string polytopes_mesh(const Ls_polytope& inner, const Ls_polytope& outer, Mesh_format f, bool exact_coordinates) {
  if (f == Mesh_format::off && exact_coordinates) return homogeneous_off(inner, outer);
  const Mesh m = both(inner, outer);
  std::ostringstream s;
  const auto precision = CGAL::parameters::stream_precision(17);  // every double reads back as itself
  bool ok = false;
  switch (f) {
    case Mesh_format::off: ok = CGAL::IO::write_OFF(s, m, precision); break;
    case Mesh_format::obj: ok = CGAL::IO::write_OBJ(s, m, precision); break;
    case Mesh_format::ply:
      CGAL::IO::set_binary_mode(s);  // exact doubles (the stream's mode decides: use_binary_mode is for file names)
      ok = CGAL::IO::write_PLY(s, m,
                               "wrenchkit limit-surface: the inner and outer polygonal limit surfaces, one mesh: face "
                               "property polytope 0 = inner (blue), 1 = outer (red)\nvertices (fx, fy, m) of loads "
                               "(theory.md 1.5) as the nearest doubles; exact values: wrenchkit limit-surface --list");
      break;
  }
  if (!ok) throw std::runtime_error(std::string("polytopes_mesh: CGAL's ") + mesh_format_name(f) + " writer failed");
  return s.str();
}

}  // namespace wrenchkit
