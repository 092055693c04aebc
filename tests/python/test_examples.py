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
    with open(tmp_path / "summary.csv", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    assert [float(r["phase.Co.fraction"]) for r in rows] == [0.1, 0.2, 0.3]
    assert all(int(float(r["runs"])) == 3 for r in rows)
    # More Co (the softer phase): a softer cell, inside the Hashin-Shtrikman bounds.
    k = [float(r["bulk_modulus_mean"]) for r in rows]
    assert k[0] > k[1] > k[2]
    for r in rows:
        assert float(r["hs_bulk_lower_mean"]) <= float(r["bulk_modulus_mean"]) <= float(r["hs_bulk_upper_mean"])


def test_the_mesh_in_gmsh_format(tmp_path):
    example("mesh_to_gmsh.py", tmp_path)
    back = meshio.read(tmp_path / "mesh.msh")
    original = meshio.read(tmp_path / "mesh.vtu")
    assert (back.cells_dict["triangle"] == original.cells_dict["triangle"]).all()
    assert sorted(back.field_data) == ["matrix", "particulate"]
