// The events' scenes (wtc/mobility/event_scenes.hpp). Geometry in the
// vehicle frame of its file: x forward, y left, z up, ground at z = 0.
#include "wtc/mobility/event_scenes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include <Eigen/Geometry>

#include "wtc/base/constants.hpp"
#include "wtc/base/error.hpp"
#include "wtc/vehicle/controllers/climb_controller.hpp"

namespace wtc::mobility {
namespace {

constexpr double kMarginM = 0.5;          // ground beyond what the run needs, each way (m)
constexpr double kPieceThicknessM = 0.5;  // every piece's thickness (m)
constexpr double kRunsOnFactor = 1.5;     // a search run lasts this many times its nominal travel time
constexpr double kSameLengthTolM = 1e-6;  // lengths closer than this are one (a lift, a track's half width; m)
constexpr double kTiltSettleS = 1.0;   // a tilt table's level start: the vehicle settles (s)
constexpr double kTiltPastTopS = 0.5;  // the run goes on past the table's top (s): a tip at the top is seen

// The wheels' extent in x (vehicle frame, m): the rearmost and frontmost contact reach.
struct Extent {
  double rear = 0.0, front = 0.0;              // x of the rearmost wheel's back, the frontmost's front
  double wheel_rear = 0.0, wheel_front = 0.0;  // their centres' x
  double r_front = 0.0, r_min = 0.0, r_max = 0.0;
  double half_width = 0.0;  // the largest |y| of a wheel plus its half width
};

Extent extent(const EventVehicle& v) {
  Extent e{.rear = INFINITY,
           .front = -INFINITY,
           .wheel_rear = INFINITY,
           .wheel_front = -INFINITY,
           .r_front = 0.0,
           .r_min = INFINITY,
           .r_max = 0.0,
           .half_width = 0.0};
  for (const WheelInfo& w : v.statics.wheels) {
    const double x = w.position.x(), r = w.radius_m;
    e.rear = std::min(e.rear, x - r);
    if (x + r > e.front) {
      e.front = x + r;
      e.r_front = r;
    }
    e.wheel_rear = std::min(e.wheel_rear, x);
    e.wheel_front = std::max(e.wheel_front, x);
    e.r_min = std::min(e.r_min, r);
    e.r_max = std::max(e.r_max, r);
    e.half_width = std::max(e.half_width, std::abs(w.position.y()) + r);
  }
  return e;
}

std::string sceneNumber(double v) {
  std::ostringstream out;
  out.precision(10);
  out << v;
  return out.str();
}

std::string list(const std::vector<std::string>& names) {
  std::string out = "[";
  for (std::size_t i = 0; i < names.size(); ++i) out += (i ? ", " : "") + names[i];
  return out + "]";
}

std::vector<std::string> drivenWheels(const EventVehicle& v) {
  std::vector<std::string> names;
  for (const WheelInfo& w : v.statics.wheels) {
    if (w.driven) names.push_back(w.name);
  }
  return names;
}

// The drives that are not wheels' (the robot's sections): held at their reference positions.
std::vector<std::string> otherDrives(const EventVehicle& v) {
  std::vector<std::string> names;
  for (const int b : v.description.actuated()) {
    if (!v.description.bodies[b].wheel) names.push_back(v.description.bodies[b].name);
  }
  return names;
}

// The driven wheels' common radius (their rates are set from it; the shipped vehicles' driven wheels
// share one).
double drivenRadius(const EventVehicle& v) {
  for (const WheelInfo& w : v.statics.wheels) {
    if (w.driven) return w.radius_m;
  }
  throw InvalidInputError("wtc::mobility: vehicle '" + v.description.name + "' has no driven wheel");
}

// The slowest of the driven wheels' drive limits (max_speed, rad/s): a
// commanded rate beyond it is clamped (wtc/vehicle/drive.hpp).
double drivenMaxRate(const EventVehicle& v) {
  double rate = std::numeric_limits<double>::infinity();
  for (const WheelInfo& w : v.statics.wheels) {
    if (w.driven && w.max_rate_radps > 0.0) rate = std::min(rate, w.max_rate_radps);
  }
  return rate;
}

// A schedule controller: the driven wheels at `points` (velocity), the other drives held.
std::string schedule(const EventVehicle& v, const std::string& wheel_points) {
  std::string s = "controller:\n  type: schedule\n  schedules:\n";
  s += "    - {drives: " + list(drivenWheels(v)) + ", mode: velocity, points: " + wheel_points + "}\n";
  if (!otherDrives(v).empty()) s += "    - {drives: " + list(otherDrives(v)) + ", mode: position, points: [[0, 0]]}\n";
  return s;
}

std::string onlyOthersHeld(const EventVehicle& v) {
  if (otherDrives(v).empty()) return "controller: {type: none}\n";
  return "controller:\n  type: schedule\n  schedules:\n    - {drives: " + list(otherDrives(v)) +
         ", mode: position, points: [[0, 0]]}\n";
}

std::string ground(const Material& g) {
  std::string soil;
  if (g.soil) {
    soil = ", soil: {name: " + g.soil->name;
    for (const SoilField& f : soilFields())
      soil += ", " + std::string(f.name) + ": " + sceneNumber((*g.soil).*f.member);
    soil += "}";
  }
  return "terrain:\n  materials:\n    ground: {mu_max: " + sceneNumber(g.mu_max) + ", s1: " + sceneNumber(g.s1) +
         ", s2: " + sceneNumber(g.s2) + ", rolling_resistance: " + sceneNumber(g.rolling_resistance) + soil +
         "}\n  pieces:\n";
}

// How far the vehicle frame must rise for its lowest wheel to stand on the
// ground (m): 0 for a vehicle whose frame is at ground level (the shipped
// ones: a wheel centre at z = r), a URDF's base link's height for one whose
// frame is its base (a car with wheels 0.12 m below it started them in the
// ground: issue 57 row 4's kick).
double groundLift(const EventVehicle& v) {
  double lift = 0.0;
  for (const WheelInfo& w : v.statics.wheels) lift = std::max(lift, w.radius_m - w.position.z());
  return lift > kSameLengthTolM ? lift : 0.0;
}

std::string placement(const EventVehicle& v, Eigen::Vector3d t, const Eigen::Matrix3d& R,
                      const std::string& extra = "") {
  t += R.col(2) * groundLift(v);
  const Eigen::AngleAxisd aa(R);
  Eigen::Vector3d axis = aa.axis();
  double degrees = aa.angle() * 180.0 / std::numbers::pi;
  if (std::abs(degrees) < 1e-12) axis = Eigen::Vector3d::UnitZ();
  return "vehicle: {file: '" + v.file.string() + "', translation: [" + sceneNumber(t.x()) + ", " + sceneNumber(t.y()) +
         ", " + sceneNumber(t.z()) + "], rotation: {axis: [" + sceneNumber(axis.x()) + ", " + sceneNumber(axis.y()) +
         ", " + sceneNumber(axis.z()) + "], degrees: " + sceneNumber(degrees) + "}" + extra + "}\n";
}

// `text` inside single quotes in YAML: a quote doubled.
std::string quoted(const std::string& text) {
  std::string out;
  for (const char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out;
}

std::string head(const EventVehicle& v, const std::string& event, double value, const std::string& description,
                 double duration, const Material& ground) {
  return "# A mobility event's trial, written by wtc-mobility (docs/mobility.md): replay it with wtc-sim.\n"
         "name: " +
         sceneName(v, event, value) + "\ndescription: '" + quoted(description) +
         "'\nduration: " + sceneNumber(duration) + "\neffects: [full" + (ground.soil ? ", soft_soil" : "") +
         "]\noutput: {rate_hz: 100}\n";
}

// A flat slab around the vehicle's path from x0 to x1 (m).
std::string slab(double x0, double x1, double half_width) {
  const double length = x1 - x0 + 2.0 * kMarginM, width = 2.0 * (half_width + kMarginM) + 4.0;
  return "    - {type: slab, material: ground, size: [" + sceneNumber(length) + ", " + sceneNumber(width) +
         "], thickness: " + sceneNumber(kPieceThicknessM) + ", translation: [" + sceneNumber(0.5 * (x0 + x1)) +
         ", 0, 0]}\n";
}

// A duration that is a whole number of 0.1 s (so any dt dividing 0.1 s divides it).
double roundDuration(double seconds) { return std::ceil(seconds * 10.0 - 1e-9) / 10.0; }

}  // namespace

std::string sceneName(const EventVehicle& v, const std::string& event, double value) {
  std::string name = v.description.name + "_" + event;
  if (isTiltTable(event, value)) {
    name += "_tilt_table";
  } else if (event == "step" || event == "grade" || event == "parked" || event == "side_slope" ||
             event == "drawbar" || event == "gap") {
    char text[32];
    std::snprintf(text, sizeof text, "_%.6g", value);
    name += text;
  }
  for (char& c : name) {
    const bool ok =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.';
    if (!ok) c = '_';
  }
  return name;
}

bool hasClimbingController(const vehicle::VehicleDescription& v) {
  try {
    vehicle::ClimbController controller(v, vehicle::ClimbControllerParams{}, "wtc::mobility");
    return true;
  } catch (const InvalidInputError&) {
    return false;
  }
}

bool isSkidSteered(const VehicleStatics& v) {
  if (!v.allDriven() || v.roots.size() != 1) return false;
  const double half = std::abs(v.wheels.front().position.y());
  return std::all_of(v.wheels.begin(), v.wheels.end(),
                     [&](const WheelInfo& w) { return std::abs(std::abs(w.position.y()) - half) < kSameLengthTolM; });
}

std::string eventScene(const EventVehicle& v, const std::string& event, double value, const MobilitySettings& s) {
  const Extent e = extent(v);
  const double r = drivenRadius(v);
  const double length = e.front - e.rear;
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  std::string text;
  if (event == "step" || event == "gap") {
    // Front of the vehicle `approach` before the face at x = 0; climbed (crossed): the rearmost wheel's
    // back past the face (the far edge) by a margin, so the first body moved approach + length + margin.
    const bool step = event == "step";
    const double speed = step ? s.step.approach_speed_mps : s.gap.approach_speed_mps;
    const double approach = step ? s.step.approach_m : s.gap.approach_m;
    const double far = step ? 0.0 : value;
    const double travel = approach + length + far + kMarginM;
    const double duration = roundDuration(
        std::max(step ? s.step.duration_s : s.gap.duration_s, kRunsOnFactor * travel / speed + kEventRampS));
    const bool own = step && s.step.vehicle_controller && hasClimbingController(v.description);
    // The ground past the face (the far edge) holds the whole travel and, for a plain drive that never
    // stops, all it can roll in the run: its front at most speed (duration - ramp / 2) from the start,
    // rolling without slip (a short vehicle's run is long: the settings' duration is the robot's climb).
    const double reach = own ? 0.0 : speed * (duration - 0.5 * kEventRampS) - approach - far + kMarginM;
    const double beyond = std::max(length + 2.0 + travel, reach);
    text = head(
        v, event, value,
        step ? "The tallest step: a ledge of " + sceneNumber(value) + " m, " +
                   (own ? "the vehicle's climbing controller" : "plain drive forward") + " at " + sceneNumber(speed) +
                   " m/s."
             : "The widest gap: " + sceneNumber(value) + " m, plain drive forward at " + sceneNumber(speed) + " m/s.",
        duration, s.ground);
    text += ground(s.ground);
    if (step) {
      text += "    - {type: ledge, material: ground, height: " + sceneNumber(value) +
              ", approach_length: " + sceneNumber(approach + length + 2.0 * kMarginM) +
              ", top_length: " + sceneNumber(beyond) + ", width: " + sceneNumber(2.0 * e.half_width + 2.0) +
              ", thickness: " + sceneNumber(kPieceThicknessM) + "}\n";
    } else {
      // Two boxes, top faces at z = 0, `value` apart: nothing under the gap.
      const double near_len = approach + length + 2.0 * kMarginM, far_len = beyond;
      const double w = 2.0 * e.half_width + 2.0, depth = 1.0;
      text += "    - {type: box, material: ground, size: [" + sceneNumber(near_len) + ", " + sceneNumber(w) + ", " +
              sceneNumber(depth) + "], translation: [" + sceneNumber(-0.5 * near_len) + ", 0, " +
              sceneNumber(-0.5 * depth) + "]}\n";
      text += "    - {type: box, material: ground, size: [" + sceneNumber(far_len) + ", " + sceneNumber(w) + ", " +
              sceneNumber(depth) + "], translation: [" + sceneNumber(value + 0.5 * far_len) + ", 0, " +
              sceneNumber(-0.5 * depth) + "]}\n";
    }
    text += placement(v, Eigen::Vector3d(-approach - e.front, 0.0, 0.0), I);
    if (own) {
      text += "controller: {type: climb, approach_speed: " + sceneNumber(speed) + "}\n";
    } else {
      text += schedule(v, "[[0, 0], [" + sceneNumber(kEventRampS) + ", " + sceneNumber(speed / r) + "]]");
    }
    // The climbing controller stops once on top: every wheel's centre above the top (equal radii, as the
    // controller's robot has); a plain drive keeps driving: the rearmost wheel past the face (the far edge).
    if (own) {
      text += "success: {min_wheel_height: " + sceneNumber(value + e.r_min - 0.01) + ", max_tilt_deg: 45}\n";
    } else {
      text += "success: {min_advance: " + sceneNumber(approach + length + far + 0.1) + ", max_tilt_deg: 45}\n";
    }
    return text;
  }
  if (isTiltTable(event, value)) {
    // Level ground under the vehicle, and the table turning (sim::TiltTable) after a second's settling up
    // to the search's top. Across: about x, the vehicle facing +x (its right side falls). Parked: about y,
    // whose +x side falls, so the vehicle faces -x, up the grade.
    const bool side = event == "side_slope";
    const TiltSettings& tilt = side ? s.side_slope.tilt : s.parked.tilt;
    const double top = side ? s.side_slope.degrees.high : s.parked.degrees.high;
    const double duration = roundDuration(kTiltSettleS + top / tilt.rate_deg_s + kTiltPastTopS);
    text = head(v, event, value,
                std::string(side ? "Across a tilt table" : "Up a tilt table") + ", wheels held: the table turns at " +
                    sceneNumber(tilt.rate_deg_s) + " deg/s to " + sceneNumber(top) +
                    " deg; the angle where it tips or slides.",
                duration, s.ground);
    text += ground(s.ground);
    const double reach = std::max({e.front, -e.rear, e.half_width}) + kMarginM;
    text += "    - {type: slab, material: ground, size: [" + sceneNumber(2.0 * reach + 2.0) + ", " +
            sceneNumber(2.0 * reach + 2.0) + "], thickness: " + sceneNumber(kPieceThicknessM) + "}\n";
    const Eigen::Matrix3d R = side ? I : Eigen::Matrix3d(Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d::UnitZ()));
    text += placement(v, Eigen::Vector3d::Zero(), R);
    text += schedule(v, "[[0, 0]]");
    text += "tilt_table: {axis: " + std::string(side ? "x" : "y") + ", rate_deg_s: " + sceneNumber(tilt.rate_deg_s) +
            ", start_s: " + sceneNumber(kTiltSettleS) + ", slide_m: " + sceneNumber(tilt.slide_m) + "}\n";
    text += "success: {max_tilt_deg: 90}\n";
    return text;
  }
  if (event == "grade" || event == "parked" || event == "side_slope") {
    const double theta = value * std::numbers::pi / 180.0;
    const bool grade = event == "grade", side = event == "side_slope";
    const double progress = grade ? s.grade.min_progress_m : 0.0;
    const double duration =
        roundDuration(grade ? s.grade.duration_s : (side ? s.side_slope.duration_s : s.parked.duration_s));
    // The incline rises along +x from its foot at x = 0. Climbing and parked: the vehicle faces up it,
    // pitched by theta. Across it: its x axis along world y, its y axis down the slope, z the slope's normal.
    const double x_s = (side ? e.half_width : -e.rear) + kMarginM;
    const double slope_length =
        x_s + (side ? e.half_width : e.front) + progress / std::max(std::cos(theta), 0.1) + 2.0 * kMarginM + 1.0;
    Eigen::Matrix3d R = Eigen::AngleAxisd(-theta, Eigen::Vector3d::UnitY()).toRotationMatrix();
    if (side) {
      R.col(0) = Eigen::Vector3d::UnitY();
      R.col(1) = Eigen::Vector3d(-std::cos(theta), 0.0, -std::sin(theta));
      R.col(2) = Eigen::Vector3d(-std::sin(theta), 0.0, std::cos(theta));
    }
    const std::string what = grade
                                 ? "The steepest grade climbed from rest: "
                                 : (side ? "Parked across a slope, wheels held: " : "Parked up a grade, wheels held: ");
    text = head(v, event, value, what + sceneNumber(value) + " deg.", duration, s.ground);
    text += ground(s.ground);
    text += "    - {type: incline, material: ground, degrees: " + sceneNumber(value) +
            ", length: " + sceneNumber(slope_length) +
            ", width: " + sceneNumber(2.0 * (side ? length : e.half_width) + 4.0) +
            ", thickness: " + sceneNumber(kPieceThicknessM) + "}\n";
    text += placement(v, Eigen::Vector3d(x_s, 0.0, x_s * std::tan(theta)), R);
    if (grade) {
      text +=
          schedule(v, "[[0, 0], [" + sceneNumber(kEventRampS) + ", " + sceneNumber(s.grade.wheel_rate_radps) + "]]");
      text += "success: {min_advance: " + sceneNumber(progress * std::cos(theta)) +
              ", max_tilt_deg: " + sceneNumber(value + 30.0) + "}\n";
    } else {
      text += schedule(v, "[[0, 0]]");
      text += "success: {max_final_speed: " +
              sceneNumber(side ? s.side_slope.max_final_speed_mps : s.parked.max_final_speed_mps) +
              ", max_distance: " + sceneNumber(side ? s.side_slope.max_slide_m : s.parked.max_slide_m) +
              ", max_tilt_deg: " + sceneNumber(value + (side ? s.side_slope.max_tilt_deg : 30.0)) + "}\n";
    }
    return text;
  }
  if (event == "drawbar" || event == "coast" || event == "braking") {
    // The drawbar's wheels turn at omega = V / (r_f (1 - i)); where that is beyond the drives' limit, which
    // would clamp it and impose a smaller slip than asked, the anchor and the vehicle go slower instead:
    // V = min(V, omega_max r_f (1 - i)) (the slip law, and so DP/W, depends on the slip alone).
    const double speed = event == "drawbar" ? std::min(s.drawbar.speed_mps, drivenMaxRate(v) * r * (1.0 - value))
                                            : (event == "coast" ? s.coast.speed_mps : s.braking.speed_mps);
    const double duration =
        roundDuration(event == "drawbar" ? s.drawbar.settle_s + s.drawbar.mean_s
                                         : (event == "coast" ? s.coast.duration_s : s.braking.duration_s));
    const double travel = speed * duration + 1.0;
    text = head(v, event, value,
                event == "drawbar" ? "Drawbar pull at driving slip " + sceneNumber(value) + ", anchor at " +
                                         sceneNumber(speed) + " m/s."
                                   : (event == "coast" ? "Coast-down from " + sceneNumber(speed) + " m/s, drives off."
                                                       : "Locked-wheel stop from " + sceneNumber(speed) + " m/s."),
                duration, s.ground);
    text += ground(s.ground) + slab(e.rear - kMarginM, e.front + travel, e.half_width);
    text += placement(v, Eigen::Vector3d::Zero(), I, ", velocity: [" + sceneNumber(speed) + ", 0, 0]");
    if (event == "drawbar") {
      // The wheels at omega = V / (r_f (1 - i)) from the start, the anchor on a spring k = (k/W) W with
      // damping ratio zeta (c = 2 zeta sqrt(k m)), at ground level below the first body's centre of mass:
      // a horizontal pull there has no moment about the ground line, so it moves no load between the
      // axles (the bound's level loads); a pull at height h would move DP h / wheelbase.
      const double k = s.drawbar.stiffness_per_weight * v.statics.weight();
      const double c = 2.0 * s.drawbar.damping_ratio * std::sqrt(k * v.statics.mass_kg);
      const vehicle::Body& first = v.description.bodies.front();
      const Eigen::Vector3d p = first.pose.translation();
      text += schedule(v, "[[0, " + sceneNumber(speed / (r * (1.0 - value))) + "]]");
      text += "drawbar: {body: " + first.name + ", point: [" + sceneNumber(p.x()) + ", " + sceneNumber(p.y()) + ", 0" +
              "], speed: " + sceneNumber(speed) + ", stiffness: " + sceneNumber(k) + ", damping: " + sceneNumber(c) +
              "}\n";
    } else if (event == "coast") {
      text += onlyOthersHeld(v);
    } else {
      text += schedule(v, "[[0, 0]]");
    }
    return text;
  }
  if (event == "turn") {
    if (!isSkidSteered(v.statics)) {
      throw InvalidInputError("wtc::mobility: vehicle '" + v.description.name +
                              "' is not skid-steered (every wheel driven, on one track): no turning in place");
    }
    const double duration = roundDuration(s.turn.duration_s);
    text = head(v, event, value,
                "Turning in place: left wheels at -" + sceneNumber(s.turn.wheel_rate_radps) + " rad/s, right at +" +
                    sceneNumber(s.turn.wheel_rate_radps) + " rad/s.",
                duration, s.ground);
    text += ground(s.ground) + slab(-length - 2.0, length + 2.0, length + 2.0);
    text += placement(v, Eigen::Vector3d::Zero(), I);
    std::vector<std::string> left, right;
    for (const WheelInfo& w : v.statics.wheels) (w.position.y() > 0.0 ? left : right).push_back(w.name);
    const std::string ramp = "[[0, 0], [" + sceneNumber(kEventRampS) + ", ";
    text += "controller:\n  type: schedule\n  schedules:\n";
    text += "    - {drives: " + list(left) + ", mode: velocity, points: " + ramp +
            sceneNumber(-s.turn.wheel_rate_radps) + "]]}\n";
    text += "    - {drives: " + list(right) + ", mode: velocity, points: " + ramp +
            sceneNumber(s.turn.wheel_rate_radps) + "]]}\n";
    if (!otherDrives(v).empty()) {
      text += "    - {drives: " + list(otherDrives(v)) + ", mode: position, points: [[0, 0]]}\n";
    }
    return text;
  }
  throw InvalidInputError("wtc::mobility: unknown event '" + event + "'");
}

}  // namespace wtc::mobility
