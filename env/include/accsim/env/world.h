// The Bullet crash world: planar rigid-body vehicles, a friction-limited
// tyre model, reference tracking for NPCs, and contact reporting.
//
// Model (chosen by measurement, see README "Benchmarks"):
//  * Every vehicle is a dynamic box (real mass and yaw inertia) constrained
//    to the ground plane (x, y, yaw free; z, roll, pitch locked). There is
//    no ground body: the road acts through the tyre model, so Bullet only
//    pays for vehicle-vehicle contacts.
//  * kDriven bodies (the ego; NPCs after contact) get tyre impulses each
//    substep: the velocity a no-slip kinematic bicycle would have after the
//    commanded acceleration/steering, reached only as far as each axle's
//    friction circle (mu * m * g / 2 per axle) allows. Braking therefore
//    saturates at min(brake limit, mu g); after an impact the car slides
//    until friction removes the slip.
//  * kTracking bodies (NPCs before contact, predicted post-collision
//    replay) get, before each substep, the velocity that lands them exactly
//    on their target pose at its end; with no contact they reach every
//    reference pose to rounding error, and at a contact the solver sees
//    their true mass and velocity, so impulses and momentum are physical.
// Not thread-safe; one World per environment.
#pragma once

#include <memory>
#include <vector>

#include "accsim/env/geometry.h"
#include "accsim/env/physical_tables.h"

namespace accsim {

struct WorldConfig {
  double physics_dt = 0.01;        // [s] substep; <= 0.01 so 30 m/s closing cannot tunnel
  int solver_iterations = 10;      // sequential-impulse iterations per substep
  double tyre_friction = 0.8;      // [-] tyre-road mu (from the map's surface)
  double body_friction = 0.3;      // [-] vehicle-vehicle contact friction
  double restitution = 0.1;        // [-] vehicle-vehicle restitution
  double rolling_resistance = 0.1; // [m/s^2] deceleration of a free-rolling vehicle
};

enum class BodyControl { kDriven, kTracking };

struct VehicleState {
  Pose2 pose;
  Vec2 velocity = Vec2::Zero();  // [m/s] world frame
  double yaw_rate = 0.0;         // [rad/s]
  double steer = 0.0;            // [rad] current road-wheel angle (kDriven)
  double speed() const { return velocity.norm(); }
  // Signed speed along the heading [m/s].
  double forward_speed() const {
    return velocity.x() * std::cos(pose.yaw) + velocity.y() * std::sin(pose.yaw);
  }
};

struct ContactEvent {
  double time = 0.0;            // [s] world time at the end of the substep that first touched
  int body_a = -1, body_b = -1; // vehicle indices, a < b
  Vec2 point = Vec2::Zero();    // [m] mean contact point, world frame
  Vec2 normal = Vec2::Zero();   // unit, from b towards a
  double impulse = 0.0;         // [N s] normal impulse summed while the pair stays in touch
  double relative_speed = 0.0;  // [m/s] speed of a's contact point relative to b's, just before contact
  double closing_speed = 0.0;   // [m/s] component of that along the normal
};

class World {
 public:
  explicit World(const WorldConfig& config);
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  // Adds a vehicle moving at `speed` along its heading; returns its index.
  int AddVehicle(const VehicleParams& params, const Pose2& pose, double speed, BodyControl control);
  // Reserves room for contacts so Step() does not allocate. Call after the
  // last AddVehicle.
  void Finalize();

  int num_vehicles() const { return static_cast<int>(vehicles_.size()); }
  const VehicleState& state(int i) const { return states_[static_cast<size_t>(i)]; }
  const VehicleParams& params(int i) const;
  BodyControl control(int i) const;
  void SetControl(int i, BodyControl control);
  // kDriven: acceleration command [m/s^2] (negative brakes; clamped to the
  // vehicle's limits) and target road-wheel angle [rad] (rate-limited).
  void SetDriveCommand(int i, double accel, double steer_target);
  // kTracking: the pose the body must have at the end of the next substep.
  void SetTrackingTarget(int i, const Pose2& target);
  // Whether the vehicle has touched another since the start.
  bool has_contacted(int i) const;

  // Advances one substep of physics_dt.
  void Step();
  double time() const { return time_; }
  const WorldConfig& config() const { return config_; }

  // Pairs that first touched during the last Step().
  const std::vector<ContactEvent>& new_contacts() const { return new_contacts_; }
  // One event per pair that ever touched, in order of first touch.
  const std::vector<ContactEvent>& contact_log() const { return contact_log_; }

  // Fraction in [0, 1] of the segment from `from` to `to` before the first
  // vehicle (other than `ignore`) is hit; 1 when nothing is hit.
  double RayCast(const Vec2& from, const Vec2& to, int ignore) const;

 private:
  struct Vehicle;
  struct Bullet;
  void ApplyTyreImpulses(Vehicle& v, size_t i);
  void ScanContacts();
  void ReadStates();

  WorldConfig config_;
  std::unique_ptr<Bullet> bullet_;
  std::vector<std::unique_ptr<Vehicle>> vehicles_;
  std::vector<VehicleState> states_;
  std::vector<VehicleState> pre_step_states_;
  std::vector<int> pair_event_;     // n*n: index into contact_log_ or -1
  std::vector<char> pair_touching_; // n*n
  std::vector<ContactEvent> new_contacts_;
  std::vector<ContactEvent> contact_log_;
  double time_ = 0.0;
  long substeps_ = 0;  // time_ = substeps_ * physics_dt, free of summation drift
};

}  // namespace accsim
