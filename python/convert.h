// The bindings' shared pieces (python/): exact values and certificates as Python objects (defined in
// wrenchkit_module.cpp), and the registration of the array API (arrays.cpp) and of the streaming batch
// (batch.cpp) on the module `wrenchkit._core`.
#pragma once

#include <pybind11/pybind11.h>

#include "exact/numbers/rational.h"
#include "exact/statics/closure.h"
#include "exact/statics/equilibrium.h"

namespace wrenchkit::python {

namespace py = pybind11;

// A rational as fractions.Fraction; a certificate as the dict wrenchkit.closure / equilibrium return.
py::object fraction(const Rational& q);
py::dict closure_certificate(const Closure_certificate& c);
py::dict equilibrium_certificate(const Equilibrium_certificate& c);

// arrays.cpp: _core.closure_arrays, equilibrium_arrays, stick_slide_arrays (NumPy in, NumPy out).
void register_arrays(py::module_& m);
// batch.cpp: _core.batch (JSON lines in, the lines of `wrenchkit batch COMMAND` out).
void register_batch(py::module_& m);

}  // namespace wrenchkit::python
