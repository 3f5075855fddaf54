#include "recorder.hpp"

#include <algorithm>
#include <charconv>

#include "general_9_format.hpp"
#include "wtc/base/error.hpp"

namespace wtc::sim {

namespace {
// When held rows go out: a write a row cost more than a large step
// (docs/accuracy-study.md, "What a run's output costs").
constexpr std::size_t kFlushBytes = 1 << 16;
constexpr std::chrono::milliseconds kFlushInterval{250};
// Enough for any integer.
constexpr int kNumberChars = 32;

void endRow(detail::CsvFile& out) { out.endRow(); }
}  // namespace

void detail::CsvFile::open(const std::filesystem::path& path) {
  file_.reset(std::fopen(path.c_str(), "w"));
  if (!file_) throw InvalidInputError("wtc::sim::Recorder: cannot write " + path.string());
  last_write_ = std::chrono::steady_clock::now();
}

detail::CsvFile& detail::CsvFile::operator<<(double value) {
  char text[kGeneral9Chars];
  row_.append(text, formatGeneral9(value, text));
  return *this;
}

detail::CsvFile& detail::CsvFile::operator<<(std::size_t value) {
  char text[kNumberChars];
  row_.append(text, std::to_chars(text, text + kNumberChars, value).ptr);
  return *this;
}

detail::CsvFile& detail::CsvFile::operator<<(int value) {
  char text[kNumberChars];
  row_.append(text, std::to_chars(text, text + kNumberChars, value).ptr);
  return *this;
}

void detail::CsvFile::endRow() {
  row_.push_back('\n');
  if (row_.size() >= kFlushBytes || std::chrono::steady_clock::now() - last_write_ >= kFlushInterval) flush();
}

void detail::CsvFile::flush() {
  if (!file_) return;
  std::fwrite(row_.data(), 1, row_.size(), file_.get());
  std::fflush(file_.get());  // whole rows on disk: a killed run keeps them
  row_.clear();
  last_write_ = std::chrono::steady_clock::now();
}

Recorder::Recorder(const std::filesystem::path& dir, const Run& run)
    : actuated_(run.engine().vehicle().actuated()), wheel_bodies_(run.engine().vehicle().wheels()) {
  const vehicle::VehicleDescription& v = run.engine().vehicle();
  bodies_.open(dir / "bodies.csv");
  drives_.open(dir / "drives.csv");
  wheels_.open(dir / "wheels.csv");
  bodies_ << "t_s";
  for (const vehicle::Body& b : v.bodies) {
    for (const char* c : {"x_m", "y_m", "z_m", "qw", "qx", "qy", "qz", "vx_mps", "vy_mps", "vz_mps", "wx_radps",
                          "wy_radps", "wz_radps"}) {
      bodies_ << ',' << b.name << '.' << c;
    }
  }
  endRow(bodies_);
  drives_ << "t_s";
  for (const int i : actuated_) {
    for (const char* c : {"position", "rate", "command", "target_rate", "effort", "saturated"}) {
      drives_ << ',' << v.bodies[i].name << '.' << c;
    }
  }
  endRow(drives_);
  wheels_ << "t_s";
  for (const int i : wheel_bodies_) {
    for (const char* c : {"contacts", "fx_N", "fy_N", "fz_N", "max_slip"})
      wheels_ << ',' << v.bodies[i].name << '.' << c;
  }
  endRow(wheels_);
  if (v.hitch) {
    hitch_.open(dir / "hitch.csv");
    hitch_ << "t_s,dx_m,dy_m,dz_m,px_N,py_N,pz_N";
    endRow(hitch_);
  }
  if (run.hasDrawbar()) {
    drawbar_.open(dir / "drawbar.csv");
    drawbar_ << "t_s,pull_N,extension_m,point_speed_mps";
    endRow(drawbar_);
  }
}

void Recorder::record(const Run& run) {
  const vehicle::VehicleState& s = run.state();
  bodies_ << s.time;
  const vehicle::VehicleDescription& v = run.engine().vehicle();
  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    const vehicle::BodyKinematics& k = s.bodies[b];
    const Eigen::Quaterniond q(vehicle::ownFrame(v.bodies[b], k.pose).linear());
    const Eigen::Vector3d& p = k.pose.translation();
    bodies_ << ',' << p.x() << ',' << p.y() << ',' << p.z() << ',' << q.w() << ',' << q.x() << ',' << q.y() << ','
            << q.z();
    for (const Eigen::Vector3d* v : {&k.linear_velocity, &k.angular_velocity}) {
      bodies_ << ',' << v->x() << ',' << v->y() << ',' << v->z();
    }
  }
  endRow(bodies_);
  drives_ << s.time;
  for (const int i : actuated_) {
    const vehicle::DriveReport& d = run.drives()[i];
    drives_ << ',' << s.joint_position[i] << ',' << s.joint_rate[i] << ',' << run.commands()[i].value << ','
            << run.targets()[i].rate << ',' << d.last_effort << ',' << (d.last_saturated ? 1 : 0);
  }
  endRow(drives_);
  wheels_ << s.time;
  for (const int i : wheel_bodies_) {
    const WheelForces& f = run.wheelForces(i);
    double slip = 0.0;
    for (const ContactForce& c : f.contacts) slip = std::max(slip, c.slip_ratio);
    wheels_ << ',' << f.contacts.size() << ',' << f.force.x() << ',' << f.force.y() << ',' << f.force.z() << ','
            << slip;
  }
  endRow(wheels_);
  if (run.hitch() && hitch_.isOpen()) {
    const vehicle::HitchForce& h = *run.hitch();
    hitch_ << s.time << ',' << h.deflection.x() << ',' << h.deflection.y() << ',' << h.deflection.z() << ','
           << h.force_local.x() << ',' << h.force_local.y() << ',' << h.force_local.z();
    endRow(hitch_);
  }
  if (drawbar_.isOpen()) {
    const DrawbarForce& d = *run.drawbar();
    drawbar_ << s.time << ',' << d.pull_N << ',' << d.extension_m << ',' << d.point_speed_mps;
    endRow(drawbar_);
  }
}

void Recorder::flush() {
  for (detail::CsvFile* f : {&bodies_, &drives_, &wheels_, &hitch_, &drawbar_}) f->flush();
}

}  // namespace wtc::sim
