#pragma once
// numpy arrays over memory the module already holds (zero copy), read-only, that keep their
// owner alive through numpy's base object.

#include <cstddef>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

namespace oasis::python {

template <typename T>
pybind11::array_t<T> view(const T* data, std::size_t size, const pybind11::handle& owner) {
  pybind11::array_t<T> array({size}, {sizeof(T)}, data, owner);
  pybind11::detail::array_proxy(array.ptr())->flags &=
      ~pybind11::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return array;
}

template <typename T>
pybind11::array_t<T> view(const T* data, std::size_t rows, std::size_t columns,
                          const pybind11::handle& owner) {
  pybind11::array_t<T> array({rows, columns}, {sizeof(T) * columns, sizeof(T)}, data, owner);
  pybind11::detail::array_proxy(array.ptr())->flags &=
      ~pybind11::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return array;
}

// A new array that owns `values` (moved into a capsule, no copy of the elements).
template <typename T>
pybind11::array_t<T> owned(std::vector<T>&& values) {
  auto* held = new std::vector<T>(std::move(values));
  const pybind11::capsule owner(
      held, [](void* pointer) { delete static_cast<std::vector<T>*>(pointer); });
  return pybind11::array_t<T>({held->size()}, {sizeof(T)}, held->data(), owner);
}

}  // namespace oasis::python
