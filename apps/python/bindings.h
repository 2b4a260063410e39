#pragma once

#include <pybind11/pybind11.h>

// The parts of the Python module lrsvo._lrsvo, one per source file.
namespace lrsvo::python {

void bindGraph(pybind11::module_& m);
void bindBal(pybind11::module_& m);
void bindMetrics(pybind11::module_& m);
void bindOdometry(pybind11::module_& m);

}  // namespace lrsvo::python
