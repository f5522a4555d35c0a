// Scripted ego drivers: the `--ego` choices of `accsim simulate`, the
// manoeuvres scenario generation checks scenarios with, and the baselines
// learned policies are compared with. All return an action
// in the CrashEnv's Box[-1, 1]^2 (accel/brake, steering) and are
// deterministic functions of the environment's state.
#pragma once

#include <array>

#include "accsim/env/crash_env.h"

namespace accsim {

using Action = std::array<float, 2>;

// Pure-pursuit steering along the ego's route (shifted sideways by
// `lateral_offset` metres, + left) with a look-ahead that grows with speed;
// the same for every driver below.
float RouteSteering(const CrashEnv& env, double lateral_offset = 0.0);
// Proportional speed keeping towards `target` [m/s], in action units.
float SpeedKeeping(const CrashEnv& env, double target);

// Keeps the scenario's target speed along the route: the "inattentive
// driver" that the reconstructed crash is built around.
Action HoldPolicy(const CrashEnv& env);

// Follows the route and brakes fully from `onset` seconds on.
Action BrakePolicy(const CrashEnv& env, double onset = 0.0);

// A cautious driver: keeps the target speed but brakes fully when any
// vehicle, extrapolated at constant velocity over `horizon` seconds, comes
// within a safety radius of the ego's own extrapolated path.
Action RuleBasedPolicy(const CrashEnv& env, double horizon = 4.0);

}  // namespace accsim
