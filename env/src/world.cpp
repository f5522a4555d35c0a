#include "accsim/env/world.h"

#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace accsim {
namespace {

// Every collision box has this height and sits on z = 0, whatever the
// vehicle's real height, so box faces meet face-on and contact normals stay
// horizontal in the planar world.
constexpr double kCollisionHalfHeight = 0.75;  // [m]
constexpr double kTouchDistance = 1e-3;        // [m] manifold points closer than this touch

double YawOf(const btTransform& t) {
  btScalar yaw, pitch, roll;
  t.getBasis().getEulerZYX(yaw, pitch, roll);
  return yaw;
}

// Bullet's default pools hold 4096 manifolds and algorithms, and it clears
// them whenever a world is built; a reset builds one, and a few vehicles need
// a handful. Small pools make a reset ~50x cheaper; Bullet falls back to the
// heap if a scene ever outgrows them.
btDefaultCollisionConstructionInfo SmallPools() {
  btDefaultCollisionConstructionInfo info;
  info.m_defaultMaxPersistentManifoldPoolSize = 64;
  info.m_defaultMaxCollisionAlgorithmPoolSize = 64;
  return info;
}

}  // namespace

struct World::Bullet {
  btDefaultCollisionConfiguration collision_config{SmallPools()};
  btCollisionDispatcher dispatcher{&collision_config};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &collision_config};
};

struct World::Vehicle {
  VehicleParams params;
  btBoxShape shape;
  btDefaultMotionState motion;
  std::unique_ptr<btRigidBody> body;
  BodyControl control = BodyControl::kDriven;
  double accel_cmd = 0.0;
  double steer_target = 0.0;
  double steer = 0.0;
  double inertia_z = 1.0;
  Pose2 target;
  bool contacted = false;

  Vehicle(const VehicleParams& p, const btTransform& t)
      : params(p),
        shape(btVector3(p.length / 2, p.width / 2, kCollisionHalfHeight)),
        motion(t) {}
};

World::World(const WorldConfig& config) : config_(config), bullet_(std::make_unique<Bullet>()) {
  if (!(config_.physics_dt > 0.0 && config_.physics_dt <= 0.01)) {
    throw std::invalid_argument("physics_dt: must be in (0, 0.01] s so a 30 m/s closing speed cannot tunnel");
  }
  if (config_.solver_iterations < 1 || config_.solver_iterations > 100) {
    throw std::invalid_argument("solver_iterations: must be in [1, 100]");
  }
  if (!(config_.tyre_friction >= 0.0 && config_.tyre_friction <= 2.0)) {
    throw std::invalid_argument("tyre_friction: must be in [0, 2]");
  }
  bullet_->world.setGravity(btVector3(0, 0, 0));
  bullet_->world.getSolverInfo().m_numIterations = config_.solver_iterations;
}

World::~World() {
  for (auto& v : vehicles_) bullet_->world.removeRigidBody(v->body.get());
}

int World::AddVehicle(const VehicleParams& params, const Pose2& pose, double speed,
                      BodyControl control) {
  btTransform t;
  t.setIdentity();
  t.setOrigin(btVector3(pose.x, pose.y, kCollisionHalfHeight));
  t.setRotation(btQuaternion(btVector3(0, 0, 1), pose.yaw));
  auto v = std::make_unique<Vehicle>(params, t);
  btVector3 inertia(0, 0, 0);
  v->shape.calculateLocalInertia(params.mass, inertia);
  v->inertia_z = inertia.z();
  btRigidBody::btRigidBodyConstructionInfo info(params.mass, &v->motion, &v->shape, inertia);
  info.m_friction = config_.body_friction;
  info.m_restitution = config_.restitution;
  info.m_linearDamping = 0.0;
  info.m_angularDamping = 0.0;
  v->body = std::make_unique<btRigidBody>(info);
  v->body->setLinearFactor(btVector3(1, 1, 0));
  v->body->setAngularFactor(btVector3(0, 0, 1));
  v->body->setActivationState(DISABLE_DEACTIVATION);
  v->body->setLinearVelocity(btVector3(speed * std::cos(pose.yaw), speed * std::sin(pose.yaw), 0));
  v->body->setUserIndex(static_cast<int>(vehicles_.size()));
  v->control = control;
  v->target = pose;
  bullet_->world.addRigidBody(v->body.get());
  vehicles_.push_back(std::move(v));
  states_.emplace_back();
  ReadStates();
  return static_cast<int>(vehicles_.size()) - 1;
}

void World::Finalize() {
  const size_t n = vehicles_.size();
  pair_event_.assign(n * n, -1);
  pair_touching_.assign(n * n, 0);
  pre_step_states_ = states_;
  new_contacts_.reserve(n * n);
  contact_log_.reserve(n * n);
}

const VehicleParams& World::params(int i) const { return vehicles_.at(static_cast<size_t>(i))->params; }
BodyControl World::control(int i) const { return vehicles_.at(static_cast<size_t>(i))->control; }
bool World::has_contacted(int i) const { return vehicles_.at(static_cast<size_t>(i))->contacted; }

void World::SetControl(int i, BodyControl control) {
  auto& v = *vehicles_.at(static_cast<size_t>(i));
  if (control == BodyControl::kDriven && v.control != BodyControl::kDriven) {
    // Wheels start where the body is heading; no steering memory from tracking.
    v.steer = 0.0;
    v.steer_target = 0.0;
  }
  v.control = control;
}

void World::SetDriveCommand(int i, double accel, double steer_target) {
  auto& v = *vehicles_.at(static_cast<size_t>(i));
  v.accel_cmd = std::clamp(accel, -v.params.max_brake, v.params.max_accel);
  v.steer_target = std::clamp(steer_target, -v.params.max_steer, v.params.max_steer);
}

void World::SetTrackingTarget(int i, const Pose2& target) {
  vehicles_.at(static_cast<size_t>(i))->target = target;
}

void World::ApplyTyreImpulses(Vehicle& v, size_t i) {
  const double dt = config_.physics_dt;
  const VehicleState& s = states_[i];
  const double c = std::cos(s.pose.yaw), sn = std::sin(s.pose.yaw);
  const double u = s.velocity.x() * c + s.velocity.y() * sn;    // forward
  const double w = -s.velocity.x() * sn + s.velocity.y() * c;   // left
  const double r = s.yaw_rate;

  const double max_dsteer = v.params.max_steer_rate * dt;
  v.steer += std::clamp(v.steer_target - v.steer, -max_dsteer, max_dsteer);

  // Longitudinal: engine or brakes, plus rolling resistance; brakes and
  // rolling resistance only ever bring the wheel speed to zero (no reverse).
  double u_des = u;
  if (v.accel_cmd >= 0.0) {
    u_des += v.accel_cmd * dt;
  } else {
    const double dv = std::min(std::abs(u), -v.accel_cmd * dt);
    u_des -= std::copysign(dv, u);
  }
  const double drag = std::min(std::abs(u_des), config_.rolling_resistance * dt);
  u_des -= std::copysign(drag, u_des);

  // Lateral and yaw: a kinematic bicycle with the centre of mass midway
  // between the axles (no slip at the rear axle).
  const double L = v.params.wheelbase;
  const double yaw_rate_des = u_des * std::tan(v.steer) / L;
  const double w_des = yaw_rate_des * (L / 2.0);

  const double m = v.params.mass;
  const double px = m * (u_des - u);
  const double py = m * (w_des - w);
  const double pl = v.inertia_z * (yaw_rate_des - r);
  // Split into axle impulses: equal longitudinal shares; lateral shares that
  // give the required force and yaw moment about the centre.
  const double fx = px / 2.0;
  const double fy_front = py / 2.0 + pl / L;
  const double fy_rear = py / 2.0 - pl / L;
  const double budget = config_.tyre_friction * kGravity * m / 2.0 * dt;  // per axle
  auto scale = [&](double lat) {
    const double demand = std::hypot(fx, lat);
    return demand > budget ? budget / demand : 1.0;
  };
  const double kf = scale(fy_front), kr = scale(fy_rear);
  const double jx = fx * kf + fx * kr;
  const double jy = fy_front * kf + fy_rear * kr;
  const double jl = (L / 2.0) * (fy_front * kf - fy_rear * kr);
  if (jx == 0.0 && jy == 0.0 && jl == 0.0) return;
  v.body->applyCentralImpulse(btVector3(jx * c - jy * sn, jx * sn + jy * c, 0));
  v.body->applyTorqueImpulse(btVector3(0, 0, jl));
}

void World::Step() {
  const double dt = config_.physics_dt;
  for (size_t i = 0; i < vehicles_.size(); ++i) {
    Vehicle& v = *vehicles_[i];
    if (v.control == BodyControl::kDriven) {
      ApplyTyreImpulses(v, i);
    } else {
      const VehicleState& s = states_[i];
      v.body->setLinearVelocity(
          btVector3((v.target.x - s.pose.x) / dt, (v.target.y - s.pose.y) / dt, 0));
      v.body->setAngularVelocity(btVector3(0, 0, WrapAngle(v.target.yaw - s.pose.yaw) / dt));
    }
  }
  // Velocities after the tyre and tracking updates are what meet at a contact.
  ReadStates();
  pre_step_states_ = states_;
  bullet_->world.stepSimulation(dt, 0, dt);
  time_ = static_cast<double>(++substeps_) * dt;
  ReadStates();
  ScanContacts();
}

void World::ReadStates() {
  for (size_t i = 0; i < vehicles_.size(); ++i) {
    const btRigidBody& b = *vehicles_[i]->body;
    const btTransform& t = b.getCenterOfMassTransform();
    VehicleState& s = states_[i];
    s.pose.x = t.getOrigin().x();
    s.pose.y = t.getOrigin().y();
    s.pose.yaw = YawOf(t);
    s.velocity = Vec2(b.getLinearVelocity().x(), b.getLinearVelocity().y());
    s.yaw_rate = b.getAngularVelocity().z();
    s.steer = vehicles_[i]->steer;
  }
}

void World::ScanContacts() {
  new_contacts_.clear();
  const size_t n = vehicles_.size();
  btCollisionDispatcher& d = bullet_->dispatcher;
  const int num_manifolds = d.getNumManifolds();
  // pair_touching_: 0 never touched, 1 in the first touch, 2 first touch over,
  // 3 in the first touch and seen in this scan.
  for (int m = 0; m < num_manifolds; ++m) {
    const btPersistentManifold* pm = d.getManifoldByIndexInternal(m);
    int a = pm->getBody0()->getUserIndex();
    int b = pm->getBody1()->getUserIndex();
    if (a < 0 || b < 0) continue;
    double impulse = 0.0;
    btVector3 point(0, 0, 0), normal(0, 0, 0);
    int touching = 0;
    for (int p = 0; p < pm->getNumContacts(); ++p) {
      const btManifoldPoint& cp = pm->getContactPoint(p);
      if (cp.getDistance() > kTouchDistance && cp.getAppliedImpulse() <= 0.0) continue;
      ++touching;
      impulse += cp.getAppliedImpulse();
      point += cp.getPositionWorldOnB();
      normal += cp.m_normalWorldOnB;
    }
    if (touching == 0) continue;
    if (a > b) {
      std::swap(a, b);
      normal = -normal;
    }
    const size_t key = static_cast<size_t>(a) * n + static_cast<size_t>(b);
    char& state = pair_touching_[key];
    if (state == 0) {
      ContactEvent e;
      e.time = time_;
      e.body_a = a;
      e.body_b = b;
      point /= touching;
      e.point = Vec2(point.x(), point.y());
      const Vec2 nrm(normal.x(), normal.y());
      e.normal = nrm.norm() > 0 ? Vec2(nrm / nrm.norm()) : Vec2::Zero();
      e.impulse = impulse;
      auto point_velocity = [&](int i) {
        const VehicleState& s = pre_step_states_[static_cast<size_t>(i)];
        const Vec2 r = e.point - s.pose.position();
        return Vec2(s.velocity + s.yaw_rate * Vec2(-r.y(), r.x()));
      };
      const Vec2 rel = point_velocity(a) - point_velocity(b);
      e.relative_speed = rel.norm();
      e.closing_speed = std::max(0.0, -rel.dot(e.normal));
      pair_event_[key] = static_cast<int>(contact_log_.size());
      contact_log_.push_back(e);
      new_contacts_.push_back(e);
      vehicles_[static_cast<size_t>(a)]->contacted = true;
      vehicles_[static_cast<size_t>(b)]->contacted = true;
      state = 3;
    } else if (state == 1) {
      contact_log_[static_cast<size_t>(pair_event_[key])].impulse += impulse;
      state = 3;
    }
  }
  for (auto& s : pair_touching_) {
    if (s == 1) s = 2;       // not seen this scan: the first touch is over
    else if (s == 3) s = 1;  // seen: still in the first touch
  }
  // new_contacts_ carry the impulse of their first substep only; the log
  // keeps accumulating.
}

double World::RayCast(const Vec2& from, const Vec2& to, int ignore) const {
  struct Callback : btCollisionWorld::ClosestRayResultCallback {
    int ignore_index;
    Callback(const btVector3& a, const btVector3& b, int ig)
        : ClosestRayResultCallback(a, b), ignore_index(ig) {}
    bool needsCollision(btBroadphaseProxy* proxy) const override {
      const auto* obj = static_cast<const btCollisionObject*>(proxy->m_clientObject);
      return obj->getUserIndex() != ignore_index && ClosestRayResultCallback::needsCollision(proxy);
    }
  };
  const btVector3 a(from.x(), from.y(), kCollisionHalfHeight), b(to.x(), to.y(), kCollisionHalfHeight);
  Callback cb(a, b, ignore);
  bullet_->world.rayTest(a, b, cb);
  return cb.hasHit() ? static_cast<double>(cb.m_closestHitFraction) : 1.0;
}

}  // namespace accsim
