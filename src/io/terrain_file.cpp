// Terrain description files: materials by name, then pieces dispatched to
// the builders of wtc::core (format in include/wtc/io/terrain_file.hpp and
// terrains/README.md).
#include "wtc/io/terrain_file.hpp"

#include "material_node.hpp"
#include "terrain_node.hpp"

#include <cmath>
#include <map>
#include <numbers>

#include "file_support.hpp"
#include "wtc/base/error.hpp"
#include "wtc/io/dem_file.hpp"
#include "wtc/io/heightfield_file.hpp"
#include "wtc/io/mesh_file.hpp"
#include "wtc/terrain/heightfield.hpp"
#include "wtc/terrain/triangle_mesh.hpp"
#include "yaml_reader.hpp"

namespace wtc::io {
namespace {

using detail::YamlError;
using detail::YamlReader;

// Keys every piece may have, besides its own.
constexpr std::initializer_list<const char*> kCommonKeys = {"type", "material", "translation", "rotation"};

int toInt(const YamlReader& in, const YAML::Node& map, const char* key, long long fallback) {
  const long long value = in.integer(map, key, fallback);
  if (value < 0 || value > (1LL << 30)) {
    in.fail(YamlReader::get(map, key).value_or(map),
            std::string(key) + " = " + std::to_string(value) + " is out of range");
  }
  return static_cast<int>(value);
}

// storage: prisms (each triangle's prism kept) or compact (the samples, or
// the vertices and triangles, kept; the same prisms formed when a wheel
// needs them).
bool readCompactStorage(const YamlReader& in, const YAML::Node& p) {
  const auto storage = YamlReader::get(p, "storage");
  const std::string kind = storage ? in.string(*storage, "storage") : "prisms";
  if (kind != "prisms" && kind != "compact") {
    in.fail(*storage, "storage: '" + kind + "' (expected prisms or compact)");
  }
  return kind == "compact";
}

// A DEM file's keys (wtc/io/dem_file.hpp): spacing only where the raster
// has no georeferencing, crop, step, frame and band.
Heightfield readDemPiece(const YamlReader& in, const YAML::Node& p, const YAML::Node& file,
                         const std::filesystem::path& path) {
  DemRequest request;
  if (const auto spacing = YamlReader::get(p, "spacing")) {
    request.spacing = spacing->IsSequence() ? in.vector<2>(*spacing, "spacing")
                                            : Eigen::Vector2d::Constant(in.number(*spacing, "spacing"));
  }
  if (const auto crop = YamlReader::get(p, "crop")) request.crop = in.vector<4>(*crop, "crop");
  if (const auto step = YamlReader::get(p, "step")) {
    const long long n = in.integer(p, "step", 1);
    if (n < 1 || n > (1 << 20)) in.fail(*step, "step = " + std::to_string(n) + " (expected 1 ... 1048576)");
    request.step = static_cast<int>(n);
  }
  if (const auto band = YamlReader::get(p, "band")) {
    const long long n = in.integer(p, "band", 1);
    if (n < 1 || n > (1 << 16)) in.fail(*band, "band = " + std::to_string(n) + " (expected 1 or more)");
    request.band = static_cast<int>(n);
  }
  if (const auto frame = YamlReader::get(p, "frame")) {
    const std::string kind = in.string(*frame, "frame");
    if (kind != "local" && kind != "map") in.fail(*frame, "frame: '" + kind + "' (expected local or map)");
    request.map_frame = kind == "map";
  }
  if (YamlReader::get(p, "height_scale")) request.height_scale = in.number(p, "height_scale", 1.0);
  request.base_depth = in.number(p, "base_depth", request.base_depth);
  request.translation = in.pose(p).translation();
  try {
    return readDem(path, request);
  } catch (const InvalidInputError& e) {
    in.fail(file, e.what());
  }
}

Heightfield readHeightfield(const YamlReader& in, const YAML::Node& p) {
  in.checkKeys(p, kCommonKeys,
               {"heights", "file", "spacing", "base_depth", "height_scale", "storage", "cell_materials", "holes",
                "crop", "step", "frame", "band"});
  if (YamlReader::get(p, "rotation")) {
    in.fail(p["rotation"], "a heightfield takes no rotation (its grid is aligned with x and y)");
  }
  const auto file = YamlReader::get(p, "file");
  const auto heights = YamlReader::get(p, "heights");
  if (file.has_value() == heights.has_value()) in.fail(p, "give exactly one of 'heights' and 'file'");
  const std::filesystem::path path = file ? in.path().parent_path() / in.string(*file, "file") : "";
  if (file && isDemPath(path)) return readDemPiece(in, p, *file, path);
  for (const char* key : {"crop", "step", "frame", "band"}) {
    if (const auto node = YamlReader::get(p, key)) {
      in.fail(*node, std::string(key) + " applies to a DEM file (.tif, .npy, .png, ...), not to " +
                         (file ? "a CSV or PGM file" : "inline heights"));
    }
  }
  HeightfieldLayout layout;
  const YAML::Node spacing = in.require(p, "spacing");
  if (spacing.IsSequence()) {
    const Eigen::Vector2d s = in.vector<2>(spacing, "spacing");
    layout.spacing_x = s.x();
    layout.spacing_y = s.y();
  } else {
    layout.spacing_x = layout.spacing_y = in.number(spacing, "spacing");
  }
  layout.origin = in.pose(p).translation();
  layout.base_depth = in.number(p, "base_depth", layout.base_depth);
  layout.height_scale = in.number(p, "height_scale", layout.height_scale);
  if (file) {
    try {
      return readHeightfieldFile(path, layout);
    } catch (const InvalidInputError& e) {
      in.fail(*file, e.what());
    }
  }
  // Inline rows, north (largest y) first, as in a CSV file.
  if (!heights->IsSequence() || heights->size() < 2) in.fail(*heights, "heights: expected a list of at least 2 rows");
  Heightfield field;
  field.rows = static_cast<int>(heights->size());
  field.spacing_x = layout.spacing_x;
  field.spacing_y = layout.spacing_y;
  field.origin = layout.origin;
  field.base_depth = layout.base_depth;
  for (std::size_t k = 0; k < heights->size(); ++k) {
    const YAML::Node row = (*heights)[k];
    if (!row.IsSequence()) in.fail(row, "heights[" + std::to_string(k) + "]: expected a list of numbers");
    if (k == 0) field.cols = static_cast<int>(row.size());
    if (static_cast<int>(row.size()) != field.cols) {
      in.fail(row, "heights[" + std::to_string(k) + "] has " + std::to_string(row.size()) +
                       " values, but heights[0] has " + std::to_string(field.cols));
    }
  }
  field.heights.resize(static_cast<std::size_t>(field.rows) * field.cols);
  for (int k = 0; k < field.rows; ++k) {
    for (int c = 0; c < field.cols; ++c) {
      const YAML::Node value = (*heights)[k][c];
      const std::string name = "heights[" + std::to_string(k) + "][" + std::to_string(c) + "]";
      const double h = layout.height_scale * in.number(value, name);
      if (!std::isfinite(h)) in.fail(value, name + " is not finite");
      field.heights[static_cast<std::size_t>(field.rows - 1 - k) * field.cols + c] = h;
    }
  }
  return field;
}

using MaterialNames = std::map<std::string, MaterialId>;

// One value per cell of a heightfield under `key`: (rows - 1) rows of
// (cols - 1) values, north (largest y) first, as the heights; `read` turns
// one entry (and its name, for errors) into a value.
template <class T, class Read>
std::vector<T> readCellGrid(const YamlReader& in, const YAML::Node& rows, const Heightfield& field,
                            const std::string& key, const std::string& values, Read read) {
  const int cell_rows = field.rows - 1, cell_cols = field.cols - 1;
  if (!rows.IsSequence() || static_cast<int>(rows.size()) != cell_rows) {
    in.fail(rows, key + ": expected " + std::to_string(cell_rows) + " rows (one per row of cells, north " +
                      "first), got " + (rows.IsSequence() ? std::to_string(rows.size()) : std::string("no list")));
  }
  std::vector<T> cells(static_cast<std::size_t>(cell_rows) * cell_cols);
  for (int k = 0; k < cell_rows; ++k) {
    const YAML::Node row = rows[k];
    const std::string name = key + "[" + std::to_string(k) + "]";
    if (!row.IsSequence() || static_cast<int>(row.size()) != cell_cols) {
      in.fail(row, name + ": expected " + std::to_string(cell_cols) + " " + values + " (one per cell)");
    }
    for (int c = 0; c < cell_cols; ++c) {
      cells[static_cast<std::size_t>(cell_rows - 1 - k) * cell_cols + c] =
          read(row[c], name + "[" + std::to_string(c) + "]");
    }
  }
  return cells;
}

// A heightfield's cell_materials: a material name per cell.
std::vector<MaterialId> readCellMaterials(const YamlReader& in, const YAML::Node& rows, const Heightfield& field,
                                          const MaterialNames& materials) {
  return readCellGrid<MaterialId>(in, rows, field, "cell_materials", "material names",
                                  [&](const YAML::Node& cell, const std::string& name) {
                                    const std::string material = in.string(cell, name);
                                    const auto found = materials.find(material);
                                    if (found == materials.end()) {
                                      in.fail(cell, name + ": unknown material '" + material + "'");
                                    }
                                    return found->second;
                                  });
}

// A heightfield's holes: 1 for a hole, 0 for ground, per cell.
std::vector<std::uint8_t> readHoles(const YamlReader& in, const YAML::Node& rows, const Heightfield& field) {
  return readCellGrid<std::uint8_t>(
      in, rows, field, "holes", "entries of 0 or 1", [&](const YAML::Node& cell, const std::string& name) {
        const double v = in.number(cell, name);
        if (v != 0.0 && v != 1.0) {
          in.fail(cell, name + " = " + cell.Scalar() + " (expected 0, ground, or 1, a hole)");
        }
        return static_cast<std::uint8_t>(v);
      });
}

// The piece types a terrain file may name, each read by its own function
// (its keys checked there) and listed once in kPieceTypes below: a new
// piece type is a builder in the core (src/terrain) and one reader here.
void readBox(TerrainBuilder& builder, const YamlReader& in, const YAML::Node& p, MaterialId material,
             const MaterialNames& /*materials*/, TerrainFileReport& /*report*/) {
  in.checkKeys(p, kCommonKeys, {"size"});
  addBox(builder, {in.vector<3>(in.require(p, "size"), "size"), in.pose(p)}, material);
}

void readSlab(TerrainBuilder& builder, const YamlReader& in, const YAML::Node& p, MaterialId material,
              const MaterialNames& /*materials*/, TerrainFileReport& /*report*/) {
  in.checkKeys(p, kCommonKeys, {"size", "thickness", "tiles"});
  SlabParams s;
  const Eigen::Vector2d size = in.vector<2>(in.require(p, "size"), "size");
  s.size_x = size.x();
  s.size_y = size.y();
  s.thickness = in.number(p, "thickness", s.thickness);
  if (const auto tiles = YamlReader::get(p, "tiles")) {
    const Eigen::Vector2d t = in.vector<2>(*tiles, "tiles");
    if (t != t.array().round().matrix() || !(t.array() >= 1.0).all() || !(t.array() <= 1e6).all()) {
      in.fail(*tiles, "tiles: expected two whole numbers in [1, 1e6]");
    }
    s.tiles_x = static_cast<int>(t.x());
    s.tiles_y = static_cast<int>(t.y());
  }
  s.pose_WL = in.pose(p);
  addSlab(builder, s, material);
}

void readIncline(TerrainBuilder& builder, const YamlReader& in, const YAML::Node& p, MaterialId material,
                 const MaterialNames& /*materials*/, TerrainFileReport& /*report*/) {
  in.checkKeys(p, kCommonKeys, {"degrees", "radians", "length", "width", "thickness", "top_length"});
  InclineParams s;
  const auto degrees = YamlReader::get(p, "degrees");
  const auto radians = YamlReader::get(p, "radians");
  if (degrees.has_value() == radians.has_value()) in.fail(p, "give exactly one of 'degrees' and 'radians' (the slope)");
  s.angle = degrees ? in.number(*degrees, "degrees") * std::numbers::pi / 180.0 : in.number(*radians, "radians");
  s.length = in.number(p, "length", s.length);
  s.width = in.number(p, "width", s.width);
  s.thickness = in.number(p, "thickness", s.thickness);
  s.top_length = in.number(p, "top_length", s.top_length);
  s.pose_WL = in.pose(p);
  addIncline(builder, s, material);
}

void readLedge(TerrainBuilder& builder, const YamlReader& in, const YAML::Node& p, MaterialId material,
               const MaterialNames& /*materials*/, TerrainFileReport& /*report*/) {
  in.checkKeys(
      p, kCommonKeys,
      {"height", "approach_length", "top_length", "width", "thickness", "approach_tiles", "heightfield_spacing",
       "storage"});
  LedgeParams s;
  s.height = in.number(in.require(p, "height"), "height");
  s.approach_length = in.number(p, "approach_length", s.approach_length);
  s.top_length = in.number(p, "top_length", s.top_length);
  s.width = in.number(p, "width", s.width);
  s.thickness = in.number(p, "thickness", s.thickness);
  s.approach_tiles = toInt(in, p, "approach_tiles", s.approach_tiles);
  s.heightfield_spacing = in.number(p, "heightfield_spacing", s.heightfield_spacing);
  s.compact_heightfield = readCompactStorage(in, p);
  if (s.compact_heightfield && !(s.heightfield_spacing > 0.0)) {
    in.fail(p["storage"], "storage: compact needs heightfield_spacing > 0 (a ledge of boxes has no samples to keep)");
  }
  s.pose_WL = in.pose(p);
  addLedge(builder, s, material);
}

void readStairs(TerrainBuilder& builder, const YamlReader& in, const YAML::Node& p, MaterialId material,
                const MaterialNames& /*materials*/, TerrainFileReport& /*report*/) {
  in.checkKeys(p, kCommonKeys, {"steps", "rise", "run", "width", "thickness", "top_length"});
  StairsParams s;
  in.require(p, "steps");
  s.steps = toInt(in, p, "steps", s.steps);
  s.rise = in.number(in.require(p, "rise"), "rise");
  s.run = in.number(in.require(p, "run"), "run");
  s.width = in.number(p, "width", s.width);
  s.thickness = in.number(p, "thickness", s.thickness);
  s.top_length = in.number(p, "top_length", s.top_length);
  s.pose_WL = in.pose(p);
  addStairs(builder, s, material);
}

void readHeightfieldPiece(TerrainBuilder& builder, const YamlReader& in, const YAML::Node& p, MaterialId material,
                          const MaterialNames& materials, TerrainFileReport& /*report*/) {
  const bool compact = readCompactStorage(in, p);
  Heightfield field = readHeightfield(in, p);
  if (const auto cells = YamlReader::get(p, "cell_materials")) {
    field.cell_materials = readCellMaterials(in, *cells, field, materials);
  }
  if (const auto holes = YamlReader::get(p, "holes")) {
    // A DEM's no-data holes stay holes: the file's and the key's are joined.
    std::vector<std::uint8_t> given = readHoles(in, *holes, field);
    for (std::size_t k = 0; k < field.cell_holes.size(); ++k) given[k] |= field.cell_holes[k];
    field.cell_holes = std::move(given);
    try {
      validate(field);
    } catch (const InvalidInputError& e) {
      in.fail(*holes, e.what());
    }
  }
  if (compact) {
    addCompactHeightfield(builder, std::move(field), material);
  } else {
    addHeightfield(builder, field, material);
  }
}

void readMesh(TerrainBuilder& builder, const YamlReader& in, const YAML::Node& p, MaterialId material,
              const MaterialNames& /*materials*/, TerrainFileReport& report) {
  in.checkKeys(p, kCommonKeys, {"file", "scale", "thickness", "keep_convex_parts", "storage"});
  MeshFileOptions options;
  options.scale = in.number(p, "scale", options.scale);
  options.pose_WM = in.pose(p);
  options.extrusion.thickness = in.number(p, "thickness", options.extrusion.thickness);
  options.extrusion.keep_convex_parts = in.boolean(p, "keep_convex_parts", false);
  options.extrusion.compact = readCompactStorage(in, p);
  const YAML::Node file = in.require(p, "file");
  const std::filesystem::path path = in.path().parent_path() / in.string(file, "file");
  MeshBuildReport mesh;
  try {
    mesh = addMeshFile(builder, path, material, options);
  } catch (const InvalidInputError& e) {
    in.fail(file, e.what());
  }
  report.degenerate_triangles_skipped += mesh.degenerate_skipped;
  if (mesh.degenerate_skipped > 0) {
    report.warnings.push_back(in.describe(p, path.string() + ": " + std::to_string(mesh.degenerate_skipped) + " of " +
                                                 std::to_string(mesh.triangles) +
                                                 " triangles are degenerate (zero area), skipped"));
  }
}

void readHull(TerrainBuilder& builder, const YamlReader& in, const YAML::Node& p, MaterialId material,
              const MaterialNames& /*materials*/, TerrainFileReport& /*report*/) {
  in.checkKeys(p, kCommonKeys, {"points"});
  const YAML::Node points = in.require(p, "points");
  if (!points.IsSequence()) in.fail(points, "points: expected a list of [x, y, z]");
  const Eigen::Isometry3d pose = in.pose(p);
  std::vector<Eigen::Vector3d> world;
  for (std::size_t i = 0; i < points.size(); ++i) {
    world.push_back(pose * in.vector<3>(points[i], "points[" + std::to_string(i) + "]"));
  }
  builder.addPiece(ConvexPolyhedron::fromPoints(world), material);
}

using PieceReader = void (*)(TerrainBuilder&, const YamlReader&, const YAML::Node&, MaterialId, const MaterialNames&,
                             TerrainFileReport&);
struct PieceType {
  const char* name;
  PieceReader read;
};
constexpr PieceType kPieceTypes[] = {
    {"box", &readBox},     {"slab", &readSlab},     {"incline", &readIncline},
    {"ledge", &readLedge}, {"stairs", &readStairs}, {"heightfield", &readHeightfieldPiece},
    {"mesh", &readMesh},   {"hull", &readHull},
};

// Adds one piece of the type its `type` names; a mesh's skipped triangles go into `report`.
void addPiece(TerrainBuilder& builder, const YamlReader& in, const YAML::Node& p, const std::string& type,
              MaterialId material, const MaterialNames& materials, TerrainFileReport& report) {
  std::string known;
  for (std::size_t k = 0; k < std::size(kPieceTypes); ++k) {
    if (type == kPieceTypes[k].name) return kPieceTypes[k].read(builder, in, p, material, materials, report);
    known += (k == 0 ? "" : k + 1 == std::size(kPieceTypes) ? " or " : ", ") + std::string(kPieceTypes[k].name);
  }
  in.fail(p["type"], "unknown piece type '" + type + "' (expected " + known + ")");
}

// soil_regions: where the soft ground remembers (wtc/terrain/soil_region.hpp),
//   - {corners: [x0, y0, x1, y1], spacing: 0.02, memory_cap_mb: 2048, flow_factor: 0, repose_angle_deg: 30}
constexpr double kMiB = static_cast<double>(kBytesPerMiB);

void addSoilRegions(TerrainBuilder& builder, const YamlReader& in, const YAML::Node& regions) {
  if (!regions.IsSequence()) in.fail(regions, "soil_regions must be a list (lines starting with '- ')");
  for (std::size_t i = 0; i < regions.size(); ++i) {
    const YAML::Node r = regions[i];
    const YamlReader region_in = in.with("soil_regions[" + std::to_string(i) + "]: ");
    region_in.requireMap(r, "a soil region");
    region_in.checkKeys(r, {"corners", "spacing", "memory_cap_mb", "flow_factor", "repose_angle_deg"});
    const Eigen::Vector4d corners = region_in.vector<4>(region_in.require(r, "corners"), "corners");
    SoilRegion region;
    region.origin = corners.head<2>();
    region.size = corners.tail<2>() - corners.head<2>();
    region.spacing = region_in.number(r, "spacing", region.spacing);
    region.memory_cap_bytes = region_in.number(r, "memory_cap_mb", region.memory_cap_bytes / kMiB) * kMiB;
    region.flow_factor = region_in.number(r, "flow_factor", region.flow_factor);
    region.repose_angle_deg = region_in.number(r, "repose_angle_deg", region.repose_angle_deg);
    try {
      builder.addSoilRegion(region, "soil region");
    } catch (const InvalidInputError& e) {
      region_in.fail(r, e.what());
    }
  }
}

}  // namespace

TerrainFileReport detail::addTerrainNode(TerrainBuilder& builder, const YamlReader& in, const YAML::Node& root) {
  if (!root.IsMap()) in.fail(root, "expected a mapping with 'materials' and 'pieces'");
  in.checkKeys(root, {"description", "materials", "pieces", "soil_regions"});

  TerrainFileReport report;
  MaterialNames materials;
  const YAML::Node material_map = in.require(root, "materials");
  in.requireMap(material_map, "materials");
  for (const auto& entry : material_map) {
    const std::string name = entry.first.Scalar();
    const YamlReader m = in.with("material '" + name + "': ");
    const Material material = detail::readMaterial(m, entry.second, name);
    try {
      materials[name] = builder.addMaterial(material);
    } catch (const InvalidInputError& e) {
      m.fail(entry.second, e.what());
    }
    ++report.materials;
  }
  if (materials.empty()) in.fail(material_map, "materials: define at least one material");

  const YAML::Node pieces = in.require(root, "pieces");
  if (!pieces.IsSequence()) in.fail(pieces, "pieces must be a list (lines starting with '- ')");
  report.pieces.first = static_cast<PieceId>(builder.pieceCount());
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const YAML::Node p = pieces[i];
    const YamlReader bare = in.with("pieces[" + std::to_string(i) + "]: ");
    bare.requireMap(p, "a piece");
    const std::string type = bare.string(bare.require(p, "type"), "type");
    const YamlReader piece = in.with("pieces[" + std::to_string(i) + "] (" + type + "): ");
    MaterialId material = materials.begin()->second;
    if (const auto name = YamlReader::get(p, "material")) {
      const auto found = materials.find(piece.string(*name, "material"));
      if (found == materials.end()) piece.fail(*name, "unknown material '" + name->Scalar() + "'");
      material = found->second;
    } else if (materials.size() > 1 && !YamlReader::get(p, "cell_materials")) {
      piece.fail(p, "missing key 'material' (the file defines " + std::to_string(materials.size()) + " materials)");
    }
    try {
      addPiece(builder, piece, p, type, material, materials, report);
    } catch (const YamlError&) {
      throw;
    } catch (const InvalidInputError& e) {
      piece.fail(p, e.what());  // a builder's complaint, named at its piece
    }
  }
  report.pieces.count = static_cast<PieceId>(builder.pieceCount()) - report.pieces.first;
  if (const auto regions = YamlReader::get(root, "soil_regions")) addSoilRegions(builder, in, *regions);
  return report;
}

TerrainFileReport addTerrainFile(TerrainBuilder& builder, const std::filesystem::path& path) {
  return detail::withYamlErrors(
      path, [&] { return detail::addTerrainNode(builder, YamlReader(path), detail::loadYamlFile(path)); });
}

Terrain loadTerrain(const std::filesystem::path& path) {
  TerrainBuilder builder;
  addTerrainFile(builder, path);
  if (builder.pieceCount() == 0) throw InvalidInputError(detail::where(path) + "the terrain has no pieces");
  return std::move(builder).build();
}

}  // namespace wtc::io
