#!/usr/bin/env python3
"""The wear life of the paper's roller (cases/paper-wear.yaml) against its normal load, plotted with matplotlib.

    scripts/python python/examples/life_vs_load.py [life_vs_load.png]

The case is a dict here, so the load is one key to change. The lives run on a thread pool: rollwear releases
the GIL while it computes, so they run on all cores. For many cases, or to resume, `rollwear sweep` (or
rollwear.sweep) is the tool; this is the interactive way.
"""
import concurrent.futures
import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt
import numpy as np

import rollwear

PAPER_WEAR = {  # cases/paper-wear.yaml
    "name": "paper-wear",
    "profiles": {"body1": {"crowned": {"Ry_m": 0.500, "width_m": 0.020}}, "body2": {"flat": {"width_m": 0.030}}},
    "bodies": {"body1": {"Rx_m": 0.020, "E_Pa": 210.0e9, "nu": 0.28},
               "body2": {"Rx_m": 0.025, "E_Pa": 210.0e9, "nu": 0.28}},
    "load": {"normal_load_N": 1500},
    "kinematics": {"speed_m_per_s": 1.0, "xi": 1.0e-3, "eta": 0, "phi_per_m": 0},
    "friction": {"mu": 0.3},
    "solver": {"normal": "auto", "nx": 80, "ny": 80},  # tangential: the default, relaxed, as the case file
    "wear": {"body1": {"law": "archard", "archard_k": 1.0e-4, "hardness_Pa": 6.0e9}, "revolutions": 1.0e10,
             "limits": {"max_depth_m": 1.0e-4, "edge": True},
             "stepping": {"method": "adaptive", "rtol": 1.0e-3, "atol_m": 1.0e-9},
             "smoothing_wavelength_m": 5.0e-4},
}


def life(load_N):
    case = dict(PAPER_WEAR, load={"normal_load_N": float(load_N)})
    r = rollwear.run(case)
    return r["summary"], r["profiles"]["body1"]


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "life_vs_load.png"
    loads = np.linspace(1000, 3000, 9)
    with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count()) as pool:
        results = list(pool.map(life, loads))
    lives = np.array([s["revolutions"] for s, _ in results])
    for F, (s, _) in zip(loads, results):
        print(f"F = {F:6.0f} N: life {s['revolutions']:.4g} revolutions ({s['hours']:.4g} h), ended by {s['ended_by']}")

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    ax1.loglog(loads, lives, "o-")
    ax1.set_xlabel("normal load F (N)")
    ax1.set_ylabel("life (revolutions of the roller)")
    ax1.set_title("wear life against load")
    ax1.grid(True, which="both", alpha=0.3)
    for F, (s, p) in list(zip(loads, results))[::4]:
        ax2.plot(p["y_m"] * 1e3, p["depth_m"][-1] * 1e6, label=f"F = {F:.0f} N ({s['ended_by']})")
    ax2.set_xlabel("lateral position y (mm)")
    ax2.set_ylabel("worn depth at the end of life (µm)")
    ax2.set_title("worn roller profiles")
    ax2.legend()
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
