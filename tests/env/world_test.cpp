#include "accsim/env/world.h"

#include <gtest/gtest.h>

#include <cmath>

namespace accsim {
namespace {

WorldConfig Config(double mu) {
  WorldConfig c;
  c.tyre_friction = mu;
  c.rolling_resistance = 0.0;
  return c;
}

// Distance a car needs to stop from `v0` under full braking.
double StoppingDistance(double v0, double mu) {
  World w(Config(mu));
  const int car = w.AddVehicle(Params(VehicleClass::kCar), Pose2{0, 0, 0.3}, v0, BodyControl::kDriven);
  w.Finalize();
  w.SetDriveCommand(car, -1e9, 0.0);
  for (int i = 0; i < 3000 && w.state(car).speed() > 1e-9; ++i) w.Step();
  EXPECT_LT(w.state(car).speed(), 1e-9);
  return w.state(car).pose.position().norm();
}

TEST(WorldTest, BrakingFrom20MpsOnDryAsphaltMatchesFriction) {
  // Tyre-limited braking: d = v^2 / (2 mu g). With dry-asphalt mu between
  // 0.7 and 0.9 that is 22.7 m to 29.1 m; the table's 0.8 gives 25.5 m
  // (the car's 9 m/s^2 brakes are stronger than the tyres' 7.85 m/s^2).
  const double d = StoppingDistance(20.0, FrictionCoefficient(Surface::kDry));
  EXPECT_GT(d, 20.0 * 20.0 / (2 * 0.9 * kGravity));
  EXPECT_LT(d, 20.0 * 20.0 / (2 * 0.7 * kGravity));
  EXPECT_NEAR(d, 20.0 * 20.0 / (2 * 0.8 * kGravity), 0.25);  // within one substep of travel
}

TEST(WorldTest, BrakingIsLongerOnLowerFriction) {
  const double dry = StoppingDistance(20.0, FrictionCoefficient(Surface::kDry));
  const double wet = StoppingDistance(20.0, FrictionCoefficient(Surface::kWet));
  const double ice = StoppingDistance(20.0, FrictionCoefficient(Surface::kIce));
  EXPECT_NEAR(wet, 400.0 / (2 * 0.5 * kGravity), 0.3);
  EXPECT_GT(wet, dry * 1.5);
  EXPECT_GT(ice, wet * 4.0);
}

TEST(WorldTest, BrakeLimitCapsDecelerationOnHighFriction) {
  // A truck's brakes (6 m/s^2) are weaker than dry tyres: they set the distance.
  World w(Config(0.8));
  const int truck = w.AddVehicle(Params(VehicleClass::kTruck), Pose2{}, 20.0, BodyControl::kDriven);
  w.Finalize();
  w.SetDriveCommand(truck, -1e9, 0.0);
  for (int i = 0; i < 3000; ++i) w.Step();
  EXPECT_NEAR(w.state(truck).pose.x, 400.0 / (2 * 6.0), 0.25);
}

TEST(WorldTest, TrackingVehicleReachesReferencePosesAtReferenceTimes) {
  World w(Config(0.8));
  auto ref = [](double t) {  // a 40 m radius arc at 10 m/s
    const double a = 10.0 * t / 40.0;
    return Pose2{40.0 * std::sin(a), 40.0 * (1 - std::cos(a)), a};
  };
  const int npc = w.AddVehicle(Params(VehicleClass::kSuv), ref(0.0), 10.0, BodyControl::kTracking);
  w.Finalize();
  double worst = 0.0, worst_yaw = 0.0;
  for (int i = 1; i <= 500; ++i) {
    w.SetTrackingTarget(npc, ref(i * 0.01));
    w.Step();
    const Pose2 want = ref(w.time());
    worst = std::max(worst, (w.state(npc).pose.position() - want.position()).norm());
    worst_yaw = std::max(worst_yaw, std::abs(WrapAngle(w.state(npc).pose.yaw - want.yaw)));
  }
  // Stated bound: 1 mm and 1 mrad (the body integrates exactly the velocity it is given).
  EXPECT_LT(worst, 1e-3);
  EXPECT_LT(worst_yaw, 1e-3);
}

TEST(WorldTest, FrictionlessHeadOnConservesLinearMomentum) {
  World w(Config(0.0));
  const int a = w.AddVehicle(Params(VehicleClass::kCar), Pose2{-10, 0, 0}, 15.0, BodyControl::kDriven);
  const int b = w.AddVehicle(Params(VehicleClass::kSuv), Pose2{10, 0.3, kPi}, 12.0, BodyControl::kDriven);
  w.Finalize();
  auto momentum = [&] {
    return Vec2(Params(VehicleClass::kCar).mass * w.state(a).velocity +
                Params(VehicleClass::kSuv).mass * w.state(b).velocity);
  };
  const Vec2 before = momentum();
  for (int i = 0; i < 200; ++i) w.Step();
  ASSERT_EQ(w.contact_log().size(), 1u);
  const Vec2 after = momentum();
  EXPECT_LT((after - before).norm(), 0.01 * before.norm());
  // The impact really changed the velocities.
  EXPECT_LT(w.state(a).velocity.x(), 5.0);
}

TEST(WorldTest, ThirtyMpsClosingSpeedDoesNotTunnelThroughAMotorcycle) {
  World w(Config(0.8));
  const int car = w.AddVehicle(Params(VehicleClass::kCar), Pose2{-10, 0, 0}, 30.0, BodyControl::kDriven);
  // Broadside: the car meets the motorcycle's 0.8 m width.
  const int moto = w.AddVehicle(Params(VehicleClass::kMotorcycle), Pose2{0, 0, kPi / 2}, 0.0,
                                BodyControl::kTracking);
  w.Finalize();
  for (int i = 0; i < 100; ++i) {
    w.SetTrackingTarget(moto, Pose2{0, 0, kPi / 2});
    w.Step();
  }
  ASSERT_EQ(w.contact_log().size(), 1u);
  const ContactEvent& e = w.contact_log().front();
  EXPECT_EQ(e.body_a, car);
  EXPECT_EQ(e.body_b, moto);
  EXPECT_NEAR(e.relative_speed, 30.0, 0.5);
  EXPECT_NEAR(e.closing_speed, 30.0, 0.5);
  EXPECT_GT(e.impulse, 0.0);
  EXPECT_NEAR(e.time, (10.0 - 2.3 - 0.4) / 30.0, 0.02);
  EXPECT_TRUE(w.has_contacted(car));
  EXPECT_TRUE(w.has_contacted(moto));
}

TEST(WorldTest, SteeringFollowsKinematicBicycleAtLowSpeed) {
  World w(Config(0.8));
  const auto& p = Params(VehicleClass::kCar);
  const int car = w.AddVehicle(p, Pose2{}, 5.0, BodyControl::kDriven);
  w.Finalize();
  w.SetDriveCommand(car, 0.0, 0.2);
  for (int i = 0; i < 300; ++i) w.Step();
  // Steady state: yaw rate = v tan(delta) / L.
  EXPECT_NEAR(w.state(car).yaw_rate, w.state(car).forward_speed() * std::tan(0.2) / p.wheelbase, 1e-3);
}

TEST(WorldTest, FrictionLimitsLateralAcceleration) {
  // Full steering at 25 m/s on ice cannot turn faster than mu g / v.
  World w(Config(FrictionCoefficient(Surface::kIce)));
  const int car = w.AddVehicle(Params(VehicleClass::kCar), Pose2{}, 25.0, BodyControl::kDriven);
  w.Finalize();
  w.SetDriveCommand(car, 0.0, 1.0);
  double max_lat_accel = 0.0;
  Vec2 prev = w.state(car).velocity;
  for (int i = 0; i < 200; ++i) {
    w.Step();
    max_lat_accel = std::max(max_lat_accel, (w.state(car).velocity - prev).norm() / 0.01);
    prev = w.state(car).velocity;
  }
  EXPECT_LE(max_lat_accel, 0.1 * kGravity * 1.0001);
}

TEST(WorldTest, RejectsSubstepsThatCouldTunnel) {
  WorldConfig c;
  c.physics_dt = 0.02;
  EXPECT_THROW(World w(c), std::invalid_argument);
}

TEST(WorldTest, RayCastHitsOtherVehicleAndIgnoresSelf) {
  World w(Config(0.8));
  const int ego = w.AddVehicle(Params(VehicleClass::kCar), Pose2{}, 0.0, BodyControl::kDriven);
  w.AddVehicle(Params(VehicleClass::kCar), Pose2{20.0, 0, 0}, 0.0, BodyControl::kTracking);
  w.Finalize();
  const double f = w.RayCast(Vec2(0, 0), Vec2(50, 0), ego);
  EXPECT_NEAR(f * 50.0, 20.0 - 2.3, 0.1);
  EXPECT_DOUBLE_EQ(w.RayCast(Vec2(0, 0), Vec2(0, 50), ego), 1.0);
}

}  // namespace
}  // namespace accsim
