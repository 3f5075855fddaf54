// A vehicle file that names a URDF (docs/urdf.md): the URDF gives the
// bodies, joints, limits, inertias and collision shapes; the file adds what
// URDF does not say: which links are WTC wheels and their tyres, which
// joints are driven and how, the hitch.
//
//   name: six_wheel_robot
//   urdf: six_wheel_robot.urdf         # relative to this file; or, for several trees:
//   # parts: [{urdf: a.urdf}, {bodies: [...YAML bodies...]}, {urdf: b.urdf}]   (bodies in that order)
//   package_path: [.]                  # optional: folders for package:// (relative to this file)
//   wheel_defaults: {tyre: {...}}      # optional: radius, width, tyre for every wheel
//   wheels:
//     - link: front_left_wheel         # radius, width, axle from its cylinder and joint
//       tyre: {radial_stiffness: 1.0e5}
//   drives:                            # limits from the joint's <limit effort velocity>
//     front_left_wheel_joint: {}       # overridable: max_effort, max_speed; position_gain
//   hitch: {...}                       # as in the YAML form
#include <cmath>

#include "vehicle/vehicle_file_parts.hpp"
#include "wtc/base/error.hpp"
#include "wtc/base/tolerances.hpp"
#include "wtc/vehicle/package_path.hpp"
#include "wtc/vehicle/urdf_file.hpp"

namespace wtc::vehicle {
namespace {

using io::detail::YamlReader;

// The mechanism of one URDF, or of several URDFs and YAML bodies in order
// (`parts:`): where each link and joint came from, for messages.
struct Mechanism {
  VehicleDescription vehicle;
  std::map<std::string, int> link_body;
  std::map<std::string, int> joint_body;
  std::map<std::string, UrdfDriveLimits> drive_limits;
  std::map<std::string, std::filesystem::path> link_file;
  std::map<std::string, std::filesystem::path> joint_file;
  std::string files;  ///< The URDF files, for "not a link of ..."
};

// Appends a URDF's bodies after those read so far (indices shifted).
void append(const YamlReader& in, const YAML::Node& node, const UrdfModel& m, Mechanism& out) {
  const int offset = static_cast<int>(out.vehicle.bodies.size());
  for (Body b : m.vehicle.bodies) {
    if (out.vehicle.find(b.name) >= 0) {
      in.fail(node, m.file.string() + ": link '" + b.name + "' has the name of a body read before it");
    }
    if (b.parent >= 0) b.parent += offset;
    if (b.joint.mimic) b.joint.mimic->master += offset;
    out.vehicle.bodies.push_back(std::move(b));
  }
  for (const auto& [link, body] : m.link_body) {
    out.link_body[link] = body + offset;
    out.link_file[link] = m.file;
  }
  for (const auto& [joint, body] : m.joint_body) {
    out.joint_body[joint] = body + offset;
    out.joint_file[joint] = m.file;
  }
  out.drive_limits.insert(m.drive_limits.begin(), m.drive_limits.end());
  out.files += (out.files.empty() ? "" : ", ") + m.file.string();
}

struct WheelSizes {
  std::optional<double> radius;
  std::optional<double> width;
  TyreParameters tyre;
};

// radius, width and tyre of a wheel entry or wheel_defaults, over `base`.
WheelSizes readWheelSizes(const YamlReader& in, const YAML::Node& node, WheelSizes base) {
  if (const auto r = YamlReader::get(node, "radius")) base.radius = in.length(*r, "radius");
  if (const auto w = YamlReader::get(node, "width")) base.width = in.length(*w, "width");
  if (const auto t = YamlReader::get(node, "tyre")) base.tyre = readTyre(in, *t, base.tyre);
  return base;
}

// The wheel on `body` (link `link`): its radius and width from the link's
// cylinder unless given, its axle the joint's axis in the body frame.
Wheel makeWheel(const YamlReader& in, const YAML::Node& node, const Mechanism& urdf, const Body& body,
                const std::string& link, const WheelSizes& sizes) {
  const std::string where = urdf.link_file.at(link).string() + ": link '" + link + "'";
  if (body.parent < 0 || body.joint.type != JointType::kRevolute) {
    in.fail(node, where + " is not on a revolute or continuous joint: a wheel turns on one");
  }
  const Eigen::Vector3d axle = (body.pose.linear().transpose() * body.joint.axis).normalized();
  // The link's cylinder: the plain shape, or the one cylinder of a compound.
  std::vector<ShapePart> cylinders;
  if (body.shape.kind == Shape::Kind::kCylinder) cylinders.push_back({body.shape, Eigen::Isometry3d::Identity()});
  for (const ShapePart& part : body.compound) {
    if (part.shape.kind == Shape::Kind::kCylinder) cylinders.push_back(part);
  }
  Wheel w;
  w.axle = axle;
  w.tyre = sizes.tyre;
  if (cylinders.size() > 1 && !(sizes.radius && sizes.width)) {
    in.fail(node, where + " has " + std::to_string(cylinders.size()) +
                      " collision cylinders: give the wheel's radius and width");
  }
  if (cylinders.empty()) {
    if (!sizes.radius || !sizes.width) {
      in.fail(node, where +
                        " has no cylinder (<collision><cylinder>) and the vehicle file gives no radius and width "
                        "for it");
    }
  } else {
    const ShapePart& c = cylinders[0];
    const Eigen::Vector3d along = c.pose_BS.linear() * Eigen::Vector3d::Unit(c.shape.cylinder_axis);
    if (along.cross(axle).norm() > tolerance::kUrdfWheelAxisSine) {
      in.fail(node, where + ": its cylinder's axis " + formatVector(body.pose.linear() * along) +
                        " is not along its joint '" + body.joint.name + "''s axis " + formatVector(body.joint.axis) +
                        " (in the root link's frame): a wheel rolls about its cylinder's axis");
    }
    if (c.pose_BS.translation().norm() > tolerance::kUrdfWheelCentreM) {
      in.fail(node, where + ": its cylinder's centre is " + formatNumber(c.pose_BS.translation().norm()) +
                        " m from the link's centre of mass: WTC's wheel is centred on its body");
    }
    w.geometry.free_radius = c.shape.radius;
    w.geometry.tread_width = c.shape.length;
  }
  if (sizes.radius) w.geometry.free_radius = *sizes.radius;
  if (sizes.width) w.geometry.tread_width = *sizes.width;
  return w;
}

void readWheels(const YamlReader& in, const YAML::Node& root, const Mechanism& urdf, VehicleDescription& v) {
  WheelSizes defaults;
  if (const auto d = YamlReader::get(root, "wheel_defaults")) {
    in.requireMap(*d, "wheel_defaults");
    in.checkKeys(*d, {"radius", "width", "tyre"});
    defaults = readWheelSizes(in.with("wheel_defaults: "), *d, defaults);
  }
  const auto wheels = YamlReader::get(root, "wheels");
  if (!wheels) return;
  if (!wheels->IsSequence()) in.fail(*wheels, "wheels: expected a list of {link: ...}");
  for (std::size_t i = 0; i < wheels->size(); ++i) {
    const YAML::Node node = (*wheels)[i];
    const YamlReader here = in.with("wheels[" + std::to_string(i) + "]: ");
    here.requireMap(node, "wheel");
    here.checkKeys(node, {"link", "radius", "width", "tyre"});
    const YAML::Node link_node = here.require(node, "link");
    const std::string link = here.string(link_node, "link");
    const auto it = urdf.link_body.find(link);
    if (it == urdf.link_body.end()) here.fail(link_node, "link '" + link + "' is not a link of " + urdf.files);
    Body& body = v.bodies[it->second];
    if (body.name != link) {
      here.fail(link_node, "link '" + link + "' is merged into '" + body.name + "' by a fixed joint in " +
                               urdf.link_file.at(link).string() + ": a wheel turns on a joint of its own");
    }
    if (body.wheel) here.fail(link_node, "link '" + link + "' is named a wheel twice");
    body.wheel = makeWheel(here, node, urdf, body, link, readWheelSizes(here, node, defaults));
  }
}

void readDrives(const YamlReader& in, const YAML::Node& root, const Mechanism& urdf, VehicleDescription& v) {
  const auto drives = YamlReader::get(root, "drives");
  if (!drives) return;
  in.requireMap(*drives, "drives");
  for (const auto& kv : *drives) {
    const std::string joint = kv.first.as<std::string>();
    const YamlReader here = in.with("drives: " + joint + ": ");
    const auto it = urdf.joint_body.find(joint);
    if (it == urdf.joint_body.end()) {
      here.fail(kv.first, "joint '" + joint + "' is not a revolute, continuous or prismatic joint of " + urdf.files);
    }
    const YAML::Node node = kv.second.IsNull() ? YAML::Node(YAML::NodeType::Map) : kv.second;
    here.requireMap(node, "drive");
    here.checkKeys(node, {"max_effort", "max_speed", "position_gain"});
    const UrdfDriveLimits& limits = urdf.drive_limits.at(joint);
    ActuatorLimits a;
    a.max_effort = here.number(node, "max_effort", limits.effort);
    a.max_speed = here.number(node, "max_speed", limits.velocity);
    a.position_gain = here.number(node, "position_gain", a.position_gain);
    if (!(a.max_effort > 0.0) || !(a.max_speed > 0.0)) {
      here.fail(kv.first, "joint '" + joint + "' has no <limit effort velocity> in " +
                              urdf.joint_file.at(joint).string() + " (effort " + formatNumber(limits.effort) +
                              ", velocity " + formatNumber(limits.velocity) +
                              "): give the drive's max_effort and max_speed");
    }
    v.bodies[it->second].joint.actuator = a;
  }
}

}  // namespace

VehicleDescription readUrdfVehicleFile(const YamlReader& in, const YAML::Node& root) {
  in.checkKeys(root,
               {"name", "description", "urdf", "parts", "package_path", "wheel_defaults", "wheels", "drives", "hitch"});
  const std::filesystem::path dir = in.path().parent_path();
  UrdfOptions options;
  options.package_path = packagePathFromEnvironment();
  if (const auto paths = YamlReader::get(root, "package_path")) {
    if (!paths->IsSequence()) in.fail(*paths, "package_path: expected a list of folders");
    for (const auto& p : *paths)
      options.package_path.push_back((dir / in.string(p, "package_path")).lexically_normal());
  }
  const auto readOne = [&](const YAML::Node& node, Mechanism& out) {
    UrdfModel m;
    try {
      m = readUrdf((dir / in.string(node, "urdf")).lexically_normal(), options);
    } catch (const InvalidInputError& e) {
      in.fail(node, e.what());
    }
    append(in, node, m, out);
  };
  Mechanism urdf;
  const auto one = YamlReader::get(root, "urdf");
  const auto parts = YamlReader::get(root, "parts");
  if (one && parts) in.fail(*parts, "give one of 'urdf' (one URDF) and 'parts' (URDFs and bodies in order)");
  if (one) {
    readOne(*one, urdf);
  } else {
    // Parts in order, each a URDF ({urdf: file}) or YAML bodies ({bodies: [...]}, as in the YAML form, without
    // wheel_defaults, parents among the bodies before them): the bodies' order is the parts'.
    if (!parts->IsSequence() || parts->size() == 0) in.fail(*parts, "parts: expected a non-empty list");
    for (std::size_t i = 0; i < parts->size(); ++i) {
      const YAML::Node part = (*parts)[i];
      const YamlReader here = in.with("parts[" + std::to_string(i) + "]: ");
      here.requireMap(part, "part");
      here.checkKeys(part, {"urdf", "bodies"});
      if (part.size() != 1) here.fail(part, "give one of 'urdf' and 'bodies'");
      if (const auto file = YamlReader::get(part, "urdf")) {
        readOne(*file, urdf);
        continue;
      }
      const YAML::Node bodies = part["bodies"];
      if (!bodies.IsSequence() || bodies.size() == 0) here.fail(bodies, "bodies: expected a non-empty list");
      for (std::size_t k = 0; k < bodies.size(); ++k) {
        readBodyInto(here, bodies, k, YAML::Node(YAML::NodeType::Map), urdf.vehicle);
      }
    }
  }
  VehicleDescription v = urdf.vehicle;
  v.name = in.string(in.require(root, "name"), "name");
  readWheels(in, root, urdf, v);
  readDrives(in, root, urdf, v);
  if (const auto hitch = YamlReader::get(root, "hitch")) v.hitch = readHitch(in.with("hitch: "), *hitch, v);
  try {
    validate(v, in.path().string());
  } catch (const InvalidInputError& e) {
    in.fail(root, e.what());
  }
  return v;
}

}  // namespace wtc::vehicle
