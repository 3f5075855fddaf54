// The single-wheel test bed on soft soil (scenes/soil_test_bed.yaml) in
// Bullet and ODE, in every mode (a soil contact is a force in each): each of the cart's wheels, at the slip its
// rate and the carriage's speed impose, settles at the steady state the
// soil's equations give for its own load (wtc::steadyWheelOnSoil, itself
// checked against an independent quadrature in tests/tyre/wheel_soil_test.cpp):
// sinkage, drawbar pull and torque to 2 % (the pull to 2 % of the load:
// it crosses zero). The drive torques tilt the cart, so its rear wheels
// carry more than its front ones; each is compared at the load it carries.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "soil_profiles.hpp"
#include "wtc/sim/engine_table.hpp"
#include "wtc/sim/run.hpp"
#include "wtc/sim/run_observer.hpp"
#include "wtc/sim/scene_file.hpp"
#include "wtc/sim/scene_run.hpp"
#include "wtc/tyre/wheel_soil.hpp"

namespace wtc::testing {
namespace {

namespace fs = std::filesystem;
const fs::path kScene = fs::path(WTC_SOURCE_DIR) / "scenes" / "soil_test_bed.yaml";
constexpr double kSettledS = 4.0;  // the means start here (s): the cart has settled by 2 s

// Means over the settled stretch, per wheel body.
struct WheelMeans {
  double load = 0, pull = 0, torque = 0, sinkage = 0, rate = 0, ahead = 0;  // ahead: of the chassis, along x
};

class Means : public sim::RunObserver {
 public:
  explicit Means(const vehicle::VehicleDescription& vehicle, double from = kSettledS)
      : wheels_(vehicle.wheels()), sums_(wheels_.size()), from_(from) {}
  void observe(const sim::Run& run) override {
    if (run.time() < from_) return;
    ++n_;
    speed_ += run.state().bodies[0].linear_velocity.x();
    for (std::size_t k = 0; k < wheels_.size(); ++k) {
      const int b = wheels_[k];
      const WheelForces& f = run.wheelForces(b);
      const vehicle::BodyKinematics& body = run.state().bodies[static_cast<std::size_t>(b)];
      const Eigen::Vector3d axle = body.pose.linear().col(1);
      sums_[k].load += f.force.z();
      sums_[k].pull += f.force.x();
      sums_[k].torque += -f.axial_moment.dot(axle);
      sums_[k].sinkage += -body.pose.translation().z();  // + r below
      sums_[k].rate += (body.angular_velocity - run.state().bodies[0].angular_velocity).dot(axle);
      sums_[k].ahead += body.pose.translation().x() - run.state().bodies[0].pose.translation().x();
    }
  }
  WheelMeans wheel(std::size_t k, double radius) const {
    WheelMeans m = sums_[k];
    for (double* x : {&m.load, &m.pull, &m.torque, &m.sinkage, &m.rate, &m.ahead}) *x /= n_;
    m.sinkage += radius;
    return m;
  }
  double speed() const { return speed_ / n_; }
  std::size_t wheels() const { return wheels_.size(); }

 private:
  std::vector<int> wheels_;
  std::vector<WheelMeans> sums_;
  double from_;
  double speed_ = 0;
  int n_ = 0;
};

TEST(SoilTestBedTest, EachWheelSettlesAtTheSoilsSteadyStateInBothEngines) {
  const Soil soil = *namedSoil("toyoura_sand");
  double worst_sinkage = 0.0, worst_torque = 0.0, worst_pull = 0.0;  // relative (the pull: to the load)
  for (const char* engine : {"bullet", "ode"}) {
    for (const char* mode : {"force", "constraint", "implicit"}) {
      for (const double slip : {0.2, 0.6}) {
        const double speed = 0.05, radius = 0.09, width = 0.11;
        const double rate = speed / (radius * (1.0 - slip));
        const sim::Scene scene = sim::loadScene(
            kScene,
            std::vector<sim::Override>{{"engine", engine}, {"mode", mode}, {"wheel_rate", std::to_string(rate)}});
        const auto world = sim::makeEngine(scene.engine, *scene.terrain, scene.vehicle, scene.placement);
        Means means(scene.vehicle);
        sim::RunOptions options;
        options.observer = &means;
        const sim::RunSummary summary = sim::runScene(scene, *world, options);
        ASSERT_TRUE(summary.success) << engine << "/" << mode;
        ASSERT_EQ(means.wheels(), 4u);
        for (std::size_t k = 0; k < means.wheels(); ++k) {
          const WheelMeans m = means.wheel(k, radius);
          const double i = 1.0 - means.speed() / (radius * m.rate);  // the slip the run imposed
          EXPECT_NEAR(i, slip, 2e-3) << engine;
          const SoilSteadyState want = steadyWheelOnSoil(soil, radius, width, m.load, i);
          const std::string label = std::string(engine) + "/" + mode + " wheel " + std::to_string(k) + " slip " +
                                    std::to_string(slip) + " load " + std::to_string(m.load);
          EXPECT_NEAR(m.sinkage, want.sinkage, 0.02 * want.sinkage) << label;
          EXPECT_NEAR(m.pull, want.forces.drawbar_pull, 0.02 * m.load) << label;
          EXPECT_NEAR(m.torque, want.forces.torque, 0.02 * want.forces.torque) << label;
          worst_sinkage = std::max(worst_sinkage, std::abs(m.sinkage / want.sinkage - 1));
          worst_torque = std::max(worst_torque, std::abs(m.torque / want.forces.torque - 1));
          worst_pull = std::max(worst_pull, std::abs(m.pull - want.forces.drawbar_pull) / m.load);
        }
      }
    }
  }
  RecordProperty("worst_sinkage_relative", std::to_string(worst_sinkage));
  RecordProperty("worst_torque_relative", std::to_string(worst_torque));
  RecordProperty("worst_pull_over_load", std::to_string(worst_pull));
}

// The test bed on ground that remembers (a soil region under the whole
// slab): the front wheels meet fresh sand and settle at part 1's steady
// state; the rear ones run in the ruts the front ones leave, and settle at
// the steady state on that rut (steadyWheelOnSoil with the uniform memory
// pressedSoil gives for the front wheel's sinkage), deeper than on fresh
// sand. At 0.2 m/s the rear wheels reach the ruts the fronts left once
// settled (the wheelbase is 0.5 m) by 4.5 s.
TEST(SoilTestBedTest, TheRearWheelsRunInTheFrontWheelsRutsAsTheModelPredicts) {
  const Soil soil = *namedSoil("toyoura_sand");
  std::string yaml;
  {
    std::ifstream in(kScene);
    yaml.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const std::string slab = "    - {type: slab, size: [8, 4], thickness: 0.5}\n";
  const std::size_t at = yaml.find(slab);
  ASSERT_NE(at, std::string::npos);
  yaml.insert(at + slab.size(), "  soil_regions: [{corners: [-4, -2, 4, 2], spacing: 0.02}]\n");
  const std::string cart = "../vehicles/";
  yaml.replace(yaml.find(cart), cart.size(), (fs::path(WTC_SOURCE_DIR) / "vehicles").string() + "/");
  const fs::path file = fs::temp_directory_path() / "wtc_soil_test_bed_ruts.yaml";
  { std::ofstream(file) << yaml; }
  const double speed = 0.2, slip = 0.3, radius = 0.09, width = 0.11;
  double worst_front = 0.0, worst_rear = 0.0;
  for (const char* engine : {"bullet", "ode"}) {
    for (const char* mode : {"force", "implicit"}) {
      const sim::Scene scene = sim::loadScene(
          file, std::vector<sim::Override>{{"engine", engine},
                                           {"mode", mode},
                                           {"speed", std::to_string(speed)},
                                           {"wheel_rate", std::to_string(speed / (radius * (1.0 - slip)))},
                                           {"duration", "8"}});
      const auto world = sim::makeEngine(scene.engine, *scene.terrain, scene.vehicle, scene.placement);
      Means means(scene.vehicle, 5.0);
      sim::RunOptions options;
      options.observer = &means;
      const sim::RunSummary summary = sim::runScene(scene, *world, options);
      ASSERT_TRUE(summary.success) << engine << "/" << mode;
      for (std::size_t k = 0; k < means.wheels(); ++k) {
        const WheelMeans m = means.wheel(k, radius);
        const double i = 1.0 - means.speed() / (radius * m.rate);
        const std::string label = std::string(engine) + "/" + mode + " wheel " + std::to_string(k);
        if (m.ahead > 0.0) {  // a front wheel, on fresh sand
          const SoilSteadyState want = steadyWheelOnSoil(soil, radius, width, m.load, i);
          EXPECT_NEAR(m.sinkage, want.sinkage, 0.02 * want.sinkage) << label;
          worst_front = std::max(worst_front, std::abs(m.sinkage / want.sinkage - 1));
          continue;
        }
        // The rut its front wheel left: that wheel's steady sinkage pressed
        // into fresh sand (its load is the other front wheel's, by symmetry).
        double front_load = 0.0;
        for (std::size_t f = 0; f < means.wheels(); ++f) {
          if (means.wheel(f, radius).ahead > 0.0) front_load += 0.5 * means.wheel(f, radius).load;
        }
        const double front_sinkage = steadyWheelOnSoil(soil, radius, width, front_load, i).sinkage;
        const UniformProfile rut(pressedSoil(soil, width, SoilMemory{}, front_sinkage));
        const SoilSteadyState want = steadyWheelOnSoil(soil, radius, width, m.load, i, 0.0, &rut);
        EXPECT_NEAR(m.sinkage, want.sinkage, 0.03 * want.sinkage) << label;
        const double on_fresh = steadyWheelOnSoil(soil, radius, width, m.load, i).sinkage;
        EXPECT_GT(m.sinkage, on_fresh) << label << ": in a rut";
        RecordProperty(std::string(engine) + "_" + mode + "_rear_on_fresh_sand_mm", std::to_string(on_fresh * 1e3));
        worst_rear = std::max(worst_rear, std::abs(m.sinkage / want.sinkage - 1));
        RecordProperty(std::string(engine) + "_" + mode + "_rear_sinkage_mm", std::to_string(m.sinkage * 1e3));
        RecordProperty(std::string(engine) + "_" + mode + "_rear_predicted_mm", std::to_string(want.sinkage * 1e3));
      }
    }
  }
  RecordProperty("worst_front_relative", std::to_string(worst_front));
  RecordProperty("worst_rear_relative", std::to_string(worst_rear));
  fs::remove(file);
}

// Skid steering on sand (Ishigami's side slip: the lateral shear and the
// bulldozing of the wheels' sides): the cart with its left wheels back and
// its right ones forward turns left in place, slower than its wheels would
// turn it without slip (r omega / (track / 2)), its wheels above their axles.
// Its wheelbase (0.5 m) is longer than its track (0.4 m) and each wheel's
// side resists with the full lateral shear and bulldozing while it spins
// (Ishigami's components are independent): it turns slowly (0.051 rad/s of
// the 0.9 its wheels would give without slip; docs/soft-soil.md).
TEST(SoilTestBedTest, ASkidSteeredCartTurnsInPlaceOnSand) {
  const double rate = 2.0, radius = 0.09, half_track = 0.20;  // rad/s, m, m
  const std::string yaml =
      "name: soil_turn\nduration: 4\nterrain:\n  materials: {sand: {soil: toyoura_sand}}\n"
      "  pieces: [{type: slab, size: [6, 6], thickness: 0.5}]\n"
      "vehicle: {file: '" +
      (fs::path(WTC_SOURCE_DIR) / "vehicles" / "soil_test_cart.yaml").string() +
      "'}\n"
      "effects: [full, soft_soil]\ncontroller:\n  type: schedule\n  schedules:\n"
      "    - {drives: [front_left_wheel, rear_left_wheel], mode: velocity, points: [[0, 0], [1, -" +
      std::to_string(rate) +
      "]]}\n"
      "    - {drives: [front_right_wheel, rear_right_wheel], mode: velocity, points: [[0, 0], [1, " +
      std::to_string(rate) + "]]}\n";
  const fs::path file = fs::temp_directory_path() / "wtc_soil_turn.yaml";
  { std::ofstream(file) << yaml; }
  for (const char* engine : {"bullet", "ode"}) {
    const sim::Scene scene = sim::loadScene(file, std::vector<sim::Override>{{"engine", engine}});
    const auto world = sim::makeEngine(scene.engine, *scene.terrain, scene.vehicle, scene.placement);
    struct Yaw : sim::RunObserver {
      double sum = 0, lowest_wheel = 1;
      int n = 0;
      void observe(const sim::Run& run) override {
        for (const auto& body : run.state().bodies) lowest_wheel = std::min(lowest_wheel, body.pose.translation().z());
        if (run.time() < 2.0) return;
        sum += run.state().bodies[0].angular_velocity.z();
        ++n;
      }
    } yaw;
    sim::RunOptions options;
    options.observer = &yaw;
    const sim::RunSummary summary = sim::runScene(scene, *world, options);
    EXPECT_FALSE(summary.nan) << engine;
    const double mean = yaw.sum / yaw.n;
    RecordProperty(std::string(engine) + "_yaw_rate_radps", std::to_string(mean));
    EXPECT_GT(mean, 0.02) << engine;                        // it turns, left (over 1 deg/s)
    EXPECT_LT(mean, radius * rate / half_track) << engine;  // and slips doing it
    EXPECT_GT(yaw.lowest_wheel, 0.0) << engine;             // no wheel sank past its axle
  }
  fs::remove(file);
}

}  // namespace
}  // namespace wtc::testing
