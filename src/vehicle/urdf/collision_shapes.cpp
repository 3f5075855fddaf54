// URDF collision elements to WTC shapes (collision_shapes.hpp).
#include "collision_shapes.hpp"

#include <cmath>

#include "wtc/base/error.hpp"
#include "wtc/base/tolerances.hpp"
#include "wtc/geometry/convex_polyhedron.hpp"
#include "wtc/io/mesh_file.hpp"
#include "wtc/vehicle/package_path.hpp"

namespace wtc::vehicle::detail {
namespace {

// A mesh's vertices, scaled by its <mesh scale>, reduced to their convex
// hull (Qhull, through ConvexPolyhedron): WTC's bodies collide as convex
// parts, and the hull is what a mesh's surface bounds.
Shape meshHull(const urdf::Mesh& mesh, const std::string& link, const CollisionContext& context) {
  const std::string where = context.urdf_file.string() + ": link '" + link + "'";
  const std::filesystem::path path =
      resolveResourceUri(mesh.filename, context.urdf_file.parent_path(), context.package_path, where);
  std::vector<Eigen::Vector3d> points;
  try {
    for (const TriangleMesh& part : io::readMeshFile(path).parts) {
      for (const Eigen::Vector3d& p : part.vertices)
        points.push_back(p.cwiseProduct(Eigen::Vector3d(mesh.scale.x, mesh.scale.y, mesh.scale.z)));
    }
    const ConvexPolyhedron hull = ConvexPolyhedron::fromPoints(points);
    // A mesh in one plane bounds no volume: ODE ignored it, Bullet threw the
    // robot from it in one step (issue 57 row 2).
    if (hull.isFlat()) {
      throw InvalidInputError("its " + std::to_string(hull.vertexCount()) +
                              " hull vertices lie in one plane: a collision mesh must enclose a volume (a plate "
                              "needs a thickness; a <box> is the exact shape for one)");
    }
    Shape s;
    s.kind = Shape::Kind::kHull;
    for (int i = 0; i < hull.vertexCount(); ++i) s.hull_vertices.push_back(hull.vertex(i));
    return s;
  } catch (const InvalidInputError& e) {
    throw InvalidInputError(where + ": mesh " + mesh.filename + " (" + path.string() + "): " + e.what());
  }
}

Shape toShape(const urdf::Geometry& g, const std::string& link, const CollisionContext& context) {
  Shape s;
  switch (g.type) {
    case urdf::Geometry::BOX: {
      const auto& box = static_cast<const urdf::Box&>(g);
      s.kind = Shape::Kind::kBox;
      s.box_size = Eigen::Vector3d(box.dim.x, box.dim.y, box.dim.z);
      break;
    }
    case urdf::Geometry::CYLINDER: {
      const auto& cylinder = static_cast<const urdf::Cylinder&>(g);
      s.kind = Shape::Kind::kCylinder;
      s.radius = cylinder.radius;
      s.length = cylinder.length;
      s.cylinder_axis = 2;  // URDF's cylinder lies along its own z
      break;
    }
    case urdf::Geometry::SPHERE:
      s.kind = Shape::Kind::kSphere;
      s.radius = static_cast<const urdf::Sphere&>(g).radius;
      break;
    case urdf::Geometry::MESH:
      return meshHull(static_cast<const urdf::Mesh&>(g), link, context);
  }
  return s;
}

// The body axis that `direction` (a unit vector in B) lies along within
// tolerance::kUrdfAxisAlignment, or -1.
int alongAxis(const Eigen::Vector3d& direction) {
  for (int k = 0; k < 3; ++k) {
    if (std::abs(direction[k]) >= 1.0 - tolerance::kUrdfAxisAlignment) return k;
  }
  return -1;
}

// The part as a plain shape centred and aligned in B, if it is one.
std::optional<Shape> asAligned(const ShapePart& part) {
  if (part.pose_BS.translation().norm() > tolerance::kUrdfShapeOffsetM) return std::nullopt;
  const Eigen::Matrix3d R = part.pose_BS.linear();
  Shape s = part.shape;
  switch (s.kind) {
    case Shape::Kind::kSphere:
      return s;
    case Shape::Kind::kCylinder: {
      const int axis = alongAxis(R.col(s.cylinder_axis));
      if (axis < 0) return std::nullopt;
      s.cylinder_axis = axis;
      return s;
    }
    case Shape::Kind::kBox: {
      // Each of the box's edges along one of B's axes: its sizes permuted.
      for (int k = 0; k < 3; ++k) {
        const int axis = alongAxis(R.col(k));
        if (axis < 0) return std::nullopt;
        s.box_size[axis] = part.shape.box_size[k];
      }
      return s;
    }
    case Shape::Kind::kHull:
    case Shape::Kind::kNone:
      break;
  }
  return std::nullopt;
}

}  // namespace

Eigen::Isometry3d toIsometry(const urdf::Pose& pose) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = Eigen::Quaterniond(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z)
                   .normalized()
                   .toRotationMatrix();
  X.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  return X;
}

void addCollisionShapes(const urdf::Link& link, const Eigen::Isometry3d& X_BL, const CollisionContext& context,
                        std::vector<ShapePart>& parts) {
  std::vector<urdf::CollisionSharedPtr> elements = link.collision_array;
  if (elements.empty() && link.collision) elements.push_back(link.collision);
  for (const urdf::CollisionSharedPtr& c : elements) {
    if (!c || !c->geometry) continue;
    parts.push_back(
        ShapePart{.shape = toShape(*c->geometry, link.name, context), .pose_BS = X_BL * toIsometry(c->origin)});
  }
}

void setBodyShape(Body& body, std::vector<ShapePart> parts) {
  if (parts.size() == 1) {
    if (const std::optional<Shape> plain = asAligned(parts[0])) {
      body.shape = *plain;
      return;
    }
  }
  body.compound = std::move(parts);
}

}  // namespace wtc::vehicle::detail
