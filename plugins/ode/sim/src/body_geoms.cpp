// A body's shape as ODE geoms (body_geoms.hpp).
#include "body_geoms.hpp"

#include <cmath>
#include <limits>
#include <optional>

#include "src/conversions.hpp"
#include "wtc/geometry/convex_polyhedron.hpp"

namespace wtc::ode {
namespace {

using vehicle::Shape;

// A convex hull as dCreateConvex wants it: points and planes relative to
// the hull's centroid (ODE wants its convex geom's origin inside, every
// plane offset >= 0), as the plugin's terrain pieces are made
// (plugins/ode/src/terrain_geoms.cpp). Returns the geom; `centre` is the
// centroid in the shape's frame, where the geom's origin must sit.
dGeomID makeConvex(const ConvexPolyhedron& hull, dSpaceID space, std::deque<ConvexGeomData>& store,
                   Eigen::Vector3d& centre) {
  centre = hull.centroid();
  ConvexGeomData& data = store.emplace_back();
  for (int v = 0; v < hull.vertexCount(); ++v) {
    const Eigen::Vector3d p = hull.vertex(v) - centre;
    data.numbers.insert(data.numbers.end(), {p.x(), p.y(), p.z()});
  }
  for (int f = 0; f < hull.faceCount(); ++f) {
    const Eigen::Vector3d n = hull.faceNormal(f);
    data.numbers.insert(data.numbers.end(), {n.x(), n.y(), n.z(), hull.faceOffset(f) - n.dot(centre)});
    const auto face = hull.faceVertices(f);
    data.polygons.push_back(static_cast<unsigned int>(face.size()));
    data.polygons.insert(data.polygons.end(), face.begin(), face.end());
  }
  const dReal* points = data.numbers.data();
  return dCreateConvex(space, points + 3 * hull.vertexCount(), static_cast<unsigned int>(hull.faceCount()), points,
                       static_cast<unsigned int>(hull.vertexCount()), data.polygons.data());
}

// A hull that is a box (six faces in three opposite pairs about orthogonal
// axes, every vertex at a corner): its size and its pose in the shape's
// frame. ODE collides a convex geom against the terrain's triangle meshes
// through libccd's GJK-EPA, one contact a pair; a thin one (a skid plate
// given as a mesh) lands on one point, rocks, and when EPA takes the wrong
// face, is thrown (docs/urdf.md, "Thin meshes in ODE", has the figures).
// ODE's box collider gives the face's contacts and holds it, as a URDF
// <box> does; so a box given as a mesh is one.
struct HullBox {
  Eigen::Vector3d size;
  Eigen::Isometry3d pose{Eigen::Isometry3d::Identity()};
};

std::optional<HullBox> boxOf(const ConvexPolyhedron& hull) {
  // Normals' cosines and corners (relative to the box's size) within a
  // float's precision: a box a CAD program wrote in single precision is one.
  constexpr double kRelativeTolerance = 1e-6;
  if (hull.faceCount() != 6 || hull.vertexCount() != 8) return std::nullopt;
  Eigen::Matrix3d axes;
  int found = 0;
  for (int f = 0; f < 6 && found < 3; ++f) {
    const Eigen::Vector3d n = hull.faceNormal(f);
    bool known = false;
    for (int k = 0; k < found; ++k) known = known || std::abs(std::abs(axes.col(k).dot(n)) - 1.0) < kRelativeTolerance;
    if (!known) axes.col(found++) = n;
  }
  if (found != 3 || std::abs(axes.col(0).dot(axes.col(1))) > kRelativeTolerance ||
      std::abs(axes.col(0).dot(axes.col(2))) > kRelativeTolerance ||
      std::abs(axes.col(1).dot(axes.col(2))) > kRelativeTolerance) {
    return std::nullopt;
  }
  axes.col(2) = axes.col(0).cross(axes.col(1)).normalized();  // right-handed
  Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (int v = 0; v < 8; ++v) {
    const Eigen::Vector3d p = axes.transpose() * hull.vertex(v);
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  const double tolerance = kRelativeTolerance * (high - low).maxCoeff();
  for (int v = 0; v < 8; ++v) {
    const Eigen::Vector3d p = axes.transpose() * hull.vertex(v);
    for (int i = 0; i < 3; ++i) {
      if (std::abs(p[i] - low[i]) > tolerance && std::abs(p[i] - high[i]) > tolerance) return std::nullopt;
    }
  }
  HullBox box{.size = high - low};
  box.pose.linear() = axes;
  box.pose.translation() = axes * (0.5 * (low + high));
  return box;
}

// One part's geom on `b`, at pose_BS from the body's centre of mass.
dGeomID addPart(const Shape& s, const Eigen::Isometry3d& pose_BS, dSpaceID space, dBodyID b,
                std::deque<ConvexGeomData>& store) {
  dGeomID geom = nullptr;
  Eigen::Isometry3d offset = pose_BS;
  switch (s.kind) {
    case Shape::Kind::kBox:
      geom = dCreateBox(space, s.box_size.x(), s.box_size.y(), s.box_size.z());
      break;
    case Shape::Kind::kCylinder:
      // ODE's cylinder lies along its z: turned onto the shape's axis.
      geom = dCreateCylinder(space, s.radius, s.length);
      offset.linear() = pose_BS.linear() * Eigen::Matrix3d(Eigen::Quaterniond::FromTwoVectors(
                                               Eigen::Vector3d::UnitZ(), Eigen::Vector3d::Unit(s.cylinder_axis)));
      break;
    case Shape::Kind::kSphere:
      geom = dCreateSphere(space, s.radius);
      break;
    case Shape::Kind::kHull: {
      const ConvexPolyhedron hull = ConvexPolyhedron::fromPoints(s.hull_vertices);
      if (const auto box = boxOf(hull)) {
        geom = dCreateBox(space, box->size.x(), box->size.y(), box->size.z());
        offset = pose_BS * box->pose;
        break;
      }
      Eigen::Vector3d centre;
      geom = makeConvex(hull, space, store, centre);
      offset.translation() = pose_BS * centre;
      break;
    }
    case Shape::Kind::kNone:
      return nullptr;
  }
  dGeomSetBody(geom, b);
  if (!offset.translation().isZero(0.0)) {
    dGeomSetOffsetPosition(geom, offset.translation().x(), offset.translation().y(), offset.translation().z());
  }
  // A cylinder's turn is always set (a YAML body's cylinder was turned so
  // even along z: its runs stay as they were).
  if (s.kind == Shape::Kind::kCylinder || !offset.linear().isIdentity(0.0)) {
    dMatrix3 m;
    toOde(Eigen::Matrix3d(offset.linear()), m);
    dGeomSetOffsetRotation(geom, m);
  }
  return geom;
}

}  // namespace

dGeomID addBodyGeoms(const vehicle::Body& body, dSpaceID space, dBodyID b, std::deque<ConvexGeomData>& convex) {
  if (body.compound.empty()) return addPart(body.shape, Eigen::Isometry3d::Identity(), space, b, convex);
  dGeomID first = nullptr;
  for (const vehicle::ShapePart& part : body.compound) {
    const dGeomID geom = addPart(part.shape, part.pose_BS, space, b, convex);
    if (first == nullptr) first = geom;
  }
  return first;
}

sim::PlacedShape placedShape(dGeomID geom) {
  sim::PlacedShape shape;
  shape.pose.linear() = rotationFromOde(dGeomGetRotation(geom));
  shape.pose.translation() = toEigen(dGeomGetPosition(geom));
  switch (dGeomGetClass(geom)) {
    case dBoxClass: {
      dVector3 lengths;
      dGeomBoxGetLengths(geom, lengths);
      shape.kind = sim::PlacedShape::Kind::kBox;
      shape.half_extents = 0.5 * Eigen::Vector3d(lengths[0], lengths[1], lengths[2]);
      break;
    }
    case dSphereClass:
      shape.kind = sim::PlacedShape::Kind::kSphere;
      shape.radius = dGeomSphereGetRadius(geom);
      break;
    case dCylinderClass: {
      dReal radius = 0.0, length = 0.0;
      dGeomCylinderGetParams(geom, &radius, &length);
      shape.kind = sim::PlacedShape::Kind::kCylinder;
      shape.radius = radius;
      shape.half_length = 0.5 * length;
      break;
    }
    default:
      break;
  }
  return shape;
}

}  // namespace wtc::ode
