#include "accsim/env/scripted_drivers.h"

#include <algorithm>
#include <cmath>

namespace accsim {
float SpeedKeeping(const CrashEnv& env, double target) {
  const VehicleState& s = env.world().state(0);
  const VehicleParams& p = env.world().params(0);
  const double err = target - s.forward_speed();
  // Proportional control with a 0.5 s time constant, in action units.
  const double accel = err / 0.5;
  const double a = accel >= 0 ? accel / p.max_accel : accel / p.max_brake;
  return static_cast<float>(std::clamp(a, -1.0, 1.0));
}

float RouteSteering(const CrashEnv& env, double lateral_offset) {
  const VehicleState& s = env.world().state(0);
  const VehicleParams& p = env.world().params(0);
  const Polyline& route = env.route();
  const double speed = std::max(0.0, s.forward_speed());
  const double lookahead = std::clamp(4.0 + 0.6 * speed, 4.0, 25.0);
  const auto proj = route.Project(s.pose.position(), env.route_s());
  const double st = proj.s + lookahead;
  const double h = route.HeadingAt(st);
  Vec2 target = route.PointAt(st) + lateral_offset * Vec2(-std::sin(h), std::cos(h));
  // Past the end of the route, keep going straight along its last heading.
  if (st > route.length()) target += (st - route.length()) * Vec2(std::cos(h), std::sin(h));
  const Vec2 local = ToLocal(target - s.pose.position(), s.pose.yaw);
  const double curvature = 2.0 * local.y() / std::max(1e-6, local.squaredNorm());
  const double steer = std::atan(curvature * p.wheelbase);
  return static_cast<float>(std::clamp(steer / p.max_steer, -1.0, 1.0));
}

Action HoldPolicy(const CrashEnv& env) {
  return {SpeedKeeping(env, env.scenario().ego.target_speed), RouteSteering(env)};
}

Action BrakePolicy(const CrashEnv& env, double onset) {
  if (env.time() + 1e-9 < onset) return HoldPolicy(env);
  return {-1.0f, RouteSteering(env)};
}

Action RuleBasedPolicy(const CrashEnv& env, double horizon) {
  const World& w = env.world();
  const VehicleState& e = w.state(0);
  const Polyline& route = env.route();
  const double speed = std::max(0.0, e.forward_speed());
  const double target = env.scenario().ego.target_speed;
  const double accel = 0.5 * w.params(0).max_accel;
  const double ego_radius = w.params(0).length / 2.0;
  // Where the ego would be if it went on (back) to its target speed: judging
  // conflicts by the current speed alone would let a stopped ego pull out
  // into the gap it just braked for.
  double s = env.route_s(), v = speed;
  for (double t = 0.25; t <= horizon + 1e-9; t += 0.25) {
    const double v_next = v < target ? std::min(target, v + accel * 0.25) : v;
    s += 0.5 * (v + v_next) * 0.25;
    v = v_next;
    const Vec2 ego_at = route.PointAt(s);
    for (int i = 1; i < w.num_vehicles(); ++i) {
      const VehicleState& o = w.state(i);
      const Vec2 other_at = o.pose.position() + o.velocity * t;
      const double radius = ego_radius + w.params(i).length / 2.0 + 1.0;
      if ((other_at - ego_at).norm() < radius) return {-1.0f, RouteSteering(env)};
    }
  }
  return HoldPolicy(env);
}

}  // namespace accsim
