#include "bindings.h"

PYBIND11_MODULE(_core, m) {
  m.doc() = "accsim C++ core: crash environments, batched environments, renderer";
  accsim::python::DefineEnv(m);
  accsim::python::DefineVectorEnv(m);
}
