#pragma once
// A body's underside on soft soil (issue 55: a belly dragging in sand;
// docs/soft-soil.md, "A body on the soil"). The engines collide a vehicle's
// own bodies (a chassis, a towed body's hull) with hard ground themselves;
// where the ground is a soil (a piece whose material has one) a rigid
// contact would hold a belly on the fresh surface, as if the sand were
// concrete. A BodyOnSoil instead presses the soil as a Bekker plate does,
// node by node of a grid under the body, as Project Chrono's SCM presses
// its grid under any body:
//
//   at a node (x, y) of cell area s^2, the body's underside z_b(x, y) (a
//   vertical line's entry into the body's convex hulls) lies Z = z_f - z_b
//   below the fresh surface z_f (the top of the terrain's highest piece
//   there, a piece with a soil);
//   sigma = reloadStress(soil, b, memory, Z) (Bekker's k Z^n on fresh soil,
//   Wong's reloading line where the ground remembers), plus the soil's
//   damping R v_in (v_in the node's speed into the soil), at least 0;
//   the node carries sigma s^2 along the surface's normal, and a shear
//   (c + sigma tan phi) s^2 against its sliding, ramped to zero over the
//   speed it could reverse within a step, max(eps, h F_s / (kappa m))
//   (F_s the whole shear's bound, as the wheels' rest ramp), and
//   where the ground remembers, the node keeps pressedSoil(soil, b, memory, Z):
//   the rut a belly leaves.
//
// b, Bekker's plate width, is the smaller extent of the nodes that carry
// the body, along the body's own x and y axes (plus a cell). At rest on
// fresh soil a flat plate of area A and weight W sinks Bekker's
// z = (W / (A (k_c / b + k_phi)))^(1/n) (tests/tyre/body_soil_test.cpp).
//
// Left out, and said in docs/soft-soil.md: the soil's push on the body's
// sides and front (a belly ploughing forward meets only the shear under
// it), the shear's memory (Janosi's displacement: the shear is a ramped
// Coulomb law), and bulldozing by a body (its nodes are compacted).
#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "wtc/geometry/convex_polyhedron.hpp"
#include "wtc/terrain/terrain.hpp"
#include "wtc/tyre/ground_memory.hpp"

namespace wtc {

/// The grid a body presses fresh soil on, outside every soil region (m):
/// the regions' default spacing. Inside a region the body presses the
/// region's own nodes.
inline constexpr double kBodySoilSpacingM = 0.02;
/// The shear's rest ramp is h F_s / (kappa m) wide (kappa, dimensionless):
/// the tyre's default stability fraction (TyreParameters::stability_fraction).
inline constexpr double kBodySoilStability = 0.4;
/// Its smallest width (m/s): the tyre's default slip speed floor.
inline constexpr double kBodySoilSpeedFloorMps = 1e-3;

/// A body's state for one step: the pose of its frame (the frame its hulls
/// are given in), the velocity of that frame's origin and its spin.
struct BodySoilMotion {
  Eigen::Isometry3d pose{Eigen::Isometry3d::Identity()};
  Eigen::Vector3d velocity{Eigen::Vector3d::Zero()};          ///< m/s, world.
  Eigen::Vector3d angular_velocity{Eigen::Vector3d::Zero()};  ///< rad/s, world.
};

/// What the soil did to the body in one step.
struct BodySoilForces {
  Eigen::Vector3d force{Eigen::Vector3d::Zero()};   ///< N, world.
  Eigen::Vector3d torque{Eigen::Vector3d::Zero()};  ///< N m about the body frame's origin, world.
  int nodes = 0;                                    ///< Nodes under the body that carried it.
  double area = 0.0;                                ///< Their cells' area (m^2).
  double plate_width = 0.0;                         ///< Bekker's b (m).
  double deepest = 0.0;                             ///< The largest Z (m) below the fresh surface.
  double normal_force = 0.0;                        ///< The pressures' sum, sum sigma s^2 (N).
};

class BodyOnSoil {
 public:
  /// `hulls`: the body's collision shape in its own frame (m), one or more
  /// convex hulls; `mass` (kg, > 0, finite) sets the shear's rest ramp.
  /// InvalidInputError naming `where` for no hull, a hull without volume or
  /// with a coordinate not finite, or a mass out of range.
  BodyOnSoil(std::vector<ConvexPolyhedron> hulls, double mass, const std::string& where = "BodyOnSoil");
  ~BodyOnSoil();
  BodyOnSoil(BodyOnSoil&&) noexcept;
  BodyOnSoil& operator=(BodyOnSoil&&) noexcept;

  /// The soil's force on the body for a step of `step_seconds` from
  /// `motion`, over every soil piece of `terrain` under it; with a memory,
  /// in its regions the body meets the remembered surface and presses it.
  /// Zero where the body is above every soil, and for a motion that is not
  /// finite (nothing pressed).
  BodySoilForces step(const Terrain& terrain, GroundMemory* memory, const BodySoilMotion& motion, double step_seconds);

  std::span<const ConvexPolyhedron> hulls() const { return hulls_; }
  double mass() const { return mass_; }

 private:
  struct Scratch;  // the step's work arrays, kept between steps (body_soil.cpp)
  std::vector<ConvexPolyhedron> hulls_;
  double mass_;
  std::unique_ptr<Scratch> scratch_;
};

}  // namespace wtc
