#pragma once
// The limits of the mobility events (wtc::mobility): the test ground, the
// engines and modes, and per event its speeds, search ranges, durations
// and criteria (docs/mobility.md). Every field has a default; a settings
// file (apps/wtc-mobility/settings.yaml shows every key with its default)
// changes any of them, and loadMobilitySettings refuses a bad one at its
// file:line:col.
#include <filesystem>
#include <string>
#include <vector>

#include "wtc/terrain/material.hpp"

namespace wtc::mobility {

/// Every event's drives ramp from rest to their rate over this (s): the
/// event scenes' schedules, and the bounds that count the wheels' travel.
inline constexpr double kEventRampS = 1.0;

/// A bisection: the largest value that passes in [low, high], to `resolution`.
struct Search {
  double low = 0.0;         ///< Assumed to pass (not run).
  double high = 0.0;        ///< Assumed to fail if it is not run and passes: tried first.
  double resolution = 0.0;  ///< The search stops when high - low <= resolution (> 0).
};

struct StepSettings {
  double approach_speed_mps = 0.3;  ///< The plain drive's speed on the level, r_f omega (m/s).
  double approach_m = 1.0;          ///< From the front wheels to the face at the start (m).
  double top_m = 3.0;               ///< The ledge's top, past the face (m).
  Search height_m{0.0, 0.8, 0.01};  ///< The issue's 1 cm.
  double duration_s = 25.0;  ///< At least (a plain drive's run lasts until the whole vehicle could be past the face).
  bool vehicle_controller = true;  ///< Use the vehicle's own climbing controller where it has one (climb).
};

struct GradeSettings {
  double wheel_rate_radps = 3.0;  ///< The driven wheels' commanded rate (ramped over 1 s).
  Search degrees{0.0, 45.0, 0.25};
  double min_progress_m = 0.3;  ///< Climbed: the first body moved at least this far (m, horizontal).
  double duration_s = 6.0;
};

/// A held event (parked, side_slope) on a tilt table (sim::TiltTable, SAE
/// J2180): the vehicle settles on level ground, then the table turns at
/// rate_deg_s up to the search's top, in one run; the answer is the angle at
/// which it tipped or slid (slide_m over the table). rate_deg_s 0: the
/// bisection instead, a run on a slope of each angle tried.
struct TiltSettings {
  /// (deg/s): halving 0.5 moved the shipped vehicles' answers and the tilt
  /// cart's by under 0.1 deg (docs/mobility.md).
  double rate_deg_s = 0.5;
  double slide_m = 0.005;  ///< (m), sim::TiltTable::slide_m.
};

struct ParkedSettings {
  Search degrees{0.0, 45.0, 0.25};
  TiltSettings tilt;
  /// Held: at the end the first body moves at most this fast (m/s), having moved at most max_slide_m
  /// (the tyres' tread and the sections settle by up to 6 cm near the limit, then hold; a vehicle that
  /// slides and stops elsewhere, the towed system jackknifing across a slope, did not hold).
  double max_final_speed_mps = 0.005;
  double max_slide_m = 0.2;
  double duration_s = 5.0;
};

struct SideSlopeSettings {
  Search degrees{0.0, 60.0, 0.25};
  TiltSettings tilt;
  double max_final_speed_mps = 0.005;  ///< Holds: at the end it moves at most this fast (m/s); slides beyond.
  double max_slide_m = 0.2;            ///< And moved at most this far (m), as ParkedSettings's.
  double max_tilt_deg = 30.0;          ///< Tips: a root tilted this much beyond the slope (deg).
  double duration_s = 5.0;
};

struct DrawbarSettings {
  double speed_mps = 0.3;  ///< The anchor's speed V, and the vehicle's at the start (m/s).
  /// The driving slips i = (omega r - V) / (omega r) (dimensionless, in [0, 1)); the wheels run at
  /// omega = V / (r_f (1 - i)).
  std::vector<double> slips{0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 0.9};
  /// k / W (1/m): a pull of W at 5 mm. Stiff, because the slip law acts on the vehicle as a damper
  /// mu'(s) W / (V (1 + s)) that, with k, sets the rig's slow time constant mu'(s) / (V (1 + s) k / W):
  /// 0.08 s at i = 5 %, V = 0.3 m/s (0.8 s at k / W = 20, where 3 s of settling left the pull 3.6 % short).
  double stiffness_per_weight = 200.0;
  double damping_ratio = 1.0;  ///< c / (2 sqrt(k m)) (dimensionless).
  double settle_s = 3.0;       ///< Before the mean (s).
  double mean_s = 1.0;         ///< The pull's mean over this stretch (s).
};

struct CoastSettings {
  double speed_mps = 1.0;   ///< The issue's 1 m/s.
  double fit_from_s = 0.3;  ///< The fitted line starts past the tread's first loading (s).
  double duration_s = 3.0;
};

struct BrakingSettings {
  double speed_mps = 2.0;  ///< The issue's 2 m/s.
  double duration_s = 3.0;
};

struct GapSettings {
  double approach_speed_mps = 0.3;
  double approach_m = 1.0;
  Search width_m{0.0, 0.8, 0.01};
  double duration_s = 20.0;
};

struct TurnSettings {
  double wheel_rate_radps = 3.0;  ///< Left wheels -omega, right +omega (ramped over 1 s).
  double duration_s = 6.0;
};

struct MobilitySettings {
  Material ground;                                    ///< The test ground (default: asphalt, mu_max 0.8, f_r 0.018).
  std::vector<std::string> engines{"bullet", "ode"};  ///< Engine table names.
  std::vector<std::string> modes{"force"};            ///< force, constraint, engine_cylinder, engine_sphere.
  double dt_s = 4e-4;
  std::vector<std::string> events{"step",  "grade",   "parked", "side_slope", "drawbar",
                                  "coast", "braking", "gap",    "turn"};
  StepSettings step;
  GradeSettings grade;
  ParkedSettings parked;
  SideSlopeSettings side_slope;
  DrawbarSettings drawbar;
  CoastSettings coast;
  BrakingSettings braking;
  GapSettings gap;
  TurnSettings turn;
};

/// The names of the events, in the report's order.
const std::vector<std::string>& eventNames();

/// The defaults changed by the file at `path` (YAML: the keys of the structs
/// above, without units: `grade: {degrees: [0, 45, 0.25], min_progress: 0.3}`).
/// Throws InvalidInputError "<path>:<line>:<col>: <key>: <problem>" for an
/// unknown key, a value of the wrong kind, a number out of its range, an
/// unknown event, engine or mode.
MobilitySettings loadMobilitySettings(const std::filesystem::path& path);

/// Throws InvalidInputError naming the field for a setting out of range
/// (what loadMobilitySettings checks, for settings made in code).
void validate(const MobilitySettings& settings);

}  // namespace wtc::mobility
