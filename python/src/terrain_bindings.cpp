// wtc.Terrain: terrains loaded or built, and their queries over NumPy
// arrays of many points at once, each a loop in C++ without the GIL (one
// query per row; no Python object per point).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <chrono>

#include "bindings.hpp"
#include "terrain_query.hpp"
#include "wtc/base/error.hpp"
#include "wtc/contact/wheel_contact.hpp"
#include "wtc/io/dem_file.hpp"
#include "wtc/io/terrain_file.hpp"
#include "wtc/terrain/heightfield.hpp"

namespace wtc::python {
namespace {

using Points = py::array_t<double, py::array::c_style | py::array::forcecast>;

// An (N, 3) array, or InvalidInputError naming `what` and its shape.
void requireRows3(const Points& a, const char* what) {
  if (a.ndim() != 2 || a.shape(1) != 3) {
    std::string shape = "(";
    for (py::ssize_t i = 0; i < a.ndim(); ++i) shape += (i ? ", " : "") + std::to_string(a.shape(i));
    throw InvalidInputError(std::string("wtc.Terrain: ") + what + " must be an array of shape (N, 3), not " + shape +
                            ")");
  }
}

void requireReach(double reach) {
  if (!(reach > 0.0) || !std::isfinite(reach)) {
    throw InvalidInputError("wtc.Terrain.query: max_distance = " + formatNumber(reach) + " must be > 0 m and finite");
  }
}

py::tuple query(const TerrainHandle& t, const Points& points, double reach) {
  requireRows3(points, "points");
  requireReach(reach);
  const py::ssize_t n = points.shape(0);
  py::array_t<double> distances(n);
  py::array_t<double> normals({n, py::ssize_t{3}});
  py::array_t<std::int32_t> pieces(n);
  const double* in = points.data();
  double* d = distances.mutable_data();
  double* nn = normals.mutable_data();
  std::int32_t* id = pieces.mutable_data();
  {
    py::gil_scoped_release nogil;
    TerrainQueryScratch scratch;
    for (py::ssize_t i = 0; i < n; ++i) {
      const TerrainPoint q = queryTerrain(*t.terrain, Eigen::Map<const Eigen::Vector3d>(in + 3 * i), reach, scratch);
      d[i] = q.distance;
      Eigen::Map<Eigen::Vector3d>(nn + 3 * i) = q.normal;
      id[i] = static_cast<std::int32_t>(q.piece);
    }
  }
  return py::make_tuple(distances, normals, pieces);
}

// The benchmark's reference: the same query called point by point from C++
// on points held in a std::vector (copied before the clock starts).
// Returns the seconds the loop took.
double cppQuerySeconds(const TerrainHandle& t, const Points& points, double reach) {
  requireRows3(points, "points");
  requireReach(reach);
  std::vector<Eigen::Vector3d> ps(static_cast<std::size_t>(points.shape(0)));
  for (std::size_t i = 0; i < ps.size(); ++i) ps[i] = Eigen::Map<const Eigen::Vector3d>(points.data() + 3 * i);
  py::gil_scoped_release nogil;
  TerrainQueryScratch scratch;
  double sink = 0.0;
  const auto t0 = std::chrono::steady_clock::now();
  for (const Eigen::Vector3d& p : ps) {
    const TerrainPoint q = queryTerrain(*t.terrain, p, reach, scratch);
    sink += q.distance + q.normal.z() + q.piece;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // Keep the loop's results alive (the optimiser may not drop the queries).
  volatile double keep = sink;
  (void)keep;
  return seconds;
}

py::dict wheelContacts(const TerrainHandle& t, const Points& centers, const Points& axles, double radius, double width,
                       bool multiple_contacts, bool tread_truncation, bool seam_rule, bool field_surface) {
  requireRows3(centers, "centers");
  requireRows3(axles, "axles");
  if (axles.shape(0) != centers.shape(0) && axles.shape(0) != 1) {
    throw InvalidInputError("wtc.Terrain.wheel_contacts: axles has " + std::to_string(axles.shape(0)) +
                            " rows, centers " + std::to_string(centers.shape(0)) +
                            " (give one axle, or one per centre)");
  }
  const WheelGeometry wheel{.free_radius = radius, .tread_width = width};
  validate(wheel, "wtc.Terrain.wheel_contacts");
  const ContactOptions options{.multiple_contacts = multiple_contacts,
                               .tread_truncation = tread_truncation,
                               .seam_rule = seam_rule,
                               .field_surface = field_surface};
  const py::ssize_t n = centers.shape(0);
  std::vector<std::int64_t> index;
  std::vector<double> point, normal, deflection, share;
  std::vector<std::int32_t> piece;
  {
    py::gil_scoped_release nogil;
    WheelContactFinder finder;
    for (py::ssize_t i = 0; i < n; ++i) {
      const WheelPose pose{.center = Eigen::Map<const Eigen::Vector3d>(centers.data() + 3 * i),
                           .axle = Eigen::Map<const Eigen::Vector3d>(axles.data() + 3 * (axles.shape(0) == 1 ? 0 : i))};
      for (const WheelContact& c : finder.find(*t.terrain, wheel, pose, options)) {
        index.push_back(i);
        point.insert(point.end(), {c.ground_point.x(), c.ground_point.y(), c.ground_point.z()});
        normal.insert(normal.end(), {-c.e.x(), -c.e.y(), -c.e.z()});
        deflection.push_back(c.deflection);
        share.push_back(c.load_share);
        piece.push_back(static_cast<std::int32_t>(c.piece));
      }
    }
  }
  const auto m = static_cast<py::ssize_t>(index.size());
  py::dict d;
  d["index"] = py::array_t<std::int64_t>(m, index.data());
  d["ground_point"] = py::array_t<double>({m, py::ssize_t{3}}, point.data());
  d["normal"] = py::array_t<double>({m, py::ssize_t{3}}, normal.data());
  d["deflection"] = py::array_t<double>(m, deflection.data());
  d["load_share"] = py::array_t<double>(m, share.data());
  d["piece"] = py::array_t<std::int32_t>(m, piece.data());
  return d;
}

TerrainHandle heightfield(const py::array_t<double, py::array::c_style | py::array::forcecast>& heights,
                          double spacing_x, double spacing_y, const std::array<double, 3>& origin, double base_depth) {
  if (heights.ndim() != 2) throw InvalidInputError("wtc.heightfield: heights must be a 2-D array (rows, cols)");
  Heightfield field;
  field.rows = static_cast<int>(heights.shape(0));
  field.cols = static_cast<int>(heights.shape(1));
  field.spacing_x = spacing_x;
  field.spacing_y = spacing_y;
  field.origin = Eigen::Vector3d(origin[0], origin[1], origin[2]);
  field.base_depth = base_depth;
  field.heights.assign(heights.data(), heights.data() + heights.size());
  TerrainBuilder builder;
  const MaterialId material = builder.addMaterial(Material{});
  addHeightfield(builder, field, material);
  return TerrainHandle{std::make_shared<const Terrain>(std::move(builder).build())};
}

bool isDescription(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".yaml" || ext == ".yml";
}

Eigen::Vector2d spacingOf(const py::object& spacing) {
  if (py::isinstance<py::float_>(spacing) || py::isinstance<py::int_>(spacing)) {
    return Eigen::Vector2d::Constant(spacing.cast<double>());
  }
  const auto pair = spacing.cast<std::array<double, 2>>();
  return Eigen::Vector2d(pair[0], pair[1]);
}

TerrainHandle loadTerrain(const std::filesystem::path& path, const py::object& spacing, const py::object& crop,
                          int step, const py::object& height_scale, const std::string& frame,
                          const std::array<double, 3>& translation, int band, const std::string& storage,
                          double base_depth) {
  if (isDescription(path)) {
    const bool defaults = spacing.is_none() && crop.is_none() && step == 1 && height_scale.is_none() &&
                          frame == "local" && translation == std::array<double, 3>{0.0, 0.0, 0.0} && band == 1 &&
                          storage == "compact" && base_depth == 1.0;
    if (!defaults) {
      throw InvalidInputError("wtc.load_terrain: " + path.string() +
                              ": a terrain file gives its pieces' keys itself; the DEM arguments are for a raster");
    }
    return TerrainHandle{std::make_shared<const Terrain>(io::loadTerrain(path))};
  }
  if (frame != "local" && frame != "map") {
    throw InvalidInputError("wtc.load_terrain: frame = '" + frame + "' (expected 'local' or 'map')");
  }
  if (storage != "compact" && storage != "prisms") {
    throw InvalidInputError("wtc.load_terrain: storage = '" + storage + "' (expected 'compact' or 'prisms')");
  }
  io::DemRequest request;
  if (!spacing.is_none()) request.spacing = spacingOf(spacing);
  if (!crop.is_none()) {
    const auto w = crop.cast<std::array<double, 4>>();
    request.crop = Eigen::Vector4d(w[0], w[1], w[2], w[3]);
  }
  request.step = step;
  if (!height_scale.is_none()) request.height_scale = height_scale.cast<double>();
  request.map_frame = frame == "map";
  request.translation = Eigen::Vector3d(translation[0], translation[1], translation[2]);
  request.band = band;
  request.base_depth = base_depth;
  Heightfield field;
  {
    py::gil_scoped_release unlocked;
    field = io::readDem(path, request);
  }
  TerrainBuilder builder;
  const MaterialId material = builder.addMaterial(Material{});
  if (storage == "compact") {
    addCompactHeightfield(builder, std::move(field), material);
  } else {
    addHeightfield(builder, field, material);
  }
  return TerrainHandle{std::make_shared<const Terrain>(std::move(builder).build())};
}

void writeDem(const std::filesystem::path& path,
              const py::array_t<double, py::array::c_style | py::array::forcecast>& heights, const py::object& spacing,
              const std::array<double, 2>& south_west, int epsg) {
  if (heights.ndim() != 2) throw InvalidInputError("wtc.write_dem: heights must be a 2-D array (rows, cols)");
  Heightfield field;
  field.rows = static_cast<int>(heights.shape(0));
  field.cols = static_cast<int>(heights.shape(1));
  const Eigen::Vector2d s = spacingOf(spacing);
  field.spacing_x = s.x();
  field.spacing_y = s.y();
  field.heights.assign(heights.data(), heights.data() + heights.size());
  // NaN samples are no ground: the cells around them become holes.
  std::vector<std::uint8_t> missing(field.heights.size(), 0);
  for (std::size_t k = 0; k < field.heights.size(); ++k) missing[k] = std::isnan(field.heights[k]) ? 1 : 0;
  holesAtMissingSamples(field, missing);
  io::DemWriteOptions options;
  options.epsg = epsg;
  options.map_south_west = Eigen::Vector2d(south_west[0], south_west[1]);
  io::writeDemGeoTiff(path, field, options);
}

}  // namespace

void bindTerrain(py::module_& m) {
  py::class_<TerrainHandle>(m, "Terrain", "A terrain: convex pieces and their index (docs/python.md).")
      .def_property_readonly("piece_count", [](const TerrainHandle& t) { return t.terrain->pieceCount(); })
      .def_property_readonly(
          "bounds",
          [](const TerrainHandle& t) {
            const Aabb& b = t.terrain->bounds();
            return py::make_tuple(std::array<double, 3>{b.min.x(), b.min.y(), b.min.z()},
                                  std::array<double, 3>{b.max.x(), b.max.y(), b.max.z()});
          },
          "(min, max) corners of the terrain's box (m)")
      .def("query", &query, py::arg("points"), py::arg("max_distance") = 1.0,
           "points (N, 3) in m -> (distances (N,) m, normals (N, 3), pieces (N,)): the nearest piece within "
           "max_distance (m); beyond it distance inf, normal 0, piece -1.")
      .def("wheel_contacts", &wheelContacts, py::arg("centers"), py::arg("axles"), py::arg("radius") = 0.19,
           py::arg("width") = 0.12, py::arg("multiple_contacts") = true, py::arg("tread_truncation") = true,
           py::arg("seam_rule") = true, py::arg("field_surface") = true,
           "WheelContactFinder at each pose (centres (N, 3) m, axles (N, 3) or (1, 3)), one finder for all: "
           "the contacts, flat, with index saying whose.")
      .def("_cpp_query_seconds", &cppQuerySeconds, py::arg("points"), py::arg("max_distance") = 1.0,
           "The benchmark's reference: the same queries point by point from C++; seconds.");
  m.def("load_terrain", &loadTerrain, py::arg("path"), py::kw_only(), py::arg("spacing") = py::none(),
        py::arg("crop") = py::none(), py::arg("step") = 1, py::arg("height_scale") = py::none(),
        py::arg("frame") = "local", py::arg("translation") = std::array<double, 3>{0.0, 0.0, 0.0},
        py::arg("band") = 1, py::arg("storage") = "compact", py::arg("base_depth") = 1.0,
        "A terrain file (.yaml, terrains/README.md), or a DEM (GeoTIFF or any raster GDAL reads, a 16-bit PNG, a "
        ".npy array) as one heightfield of the default material, with the terrain file's keys as arguments "
        "(docs/terrain.md#dems-geotiff-png-npy-issue-53-item-4); a DEM keeps only its samples (storage='compact') unless "
        "storage='prisms'.");
  m.def("write_dem", &writeDem, py::arg("path"), py::arg("heights"), py::arg("spacing"), py::kw_only(),
        py::arg("south_west") = std::array<double, 2>{0.0, 0.0}, py::arg("epsg") = 0,
        "Writes heights (rows, cols) in m, row 0 the south edge as in wtc.heightfield, NaN for no ground, as a "
        "north-up GeoTIFF of `spacing` m (a number or (x, y)) whose south-west sample is at `south_west` in the "
        "projected system EPSG:`epsg` (0: none).");
  m.def("heightfield", &heightfield, py::arg("heights"), py::arg("spacing_x") = 1.0, py::arg("spacing_y") = 1.0,
        py::arg("origin") = std::array<double, 3>{0.0, 0.0, 0.0}, py::arg("base_depth") = 1.0,
        "A terrain of one heightfield: heights (rows, cols) in m, rows along y, columns along x.");
}

}  // namespace wtc::python
