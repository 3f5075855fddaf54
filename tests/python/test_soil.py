"""Soft soil from Python (docs/soft-soil.md): the shipped soils and the wheel's steady state on them, against the
equations of Wong & Reece and Ishigami et al. 2007 integrated here with NumPy (a trapezoid on 20,001 angles, not the
library's Gauss-Legendre), and bad soils refused by name."""
import math

import numpy as np
import pytest

import wtc

RADIUS, WIDTH, LOAD = 0.09, 0.11, 64.68   # Ishigami's wheel and load (m, m, N)


def forces(soil, z, slip):
    """W, DP and T at sinkage z and driving slip, theta_2 = 0."""
    t1 = math.acos(1 - z / RADIUS)
    tm = (soil["a0"] + soil["a1"] * slip) * t1
    th = np.linspace(0.0, t1, 20001)
    k = (soil["k_c"] / WIDTH + soil["k_phi"]) * RADIUS ** soil["n"]
    rear = np.cos(t1 - th / tm * (t1 - tm)) if tm > 0 else np.cos(th)
    c = np.where(th >= tm, np.cos(th), rear)
    sigma = k * np.maximum(c - math.cos(t1), 0.0) ** soil["n"]
    j = RADIUS * ((t1 - th) - (1 - slip) * (math.sin(t1) - np.sin(th)))
    tau = (soil["cohesion"] + sigma * math.tan(math.radians(soil["friction_angle_deg"]))) * \
        (1 - np.exp(-j / soil["shear_modulus_x"]))
    w = RADIUS * WIDTH * np.trapz(sigma * np.cos(th) + tau * np.sin(th), th)
    dp = RADIUS * WIDTH * np.trapz(tau * np.cos(th) - sigma * np.sin(th), th)
    t = RADIUS ** 2 * WIDTH * np.trapz(tau, th)
    return w, dp, t


def test_the_shipped_soils_are_listed_with_their_fields():
    soils = wtc.soils()
    assert sorted(soils) == ["dry_sand", "lete_sand", "lunar_regolith", "sandy_loam", "toyoura_sand"]
    assert soils["toyoura_sand"]["friction_angle_deg"] == 37.2
    assert soils["lete_sand"]["n"] == 0.79


@pytest.mark.parametrize("name", ["toyoura_sand", "lete_sand"])
@pytest.mark.parametrize("slip", [0.1, 0.5, 0.9])
def test_the_steady_state_is_the_equations_integrated_independently(name, slip):
    soil = wtc.soils()[name]
    got = wtc.wheel_on_soil(name, RADIUS, WIDTH, LOAD, slip)
    lo, hi = 0.0, RADIUS
    for _ in range(50):
        mid = 0.5 * (lo + hi)
        if forces(soil, mid, slip)[0] < LOAD:
            lo = mid
        else:
            hi = mid
    z = 0.5 * (lo + hi)
    w, dp, t = forces(soil, z, slip)
    assert got["normal"] == pytest.approx(LOAD, rel=1e-9)
    assert got["sinkage"] == pytest.approx(z, rel=0.02)
    assert got["drawbar_pull"] == pytest.approx(dp, abs=0.02 * LOAD)
    assert got["torque"] == pytest.approx(t, rel=0.02)


def test_a_soil_given_by_its_fields_over_a_base():
    firmer = wtc.wheel_on_soil({"base": "toyoura_sand", "k_phi": 2 * 8.14e5}, RADIUS, WIDTH, LOAD, 0.2)
    plain = wtc.wheel_on_soil("toyoura_sand", RADIUS, WIDTH, LOAD, 0.2)
    assert firmer["sinkage"] < plain["sinkage"]


def test_bad_soils_and_loads_are_refused_by_name():
    with pytest.raises(wtc.InvalidInputError, match="unknown soil 'quicksand'"):
        wtc.wheel_on_soil("quicksand", RADIUS, WIDTH, LOAD, 0.2)
    with pytest.raises(wtc.InvalidInputError, match="unknown soil field 'kphi'"):
        wtc.wheel_on_soil({"base": "dry_sand", "kphi": 1.0}, RADIUS, WIDTH, LOAD, 0.2)
    with pytest.raises(wtc.InvalidInputError, match="friction_angle_deg = 95"):
        wtc.wheel_on_soil({"base": "dry_sand", "friction_angle_deg": 95}, RADIUS, WIDTH, LOAD, 0.2)
    with pytest.raises(wtc.InvalidInputError, match="before the axle sinks in"):
        wtc.wheel_on_soil("lunar_regolith", RADIUS, WIDTH, 5e4, 0.2)
    with pytest.raises(wtc.InvalidInputError, match="slip"):
        wtc.wheel_on_soil("lunar_regolith", RADIUS, WIDTH, LOAD, 1.5)
