#!/usr/bin/env python3
"""WTC's rigid wheel on soil against Ding et al. 2011's single-wheel tests.

Ding, Gao, Deng, Tao, Iagnemma & Liu (2011), "Experimental study and analysis
on driving wheels' performance for planetary exploration rovers moving in
deformable soil", J. Terramechanics 48(1) 27-45: a smooth rigid wheel,
R 157.35 mm, b 165 mm, W 80 N, on their lunar soil simulant (their Table 2:
n 1.10, k_c 15.6 kPa/m^(n-1), k_phi 2407.4 kPa/m^n, c 0.25 kPa, phi 31.9 deg,
rho 1605 kg/m^3, K 9.7-13.1 mm). The measured DP, T and sinkage are read
from their Fig. 9 (h = 0) by the roverdevkit project
(Autonomous-Mission-Systems-Lab/roverdevkit,
data/validation/single_wheel_experiments.csv, marked digitised_approx):
approximate, not the paper's tabulated values. The Wong-Reece a0, a1 of this
soil are not given there: Toyoura sand's 0.40, 0.15 are assumed.

usage: PYTHONPATH=build/python python3 tools/soil_ding2011.py
"""
import wtc

RADIUS_M, WIDTH_M, LOAD_N = 0.15735, 0.165, 80.0
# slip: (DP N, T N m, sinkage mm), digitised from Ding et al. 2011 Fig. 9.
DIGITISED = {0.0: (-6.5, 0.0, 5.0), 0.1: (11.0, 3.0, 5.5), 0.2: (14.5, 4.2, 7.5),
             0.3: (15.0, 4.8, 10.0), 0.4: (15.0, 5.0, 12.5), 0.6: (15.0, 5.3, 17.5)}
SHEAR_MODULI_M = (0.0097, 0.0131)  # the ends of their measured K


def soil(k):
    return {"base": "toyoura_sand", "name": "ding2011_simulant", "k_c": 15.6e3, "k_phi": 2407.4e3, "n": 1.10,
            "cohesion": 250.0, "friction_angle_deg": 31.9, "shear_modulus_x": k, "shear_modulus_y": k,
            "density": 1605.0}


def main():
    print("| slip | DP measured (N) | DP model, K 9.7 / 13.1 mm | T measured (N m) | T model | "
          "sinkage measured (mm) | sinkage model |")
    print("|---|---|---|---|---|---|---|")
    for slip, (dp, torque, sinkage) in DIGITISED.items():
        runs = [wtc.wheel_on_soil(soil(k), RADIUS_M, WIDTH_M, LOAD_N, slip) for k in SHEAR_MODULI_M]
        print(f"| {slip:.1f} | {dp:.1f} | {runs[0]['drawbar_pull']:.1f} / {runs[1]['drawbar_pull']:.1f} | "
              f"{torque:.1f} | {runs[0]['torque']:.2f} / {runs[1]['torque']:.2f} | {sinkage:.1f} | "
              f"{runs[0]['sinkage'] * 1e3:.1f} / {runs[1]['sinkage'] * 1e3:.1f} |")


if __name__ == "__main__":
    main()
