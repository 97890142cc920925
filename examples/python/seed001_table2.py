"""Seed 001 Table 2 (filleted end mill, lead 5 deg): the simulated exact L/2 beside the
printed one, as `scallop validate` reports it, and a scallop profile plotted with
Matplotlib. Run with PYTHONPATH=<build>/python: python3 seed001_table2.py [OUT.png]"""
import sys

import matplotlib
matplotlib.use("Agg")  # no display needed: the plot goes into a PNG
import matplotlib.pyplot as plt

import scallop

# Seed 001 Table 2: condition, R, corner radius, h (mm), printed L/2 (mm).
TABLE2 = [("F1a", 3, 1, 0.05, 1.442), ("F1b", 3, 1, 0.10, 1.879), ("F2a", 5, 1, 0.05, 2.090),
          ("F2b", 5, 1, 0.10, 2.843), ("F3a", 6, 2, 0.05, 2.115), ("F3b", 6, 2, 0.10, 2.884),
          ("F4a", 7, 3, 0.05, 2.140), ("F4b", 7, 3, 0.10, 2.924)]

print(f"{'':4} {'R':>3} {'r':>3} {'h':>5} {'printed L/2':>12} {'simulated L/2':>14} {'diff um':>8}")
for name, R, r, h, printed in TABLE2:
    simulated = scallop.interval(tool="bull", radius=R, corner_radius=r, lead=5,
                                 scallop=h)["simulated_half_interval"]
    print(f"{name:4} {R:3} {r:3} {h:5.2f} {printed:12.3f} {simulated:14.6f} "
          f"{1000 * (printed - simulated):+8.1f}")

# The profile across three passes of F3b's cutter at the simulated step-over 2 L/2.
L2 = scallop.interval(tool="bull", radius=6, corner_radius=2, lead=5,
                      scallop=0.1)["simulated_half_interval"]
run = scallop.simulate({
    "tool": {"type": "bull", "radius": 6, "corner_radius": 2},
    "stock": {"min": [0, 0, -2], "max": [4, 4 * L2, 0]},
    "grid": {"spacing": 0.005},
    "path": {"raster": {"direction": "x", "step_over": 2 * L2, "depth": 0.5, "lead_deg": 5}}})
column = run.heights[:, run.grid.nx // 2]          # heights along y at the middle x
floor = run.report["measurements"]["floor_z"]
plt.figure(figsize=(7, 3))
plt.plot(run.grid.y, 1000 * (column - floor), lw=1.2)
plt.axhline(100, ls="--", c="grey", label="h = 0.1 mm")
plt.xlabel("y (cross-feed), mm")
plt.ylabel("height above floor, um")
plt.title(f"Seed 001 F3b: bull R6 r2, lead 5 deg, step-over 2 x {L2:.4f} mm")
plt.legend()
plt.tight_layout()
out = sys.argv[1] if len(sys.argv) > 1 else "seed001_f3b_profile.png"
plt.savefig(out, dpi=120)
print(f"largest scallop {run.report['measurements']['max_scallop_height']:.6f} mm; wrote {out}")
