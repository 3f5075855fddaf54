#pragma once
// A vehicle's mechanism from a URDF file (read with urdfdom), as a
// wtc::vehicle::VehicleDescription without wheels or drives: a vehicle file
// with `urdf:` (vehicle_file.hpp) names the wheels and the drives.
// docs/urdf.md has the mapping table; in short:
//
// - Links are bodies, in the order of the <link> elements in the file (a
//   parent before its children), so that a URDF written in a YAML vehicle's
//   order gives its CSV series' column order. The root link's frame is the
//   vehicle frame V.
// - A link on a fixed joint is merged into its parent (mass, centre of mass,
//   the tensor by the parallel-axis theorem, its collision elements), as
//   URDF tools lump them; its children hang from the merged body.
// - <inertial>: the body's frame is the link frame times the inertial
//   origin; a tensor with products of inertia is rotated to its principal
//   axes (the body frame then turns with them: principal_inertia.hpp).
// - Joints: revolute (with limits), continuous (revolute, no limits),
//   prismatic, fixed; origins and axes composed into V; <limit effort
//   velocity> kept per joint for the drives the vehicle file names;
//   <mimic> as Joint::mimic.
// - <collision>: one box, cylinder or sphere at the centre of mass and
//   along the body's axes is Body::shape; anything else (several elements,
//   an offset or turned one, a mesh taken as its convex hull) is
//   Body::compound.
//
// Refused (InvalidInputError "<file>: link 'x' ..." or "joint 'y' ..."):
// what urdfdom refuses (its message), what it logs as an error while still
// returning a model (an <inertial> without <mass>), floating and planar
// joints, closed chains (a link the child of two joints, a cycle), a link
// without mass on a moving joint, a mass or inertia that is not positive
// (including a principal moment, and the triangle inequality), a mimic of
// a joint the file lacks, a package:// URI found on no package path.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "wtc/vehicle/vehicle_description.hpp"

namespace wtc::vehicle {

struct UrdfOptions {
  /// Folders to resolve package://NAME/REST in, in order: an entry DIR is
  /// the package NAME when DIR/package.xml names it, else DIR/NAME when
  /// that folder exists (package_path.hpp).
  std::vector<std::filesystem::path> package_path;
};

/// A joint's <limit effort velocity> (N m or N; rad/s or m/s); 0 when the
/// joint has no <limit>.
struct UrdfDriveLimits {
  double effort = 0.0;
  double velocity = 0.0;
};

struct UrdfModel {
  std::filesystem::path file;
  VehicleDescription vehicle;                           ///< Bodies and joints; no wheels, no drives, no hitch.
  std::map<std::string, int> link_body;                 ///< Every link to its body (a merged link to its parent's).
  std::map<std::string, int> joint_body;                ///< Every non-fixed joint to the body it holds.
  std::map<std::string, UrdfDriveLimits> drive_limits;  ///< Per non-fixed joint.
};

/// Reads `file`. Throws InvalidInputError naming the file and the link or
/// joint (see above).
UrdfModel readUrdf(const std::filesystem::path& file, const UrdfOptions& options = {});

}  // namespace wtc::vehicle
