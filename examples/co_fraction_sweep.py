"""The effective bulk and shear moduli of WC-Co against the Co fraction: a sweep of three
fractions, three realisations each, its summary plotted with the 95 % confidence intervals
and the Hashin-Shtrikman bounds (OUT/moduli.png; the sweep's own files in OUT).

    PYTHONPATH=build/python python3 examples/co_fraction_sweep.py [OUT]
"""

import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import grainmesh  # noqa: E402

here = os.path.dirname(os.path.abspath(__file__))
out = sys.argv[1] if len(sys.argv) > 1 else "out/examples/co_fraction_sweep"
config = grainmesh.read_config(os.path.join(here, "..", "data", "examples", "grains_wc_co.ini"))
config["tessellation"]["grains"] = 60
config["homogenise"] = {"boundary": "periodic"}
config["output"] = {"pictures": "none"}
config["sweep"] = {"phase.Co.fraction": [0.1, 0.2, 0.3], "realisations": 3}
sweep = grainmesh.sweep(config, out, jobs=2, quiet=True)

fraction = [row["phase.Co.fraction"] for row in sweep.rows]
fig, ax = plt.subplots(figsize=(5, 3.5))
for key, bound, label in (("bulk_modulus", "hs_bulk", "K"), ("shear_modulus", "hs_shear", "G")):
    mean = [row[f"{key}_mean"] / 1e9 for row in sweep.rows]
    ci = [row[f"{key}_ci95"] / 1e9 for row in sweep.rows]
    line = ax.errorbar(fraction, mean, yerr=ci, marker="o", capsize=3, label=f"{label} (95 % interval)")
    for side in ("lower", "upper"):
        ax.plot(fraction, [row[f"{bound}_{side}_mean"] / 1e9 for row in sweep.rows], ":", color=line[0].get_color())
    for x, m, c in zip(fraction, mean, ci):
        print(f"Co {x:.2f}: {label} = {m:.1f} +/- {c:.1f} GPa")
ax.set_xlabel("Co area fraction")
ax.set_ylabel("GPa (plane strain; dotted: Hashin-Shtrikman)")
ax.legend()
fig.tight_layout()
fig.savefig(os.path.join(out, "moduli.png"), dpi=120)
print(f"plot: {os.path.join(out, 'moduli.png')}")
