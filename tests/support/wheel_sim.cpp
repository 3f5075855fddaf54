#include "wheel_sim.hpp"

#include <cmath>

#include <Eigen/Geometry>

#include "wtc/terrain/terrain_primitives.hpp"

namespace wtc::testing {

Terrain tiltedSlab(double slope_rad, const Material& material) {
  TerrainBuilder builder;
  const MaterialId id = builder.addMaterial(material);
  SlabParams slab;
  slab.size_x = slab.size_y = 20.0;
  // A rotation about y by -slope maps +x to (cos, 0, sin): rising toward +x.
  slab.pose_WL = Eigen::Isometry3d(Eigen::AngleAxisd(-slope_rad, Eigen::Vector3d::UnitY()));
  addSlab(builder, slab, id);
  return std::move(builder).build();
}

Terrain flatGround(int tiles, const Material& material) {
  TerrainBuilder builder;
  SlabParams slab;
  slab.size_x = slab.size_y = 40.0;
  slab.tiles_x = slab.tiles_y = tiles;
  addSlab(builder, slab, builder.addMaterial(material));
  return std::move(builder).build();
}

namespace {
// Two flanks along y rising at `slope_rad` from x = -edge and x = +edge
// (m) to x = -+1 m, each a prism down to z = -1 m.
void addFlanks(TerrainBuilder& builder, MaterialId material, double slope_rad, double edge) {
  const double rise = std::tan(slope_rad);
  for (const double side : {-1.0, 1.0}) {
    const double inner = side * edge;
    builder.addPiece(ConvexPolyhedron::fromPoints({{side, -1, rise},
                                                   {inner, -1, 0},
                                                   {side, 1, rise},
                                                   {inner, 1, 0},
                                                   {side, -1, -1},
                                                   {inner, -1, -1},
                                                   {side, 1, -1},
                                                   {inner, 1, -1}}),
                     material);
  }
}
}  // namespace

Terrain valley(double slope_rad) {
  TerrainBuilder builder;
  addFlanks(builder, builder.addMaterial({}), slope_rad, 0.0);
  return std::move(builder).build();
}

Terrain trough(double slope_rad, double floor_width) {
  TerrainBuilder builder;
  const MaterialId material = builder.addMaterial({});
  const double edge = 0.5 * floor_width;
  builder.addPiece(ConvexPolyhedron::box({-edge, -1, -1}, {edge, 1, 0}), material);
  addFlanks(builder, material, slope_rad, edge);
  return std::move(builder).build();
}

Eigen::Vector3d slabNormal(double slope_rad) { return {-std::sin(slope_rad), 0.0, std::cos(slope_rad)}; }
Eigen::Vector3d downhill(double slope_rad) { return {-std::cos(slope_rad), 0.0, -std::sin(slope_rad)}; }

void restOnSlab(SimWheel& wheel, double slope_rad) {
  const double load = wheel.mass * kGravityMps2 * std::cos(slope_rad);
  const double deflection = load / wheel.description.tyre.radial_stiffness;
  wheel.center = (wheel.description.geometry.free_radius - deflection) * slabNormal(slope_rad);
  wheel.velocity.setZero();
  wheel.spin = 0.0;
}

const WheelForces& step(const TyreModel& model, const Terrain& terrain, double h, SimWheel& wheel) {
  WheelMotion motion;
  motion.velocity = wheel.velocity;
  motion.angular_velocity = wheel.spin * wheel.axle;
  const WheelForces& forces =
      model.step(terrain, wheel.description, {wheel.center, wheel.axle}, motion, h, wheel.state);
  const Eigen::Vector3d gravity{0.0, 0.0, -kGravityMps2};
  wheel.velocity += h * (forces.force / wheel.mass + gravity);
  wheel.center += h * wheel.velocity;
  if (!wheel.locked) {
    wheel.spin +=
        h * (forces.axial_moment.dot(wheel.axle) + wheel.drive_torque) / wheel.description.inertia.axial_inertia;
  }
  return forces;
}

}  // namespace wtc::testing
