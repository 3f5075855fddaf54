#pragma once
// The MuJoCo sim engine's own constants (internal to wtc::mujoco_sim), with
// units; the constants every engine shares are wtc/sim/sim_constants.hpp's.

namespace wtc::mujoco {

/// opt.impratio of the models the engine builds (dimensionless): MuJoCo's
/// friction rows are this much stiffer than their contact's normal row. A
/// WTC contact's friction creeps at F / (impratio (h c + b)) m/s per newton
/// F (docs/mujoco-plugin.md, "Friction"): at 10, 5 mm/s under 50 N for the
/// default tyre at 0.4 ms, where 1 (MuJoCo's default) lets it creep 53 mm/s.
inline constexpr double kImpratio = 10.0;

/// The contact list's length and the constraint rows' (opt nconmax, njmax):
/// room for a vehicle's bodies on many pieces, and its wheels' contacts.
/// MuJoCo 2.2.2's mjData holds a dense njmax x njmax matrix (efc_AR), so
/// the rows cost memory as their square (8 MB at 1000). The engine refuses
/// a step that ran out of either (sim_engine.cpp, requireRoom).
inline constexpr int kContacts = 2000;
inline constexpr int kConstraintRows = 1000;

/// A MuJoCo height field needs a positive elevation range: a flat field's
/// (m), which its samples' normalised heights (all 0) do not use.
inline constexpr double kFlatFieldRangeM = 1e-3;

/// How far below a height field's lowest sample of ground its holes' samples
/// go (m): MuJoCo's height fields have none (mjcf_model.cpp, fieldSamples).
inline constexpr double kHolePitDepthM = 1.0;

/// A drive is its joint's friction row with a velocity target
/// (sim_engine.cpp): its impedance (MuJoCo's largest, mjMAXIMP: the row is
/// as rigid as MuJoCo makes one), and the effort cap of a drive whose
/// limits are off (N m or N; a friction row needs a finite bound).
inline constexpr double kDriveImpedance = 0.9999;
inline constexpr double kUncappedDriveEffort = 1e9;

/// A mimic's joint equality: its time constant in steps (MuJoCo refuses one
/// under 2 h: mjMINVAL's safety, "refsafe"), damping ratio 1, and the
/// drives' impedance.
inline constexpr double kMimicTimeConstantSteps = 2.0;

/// opt.mpr_iterations: libccd's MPR, MuJoCo's collider for a hull against
/// another convex shape (count).
inline constexpr int kMprIterations = 1000;

}  // namespace wtc::mujoco
