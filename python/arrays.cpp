// The array API's native part (_core.closure_arrays, equilibrium_arrays, stick_slide_arrays): rows of doubles
// → Scenes → the pipeline (exact/pipeline/: answer_closure, answer_equilibrium, answer_support, the very
// functions of every front end) on `jobs` threads of the batch's ordered map, the GIL released → NumPy
// arrays. Each double is read as the exact binary rational it denotes (set_point_contact; mpq_set_d for
// the loads and supports), so a row's answer is the exact answer for the scene built with Fraction(x) of the
// same doubles. The package (python/wrenchkit/__init__.py) validates the arrays first (shape, dtype, NaN,
// infinities, zero normals, negative μ, with the row, the contact and the value), so nothing here meets bad
// input; a status other than answered / undecided raises InternalError (a bug) and nothing is returned.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>

#include "core/mode.h"
#include "exact/certificates/certificates.h"
#include "exact/io/scene.h"
#include "exact/io/scene_writer.h"
#include "exact/pipeline/ordered_map.h"
#include "exact/pipeline/pipeline.h"
#include "exact/pipeline/quality_answer.h"
#include "exact/pipeline/support_answer.h"
#include "python/convert.h"

namespace wrenchkit::python {

namespace {

using Doubles = py::array_t<double, py::array::c_style>;
using Counts = py::array_t<std::int64_t, py::array::c_style>;

// decided_by as the small integers of docs/python.md (wrenchkit.DECIDED_BY): -1 undecided (mode "float" only).
std::int8_t decided_code(Arithmetic d) { return static_cast<std::int8_t>(d); }
// motion and motion_decided_by (wrenchkit.MOTION, wrenchkit.MOTION_DECIDED_BY).
std::int8_t motion_code(Motion m) {
  return m == Motion::sticks ? 1 : m == Motion::slides ? 0 : m == Motion::impending ? 2 : -1;
}
std::int8_t motion_decided_code(Decided_by d) {
  switch (d) {
    case Decided_by::float_search: return 0;
    case Decided_by::polygons: return 1;
    case Decided_by::flat: return 2;
    case Decided_by::certificate: return 3;
    case Decided_by::newton: return 4;
    default: return -1;
  }
}

Request request_for(const std::string& mode, bool certificates) {
  const std::optional<Mode> m = parse_mode(mode);
  if (!m) throw std::invalid_argument("mode: \"" + mode + "\" " + kModeChoices);
  Request r;
  r.mode = *m;
  r.certify = certificates;
  return r;
}

// The contacts of one row (validated by the caller).
struct Contact_rows {
  const double *points, *normals, *mu;
  const std::int64_t* counts;
  std::size_t rows, width;
  void fill(Scene& s, std::size_t row) const {
    const std::size_t n = static_cast<std::size_t>(counts[row]);
    if (s.contacts.size() != n) s.contacts.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t c = row * width + k;
      set_point_contact(s.contacts[k], points[2 * c], points[2 * c + 1], normals[2 * c], normals[2 * c + 1], mu[c]);
    }
  }
};

Contact_rows contact_rows(const Doubles& points, const Doubles& normals, const Doubles& mu, const Counts& counts) {
  return {points.data(), normals.data(), mu.data(), counts.data(), static_cast<std::size_t>(counts.shape(0)),
          static_cast<std::size_t>(mu.shape(1))};
}

struct Worker {
  Scene scene;
  std::string text;  // the scene's canonical text, for the checker (certificates only)
};

// The rows 0..rows-1 through `answer(Worker&, row, Item&)` on `jobs` threads, the GIL released; `emit(row,
// Item&)` on the calling thread in row order (it takes the GIL itself when it needs Python). Windows of
// kRowsPerThread rows per thread: the threads meet once per window, and a row costs about a microsecond, so
// a small window would make every thread wait for one that the system preempted.
constexpr std::size_t kRowsPerThread = 8192;
template <class Item, class Answer, class Emit>
void map_rows(std::size_t rows, unsigned jobs, Answer answer, Emit emit) {
  py::gil_scoped_release release;
  std::size_t next = 0;
  ordered_map<std::size_t, Item, Worker>(
      jobs, [&](std::size_t& i) { return next < rows ? (i = next++, true) : false; },
      [&](Worker& w, std::size_t row, Item& out, std::size_t) { answer(w, row, out); },
      [&](std::size_t row, Item& item) { emit(row, item); }, kRowsPerThread);
}

// A status that the validated arrays cannot produce: a bug, raised as InternalError (std::runtime_error).
template <class Item>
void expect_answered(const Item& item, std::size_t row) {
  if (item.status != Status::answered && item.status != Status::undecided)
    throw std::runtime_error("row " + std::to_string(row) + ": " + item.message);
}

template <class T>
py::array_t<T> vector_of(std::size_t n) {
  return py::array_t<T>(static_cast<py::ssize_t>(n));
}

py::dict closure_arrays(const Doubles& points, const Doubles& normals, const Doubles& mu, const Counts& counts,
                        const std::string& mode, bool certificates, unsigned jobs) {
  const Contact_rows in = contact_rows(points, normals, mu, counts);
  const Request request = request_for(mode, certificates);
  auto force = vector_of<bool>(in.rows), form = vector_of<bool>(in.rows);
  auto decided = vector_of<std::int8_t>(in.rows);
  auto predicates = vector_of<std::int32_t>(in.rows), exact = vector_of<std::int32_t>(in.rows);
  bool* f = force.mutable_data();
  bool* g = form.mutable_data();
  std::int8_t* d = decided.mutable_data();
  std::int32_t* p = predicates.mutable_data();
  std::int32_t* e = exact.mutable_data();
  py::list certs;
  struct Item {
    Closure_item item;
    std::string text;
  };
  map_rows<Item>(
      in.rows, jobs,
      [&](Worker& w, std::size_t row, Item& out) {
        in.fill(w.scene, row);
        if (certificates) out.text = write_scene(w.scene);
        out.item = answer_closure(w.scene, out.text, request);
      },
      [&](std::size_t row, Item& o) {
        const Closure_item& r = o.item;
        expect_answered(r, row);
        const bool ok = r.status == Status::answered;
        f[row] = ok && r.force.holds;
        g[row] = ok && r.form.holds;
        d[row] = ok ? decided_code(r.decided_by()) : -1;
        p[row] = static_cast<std::int32_t>(r.force.predicates + r.form.predicates);
        e[row] = static_cast<std::int32_t>(r.force.exact_predicates + r.form.exact_predicates);
        if (!certificates) return;
        py::gil_scoped_acquire gil;
        if (!ok) {
          certs.append(py::none());
          return;
        }
        py::dict c;
        c["force_closure"] = r.force.holds;
        c["form_closure"] = r.form.holds;
        c["certificate"] = closure_certificate(r.force.certificate);
        c["form_certificate"] = closure_certificate(r.form.certificate);
        c["certificate_json"] = r.force_certificate;
        c["form_certificate_json"] = r.form_certificate;
        c["scene_json"] = o.text;
        certs.append(c);
      });
  py::dict out;
  out["force_closure"] = force;
  out["form_closure"] = form;
  out["decided_by"] = decided;
  out["predicates"] = predicates;
  out["exact_predicates"] = exact;
  if (certificates) out["certificates"] = certs;
  return out;
}

py::dict equilibrium_arrays(const Doubles& points, const Doubles& normals, const Doubles& mu, const Counts& counts,
                            const Doubles& loads, const std::string& mode, bool certificates, unsigned jobs) {
  const Contact_rows in = contact_rows(points, normals, mu, counts);
  const double* l = loads.data();
  const Request request = request_for(mode, certificates);
  auto balanced = vector_of<bool>(in.rows);
  auto decided = vector_of<std::int8_t>(in.rows);
  auto predicates = vector_of<std::int32_t>(in.rows), exact = vector_of<std::int32_t>(in.rows);
  bool* b = balanced.mutable_data();
  std::int8_t* d = decided.mutable_data();
  std::int32_t* p = predicates.mutable_data();
  std::int32_t* e = exact.mutable_data();
  py::list certs;
  struct Item {
    Equilibrium_item item;
    std::string text;
  };
  map_rows<Item>(
      in.rows, jobs,
      [&](Worker& w, std::size_t row, Item& out) {
        in.fill(w.scene, row);
        if (!w.scene.load) w.scene.load.emplace().kind = Load::Kind::wrench;
        Vec3q& x = w.scene.load->wrench;  // mpq_set_d: exact
        x[0] = l[3 * row];
        x[1] = l[3 * row + 1];
        x[2] = l[3 * row + 2];
        if (certificates) out.text = write_scene(w.scene);
        out.item = answer_equilibrium(w.scene, out.text, request);
      },
      [&](std::size_t row, Item& o) {
        const Equilibrium_item& r = o.item;
        expect_answered(r, row);
        const bool ok = r.status == Status::answered;
        b[row] = ok && r.answer.balanced;
        d[row] = ok ? decided_code(r.answer.decided_by()) : -1;
        p[row] = static_cast<std::int32_t>(r.answer.predicates);
        e[row] = static_cast<std::int32_t>(r.answer.exact_predicates);
        if (!certificates) return;
        py::gil_scoped_acquire gil;
        if (!ok) {
          certs.append(py::none());
          return;
        }
        py::dict c;
        c["balanced"] = r.answer.balanced;
        c["certificate"] = equilibrium_certificate(r.answer.certificate);
        c["certificate_json"] = r.certificate;
        c["scene_json"] = o.text;
        certs.append(c);
      });
  py::dict out;
  out["balanced"] = balanced;
  out["decided_by"] = decided;
  out["predicates"] = predicates;
  out["exact_predicates"] = exact;
  if (certificates) out["certificates"] = certs;
  return out;
}

py::dict stick_slide_arrays(const Doubles& points, const Doubles& forces, const Doubles& mu, const Counts& counts,
                            const Doubles& loads, int sides, const std::string& mode, bool certificates,
                            unsigned jobs) {
  const double *pt = points.data(), *fc = forces.data(), *m = mu.data(), *l = loads.data();
  const std::int64_t* n = counts.data();
  const std::size_t rows = static_cast<std::size_t>(counts.shape(0)), width = static_cast<std::size_t>(mu.shape(1));
  const Request request = request_for(mode, true);  // the motion's certificate is always checked
  Support_query q;
  q.sides = sides;
  q.polytopes = false;
  auto motion = vector_of<std::int8_t>(rows), decided = vector_of<std::int8_t>(rows);
  std::int8_t* mo = motion.mutable_data();
  std::int8_t* d = decided.mutable_data();
  py::list certs;
  struct Item {
    Support_item item;
    std::string text;
  };
  map_rows<Item>(
      rows, jobs,
      [&](Worker& w, std::size_t row, Item& out) {
        if (!w.scene.support) w.scene.support.emplace();
        std::vector<Support_point>& s = w.scene.support->points;
        s.resize(static_cast<std::size_t>(n[row]));
        for (std::size_t k = 0; k < s.size(); ++k) {
          const std::size_t c = row * width + k;
          s[k].at.x = pt[2 * c];  // mpq_set_d: exact
          s[k].at.y = pt[2 * c + 1];
          s[k].force = fc[c];
          s[k].mu = m[c];
        }
        Support_query rq = q;
        rq.load = Vec3q{Rational(l[3 * row]), Rational(l[3 * row + 1]), Rational(l[3 * row + 2])};
        out.text = write_scene(w.scene);
        out.item = answer_support(w.scene, out.text, "row " + std::to_string(row), request, rq);
      },
      [&](std::size_t row, Item& o) {
        const Support_item& r = o.item;
        expect_answered(r, row);
        const bool ok = r.status == Status::answered;
        mo[row] = ok ? motion_code(r.motion->motion) : -1;
        d[row] = ok ? motion_decided_code(r.motion->decided_by) : -1;
        if (!certificates) return;
        py::gil_scoped_acquire gil;
        py::dict c;
        c["motion"] = ok ? motion_name(r.motion->motion) : "undecided";
        c["certificate_json"] = ok ? r.certificate : std::string();
        c["uncertified"] = ok ? r.motion->uncertified : r.message;
        c["scene_json"] = o.text;
        certs.append(c);
      });
  py::dict out;
  out["motion"] = motion;
  out["motion_decided_by"] = decided;
  if (certificates) out["certificates"] = certs;
  return out;
}

// The grasp quality of each row (docs/quality.md): ε's bracket as doubles rounded outward (lower down, upper up, so
// [lower, upper] still holds ε), force closure, and with critical_mu the critical friction of closure (its bracket,
// NaN for "never", 0 for "always"); every certificate checked (the pipeline's quality item). Without certificates
// (L1), ε comes from the float twin where it certifies it ("epsilon_twin": a certified bracket about 10⁻¹⁴ wide),
// else from the exact engine.
py::dict quality_arrays(const Doubles& points, const Doubles& normals, const Doubles& mu, const Counts& counts,
                        const std::string& norm, const std::string& normalize, const std::string& mode, bool critical,
                        bool certificates, unsigned jobs) {
  const Contact_rows in = contact_rows(points, normals, mu, counts);
  const Request request = request_for(mode, certificates);
  Quality_query query;
  query.critical_mu = critical;
  query.norm = norm == "Linf" ? Quality_norm::linf : Quality_norm::l1;
  query.normalize = normalize == "unit-force" ? Force_normalization::unit_force
                    : normalize == "as-given" ? Force_normalization::as_given
                                              : Force_normalization::unit_normal;
  query.about = Vec2{};  // the origin: array rows have no centre of mass
  query.twin_first = !certificates;  // the float twin's certified bracket where it decides (no certificate asked)
  auto closed = vector_of<bool>(in.rows);
  auto lower = vector_of<double>(in.rows), upper = vector_of<double>(in.rows);
  auto mu_lo = vector_of<double>(in.rows), mu_hi = vector_of<double>(in.rows);
  auto by_twin = vector_of<bool>(in.rows);
  bool* tw = by_twin.mutable_data();
  bool* c = closed.mutable_data();
  double *lo = lower.mutable_data(), *hi = upper.mutable_data(), *ml = mu_lo.mutable_data(), *mh = mu_hi.mutable_data();
  const auto down = [](const Rational& q) { const double d = q.get_d(); return Rational(d) > q ? std::nextafter(d, -INFINITY) : d; };
  const auto up = [](const Rational& q) { const double d = q.get_d(); return Rational(d) < q ? std::nextafter(d, INFINITY) : d; };
  struct Item {
    Quality_item item;
  };
  map_rows<Item>(
      in.rows, jobs,
      [&](Worker& w, std::size_t row, Item& out) {
        in.fill(w.scene, row);
        if (certificates) w.text = write_scene(w.scene);
        out.item = answer_quality(std::move(w.scene), w.text, request, query);
        w.scene = std::move(out.item.scene);  // (back for the next row: no copy of its contacts)
      },
      [&](std::size_t row, Item& o) {
        const Quality_item& r = o.item;
        if (r.status == Status::bad_input) throw std::invalid_argument("row " + std::to_string(row) + ": " + r.message);
        if (r.status != Status::answered) throw std::runtime_error("row " + std::to_string(row) + ": " + r.message);
        c[row] = r.answer.closure.holds;
        tw[row] = r.answer.twin;
        lo[row] = down(r.answer.lower), hi[row] = up(r.answer.upper);
        ml[row] = mh[row] = NAN;
        if (r.critical && r.critical->closure.kind != Critical_kind::never) {
          const Critical_mu& m = r.critical->closure;
          ml[row] = m.kind == Critical_kind::always ? 0 : down(m.lower);
          mh[row] = m.kind == Critical_kind::always ? 0 : up(m.upper);
        }
      });
  py::dict out;
  out["force_closure"] = closed;
  out["epsilon_lower"] = lower;
  out["epsilon_upper"] = upper;
  out["epsilon_twin"] = by_twin;  // the row's ε (and closure) certified by the float twin, not the exact engine
  if (critical) out["critical_mu_lower"] = mu_lo, out["critical_mu_upper"] = mu_hi;
  return out;
}

}  // namespace

void register_arrays(py::module_& m) {
  m.def("quality_arrays", &quality_arrays);
  m.def("closure_arrays", &closure_arrays);
  m.def("equilibrium_arrays", &equilibrium_arrays);
  m.def("stick_slide_arrays", &stick_slide_arrays);
}

}  // namespace wrenchkit::python
