#pragma once

// The constants of whole-vehicle runs (wtc::sim), with units, in one place;
// the core's physical constants are in wtc/base/constants.hpp.
#include "wtc/base/constants.hpp"

#include <numbers>

namespace wtc::sim {

/// Coulomb friction of a vehicle's non-wheel bodies (chassis, carriers)
/// against the ground, in every engine (dimensionless): what a steel frame
/// scraping asphalt has, roughly; only off-design contacts use it.
inline constexpr double kBodyGroundFriction = 0.6;

/// A body beyond any of these has diverged (an unstable step, an
/// explosion), and a run stops there as it does at a non-finite state:
/// no vehicle of WTC's comes near them, and ODE's hash space aborts the
/// process on bounding boxes beyond about 1e9 m (an assertion in
/// collision_space.cpp), which a run that went on would reach. The
/// distance is the largest a description may give (kMaxLengthM).
inline constexpr double kDivergedSpeedMps = 1e3;
inline constexpr double kDivergedAngularSpeedRadps = 1e4;
inline constexpr double kDivergedDistanceM = kMaxLengthM;

/// Two contacts of one pair of bodies (or a body and the ground) closer
/// than this (m), with normals whose cosine is within kDuplicateContactCos
/// of 1 (dimensionless), are one contact found twice (a box against two
/// terrain pieces that share a face). Kept as ODE's collider gives them,
/// they are left out of a step only when they made ODE's direct solver give
/// up (its Dantzig LCP meets their rows as a degenerate pair;
/// docs/hard-cases.md). 1 nm: far below any feature, far above roundoff of
/// coordinates of a few metres.
inline constexpr double kDuplicateContactM = 1e-9;
inline constexpr double kDuplicateContactCos = 1e-12;

/// How far beyond its depth a body's contact point may lie from a terrain
/// face, or from a face of the body, and still be on it, when a sim engine
/// finds the normals a heightfield's surface can give there
/// (sim::TerrainNormalCone): 0.1 mm (m), plus 1e-6 of the point's largest
/// coordinate (dimensionless). ODE's colliders put a contact a few float
/// ulps off the surface (docs/ode-plugin.md, "Terrain shapes": 2e-6 m at
/// 10 m); the reach is far above that and far below any terrain feature (a
/// heightfield's cell is 1 cm or more).
inline constexpr double kTerrainFaceReachM = 1e-4;
inline constexpr double kTerrainFaceReachPerM = 1e-6;
/// The same cone's numerical slack (dimensionless): two faces are the two
/// sides of one wall when their normals' cosine is within it of -1, and a
/// projection onto the cone shorter than it vanishes.
inline constexpr double kTerrainNormalSlack = 1e-9;
/// A contact's normal this close to the cone (the sine of the angle, rad)
/// is in it: a body's roll about a terrain edge from roundoff tilts its
/// face's normal off the edge's cone by up to 5e-7 rad, a meaningless
/// difference, where the normals the cone corrects are tens of degrees off.
inline constexpr double kTerrainNormalToleranceRad = 1e-3;

/// A vehicle's joints that came apart by more than this over a run (the
/// largest gap at a joint's anchor, the largest angle off its axis,
/// vehicle::jointError) did not hold the mechanism the description gives:
/// the run warns, and a mobility trial does not count. A joint solved to
/// the engines' tolerance stays within microns and thousandths of a degree.
inline constexpr double kJointGapBoundM = 1e-3;
inline constexpr double kJointAngleBoundRad = 0.1 * std::numbers::pi / 180.0;

/// A body's centre may go this far (m) beyond the terrain's bounding box,
/// horizontally, or below its lowest point, before the run counts as having
/// left its terrain (not a success): a vehicle at the terrain's edge has
/// centres beyond it by less than its own length.
inline constexpr double kTerrainBoundsMarginM = 2.0;
/// A body's shape that starts deeper than this in the terrain is said
/// before the run (m): the engines' own contacts push out a millimetre's
/// overlap over several steps, a deeper one in a kick (a 5 mm bumper at
/// about 1 m/s).
inline constexpr double kStartOverlapM = 1e-3;
/// A tilt table's vehicle tipped when all its uphill wheels have had no
/// contact this long (s): longer than a bounce of a settled tyre off the
/// ground (a few steps), far shorter than a tilt of 0.1 deg at 1 deg/s.
inline constexpr double kTiltLiftHoldS = 0.02;
/// A tilt table's run ends this long after the tip or the slide (s): the
/// answer is in; what follows (a fall) is not measured.
inline constexpr double kTiltAfterS = 0.2;

/// The most triangles the replay page of a run draws of its terrain
/// (wtc::sim::replayTerrain; docs/vehicles-and-scenes.md gives the bytes
/// this makes): a terrain within it is drawn whole, a larger one only
/// around the vehicle's path, and coarser where that is still too much.
/// A page stays a few MB whatever the terrain (a large compact
/// heightfield drawn whole made a page no browser finished drawing).
inline constexpr long long kReplayTerrainMaxTriangles = 100'000;
/// How far beyond every body's positions over the run a terrain too large
/// to draw whole is drawn (m, horizontally): more than the page's camera,
/// 6 m from the vehicle, shows around it.
inline constexpr double kReplayTerrainMarginM = 10.0;
/// How often a run's replay keeps the ruts of soil that remembers (s of
/// simulated time): a wheel at 0.2 m/s moves 5 cm between two; each looks
/// at every touched node, so a long run's snapshots cost its nodes times
/// its duration over this.
inline constexpr double kReplaySoilPeriodS = 0.25;

/// A mimic joint (URDF's <mimic>) is held as a velocity constraint with its
/// position error fed back at this fraction per step (dimensionless), as a
/// joint's ERP: ODE's default ERP 0.2, Bullet's gear constraint the same.
inline constexpr double kMimicErp = 0.2;
/// A mimic's two axes count as parallel when |cos| is within this of 1
/// (dimensionless): ODE holds such a mimic between two bodies only when its
/// multiplier is the axes' cos, +1 or -1 (within kMimicParallelMultiplier:
/// the two children then turn together, a steering linkage).
inline constexpr double kMimicParallelCos = 1e-6;
inline constexpr double kMimicParallelMultiplier = 1e-9;
/// The largest impulse a mimic's constraint applies in one step (N m s):
/// unlimited in effect, as the rods or gears of a differential are rigid.
inline constexpr double kMimicMaxImpulse = 1e6;

}  // namespace wtc::sim
