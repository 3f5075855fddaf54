#pragma once
// Query kernels for the pieces terrains are made of, chosen once per piece
// when it is built (ConvexPolyhedron::kernel_) and read by the point query:
// box_kernel.hpp (axis-aligned boxes), prism_kernel.hpp (the prisms of
// heightfields and extruded meshes, and triangular prisms built by Qhull).
//
// A kernel takes the general query's decisions (the plane bound's face, the
// face's crossed edges, the edge and vertex regions) by the general
// arithmetic, with what the piece's kind fixes taken as constants: its
// topology (face sizes, face-edge twins, a vertex's neighbours), and for the
// box the terms that are exactly zero. Every answer is the same, bit for bit
// (PieceKernelTest).
#include <cstdint>
#include <vector>

#include "wtc/geometry/convex_polyhedron.hpp"

namespace wtc::detail {

enum class PieceKernel : std::uint8_t {
  kGeneral = 0,        ///< any piece: the general query
  kAxisBox = 1,        ///< an axis-aligned box in ConvexPolyhedron::box's layout (box_kernel.hpp)
  kPrism = 2,          ///< a triangular prism in the terrain builders' layout (prism_kernel.hpp)
  kUprightPrism = 3,   ///< such a prism with vertical sides on a flat bottom: a heightfield cell
  kLabelledPrism = 4,  ///< a triangular prism in its own labelling (Qhull's): its lists read from the piece,
                       ///< its vertex neighbours stored with its topology (prism_kernel.hpp)
};

/// The kernel that fits `poly`, whose numbers and topology are complete
/// (convex_polyhedron.cpp calls it last when it builds a piece).
PieceKernel kernelFor(const ConvexPolyhedron& poly);
/// kernelFor of a piece whose topology was copied from a piece of kernel
/// `like` (PolyhedronLayout::sameTopologyAs): a prism's face lists need no
/// second look, only its numbers (the compact terrains form prisms so).
PieceKernel kernelForTopologyOf(const ConvexPolyhedron& poly, PieceKernel like);
/// Stores what the kernel of `poly` (chosen by kernelFor) reads besides the
/// layout: the vertex neighbours of a kLabelledPrism, after its twins, in
/// `topology`, the piece's topology while it is built (assembleInto).
void storeKernelData(ConvexPolyhedron& poly, std::vector<std::int32_t>& topology);

}  // namespace wtc::detail
