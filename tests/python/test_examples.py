"""The examples run as a user runs them, and write their files."""

import csv
import os
import subprocess
import sys

import meshio

EXAMPLES = os.path.join(os.path.dirname(__file__), "..", "..", "examples")


def example(name, out):
    done = subprocess.run([sys.executable, os.path.join(EXAMPLES, name), str(out)], capture_output=True, text=True,
                          timeout=600, env=os.environ)
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_the_wc_co_tensor_and_expansion(tmp_path):
    printed = example("wc_co_tensor.py", tmp_path)
    assert "C11 =" in printed and "alpha_xx =" in printed
    assert (tmp_path / "report.json").exists() and (tmp_path / "mesh.vtu").exists()


def test_the_co_fraction_sweep_plots(tmp_path):
    example("co_fraction_sweep.py", tmp_path)
    assert (tmp_path / "moduli.png").stat().st_size > 10000
    with open(tmp_path / "moduli.csv", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 9
    # More Co (the softer phase): a softer cell, realisation by realisation.
    k = {(float(r["co_fraction"]), int(r["seed"])): float(r["K_GPa"]) for r in rows}
    assert all(k[(0.1, s)] > k[(0.2, s)] > k[(0.3, s)] for s in (1, 2, 3))


def test_the_mesh_in_gmsh_format(tmp_path):
    example("mesh_to_gmsh.py", tmp_path)
    back = meshio.read(tmp_path / "mesh.msh")
    original = meshio.read(tmp_path / "mesh.vtu")
    assert (back.cells_dict["triangle"] == original.cells_dict["triangle"]).all()
    assert sorted(back.field_data) == ["matrix", "particulate"]
