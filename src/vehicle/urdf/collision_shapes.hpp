#pragma once
// A URDF link's <collision> elements as WTC shapes (box, cylinder, sphere,
// a mesh as its convex hull), and a body's shape made of them: one part
// centred and along the body's axes is the plain Body::shape, anything
// else a compound. Private to the URDF reader.
#include <filesystem>
#include <vector>

#include <urdf_model/link.h>
#include <urdf_model/pose.h>
#include <Eigen/Geometry>

#include "wtc/vehicle/vehicle_description.hpp"

namespace wtc::vehicle::detail {

Eigen::Isometry3d toIsometry(const urdf::Pose& pose);

struct CollisionContext {
  std::filesystem::path urdf_file;                  ///< Relative mesh names resolve against its folder.
  std::vector<std::filesystem::path> package_path;  ///< For package:// URIs.
};

/// Appends `link`'s collision elements to `parts`, each at its pose in the
/// body frame B; X_BL is the link's frame in B. Throws InvalidInputError
/// naming the file and the link for a mesh that cannot be found or read,
/// or whose points span no volume.
void addCollisionShapes(const urdf::Link& link, const Eigen::Isometry3d& X_BL, const CollisionContext& context,
                        std::vector<ShapePart>& parts);

/// Sets body.shape (one box, cylinder or sphere centred on the centre of
/// mass and along the body's axes, within tolerance::kUrdfShapeOffsetM and
/// kUrdfAxisAlignment) or body.compound (anything else) from `parts`.
void setBodyShape(Body& body, std::vector<ShapePart> parts);

}  // namespace wtc::vehicle::detail
