// The compiled part of the Python package lrsvo (apps/python/lrsvo/__init__.py
// re-exports it): lrsvo::Error becomes lrsvo.Error (a ValueError), a file's
// lrsvo::ParseError lrsvo.ParseError, with the same messages.
#include <pybind11/pybind11.h>

#include "bindings.h"
#include "lrsvo/constraints/constraint_types.h"
#include "lrsvo/edges/edge_types.h"
#include "lrsvo/graph/error.h"

namespace py = pybind11;

PYBIND11_MODULE(_lrsvo, m) {
  m.doc() = "lrsvo: graph optimisation with bounds, and long-range stereo visual odometry";
  lrsvo::registerEdgeTypes();
  lrsvo::registerConstraintTypes();

  static py::exception<lrsvo::Error> error(m, "Error", PyExc_ValueError);
  static py::exception<lrsvo::ParseError> parseError(m, "ParseError", error.ptr());
  py::register_exception_translator([](std::exception_ptr raised) {
    try {
      if (raised) std::rethrow_exception(raised);
    } catch (const lrsvo::ParseError& e) {
      parseError(e.what());
    } catch (const lrsvo::Error& e) {
      error(e.what());
    }
  });

  lrsvo::python::bindGraph(m);
  lrsvo::python::bindBal(m);
  lrsvo::python::bindMetrics(m);
  lrsvo::python::bindOdometry(m);
}
