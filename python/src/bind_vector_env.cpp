// VectorEnv with zero-copy numpy outputs, for accsim.vector.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <nlohmann/json.hpp>

#include "accsim/env/vector_env.h"
#include "accsim/scenarios/suite_generator.h"
#include "bindings.h"

namespace py = pybind11;

namespace accsim::python {
namespace {

// A numpy view of a buffer owned by the VectorEnv; `owner` (the Python
// wrapper of the VectorEnv) becomes the array's base, so the env lives as
// long as any view does. The core only writes these buffers (it never reads
// them back), so a caller writing into a view cannot disturb a simulation;
// the views of read-only accessors are still marked read-only.
template <typename T>
py::array View(T* data, std::vector<py::ssize_t> shape, py::handle owner) {
  return py::array(py::dtype::of<T>(), std::move(shape), data, owner);
}

template <typename T>
py::array ReadOnlyView(const T* data, std::vector<py::ssize_t> shape, py::handle owner) {
  py::array a(py::dtype::of<T>(), std::move(shape), data, owner);
  a.attr("flags").attr("writeable") = false;
  return a;
}

std::string ShapeString(const py::array& a) {
  std::string shape;
  for (py::ssize_t d = 0; d < a.ndim(); ++d) shape += (d ? ", " : "") + std::to_string(a.shape(d));
  return "(" + shape + (a.ndim() == 1 ? ",)" : ")");
}

}  // namespace

void DefineVectorEnv(py::module_& m) {
  py::class_<VectorEnv>(m, "VectorEnv", "N CrashEnvs stepped on a C++ thread pool")
      .def(py::init([](int num_envs, const std::vector<std::string>& scenarios, const std::string& config_yaml,
                       const std::string& config_json, int num_threads, bool same_step) {
             return std::make_unique<VectorEnv>(num_envs, LoadConfig(config_yaml, config_json),
                                                LoadScenarioSet(scenarios), num_threads,
                                                same_step ? AutoresetMode::kSameStep : AutoresetMode::kNextStep);
           }),
           py::arg("num_envs"), py::arg("scenarios"), py::arg("config_yaml") = "", py::arg("config_json") = "",
           py::arg("num_threads") = 0, py::arg("same_step") = false)
      .def_property_readonly("num_envs", &VectorEnv::num_envs)
      .def_property_readonly("num_threads", &VectorEnv::num_threads)
      .def_property_readonly("spec", &VectorEnv::spec, py::return_value_policy::reference_internal)
      .def_property_readonly("same_step",
                             [](const VectorEnv& v) { return v.autoreset_mode() == AutoresetMode::kSameStep; })
      .def(
          "reset",
          [](VectorEnv& v, std::optional<uint64_t> seed) {
            py::gil_scoped_release release;
            v.Reset(seed);
          },
          py::arg("seed") = py::none())
      .def(
          "reset_each",
          [](VectorEnv& v, const std::vector<uint64_t>& seeds) {
            py::gil_scoped_release release;
            v.Reset(seeds);
          },
          py::arg("seeds"), "Resets environment i with seeds[i]")
      .def(
          "step",
          [](VectorEnv& v, py::array actions_in) {
            // Validate with the GIL held: shape and dtype here, finiteness in C++.
            if (actions_in.ndim() != 2 || actions_in.shape(0) != v.num_envs() ||
                actions_in.shape(1) != v.spec().action_dim) {
              throw py::value_error("actions: expected shape (" + std::to_string(v.num_envs()) + ", " +
                                    std::to_string(v.spec().action_dim) + "), got " + ShapeString(actions_in));
            }
            const char kind = actions_in.dtype().kind();
            if (kind != 'f' && kind != 'i' && kind != 'u') {
              throw py::value_error("actions: expected a numeric array, got dtype " +
                                    std::string(py::str(actions_in.dtype())));
            }
            auto actions = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(actions_in);
            const float* data = actions.data();
            const size_t size = static_cast<size_t>(actions.size());
            py::gil_scoped_release release;
            v.Step(data, size);
          },
          py::arg("actions"))
      .def_property_readonly("observations",
                             [](py::object self) {
                               auto& v = self.cast<VectorEnv&>();
                               return View(v.observations(), {v.num_envs(), v.spec().obs_dim}, self);
                             })
      .def_property_readonly("final_observations",
                             [](py::object self) {
                               const auto& v = self.cast<const VectorEnv&>();
                               return ReadOnlyView(v.final_observations(), {v.num_envs(), v.spec().obs_dim}, self);
                             })
      .def_property_readonly("rewards",
                             [](py::object self) {
                               const auto& v = self.cast<const VectorEnv&>();
                               return ReadOnlyView(v.rewards(), {v.num_envs()}, self);
                             })
      .def_property_readonly("reward_terms",
                             [](py::object self) {
                               const auto& v = self.cast<const VectorEnv&>();
                               return ReadOnlyView(v.reward_terms(), {v.num_envs(), kNumRewardTerms}, self);
                             })
      .def_property_readonly("terminated",
                             [](py::object self) {
                               const auto& v = self.cast<const VectorEnv&>();
                               return ReadOnlyView(v.terminated(), {v.num_envs()}, self);
                             })
      .def_property_readonly("truncated",
                             [](py::object self) {
                               const auto& v = self.cast<const VectorEnv&>();
                               return ReadOnlyView(v.truncated(), {v.num_envs()}, self);
                             })
      .def(
          "final_info", [](const VectorEnv& v, int i) { return StepInfoDict(v.final_info(i)); }, py::arg("index"),
          "Info dict of environment `index`'s last episode-ending step");
}

}  // namespace accsim::python
