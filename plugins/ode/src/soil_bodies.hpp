#pragma once
// The plugin's bodies on soft soil (internal to wtc::ode; design note in
// include/wtc/ode/plugin.hpp, addSoilBody): each beginStep puts every
// body's soil force (wtc::BodyOnSoil) on it, and keepRigidContacts drops
// its rigid contacts on soil pieces.
#include <memory>
#include <unordered_map>
#include <vector>

#include <ode/ode.h>

#include "wtc/ode/plugin.hpp"
#include "wtc/ode/terrain_geoms.hpp"
#include "wtc/tyre/body_soil.hpp"
#include "wtc/tyre/ground_memory.hpp"

namespace wtc::ode {

class SoilBodies {
 public:
  SoilBodyId add(const SoilBody& spec, bool is_wheel);
  /// Every body's soil force for a step of h, on the body (dBodyAddForce:
  /// ODE clears it after the world step).
  void step(const Terrain& terrain, GroundMemory* memory, double h);
  const BodySoilForces& forces(SoilBodyId id) const;
  int count() const { return static_cast<int>(bodies_.size()); }
  int keepRigidContacts(const TerrainGeoms& terrain, dGeomID a, dGeomID b, dContactGeom* contacts, int count,
                        int stride) const;

 private:
  struct Body {
    dBodyID body;
    BodyOnSoil soil;
    BodySoilForces last;
  };
  std::vector<std::unique_ptr<Body>> bodies_;
  std::unordered_map<dBodyID, SoilBodyId> of_body_;
};

}  // namespace wtc::ode
