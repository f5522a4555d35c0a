// The one table of physical constants: road surfaces and vehicle classes.
#pragma once

#include <string>
#include <string_view>

namespace accsim {

constexpr double kGravity = 9.81;  // [m/s^2]

enum class Surface { kDry, kWet, kSnow, kIce };

// Tyre-road peak friction coefficient per surface (passenger-car tyres;
// mid-range of published values: dry asphalt 0.7-0.9, wet 0.4-0.6,
// packed snow 0.2-0.3, ice 0.05-0.15).
double FrictionCoefficient(Surface surface);
std::string_view ToString(Surface surface);
// Throws std::invalid_argument("surface: ...") for unknown names.
Surface SurfaceFromString(std::string_view name);

enum class VehicleClass { kCar, kSuv, kPickup, kVan, kTruck, kBus, kMotorcycle };

struct VehicleParams {
  double mass;              // [kg]
  double length;            // [m] bumper to bumper
  double width;             // [m]
  double height;            // [m]
  double wheelbase;         // [m]
  double max_accel;         // [m/s^2] engine limit at low speed
  double max_brake;         // [m/s^2] brake system limit (tyres may limit further)
  double max_steer;         // [rad] road-wheel angle
  double max_steer_rate;    // [rad/s]
};

const VehicleParams& Params(VehicleClass cls);
std::string_view ToString(VehicleClass cls);
// Throws std::invalid_argument("vehicle class: ...") for unknown names.
VehicleClass VehicleClassFromString(std::string_view name);

}  // namespace accsim
