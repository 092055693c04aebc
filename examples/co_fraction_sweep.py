"""The effective bulk and shear moduli of WC-Co against the Co fraction, three realisations
(seeds) per fraction, plotted with their spread: OUT/moduli.png and OUT/moduli.csv.

    PYTHONPATH=build/python python3 examples/co_fraction_sweep.py [OUT]
"""

import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import grainmesh  # noqa: E402

here = os.path.dirname(os.path.abspath(__file__))
out = sys.argv[1] if len(sys.argv) > 1 else "out/examples/co_fraction_sweep"
config = os.path.join(here, "..", "data", "examples", "grains_wc_co.ini")
fractions = [0.1, 0.2, 0.3]
rows = []
for fraction in fractions:
    for seed in (1, 2, 3):
        run = grainmesh.run(config, os.path.join(out, f"co{fraction}_seed{seed}"), quiet=True, set={
            "phase.Co.fraction": fraction, "tessellation.seed": seed, "tessellation.grains": 60,
            "homogenise.boundary": "periodic", "output.pictures": "none"})
        e = run.effective
        rows.append({"co_fraction": fraction, "seed": seed, "K_GPa": e["bulk_modulus"] / 1e9,
                     "G_GPa": e["shear_modulus"] / 1e9})
        print(f"Co {fraction:.2f}, seed {seed}: K {rows[-1]['K_GPa']:.1f} GPa, G {rows[-1]['G_GPa']:.1f} GPa")

with open(os.path.join(out, "moduli.csv"), "w", newline="", encoding="utf-8") as f:
    writer = csv.DictWriter(f, fieldnames=list(rows[0]))
    writer.writeheader()
    writer.writerows(rows)

fig, ax = plt.subplots(figsize=(5, 3.5))
for key, label in (("K_GPa", "bulk modulus K"), ("G_GPa", "shear modulus G")):
    values = np.array([[r[key] for r in rows if r["co_fraction"] == x] for x in fractions])
    ax.errorbar(fractions, values.mean(axis=1), yerr=values.std(axis=1, ddof=1), marker="o", capsize=3, label=label)
ax.set_xlabel("Co area fraction")
ax.set_ylabel("GPa (plane strain, 2D)")
ax.legend()
fig.tight_layout()
fig.savefig(os.path.join(out, "moduli.png"), dpi=120)
print(f"plot: {os.path.join(out, 'moduli.png')}")
