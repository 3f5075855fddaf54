// What each one-run event measures, read from the run's series
// (wtc/mobility/mobility_run.hpp, measureRun).
#include <cmath>

#include "study/series.hpp"
#include "wtc/base/constants.hpp"
#include "wtc/base/error.hpp"
#include "wtc/mobility/mobility_run.hpp"

namespace wtc::mobility {
namespace {

using study::detail::readSeries;
using study::detail::Series;

// Below this fraction of its start speed a coasting vehicle has nearly stopped: the fit ends (dimensionless).
constexpr double kCoastFitSpeedFraction = 0.05;

std::string firstBody(const EventVehicle& v) { return v.description.bodies.front().name; }

// The least-squares slope of y against t.
double slope(const std::vector<double>& t, const std::vector<double>& y) {
  const double n = static_cast<double>(t.size());
  double st = 0, sy = 0, stt = 0, sty = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    st += t[i];
    sy += y[i];
    stt += t[i] * t[i];
    sty += t[i] * y[i];
  }
  return (n * sty - st * sy) / (n * stt - st * st);
}

}  // namespace

double measureRun(const EventVehicle& v, const std::string& event, const MobilitySettings& s,
                  const std::filesystem::path& dir, double* torque) {
  if (event == "drawbar") {
    // DP/W: the rig's mean pull after it settled; sum |T| / (r_f W) from the driven wheels' efforts.
    const Series pull = readSeries(dir / "drawbar.csv");
    const std::size_t c = pull.column("pull_N");
    double sum = 0.0;
    int n = 0;
    for (const auto& row : pull.rows) {
      if (row[0] < s.drawbar.settle_s) continue;
      sum += row[c];
      ++n;
    }
    if (n == 0) throw InvalidInputError(pull.file.string() + ": no rows after the settling time");
    if (torque != nullptr) {
      const Series drives = readSeries(dir / "drives.csv");
      double t_sum = 0.0;
      int rows = 0;
      for (const auto& row : drives.rows) {
        if (row[0] < s.drawbar.settle_s) continue;
        for (const WheelInfo& w : v.statics.wheels) {
          if (w.driven) t_sum += std::abs(row[drives.column(w.name + ".effort")]) / w.radius_m;
        }
        ++rows;
      }
      *torque = rows > 0 ? t_sum / rows / v.statics.weight() : 0.0;
    }
    return sum / n / v.statics.weight();
  }
  const Series bodies = readSeries(dir / "bodies.csv");
  const std::string b = firstBody(v);
  if (event == "coast") {
    const std::size_t vx = bodies.column(b + ".vx_mps"), vy = bodies.column(b + ".vy_mps");
    std::vector<double> t, speed;
    for (const auto& row : bodies.rows) {
      const double sp = std::hypot(row[vx], row[vy]);
      if (row[0] < s.coast.fit_from_s) continue;
      if (sp < kCoastFitSpeedFraction * s.coast.speed_mps) break;
      t.push_back(row[0]);
      speed.push_back(sp);
    }
    if (t.size() < 3) throw InvalidInputError(bodies.file.string() + ": too few rows to fit the coast-down");
    return -slope(t, speed);
  }
  if (event == "braking") {
    const std::size_t x = bodies.column(b + ".x_m"), y = bodies.column(b + ".y_m");
    const auto& first = bodies.rows.front();
    const auto& last = bodies.rows.back();
    return std::hypot(last[x] - first[x], last[y] - first[y]);
  }
  if (event == "turn") {
    // The mean yaw rate over the second half of the run (the ramp is over by then).
    const std::size_t wz = bodies.column(b + ".wz_radps");
    const double from = 0.5 * bodies.rows.back()[0];
    double sum = 0.0;
    int n = 0;
    for (const auto& row : bodies.rows) {
      if (row[0] < from) continue;
      sum += row[wz];
      ++n;
    }
    return std::abs(sum / n);
  }
  throw InvalidInputError("wtc::mobility::measureRun: event '" + event + "' is a search, not measured from one run");
}

}  // namespace wtc::mobility
