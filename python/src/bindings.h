// One Define function per concern; each only converts and forwards.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

#include "accsim/env/crash_env.h"

namespace accsim::python {

// Config from a YAML path or a JSON string (Python dicts arrive as JSON).
CrashEnvConfig LoadConfig(const std::string& yaml_path, const std::string& json_text);

// A StepInfo as the Python info dict (reward terms, collision details,
// episode statistics).
pybind11::dict StepInfoDict(const StepInfo& info);

void DefineEnv(pybind11::module_& m);
void DefineVectorEnv(pybind11::module_& m);

}  // namespace accsim::python
