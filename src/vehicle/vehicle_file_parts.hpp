#pragma once
// The parts of a vehicle file that both of its forms read: the YAML bodies
// (vehicle_file.cpp) and a URDF's mechanism with the wheels, drives and
// hitch the file adds (urdf/urdf_vehicle_file.cpp). Private to wtc::vehicle.
#include "io/yaml_reader.hpp"
#include "wtc/vehicle/vehicle_description.hpp"

namespace wtc::vehicle {

/// A `tyre:` mapping over `base`, validated at the offending key.
TyreParameters readTyre(const io::detail::YamlReader& in, const YAML::Node& tyre, const TyreParameters& base);

/// bodies[i] of a `bodies:` list (the YAML form's), its wheel over
/// `defaults`, validated and appended to `v` (a parent named before it).
void readBodyInto(const io::detail::YamlReader& in, const YAML::Node& bodies, std::size_t i, const YAML::Node& defaults,
                  VehicleDescription& v);

/// A `hitch:` mapping naming bodies of `v`.
Hitch readHitch(const io::detail::YamlReader& in, const YAML::Node& node, const VehicleDescription& v);

/// A vehicle file with `urdf:` (docs/urdf.md): the URDF's mechanism and the
/// file's wheels, drives and hitch.
VehicleDescription readUrdfVehicleFile(const io::detail::YamlReader& in, const YAML::Node& root);

}  // namespace wtc::vehicle
