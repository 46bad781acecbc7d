// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Shared pieces of the Python module: checked conversion of NumPy arguments (dtype, shape, contiguity, finite values,
// index ranges) with messages that name the argument, the bridge from the library's progress callbacks to Python
// (signals, a user callback, cancellation), and running a computation with the GIL released.

#ifndef MDCS_PYTHON_COMMON_H
#define MDCS_PYTHON_COMMON_H

#include <CGAL/MDCS/progress.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace mdcs_python {

namespace py = pybind11;

/// Raised (as mdcs.OperationCancelled) when a progress callback returned False.
class Cancelled_error : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// Raised as IndexError: an index argument is out of range.
class Index_error : public std::out_of_range
{
public:
  using std::out_of_range::out_of_range;
};

/// Raised as ValueError.
class Value_error : public std::invalid_argument
{
public:
  using std::invalid_argument::invalid_argument;
};

typedef py::array_t<double, py::array::c_style | py::array::forcecast> Double_array;
typedef py::array_t<std::int64_t, py::array::c_style | py::array::forcecast> Index_array;

/// "(3, 4)" for an array's shape.
std::string shape_text(const py::array& a);

/// A real-valued array with `ndim` dimensions (and `columns` columns when `columns >= 0` and ndim == 2), converted
/// to a C-contiguous float64 array (a copy when the input is another dtype or not contiguous). Integer and float
/// dtypes are accepted; anything else (bool, complex, object, strings) raises ValueError. With `finite`, NaN and
/// infinite values raise ValueError naming the first such entry.
Double_array checked_doubles(py::handle object, const char* name, int ndim, py::ssize_t columns, bool finite,
                             const char* shape_hint);

/// An integer array with `ndim` dimensions (and `columns` columns when ndim == 2 and columns >= 0), converted to a
/// C-contiguous int64 array. Float, bool and other dtypes raise ValueError. Entries outside [0, upper) raise
/// IndexError naming the entry (no check when upper < 0).
Index_array checked_indices(py::handle object, const char* name, int ndim, py::ssize_t columns, std::int64_t upper,
                            const char* shape_hint, const char* upper_name);

/// A scalar index in [0, upper), or IndexError / ValueError (not an integer).
std::int64_t checked_index(py::handle object, const char* name, std::int64_t upper, const char* upper_name);

/// Indices given as one integer or a 1-D integer array: a vector in [0, upper).
std::vector<std::int64_t> checked_index_list(py::handle object, const char* name, std::int64_t upper,
                                             const char* upper_name);

/// A finite number >= `low` (or > low when `strict`), or ValueError.
double checked_number(py::handle object, const char* name, double low, bool strict);

/// A number that may be None (returns `none_value`).
double number_or(py::handle object, const char* name, double none_value, double low, bool strict);

/// A thread count: an integer in [0, 1024] (0: every hardware thread; the command-line tool's range), or
/// ValueError.
std::size_t checked_thread_count(py::handle object);

/*!
  The progress callback handed to the library's algorithms (signature `bool(const char* stage, double fraction)`).
  It is called without the GIL; it takes the GIL at most every `interval` (and for the last report of a stage),
  checks for signals (Ctrl-C) and calls the Python callback `callback(stage, fraction)` if one was given; when a
  signal is pending, the callback raises, or it returns False, it returns false, which makes the algorithm throw
  `CGAL::MDCS::Operation_cancelled`. `run_without_gil()` then raises the Python error (KeyboardInterrupt, the
  callback's exception) or mdcs.OperationCancelled.
*/
class Progress_bridge
{
public:
  explicit Progress_bridge(py::object callback, double interval_seconds = 0.03);
  ~Progress_bridge();
  Progress_bridge(const Progress_bridge&) = delete;
  Progress_bridge& operator=(const Progress_bridge&) = delete;

  bool operator()(const char* stage, double fraction);

  /// With the GIL held: raises the stashed Python error, if any (as pybind11::error_already_set).
  void raise_stashed_error();
  bool has_stashed_error() const { return type_ != nullptr; }
  /// Whether a report returned false (a signal, the callback's exception, or the callback's False).
  bool stopped() const { return stopped_; }

private:
  py::object callback_;
  std::chrono::steady_clock::duration interval_;
  std::chrono::steady_clock::time_point last_;
  std::string last_stage_;
  bool stopped_ = false;
  PyObject* type_ = nullptr;
  PyObject* value_ = nullptr;
  PyObject* traceback_ = nullptr;
};

/// Runs `work()` with the GIL released. Operation_cancelled becomes the stashed Python error (KeyboardInterrupt
/// after Ctrl-C, the callback's own exception) or mdcs.OperationCancelled; other C++ exceptions propagate to
/// pybind11's translators (ValueError, IndexError, RuntimeError, MemoryError).
template <class Work>
auto run_without_gil(Progress_bridge& progress, Work&& work) -> decltype(work())
{
  try {
    py::gil_scoped_release release;
    return work();
  } catch(const CGAL::MDCS::Operation_cancelled& e) {
    progress.raise_stashed_error();
    throw Cancelled_error(e.what());
  }
}

/// A 1-D NumPy array that takes over `values` (no copy).
template <class T>
py::array_t<T> to_numpy(std::vector<T>&& values)
{
  auto* owned = new std::vector<T>(std::move(values));
  py::capsule free_when_done(owned, [](void* p) { delete reinterpret_cast<std::vector<T>*>(p); });
  return py::array_t<T>({py::ssize_t(owned->size())}, {py::ssize_t(sizeof(T))}, owned->data(), free_when_done);
}

/// A 2-D C-contiguous NumPy array of `rows` x `columns` that takes over `values` (row-major, no copy).
template <class T>
py::array_t<T> to_numpy(std::vector<T>&& values, py::ssize_t rows, py::ssize_t columns)
{
  if(py::ssize_t(values.size()) != rows * columns)
    throw std::logic_error("mdcs: internal error: array size does not match its shape");
  auto* owned = new std::vector<T>(std::move(values));
  py::capsule free_when_done(owned, [](void* p) { delete reinterpret_cast<std::vector<T>*>(p); });
  return py::array_t<T>({rows, columns}, {py::ssize_t(sizeof(T)) * columns, py::ssize_t(sizeof(T))}, owned->data(),
                        free_when_done);
}

// Registration of each package's bindings (one translation unit per package).
void bind_geodesics(py::module_& m);
void bind_mwt(py::module_& m);
void bind_variational_curves(py::module_& m);
void bind_variational_surfaces(py::module_& m);
void bind_silhouettes(py::module_& m);
void bind_min_cut(py::module_& m);
void bind_io(py::module_& m);
void bind_reference(py::module_& m);

} // namespace mdcs_python

#endif // MDCS_PYTHON_COMMON_H
