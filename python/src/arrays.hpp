// numpy arrays that view a run's own storage (no copy): a field of every element of a vector of
// structs (a strided view), a vector of doubles, an Eigen vector. Each array's base is a capsule that
// holds the run's results, so the storage lives as long as any array of it. The arrays are read-only:
// the results are shared by every array and typed result of the run.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "core/types.hpp"

namespace drillflex::python {

// The base of a run's arrays: a capsule holding a reference to its results.
inline py::capsule ResultOwner(const RunHandle& run) {
  auto* owner = new std::shared_ptr<const pipeline::CaseResults>(run.results);
  return py::capsule(owner, [](void* pointer) { delete static_cast<std::shared_ptr<const pipeline::CaseResults>*>(pointer); });
}

// Adds run.<name>(): None when the run did not compute the result `member`, else the dict
// `fields(run, result, owner)` makes of it (owner: the base of its arrays).
template <class Result, class Fields>
void DefFields(py::class_<RunHandle>& run, const char* name, std::optional<Result> pipeline::CaseResults::*member,
               Fields fields) {
  run.def(name, [member, fields](const RunHandle& self) -> py::object {
    const std::optional<Result>& result = (*self.results).*member;
    if (!result) return py::none();
    return fields(self, *result, ResultOwner(self));
  });
}

// A read-only array of `shape` with `strides` (bytes) at `data`, owned by `owner`; an empty one when
// there is nothing to view.
template <class V>
py::array View(std::vector<py::ssize_t> shape, std::vector<py::ssize_t> strides, const V* data, const py::capsule& owner) {
  for (const py::ssize_t extent : shape) {
    if (extent == 0) return py::array_t<V>(shape);
  }
  py::array array = py::array_t<V>(std::move(shape), std::move(strides), data, owner);
  array.attr("setflags")(py::arg("write") = false);
  return array;
}

inline py::ssize_t Offset(const void* from, const void* to) {
  return static_cast<const char*>(to) - static_cast<const char*>(from);
}

// `field` of every element of `items`: shape (n,) for a number, (n, 3) for a Vec3.
template <class T, class V>
py::array FieldView(const std::vector<T>& items, V T::*field, const py::capsule& owner) {
  const auto n = static_cast<py::ssize_t>(items.size());
  const auto stride = static_cast<py::ssize_t>(sizeof(T));
  if constexpr (std::is_same_v<V, Vec3>) {
    const double* data = items.empty() ? nullptr : (items.front().*field).data();
    return View<double>({n, 3}, {stride, sizeof(double)}, data, owner);
  } else {
    return View<V>({n}, {stride}, items.empty() ? nullptr : &(items.front().*field), owner);
  }
}

inline py::array VectorView(const std::vector<double>& values, const py::capsule& owner) {
  return View<double>({static_cast<py::ssize_t>(values.size())}, {sizeof(double)}, values.data(), owner);
}

inline py::array VectorView(const VecX& values, const py::capsule& owner) {
  return View<double>({static_cast<py::ssize_t>(values.size())}, {sizeof(double)}, values.data(), owner);
}

// A list of Vec3 as an (n, 3) array.
inline py::array Vec3View(const std::vector<Vec3>& values, const py::capsule& owner) {
  return View<double>({static_cast<py::ssize_t>(values.size()), 3}, {sizeof(Vec3), sizeof(double)},
                      values.empty() ? nullptr : values.front().data(), owner);
}

// A copy into a new array: for what the results do not hold as one block (a table of samples' lists).
inline py::array_t<double> Matrix(std::size_t rows, std::size_t columns) {
  return py::array_t<double>({static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(columns)});
}

}  // namespace drillflex::python
