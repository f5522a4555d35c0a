#include "accsim/env/crash_env.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace accsim {
namespace {

constexpr double kSpeedScale = 40.0;   // [m/s]
constexpr double kAccelScale = 10.0;   // [m/s^2]
constexpr double kRemainingScale = 200.0;  // [m]
constexpr double kRouteOffsetScale = 5.0;  // [m]
constexpr double kTtcHorizon = 10.0;   // [s] time-to-collision beyond this counts as none

// Adds the time since the last Lap() to a profile counter when enabled.
class Stopwatch {
 public:
  explicit Stopwatch(bool on) : on_(on) {
    if (on_) last_ = std::chrono::steady_clock::now();
  }
  void Lap(double& into) {
    if (!on_) return;
    const auto now = std::chrono::steady_clock::now();
    into += std::chrono::duration<double>(now - last_).count();
    last_ = now;
  }

 private:
  bool on_;
  std::chrono::steady_clock::time_point last_;
};

float Clip(double v) { return static_cast<float>(std::clamp(v, -1.0, 1.0)); }

bool SameMap(const RoadMapSpec& a, const RoadMapSpec& b) {
  return a.type == b.type && a.lanes_per_direction == b.lanes_per_direction &&
         a.divided == b.divided && a.lane_width == b.lane_width &&
         a.median_width == b.median_width && a.length == b.length &&
         a.speed_limit == b.speed_limit && a.surface == b.surface;
}

}  // namespace

CrashEnv::CrashEnv(CrashEnvConfig config, std::vector<std::shared_ptr<const Scenario>> scenarios)
    : config_(std::move(config)), spec_(MakeEnvSpec(config_)), scenarios_(std::move(scenarios)) {
  if (scenarios_.empty()) throw std::invalid_argument("scenarios: at least one scenario is needed");
  for (size_t i = 0; i < scenarios_.size(); ++i) {
    if (!scenarios_[i]) throw std::invalid_argument("scenarios[" + std::to_string(i) + "]: null");
  }
  obs_.assign(static_cast<size_t>(spec_.obs_dim), 0.0f);
}

CrashEnv::~CrashEnv() = default;

double CrashEnv::Uniform() { return static_cast<double>(rng_() >> 11) * 0x1.0p-53; }

const float* CrashEnv::Reset(std::optional<uint64_t> seed, int scenario_index) {
  if (seed) rng_.seed(*seed);
  if (scenario_index >= static_cast<int>(scenarios_.size())) {
    throw std::invalid_argument("scenario_index: " + std::to_string(scenario_index) +
                                " is out of range (the environment has " +
                                std::to_string(scenarios_.size()) + " scenarios)");
  }
  // Always draw, so the stream does not depend on whether an index was given.
  const auto drawn = static_cast<int>(Uniform() * static_cast<double>(scenarios_.size()));
  const int index = scenario_index >= 0 ? scenario_index : drawn;
  scenario_ = scenarios_[static_cast<size_t>(index)];
  const Scenario& sc = *scenario_;
  if (!map_ || !SameMap(map_->spec(), sc.map)) map_ = std::make_shared<const RoadMap>(sc.map);

  WorldConfig wc;
  wc.physics_dt = 1.0 / config_.physics_hz;
  wc.solver_iterations = config_.solver_iterations;
  wc.tyre_friction = map_->friction();
  world_ = std::make_unique<World>(wc);

  const double speed_jitter = (2.0 * Uniform() - 1.0) * config_.start_speed_jitter;
  const double ego_speed = std::max(0.0, sc.ego.speed + speed_jitter);
  world_->AddVehicle(Params(sc.ego.vehicle_class), sc.ego.start, ego_speed, BodyControl::kDriven);
  ids_.assign(1, sc.ego.id);
  npc_cursor_.assign(sc.npcs.size() + 1, 0);
  npc_time_offset_.assign(sc.npcs.size() + 1, 0.0);
  for (size_t k = 0; k < sc.npcs.size(); ++k) {
    const NpcSpec& npc = sc.npcs[k];
    const double offset = (2.0 * Uniform() - 1.0) * config_.npc_time_jitter;
    npc_time_offset_[k + 1] = offset;
    const TrajectoryPoint p = npc.reference.Sample(-offset);
    world_->AddVehicle(Params(npc.vehicle_class), Pose2{p.x, p.y, p.yaw}, p.v, BodyControl::kTracking);
    ids_.push_back(npc.id);
  }
  world_->Finalize();
  const size_t n = ids_.size();
  contact_time_.assign(n, -1.0);
  contact_pose_.assign(n, Pose2{});
  neighbours_.clear();
  neighbours_.reserve(n);

  time_limit_ = config_.time_limit > 0.0 ? config_.time_limit : sc.time_limit;
  route_s_ = route().Project(sc.ego.start.position()).s;
  route_start_s_ = route_s_;
  prev_action_ = {0.0f, 0.0f};
  prev_forward_speed_ = ego_speed;
  reward_ = 0.0;
  terminated_ = truncated_ = false;
  needs_reset_ = false;
  off_road_reported_ = false;
  info_ = StepInfo{};
  info_.scenario_index = index;
  info_.route_progress = 0.0;
  info_.route_length = route().length();
  info_.min_ttc = std::numeric_limits<double>::infinity();
  ComputeObservation();
  return obs_.data();
}

void CrashEnv::UpdateNpcTargets(double t_next) {
  const Scenario& sc = *scenario_;
  for (size_t k = 0; k < sc.npcs.size(); ++k) {
    const size_t i = k + 1;
    if (world_->control(static_cast<int>(i)) != BodyControl::kTracking) continue;
    const NpcSpec& npc = sc.npcs[k];
    if (contact_time_[i] < 0.0) {
      const TrajectoryPoint p = npc.reference.Sample(t_next - npc_time_offset_[i], &npc_cursor_[i]);
      world_->SetTrackingTarget(static_cast<int>(i), Pose2{p.x, p.y, p.yaw});
    } else {
      // Predicted post-collision motion, replayed relative to where the
      // contact actually happened.
      const auto& pts = npc.predicted.points();
      const TrajectoryPoint& p0 = pts.front();
      const TrajectoryPoint p = npc.predicted.Sample(p0.t + (t_next - contact_time_[i]), &npc_cursor_[i]);
      const Pose2& c = contact_pose_[i];
      const double dyaw = c.yaw - p0.yaw;
      const double dx = p.x - p0.x, dy = p.y - p0.y;
      world_->SetTrackingTarget(
          static_cast<int>(i),
          Pose2{c.x + std::cos(dyaw) * dx - std::sin(dyaw) * dy,
                c.y + std::sin(dyaw) * dx + std::cos(dyaw) * dy, WrapAngle(p.yaw + dyaw)});
    }
  }
}

void CrashEnv::OnContacts() {
  for (const ContactEvent& e : world_->new_contacts()) {
    for (int i : {e.body_a, e.body_b}) {
      const size_t u = static_cast<size_t>(i);
      if (i == 0 || contact_time_[u] >= 0.0) continue;
      contact_time_[u] = e.time;
      contact_pose_[u] = world_->state(i).pose;
      const NpcSpec& npc = scenario_->npcs[u - 1];
      if (npc.post_collision == PostCollisionSource::kPredicted && !npc.predicted.empty()) {
        npc_cursor_[u] = 0;
      } else {
        world_->SetControl(i, BodyControl::kDriven);
        world_->SetDriveCommand(i, -config_.post_contact_brake * world_->params(i).max_brake, 0.0);
      }
    }
    if (e.body_a == 0 && !info_.ego_collision) {
      CollisionInfo c;
      c.time = e.time;
      c.other = e.body_b;
      c.other_id = ids_[static_cast<size_t>(e.body_b)];
      c.point = e.point;
      c.impulse = e.impulse;
      c.relative_speed = e.relative_speed;
      c.closing_speed = e.closing_speed;
      info_.ego_collision = c;
      info_.collision = true;
    } else if (e.body_a != 0) {
      ++info_.npc_contacts;
    }
  }
}

void CrashEnv::Step(const float* action, size_t size) {
  if (needs_reset_) {
    throw std::logic_error(world_ ? "Step() after the episode ended: call Reset() first"
                                  : "Step() before Reset(): call Reset() first");
  }
  if (size != static_cast<size_t>(spec_.action_dim)) {
    throw std::invalid_argument("action: expected " + std::to_string(spec_.action_dim) +
                                " values (accel, steer), got " + std::to_string(size));
  }
  if (action == nullptr) throw std::invalid_argument("action: null pointer");
  std::array<float, 2> a{};
  for (size_t k = 0; k < 2; ++k) {
    if (!std::isfinite(action[k])) {
      throw std::invalid_argument("action[" + std::to_string(k) + "] (" + spec_.action_names[k] +
                                  "): not a finite number (" + std::to_string(action[k]) + ")");
    }
    a[k] = std::clamp(action[k], -1.0f, 1.0f);
    if (a[k] != action[k]) ++info_.clipped_actions;
  }

  const VehicleParams& ego = world_->params(0);
  const double accel = a[0] >= 0.0f ? a[0] * ego.max_accel : a[0] * ego.max_brake;
  world_->SetDriveCommand(0, accel, a[1] * ego.max_steer);

  info_.collision = false;
  info_.off_road = info_.goal = info_.time_limit = false;
  const double dt = world_->config().physics_dt;
  Stopwatch watch(profiling_);
  for (int k = 0; k < spec_.substeps; ++k) {
    UpdateNpcTargets(world_->time() + dt);
    watch.Lap(profile_.npc_control);
    world_->Step();
    watch.Lap(profile_.physics);
    if (!world_->new_contacts().empty()) OnContacts();
    watch.Lap(profile_.npc_control);
  }

  // The ego's collision impulse: everything exchanged with that vehicle
  // since first touch, not just the first substep's share.
  if (info_.ego_collision) {
    for (const ContactEvent& e : world_->contact_log()) {
      if (e.body_a == 0 && e.body_b == info_.ego_collision->other) info_.ego_collision->impulse = e.impulse;
    }
  }

  // Reward terms and termination.
  auto& terms = info_.reward_terms;
  terms.fill(0.0);
  const VehicleState& s = world_->state(0);
  const auto proj = route().Project(s.pose.position(), route_s_);
  const double progress = proj.s - route_s_;
  route_s_ = proj.s;
  terms[kRewardProgress] = config_.reward.progress * progress;
  if (info_.collision) terms[kRewardCollision] = config_.reward.collision;
  const bool on_road = map_->OnRoad(s.pose.position());
  if (!on_road && !off_road_reported_) {
    terms[kRewardOffRoad] = config_.reward.off_road;
    off_road_reported_ = true;
  }
  info_.off_road = !on_road;
  if (const auto loc = map_->Locate(s.pose)) {
    const double half = map_->lane(loc->lane_id).width / 2.0;
    const double dev = std::min(1.0, (loc->lateral / half) * (loc->lateral / half));
    terms[kRewardLaneDeviation] = config_.reward.lane_deviation * dev;
  }
  const double d0 = a[0] - prev_action_[0], d1 = a[1] - prev_action_[1];
  terms[kRewardComfort] = config_.reward.comfort * (d0 * d0 + d1 * d1) / 8.0;
  prev_action_ = a;
  const double remaining = route().length() - route_s_;
  info_.goal = remaining <= config_.goal_tolerance;
  if (info_.goal) terms[kRewardGoal] = config_.reward.goal;

  reward_ = 0.0;
  for (double t : terms) reward_ += t;
  info_.time = world_->time();
  info_.route_progress = route_s_ - route_start_s_;
  info_.min_ttc = std::min(info_.min_ttc, MinTimeToCollision());
  ++info_.episode_steps;
  info_.episode_return += reward_;

  terminated_ = (info_.collision && config_.terminate_on_collision) || info_.off_road || info_.goal;
  info_.time_limit = world_->time() >= time_limit_ - 1e-9;
  truncated_ = !terminated_ && info_.time_limit;
  needs_reset_ = terminated_ || truncated_;
  watch.Lap(profile_.reward);
  ComputeObservation();
  watch.Lap(profile_.observation);
  ++profile_.steps;
  prev_forward_speed_ = s.forward_speed();
}

double CrashEnv::MinTimeToCollision() const {
  // Time until the ego's and each other vehicle's footprints (oriented
  // boxes) first overlap if both keep their current velocity: on each of the
  // four separating axes the overlap is a time interval; the boxes overlap
  // where all four intervals do.
  const World& w = *world_;
  const VehicleState& e = w.state(0);
  const VehicleParams& ep = w.params(0);
  double best = std::numeric_limits<double>::infinity();
  for (int i = 1; i < w.num_vehicles(); ++i) {
    const VehicleState& o = w.state(i);
    const VehicleParams& op = w.params(i);
    const Vec2 d = o.pose.position() - e.pose.position();
    const Vec2 vel = o.velocity - e.velocity;
    const Vec2 ue(std::cos(e.pose.yaw), std::sin(e.pose.yaw)), ve(-ue.y(), ue.x());
    const Vec2 uo(std::cos(o.pose.yaw), std::sin(o.pose.yaw)), vo(-uo.y(), uo.x());
    double enter = -std::numeric_limits<double>::infinity();
    double exit = std::numeric_limits<double>::infinity();
    for (const Vec2& n : {ue, ve, uo, vo}) {
      const double r = ep.length / 2 * std::abs(n.dot(ue)) + ep.width / 2 * std::abs(n.dot(ve)) +
                       op.length / 2 * std::abs(n.dot(uo)) + op.width / 2 * std::abs(n.dot(vo));
      const double p = n.dot(d), q = n.dot(vel);
      if (std::abs(q) < 1e-12) {
        if (std::abs(p) >= r) {
          enter = std::numeric_limits<double>::infinity();
          break;
        }
        continue;
      }
      const double t1 = (-r - p) / q, t2 = (r - p) / q;
      enter = std::max(enter, std::min(t1, t2));
      exit = std::min(exit, std::max(t1, t2));
    }
    if (enter <= exit && exit >= 0.0 && enter < kTtcHorizon) best = std::min(best, std::max(0.0, enter));
  }
  return best;
}

void CrashEnv::ComputeObservation() {
  float* o = obs_.data();
  const VehicleState& s = world_->state(0);
  const VehicleParams& p = world_->params(0);
  const double fwd = s.forward_speed();
  const double lat = -s.velocity.x() * std::sin(s.pose.yaw) + s.velocity.y() * std::cos(s.pose.yaw);
  const double policy_dt = spec_.policy_dt;
  int k = spec_.ego_offset;
  o[k++] = Clip(s.speed() / kSpeedScale);
  o[k++] = Clip((fwd - prev_forward_speed_) / policy_dt / kAccelScale);
  o[k++] = Clip(s.yaw_rate);
  o[k++] = Clip(s.steer / p.max_steer);
  o[k++] = Clip(lat / 10.0);
  const auto loc = map_->Locate(s.pose);
  if (loc) {
    o[k++] = Clip(loc->lateral / (map_->lane(loc->lane_id).width / 2.0));
    o[k++] = Clip(loc->heading_error / kPi);
  } else {
    o[k++] = 0.0f;
    o[k++] = 0.0f;
  }
  o[k++] = map_->OnRoad(s.pose.position()) ? 1.0f : 0.0f;
  o[k++] = Clip(map_->spec().speed_limit / kSpeedScale);
  o[k++] = Clip(std::max(0.0, time_limit_ - world_->time()) / time_limit_);

  k = spec_.route_offset;
  const Polyline& r = route();
  const auto proj = r.Project(s.pose.position(), route_s_);
  o[k++] = Clip(r.length() > 0 ? proj.s / r.length() : 1.0);
  o[k++] = Clip((r.length() - proj.s) / kRemainingScale);
  o[k++] = Clip(proj.lateral / kRouteOffsetScale);
  const double lookahead = std::max(5.0, 1.0 * std::abs(fwd));
  const double herr = WrapAngle(r.HeadingAt(proj.s + lookahead) - s.pose.yaw);
  o[k++] = Clip(std::sin(herr));
  o[k++] = Clip(std::cos(herr));

  k = spec_.vehicles_offset;
  neighbours_.clear();
  const double range = config_.observation_range;
  for (int i = 1; i < world_->num_vehicles(); ++i) {
    const double d = (world_->state(i).pose.position() - s.pose.position()).norm();
    if (d <= range) neighbours_.emplace_back(d, i);
  }
  std::sort(neighbours_.begin(), neighbours_.end());
  for (int slot = 0; slot < config_.observed_vehicles; ++slot) {
    float* v = o + k + slot * spec_.vehicle_features;
    if (static_cast<size_t>(slot) >= neighbours_.size()) {
      std::fill(v, v + spec_.vehicle_features, 0.0f);
      continue;
    }
    const int i = neighbours_[static_cast<size_t>(slot)].second;
    const VehicleState& n = world_->state(i);
    const VehicleParams& np = world_->params(i);
    const Vec2 dp = ToLocal(n.pose.position() - s.pose.position(), s.pose.yaw);
    const Vec2 dv = ToLocal(n.velocity - s.velocity, s.pose.yaw);
    const double dyaw = n.pose.yaw - s.pose.yaw;
    v[0] = 1.0f;
    v[1] = Clip(dp.x() / range);
    v[2] = Clip(dp.y() / range);
    v[3] = Clip(dv.x() / kSpeedScale);
    v[4] = Clip(dv.y() / kSpeedScale);
    v[5] = Clip(std::cos(dyaw));
    v[6] = Clip(std::sin(dyaw));
    v[7] = Clip(np.length / 20.0);
    v[8] = Clip(np.width / 5.0);
  }

  k = spec_.rays_offset;
  for (int ray = 0; ray < config_.num_rays; ++ray) {
    const double ang = s.pose.yaw + 2.0 * kPi * ray / config_.num_rays;
    const Vec2 to = s.pose.position() + config_.ray_range * Vec2(std::cos(ang), std::sin(ang));
    o[k++] = static_cast<float>(world_->RayCast(s.pose.position(), to, 0));
  }
}

void CrashEnv::CopyObservation(float* out) const { std::copy(obs_.begin(), obs_.end(), out); }

}  // namespace accsim
