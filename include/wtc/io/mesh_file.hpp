#pragma once
// Triangle meshes from files, through assimp (OBJ, STL, PLY, glTF 2, FBX,
// Collada, 3DS, OFF and the rest of its formats), turned into ground by
// wtc::addTriangleMesh (extrusion rule in <wtc/terrain/triangle_mesh.hpp>).
//
// What is read: every mesh instance of the scene graph (a mesh referenced by
// two nodes is two parts), in the file's frame M with the node transforms
// applied, then scaled by `scale` and placed by `pose_WM`. Polygons are
// triangulated; points and lines are ignored (and counted). A node
// transform that mirrors (negative determinant) reverses the winding back,
// so "counter-clockwise from outside" survives it. No up-axis conversion:
// glTF is Y-up, so a glTF ground usually needs pose_WM = a +90 deg rotation
// about x.
//
// Errors: InvalidInputError whose message starts with the path, for a
// missing file, a path that is not a regular file or a file over
// kMaxDataFileBytes (wtc/io/file_limits.hpp; the same for every file assimp
// opens for it, an OBJ's .mtl, a glTF's .bin), an OFF, PLY or binary STL header declaring more vertices,
// faces or triangles than the file's size can hold (checked before assimp
// allocates for them), a file assimp cannot read or validate (its error string is
// included), an empty scene (no meshes, or meshes without vertices), a
// point cloud (vertices, no faces), a scene with points and lines but no
// triangles; and from addTriangleMesh, naming the part and the triangle,
// for non-finite coordinates.
#include <Eigen/Geometry>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "wtc/terrain/triangle_mesh.hpp"

namespace wtc::io {

struct MeshFileOptions {
  double scale = 1.0;  ///< Uniform scale of the file's coordinates (dimensionless, > 0; 0.001 for mm).
  Eigen::Isometry3d pose_WM = Eigen::Isometry3d::Identity();  ///< The file's frame in the world (rigid).
  MeshExtrusionOptions extrusion;                             ///< Thickness and convex-part rule.
};

/// The triangles of a file, one TriangleMesh per mesh instance, in world
/// coordinates (m), as read (addTriangleMesh checks that they are finite).
struct MeshFileContents {
  std::vector<TriangleMesh> parts;
  std::int64_t ignored_points = 0;  ///< Point primitives skipped.
  std::int64_t ignored_lines = 0;   ///< Line primitives skipped.
  std::int64_t triangleCount() const;
};

/// Reads the file. Throws InvalidInputError (see above).
MeshFileContents readMeshFile(const std::filesystem::path& path, const MeshFileOptions& options = {});

/// Reads the file and adds every part to `builder`; returns the totals
/// (degenerate_skipped: the zero-area triangles skipped, for the caller to
/// report). Throws, besides readMeshFile's errors, "<path>: all 12 of its
/// 12 triangles are degenerate ..." when no triangle is left.
MeshBuildReport addMeshFile(TerrainBuilder& builder, const std::filesystem::path& path, MaterialId material,
                            const MeshFileOptions& options = {});

}  // namespace wtc::io
