// A vehicle and its terrain as MJCF (mjcf_model.hpp).
#include "mjcf_model.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>
#include <string>

#include "mujoco_constants.hpp"
#include "wtc/base/constants.hpp"
#include "wtc/base/error.hpp"
#include "wtc/sim/sim_constants.hpp"
#include "wtc/terrain/heightfield.hpp"

namespace wtc::mujoco {
namespace {

using vehicle::Body;
using vehicle::JointType;
using vehicle::Shape;

constexpr const char* kWhere = "wtc::mujoco sim engine";
// Two face normals of a piece count as parallel (or perpendicular) within
// this of their cos (dimensionless): a box built by WTC's terrain builders
// is exact to rounding.
constexpr double kBoxPieceCos = 1e-9;

// Contact bits (mjcf_model.hpp): ground against bodies only.
constexpr const char* kGroundBits = R"( contype="1" conaffinity="0")";
constexpr const char* kBodyBits = R"( contype="0" conaffinity="1")";
constexpr const char* kNoContact = R"( contype="0" conaffinity="0")";

struct Writer {
  std::ostringstream assets, ground, bodies, equalities;
  int meshes = 0;

  Writer() {
    for (std::ostringstream* s : {&assets, &ground, &bodies, &equalities}) s->precision(17);
  }
};

std::string vec(const Eigen::Vector3d& v) {
  std::ostringstream s;
  s.precision(17);
  s << v.x() << ' ' << v.y() << ' ' << v.z();
  return s.str();
}

std::string quat(const Eigen::Matrix3d& r) {
  const Eigen::Quaterniond q(r);
  std::ostringstream s;
  s.precision(17);
  s << q.w() << ' ' << q.x() << ' ' << q.y() << ' ' << q.z();
  return s.str();
}

std::string frame(const Eigen::Isometry3d& pose) {
  return " pos=\"" + vec(pose.translation()) + "\" quat=\"" + quat(pose.linear()) + "\"";
}

// A geom's sliding friction (MuJoCo's torsional and rolling ones off).
std::string friction(double mu) { return " friction=\"" + formatNumber(mu) + " 0 0\""; }

// A convex mesh asset of `vertices` (in the frame of the geom that uses it).
std::string meshAsset(Writer& w, const std::vector<Eigen::Vector3d>& vertices) {
  const std::string name = "mesh" + std::to_string(w.meshes++);
  w.assets << "    <mesh name=\"" << name << "\" vertex=\"";
  for (const Eigen::Vector3d& v : vertices) w.assets << vec(v) << ' ';
  w.assets << "\"/>\n";
  return name;
}

// A convex polyhedron that is a box (six faces in three opposite,
// perpendicular pairs) as its pose and full edge lengths. MuJoCo 2.2.2
// collides boxes with its own colliders, several points a pair; a mesh
// against a box through one point of libccd's MPR, whose depth is far off
// for a small body on a large box (docs/mujoco-plugin.md, "Not served yet").
std::optional<std::pair<Eigen::Isometry3d, Eigen::Vector3d>> asBox(const ConvexPolyhedron& p) {
  if (p.faceCount() != 6 || p.vertexCount() != 8) return std::nullopt;
  std::vector<Eigen::Vector3d> axes;
  for (int f = 0; f < 6; ++f) {
    const Eigen::Vector3d n = p.faceNormal(f);
    bool opposite = false, seen = false;
    for (int g = 0; g < 6; ++g) opposite = opposite || n.dot(p.faceNormal(g)) < -1.0 + kBoxPieceCos;
    for (const Eigen::Vector3d& a : axes) seen = seen || std::abs(n.dot(a)) > 1.0 - kBoxPieceCos;
    if (!opposite) return std::nullopt;
    if (!seen) axes.push_back(n);
  }
  if (axes.size() != 3 || std::abs(axes[0].dot(axes[1])) > kBoxPieceCos ||
      std::abs(axes[0].dot(axes[2])) > kBoxPieceCos || std::abs(axes[1].dot(axes[2])) > kBoxPieceCos) {
    return std::nullopt;
  }
  Eigen::Matrix3d r;
  r << axes[0], axes[1], axes[0].cross(axes[1]);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d local = r.transpose() * p.vertex(i);
    lo = lo.cwiseMin(local);
    hi = hi.cwiseMax(local);
  }
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = r;
  pose.translation() = r * (0.5 * (lo + hi));
  return std::make_pair(pose, Eigen::Vector3d(hi - lo));
}

// One collision shape of a body as a geom, at `pose` in the body frame.
void shapeGeom(Writer& w, const Shape& shape, const Eigen::Isometry3d& pose, const std::string& attributes) {
  std::ostream& o = w.bodies;
  switch (shape.kind) {
    case Shape::Kind::kNone:
      return;
    case Shape::Kind::kBox:
      o << "      <geom type=\"box\" size=\"" << vec(shape.box_size / 2.0) << "\"" << frame(pose);
      break;
    case Shape::Kind::kCylinder: {
      // MuJoCo's cylinder runs along z: turned onto the shape's axis.
      Eigen::Isometry3d turned = pose;
      turned.linear() = pose.linear() * Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(),
                                                                           Eigen::Vector3d::Unit(shape.cylinder_axis))
                                            .toRotationMatrix();
      o << "      <geom type=\"cylinder\" size=\"" << shape.radius << ' ' << shape.length / 2.0 << "\""
        << frame(turned);
      break;
    }
    case Shape::Kind::kSphere:
      o << "      <geom type=\"sphere\" size=\"" << shape.radius << "\"" << frame(pose);
      break;
    case Shape::Kind::kHull:
      if (const auto box = asBox(ConvexPolyhedron::fromPoints(shape.hull_vertices))) {
        o << "      <geom type=\"box\" size=\"" << vec(box->second / 2.0) << "\"" << frame(pose * box->first);
      } else {
        o << "      <geom type=\"mesh\" mesh=\"" << meshAsset(w, shape.hull_vertices) << "\"" << frame(pose);
      }
      break;
  }
  o << attributes << "/>\n";
}

// A wheel's tread: a cylinder along its axle, or a sphere (sim::treadIsSphere).
void treadGeom(Writer& w, int i, const Body& body, const sim::EngineSettings& settings) {
  const WheelGeometry& g = body.wheel->geometry;
  std::ostream& o = w.bodies;
  o << "      <geom name=\"tread" << i << "\"";
  if (sim::treadIsSphere(settings, g)) {
    o << " type=\"sphere\" size=\"" << g.free_radius << "\"";
  } else {
    o << " type=\"cylinder\" size=\"" << g.free_radius << ' ' << g.tread_width / 2.0 << "\" quat=\""
      << quat(Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), body.wheel->axle).toRotationMatrix())
      << "\"";
  }
  // WTC's wheels: WTC's contact alone. The engine's own: the ground's friction.
  o << (settings.native_wheels ? std::string(kBodyBits) + friction(0.0) : std::string(kNoContact)) << "/>\n";
}

void writeBody(Writer& w, const sim::EngineSettings& settings, const vehicle::VehicleDescription& v,
               const Eigen::Isometry3d& placement, int i) {
  const Body& b = v.bodies[i];
  const Eigen::Isometry3d pose = sim::startPose(v, i, placement);
  const Eigen::Isometry3d relative = b.parent < 0 ? pose : sim::startPose(v, b.parent, placement).inverse() * pose;
  std::ostream& o = w.bodies;
  o << "    <body name=\"b" << i << "\"" << frame(relative) << ">\n";
  o << "      <inertial pos=\"0 0 0\" mass=\"" << b.mass << "\" diaginertia=\"" << vec(b.inertia) << "\"/>\n";
  if (b.parent < 0) {
    o << "      <freejoint name=\"j" << i << "\"/>\n";
  } else if (b.joint.type != JointType::kFixed) {
    const Eigen::Vector3d anchor = pose.inverse() * (placement * b.joint.anchor);
    const Eigen::Vector3d axis = pose.linear().transpose() * (placement.linear() * b.joint.axis);
    const char* type = b.joint.type == JointType::kRevolute    ? "hinge"
                       : b.joint.type == JointType::kPrismatic ? "slide"
                                                               : "ball";
    o << "      <joint name=\"j" << i << "\" type=\"" << type << "\" pos=\"" << vec(anchor) << "\"";
    if (b.joint.type != JointType::kBall) o << " axis=\"" << vec(axis) << "\"";
    if (b.joint.limits)
      o << " limited=\"true\" range=\"" << b.joint.limits->lower << ' ' << b.joint.limits->upper << "\"";
    o << "/>\n";
  }
  const std::string body_attributes = std::string(kBodyBits) + " priority=\"1\"" + friction(sim::kBodyGroundFriction);
  if (b.wheel) {
    treadGeom(w, i, b, settings);
  } else if (!b.compound.empty()) {
    for (const vehicle::ShapePart& part : b.compound) shapeGeom(w, part.shape, part.pose_BS, body_attributes);
  } else {
    shapeGeom(w, b.shape, Eigen::Isometry3d::Identity(), body_attributes);
  }
  // Children nest inside (the description lists parents first).
  for (std::size_t c = 0; c < v.bodies.size(); ++c) {
    if (v.bodies[c].parent == i) writeBody(w, settings, v, placement, static_cast<int>(c));
  }
  o << "    </body>\n";
}

// The heights MuJoCo's height field gets (m), rows along y, columns along
// x. It has no holes: a sample all of whose cells are holes drops
// kHolePitDepthM below the field's lowest sample of ground, so a body that
// meets a hole falls into a pit, and the cells around a hole slope into it.
// (WTC's wheels see the holes themselves: their ground is WTC's terrain.)
std::vector<double> fieldSamples(const Heightfield& f) {
  std::vector<double> z = f.heights;
  if (!f.hasHoles()) return z;
  const auto allHoles = [&](int r, int c) {
    for (const int cr : {r - 1, r}) {
      for (const int cc : {c - 1, c}) {
        if (cr >= 0 && cc >= 0 && cr < f.rows - 1 && cc < f.cols - 1 && !f.isHole(cr, cc)) return false;
      }
    }
    return true;
  };
  double lowest = std::numeric_limits<double>::infinity();
  std::vector<std::uint8_t> pit(z.size(), 0);
  for (int r = 0; r < f.rows; ++r) {
    for (int c = 0; c < f.cols; ++c) {
      const std::size_t s = static_cast<std::size_t>(r) * f.cols + c;
      pit[s] = allHoles(r, c) ? 1 : 0;
      if (!pit[s]) lowest = std::min(lowest, z[s]);
    }
  }
  if (!std::isfinite(lowest)) lowest = 0.0;  // all holes: nothing to stand on anywhere
  for (std::size_t s = 0; s < z.size(); ++s) {
    if (pit[s]) z[s] = lowest - kHolePitDepthM;
  }
  return z;
}

// The samples' lowest height and their range (m): MuJoCo's height field
// holds heights normalised to [0, 1] of a positive range above the lowest.
struct FieldRange {
  double lowest = 0.0;
  double range = 0.0;
};
FieldRange fieldRange(const std::vector<double>& z) {
  const auto [lo, hi] = std::minmax_element(z.begin(), z.end());
  return {*lo, std::max(*hi - *lo, kFlatFieldRangeM)};
}

// A compact heightfield as one MuJoCo height field, centred on the field's
// box; its samples are written into the compiled model (fillHeightfields).
void heightfieldGeom(Writer& w, const Heightfield& f, std::size_t k, double mu) {
  const FieldRange z = fieldRange(fieldSamples(f));
  const double half_x = 0.5 * (f.cols - 1) * f.spacing_x, half_y = 0.5 * (f.rows - 1) * f.spacing_y;
  w.assets << "    <hfield name=\"field" << k << "\" nrow=\"" << f.rows << "\" ncol=\"" << f.cols << "\" size=\""
           << half_x << ' ' << half_y << ' ' << z.range << ' ' << f.base_depth << "\"/>\n";
  const Eigen::Vector3d centre = f.origin + Eigen::Vector3d(half_x, half_y, z.lowest);
  w.ground << "    <geom type=\"hfield\" hfield=\"field" << k << "\" pos=\"" << vec(centre) << "\"" << kGroundBits
           << friction(mu) << "/>\n";
}

void fillHeightfields(mjModel& m, const Terrain& terrain) {
  int h = 0;
  for (std::size_t k = 0; k < terrain.compactFieldCount(); ++k) {
    const Terrain::CompactField part = terrain.compactField(k);
    if (part.field == nullptr) continue;
    const std::vector<double> samples = fieldSamples(*part.field);
    const FieldRange z = fieldRange(samples);
    float* data = m.hfield_data + m.hfield_adr[h++];
    // Rows along y, columns along x, from the field's low corner (MuJoCo's
    // and WTC's order alike), normalised to [0, 1] of the field's range.
    for (std::size_t s = 0; s < samples.size(); ++s) data[s] = static_cast<float>((samples[s] - z.lowest) / z.range);
  }
}

// The pieces are geoms of the world body. (MuJoCo 2.2.2 tests the world
// body's geoms against every body each step, so a terrain of many pieces
// costs by their count: docs/mujoco-plugin.md. Static bodies per tile of
// ground did worse: its broadphase pairs static bodies whose boxes touch,
// and loops over their geoms before its filter drops the pair.)
void writeGround(Writer& w, const Terrain& terrain) {
  const std::vector<double> mu = sim::nativeWheelFrictions(terrain);
  std::optional<ConvexPolyhedron> scratch;
  const auto pieceGeom = [&](const ConvexPolyhedron& p, MaterialId material) {
    std::ostream& g = w.ground;
    if (const auto box = asBox(p)) {
      g << "    <geom type=\"box\" size=\"" << vec(box->second / 2.0) << "\"" << frame(box->first);
    } else {
      std::vector<Eigen::Vector3d> vertices;
      for (int i = 0; i < p.vertexCount(); ++i) vertices.push_back(p.vertex(i));
      g << "    <geom type=\"mesh\" mesh=\"" << meshAsset(w, vertices) << "\"";
    }
    g << kGroundBits << friction(mu[material]) << "/>\n";
  };
  for (std::size_t s = 0; s < terrain.pieces().size(); ++s) {
    pieceGeom(terrain.pieces()[s], terrain.materialId(terrain.storedId(s)));
  }
  for (std::size_t k = 0; k < terrain.compactFieldCount(); ++k) {
    const Terrain::CompactField part = terrain.compactField(k);
    if (part.field != nullptr) {
      heightfieldGeom(w, *part.field, k, mu[part.material]);
      continue;
    }
    for (PieceId id = part.first; id < part.first + part.count; ++id) {
      pieceGeom(terrain.piece(id, scratch), terrain.materialId(id));
    }
  }
}

void writeMimics(Writer& w, const vehicle::VehicleDescription& v, double step_seconds) {
  for (std::size_t i = 0; i < v.bodies.size(); ++i) {
    const Body& b = v.bodies[i];
    if (b.parent < 0 || !b.joint.mimic) continue;
    // q_i = offset + multiplier q_master: polycoef's a0 + a1 q2. MuJoCo's
    // default solref (a 20 ms time constant) lets the joints part by mrad
    // on rough ground; the stiffest it allows is 2 h, critically damped.
    w.equalities << "    <joint joint1=\"j" << i << "\" joint2=\"j" << b.joint.mimic->master << "\" polycoef=\""
                 << b.joint.mimic->offset << ' ' << b.joint.mimic->multiplier << " 0 0 0\" solref=\""
                 << kMimicTimeConstantSteps * step_seconds << " 1\" solimp=\"" << kDriveImpedance << ' '
                 << kDriveImpedance << " 0.001\"/>\n";
  }
}

std::unique_ptr<mjModel, ModelDeleter> compile(const std::string& xml) {
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  mj_makeEmptyFileVFS(vfs.get(), "vehicle.xml", static_cast<int>(xml.size()));
  std::memcpy(vfs->filedata[mj_findFileVFS(vfs.get(), "vehicle.xml")], xml.data(), xml.size());
  char error[1000] = "";
  mjModel* m = mj_loadXML("vehicle.xml", vfs.get(), error, sizeof error);
  mj_deleteVFS(vfs.get());
  if (m == nullptr) throw InvalidInputError(std::string(kWhere) + ": MuJoCo refused the model: " + error);
  return std::unique_ptr<mjModel, ModelDeleter>(m);
}

}  // namespace

VehicleModel buildVehicleModel(const sim::EngineSettings& settings, const Terrain& terrain,
                               const vehicle::VehicleDescription& v, const Eigen::Isometry3d& placement) {
  Writer w;
  writeGround(w, terrain);
  for (std::size_t i = 0; i < v.bodies.size(); ++i) {
    if (v.bodies[i].parent < 0) writeBody(w, settings, v, placement, static_cast<int>(i));
  }
  writeMimics(w, v, settings.step_seconds);
  std::ostringstream xml;
  xml.precision(17);
  // Euler: constraint mode's stages are Euler's (euler_stages.hpp). The
  // elliptic cone with impratio: docs/mujoco-plugin.md, "Friction".
  xml << "<mujoco model=\"" << v.name << "\">\n"
      << "  <compiler angle=\"radian\"/>\n"
      << "  <option timestep=\"" << settings.step_seconds << "\" integrator=\"Euler\" cone=\"elliptic\" impratio=\""
      << kImpratio << "\" mpr_iterations=\"" << kMprIterations << "\" gravity=\"0 0 " << -kGravityMps2 << "\"/>\n"
      << "  <size nconmax=\"" << kContacts << "\" njmax=\"" << kConstraintRows << "\"/>\n"
      << "  <asset>\n"
      << w.assets.str() << "  </asset>\n"
      << "  <worldbody>\n"
      << w.ground.str() << w.bodies.str() << "  </worldbody>\n"
      << "  <equality>\n"
      << w.equalities.str() << "  </equality>\n"
      << "</mujoco>\n";
  VehicleModel out;
  out.model = compile(xml.str());
  mjModel& m = *out.model;
  fillHeightfields(m, terrain);
  for (std::size_t i = 0; i < v.bodies.size(); ++i) {
    const std::string n = std::to_string(i);
    out.body.push_back(mj_name2id(&m, mjOBJ_BODY, ("b" + n).c_str()));
    const int joint = mj_name2id(&m, mjOBJ_JOINT, ("j" + n).c_str());
    out.dof.push_back(joint < 0 ? -1 : m.jnt_dofadr[joint]);
    out.qpos.push_back(joint < 0 ? -1 : m.jnt_qposadr[joint]);
    out.wheel_geom.push_back(mj_name2id(&m, mjOBJ_GEOM, ("tread" + n).c_str()));
  }
  return out;
}

}  // namespace wtc::mujoco
