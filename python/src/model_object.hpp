#pragma once
// The Python `Model`: an explicit model of the compiler (model/explicit_model.hpp), immutable
// once built, with what properties need to read it (a PRISM program's names).

#include <memory>
#include <string>

#include <pybind11/pybind11.h>

#include "model/explicit_model.hpp"
#include "property/evaluator.hpp"

namespace oasis::python {

struct ModelObject {
  model::ExplicitModel model;
  property::Names names;  // a PRISM program's constants, formulas and variables
  std::string path;       // the file it was read from, or "" for a quotient
};

using ModelPointer = std::shared_ptr<ModelObject>;

// The context named or numbered by `context` (an int or a str); ValueError otherwise.
std::size_t context_index(const model::ExplicitModel& model, const pybind11::handle& context);

// fractions.Fraction of an exact rational.
pybind11::object fraction(const Rational& value);

void bind_model(pybind11::module_& module);

}  // namespace oasis::python
