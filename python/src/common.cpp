// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Checked NumPy arguments and the progress bridge (see common.h).

#include "common.h"

#include <cmath>
#include <sstream>

namespace mdcs_python {

std::string shape_text(const py::array& a)
{
  std::ostringstream s;
  s << '(';
  for(py::ssize_t i = 0; i < a.ndim(); ++i) {
    if(i > 0) s << ", ";
    s << a.shape(i);
  }
  if(a.ndim() == 1) s << ',';
  s << ')';
  return s.str();
}

namespace {

py::array as_array(py::handle object, const char* name, const char* what)
{
  if(object.is_none())
    throw Value_error(std::string("mdcs: ") + name + " is None; expected " + what);
  py::array a = py::array::ensure(object);
  if(!a)
    throw Value_error(std::string("mdcs: ") + name + " cannot be read as an array (ragged nested lists or "
                      "non-numeric entries?); expected " + what);
  return a;
}

std::string dtype_text(const py::array& a) { return py::str(a.dtype()).cast<std::string>(); }

void check_shape(const py::array& a, const char* name, int ndim, py::ssize_t columns, const char* shape_hint)
{
  const bool bad_columns = ndim == 2 && columns >= 0 && a.ndim() == 2 && a.shape(1) != columns;
  if(a.ndim() != ndim || bad_columns) {
    std::string message = std::string("mdcs: ") + name + " must have shape " + shape_hint + ", got shape " + shape_text(a);
    if(bad_columns && columns == 3 && std::string(name).find("faces") != std::string::npos)
      message += " (only triangle faces are supported: triangulate polygons first)";
    throw Value_error(message);
  }
}

std::string entry_text(const char* name, py::ssize_t flat, int ndim, py::ssize_t columns)
{
  std::ostringstream s;
  if(ndim == 2 && columns > 0) s << name << '[' << flat / columns << ", " << flat % columns << ']';
  else s << name << '[' << flat << ']';
  return s.str();
}

} // namespace

Double_array checked_doubles(py::handle object, const char* name, int ndim, py::ssize_t columns, bool finite,
                             const char* shape_hint)
{
  const std::string what = std::string("a float array of shape ") + shape_hint;
  py::array a = as_array(object, name, what.c_str());
  const char kind = a.dtype().kind();
  if(kind != 'f' && kind != 'i' && kind != 'u')
    throw Value_error(std::string("mdcs: ") + name + " must be " + what + " (float or integer dtype), got dtype " +
                      dtype_text(a));
  check_shape(a, name, ndim, columns, shape_hint);
  Double_array d = Double_array::ensure(a);
  if(!d) throw Value_error(std::string("mdcs: ") + name + " cannot be converted to float64");
  if(finite) {
    const double* p = d.data();
    const py::ssize_t n = d.size();
    const py::ssize_t cols = ndim == 2 ? d.shape(1) : 1;
    for(py::ssize_t i = 0; i < n; ++i)
      if(!std::isfinite(p[i]))
        throw Value_error("mdcs: " + entry_text(name, i, ndim, cols) + " is " + (std::isnan(p[i]) ? "NaN" : "infinite") +
                          "; every value of " + name + " must be finite");
  }
  return d;
}

Index_array checked_indices(py::handle object, const char* name, int ndim, py::ssize_t columns, std::int64_t upper,
                            const char* shape_hint, const char* upper_name)
{
  const std::string what = std::string("an integer array of shape ") + shape_hint;
  py::array a = as_array(object, name, what.c_str());
  const char kind = a.dtype().kind();
  // An empty list becomes an empty float64 array in NumPy: no index, no dtype problem.
  const bool empty_numbers = a.size() == 0 && kind == 'f';
  if(kind != 'i' && kind != 'u' && !empty_numbers) {
    std::string message = std::string("mdcs: ") + name + " must be " + what + ", got dtype " + dtype_text(a);
    if(kind == 'f') message += " (convert it with .astype(int) if its values are whole numbers)";
    throw Value_error(message);
  }
  check_shape(a, name, ndim, columns, shape_hint);
  if(kind == 'u' && a.itemsize() == 8 && a.size() > 0) {
    // uint64 values above 2^63 would wrap to negative int64 values below.
    const std::uint64_t largest = a.attr("max")().cast<std::uint64_t>();
    if(largest > std::uint64_t(INT64_MAX))
      throw Index_error(std::string("mdcs: ") + name + " holds the index " + std::to_string(largest) + ", out of range");
  }
  Index_array d = Index_array::ensure(a);
  if(!d) throw Value_error(std::string("mdcs: ") + name + " cannot be converted to int64");
  if(upper >= 0) {
    const std::int64_t* p = d.data();
    const py::ssize_t n = d.size();
    const py::ssize_t cols = ndim == 2 ? d.shape(1) : 1;
    for(py::ssize_t i = 0; i < n; ++i)
      if(p[i] < 0 || p[i] >= upper)
        throw Index_error("mdcs: " + entry_text(name, i, ndim, cols) + " = " + std::to_string(p[i]) +
                          " is out of range: there are " + std::to_string(upper) + " " + upper_name +
                          " (valid indices 0.." + std::to_string(upper - 1) + ")");
  }
  return d;
}

std::int64_t checked_index(py::handle object, const char* name, std::int64_t upper, const char* upper_name)
{
  if(py::isinstance<py::array>(object) && py::reinterpret_borrow<py::array>(object).ndim() == 0)
    return checked_index(object.attr("item")(), name, upper, upper_name);
  if(PyBool_Check(object.ptr()) || py::isinstance<py::array>(object) || !PyIndex_Check(object.ptr()))
    throw Value_error(std::string("mdcs: ") + name + " must be an integer index, got " +
                      py::str(py::type::of(object)).cast<std::string>());
  PyObject* index = PyNumber_Index(object.ptr());
  if(index == nullptr) {
    PyErr_Clear();
    throw Value_error(std::string("mdcs: ") + name + " must be an integer index");
  }
  long long i = PyLong_AsLongLong(index);
  Py_DECREF(index);
  if(i == -1 && PyErr_Occurred()) {
    PyErr_Clear();
    throw Index_error(std::string("mdcs: ") + name + " is out of range: there are " + std::to_string(upper) + " " +
                      upper_name);
  }
  if(i < 0 || i >= upper)
    throw Index_error(std::string("mdcs: ") + name + " = " + std::to_string(i) + " is out of range: there are " +
                      std::to_string(upper) + " " + upper_name);
  return std::int64_t(i);
}

std::vector<std::int64_t> checked_index_list(py::handle object, const char* name, std::int64_t upper,
                                             const char* upper_name)
{
  const bool zero_d = py::isinstance<py::array>(object) && py::reinterpret_borrow<py::array>(object).ndim() == 0;
  if(zero_d || (!object.is_none() && !PyBool_Check(object.ptr()) && !py::isinstance<py::array>(object) &&
                PyIndex_Check(object.ptr())))
    return {checked_index(object, name, upper, upper_name)};
  Index_array a = checked_indices(object, name, 1, -1, upper, "(k,)", upper_name);
  return std::vector<std::int64_t>(a.data(), a.data() + a.size());
}

double checked_number(py::handle object, const char* name, double low, bool strict)
{
  double x = 0;
  try {
    if(PyBool_Check(object.ptr())) throw py::cast_error();
    x = py::float_(py::reinterpret_borrow<py::object>(object)).cast<double>();
  } catch(const py::error_already_set&) {
    throw Value_error(std::string("mdcs: ") + name + " must be a number");
  } catch(const py::cast_error&) {
    throw Value_error(std::string("mdcs: ") + name + " must be a number");
  }
  if(!std::isfinite(x) || x < low || (strict && x == low)) {
    std::ostringstream s;
    s.precision(17);
    s << "mdcs: " << name << " must be a finite number " << (strict ? "> " : ">= ") << low << ", got " << x;
    throw Value_error(s.str());
  }
  return x;
}

double number_or(py::handle object, const char* name, double none_value, double low, bool strict)
{
  if(object.is_none()) return none_value;
  return checked_number(object, name, low, strict);
}

std::size_t checked_thread_count(py::handle object)
{
  const char* what = "mdcs: threads must be an integer from 0 (every hardware thread) to 1024";
  if(PyBool_Check(object.ptr()) || !PyIndex_Check(object.ptr())) throw Value_error(what);
  long long n = 0;
  try {
    n = py::reinterpret_borrow<py::object>(object).cast<long long>();
  } catch(const py::cast_error&) {
    throw Value_error(what); // beyond long long
  }
  if(n < 0 || n > 1024) throw Value_error(std::string(what) + ", got " + std::to_string(n));
  return std::size_t(n);
}

// ---------------------------------------------------------------------------------------------------------------

Progress_bridge::Progress_bridge(py::object callback, double interval_seconds)
  : callback_(std::move(callback)),
    interval_(std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(interval_seconds))),
    last_(std::chrono::steady_clock::now())
{
  if(callback_.is_none()) callback_ = py::object();
}

Progress_bridge::~Progress_bridge()
{
  // Destroyed in the binding code, with the GIL held.
  Py_XDECREF(type_);
  Py_XDECREF(value_);
  Py_XDECREF(traceback_);
}

bool Progress_bridge::operator()(const char* stage, double fraction)
{
  if(stopped_) return false;
  // Most reports are skipped without touching the GIL: the library reports about a hundred times per stage, and a
  // check every few hundredths of a second keeps Ctrl-C responsive at no measurable cost.
  const auto now = std::chrono::steady_clock::now();
  const bool stage_changed = last_stage_ != stage;
  const bool last_of_stage = fraction >= 1.0 && callback_;
  if(!stage_changed && !last_of_stage && now - last_ < interval_) return true;
  last_ = now;
  if(stage_changed) last_stage_ = stage;

  py::gil_scoped_acquire gil;
  if(PyErr_CheckSignals() != 0) {
    PyErr_Fetch(&type_, &value_, &traceback_);
    stopped_ = true;
    return false;
  }
  if(!callback_) return true;
  PyObject* result = PyObject_CallFunction(callback_.ptr(), "sd", stage, fraction);
  if(result == nullptr) {
    PyErr_Fetch(&type_, &value_, &traceback_);
    stopped_ = true;
    return false;
  }
  // None and True continue; False (or anything falsy but None) cancels.
  const bool keep_going = result == Py_None || PyObject_IsTrue(result) != 0;
  Py_DECREF(result);
  if(!keep_going) stopped_ = true;
  return keep_going;
}

void Progress_bridge::raise_stashed_error()
{
  if(type_ == nullptr) return;
  PyErr_Restore(type_, value_, traceback_); // steals the references
  type_ = value_ = traceback_ = nullptr;
  throw py::error_already_set();
}

} // namespace mdcs_python
