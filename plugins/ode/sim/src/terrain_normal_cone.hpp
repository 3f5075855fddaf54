#pragma once
// The normal a vehicle body's contact with the terrain may have: one the
// terrain's surface can push along, not one that only a single piece of it
// can.
//
// WTC's terrain is a union of convex pieces (a heightfield is two
// triangular prisms a cell). ODE collides a body with each piece alone, and
// a piece's faces include walls it shares with its neighbours, inside the
// terrain. Where a body touches the terrain at a point of such a wall (a
// grid line of a heightfield running along a box's side face, the box
// across the field's top edge), a piece's separating axis can be the wall's
// normal or an edge cross product with one of the walls' edges: a contact
// pushing sideways, which the piece on the wall's other side answers with
// the opposite push. Their friction holds the body (docs/accuracy-study.md,
// "ODE's climb on 2 and 1 cm heightfields"). No such normal exists on the
// terrain's surface.
//
// The normals the terrain's surface can give at a point p are the cone N
// spanned by the normals of its exposed faces through p: those of the
// pieces within reach of p, less the walls that another piece covers there
// (a face of the same plane with the opposite normal through p). On a face
// N is the face's normal, on a convex edge the normals between the two
// faces', at a concave crease both faces' (and those between). A contact's
// normal n in N (to within a milliradian: roundoff) is kept as it is; one
// outside N is projected onto it, the nearest normal the surface can give
// (Moreau: q = argmin |n - q| over N); one whose projection vanishes (n
// orthogonal to N, or pointing into the terrain) is no contact the surface
// can make, and is left out. Bullet's
// btAdjustInternalEdgeContacts makes the same correction for one triangle
// mesh's internal edges; here the pieces are WTC's and so is the cone.
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "wtc/geometry/convex_polyhedron.hpp"
#include "wtc/terrain/terrain.hpp"

namespace wtc::ode {

class TerrainNormalCone {
 public:
  /// `terrain` must outlive this.
  explicit TerrainNormalCone(const Terrain& terrain);

  /// The normal for a contact of a body with the terrain at p_W (world, m)
  /// with unit normal n_W pointing out of the terrain (into the body) and
  /// penetration `depth` (m). The cone is that of the terrain's exposed
  /// faces within reach of p_W: max(depth, 0) + kTerrainFaceReachM, plus
  /// kTerrainFaceReachPerM of p_W's largest coordinate. Returns n_W itself
  /// when it is in the cone (to within kTerrainNormalToleranceRad) or when
  /// no face is within reach (nothing to correct it by); its unit
  /// projection onto the cone when outside; nullopt when that projection
  /// vanishes. Allocates nothing on stored pieces once its scratch has
  /// grown to those around a point (a compact field's are formed anew).
  std::optional<Eigen::Vector3d> normal(const Eigen::Vector3d& p_W, const Eigen::Vector3d& n_W, double depth);

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
Eigen::Vector3d projectOntoCone(const Eigen::Vector3d& n, const std::vector<Eigen::Vector3d>& generators);

}  // namespace wtc::ode
