// CrashEnv, its spec and the renderer, for accsim.env.CrashEnv.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <nlohmann/json.hpp>

#include "accsim/env/crash_env.h"
#include "accsim/env/renderer.h"
#include "accsim/scenarios/suite_generator.h"
#include "bindings.h"

namespace py = pybind11;

namespace accsim::python {
namespace {

py::dict InfoDict(const CrashEnv& env) {
  py::dict d = StepInfoDict(env.info());
  d["scenario"] = env.scenario().name;
  return d;
}

py::array_t<float> ObsCopy(const CrashEnv& env) {
  py::array_t<float> a(env.spec().obs_dim);
  env.CopyObservation(a.mutable_data());
  return a;
}

}  // namespace

py::dict StepInfoDict(const StepInfo& i) {
  py::dict terms;
  for (int t = 0; t < kNumRewardTerms; ++t) terms[RewardTermName(t)] = i.reward_terms[static_cast<size_t>(t)];
  py::dict d;
  d["reward_terms"] = terms;
  d["collision"] = i.ego_collision.has_value();
  if (i.ego_collision) {
    const CollisionInfo& c = *i.ego_collision;
    py::dict cd;
    cd["time"] = c.time;
    cd["other"] = c.other_id;
    cd["point"] = py::make_tuple(c.point.x(), c.point.y());
    cd["impulse"] = c.impulse;
    cd["relative_speed"] = c.relative_speed;
    cd["closing_speed"] = c.closing_speed;
    d["collision_info"] = cd;
  }
  d["off_road"] = i.off_road;
  d["goal"] = i.goal;
  d["time_limit"] = i.time_limit;
  d["time"] = i.time;
  d["route_progress"] = i.route_progress;
  d["route_length"] = i.route_length;
  d["min_ttc"] = i.min_ttc;
  d["npc_contacts"] = i.npc_contacts;
  d["clipped_actions"] = i.clipped_actions;
  d["episode_steps"] = i.episode_steps;
  d["episode_return"] = i.episode_return;
  d["scenario_index"] = i.scenario_index;
  return d;
}

CrashEnvConfig LoadConfig(const std::string& yaml_path, const std::string& json_text) {
  if (!yaml_path.empty()) return LoadCrashEnvConfig(yaml_path);
  if (json_text.empty()) return CrashEnvConfig{};
  try {
    return CrashEnvConfigFromJson(nlohmann::json::parse(json_text));
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(std::string("config: ") + e.what());
  }
}

void DefineEnv(py::module_& m) {
  py::class_<EnvSpec>(m, "EnvSpec", "Observation and action layout derived from a config")
      .def_readonly("obs_dim", &EnvSpec::obs_dim)
      .def_readonly("action_dim", &EnvSpec::action_dim)
      .def_readonly("obs_low", &EnvSpec::obs_low)
      .def_readonly("obs_high", &EnvSpec::obs_high)
      .def_readonly("action_low", &EnvSpec::action_low)
      .def_readonly("action_high", &EnvSpec::action_high)
      .def_readonly("obs_names", &EnvSpec::obs_names)
      .def_readonly("obs_units", &EnvSpec::obs_units)
      .def_readonly("action_names", &EnvSpec::action_names)
      .def_readonly("reward_terms", &EnvSpec::reward_terms)
      .def_readonly("policy_dt", &EnvSpec::policy_dt)
      .def_readonly("substeps", &EnvSpec::substeps);

  py::class_<CrashEnv>(m, "CrashEnv", "One ego vehicle through a reconstructed crash (C++ core)")
      .def(py::init([](const std::vector<std::string>& scenarios, const std::string& config_yaml,
                       const std::string& config_json) {
             return std::make_unique<CrashEnv>(LoadConfig(config_yaml, config_json), LoadScenarioSet(scenarios));
           }),
           py::arg("scenarios"), py::arg("config_yaml") = "", py::arg("config_json") = "")
      .def_property_readonly("spec", &CrashEnv::spec, py::return_value_policy::reference_internal)
      .def_property_readonly("num_scenarios", &CrashEnv::num_scenarios)
      .def(
          "reset",
          [](CrashEnv& env, std::optional<uint64_t> seed, int scenario_index) {
            {
              py::gil_scoped_release release;
              env.Reset(seed, scenario_index);
            }
            return py::make_tuple(ObsCopy(env), InfoDict(env));
          },
          py::arg("seed") = py::none(), py::arg("scenario_index") = -1)
      .def(
          "step",
          [](CrashEnv& env, py::array_t<float, py::array::c_style | py::array::forcecast> action) {
            if (action.ndim() != 1 || action.shape(0) != env.spec().action_dim) {
              throw py::value_error("action: expected shape (" + std::to_string(env.spec().action_dim) +
                                    ",), got " + std::to_string(action.ndim()) + "-d array of " +
                                    std::to_string(action.size()) + " values");
            }
            {
              py::gil_scoped_release release;
              env.Step(action.data(), static_cast<size_t>(action.size()));
            }
            return py::make_tuple(ObsCopy(env), env.reward(), env.terminated(), env.truncated(), InfoDict(env));
          },
          py::arg("action"))
      .def_property_readonly("time", &CrashEnv::time);

  py::class_<Renderer>(m, "Renderer", "Top-down RGB frames of an environment")
      .def(py::init([](int width, int height, const std::string& camera, double metres_per_pixel) {
             RenderOptions o;
             o.width = width;
             o.height = height;
             o.camera = CameraModeFromString(camera);
             o.metres_per_pixel = metres_per_pixel;
             return std::make_unique<Renderer>(o);
           }),
           py::arg("width") = 640, py::arg("height") = 480, py::arg("camera") = "ego",
           py::arg("metres_per_pixel") = 0.12)
      .def("render", [](Renderer& r, const CrashEnv& env) {
        py::array_t<uint8_t> img({r.options().height, r.options().width, 3});
        r.Render(env, img.mutable_data());
        return img;
      });
}

}  // namespace accsim::python
