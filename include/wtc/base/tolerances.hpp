#pragma once
// Every geometric tolerance of WTC, named, with its unit, in one place.
//
// Lengths are relative to a piece's size (the diagonal of its bounding box)
// wherever the algorithm is scale-free, so that a 1 mm bolt head and a 100 m
// slab behave the same. kRoundoff is the base value; the others are multiples
// of it, chosen with the reason written beside them.
namespace wtc::tolerance {

/// Unit roundoff of double (dimensionless): 2^-52.
inline constexpr double kRoundoff = 2.220446049250313e-16;

/// Default relative tolerance of the point query (dimensionless): GJK stops
/// when its bounds prove the closest point to within this fraction of the
/// distance (the distance itself then to tol^2 / 2). On polyhedra GJK ends
/// exactly (no new support vertex) in a few iterations, so the default sits
/// near roundoff: the exact stop decides, not the tolerance.
inline constexpr double kQueryRelativeTolerance = 1e3 * kRoundoff;

/// Distance below which a point counts as on the surface (relative to piece
/// size): there the direction p -> closest point is noise, so the face normal
/// is reported instead.
inline constexpr double kTouchingRelative = 1e2 * kRoundoff;

/// Roundoff slack when comparing two computations of the distance to one
/// face plane (relative to piece size + distance): 64 ulps.
inline constexpr double kPlaneSlackRelative = 64 * kRoundoff;

/// Points of a hull closer than this are merged; vertices farther than this
/// from a face's plane make a trusted face list non-planar (relative to piece
/// size). 1e-9 keeps 1 mm features distinct on a 1 km piece.
inline constexpr double kHullMergeRelative = 1e-9;

/// Thickness below which a point set is a flat piece (relative to size).
inline constexpr double kFlatRelative = 1e-9;

/// A compact part's piece is found beyond a wheel's reach from its corners'
/// face planes, without forming it, only when they clear the reach by this
/// margin (relative to the largest coordinate of the point and the
/// corners, m / m). The formed piece's planes are the same ones computed
/// another way (in its local frame, Newell normals): they differ by
/// roundoff, a few ulps of those coordinates divided by a face's sine
/// (below). 1e-9 is far above that, and far below any reach: at worst a
/// piece 5 um beyond a wheel 5 km from the origin is formed, not skipped.
inline constexpr double kFormedPlaneMarginRelative = 1e-9;

/// A face whose two edges at a corner make a smaller sine than this
/// (dimensionless) is a sliver: its normal is left to roundoff, so its plane
/// is not used to skip the piece (the others still are).
inline constexpr double kFormedPlaneMinSine = 1e-3;

/// Default iteration cap of the point query. GJK on a polyhedron with V
/// vertices needs at most a handful more iterations than simplex changes;
/// 64 is never reached on valid pieces (see the characterisation tests).
inline constexpr int kDefaultMaxIterations = 64;

/// Pieces with more vertices than this find support points by hill climbing
/// over the vertex adjacency instead of a linear scan (count of vertices;
/// measured crossover, see bench/point_query_bench.cpp).
inline constexpr int kHillClimbMinVertices = 48;

}  // namespace wtc::tolerance

namespace wtc::tolerance {

/// Two ground pieces closer than this are one surface at a seam (relative to
/// the wheel's free radius): a contact point this close to (or inside)
/// another touching piece that is nearer to the wheel centre is an internal
/// seam, not ground (docs/wheel-contact.md). 1e-6 x 0.19 m = 0.19 um: far
/// above the roundoff of shared heightfield vertices, far below any real gap.
inline constexpr double kSeamGapRelative = 1e-6;

/// Smallest acceptable |axle| before normalising (dimensionless; the axle
/// is a direction, its length is discarded).
inline constexpr double kMinAxleNorm = 1e-9;

/// |a x n| below which a wheel lies on its side on soft soil, its axle
/// along the surface normal, and has no arc to integrate (the sine of the
/// angle between them; src/tyre/soil_contact.cpp).
inline constexpr double kWheelOnItsSideSine = 1e-9;

/// Where the ground remembers, the rim's entry (src/tyre/wheel_soil.cpp):
/// at the fresh surface's entry a rim within this fraction of its radius
/// above the remembered surface meets it there, as on fresh ground (the
/// round trip acos / cos leaves ~1e-16 r), and the search for an entry
/// inside stops within kSoilEntryRad of the crossing or where the rim is
/// within kSoilEntryRelative of the radius of the remembered surface.
inline constexpr double kSoilFreshEntryRelative = 1e-12;
inline constexpr double kSoilEntryRelative = 1e-9;
inline constexpr double kSoilEntryRad = 1e-9;

/// A point is a soil grid's node when it lies within this fraction of the
/// grid's spacing of it, along x and y (dimensionless): a saved ground
/// memory's coordinates, printed to 17 digits, are the nodes' own to
/// roundoff; a point a micrometre off a 2 cm grid's node is another point.
inline constexpr double kSoilNodeRelative = 1e-6;

}  // namespace wtc::tolerance

namespace wtc::tolerance {

/// The tyre model's tread deflection is capped where mu(s) has reached
/// mu_max within this fraction (dimensionless): the steady state then
/// matches the slip law to 1e-4 relative, and a wheel that stops spinning
/// unwinds at most s1 ln(1e4 (1 + s2)) relaxation lengths of tread.
inline constexpr double kTractionSaturation = 1e-4;

/// Implicit mode's row along the law's force keeps at least this fraction
/// of the law's initial stiffness (dimensionless) where mu(s) is flat or
/// falling (saturated, or past a peak): the row then pushes with the law's
/// force at the start of the step, as force mode does, its target velocity
/// finite (R_z mu / (1e-3 k (w + tau)): about 4 km/s for the robot's wheel
/// at 0.4 ms, far from any velocity it meets, so the row stays on its bound).
inline constexpr double kTreadSlopeFloor = 1e-3;

/// A contact inherits the tread state of the previous step's contact whose
/// direction e is within 30 deg; this is cos(30 deg) (dimensionless). 30 deg
/// keeps a seam crossing (same e) and a rolling over an edge (e turns by
/// well under a degree per step) continuous, and keeps the face and ground
/// contacts of a ledge foot (e 90 deg apart) apart.
inline constexpr double kTreadStateMatchCos = 0.8660254037844387;
// Two face normals of one piece within this cosine are the same face: the
// pushed-out face of a centre inside a piece is then the query's own
// (wheel_contact.cpp), and the query's values are kept bit for bit.
inline constexpr double kSameFaceNormalCos = 1.0 - 1e-12;

/// After a call that found the ground at a wheel's cut cap, the next looks
/// for cap contacts out to r_f (1 + this) (dimensionless): 2 % (3.8 mm on
/// the robot's wheel), above the millimetre an engine's contact on the cap's
/// rim lets the wheel rise and fall, so that the engine's cap collision
/// (which these contacts switch on) does not come and go.
inline constexpr double kCapHysteresisRelative = 0.02;

/// A sticking contact's friction runs along the rest load's part in its
/// tangent plane when that part is above this fraction of the load
/// (dimensionless); on level ground (below it) its direction is the usual.
inline constexpr double kRestLoadRelative = 1e-9;

}  // namespace wtc::tolerance

namespace wtc::tolerance {

/// A scene's duration is a whole number of its steps when duration / dt is
/// within this fraction of an integer (dimensionless): far above the
/// roundoff of dividing two decimal numbers (18 / 0.00005 is 360000 to a
/// few ulps), far below any step a user means (1e-9 of a 25 s run is 25 ns).
inline constexpr double kWholeStepsRelative = 1e-9;

/// A drive whose solved force is within this fraction of its cap is at its
/// cap (dimensionless): a capped row's force is the cap itself, read back
/// through the joint's feedback and its unit axis with a few ulps of
/// roundoff; far below any margin a controller leaves (ODE's drive rows,
/// plugins/ode/sim/src/drive_rows.hpp).
inline constexpr double kDriveAtCapRelative = 1e-9;

}  // namespace wtc::tolerance

namespace wtc::tolerance {

/// A run's vehicle may gain at most the energy of lifting it this high
/// (m) beyond its energy after the first step plus its drives' work
/// (sim::EnergyBalance; the limit is m g times this, J): more was made
/// from nothing, and the run is not a success. Every shipped scene, in
/// Bullet and ODE, in force and constraint mode, gains none at all (the
/// measured margins: docs/vehicles-and-scenes.md, "Energy and bounds").
inline constexpr double kEnergyGrowthHeightM = 0.01;

}  // namespace wtc::tolerance

namespace wtc::tolerance {

/// The replay's height grid (wtc::sim::replayTerrain) finds a piece under
/// a grid point when the point is inside each of the piece's side planes
/// within this (relative to the piece's size): two pieces that share a wall
/// (a heightfield's cells) then both hold a point on it, rather than
/// neither by roundoff. As kHullMergeRelative: far above roundoff, far
/// below any feature.
inline constexpr double kReplayGridSlackRelative = 1e-9;

}  // namespace wtc::tolerance

namespace wtc::tolerance {

/// A URDF collision element counts as centred on its body's centre of mass
/// when it is nearer than this (m), and as along the body's axes when its
/// axes are within this of them (dimensionless, a cosine's distance from 1
/// or a sine): then it is the body's plain shape, not a compound part. A
/// roll of pi/2 written as 1.5707963267948966 leaves 6e-17 in the rotation;
/// 1e-9 is far above that and far below any intended offset or tilt.
inline constexpr double kUrdfShapeOffsetM = 1e-9;
inline constexpr double kUrdfAxisAlignment = 1e-9;

/// A wheel link's cylinder must lie along its joint's axis to within this
/// sine (dimensionless), and be centred on the link's centre of mass to
/// within this distance (m): WTC's wheel turns about its centre on its axle.
inline constexpr double kUrdfWheelAxisSine = 1e-6;
inline constexpr double kUrdfWheelCentreM = 1e-6;

/// Bullet's wheel drives: two wheels share one articulated-body solve
/// (plugins/bullet/sim/src/wheel_drive_responses.hpp) when each wheel's
/// centre of mass is on its joint's axis, the axis is a principal axis of
/// its inertia, and the two axles are parallel, each to within this
/// (dimensionless: a sine, or a length or moment relative to the wheel's
/// own). Those hold exactly for a wheel built on its axle; 1e-12 admits
/// the rounding of the frames they are computed in, and the shared solve
/// then differs from Bullet's own by rounding alone.
inline constexpr double kSharedDriveSolveRelative = 1e-12;

}  // namespace wtc::tolerance
