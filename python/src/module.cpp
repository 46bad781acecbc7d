// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The extension module mdcs._mdcs: one submodule per package (each bound in its own translation unit), the
// exception types, and what the module was built with.

#include "common.h"

#include <CGAL/MDCS/concurrency.h>
#include <CGAL/version.h>

#ifndef MDCS_VERSION
#define MDCS_VERSION "0.0.0"
#endif

namespace py = pybind11;

PYBIND11_MODULE(_mdcs, m)
{
  namespace mp = mdcs_python;
  m.doc() = "C++ core of the mdcs package (pybind11 bindings of the MDCS library); use the mdcs package itself.";
  m.attr("__version__") = MDCS_VERSION;
  m.attr("cgal_version") = CGAL_VERSION_STR;
  m.attr("has_tbb") = CGAL::MDCS::has_parallel_support();
  m.attr("hardware_threads") = CGAL::MDCS::hardware_threads();

  static py::exception<mp::Cancelled_error> cancelled(m, "OperationCancelled", PyExc_RuntimeError);
  cancelled.doc() = "A computation was cancelled by its progress callback (the callback returned False).";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if(p) std::rethrow_exception(p);
    } catch(const mp::Cancelled_error& e) {
      cancelled(e.what());
    } catch(const CGAL::MDCS::Operation_cancelled& e) {
      cancelled(e.what());
    } catch(const mp::Index_error& e) {
      PyErr_SetString(PyExc_IndexError, e.what());
    }
  });

  mp::bind_geodesics(m);
  mp::bind_mwt(m);
  mp::bind_variational_curves(m); // before the surfaces: it creates the submodule
  mp::bind_variational_surfaces(m);
  mp::bind_silhouettes(m);
  mp::bind_min_cut(m);
  mp::bind_io(m);
  mp::bind_reference(m);
}
