#pragma once
// The normal a vehicle body's contact with a heightfield may have: one the
// field's surface can push along, not one that only a single cell of it can.
//
// A heightfield is two triangular prisms a cell; an engine's heightfield
// shape meets a body with each triangle, or its plane, alone (ODE's
// dHeightfield, MuJoCo's height field: one prism a triangle). Two faults
// follow (docs/terrain.md, "The bodies on a field"):
// - where a grid line runs along a box's side face, a wall between two
//   prisms (inside the ground) gives a contact pushing sideways, answered by
//   the opposite push from the wall's other side; their friction holds the
//   body;
// - where a box lies across a convex edge of the field (the sampled ledge's
//   top edge), ODE gave the contact the steeper face's normal: a wall at the
//   edge that the box, driven up over it, cannot pass.
//
// The normals the surface can give at a point p are the cone N spanned by
// the normals of its exposed faces through p: those of the pieces within
// reach of p, less the walls that another piece covers there (a face of the
// same plane with the opposite normal through p). On a face N is the face's
// normal, on an edge the normals between the two faces'. The contact's
// normal is chosen by the features that touch:
// - on an edge or a corner of the field (N more than one normal), where p
//   lies on the body's surface, a normal both surfaces can give: the engine's n when
//   it is in N and in the body's cone B (the inward normals of the body's
//   faces through p), else the generator of one cone that lies in the other
//   nearest n. A box's face across the field's edge gets the face's normal,
//   the one along which neither can enter the other, whatever the body's
//   motion;
// - otherwise the engine's normal n when it is in N (to within a milliradian:
//   roundoff), or its projection onto N, the nearest normal the surface can
//   give (Moreau: q = argmin |n - q| over N); one whose projection vanishes
//   (n orthogonal to N, or pointing into the ground) is no contact the
//   surface can make, and is left out.
// Bullet's btAdjustInternalEdgeContacts makes the second correction for one
// triangle mesh's internal edges; here the pieces are WTC's and so is the
// cone.
#include <optional>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "sim/placed_shape.hpp"
#include "wtc/geometry/convex_polyhedron.hpp"
#include "wtc/terrain/terrain.hpp"

namespace wtc::sim {

class TerrainNormalCone {
 public:
  /// `terrain` must outlive this.
  explicit TerrainNormalCone(const Terrain& terrain);

  /// How far from p_W a face may pass and still be through it, for a
  /// contact of penetration `depth` (m): max(depth, 0) +
  /// kTerrainFaceReachM, plus kTerrainFaceReachPerM of p_W's largest
  /// coordinate.
  static double reach(const Eigen::Vector3d& p_W, double depth);

  /// The normal for a contact of a body with the terrain at p_W (world, m)
  /// with unit normal n_W pointing out of the terrain (into the body) and
  /// penetration `depth` (m); `body_W`, the inward normals (out of the
  /// terrain) of the body's faces through p_W. Where the cone of the
  /// terrain's faces through p_W has more than one normal and the two cones
  /// meet, n_W when it is in both, else the generator of one in the other
  /// nearest n_W; else n_W itself when it is in the cone (to within
  /// kTerrainNormalToleranceRad) or when no face is within reach (nothing to
  /// correct it by); its unit projection onto the cone when outside;
  /// nullopt when that projection vanishes. Allocates nothing once its
  /// scratch has grown to the pieces around a point.
  std::optional<Eigen::Vector3d> normal(const Eigen::Vector3d& p_W, const Eigen::Vector3d& n_W, double depth,
                                        std::span<const Eigen::Vector3d> body_W);
  /// The same for a body of shape `body`: its faces through p_W within
  /// reach(p_W, depth).
  std::optional<Eigen::Vector3d> normal(const Eigen::Vector3d& p_W, const Eigen::Vector3d& n_W, double depth,
                                        const PlacedShape& body);

 private:
  // A face of a piece within reach of the point: n . x = d (world, m).
  struct Face {
    Eigen::Vector3d n;
    double d = 0.0;
    int piece = 0;  // index into the query's pieces
  };

  void collectFaces(const Eigen::Vector3d& p_W, double reach);
  void collectExposedNormals(double reach);

  const Terrain& terrain_;
  std::vector<PieceId> pieces_;              // scratch: the pieces near the point
  std::optional<ConvexPolyhedron> formed_;   // scratch: a compact field's piece
  std::vector<Face> faces_;                  // scratch: their faces within reach
  std::vector<Eigen::Vector3d> generators_;  // scratch: the exposed faces' normals, each once
};

/// The projection of n onto the cone of nonnegative combinations of
/// `generators` (unit vectors): the point of the cone nearest n.
Eigen::Vector3d projectOntoCone(const Eigen::Vector3d& n, std::span<const Eigen::Vector3d> generators);

/// Whether n lies in that cone, to within kTerrainNormalToleranceRad.
bool inCone(const Eigen::Vector3d& n, std::span<const Eigen::Vector3d> generators);

}  // namespace wtc::sim
