#include "wtc/sim/replay.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>

#include "replay_mm.hpp"
#include "wtc/base/error.hpp"
#include "wtc/base/tolerances.hpp"
#include "wtc/geometry/convex_polyhedron.hpp"
#include "wtc/sim/replay_terrain.hpp"
#include "wtc/sim/step_count.hpp"
#include "wtc/tyre/ground_memory.hpp"

namespace wtc::sim {
namespace {

constexpr double kQuaternionScale = 1e4;
constexpr double kSinkageScale = 1e4;  // 0.1 mm a unit

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) >= 0x20) out += c;
  }
  return out + "\"";
}

template <typename Numbers>
void writeArray(std::ostream& out, const Numbers& numbers) {
  out << '[';
  bool first = true;
  for (const auto n : numbers) {
    if (!first) out << ',';
    out << n;
    first = false;
  }
  out << ']';
}

void writeArrays(std::ostream& out, const std::vector<std::vector<long long>>& arrays) {
  out << '[';
  for (std::size_t i = 0; i < arrays.size(); ++i) {
    if (i) out << ',';
    writeArray(out, arrays[i]);
  }
  out << ']';
}

// Whether a run's clock (a whole number of steps times dt) has reached
// `mark` (a sum of frame periods), to the roundoff of both.
bool reached(double time, double mark) { return time >= mark * (1.0 - tolerance::kWholeStepsRelative); }

void writeTerrain(std::ostream& out, const ReplayTerrain& terrain) {
  out << "\"terrain\":{\"positions\":";
  writeArray(out, terrain.positions);
  out << ",\"indices\":";
  writeArray(out, terrain.indices);
  out << ",\"note\":" << quoted(terrain.note()) << '}';
}

// A shape's fields: its kind and sizes (mm); a hull as its triangles
// (positions in mm, a fan over each face of its Qhull hull).
void writeShape(std::ostream& out, const vehicle::Shape& s) {
  switch (s.kind) {
    case vehicle::Shape::Kind::kBox:
      out << ",\"kind\":\"box\",\"size\":[" << replayMm(s.box_size.x()) << ',' << replayMm(s.box_size.y()) << ','
          << replayMm(s.box_size.z()) << ']';
      break;
    case vehicle::Shape::Kind::kCylinder: {
      const Eigen::Vector3d a = Eigen::Vector3d::Unit(s.cylinder_axis);
      out << ",\"kind\":\"cylinder\",\"radius\":" << replayMm(s.radius) << ",\"width\":" << replayMm(s.length)
          << ",\"axis\":[" << a.x() << ',' << a.y() << ',' << a.z() << ']';
      break;
    }
    case vehicle::Shape::Kind::kSphere:
      out << ",\"kind\":\"sphere\",\"radius\":" << replayMm(s.radius);
      break;
    case vehicle::Shape::Kind::kHull: {
      const ConvexPolyhedron hull = ConvexPolyhedron::fromPoints(s.hull_vertices);
      out << ",\"kind\":\"hull\",\"positions\":[";
      for (int v = 0; v < hull.vertexCount(); ++v) {
        const Eigen::Vector3d p = hull.vertex(v);
        out << (v ? "," : "") << replayMm(p.x()) << ',' << replayMm(p.y()) << ',' << replayMm(p.z());
      }
      out << "],\"indices\":[";
      bool first = true;
      for (int f = 0; f < hull.faceCount(); ++f) {
        const auto face = hull.faceVertices(f);
        for (std::size_t k = 1; k + 1 < face.size(); ++k) {
          out << (first ? "" : ",") << face[0] << ',' << face[k] << ',' << face[k + 1];
          first = false;
        }
      }
      out << ']';
      break;
    }
    case vehicle::Shape::Kind::kNone:
      out << ",\"kind\":\"none\"";
      break;
  }
}

void writeBodies(std::ostream& out, const vehicle::VehicleDescription& v) {
  out << "\"bodies\":[";
  for (std::size_t i = 0; i < v.bodies.size(); ++i) {
    const vehicle::Body& b = v.bodies[i];
    out << (i ? "," : "") << "{\"name\":" << quoted(b.name);
    if (b.wheel) {
      const Eigen::Vector3d& a = b.wheel->axle;
      out << ",\"kind\":\"wheel\",\"radius\":" << replayMm(b.wheel->geometry.free_radius)
          << ",\"width\":" << replayMm(b.wheel->geometry.tread_width) << ",\"axis\":[" << a.x() << ',' << a.y() << ','
          << a.z() << ']';
    } else if (!b.compound.empty()) {
      // Each part at its pose in the body's frame: [x, y, z] (mm) and the
      // quaternion [w, x, y, z] (scaled as the poses' are).
      out << ",\"kind\":\"compound\",\"parts\":[";
      for (std::size_t k = 0; k < b.compound.size(); ++k) {
        const vehicle::ShapePart& part = b.compound[k];
        const Eigen::Vector3d& p = part.pose_BS.translation();
        const Eigen::Quaterniond q(part.pose_BS.linear());
        out << (k ? "," : "") << "{\"position\":[" << replayMm(p.x()) << ',' << replayMm(p.y()) << ','
            << replayMm(p.z()) << "],\"quaternion\":[" << std::llround(q.w() * kQuaternionScale) << ','
            << std::llround(q.x() * kQuaternionScale) << ',' << std::llround(q.y() * kQuaternionScale) << ','
            << std::llround(q.z() * kQuaternionScale) << ']';
        writeShape(out, part.shape);
        out << '}';
      }
      out << ']';
    } else {
      writeShape(out, b.shape);
    }
    out << '}';
  }
  out << ']';
}

}  // namespace

Replay::Replay(const Scene& scene, double fps)
    : scene_(scene), period_(1.0 / fps), last_step_(stepCount(scene.duration_seconds, scene.engine.step_seconds)) {
  if (!(fps > 0.0) || !std::isfinite(fps)) {
    throw InvalidInputError("wtc::sim::Replay: frame rate " + formatNumber(fps) + " must be finite and > 0");
  }
  for (const SoilRegion& region : scene.terrain->soilRegions()) {
    soil_spacing_ = soil_spacing_ > 0.0 ? std::min(soil_spacing_, region.spacing) : region.spacing;
  }
}

// The nodes whose sinkage changed since the last snapshot, as of the frame
// just kept; a node seen for the first time gets its place and the
// terrain's top there.
void Replay::keepSoil(const Run& run) {
  const GroundMemory* memory = groundMemory(run.engine());
  if (memory == nullptr) return;
  std::vector<long long> update{static_cast<long long>(times_ms_.size()) - 1};
  memory->forEachTouchedNode([&](double x, double y, const SoilMemory& m) {
    const long long x_mm = replayMm(x), y_mm = replayMm(y), sinkage = std::llround(m.plastic_sinkage * kSinkageScale);
    const std::uint64_t key =
        static_cast<std::uint64_t>(static_cast<std::uint32_t>(x_mm)) << 32 | static_cast<std::uint32_t>(y_mm);
    const auto [shown, first] = soil_shown_.try_emplace(key, ShownNode{soil_nodes_.size() / 3, 0});
    if (first) {
      soil_nodes_.insert(soil_nodes_.end(), {x_mm, y_mm, replayMm(terrainTopAt(*scene_.terrain, x, y).value_or(0.0))});
    } else if (shown->second.sinkage == sinkage) {
      return;
    }
    shown->second.sinkage = sinkage;
    update.insert(update.end(), {static_cast<long long>(shown->second.index), sinkage});
  });
  if (update.size() == 1) return;
  // The end's snapshot may fall on the frame of the one before: one update a frame (the later pairs win).
  if (!soil_updates_.empty() && soil_updates_.back().front() == update.front()) {
    soil_updates_.back().insert(soil_updates_.back().end(), update.begin() + 1, update.end());
  } else {
    soil_updates_.push_back(std::move(update));
  }
}

void Replay::observe(const Run& run) {
  // The ruts at the run's end, at its last frame, whenever that falls.
  const bool end = run.steps() >= last_step_;
  if (!reached(run.time(), next_)) {
    if (end && soil_spacing_ > 0.0 && !times_ms_.empty()) keepSoil(run);
    return;
  }
  next_ += period_;
  times_ms_.push_back(std::llround(run.time() * 1e3));
  for (const vehicle::BodyKinematics& k : run.state().bodies) {
    const Eigen::Vector3d& p = k.pose.translation();
    const Eigen::Quaterniond q(k.pose.linear());
    poses_.insert(poses_.end(), {replayMm(p.x()), replayMm(p.y()), replayMm(p.z()),
                                 std::llround(q.w() * kQuaternionScale), std::llround(q.x() * kQuaternionScale),
                                 std::llround(q.y() * kQuaternionScale), std::llround(q.z() * kQuaternionScale)});
  }
  std::vector<long long>& c = contacts_.emplace_back();
  for (const int w : scene_.vehicle.wheels()) {
    for (const ContactForce& f : run.wheelForces(w).contacts) {
      const Eigen::Vector3d& p = f.contact.point;
      c.insert(c.end(), {replayMm(p.x()), replayMm(p.y()), replayMm(p.z()), std::llround(f.force.x()),
                         std::llround(f.force.y()), std::llround(f.force.z())});
    }
  }
  if (soil_spacing_ > 0.0 && (end || reached(run.time(), next_soil_))) {
    next_soil_ += kReplaySoilPeriodS;
    keepSoil(run);
  }
}

Aabb Replay::pathBounds() const {
  Aabb box{Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()),
           Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity())};
  for (std::size_t k = 0; k + 7 <= poses_.size(); k += 7) {
    box.include(Eigen::Vector3d(static_cast<double>(poses_[k]), static_cast<double>(poses_[k + 1]),
                                static_cast<double>(poses_[k + 2])) /
                kReplayMmPerM);
  }
  return box;
}

void Replay::write(const std::filesystem::path& path, const RunSummary& summary) const {
  std::ofstream out(path);
  if (!out) throw InvalidInputError("wtc::sim::Replay: cannot write " + path.string());
  out << "// The data of replay.html (written by wtc-sim): see include/wtc/sim/replay.hpp.\n";
  out << "const WTC_REPLAY = {\"scene\":" << quoted(summary.scene) << ",\"engine\":" << quoted(summary.engine)
      << ",\"mode\":" << quoted(summary.mode) << ",\"dt\":" << summary.dt
      << ",\"real_time_factor\":" << summary.real_time_factor << ",\"success\":" << (summary.success ? "true" : "false")
      << ",\"fps\":" << 1.0 / period_ << ',';
  writeTerrain(out, replayTerrain(*scene_.terrain, pathBounds()));
  out << ',';
  writeBodies(out, scene_.vehicle);
  out << ",\"times\":";
  writeArray(out, times_ms_);
  out << ",\"poses\":";
  writeArray(out, poses_);
  out << ",\"contacts\":";
  writeArrays(out, contacts_);
  if (soil_spacing_ > 0.0) {
    out << ",\"soil\":{\"spacing\":" << replayMm(soil_spacing_) << ",\"nodes\":";
    writeArray(out, soil_nodes_);
    out << ",\"updates\":";
    writeArrays(out, soil_updates_);
    out << '}';
  }
  out << "};\n";
  if (!out) throw InvalidInputError("wtc::sim::Replay: writing " + path.string() + " failed");
}

}  // namespace wtc::sim
