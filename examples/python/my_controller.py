#!/usr/bin/env python3
"""A towed-path controller written in Python: the tug tracks the S-curve of scenes/towed_path.yaml.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/my_controller.py [--duration 12] [--quick] [--out DIR]

PathController below is vehicle::PathController (src/vehicle/controllers/path/path_controller.cpp), line by line,
in plain floats in the C++ order of operations, so that its run is the C++ one's (tests/python/
test_controllers.py holds them to 1e-9). The law (vehicles spec, section 2): a point C, `lead` ahead of the drive
axle's midpoint A, follows the path Xc*(t) = sum a_i t^i, Yc*(t) = sum b_i t^i with
    u = dC*/dt + diag(Kx, Ky) (C* - C),   V = u . (cos psi, sin psi),   Omega = u . (-sin psi, cos psi) / lead,
and the drive wheels are told omega_R,L = (V +- Omega d) / R.

A scene names it as   controller: {type: python, module: my_controller, class: PathController,
                                   settings: {body: tug, left_drive: ..., x: [...], y: [...], ...}}
(the keys of `type: path`), or a script hands an instance to wtc.run(scene, controller=...).
"""
import argparse
import math
import pathlib
import sys


class PathController:
    """update(t, sensors) -> {wheel: rate (rad/s)}; summary() and failure() as the C++ controller's."""

    def __init__(self, body, left_drive, right_drive, x, y, lead=1.0, gains=(1.0, 1.0), max_tracking_error=0.5,
                 end_time=math.inf):
        if not (lead > 0.0 and math.isfinite(lead)):
            raise ValueError(f"lead {lead} m must be > 0 (C ahead of the axle)")
        if not 1 <= len(x) <= 6 or not 1 <= len(y) <= 6:
            raise ValueError("x, y: expected 1 to 6 polynomial coefficients (degree <= 5)")
        self.body, self.left_drive, self.right_drive = body, left_drive, right_drive
        self.a = [float(c) for c in x] + [0.0] * (6 - len(x))
        self.b = [float(c) for c in y] + [0.0] * (6 - len(y))
        self.lead, self.gain_x, self.gain_y = float(lead), float(gains[0]), float(gains[1])
        self.max_tracking_error, self.end_time = float(max_tracking_error), float(end_time)
        self.geometry = None  # read from the vehicle's description at the first call
        self.max_error = self.sum_sq_error = self.last_error = self.lost_time = 0.0
        self.samples = 0
        self.lost = False

    def _read_geometry(self, sensors):
        """A (the axle's midpoint) in the tug's frame, the half track d and the wheel radius R."""
        tug, left, right = (sensors.description(n) for n in (self.body, self.left_drive, self.right_drive))
        if left["radius"] != right["radius"]:
            raise ValueError("the drive wheels have different radii")
        m = tug["pose"]
        # to_body = pose^-1: R^T, -(R^T t); then to_body * p, each row summed in Eigen's order.
        rt = [[m[j][i] for j in range(3)] for i in range(3)]
        t = [-((rt[i][0] * m[0][3] + rt[i][1] * m[1][3]) + rt[i][2] * m[2][3]) for i in range(3)]

        def to_body(p):
            return [((rt[i][0] * p[0] + rt[i][1] * p[1]) + rt[i][2] * p[2]) + t[i] for i in range(3)]

        pl = to_body([left["pose"][i][3] for i in range(3)])
        pr = to_body([right["pose"][i][3] for i in range(3)])
        mid = [0.5 * (pl[i] + pr[i]) for i in range(3)]
        d = [pl[i] - pr[i] for i in range(3)]
        half_track = 0.5 * math.sqrt((d[0] * d[0] + d[1] * d[1]) + d[2] * d[2])
        self.geometry = (tug["index"], mid, half_track, left["radius"])

    def desired(self, t):
        cx = cy = 0.0
        power = 1.0
        for i in range(6):
            cx += power * self.a[i]
            cy += power * self.b[i]
            power *= t
        return cx, cy

    def desired_velocity(self, t):
        vx = vy = 0.0
        power = 1.0
        for i in range(1, 6):
            vx += i * power * self.a[i]
            vy += i * power * self.b[i]
            power *= t
        return vx, vy

    def update(self, time, sensors):
        if self.geometry is None:
            self._read_geometry(sensors)
        body, mid, half_track, radius = self.geometry
        r = sensors.rotation[body].tolist()
        p = sensors.position[body].tolist()
        psi = math.atan2(r[1][0], r[0][0])
        hx, hy = math.cos(psi), math.sin(psi)
        lx, ly = -math.sin(psi), math.cos(psi)
        t = min(time, self.end_time)
        # C = pose * (A + lead x), its x and y.
        v = (mid[0] + self.lead, mid[1] + 0.0, mid[2] + 0.0)
        c = [((r[i][0] * v[0] + r[i][1] * v[1]) + r[i][2] * v[2]) + p[i] for i in range(2)]
        dx, dy = self.desired(t)
        ex, ey = dx - c[0], dy - c[1]
        if self.lost or time >= self.end_time:
            ux = uy = 0.0
        else:
            vx, vy = self.desired_velocity(t)
            ux, uy = vx + self.gain_x * ex, vy + self.gain_y * ey
        speed = ux * hx + uy * hy
        yaw_rate = (ux * lx + uy * ly) / self.lead
        commands = {self.right_drive: (speed + yaw_rate * half_track) / radius,
                    self.left_drive: (speed - yaw_rate * half_track) / radius}
        self.last_error = math.sqrt(ex * ex + ey * ey)
        self.max_error = max(self.max_error, self.last_error)
        self.sum_sq_error += self.last_error * self.last_error
        self.samples += 1
        if not self.lost and self.last_error > self.max_tracking_error:
            self.lost, self.lost_time = True, time
        return commands

    def summary(self):
        return {"max_tracking_error_m": self.max_error,
                "rms_tracking_error_m": math.sqrt(self.sum_sq_error / self.samples) if self.samples else 0.0,
                "final_tracking_error_m": self.last_error}

    def failure(self):
        if not self.lost:
            return None
        return (f"path lost at t = {self.lost_time:.9g} s: the tracking error passed "
                f"{self.max_tracking_error:.9g} m")


# The S-curve of scenes/towed_path.yaml (its case path: 2), as that scene's `controller` gives it.
S_CURVE = dict(body="tug", left_drive="tug_left_wheel", right_drive="tug_right_wheel", lead=1.0, x=[-9, 0.8],
               y=[0, 0, 0.0416667, -0.00231481], gains=[1.0, 1.0], max_tracking_error=0.5, end_time=12)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--duration", type=float, default=12.0, help="simulated time (s)")
    parser.add_argument("--quick", action="store_true", help="1 s, no figures, no replay (the test suite's)")
    parser.add_argument("--out", help="output directory (default runs/towed_path_bullet_force[_N])")
    args = parser.parse_args()
    import wtc  # here, so that a scene can import this module without the package's side effects first

    root = pathlib.Path(__file__).resolve().parents[2]
    duration = 1.0 if args.quick else args.duration
    scene = wtc.load_scene(root / "scenes/towed_path.yaml", duration=duration)
    summary = wtc.run(scene, out=args.out, controller=PathController(**S_CURVE), progress=not args.quick,
                      plots=not args.quick, replay=not args.quick)
    fields = summary  # summary.json's keys: the controller's figures among them
    print(f"towed_path with a Python path controller: {'success' if summary['success'] else 'FAILED'} "
          f"after {summary['sim_time']:.3f} s; tracking error max {fields['max_tracking_error_m'] * 1e3:.1f} mm, "
          f"rms {fields['rms_tracking_error_m'] * 1e3:.1f} mm; outputs in {summary['out']}")
    return 0 if summary["success"] or args.quick else 1


if __name__ == "__main__":
    sys.exit(main())
