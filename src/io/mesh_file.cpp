// Mesh files through assimp: read, walk the scene graph applying node
// transforms, keep the triangles, and hand each mesh instance to
// wtc::addTriangleMesh (rules in include/wtc/io/mesh_file.hpp).
#include "wtc/io/mesh_file.hpp"

#include <cmath>
#include <utility>

// clang-format off
#include <sys/stat.h>

#include <assimp/DefaultIOSystem.h>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
// clang-format on


#include "file_support.hpp"
#include "mesh_header_check.hpp"
#include "wtc/base/checks.hpp"
#include "wtc/base/error.hpp"

namespace wtc::io {
namespace {

using detail::where;

// assimp's file access with WTC's rule for every file it opens, the mesh
// and what it references (an OBJ's .mtl, a glTF's .bin): a regular file
// within kMaxDataFileBytes. assimp's own test for existence opens the file,
// which waits forever on a FIFO: stat() instead. A refusal is kept for the
// message (assimp would only say "unable to open").
class CheckedIOSystem : public Assimp::DefaultIOSystem {
 public:
  bool Exists(const char* file) const override {
    struct stat st {};
    return ::stat(file, &st) == 0;
  }
  Assimp::IOStream* Open(const char* file, const char* mode) override {
    try {
      detail::requireRegularFile(file, kMaxDataFileBytes, detail::kDataFileKind);
    } catch (const InvalidInputError& e) {
      if (refused_.empty()) refused_ = e.what();
      return nullptr;
    }
    return DefaultIOSystem::Open(file, mode);
  }
  /// The first file refused, as an error message; empty if none.
  const std::string& refused() const { return refused_; }

 private:
  std::string refused_;
};

Eigen::Matrix4d toEigen(const aiMatrix4x4& m) {
  Eigen::Matrix4d out;
  for (unsigned r = 0; r < 4; ++r) {
    for (unsigned c = 0; c < 4; ++c) out(r, c) = m[r][c];
  }
  return out;
}

void checkOptions(const std::filesystem::path& path, const MeshFileOptions& options) {
  const std::string file = path.string();
  requirePositive(options.scale, file.c_str(), "scale", "dimensionless");
  requireRigid(options.pose_WM, file.c_str(), "pose_WM");
}

// Appends the triangles of `mesh`, transformed by `transform`, as one part.
void addPart(const std::filesystem::path& path, const aiMesh& mesh, unsigned mesh_index,
             const Eigen::Affine3d& transform, MeshFileContents& out) {
  TriangleMesh part;
  part.name = path.string() + ", mesh ";
  if (mesh.mName.length > 0) {
    part.name.append("'").append(mesh.mName.C_Str()).append("'");
  } else {
    part.name += std::to_string(mesh_index);
  }
  part.vertices.reserve(mesh.mNumVertices);
  for (unsigned i = 0; i < mesh.mNumVertices; ++i) {
    const aiVector3D& v = mesh.mVertices[i];
    part.vertices.push_back(transform * Eigen::Vector3d(v.x, v.y, v.z));
  }
  // A mirroring transform turns counter-clockwise into clockwise.
  const bool mirrored = transform.linear().determinant() < 0.0;
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
    const aiFace& face = mesh.mFaces[f];
    if (face.mNumIndices == 1) {
      ++out.ignored_points;
    } else if (face.mNumIndices == 2) {
      ++out.ignored_lines;
    } else {
      // Triangulate already split polygons; a fan covers any it left.
      for (unsigned k = 1; k + 1 < face.mNumIndices; ++k) {
        const auto a = static_cast<std::int32_t>(face.mIndices[0]);
        const auto b = static_cast<std::int32_t>(face.mIndices[k]);
        const auto c = static_cast<std::int32_t>(face.mIndices[k + 1]);
        part.triangles.push_back(mirrored ? std::array{a, c, b} : std::array{a, b, c});
      }
    }
  }
  if (!part.triangles.empty()) out.parts.push_back(std::move(part));
}

}  // namespace

std::int64_t MeshFileContents::triangleCount() const {
  std::int64_t count = 0;
  for (const auto& part : parts) count += static_cast<std::int64_t>(part.triangles.size());
  return count;
}

MeshFileContents readMeshFile(const std::filesystem::path& path, const MeshFileOptions& options) {
  checkOptions(path, options);
  detail::requireRegularFile(path, kMaxDataFileBytes, detail::kDataFileKind);
  detail::checkDeclaredCounts(path);  // before assimp allocates what the header claims

  // Read without post-processing first, to tell a point cloud (vertices,
  // no faces: assimp's validation would only say "contains no faces") from
  // a broken file; then validate, then triangulate.
  Assimp::Importer importer;
  auto* files = new CheckedIOSystem;  // the importer owns it
  importer.SetIOHandler(files);
  const aiScene* scene = importer.ReadFile(path.string(), 0);
  if (!files->refused().empty()) throw InvalidInputError(where(path) + "refers to " + files->refused());
  if (scene == nullptr) {
    throw InvalidInputError(where(path) + "cannot read the mesh file: " + importer.GetErrorString());
  }
  if (scene->mNumMeshes == 0) throw InvalidInputError(where(path) + "empty scene: the file contains no meshes");
  std::int64_t vertices = 0, faces = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    if (scene->mMeshes[m] != nullptr) {
      vertices += scene->mMeshes[m]->mNumVertices;
      faces += scene->mMeshes[m]->mNumFaces;
    }
  }
  if (faces == 0) {
    throw InvalidInputError(where(path) + (vertices == 0 ? "empty scene: its meshes have no vertices"
                                                         : "point cloud: " + std::to_string(vertices) +
                                                               " vertices and no faces (a point cloud is not ground)"));
  }
  scene = importer.ApplyPostProcessing(aiProcess_ValidateDataStructure);
  if (scene != nullptr) scene = importer.ApplyPostProcessing(aiProcess_Triangulate);
  if (scene == nullptr) {
    throw InvalidInputError(where(path) + "cannot read the mesh file: " + importer.GetErrorString());
  }
  if ((scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) != 0) {
    throw InvalidInputError(where(path) + "assimp read an incomplete scene (the file is damaged or unsupported)");
  }

  const Eigen::Affine3d file_to_world = options.pose_WM * Eigen::Scaling(options.scale);
  MeshFileContents out;
  if (scene->mRootNode == nullptr) {
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) addPart(path, *scene->mMeshes[m], m, file_to_world, out);
  } else {
    // Depth-first over the node tree with the accumulated transform.
    std::vector<std::pair<const aiNode*, Eigen::Affine3d>> stack = {
        {scene->mRootNode, file_to_world * Eigen::Affine3d(toEigen(scene->mRootNode->mTransformation))}};
    while (!stack.empty()) {
      const auto [node, transform] = stack.back();
      stack.pop_back();
      for (unsigned k = 0; k < node->mNumMeshes; ++k) {
        const unsigned m = node->mMeshes[k];
        addPart(path, *scene->mMeshes[m], m, transform, out);
      }
      for (unsigned k = 0; k < node->mNumChildren; ++k) {
        const aiNode* child = node->mChildren[k];
        stack.emplace_back(child, transform * Eigen::Affine3d(toEigen(child->mTransformation)));
      }
    }
  }
  if (out.parts.empty()) {
    throw InvalidInputError(where(path) + "no triangles, only " + std::to_string(out.ignored_points) + " points and " +
                            std::to_string(out.ignored_lines) + " lines (points and lines are not ground)");
  }
  return out;
}

MeshBuildReport addMeshFile(TerrainBuilder& builder, const std::filesystem::path& path, MaterialId material,
                            const MeshFileOptions& options) {
  const MeshFileContents contents = readMeshFile(path, options);
  MeshBuildReport report;
  report.pieces.first = static_cast<PieceId>(builder.pieceCount());
  builder.reserve(static_cast<std::size_t>(contents.triangleCount()));  // once per file, not per part
  for (const auto& part : contents.parts) report.append(addTriangleMesh(builder, part, material, options.extrusion));
  if (report.pieces.count == 0) {
    // Every triangle skipped: said here, or the terrain would only find
    // itself without pieces, with no word of this file.
    throw InvalidInputError(where(path) + "all " + std::to_string(report.degenerate_skipped) + " of its " +
                            std::to_string(report.triangles) +
                            " triangles are degenerate (zero area: collinear or repeated vertices), so the mesh "
                            "holds no ground");
  }
  return report;
}

}  // namespace wtc::io
