// One Define function per concern; each only converts and forwards.
#pragma once

#include <pybind11/pybind11.h>

namespace accsim::python {

void DefineEnv(pybind11::module_& m);
void DefineVectorEnv(pybind11::module_& m);

}  // namespace accsim::python
