#include "wtc/terrain.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "wtc/error.hpp"

namespace wtc {
namespace {

// Pieces per leaf: a leaf's boxes are tested in one short loop; deeper trees
// cost more node visits. 4 measured best on heightfields (docs/terrain.md).
constexpr int kLeafPieces = 4;

// Single-precision box rounded outward: never smaller than the double box,
// so the index never misses a piece.
void storeOutward(const Aabb& box, float min[3], float max[3]) {
  for (int k = 0; k < 3; ++k) {
    min[k] = std::nextafter(static_cast<float>(box.min[k]), -std::numeric_limits<float>::infinity());
    max[k] = std::nextafter(static_cast<float>(box.max[k]), std::numeric_limits<float>::infinity());
  }
}

}  // namespace

MaterialId TerrainBuilder::addMaterial(const Material& material) {
  validate(material, "TerrainBuilder::addMaterial (material '" + material.name + "')");
  materials_.push_back(material);
  return static_cast<MaterialId>(materials_.size() - 1);
}

PieceId TerrainBuilder::addPiece(ConvexPolyhedron piece, MaterialId material) {
  if (material < 0 || material >= materialCount()) {
    throw InvalidInputError("wtc::TerrainBuilder::addPiece: material id " + std::to_string(material) +
                            " is not registered (" + std::to_string(materials_.size()) + " materials)");
  }
  pieces_.push_back(std::move(piece));
  piece_material_.push_back(material);
  return static_cast<PieceId>(pieces_.size() - 1);
}

void TerrainBuilder::reserve(std::size_t count) {
  pieces_.reserve(pieces_.size() + count);
  piece_material_.reserve(piece_material_.size() + count);
}

Terrain TerrainBuilder::build() && {
  if (pieces_.empty()) throw InvalidInputError("wtc::TerrainBuilder::build: the terrain has no pieces");
  Terrain terrain;
  terrain.pieces_ = std::move(pieces_);
  terrain.piece_material_ = std::move(piece_material_);
  terrain.materials_ = std::move(materials_);
  terrain.buildIndex();
  return terrain;
}

// Top-down build over piece centroids: split at the median along the widest
// axis (nth_element: O(n log n) overall). Nodes are stored depth-first, the
// left child right after its parent, so a query walks memory forward.
void Terrain::buildIndex() {
  const auto n = static_cast<PieceId>(pieces_.size());
  order_.resize(n);
  std::iota(order_.begin(), order_.end(), 0);
  std::vector<Eigen::Vector3d> centre(n);
  bounds_ = pieces_[0].bounds();
  for (PieceId i = 0; i < n; ++i) {
    centre[i] = pieces_[i].bounds().center();
    bounds_.min = bounds_.min.cwiseMin(pieces_[i].bounds().min);
    bounds_.max = bounds_.max.cwiseMax(pieces_[i].bounds().max);
  }
  nodes_.clear();
  nodes_.reserve(2 * static_cast<std::size_t>(n) / (kLeafPieces / 2) + 1);

  // Depth is about log2(n / kLeafPieces): 18 for a million pieces.
  auto build = [&](auto& self, std::int32_t begin, std::int32_t end) -> std::int32_t {
    Aabb box = pieces_[order_[begin]].bounds();
    Eigen::Vector3d lo = centre[order_[begin]];
    Eigen::Vector3d hi = lo;
    for (std::int32_t k = begin + 1; k < end; ++k) {
      box.min = box.min.cwiseMin(pieces_[order_[k]].bounds().min);
      box.max = box.max.cwiseMax(pieces_[order_[k]].bounds().max);
      lo = lo.cwiseMin(centre[order_[k]]);
      hi = hi.cwiseMax(centre[order_[k]]);
    }
    const auto index = static_cast<std::int32_t>(nodes_.size());
    nodes_.emplace_back();
    storeOutward(box, nodes_[index].min, nodes_[index].max);
    if (end - begin <= kLeafPieces) {
      nodes_[index].first_or_right = begin;
      nodes_[index].count = end - begin;
      return index;
    }
    int axis = 0;
    (hi - lo).maxCoeff(&axis);
    const std::int32_t mid = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                     [&](PieceId a, PieceId b) { return centre[a][axis] < centre[b][axis]; });
    self(self, begin, mid);
    const std::int32_t right = self(self, mid, end);
    nodes_[index].first_or_right = right;
    nodes_[index].count = 0;
    return index;
  };
  build(build, 0, n);
  nodes_.shrink_to_fit();
}

void Terrain::overlapping(const Aabb& box, std::vector<PieceId>& out) const {
  float lo[3];
  float hi[3];
  storeOutward(box, lo, hi);
  auto overlaps = [&](const Node& node) {
    return lo[0] <= node.max[0] && node.min[0] <= hi[0] && lo[1] <= node.max[1] && node.min[1] <= hi[1] &&
           lo[2] <= node.max[2] && node.min[2] <= hi[2];
  };
  // Depth-first walk; 64 entries bound a tree of 2^64 leaves.
  std::int32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!overlaps(node)) continue;
    if (node.count > 0) {
      for (std::int32_t k = node.first_or_right; k < node.first_or_right + node.count; ++k) {
        if (pieces_[order_[k]].bounds().overlaps(box)) out.push_back(order_[k]);
      }
      continue;
    }
    const auto self = static_cast<std::int32_t>(&node - nodes_.data());
    stack[top++] = node.first_or_right;
    stack[top++] = self + 1;
  }
}

std::size_t Terrain::pieceMemoryBytes() const {
  std::size_t bytes = piece_material_.capacity() * sizeof(MaterialId);
  for (const auto& p : pieces_) bytes += p.memoryBytes();
  return bytes;
}

std::size_t Terrain::indexMemoryBytes() const {
  return nodes_.capacity() * sizeof(Node) + order_.capacity() * sizeof(PieceId);
}

}  // namespace wtc
