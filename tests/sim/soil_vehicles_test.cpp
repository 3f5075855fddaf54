// Whole vehicles on soil that remembers (issue 55, item 3; docs/soft-soil.md,
// vehicles on soil): the shipped soil scenes, whole, in Bullet and ODE, force
// and implicit modes. Each meets its success criteria and leaves ruts; the
// engines and modes agree; and, checked against Newton's second law rather
// than our own earlier output, the ground carries the vehicle: over the
// second half of a run the mean of the wheels' ground forces, plus the
// weight, equals the vehicle's change of momentum over that time (on the
// slope this includes holding W sin 15 deg down it). Nothing but the wheels
// touches the ground in these scenes, so the balance is exact up to how a
// mode reports its forces.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "wtc/base/constants.hpp"
#include "wtc/sim/engine_table.hpp"
#include "wtc/sim/run.hpp"
#include "wtc/sim/run_observer.hpp"
#include "wtc/sim/scene_file.hpp"
#include "wtc/sim/scene_run.hpp"

namespace wtc::testing {
namespace {

namespace fs = std::filesystem;
const fs::path kScenes = fs::path(WTC_SOURCE_DIR) / "scenes";
constexpr double kBalanceOfWeight = 0.01;    // Newton's balance to 1 % of the weight
constexpr double kAgreementRelative = 0.01;  // engines and modes: distance and turn to 1 %

// From `from` on: the mean of the wheels' ground forces (world) and the
// vehicle's momentum at the first and last step observed.
class GroundBalance final : public sim::RunObserver {
 public:
  GroundBalance(const vehicle::VehicleDescription& v, double from) : vehicle_(v), from_(from) {}
  void observe(const sim::Run& run) override {
    if (run.time() < from_) return;
    Eigen::Vector3d momentum = Eigen::Vector3d::Zero();
    for (std::size_t b = 0; b < vehicle_.bodies.size(); ++b) {
      momentum += vehicle_.bodies[b].mass * run.state().bodies[b].linear_velocity;
    }
    if (n_ == 0) {
      first_ = momentum;
      t0_ = run.time();
    }
    last_ = momentum;
    t1_ = run.time();
    for (const int w : vehicle_.wheels()) force_ += run.wheelForces(w).force;
    ++n_;
  }
  // (mean ground force + M g) - dp/dt, over M g.
  Eigen::Vector3d imbalance() const {
    const double weight = vehicle_.totalMass() * kGravityMps2;
    const Eigen::Vector3d ground = force_ / n_;
    const Eigen::Vector3d rate = (last_ - first_) / (t1_ - t0_);
    return (ground - Eigen::Vector3d(0, 0, weight) - rate) / weight;
  }
  Eigen::Vector3d meanForce() const { return force_ / n_; }

 private:
  const vehicle::VehicleDescription& vehicle_;
  double from_;
  Eigen::Vector3d force_ = Eigen::Vector3d::Zero(), first_, last_;
  double t0_ = 0.0, t1_ = 0.0;
  int n_ = 0;
};

TEST(SoilVehiclesTest, EachSoilSceneSucceedsAndTheGroundCarriesTheVehicleInBothEnginesAndModes) {
  double worst_balance = 0.0, worst_agreement = 0.0;
  for (const char* name : {"rover_sand", "rover_sand_slope", "rover_sand_turn", "robot_sand"}) {
    double first_distance = -1.0, first_turn = 0.0;
    for (const char* engine : {"bullet", "ode"}) {
      for (const char* mode : {"force", "implicit"}) {
        const std::string label = std::string(name) + " in " + engine + "/" + mode;
        const sim::Scene s = sim::loadScene(kScenes / (std::string(name) + ".yaml"),
                                            std::vector<sim::Override>{{"engine", engine}, {"mode", mode}});
        const auto world = sim::makeEngine(s.engine, *s.terrain, s.vehicle, s.placement);
        GroundBalance balance(s.vehicle, 0.5 * s.duration_seconds);
        sim::RunOptions options;
        options.observer = &balance;
        const sim::RunSummary r = sim::runScene(s, *world, options);
        EXPECT_TRUE(r.success) << label;
        EXPECT_GT(r.fields.at("soil_memory_touched_nodes"), 0.0) << label << ": no ruts";
        const Eigen::Vector3d off = balance.imbalance();
        EXPECT_LT(off.norm(), kBalanceOfWeight) << label << ": " << off.transpose();
        const double distance = r.fields.at("distance_m"), turn = r.fields.at("yaw_change_deg");
        if (first_distance < 0.0) {
          first_distance = distance;
          first_turn = turn;
        }
        EXPECT_NEAR(distance, first_distance, kAgreementRelative * first_distance) << label;
        EXPECT_NEAR(turn, first_turn, kAgreementRelative * std::max(std::abs(first_turn), 1.0)) << label;
        worst_balance = std::max(worst_balance, off.norm());
        worst_agreement = std::max(worst_agreement, std::abs(distance / first_distance - 1.0));
        const Eigen::Vector3d f = balance.meanForce();
        std::printf("%s: %.4f m, turned %.2f deg, ground force (%.1f, %.1f, %.1f) N, off %.2g of W\n", label.c_str(),
                    distance, turn, f.x(), f.y(), f.z(), off.norm());
      }
    }
    RecordProperty(std::string(name) + "_distance_m", std::to_string(first_distance));
    RecordProperty(std::string(name) + "_turn_deg", std::to_string(first_turn));
  }
  RecordProperty("worst_balance_over_weight", std::to_string(worst_balance));
  RecordProperty("worst_distance_relative", std::to_string(worst_agreement));
}

}  // namespace
}  // namespace wtc::testing
