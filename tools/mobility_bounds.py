#!/usr/bin/env python3
"""The bounds mechanics gives for the mobility events of issue 39, from a vehicle file and a material.

usage: tools/mobility_bounds.py [VEHICLE.yaml ...] [--material NAME=mu_max,s1,s2,f_r ...]

Without arguments: vehicles/six_wheel_robot.yaml and vehicles/towed_system.yaml on the
materials of terrains/*.yaml and the towed incline's three friction cases. Prints, per
vehicle, what docs/mobility-bounds.md derives: the vehicle's numbers (mass, centre of mass,
wheels, drives), the static wheel loads (tyre springs, the hitch's vertical spring), and per
material the grade, side-slope, drawbar-pull, coast-down, braking, step and turning bounds.

Everything here is quasi-static mechanics on the vehicle's description with every joint
at zero (sections level and retracted), rigid bodies, the tyres as vertical springs at
the wheel centres' x, y symmetry about the vehicle's x-z plane (checked), and the project's
slip law mu(s) = mu_max (1 - exp(-s/s1)) (1 + s2 exp(-s/s1)) with its rolling-resistance
moment M_r = f_r R_z r_0 (docs/tyre-model.md). Standard library and PyYAML only.
"""
import argparse
import glob
import math
import os
import sys

import yaml

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
G = 9.81  # m/s^2, wtc::kGravityMps2
R0_RATIO = 0.97  # r_0 / r_f, TyreParameters::rolling_radius_ratio's default
DEFAULT_STIFFNESS = 1e5  # N/m, TyreParameters::radial_stiffness's default
SLIP_LEVELS = [0.05, 0.10, 0.20, 0.30, 0.50, 0.70, 0.90]  # conventional driving slip i (dimensionless)


# ---------------------------------------------------------------- the slip law


def mu(m, s):
    """mu(s) = mu_max (1 - e^(-s/s1)) (1 + s2 e^(-s/s1)) (spec section 4)."""
    q = math.exp(-s / m["s1"])
    return m["mu_max"] * (1.0 - q) * (1.0 + m["s2"] * q)


def mu_peak(m):
    """The largest mu(s): mu_max for s2 <= 1, mu_max (1 + s2)^2 / (4 s2) otherwise."""
    s2 = m["s2"]
    return m["mu_max"] if s2 <= 1.0 else m["mu_max"] * (1.0 + s2) ** 2 / (4.0 * s2)


def s2_for_peak(mu_max, peak):
    """s2 > 1 with mu_max (1 + s2)^2 / (4 s2) = peak (what a terrain's mu_peak sets)."""
    k = peak / mu_max  # (1 + s2)^2 = 4 k s2  ->  s2^2 + (2 - 4k) s2 + 1 = 0, the larger root
    b = 2.0 - 4.0 * k
    return (-b + math.sqrt(b * b - 4.0)) / 2.0


# ---------------------------------------------------------------- the vehicle


def load_vehicle(path):
    with open(path) as f:
        doc = yaml.safe_load(f)
    defaults = doc.get("wheel_defaults", {})
    bodies = []
    for b in doc["bodies"]:
        body = {"name": b["name"], "mass": float(b.get("mass", defaults.get("mass", 0.0))), "t": [float(v) for v in b.get("translation", [0, 0, 0])],
                "parent": b.get("parent"), "joint": dict(defaults.get("joint", {})) if "wheel" in b else {},
                "wheel": None}
        body["joint"].update(b.get("joint", {}))
        if "wheel" in b:
            w = dict(defaults.get("wheel", {}))
            w.update(b["wheel"] or {})
            tyre = dict(defaults.get("wheel", {}).get("tyre", {}))
            tyre.update((b["wheel"] or {}).get("tyre", {}))
            body["wheel"] = {"r": float(w["radius"]), "width": float(w["width"]),
                             "c": float(tyre.get("radial_stiffness", DEFAULT_STIFFNESS)),
                             "r0_ratio": float(tyre.get("rolling_radius_ratio", R0_RATIO))}
        bodies.append(body)
    by_name = {b["name"]: b for b in bodies}
    for b in bodies:  # the root each body hangs from, and whether a wheel castors
        root = b
        while root["parent"]:
            root = by_name[root["parent"]]
        b["root"] = root["name"]
        if b["wheel"]:
            joint = b["joint"]
            parent_joint = by_name[b["parent"]]["joint"] if b["parent"] else {}
            swivel = parent_joint.get("type") == "revolute" and [abs(v) for v in parent_joint.get("axis", [])] == [0, 0, 1]
            b["wheel"]["caster"] = joint.get("type") == "ball" or swivel
            drive = joint.get("drive")
            b["wheel"]["drive"] = (float(drive["max_effort"]), float(drive["max_speed"])) if drive else None
            # The tread as a solid disc (vehicle_file.cpp): I = m r^2 / 2 about the axle.
            b["wheel"]["I"] = 0.5 * b["mass"] * b["wheel"]["r"] ** 2
    hitch = None
    if "hitch" in doc:
        h = doc["hitch"]
        a, bb = by_name[h["body_a"]], by_name[h["body_b"]]
        p = [a["t"][i] + h["point_a"][i] for i in range(3)]
        q = [bb["t"][i] + h["point_b"][i] for i in range(3)]
        hitch = {"a": a["root"], "b": bb["root"], "p": p, "q": q, "k": [float(v) for v in h["stiffness"]]}
    return {"name": doc["name"], "bodies": bodies, "hitch": hitch, "path": path}


def roots(v):
    names = []
    for b in v["bodies"]:
        if b["root"] not in names:
            names.append(b["root"])
    return names


def mass_and_com(bodies):
    m = sum(b["mass"] for b in bodies)
    return m, [sum(b["mass"] * b["t"][i] for b in bodies) / m for i in range(3)]


def wheels(v, root=None):
    return [b for b in v["bodies"] if b["wheel"] and (root is None or b["root"] == root)]


# ---------------------------------------------------------------- planar statics


class NoEquilibrium(Exception):
    """The supports left cannot hold the vehicle (it tips)."""


def solve(a, b):
    """Gaussian elimination with partial pivoting (small dense systems); NoEquilibrium if singular."""
    n = len(b)
    m = [row[:] + [b[i]] for i, row in enumerate(a)]
    for col in range(n):
        pivot = max(range(col, n), key=lambda r: abs(m[r][col]))
        if abs(m[pivot][col]) < 1e-9:
            raise NoEquilibrium()
        m[col], m[pivot] = m[pivot], m[col]
        for r in range(n):
            if r != col and m[r][col] != 0.0:
                f = m[r][col] / m[col][col]
                for c in range(col, n + 1):
                    m[r][c] -= f * m[col][c]
    return [m[i][n] / m[i][i] for i in range(n)]


def loads(v, slope=0.0, accel=0.0, free_coefficient=0.0):
    """loads_with_lift() without the names of the lifted wheels."""
    n, hx, _ = loads_with_lift(v, slope, accel, free_coefficient)
    return n, hx


def loads_with_lift(v, slope=0.0, accel=0.0, free_coefficient=0.0):
    """solve_loads(), again without the wheels whose spring would pull (they lift off, N = 0)."""
    lifted = set()
    while True:
        n, hx = solve_loads(v, slope, accel, free_coefficient, lifted)
        pulling = [k for k, x in n.items() if x < 0.0 and k not in lifted]
        if not pulling:
            return n, hx, sorted(lifted)
        lifted.add(min(pulling, key=lambda k: n[k]))


def solve_loads(v, slope, accel, free_coefficient, lifted):
    """Normal loads (N) of every wheel, in the slope's frame, quasi-static.

    The vehicle faces +x up a grade `slope` (rad) and accelerates at `accel` (m/s^2, along +x);
    each root body is rigid with its joints at zero and moves by a heave z and a pitch beta
    (w(x) = z + beta x); each wheel is a vertical spring c at its centre's x; the hitch is
    stiff along x (its force H_x unknown) and a spring k_z vertically. Free wheels (no drive)
    carry a longitudinal force -free_coefficient N at the ground (rolling resistance for a
    rolling vehicle, 0 parked); the driven wheels take whatever the x-balance of their root
    needs. Longitudinal ground forces act at z = 0 and give no moment about the ground line;
    gravity, the inertial force and the hitch's H_x act at their heights.
    Returns ({wheel name: N}, H_x on body b (N) or None).
    """
    names = roots(v)
    index = {n: i for i, n in enumerate(names)}
    hitch = v["hitch"]
    unknowns = 2 * len(names) + (1 if hitch else 0)
    rows, rhs = [], []
    gx, gz = -G * math.sin(slope), -G * math.cos(slope)
    for n in names:
        i = index[n]
        m, c = mass_and_com([b for b in v["bodies"] if b["root"] == n])
        fx, fz = m * (gx - accel), m * gz  # gravity and d'Alembert force at the COM
        vert = [0.0] * unknowns
        mom = [0.0] * unknowns
        for w in wheels(v, n):  # N = -c w(x): force c (-z - beta x) up at x
            k, x = (0.0 if w["name"] in lifted else w["wheel"]["c"]), w["t"][0]
            vert[2 * i] -= k
            vert[2 * i + 1] -= k * x
            mom[2 * i] -= k * x  # moment x F_z
            mom[2 * i + 1] -= k * x * x
        # sum F_z + fz = 0 ; sum (x F_z - z F_x) + (x_c fz - z_c fx) = 0
        b_vert, b_mom = -fz, -(c[0] * fz - c[2] * fx)
        if hitch and n in (hitch["a"], hitch["b"]):
            xh, zh, kz = hitch["p"][0], hitch["p"][2], hitch["k"][2]
            ia, ib = index[hitch["a"]], index[hitch["b"]]
            sign = 1.0 if n == hitch["b"] else -1.0  # +P on b, -P on a; P_z = kz (w_a - w_b)
            for j, coef in ((2 * ia, kz), (2 * ia + 1, kz * xh), (2 * ib, -kz), (2 * ib + 1, -kz * xh)):
                vert[j] += sign * coef
                mom[j] += sign * coef * xh
            mom[-1] += -zh * sign  # -z_h (sign H_x)
        rows += [vert, mom]
        rhs += [b_vert, b_mom]
    if hitch:  # the towed root's x-balance: sum of its ground forces + H_x + m (gx - a) = 0
        n = hitch["b"]
        i = index[n]
        m, _ = mass_and_com([b for b in v["bodies"] if b["root"] == n])
        row = [0.0] * unknowns
        for w in wheels(v, n):
            if w["wheel"]["drive"]:
                sys.exit("mobility_bounds.py: a driven wheel on the towed body is not handled")
            k, x = (0.0 if w["name"] in lifted else w["wheel"]["c"]), w["t"][0]
            row[2 * i] += free_coefficient * k  # -coef N = coef c w
            row[2 * i + 1] += free_coefficient * k * x
        row[-1] = 1.0
        rows.append(row)
        rhs.append(-m * (gx - accel))
    sol = solve(rows, rhs)
    out = {}
    for w in wheels(v):
        i = index[w["root"]]
        c = 0.0 if w["name"] in lifted else w["wheel"]["c"]
        out[w["name"]] = -c * (sol[2 * i] + sol[2 * i + 1] * w["t"][0])
    return out, (sol[-1] if hitch else None)


def split(v, n):
    driven = sum(n[w["name"]] for w in wheels(v) if w["wheel"]["drive"])
    free = sum(n[w["name"]] for w in wheels(v) if not w["wheel"]["drive"])
    return driven, free


# ---------------------------------------------------------------- the events


def fmt(x, digits=4):
    return f"{x:.{digits}g}"


def deg(x):
    return f"{math.degrees(x):.2f} deg"


def bisect(f, lo, hi, iterations=80):
    """The root of f in [lo, hi] (f(lo) and f(hi) of opposite signs)."""
    flo = f(lo)
    for _ in range(iterations):
        mid = 0.5 * (lo + hi)
        if (f(mid) > 0) == (flo > 0):
            lo, flo = mid, f(mid)
        else:
            hi = mid
    return 0.5 * (lo + hi)


def describe(v):
    m, c = mass_and_com(v["bodies"])
    print(f"## {v['name']} ({os.path.relpath(v['path'], ROOT)})\n")
    print(f"- mass m = {fmt(m)} kg, weight W = m g = {fmt(m * G)} N; centre of mass (x, y, z) = "
          f"({fmt(c[0])}, {fmt(c[1])}, {fmt(c[2])}) m, joints at zero")
    for n in roots(v):
        mr, cr = mass_and_com([b for b in v["bodies"] if b["root"] == n])
        if len(roots(v)) > 1:
            print(f"- root body `{n}` with what hangs from it: {fmt(mr)} kg, centre of mass "
                  f"({fmt(cr[0])}, {fmt(cr[2])}) m (x, z)")
    for w in wheels(v):
        ww = w["wheel"]
        kind = "driven (" + fmt(ww["drive"][0]) + " N m, " + fmt(ww["drive"][1]) + " rad/s)" if ww["drive"] else (
            "caster (free in yaw)" if ww["caster"] else "free")
        print(f"- wheel `{w['name']}` at x = {fmt(w['t'][0])}, y = {fmt(w['t'][1])} m: r_f = {fmt(ww['r'])} m, "
              f"c = {fmt(ww['c'])} N/m, I = m r^2 / 2 = {fmt(ww['I'])} kg m^2, {kind}")
    if v["hitch"]:
        h = v["hitch"]
        print(f"- hitch between `{h['a']}` and `{h['b']}` at x = {fmt(h['p'][0])}, z = {fmt(h['p'][2])} m, "
              f"vertical stiffness {fmt(h['k'][2])} N/m")
    asym = max(abs(sum(b["mass"] * b["t"][1] for b in v["bodies"])), 0.0)
    if asym > 1e-9:
        print(f"- WARNING: not symmetric about x-z (sum m y = {asym}); the planar loads below are approximate")
    n, hx = loads(v)
    print("\nStatic wheel loads on level ground (N):", ", ".join(f"{k} {fmt(x)}" for k, x in n.items()))
    d, f = split(v, n)
    print(f"Driven wheels carry {fmt(d)} N ({fmt(100 * d / (m * G), 3)} % of W), free wheels {fmt(f)} N.\n")


def events(v, material_name, mat):
    m, c = mass_and_com(v["bodies"])
    weight = m * G
    ws = wheels(v)
    driven = [w for w in ws if w["wheel"]["drive"]]
    lateral = [w for w in ws if not w["wheel"]["caster"]]
    f_r, peak, mu1 = mat["f_r"], mu_peak(mat), mu(mat, 1.0)
    print(f"### {v['name']} on {material_name}: mu_max {mat['mu_max']}, s1 {mat['s1']}, s2 {fmt(mat['s2'])}, "
          f"f_r {f_r}\n")
    print(f"- peak of mu(s) {fmt(peak)}, mu(1) = {fmt(mu1, 6)} (the locked wheel's), "
          f"mu_max {mat['mu_max']} (a spinning wheel's, s -> infinity)")
    n0, _ = loads(v)
    d0, _ = split(v, n0)
    all_driven = len(driven) == len(ws)

    # Grade climbing from rest (traction) and by the drives' torque.
    if all_driven:
        grade_traction = math.atan(peak)
        grade_spin = math.atan(mat["mu_max"])
        note = "all wheels driven: tan(theta) = mu (the loads' distribution does not matter)"
    else:
        coef = f_r * R0_RATIO

        def need(theta, mu_avail):
            try:
                n, hx = loads(v, slope=theta, free_coefficient=coef)
            except NoEquilibrium:
                return -1.0
            dn, fn = split(v, n)
            return mu_avail * dn - (weight * math.sin(theta) + coef * fn)

        grade_traction = bisect(lambda t: need(t, peak), 0.0, math.radians(60))
        grade_spin = bisect(lambda t: need(t, mat["mu_max"]), 0.0, math.radians(60))
        n, hx, lifted = loads_with_lift(v, slope=grade_traction, free_coefficient=coef)
        dn, fn = split(v, n)
        note = (f"driven wheels only; at that grade the planar statics give N_driven = {fmt(dn)} N, N_free = "
                f"{fmt(fn)} N, hitch {fmt(hx)} N" + (f", lifted: {', '.join(lifted)}" if lifted else "") +
                f"; {fmt(peak)} x {fmt(dn)} = W sin + {fmt(coef)} N_free = {fmt(weight * math.sin(grade_traction))} + "
                f"{fmt(coef * fn)}")
    torque = sum(w["wheel"]["drive"][0] for w in driven)
    r_d = driven[0]["wheel"]["r"]
    # sum T = r_d (W sin + f_r (r_0/r_f) W cos) for equal radii (docs/mobility-bounds.md)
    k = torque / (r_d * weight)
    a = f_r * R0_RATIO
    grade_torque = math.asin(min(1.0, k / math.hypot(1.0, a))) - math.atan(a) if k < math.hypot(1.0, a) else math.pi / 2
    print(f"- grade from rest, traction at the peak: {deg(grade_traction)}; with the wheels spinning (mu_max): "
          f"{deg(grade_spin)} ({note})")
    print(f"- grade by the drives' torque: sum T_max = {fmt(torque)} N m, sum T_max / (r W) = {fmt(k)}: "
          f"sin + {fmt(a)} cos <= {fmt(k)}: {deg(grade_torque) if k < math.hypot(1, a) else 'any grade'}")

    # Parked on the grade with the driven wheels held: the tread sticks up to the peak.
    if all_driven:
        parked = math.atan(peak)
    else:
        def hold(theta):
            try:
                n, hx = loads(v, slope=theta)
            except NoEquilibrium:
                return -1.0
            dn, _ = split(v, n)
            return peak * dn - weight * math.sin(theta)
        parked = bisect(hold, 0.0, math.radians(60))
        n, hx, lifted = loads_with_lift(v, slope=parked)
        dn, _ = split(v, n)
        print(f"- parked, driven wheels held: {fmt(peak)} N_driven = W sin: N_driven = {fmt(dn)} N at {deg(parked)}"
              + (f" ({', '.join(lifted)} lifted)" if lifted else "") + " (free wheels hold nothing at rest)")
    if all_driven:
        print(f"- parked, every wheel held: tan = peak: {deg(parked)}")

    # Pitch-over on a grade: the centre of mass past the lowest axle.
    xs = sorted(w["t"][0] for w in ws)
    if len(roots(v)) == 1:
        back = c[0] - xs[0]
        print(f"- tip-over on a grade (uphill facing, about the rear axle): atan({fmt(back)} / {fmt(c[2])}) = "
              f"{deg(math.atan2(back, c[2]))}")

    # Side slope: sliding and tipping.
    slide_share = sum(n0[w["name"]] for w in lateral) / weight
    slide = math.atan(peak * slide_share)
    print(f"- side slope, sliding, all together: the wheels that resist sideways ({len(lateral)} of {len(ws)}) carry "
          f"{fmt(100 * slide_share, 4)} % of W: tan(phi) = {fmt(peak)} x {fmt(slide_share, 4)}: {deg(slide)}")
    if v["hitch"]:
        side_slope_with_hitch(v, peak, n0)
    for n in roots(v):
        body = [b for b in v["bodies"] if b["root"] == n]
        mr, cr = mass_and_com(body)
        support = [(w["t"][0], abs(w["t"][1])) for w in wheels(v, n)]
        if v["hitch"] and n == v["hitch"]["b"]:
            support.append((v["hitch"]["p"][0], 0.0))
        # The support polygon's half-width at the COM's x (symmetric in y): the largest y on
        # its outline at x_c, from the segments between support points.
        half = 0.0
        for (x1, y1) in support:
            for (x2, y2) in support:
                if x1 == x2:
                    if abs(x1 - cr[0]) < 1e-12:
                        half = max(half, y1, y2)
                    continue
                t = (cr[0] - x1) / (x2 - x1)
                if 0.0 <= t <= 1.0:
                    half = max(half, y1 + t * (y2 - y1))
        print(f"- side slope, tipping of `{n}`: half-width of its support at the centre of mass {fmt(half)} m, "
              f"height {fmt(cr[2])} m: atan = {deg(math.atan2(half, cr[2]))}")

    # Drawbar pull against slip.
    if all_driven:
        print("- drawbar pull, every wheel at one slip (WTC's law: rolling resistance is a moment the drives "
              "take): DP/W = mu(s); torque coefficient sum T / (r_f W) = mu(s) + f_r r_0 / r_f")
    else:
        print(f"- drawbar pull of the whole vehicle, driven wheels at one slip: DP/W = mu(s) x {fmt(d0 / weight, 4)} "
              f"- f_r (r_0/r_f) x {fmt(1 - d0 / weight, 4)} (level loads)")
    header = "| driving slip i | s = i/(1-i) | mu(s) | DP/W |"
    print("\n" + header + "\n|---|---|---|---|")
    for i in SLIP_LEVELS + [1.0]:
        s = math.inf if i >= 1.0 else i / (1.0 - i)
        mus = mat["mu_max"] if math.isinf(s) else mu(mat, s)
        dp = mus if all_driven else mus * d0 / weight - f_r * R0_RATIO * (1 - d0 / weight)
        print(f"| {100 * i:.0f} % | {'inf' if math.isinf(s) else fmt(s, 4)} | {fmt(mus, 4)} | {fmt(dp, 4)} |")
    print()

    # Coast-down from 1 m/s, drives off.
    inertia = sum(w["wheel"]["I"] / w["wheel"]["r"] ** 2 for w in ws)
    resist = sum(f_r * w["wheel"]["r0_ratio"] * n0[w["name"]] for w in ws)
    coast = resist / (m + inertia)
    print(f"- coast-down, drives off: a = sum f_r R_z r_0 / r_f / (m + sum I / r_f^2) = {fmt(resist)} / "
          f"({fmt(m)} + {fmt(inertia)}) = {fmt(coast)} m/s^2; from 1 m/s: {fmt(1 / (2 * coast))} m in "
          f"{fmt(1 / coast)} s")

    # Locked-wheel stop from 2 m/s.
    if all_driven:
        decel = G * mu1
        print(f"- braking, every wheel locked: a = g mu(1) = {fmt(decel)} m/s^2; from 2 m/s: "
              f"v^2 / (2 g mu(1)) = {fmt(4 / (2 * decel))} m")
    else:
        free_inertia = sum(w["wheel"]["I"] / w["wheel"]["r"] ** 2 for w in ws if not w["wheel"]["drive"])
        coef = f_r * R0_RATIO
        a = G * mu1 * d0 / weight
        for _ in range(50):  # the loads shift with the deceleration: iterate
            n, _ = loads(v, accel=-a, free_coefficient=coef)
            dn, fn = split(v, n)
            a = (mu1 * dn + coef * fn) / (m + free_inertia)
        print(f"- braking, driven wheels locked, the rest rolling: a = (mu(1) N_driven + f_r (r_0/r_f) N_free) / "
              f"(m + sum I_free / r^2) = ({fmt(mu1, 5)} x {fmt(dn)} + {fmt(coef)} x {fmt(fn)}) / "
              f"({fmt(m)} + {fmt(free_inertia)}) = {fmt(a)} m/s^2 (loads with the deceleration's transfer); "
              f"from 2 m/s: {fmt(4 / (2 * a))} m")

    # Step climbing with a plain drive forward (rigid vehicle, sharp edge, Coulomb at the peak).
    step(v, mat)
    if all_driven and len(set(abs(w["t"][1]) for w in ws)) == 1:
        turn(v, mat)
    print()


def side_slope_with_hitch(v, peak, n0):
    """Parked across a slope: the hitch's lateral force from the towed body's yaw balance.

    The towed body resists sideways only at one axle (its casters swivel): its yaw balance about
    that axle gives the hitch's share of its weight's slope component, H = G_b (x_cb - x_m) /
    (x_h - x_m). The tug carries its own G_a plus H at its resisting axle, and H's yaw moment
    about that axle as a longitudinal couple of its (held) wheels. First order: the normal loads
    are the level ones times cos(phi), no lateral load transfer.
    """
    h = v["hitch"]
    bodies = {n: [b for b in v["bodies"] if b["root"] == n] for n in (h["a"], h["b"])}
    lateral = {n: [w for w in wheels(v, n) if not w["wheel"]["caster"]] for n in bodies}
    xs = {n: sorted(set(round(w["t"][0], 6) for w in lateral[n])) for n in bodies}
    if any(len(x) != 1 for x in xs.values()):
        print("  - (the bodies resist sideways at more than one axle each: indeterminate, the aggregate bound only)")
        return
    ma, ca = mass_and_com(bodies[h["a"]])
    mb, cb = mass_and_com(bodies[h["b"]])
    xh, xm, xd = h["p"][0], xs[h["b"]][0], xs[h["a"]][0]
    share = (cb[0] - xm) / (xh - xm)  # H / G_b
    tan_main = peak * sum(n0[w["name"]] for w in lateral[h["b"]]) / ((1 - share) * mb * G)
    wheels_a = lateral[h["a"]]
    half = abs(wheels_a[0]["t"][1])
    per_wheel_lateral = (ma + share * mb) / len(wheels_a)  # x g sin(phi)
    couple = share * mb * (xd - xh) / (2 * half)  # per wheel, x g sin(phi)
    need = math.hypot(per_wheel_lateral, couple) * G
    tan_tug = peak * min(n0[w["name"]] for w in wheels_a) / need
    print(f"  - with the hitch: the towed body's yaw about its axle at x = {fmt(xm)} puts H = G_b ({fmt(cb[0])} - "
          f"({fmt(xm)})) / ({fmt(xh)} - ({fmt(xm)})) = {fmt(share, 4)} G_b on the hitch; its own wheels slide at "
          f"tan(phi) = {fmt(peak)} N / ({fmt(1 - share, 4)} m_b g) = {fmt(tan_main, 4)}: {deg(math.atan(tan_main))}")
    print(f"  - the tug's resisting wheels: lateral ({fmt(ma)} + {fmt(share, 4)} x {fmt(mb)}) / {len(wheels_a)} = "
          f"{fmt(per_wheel_lateral)} kg x g sin(phi) each, and a couple {fmt(share * mb * (xd - xh))} kg m x g sin(phi) "
          f"about their axle: +-{fmt(couple)} kg x g sin(phi) along x each; resultant {fmt(need / G)} kg x g sin(phi) "
          f"against mu N = {fmt(peak)} x {fmt(min(n0[w['name']] for w in wheels_a))} N cos(phi): tan(phi) = "
          f"{fmt(tan_tug, 4)}: {deg(math.atan(tan_tug))}; the vehicle slides at "
          f"{deg(math.atan(min(tan_tug, tan_main)))}")


def step_height(r, alpha):
    return r * (1.0 - math.cos(min(alpha, math.pi / 2)))


def step(v, mat):
    """Per axle: tan(alpha - phi) <= P / L for a driven wheel, tan(alpha) <= P / L for a free one."""
    peak = mu_peak(mat)
    phi = math.atan(peak)
    coef = mat["f_r"] * R0_RATIO
    n0, _ = loads(v)
    ws = wheels(v)
    m, _ = mass_and_com(v["bodies"])
    weight = m * G
    axles = {}
    for w in ws:
        axles.setdefault(round(w["t"][0], 6), []).append(w)
    order = sorted(axles, reverse=True)  # the front axle meets the step first
    print("- step, plain drive forward (each axle in turn at the edge, the rest on level ground at their "
          "level loads, driven wheels at the peak of mu, free wheels' rolling resistance):")
    gaps = []
    for x in order:
        axle = axles[x]
        load = sum(n0[w["name"]] for w in axle)
        others = [w for w in ws if w not in axle]
        push = sum(peak * n0[w["name"]] if w["wheel"]["drive"] else -coef * n0[w["name"]] for w in others)
        r = axle[0]["wheel"]["r"]
        driven = axle[0]["wheel"]["drive"] is not None
        alpha = phi + math.atan2(push, load) if driven else math.atan2(max(push, 0.0), load)
        h = step_height(r, alpha)
        gaps.append(2.0 * math.sqrt(h * (2.0 * r - h)))
        print(f"  - axle at x = {fmt(x)} ({', '.join(w['name'] for w in axle)}; {'driven' if driven else 'free'}, "
              f"r = {fmt(r)} m): L = {fmt(load)} N, P = {fmt(push)} N, P/L = {fmt(push / load, 4)}: "
              f"alpha <= {fmt(math.degrees(alpha), 4)} deg, h <= r (1 - cos alpha) = {fmt(h, 4)} m"
              + (" (the whole radius: alpha reaches 90 deg)" if alpha >= math.pi / 2 else ""))
    if len(axles) == 3 and all(w["wheel"]["drive"] for w in ws):
        # A rigid three-axle vehicle lifts its middle axle off as soon as the front rises more
        # than a few tyre deflections: the front climbs pushed by the rear alone, each carrying
        # W/2 (no load transfer), P/L = mu: alpha <= 2 phi.
        r = ws[0]["wheel"]["r"]
        print(f"  - rigid three axles, middle one hanging (front and rear carry W/2 each): P/L = mu, "
              f"alpha <= 2 atan(mu) = {fmt(math.degrees(2 * phi), 4)} deg, h <= {fmt(step_height(r, 2 * phi), 4)} m")
    print(f"- gap, plain drive forward: a wheel over a gap g rests on both edges sqrt(r^2 - g^2/4) above them, "
          f"so the far edge is a step of r - sqrt(r^2 - g^2/4): g <= 2 sqrt(h (2 r - h)) with each axle's h above: "
          f"{', '.join(fmt(g, 3) + ' m' for g in gaps)}; the vehicle's: {fmt(min(gaps), 3)} m (and g < 2 r; the other "
          f"axles must carry the vehicle meanwhile)")
    print(f"  - a lone driven wheel (P = 0): alpha <= atan(mu): h <= r (1 - 1/sqrt(1 + mu^2)) = "
          f"{', '.join(fmt(step_height(w, phi), 4) + ' m (r = ' + fmt(w) + ')' for w in sorted(set(x['wheel']['r'] for x in ws)))}")


def turn(v, mat):
    """Skid steer in place: the moment of fully sliding wheels, and the steady turn at a wheel rate."""
    ws = wheels(v)
    n0, _ = loads(v)
    mu_s = mat["mu_max"]
    slide = sum(mu_s * n0[w["name"]] * math.hypot(w["t"][0], w["t"][1]) for w in ws)
    b = abs(ws[0]["t"][1])
    drive = sum(mu_s * n0[w["name"]] * b for w in ws)
    print(f"- turning in place: sum mu N_i d_i (every wheel sliding around the centre) = {fmt(slide)} N m; "
          f"the largest yaw moment the drives can give, sum mu N_i |y_i| = {fmt(drive)} N m")
    r = ws[0]["wheel"]["r"]
    for rate in (3.0,):
        def moment(omega):  # yaw moment of the ground forces at yaw rate omega (right wheels forward)
            total = 0.0
            for w in ws:
                x, y = w["t"][0], w["t"][1]
                spin = rate if y < 0 else -rate
                vs = (-omega * y - spin * r, omega * x)  # V_P = body velocity at the wheel - omega_w r x
                speed = math.hypot(*vs)
                vo = max(omega * math.hypot(x, y), 1e-3)
                f = -mu(mat, speed / vo) * n0[w["name"]] / speed
                total += x * f * vs[1] - y * f * vs[0]
            return total
        omega = bisect(moment, 1e-6, rate * r / b)
        torques = []
        for w in ws:
            x, y = w["t"][0], w["t"][1]
            spin = rate if y < 0 else -rate
            vs = (-omega * y - spin * r, omega * x)
            speed = math.hypot(*vs)
            fx = -mu(mat, speed / max(omega * math.hypot(x, y), 1e-3)) * n0[w["name"]] * vs[0] / speed
            torques.append(abs(fx * r) + mat["f_r"] * n0[w["name"]] * R0_RATIO * r)
        print(f"  - steady turn at wheel rates +-{fmt(rate)} rad/s (equal loads, quasi-steady): yaw rate "
              f"{fmt(omega, 4)} rad/s = {fmt(math.degrees(omega), 4)} deg/s; drive torques "
              f"{fmt(min(torques), 3)}-{fmt(max(torques), 3)} N m (cap {fmt(ws[0]['wheel']['drive'][0])})")


def materials():
    out = {}
    for path in sorted(glob.glob(os.path.join(ROOT, "terrains", "*.yaml"))):
        with open(path) as f:
            doc = yaml.safe_load(f)
        for name, m in (doc.get("materials") or {}).items():
            out.setdefault(name, {"mu_max": m.get("mu_max", 0.8), "s1": m.get("s1", 0.1), "s2": m.get("s2", 0.0),
                                  "f_r": m.get("rolling_resistance", 0.018)})
    for case, (dyn, stat) in {1: (0.45, 0.75), 2: (0.30, 0.50), 3: (0.21, 0.35)}.items():
        out[f"towed_incline case {case} ({dyn}/{stat})"] = {"mu_max": dyn, "s1": 0.1, "s2": s2_for_peak(dyn, stat),
                                                           "f_r": 0.018}
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("vehicles", nargs="*")
    parser.add_argument("--material", action="append", default=[], help="NAME=mu_max,s1,s2,f_r")
    args = parser.parse_args()
    paths = args.vehicles or [os.path.join(ROOT, "vehicles", f) for f in ("six_wheel_robot.yaml", "towed_system.yaml")]
    mats = materials()
    if args.material:
        mats = {}
    for spec in args.material:
        try:
            name, values = spec.split("=")
            mu_max, s1, s2, f_r = (float(x) for x in values.split(","))
        except ValueError:
            sys.exit(f"mobility_bounds.py: --material '{spec}': expected NAME=mu_max,s1,s2,f_r (four numbers)")
        if not (all(math.isfinite(x) for x in (mu_max, s1, s2, f_r)) and mu_max > 0 and s1 > 0 and s2 >= 0
                and f_r >= 0):
            sys.exit(f"mobility_bounds.py: --material '{spec}': needs mu_max > 0, s1 > 0, s2 >= 0, f_r >= 0")
        mats[name] = {"mu_max": mu_max, "s1": s1, "s2": s2, "f_r": f_r}
    for path in paths:
        if not os.path.isfile(path):
            sys.exit(f"mobility_bounds.py: {path}: no such vehicle file")
    for path in paths:
        v = load_vehicle(path)
        describe(v)
        for name, mat in mats.items():
            events(v, name, mat)


if __name__ == "__main__":
    main()
