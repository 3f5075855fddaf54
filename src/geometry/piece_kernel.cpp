// Which query kernel fits a piece (piece_kernel.hpp): each kernel's
// conditions checked on the stored numbers themselves, exactly, so that the
// kernel's shortened arithmetic is the general arithmetic's to the bit.
#include "piece_kernel.hpp"

#include <algorithm>

#include "box_kernel.hpp"
#include "prism_kernel.hpp"

namespace wtc::detail {
namespace {

using Layout = PolyhedronLayout;

// An axis-aligned box in ConvexPolyhedron::box's layout: its face lists,
// vertex i at (bit 0 ? hi : lo) per axis with lo < 0 < hi, face normals
// exactly -+ the axes (other components zero), offsets d != 0, and each
// side plane zero but on boxSideAxis.
bool isAxisBox(const ConvexPolyhedron& poly) {
  if (poly.vertexCount() != 8 || poly.faceCount() != 6 || poly.isFlat()) return false;
  for (int f = 0; f < 6; ++f) {
    if (Layout::faceSize(poly, f) != 4 || Layout::faceEdgeStart(poly, f) != 4 * f) return false;
    const std::int32_t* list = Layout::faceVertexList(poly, f);
    for (int k = 0; k < 4; ++k) {
      if (list[k] != kBoxFaces[f][k]) return false;
    }
  }
  const Eigen::Vector3d lo = poly.vertexLocal(0);
  const Eigen::Vector3d hi = poly.vertexLocal(7);
  for (int axis = 0; axis < 3; ++axis) {
    if (!(lo[axis] < 0.0 && hi[axis] > 0.0)) return false;
  }
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d v = poly.vertexLocal(i);
    for (int axis = 0; axis < 3; ++axis) {
      if (v[axis] != ((i >> axis) & 1 ? hi[axis] : lo[axis])) return false;
    }
  }
  for (int f = 0; f < 6; ++f) {
    const int axis = f / 2;
    const double sign = f % 2 == 0 ? -1.0 : 1.0;
    const Eigen::Vector3d n = poly.faceNormal(f);
    for (int c = 0; c < 3; ++c) {
      if (n[c] != (c == axis ? sign : 0.0)) return false;
    }
    if (Layout::pd(poly)[f] == 0.0) return false;
    const double* side = Layout::faceEdgePlanes(poly, f);
    for (int k = 0; k < 4; ++k, side += 4) {
      for (int c = 0; c < 3; ++c) {
        if ((side[c] != 0.0) != (c == boxSideAxis(f, k))) return false;
      }
    }
  }
  return true;
}

// The terrain builders' prism: its face starts and lists, solid. The twins
// and the neighbours follow from the face lists of a closed piece (fromMesh
// and the copied topology of the formed prisms guarantee it). A prism
// formed from another's topology inherits this answer (kernelForTopologyOf).
bool isBuildersPrism(const ConvexPolyhedron& poly) {
  if (poly.faceCount() != kPrismFaceCount || poly.isFlat()) return false;
  // topology: [face starts (F + 1) | face lists], as kPrismStart then kPrismList.
  const std::int32_t* starts = Layout::faceVertexList(poly, 0) - (kPrismFaceCount + 1);
  std::int32_t differ = 0;  // one pass without a branch: the compiler vectorises it
  for (int i = 0; i <= kPrismFaceCount; ++i) differ |= starts[i] ^ kPrismStart[i];
  for (int e = 0; e < kPrismFaceEdges; ++e) differ |= starts[kPrismFaceCount + 1 + e] ^ kPrismList[e];
  return differ == 0;
}

// A builders' prism that stands upright on a flat bottom: each top vertex
// exactly above its bottom one, the bottom's three heights equal, side
// normals with n_z = 0 and the bottom's (0, 0, -1) exactly. Then the side
// planes s = n x (b - a) that uprightPrismClassify drops terms of are zero
// there exactly: a vertical edge (0, 0, h) gives s_z = n_x 0 - n_y 0; a
// horizontal edge (e_x, e_y, 0) of a side face (n_z = 0) gives
// s_x = n_y 0 - 0 e_y and s_y = 0 e_x - n_x 0; of the bottom
// (n_x = n_y = 0), s_z = 0 e_y - 0 e_x.
bool isUpright(const ConvexPolyhedron& poly) {
  // The layout's arrays at their fixed places for 6 vertices and 5 faces:
  // one pointer read (the compact terrains check every prism they form).
  const double* x = Layout::vx(poly);
  const double* y = x + 6;
  const double* z = y + 6;
  const double* nx = z + 6;
  const double* ny = nx + kPrismFaceCount;
  const double* nz = ny + kPrismFaceCount;
  return x[0] == x[3] && x[1] == x[4] && x[2] == x[5] && y[0] == y[3] && y[1] == y[4] && y[2] == y[5] && z[3] == z[4] &&
         z[4] == z[5] && nx[1] == 0.0 && ny[1] == 0.0 && nz[1] == -1.0 && nz[2] == 0.0 && nz[3] == 0.0 && nz[4] == 0.0;
}

// A triangular prism in any labelling (Qhull's order of vertices, faces and
// each face's first vertex): 6 vertices, two triangles and three quads, each
// vertex on three faces (three neighbours), solid, no adjacency lists. The
// twins follow from the face lists of a closed piece, as above.
bool isLabelledPrism(const ConvexPolyhedron& poly) {
  if (poly.faceCount() != kPrismFaceCount || poly.isFlat() || Layout::hasAdjacency(poly)) return false;
  int triangles = 0;
  int quads = 0;
  for (int f = 0; f < kPrismFaceCount; ++f) {
    const int size = Layout::faceSize(poly, f);
    triangles += size == 3;
    quads += size == 4;
  }
  if (triangles != 2 || quads != 3) return false;
  int faces_at[6] = {};
  for (int f = 0; f < kPrismFaceCount; ++f) {
    const std::int32_t* list = Layout::faceVertexList(poly, f);
    for (int k = 0; k < Layout::faceSize(poly, f); ++k) ++faces_at[list[k]];
  }
  return std::all_of(faces_at, faces_at + 6, [](int n) { return n == 3; });
}

}  // namespace

PieceKernel kernelFor(const ConvexPolyhedron& poly) {
  // By vertex count first: the compact terrains choose for every prism they form.
  switch (poly.vertexCount()) {
    case 6:
      if (isBuildersPrism(poly)) return isUpright(poly) ? PieceKernel::kUprightPrism : PieceKernel::kPrism;
      if (isLabelledPrism(poly)) return PieceKernel::kLabelledPrism;
      break;
    case 8:
      if (isAxisBox(poly)) return PieceKernel::kAxisBox;
      break;
    default:
      break;
  }
  return PieceKernel::kGeneral;
}

PieceKernel kernelForTopologyOf(const ConvexPolyhedron& poly, PieceKernel like) {
  if (like == PieceKernel::kPrism || like == PieceKernel::kUprightPrism) {
    return isUpright(poly) ? PieceKernel::kUprightPrism : PieceKernel::kPrism;
  }
  // The copied topology holds like's kernel data (storeKernelData) already.
  if (like == PieceKernel::kLabelledPrism) return like;
  const PieceKernel kernel = kernelFor(poly);
  return kernel == PieceKernel::kLabelledPrism ? PieceKernel::kGeneral : kernel;  // no data stored: no kernel
}

void storeKernelData(ConvexPolyhedron& poly, std::vector<std::int32_t>& topology) {
  if (static_cast<PieceKernel>(Layout::kernel(poly)) != PieceKernel::kLabelledPrism) return;
  // Each face-edge's end is a neighbour of its start: every vertex's three
  // neighbours, in face order (the vertex region's answer does not depend on
  // their order).
  std::int32_t around[6][3];
  int count[6] = {};
  for (int f = 0; f < kPrismFaceCount; ++f) {
    const std::int32_t* list = Layout::faceVertexList(poly, f);
    const int size = Layout::faceSize(poly, f);
    for (int k = 0; k < size; ++k) {
      const std::int32_t from = list[k == 0 ? size - 1 : k - 1];
      around[from][count[from]++] = list[k];
    }
  }
  Layout::appendKernelData(poly, topology, around[0], 18);
}

}  // namespace wtc::detail
