#include "accsim/env/physical_tables.h"

#include <array>
#include <stdexcept>
#include <string>

namespace accsim {
namespace {

struct SurfaceRow {
  Surface surface;
  std::string_view name;
  double mu;
};
// Peak tyre-road friction, mid-range of published values for passenger tyres.
constexpr std::array<SurfaceRow, 4> kSurfaces{{
    {Surface::kDry, "dry", 0.80},
    {Surface::kWet, "wet", 0.50},
    {Surface::kSnow, "snow", 0.25},
    {Surface::kIce, "ice", 0.10},
}};

struct VehicleRow {
  VehicleClass cls;
  std::string_view name;
  VehicleParams params;
};
// Typical US-fleet values (curb mass plus one occupant). Brake limits are the
// brake system's; on a surface the tyres cap deceleration at mu * g.
//                        mass    len   wid   hgt   wb   acc  brake steer rate
constexpr std::array<VehicleRow, 7> kVehicles{{
    {VehicleClass::kCar, "car", {1500, 4.60, 1.80, 1.45, 2.70, 3.5, 9.0, 0.60, 1.0}},
    {VehicleClass::kSuv, "suv", {2100, 4.80, 1.95, 1.75, 2.85, 3.0, 8.5, 0.60, 1.0}},
    {VehicleClass::kPickup, "pickup", {2300, 5.50, 2.00, 1.85, 3.50, 3.0, 8.0, 0.60, 1.0}},
    {VehicleClass::kVan, "van", {2200, 5.10, 2.00, 2.00, 3.20, 2.5, 8.0, 0.60, 1.0}},
    {VehicleClass::kTruck, "truck", {12000, 9.00, 2.50, 3.50, 5.50, 1.5, 6.0, 0.55, 0.6}},
    {VehicleClass::kBus, "bus", {13000, 12.0, 2.55, 3.20, 6.00, 1.2, 6.0, 0.55, 0.6}},
    {VehicleClass::kMotorcycle, "motorcycle", {250, 2.20, 0.80, 1.30, 1.45, 5.0, 9.0, 0.50, 1.2}},
}};

template <typename Rows>
std::string Names(const Rows& rows) {
  std::string out;
  for (const auto& r : rows) {
    if (!out.empty()) out += ", ";
    out += r.name;
  }
  return out;
}

}  // namespace

double FrictionCoefficient(Surface surface) {
  for (const auto& r : kSurfaces) {
    if (r.surface == surface) return r.mu;
  }
  throw std::invalid_argument("surface: unknown enum value");
}

std::string_view ToString(Surface surface) {
  for (const auto& r : kSurfaces) {
    if (r.surface == surface) return r.name;
  }
  return "unknown";
}

Surface SurfaceFromString(std::string_view name) {
  for (const auto& r : kSurfaces) {
    if (r.name == name) return r.surface;
  }
  throw std::invalid_argument("surface: unknown '" + std::string(name) + "' (expected " +
                              Names(kSurfaces) + ")");
}

const VehicleParams& Params(VehicleClass cls) {
  for (const auto& r : kVehicles) {
    if (r.cls == cls) return r.params;
  }
  throw std::invalid_argument("vehicle class: unknown enum value");
}

std::string_view ToString(VehicleClass cls) {
  for (const auto& r : kVehicles) {
    if (r.cls == cls) return r.name;
  }
  return "unknown";
}

VehicleClass VehicleClassFromString(std::string_view name) {
  for (const auto& r : kVehicles) {
    if (r.name == name) return r.cls;
  }
  throw std::invalid_argument("vehicle class: unknown '" + std::string(name) + "' (expected " +
                              Names(kVehicles) + ")");
}

}  // namespace accsim
