// Scene files: every shipped scene loads; overrides reach any value (lists
// included) and parameters; bad scenes are refused before anything runs,
// naming the file, the line, the key and the problem.
#include "wtc/sim/scene_file.hpp"

#include <unistd.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "vehicle/controllers/controller_types.hpp"
#include "wtc/base/error.hpp"
#include "wtc/sim/engine_table.hpp"
#include "wtc/tyre/contact_mode.hpp"
#include "wtc/tyre/traction_law.hpp"

namespace wtc::sim {
namespace scene_file_test {

using ::testing::HasSubstr;
namespace fs = std::filesystem;
const fs::path kScenes = fs::path(WTC_SOURCE_DIR) / "scenes";

std::vector<fs::path> shippedScenes() {
  std::vector<fs::path> all;
  for (const auto& entry : fs::directory_iterator(kScenes)) {
    if (entry.path().extension() == ".yaml") all.push_back(entry.path());
  }
  std::sort(all.begin(), all.end());
  return all;
}

// The error of loading `text` as a scene beside the shipped ones (so that
// its relative paths resolve), with `overrides`, and of asking the engine
// table for its engine (as wtc-sim and wtc-study do before anything runs).
// A folder of this process's own beside scenes/ (the text's paths are
// relative to it, as a shipped scene's are): the suite and the sanitized
// suite run at once from one source tree, and a shared file name let one
// remove the other's scene (seen in a fresh root: "file not found").
fs::path scratchFolder() { return fs::path(WTC_SOURCE_DIR) / ("scenes_test_" + std::to_string(::getpid())); }

fs::path scratchFile(const std::string& name) {
  fs::create_directories(scratchFolder());
  return scratchFolder() / name;
}

std::string errorOf(const std::string& text, std::vector<Override> overrides = {}) {
  const fs::path path = scratchFile("wtc_scene_file_test.yaml.tmp");
  std::ofstream(path) << text;
  std::string said = "no error";
  try {
    requireEngine(loadScene(path, overrides).engine);
  } catch (const InvalidInputError& e) {
    said = e.what();
  }
  fs::remove_all(scratchFolder());
  return said;
}

const std::string kMinimal =
    "name: t\nduration: 1\nterrain: ../terrains/flat.yaml\nvehicle: ../vehicles/six_wheel_robot.yaml\n"
    "controller: {type: none}\n";

TEST(SceneFileTest, EveryShippedSceneLoadsAndNamesItsVehicleAndController) {
  const auto scenes = shippedScenes();
  ASSERT_GE(scenes.size(), 6u);
  for (const fs::path& file : scenes) {
    const sim::Scene scene = loadScene(file);
    EXPECT_EQ(scene.name, file.stem().string()) << file;
    EXPECT_GT(scene.duration_seconds, 0.0) << file;
    EXPECT_FALSE(scene.vehicle.bodies.empty()) << file;
    EXPECT_THAT(scene.controller_type, ::testing::AnyOf("schedule", "path", "climb")) << file;
    EXPECT_NE(scene.make_controller(), nullptr) << file;
  }
}

TEST(SceneFileTest, OverridesReachValuesListsAndParameters) {
  const fs::path file = kScenes / "robot_straight.yaml";
  const sim::Scene plain = loadScene(file);
  EXPECT_EQ(plain.parameters.at("wheel_rate"), 4.0);
  const std::vector<Override> overrides = {
      parseOverride("engine=ode_quick"), parseOverride("mode=constraint"),
      parseOverride("dt=0.001"),         parseOverride("solver_residual=1e-8"),
      parseOverride("wheel_rate=2.5"),   parseOverride("vehicle.translation=[1, 2, 0.5]"),
      parseOverride("output.rate_hz=50")};
  const sim::Scene s = loadScene(file, overrides);
  EXPECT_EQ(s.engine.engine, "ode_quick");
  EXPECT_EQ(s.engine.mode, ContactMode::kConstraint);
  EXPECT_FALSE(s.engine.native_wheels);
  EXPECT_EQ(s.engine.step_seconds, 0.001);
  EXPECT_EQ(s.engine.solver_residual, 1e-8);
  EXPECT_EQ(s.parameters.at("wheel_rate"), 2.5);
  EXPECT_EQ(s.placement.translation(), Eigen::Vector3d(1, 2, 0.5));
  EXPECT_EQ(s.output.rate_hz, 50.0);
  // A list element by index: the second schedule's single point.
  const sim::Scene t =
      loadScene(file, std::vector<Override>{parseOverride("controller.schedules.1.points.0=[0, 0.1]")});
  vehicle::VehicleState state;
  state.time = 0.0;
  std::vector<vehicle::DriveCommand> commands(t.vehicle.bodies.size());
  t.make_controller()->update(state, commands);
  EXPECT_EQ(commands[t.vehicle.find("front_slider")].value, 0.1);
}

// A case parameter picks derived parameters; a material given its static
// coefficient (mu_peak) gets the s2 whose peak it is (the spec's mapping).
TEST(SceneFileTest, CasesPickParametersAndMuPeakSetsS2) {
  for (const auto& [which, dynamic, peak] : {std::tuple{"1", 0.45, 0.75}, {"2", 0.30, 0.50}, {"3", 0.21, 0.35}}) {
    const sim::Scene s = loadScene(kScenes / "towed_incline.yaml", std::vector<Override>{{"friction_case", which}});
    const Material& m = s.terrain->material(0);
    EXPECT_EQ(m.mu_max, dynamic) << which;
    EXPECT_NEAR(tractionPeak(m), peak, 1e-9) << which;
    EXPECT_NEAR(m.s2, 4.44, 0.01) << which;  // the spec's s2 for a static/dynamic ratio of 5/3
  }
}

// Case: every WTC contact mode is a scene's mode, by the name summaries and
// run directories use.
TEST(SceneFileTest, EveryWtcContactModeIsASceneModeByItsName) {
  const fs::path file = kScenes / "robot_straight.yaml";
  for (const ContactMode mode : {ContactMode::kForce, ContactMode::kConstraint, ContactMode::kImplicit}) {
    const std::string name(contactModeName(mode));
    const sim::Scene s = loadScene(file, std::vector<Override>{parseOverride("mode=" + name)});
    EXPECT_EQ(s.engine.mode, mode) << name;
    EXPECT_FALSE(s.engine.native_wheels) << name;
    EXPECT_EQ(sim::modeName(s.engine), name);
  }
}

TEST(SceneFileTest, TheEnginesOwnWheelContactIsAMode) {
  const fs::path file = kScenes / "robot_straight.yaml";
  const std::vector<Override> to_cylinder = {parseOverride("mode=engine_cylinder")};
  const std::vector<Override> to_sphere = {parseOverride("mode=engine_sphere")};
  const sim::Scene cylinder = loadScene(file, to_cylinder);
  EXPECT_EQ(cylinder.engine.native_wheels, sim::NativeWheelShape::kCylinder);
  EXPECT_EQ(sim::modeName(cylinder.engine), "engine_cylinder");
  const sim::Scene sphere = loadScene(file, to_sphere);
  EXPECT_EQ(sphere.engine.native_wheels, sim::NativeWheelShape::kSphere);
  EXPECT_EQ(sim::modeName(sphere.engine), "engine_sphere");
  EXPECT_EQ(sim::modeName(loadScene(file).engine), "force");
}

TEST(SceneFileTest, BadScenesAreRefusedWithFileLineKeyAndProblem) {
  // Case: a typo in a key, at its line.
  EXPECT_THAT(errorOf(kMinimal + "durration: 2\n"),
              HasSubstr("wtc_scene_file_test.yaml.tmp:6:1: unknown key 'durration'"));
  // Case: an unknown engine, a wrong type, a non-finite or impossible number.
  EXPECT_THAT(errorOf(kMinimal + "engine: physx\n"),
              HasSubstr(":6:9: engine: unknown engine 'physx' (expected bullet, ode"));
  EXPECT_THAT(errorOf(kMinimal + "dt: fast\n"), HasSubstr(":6:5: dt: 'fast' is not a number"));
  EXPECT_THAT(errorOf(kMinimal + "mode: rigid\n"),
              HasSubstr(":6:7: mode: 'rigid' (expected force, constraint, implicit, engine_cylinder or engine_sphere)"));
  EXPECT_THAT(errorOf(kMinimal + "dt: .nan\n"), HasSubstr("dt: '.nan' is not a finite number"));
  EXPECT_THAT(errorOf(kMinimal + "dt: -0.001\n"), HasSubstr("dt: must be > 0 s"));
  EXPECT_THAT(errorOf(kMinimal + "solver_residual: 0\n"), HasSubstr("solver_residual: must be > 0 (m/s)^2"));
  // Case: a missing terrain file, named.
  EXPECT_THAT(errorOf("name: t\nduration: 1\nterrain: nowhere.yaml\nvehicle: ../vehicles/six_wheel_robot.yaml\n"
                      "controller: {type: none}\n"),
              HasSubstr("nowhere.yaml: file not found"));
  // Case: a controller naming a body without a drive, or an unknown type.
  EXPECT_THAT(
      errorOf("name: t\nduration: 1\nterrain: ../terrains/flat.yaml\nvehicle: ../vehicles/six_wheel_robot.yaml\n"
              "controller: {type: schedule, schedules: [{drives: [middle], mode: velocity, points: [[0, 1]]}]}\n"),
      HasSubstr("'middle' is not a driven body of vehicle 'six_wheel_robot'"));
  EXPECT_THAT(errorOf(kMinimal + "effects: [slip_traction, warp_drive]\n"), HasSubstr("warp_drive"));
  // Case: a parameter used but never defined.
  EXPECT_THAT(errorOf(kMinimal + "dt: $step\n"), HasSubstr("'$step' names no parameter of the scene"));
  // Case: overrides that cannot apply, named as overrides.
  EXPECT_THAT(errorOf(kMinimal, {parseOverride("duration.x=1")}),
              HasSubstr("--set duration.x=1: 'duration' in 'duration.x' is below a value"));
  EXPECT_THAT(errorOf(kMinimal, {parseOverride("nonsense=1")}), HasSubstr("unknown key 'nonsense'"));
  EXPECT_THROW(parseOverride("no_equals_sign"), InvalidInputError);
  // Case: a case that does not exist, named with the known ones.
  EXPECT_THAT(errorOf(kMinimal + "parameters: {pick: 4}\ncases: {pick: {1: {a: 1}, 2: {a: 2}}}\n"),
              HasSubstr("cases.pick: no case 4 (known: 1, 2)"));
  // Case: a path controller with a wheel that is not driven, or C behind the axle.
  const std::string towed =
      "name: t\nduration: 1\nterrain: ../terrains/flat.yaml\nvehicle: ../vehicles/towed_system.yaml\n";
  EXPECT_THAT(errorOf(towed + "controller: {type: path, body: tug, left_drive: nose_wheel, right_drive: "
                              "tug_right_wheel, x: [0], y: [0]}\n"),
              HasSubstr("left_drive 'nose_wheel' is not a driven wheel"));
  EXPECT_THAT(errorOf(towed + "controller: {type: path, body: tug, left_drive: tug_left_wheel, right_drive: "
                              "tug_right_wheel, lead: -1, x: [0], y: [0]}\n"),
              HasSubstr("lead -1 m must be > 0"));
  EXPECT_THAT(errorOf(towed + "controller: {type: path, body: tug, left_drive: tug_left_wheel, right_drive: "
                              "tug_right_wheel, x: [0, 1, 2, 3, 4, 5, 6], y: [0]}\n"),
              HasSubstr("expected 1 to 6 polynomial coefficients"));
}

// An override's value has no line in the scene: its errors were placed at
// 1:1; they name the override.
TEST(SceneFileTest, ErrorsInAnOverridesValueNameTheOverride) {
  EXPECT_THAT(errorOf(kMinimal, {parseOverride("dt=-1")}),
              ::testing::AllOf(HasSubstr("wtc_scene_file_test.yaml.tmp: --set dt=-1: dt: must be > 0 s"),
                             ::testing::Not(HasSubstr(":1:1:"))));
  EXPECT_THAT(
      errorOf(kMinimal, {parseOverride("vehicle={file: ../vehicles/six_wheel_robot.yaml, translation: [0, x, 0]}")}),
      HasSubstr(": --set vehicle={file: ../vehicles/six_wheel_robot.yaml, translation: [0, x, 0]}: vehicle: "
                "translation[1]: 'x' is not a number"));
  // A path the document did not have: the override made every part of it, and an error there is the
  // override's (issue 57 row 11: "vehicle: missing key 'axis'" named no --set).
  EXPECT_THAT(errorOf("name: t\nduration: 1\nterrain: ../terrains/flat.yaml\n"
                      "vehicle: {file: ../vehicles/six_wheel_robot.yaml}\ncontroller: {type: none}\n",
                      {parseOverride("vehicle.rotation.degrees=90")}),
              HasSubstr("wtc_scene_file_test.yaml.tmp: --set vehicle.rotation.degrees=90: vehicle: missing key 'axis'"));
  // A value the override did not touch keeps its line.
  EXPECT_THAT(errorOf(kMinimal + "dt: -1\n", {parseOverride("duration=2")}),
              HasSubstr("wtc_scene_file_test.yaml.tmp:6:5: dt: must be > 0 s"));
}

// A file the scene names that is missing or broken: the scene's line, column
// and key, then the file's own message.
TEST(SceneFileTest, AReferencedFileThatFailsIsNamedAtTheScenesLineAndKey) {
  const std::string missing_terrain =
      "name: t\nduration: 1\nterrain: nowhere.yaml\nvehicle: ../vehicles/six_wheel_robot.yaml\n"
      "controller: {type: none}\n";
  EXPECT_THAT(errorOf(missing_terrain), HasSubstr("wtc_scene_file_test.yaml.tmp:3:10: terrain: " +
                                                  (scratchFolder() / "nowhere.yaml").string() + ": file not found"));
  const std::string missing_vehicle =
      "name: t\nduration: 1\nterrain: ../terrains/flat.yaml\nvehicle: {file: ghost.yaml, translation: [0, 0, 0]}\n"
      "controller: {type: none}\n";
  EXPECT_THAT(errorOf(missing_vehicle), HasSubstr("wtc_scene_file_test.yaml.tmp:4:17: vehicle.file: " +
                                                  (scratchFolder() / "ghost.yaml").string() + ": file not found"));
  EXPECT_THAT(errorOf(kMinimal, {parseOverride("vehicle=ghost.yaml")}),
              HasSubstr("wtc_scene_file_test.yaml.tmp: --set vehicle=ghost.yaml: vehicle: " +
                        (scratchFolder() / "ghost.yaml").string() + ": file not found"));
}

// Degenerate triangles a mesh skipped reach the scene's warnings (and so
// the run's summary); a mesh of nothing else is an error.
TEST(SceneFileTest, SkippedDegenerateTrianglesAreSceneWarnings) {
  const fs::path mesh = scratchFile("wtc_scene_file_test_mesh.obj.tmp");
  // Two ground triangles and one whose vertices are collinear.
  std::ofstream(mesh) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 1 3 4\nf 1 2 5\n";
  const std::string scene =
      "name: t\nduration: 1\nvehicle: ../vehicles/six_wheel_robot.yaml\ncontroller: {type: none}\n"
      "terrain:\n  materials: {a: {}}\n  pieces:\n    - {type: mesh, file: " +
      mesh.string() + ", translation: [0, 0, 0], thickness: 0.1}\n";
  const fs::path path = scratchFile("wtc_scene_file_test.yaml.tmp");
  std::ofstream(path) << scene;
  const sim::Scene s = loadScene(path);
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_THAT(s.warnings[0], HasSubstr(path.string() + ":8:7: pieces[0] (mesh): " + mesh.string() +
                                       ": 1 of 3 triangles are degenerate (zero area), skipped"));
  std::ofstream(mesh) << "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n";
  EXPECT_THAT(errorOf(scene), HasSubstr(mesh.string() + ": all 1 of its 1 triangles are degenerate"));
  fs::remove_all(scratchFolder());
}

// Issue 35: a scene's name becomes part of the output directory's name
// (runs/<name>_<engine>_<mode>); one that could reach outside it is
// refused where it stands, in the file or in --set.
TEST(SceneFileTest, NamesThatCouldLeaveTheOutputDirectoryAreRefused) {
  const std::string rest =
      "duration: 1\nterrain: ../terrains/flat.yaml\nvehicle: ../vehicles/six_wheel_robot.yaml\n"
      "controller: {type: none}\n";
  // Case: a path separator, a parent directory, a hidden name, a control character, in the file.
  EXPECT_THAT(errorOf("name: a/b\n" + rest), HasSubstr(":1:7: name: 'a/b' has the character '/'"));
  EXPECT_THAT(errorOf("name: ../../escape\n" + rest), HasSubstr(":1:7: name: '../../escape' starts with '.'"));
  EXPECT_THAT(errorOf("name: .hidden\n" + rest), HasSubstr("name: '.hidden' starts with '.'"));
  EXPECT_THAT(errorOf("name: \"a\\tb\"\n" + rest), HasSubstr("name: 'a\\x09b' has the character '\\x09'"));
  EXPECT_THAT(errorOf("name: \"\"\n" + rest), HasSubstr("name: '' is empty"));
  EXPECT_THAT(errorOf("name: " + std::string(129, 'a') + "\n" + rest), HasSubstr("is 129 characters long"));
  // Case: the same through an override, named as the name.
  EXPECT_THAT(errorOf("name: t\n" + rest, {parseOverride("name=../../escape")}),
              HasSubstr("name: '../../escape' starts with '.'"));
  // Case: what the format allows loads.
  EXPECT_EQ(errorOf("name: robot-2.v3_final\n" + rest), "no error");
}

// Issue 35: a run simulates its whole duration in whole steps; a step
// longer than the duration (0 steps, reported as a success) or a duration
// between two whole numbers of steps (once rounded: dt 10 ran 30 s of 25)
// is refused, with both numbers and the nearest whole durations.
TEST(SceneFileTest, AStepThatDoesNotDivideTheDurationIsRefused) {
  EXPECT_THAT(errorOf(kMinimal + "dt: 10\n"),
              HasSubstr(":6:5: dt: duration 1 s, dt 10 s: the step is longer than the duration"));
  EXPECT_THAT(errorOf(kMinimal, {{"duration", "0.25"}, {"dt", "0.1"}}),
              HasSubstr("duration: duration 0.25 s, dt 0.1 s: the duration is 2.5 steps, not a whole number of them; "
                        "the nearest durations that are: 0.2 s and 0.3 s"));
  EXPECT_THAT(errorOf(kMinimal, {{"duration", "1e300"}, {"dt", "1e-300"}}), HasSubstr("more than 2^53"));
  // Case: a whole number of steps to roundoff loads (0.3 / 0.1 is 2.9999999999999996 in doubles).
  EXPECT_EQ(errorOf(kMinimal, {{"duration", "0.3"}, {"dt", "0.1"}}), "no error");
}

}  // namespace scene_file_test
}  // namespace wtc::sim

namespace wtc::sim {
namespace scene_file_test {

// A controller that holds every drive off, as a layer above would register
// one (the Python bindings' `type: python`).
class Idle final : public vehicle::Controller {
 public:
  void update(const vehicle::VehicleState&, std::span<vehicle::DriveCommand>) override {}
};

// The scene reader finds a controller type in one table: an unknown type
// is refused naming the known ones, and a type added at run time is read
// by its own reader (its keys checked there, its refusals placed in the
// scene) without a change to the reader.
TEST(SceneFileTest, ControllerTypesComeFromOneTableThatALayerAboveMayExtend) {
  const std::string rest = "name: t\nduration: 1\nterrain: ../terrains/flat.yaml\n"
                           "vehicle: ../vehicles/six_wheel_robot.yaml\n";
  EXPECT_THAT(errorOf(rest + "controller: {type: idle}\n"),
              HasSubstr(":5:20: controller.type: 'idle' (expected none, schedule, path or climb)"));
  vehicle::addControllerType(
      {.name = "idle", .read = [](const io::detail::YamlReader& in, const YAML::Node& node,
                                  const vehicle::VehicleDescription&) -> vehicle::ControllerFactory {
         in.checkKeys(node, {"type", "gain"});
         if (in.number(node, "gain", 1.0) <= 0.0) in.fail(node["gain"], "controller.gain: must be > 0");
         return [] { return std::unique_ptr<vehicle::Controller>(std::make_unique<Idle>()); };
       }});
  EXPECT_EQ(errorOf(rest + "controller: {type: idle}\n"), "no error");
  EXPECT_THAT(errorOf(rest + "controller: {type: idle, gain: -1}\n"), HasSubstr(":5:32: controller.gain: must be > 0"));
  EXPECT_THAT(errorOf(rest + "controller: {type: idle, speed: 1}\n"), HasSubstr("unknown key 'speed'"));
  EXPECT_THAT(vehicle::controllerTypeNames(), HasSubstr("climb or idle"));
  EXPECT_THROW(vehicle::addControllerType({.name = "path", .read = vehicle::readPathController}), InvalidInputError);
}


// The mobility rigs' keys (docs/mobility-bounds.md, "Test rigs"): a
// vehicle's starting velocity, a drawbar, a schedule that switches its
// drives off; read as given, each misuse refused at its line and key.
TEST(SceneFileTest, TheRigsKeysAreReadAndTheirMisusesRefusedWhereTheyStand) {
  const std::string head = "name: t\nduration: 1\nterrain: ../terrains/flat.yaml\ncontroller: {type: none}\n";
  const std::string robot = "vehicle: {file: ../vehicles/six_wheel_robot.yaml, velocity: [1, 0, 0]}\n";
  const fs::path path = scratchFile("wtc_scene_file_rigs_test.yaml.tmp");
  std::ofstream(path)
      << head << robot
      << "drawbar: {body: middle, point: [-0.3, 0, 0.19], speed: 0.3, stiffness: 2.0e4, damping: 3000}\n";
  const Scene scene = loadScene(path);
  fs::remove(path);
  EXPECT_EQ(scene.start_velocity_V, Eigen::Vector3d(1, 0, 0));
  ASSERT_TRUE(scene.drawbar.has_value());
  EXPECT_EQ(scene.drawbar->body, scene.vehicle.find("middle"));
  EXPECT_EQ(scene.drawbar->point_V, Eigen::Vector3d(-0.3, 0, 0.19));
  EXPECT_FALSE(scene.drawbar->force_N.has_value());
  EXPECT_EQ(scene.drawbar->speed_mps, 0.3);
  EXPECT_EQ(scene.drawbar->stiffness_Npm, 2.0e4);
  EXPECT_EQ(scene.drawbar->damping_Nspm, 3000.0);
  EXPECT_EQ(errorOf(head + robot + "drawbar: {body: middle, point: [0, 0, 0], force: 100}\n"), "no error");

  EXPECT_THAT(errorOf(head + "vehicle: {file: ../vehicles/six_wheel_robot.yaml, velocity: [2000, 0, 0]}\n"),
              HasSubstr(":5:61: vehicle.velocity: 2000 m/s is beyond the speed at which a run stops as diverged"));
  EXPECT_THAT(errorOf(head + "vehicle: {file: ../vehicles/six_wheel_robot.yaml, velocity: [1, 0]}\n"),
              HasSubstr(":5:61: vehicle.velocity: expected a list of 3 numbers"));
  EXPECT_THAT(errorOf(head + robot + "drawbar: {body: mast, point: [0, 0, 0], force: 1}\n"),
              HasSubstr(":6:17: drawbar.body: 'mast' is not a body of vehicle 'six_wheel_robot'"));
  EXPECT_THAT(errorOf(head + robot + "drawbar: {body: middle, point: [0, 0, 0], force: 1, speed: 1}\n"),
              HasSubstr(":6:60: drawbar: give either force (a constant pull, N) or speed, stiffness and damping"));
  EXPECT_THAT(errorOf(head + robot + "drawbar: {body: middle, point: [0, 0, 0]}\n"),
              HasSubstr(":6:10: drawbar: give force (a constant pull, N) or speed, stiffness and damping"));
  EXPECT_THAT(errorOf(head + robot + "drawbar: {body: middle, point: [0, 0, 0], force: 1, stiffness: 5}\n"),
              HasSubstr(":6:64: drawbar.stiffness: only for an anchor (speed), not with force"));
  EXPECT_THAT(errorOf(head + robot + "drawbar: {body: middle, point: [0, 0, 0], speed: 1, stiffness: 0}\n"),
              HasSubstr(":6:64: drawbar: stiffness = 0 must be finite and > 0 (N/m) for a moving anchor"));
  EXPECT_THAT(errorOf(head + robot + "drawbar: {body: middle, point: [0, 0, 0], speed: 1}\n"),
              HasSubstr("missing key 'stiffness'"));
  EXPECT_THAT(
      errorOf(head + robot + "drawbar: {body: middle, point: [0, 0, 0], speed: 1, stiffness: 1, damping: -1}\n"),
      HasSubstr("drawbar: damping = -1 must be finite and >= 0 (N s/m)"));
  EXPECT_THAT(errorOf(head + robot + "drawbar: {body: middle, point: [1e300, 0, 0], force: 1}\n"),
              HasSubstr(":6:32: drawbar: point must be finite and within 1e+06 m"));
  EXPECT_THAT(errorOf(head + robot + "drawbar: {body: middle, point: [0, 0, 0], force: 1, pull: 2}\n"),
              HasSubstr("unknown key 'pull'"));

  const std::string schedule =
      "name: t\nduration: 1\nterrain: ../terrains/flat.yaml\n"
      "vehicle: ../vehicles/six_wheel_robot.yaml\ncontroller: {type: schedule, schedules: "
      "[{drives: [front_left_wheel], mode: ";
  EXPECT_EQ(errorOf(schedule + "velocity, points: [[0, 1]], off_after: 0.5}]}\n"), "no error");
  EXPECT_THAT(errorOf(schedule + "velocity, points: [[0, 1]], off_after: -1}]}\n"),
              HasSubstr("controller.schedules[0]: off_after: -1 must be >= 0 (s)"));
  EXPECT_THAT(errorOf(schedule + "off, points: [[0, 1]], off_after: 1}]}\n"),
              HasSubstr("controller.schedules[0]: off_after: the schedule's mode is off already"));
}

}  // namespace scene_file_test
}  // namespace wtc::sim
