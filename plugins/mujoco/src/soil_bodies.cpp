// The plugin's bodies on soft soil (soil_bodies.hpp).
#include "soil_bodies.hpp"

#include <algorithm>
#include <string>

#include "src/conversions.hpp"
#include "wtc/base/error.hpp"

namespace wtc::mujoco {

SoilBodyId SoilBodies::add(const mjModel& m, const SoilBody& spec, bool is_wheel) {
  static constexpr const char* kWhere = "wtc::mujoco::Plugin::addSoilBody";
  if (spec.body <= 0 || spec.body >= m.nbody) {
    throw InvalidInputError(std::string(kWhere) + ": body " + std::to_string(spec.body) +
                            (spec.body == 0 ? " is the world" : " is not a body of the model"));
  }
  if (is_wheel) {
    throw InvalidInputError(std::string(kWhere) + ": body " + std::to_string(spec.body) +
                            " is a registered wheel's: the soil meets it as one");
  }
  if (has(spec.body)) {
    throw InvalidInputError(std::string(kWhere) + ": body " + std::to_string(spec.body) + " is already a soil body");
  }
  if (m.body_weldid[spec.body] == 0) {
    throw InvalidInputError(std::string(kWhere) + ": body " + std::to_string(spec.body) +
                            " is welded to the world: the soil cannot move it");
  }
  bodies_.push_back(std::make_unique<Body>(Body{
      .body = spec.body, .soil = BodyOnSoil(spec.hulls, m.body_mass[spec.body], kWhere), .last = {}, .wrench = {}}));
  return static_cast<SoilBodyId>(bodies_.size() - 1);
}

bool SoilBodies::has(int body) const {
  return std::any_of(bodies_.begin(), bodies_.end(), [&](const auto& b) { return b->body == body; });
}

void SoilBodies::step(const mjModel& m, mjData& d, const Terrain& terrain, GroundMemory* memory, double h) {
  for (const auto& b : bodies_) {
    const int i = b->body;
    // The hulls' frame is the body's (xpos, xmat).
    const Eigen::Vector3d origin = vec3(d.xpos + 3 * i);
    const PointVelocity v = velocityAt(m, d, i, origin);
    BodySoilMotion motion;
    motion.pose.linear() = mat3(d.xmat + 9 * i);
    motion.pose.translation() = origin;
    motion.angular_velocity = v.angular;
    motion.velocity = v.linear;
    b->last = b->soil.step(terrain, memory, motion, h);
    // About the frame's origin.
    if (b->last.nodes > 0) b->wrench.add(d, i, b->last.force, b->last.torque, origin);
  }
}

void SoilBodies::restore(mjData& d) {
  for (const auto& b : bodies_) b->wrench.restore(d);
}

void SoilBodies::dropRigidContacts(const mjModel& m, mjData& d, const Terrain& terrain) const {
  if (bodies_.empty()) return;
  const auto pieceCount = static_cast<PieceId>(terrain.pieceCount());
  for (int i = 0; i < d.ncon; ++i) {
    mjContact& c = d.contact[i];
    const int b1 = m.geom_bodyid[c.geom1], b2 = m.geom_bodyid[c.geom2];
    const bool ground1 = m.body_weldid[b1] == 0, ground2 = m.body_weldid[b2] == 0;
    if (ground1 == ground2 || !has(ground1 ? b2 : b1)) continue;
    const PieceId piece = terrain.nearestPiece(vec3(c.pos), 0, pieceCount, kSoilContactReachM);
    if (piece >= 0 && terrain.material(piece).soil) c.exclude = 1;  // mj_instantiateContact skips it
  }
}

const BodySoilForces& SoilBodies::forces(SoilBodyId id) const {
  if (id < 0 || static_cast<std::size_t>(id) >= bodies_.size()) {
    throw InvalidInputError("wtc::mujoco::Plugin::soilForces: soil body " + std::to_string(id) +
                            " is not registered (" + std::to_string(bodies_.size()) + " soil bodies)");
  }
  return bodies_[static_cast<std::size_t>(id)]->last;
}

}  // namespace wtc::mujoco
