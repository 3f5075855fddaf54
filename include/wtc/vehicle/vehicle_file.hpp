#pragma once
// Vehicle description files (YAML), read into wtc::vehicle::VehicleDescription.
// vehicles/README.md has the full reference; vehicles/*.yaml are the shipped
// vehicles. In short (lengths m, masses kg, angles as the key says):
//
//   name: six_wheel_robot
//   wheel_defaults:                  # optional: every wheel body starts from these
//     mass: 3.7
//     wheel: {radius: 0.19, width: 0.12, axle: [0, 1, 0], tyre: {radial_stiffness: 1e5}}
//     joint: {type: revolute, axis: [0, 1, 0], drive: {max_effort: 100, max_speed: 5}}
//   bodies:                          # parents before children
//     - name: middle
//       mass: 70
//       shape: {box: [0.6, 0.4, 0.2]}          # or {cylinder: {radius, length, axis: y}}, {sphere: r}
//       translation: [0, 0, 0.19]              # centre of mass in V; rotation: as in terrain files
//       inertia: [1, 2, 3]                     # optional: principal moments; default from the shape
//     - name: front_left_wheel
//       parent: front_slider
//       wheel: {}                              # a wheel: the wheel_defaults, overridable here
//       translation: [0.43, 0.28, 0.19]
//       joint: {anchor: [0.43, 0.28, 0.19]}    # merged over wheel_defaults.joint
//   hitch: {body_a: tug, point_a: [..], body_b: towed, point_b: [..], stiffness: [Cx, Cy, Cz], damping: [..]}
//
// A vehicle file with `urdf:` (or `parts:`) takes its bodies from URDF files
// instead and adds wheels, drives and a hitch (docs/urdf.md,
// wtc/vehicle/urdf_file.hpp).
//
// Joints: {type: revolute|prismatic|ball|fixed, anchor (default: the body's
// translation), axis, limits: [lower, upper] (rad or m) or limits_deg
// (revolute), drive: {max_effort, max_speed, position_gain}}.
// Errors: InvalidInputError "<file>:<line>:<column>: bodies[3] (front_slider): joint: ..."
// at the offending node; unknown keys and keys given twice are errors. A
// value a wheel inherits is named at its line in wheel_defaults, "(inherited
// from wheel_defaults by wheel 'front_left_wheel')". Sizes (wheel radius and
// width, shapes) must be > 0 and at most wtc::kMaxLengthM.
#include <filesystem>

#include "wtc/vehicle/vehicle_description.hpp"

namespace wtc::vehicle {

/// Reads and validates the vehicle file.
vehicle::VehicleDescription loadVehicle(const std::filesystem::path& path);

}  // namespace wtc::vehicle
