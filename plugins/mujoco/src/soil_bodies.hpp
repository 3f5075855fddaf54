#pragma once
// The plugin's bodies on soft soil (internal to wtc::mujoco; design note in
// include/wtc/mujoco/plugin.hpp, addSoilBody): each step puts every body's
// soil force (wtc::BodyOnSoil) into its xfrc_applied, and
// dropRigidContacts takes its MuJoCo contacts on soil pieces out of the
// step after mj_collision.
#include <memory>
#include <vector>

#include <mujoco/mujoco.h>

#include "added_wrench.hpp"
#include "wtc/mujoco/plugin.hpp"
#include "wtc/tyre/body_soil.hpp"

namespace wtc::mujoco {

/// How far from a MuJoCo contact's point its terrain piece is looked for
/// (m): the point lies midway between the two surfaces, within half the
/// penetration of the piece, millimetres; 5 cm leaves room for a deep one.
inline constexpr double kSoilContactReachM = 0.05;

class SoilBodies {
 public:
  SoilBodyId add(const mjModel& m, const SoilBody& spec, bool is_wheel);
  /// Every body's soil force for a step of h, added to its xfrc_applied
  /// (at the centre of mass); the user's own kept for restore().
  void step(const mjModel& m, mjData& d, const Terrain& terrain, GroundMemory* memory, double h);
  /// Puts each body's xfrc_applied back as step found it.
  void restore(mjData& d);
  /// Marks excluded the contacts of this step between a soil body's geom
  /// and a geom welded to the world at a point whose nearest piece has a
  /// soil: the soil carries the body there, not MuJoCo's rigid contact.
  void dropRigidContacts(const mjModel& m, mjData& d, const Terrain& terrain) const;
  const BodySoilForces& forces(SoilBodyId id) const;
  int count() const { return static_cast<int>(bodies_.size()); }
  bool has(int body) const;

 private:
  struct Body {
    int body;
    BodyOnSoil soil;
    BodySoilForces last;
    AddedWrench wrench;  // the soil force in xfrc_applied this step
  };
  std::vector<std::unique_ptr<Body>> bodies_;
};

}  // namespace wtc::mujoco
