// Vehicle description files (format in include/wtc/vehicle/vehicle_file.hpp and
// vehicles/README.md).
#include "wtc/vehicle/vehicle_file.hpp"

#include <numbers>

#include "io/file_support.hpp"
#include "io/yaml_reader.hpp"
#include "vehicle/vehicle_file_parts.hpp"
#include "wtc/base/error.hpp"

namespace wtc::vehicle {
namespace {

using io::detail::YamlError;
using io::detail::YamlReader;

constexpr double kDegree = std::numbers::pi / 180.0;

/// A mapping that overlays `over` on `base` (one level deep for nested
/// maps). Its entries are the nodes of both, not copies: their marks, and
/// so the places errors name, stay those of the file (a copy's are 1:1).
YAML::Node overlay(const YAML::Node& base, const YAML::Node& over) {
  YAML::Node out(YAML::NodeType::Map);
  // Keyed by the key nodes themselves (yaml-cpp finds a node key by
  // identity, a string key by value: each key is added once).
  if (base) {
    for (const auto& kv : base) {
      if (!over || !over[kv.first.as<std::string>()]) out[kv.first] = kv.second;
    }
  }
  if (!over) return out;
  for (const auto& kv : over) {
    const YAML::Node below = base ? base[kv.first.as<std::string>()] : YAML::Node();
    out[kv.first] = kv.second.IsMap() && below && below.IsMap() ? overlay(below, kv.second) : kv.second;
  }
  return out;
}

Shape readShape(const YamlReader& in, const YAML::Node& node) {
  in.requireMap(node, "shape");
  in.checkKeys(node, {"box", "cylinder", "sphere"});
  if (node.size() != 1) in.fail(node, "shape: give exactly one of box, cylinder, sphere");
  Shape s;
  if (const auto box = YamlReader::get(node, "box")) {
    s.kind = Shape::Kind::kBox;
    if (!box->IsSequence() || box->size() != 3) in.fail(*box, "shape.box: expected a list of 3 numbers");
    for (int k = 0; k < 3; ++k) s.box_size[k] = in.length((*box)[k], "shape.box[" + std::to_string(k) + "]");
  } else if (const auto cyl = YamlReader::get(node, "cylinder")) {
    in.requireMap(*cyl, "shape.cylinder");
    in.checkKeys(*cyl, {"radius", "length", "axis"});
    s.kind = Shape::Kind::kCylinder;
    s.radius = in.length(in.require(*cyl, "radius"), "shape.cylinder.radius");
    s.length = in.length(in.require(*cyl, "length"), "shape.cylinder.length");
    const std::string axis = YamlReader::get(*cyl, "axis") ? in.string((*cyl)["axis"], "axis") : "y";
    if (axis != "x" && axis != "y" && axis != "z")
      in.fail((*cyl)["axis"], "shape.cylinder.axis: '" + axis + "' is not x, y or z");
    s.cylinder_axis = axis[0] - 'x';
  } else {
    s.kind = Shape::Kind::kSphere;
    s.radius = in.length(node["sphere"], "shape.sphere");
  }
  return s;
}

}  // namespace

TyreParameters readTyre(const YamlReader& in, const YAML::Node& tyre_node, const TyreParameters& base) {
  const YAML::Node* tyre = &tyre_node;
  in.requireMap(*tyre, "wheel.tyre");
  in.checkKeys(
      *tyre, {"radial_stiffness", "radial_damping", "rolling_radius_ratio", "slip_speed_floor", "tangential_stiffness",
              "standstill_damping_ratio", "standstill_speed", "stability_fraction", "spin_floor"});
  TyreParameters t = base;
  t.radial_stiffness = in.number(*tyre, "radial_stiffness", t.radial_stiffness);
  t.radial_damping = in.number(*tyre, "radial_damping", t.radial_damping);
  t.rolling_radius_ratio = in.number(*tyre, "rolling_radius_ratio", t.rolling_radius_ratio);
  t.slip_speed_floor = in.number(*tyre, "slip_speed_floor", t.slip_speed_floor);
  t.tangential_stiffness = in.number(*tyre, "tangential_stiffness", t.tangential_stiffness);
  t.standstill_damping_ratio = in.number(*tyre, "standstill_damping_ratio", t.standstill_damping_ratio);
  t.standstill_speed = in.number(*tyre, "standstill_speed", t.standstill_speed);
  t.stability_fraction = in.number(*tyre, "stability_fraction", t.stability_fraction);
  t.spin_floor = in.number(*tyre, "spin_floor", t.spin_floor);
  try {
    validate(t, "wheel");
  } catch (const InvalidInputError& e) {
    // At the parameter the message names ("wheel: tyre radial_stiffness = -1 ...").
    const std::string message = e.what();
    for (const auto& entry : *tyre) {
      if (message.find("tyre " + entry.first.Scalar() + " = ") != std::string::npos) in.fail(entry.second, message);
    }
    in.fail(*tyre, message);
  }
  return t;
}

namespace {

Wheel readWheel(const YamlReader& in, const YAML::Node& node) {
  in.requireMap(node, "wheel");
  in.checkKeys(node, {"radius", "width", "axle", "tyre"});
  Wheel w;
  // Checked here, at the value: the disc's inertia made of a radius of 0
  // or 1e300 would be the first thing to fail, naming the inertia.
  w.geometry.free_radius = in.length(in.require(node, "radius"), "wheel.radius");
  w.geometry.tread_width = in.length(in.require(node, "width"), "wheel.width");
  if (const auto axle = YamlReader::get(node, "axle")) w.axle = in.vector<3>(*axle, "wheel.axle");
  if (const auto tyre = YamlReader::get(node, "tyre")) w.tyre = readTyre(in, *tyre, w.tyre);
  return w;
}

JointType readJointType(const YamlReader& in, const YAML::Node& node) {
  const std::string type = in.string(node, "joint.type");
  if (type == "revolute") return JointType::kRevolute;
  if (type == "prismatic") return JointType::kPrismatic;
  if (type == "ball") return JointType::kBall;
  if (type == "fixed") return JointType::kFixed;
  in.fail(node, "joint.type: '" + type + "' is not revolute, prismatic, ball or fixed");
}

Joint readJoint(const YamlReader& in, const YAML::Node& node, const Eigen::Vector3d& default_anchor) {
  in.requireMap(node, "joint");
  in.checkKeys(node, {"type", "anchor", "axis", "limits", "limits_deg", "drive"});
  Joint j;
  j.type = readJointType(in, in.require(node, "type"));
  j.anchor = YamlReader::get(node, "anchor") ? in.vector<3>(node["anchor"], "joint.anchor") : default_anchor;
  if (const auto axis = YamlReader::get(node, "axis")) j.axis = in.vector<3>(*axis, "joint.axis");
  const auto limits = YamlReader::get(node, "limits");
  const auto limits_deg = YamlReader::get(node, "limits_deg");
  if (limits && limits_deg) in.fail(node, "joint: give at most one of 'limits' and 'limits_deg'");
  if (limits_deg && j.type != JointType::kRevolute)
    in.fail(*limits_deg, "joint.limits_deg: only a revolute joint has angles");
  if (limits || limits_deg) {
    const double scale = limits_deg ? kDegree : 1.0;
    const Eigen::Vector2d l =
        in.vector<2>(limits ? *limits : *limits_deg, limits ? "joint.limits" : "joint.limits_deg");
    j.limits = JointLimits{scale * l.x(), scale * l.y()};
  }
  if (const auto drive = YamlReader::get(node, "drive")) {
    in.requireMap(*drive, "joint.drive");
    in.checkKeys(*drive, {"max_effort", "max_speed", "position_gain"});
    ActuatorLimits a;
    a.max_effort = in.number(in.require(*drive, "max_effort"), "joint.drive.max_effort");
    a.max_speed = in.number(in.require(*drive, "max_speed"), "joint.drive.max_speed");
    a.position_gain = in.number(*drive, "position_gain", a.position_gain);
    j.actuator = a;
  }
  return j;
}

Body readBody(const YamlReader& in, const YAML::Node& node, bool is_wheel, const VehicleDescription& so_far);

// A body as listed: a wheel gets wheel_defaults under its own keys.
Body readListedBody(const YamlReader& in, const YAML::Node& given, const YAML::Node& wheel_defaults,
                    const VehicleDescription& so_far) {
  in.requireMap(given, "body");
  const bool is_wheel = YamlReader::get(given, "wheel").has_value();
  const YAML::Node node = is_wheel ? overlay(wheel_defaults, given) : given;
  if (is_wheel) {
    // A value from wheel_defaults is named at its line there, as inherited;
    // a mapping merged of both has no line: the body's.
    const YAML::Node name = given["name"];
    const std::string wheel = name && name.IsScalar() ? "wheel '" + name.Scalar() + "'" : "this wheel";
    return readBody(in.withOrigin({.subtree = wheel_defaults, .label = "inherited from wheel_defaults by " + wheel})
                        .withFallback(given),
                    node, true, so_far);
  }
  return readBody(in, node, false, so_far);
}

Body readBody(const YamlReader& in, const YAML::Node& node, bool is_wheel, const VehicleDescription& so_far) {
  in.checkKeys(node, {"name", "mass", "shape", "inertia", "translation", "rotation", "wheel", "parent", "joint"});
  Body b;
  b.name = in.string(in.require(node, "name"), "name");
  b.mass = in.number(in.require(node, "mass"), "mass");
  b.pose = in.pose(node);
  if (const auto shape = YamlReader::get(node, "shape")) b.shape = readShape(in, *shape);
  if (is_wheel) {
    b.wheel = readWheel(in, node["wheel"]);
    // The tread as a solid disc, for the inertia; its ground contact is WTC's.
    if (b.shape.kind == Shape::Kind::kNone) {
      b.shape = Shape{.kind = Shape::Kind::kCylinder,
                      .radius = b.wheel->geometry.free_radius,
                      .length = b.wheel->geometry.tread_width,
                      .cylinder_axis = 1,
                      .hull_vertices = {}};
    }
  }
  if (const auto inertia = YamlReader::get(node, "inertia")) {
    b.inertia = in.vector<3>(*inertia, "inertia");
  } else if (b.shape.kind == Shape::Kind::kNone) {
    in.fail(node, "a body without a shape needs 'inertia'");
  } else if (std::isfinite(b.mass) && b.mass > 0.0) {
    b.inertia = solidInertia(b.shape, b.mass);
  }
  if (const auto parent = YamlReader::get(node, "parent")) {
    const std::string name = in.string(*parent, "parent");
    b.parent = so_far.find(name);
    if (b.parent < 0) in.fail(*parent, "parent '" + name + "' is not a body listed before this one");
    b.joint = readJoint(in, in.require(node, "joint"), b.pose.translation());
  } else if (YamlReader::get(node, "joint") && !is_wheel) {
    in.fail(node["joint"], "a root body (no parent) has no joint");
  }
  return b;
}

}  // namespace

void readBodyInto(const YamlReader& in, const YAML::Node& bodies, std::size_t i, const YAML::Node& defaults,
                  VehicleDescription& v) {
  // A list item that is not a mapping ("- name" cut short) has no keys to read.
  in.requireMap(bodies[i], ("bodies[" + std::to_string(i) + "]").c_str());
  const YAML::Node name = bodies[i]["name"];
  const YamlReader here = in.with("bodies[" + std::to_string(i) + "]" +
                                  (name && name.IsScalar() ? " (" + name.as<std::string>() + ")" : "") + ": ");
  Body body = readListedBody(here, bodies[i], defaults, v);
  if (v.find(body.name) >= 0) here.fail(bodies[i]["name"], "name '" + body.name + "' is used twice");
  try {
    validate(body, static_cast<int>(v.bodies.size()), "body");
  } catch (const InvalidInputError& e) {
    here.fail(bodies[i], e.what());
  }
  v.bodies.push_back(std::move(body));
}

Hitch readHitch(const YamlReader& in, const YAML::Node& node, const VehicleDescription& v) {
  in.requireMap(node, "hitch");
  in.checkKeys(node, {"body_a", "point_a", "body_b", "point_b", "stiffness", "damping"});
  Hitch h;
  for (const auto& [key, index] : {std::pair{"body_a", &h.body_a}, std::pair{"body_b", &h.body_b}}) {
    const YAML::Node n = in.require(node, key);
    *index = v.find(in.string(n, key));
    if (*index < 0) in.fail(n, std::string(key) + ": no body '" + n.as<std::string>() + "'");
  }
  h.point_a = in.vector<3>(in.require(node, "point_a"), "point_a");
  h.point_b = in.vector<3>(in.require(node, "point_b"), "point_b");
  h.stiffness = in.vector<3>(in.require(node, "stiffness"), "stiffness");
  h.damping = in.vector<3>(in.require(node, "damping"), "damping");
  return h;
}

namespace {

VehicleDescription readVehicleFile(const std::filesystem::path& path) {
  const YAML::Node root = io::detail::loadYamlFile(path);
  const YamlReader in(path);
  in.requireMap(root, "vehicle file");
  if (YamlReader::get(root, "urdf") || YamlReader::get(root, "parts")) return readUrdfVehicleFile(in, root);
  in.checkKeys(root, {"name", "description", "wheel_defaults", "bodies", "hitch"});
  VehicleDescription v;
  v.name = in.string(in.require(root, "name"), "name");
  const YAML::Node defaults = YamlReader::get(root, "wheel_defaults").value_or(YAML::Node(YAML::NodeType::Map));
  in.requireMap(defaults, "wheel_defaults");
  const YAML::Node bodies = in.require(root, "bodies");
  if (!bodies.IsSequence() || bodies.size() == 0) in.fail(bodies, "bodies: expected a non-empty list");
  for (std::size_t i = 0; i < bodies.size(); ++i) readBodyInto(in, bodies, i, defaults, v);
  if (const auto hitch = YamlReader::get(root, "hitch")) {
    v.hitch = readHitch(in.with("hitch: "), *hitch, v);
  }
  try {
    validate(v, path.string());
  } catch (const YamlError&) {
    throw;
  } catch (const InvalidInputError& e) {
    in.fail(root, e.what());
  }
  return v;
}

}  // namespace

VehicleDescription loadVehicle(const std::filesystem::path& path) {
  // A URDF alone lacks what makes a vehicle (which links are wheels, their
  // tyres, the drives): said plainly rather than as the XML's YAML error.
  if (path.extension() == ".urdf" || path.extension() == ".URDF") {
    throw InvalidInputError(path.string() +
                            ": a URDF, not a vehicle file: give a vehicle file (YAML) that names it (urdf: " +
                            path.filename().string() + ") and adds its wheels and drives (docs/urdf.md)");
  }
  return io::detail::withYamlErrors(path, [&] { return readVehicleFile(path); });
}

}  // namespace wtc::vehicle
