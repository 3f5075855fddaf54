#pragma once
// Triangle meshes as ground: each triangle becomes a thin prism extruded
// below the surface, so that any surface mesh (open or closed, with walls
// and overhangs) is solid ground made of convex pieces. File formats are
// read by wtc::io (assimp); this is the geometry, with no file I/O.
//
// Extrusion along -normal, by a fixed thickness. Triangle (a, b, c),
// counter-clockwise seen from outside with unit normal n, becomes the right
// prism (a, b, c, a - t n, b - t n, c - t n). Chosen over "straight down to
// a base plane" (the heightfield's rule) because it needs no up axis (glTF is
// Y-up, most CAD Z-up), handles vertical walls (which would give zero-volume
// vertical prisms) and overhangs or the underside of a closed rock (which
// would fill the space below them down to the base), and keeps each piece
// small and its bounding box tight. The prisms of adjacent triangles share
// their top edges, so the surface has no gaps; below it they overlap at
// concave edges and fan apart at convex ones, where nothing reaches.
//
// Choosing the thickness t: larger than any wheel deflection the simulation
// can produce (so a wheel centre never passes through a skin) and smaller
// than the thinnest solid the mesh models (a 5 cm plate extruded 20 cm pokes
// 15 cm out of its other side). Where two faces meet at a ridge sharper than
// 90 degrees (n1 . n2 < 0), one skin pokes out of the other face by up to
// t |n1 . n2| near the ridge; keep t small there or keep the part whole.
//
// Degenerate triangles (an altitude below kDegenerateTriangleRelative x the
// larger of the longest edge and the thickness: zero area, collinear or
// repeated vertices) carry no surface; they are skipped and counted, not an
// error.
//
// Closed parts. A part whose triangles close up (every edge shared by two
// triangles of opposite direction) and enclose negative volume is wound
// inside-out: its triangles are flipped (and counted) before extrusion. With
// keep_convex_parts, a closed part whose enclosed volume matches its convex
// hull's (relative kConvexPartVolumeRelative) becomes one piece, the hull.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "wtc/terrain/terrain.hpp"

namespace wtc {

/// Smallest triangle altitude kept, relative to the larger of the longest
/// edge and the thickness (the prism's size) (dimensionless). 1e-6 keeps a
/// 1 um wide sliver of a 1 m triangle, and stays 1000x above the relative
/// tolerance (1e-9) under which ConvexPolyhedron::fromMesh rejects a piece
/// as flat.
inline constexpr double kDegenerateTriangleRelative = 1e-6;

/// Relative volume mismatch under which a closed part counts as convex
/// (dimensionless). Mesh files store single-precision coordinates (relative
/// error ~6e-8, volume error a few times that); a dent of depth d in a face
/// of a part of height H changes the volume by ~d / (3 H), so the dents this
/// accepts are below 3e-6 H deep.
inline constexpr double kConvexPartVolumeRelative = 1e-6;

/// One part of a mesh in world coordinates (m). Triangles are vertex index
/// triples, counter-clockwise seen from outside (the convention of OBJ, STL,
/// PLY and glTF).
struct TriangleMesh {
  std::string name;  ///< For messages, e.g. "rock.obj, mesh 'Rock'".
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<std::int32_t, 3>> triangles;
};

struct MeshExtrusionOptions {
  double thickness = 0.1;          ///< Extrusion depth along -normal (m, > 0); see the note above.
  bool keep_convex_parts = false;  ///< A closed convex part becomes one piece.
  /// Keep the vertices and triangles and form each prism when a wheel
  /// needs it, bit for bit the stored one (memory: docs/terrain.md). An
  /// engine plugin gives the part to its engine as one triangle-mesh shape.
  /// A part kept whole (keep_convex_parts) is stored as before.
  bool compact = false;
};

/// What addTriangleMesh did, for the caller to check or print.
struct MeshBuildReport {
  PieceRange pieces;                    ///< Pieces added.
  std::int64_t triangles = 0;           ///< Triangles read.
  std::int64_t degenerate_skipped = 0;  ///< Zero-area triangles skipped.
  int convex_parts = 0;                 ///< Parts kept as one convex piece.
  int flipped_parts = 0;                ///< Closed parts wound inside-out, flipped.

  /// Accumulates another part's report (the pieces must follow on).
  void append(const MeshBuildReport& other);
};

/// Adds one mesh part. Throws InvalidInputError naming the part, the
/// triangle and the vertex for a non-finite vertex or an index out of range,
/// and for thickness not finite and > 0.
MeshBuildReport addTriangleMesh(TerrainBuilder& builder, const TriangleMesh& mesh, MaterialId material,
                                const MeshExtrusionOptions& options = {});

/// The right prism under triangle (a, b, c) (counter-clockwise from outside),
/// reaching `thickness` (m) along minus its unit normal. Precondition: the
/// triangle is not degenerate.
ConvexPolyhedron makeExtrudedTriangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                                      double thickness);

}  // namespace wtc
