"""The Python module against the command: the same run to the bit, the same arrays as
mesh.vtu, errors as exceptions naming the key, Ctrl-C as KeyboardInterrupt leaving nothing."""

import json
import os
import signal
import subprocess
import sys
import textwrap
import time

import meshio
import numpy as np
import pytest

import grainmesh
from conftest import without_timings


def test_the_default_run_is_the_commands_to_the_bit(tmp_path, run_binary):
    done = run_binary("run", "-o", tmp_path / "command", "--quiet")
    assert done.returncode == 0, done.stderr
    run = grainmesh.run(out=tmp_path / "python", quiet=True)
    with open(tmp_path / "command" / "report.json", encoding="utf-8") as f:
        command = json.load(f)
    assert without_timings(run.report) == without_timings(command)
    assert run.report["mesh"]["cells"] == len(run.mesh.cells["triangle"])
    # The arrays are mesh.vtu's, as meshio reads them.
    m = meshio.read(tmp_path / "command" / "mesh.vtu")
    assert np.array_equal(run.mesh.points, m.points)
    assert np.array_equal(run.mesh.cells["triangle"], m.cells_dict["triangle"])
    for name in ("grain", "phase"):
        assert np.array_equal(run.mesh.cell_data[name], m.cell_data_dict[name]["triangle"])
    assert run.mesh.phase_names == ["particulate", "matrix"]
    t = run.tessellation
    assert len(t["grains"]) == run.report["grains"] == 100
    assert [p["name"] for p in t["phases"]] == run.mesh.phase_names
    assert set(np.unique(run.mesh.cell_data["grain"])) == {g["id"] for g in t["grains"]}
    assert len(t["partners"]["x"]) > 0  # periodic vertex pairs across the cell


def test_a_config_dict_and_overrides_run_as_the_file_would(tmp_path):
    config = grainmesh.default_config()
    config["tessellation"]["grains"] = 12
    run = grainmesh.run(config, tmp_path / "dict", set={"mesh.triangles_per_grain": 30}, quiet=True)
    assert run.report["grains"] == 12
    assert run.effective is None  # the default cell's mixed load answers only when solved
    # The same keys flat.
    flat = {f"{s}.{k}": v for s, keys in config.items() for k, v in keys.items()}
    again = grainmesh.run(flat, tmp_path / "flat", set={"mesh": {"triangles_per_grain": 30}}, quiet=True)
    assert without_timings(again.report) == without_timings(run.report) | {"config": again.report["config"]}


def test_a_bad_key_raises_naming_it_and_writes_nothing(tmp_path):
    with pytest.raises(grainmesh.ConfigError, match="tessellation.grainz") as e:
        grainmesh.run(out=tmp_path / "bad", set={"tessellation.grainz": 5}, quiet=True)
    assert e.value.exit_code == 2
    config = grainmesh.default_config()
    config["mesh"] = {"triangels_per_grain": 30}
    with pytest.raises(ValueError, match=r"the config dict.*mesh\.triangels_per_grain"):
        grainmesh.run(config, tmp_path / "bad", quiet=True)
    with pytest.raises(grainmesh.ConfigError, match="tessellation.grains"):
        grainmesh.run(out=tmp_path / "bad", set={"tessellation.grains": -3}, quiet=True)
    with pytest.raises(grainmesh.FileError, match="nowhere.ini"):
        grainmesh.run(tmp_path / "nowhere.ini", tmp_path / "bad", quiet=True)
    assert os.listdir(tmp_path) == []


def test_ctrl_c_raises_keyboard_interrupt_within_a_second_and_leaves_nothing(tmp_path):
    out = tmp_path / "long"
    script = textwrap.dedent(f"""
        import sys, time, grainmesh
        try:
            grainmesh.run(out={str(out)!r}, set={{"tessellation.grains": 20000, "domain.width": 15,
                                               "domain.height": 13}}, quiet=True)
        except KeyboardInterrupt:
            print("KeyboardInterrupt", time.monotonic(), flush=True)
            sys.exit(42)
    """)
    child = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             text=True, env=os.environ)
    time.sleep(3.0)  # well into the meshing of 20,000 grains
    assert child.poll() is None, child.communicate()
    sent = time.monotonic()
    child.send_signal(signal.SIGINT)
    stdout, stderr = child.communicate(timeout=30)
    assert child.returncode == 42, stderr
    raised = float(stdout.split()[1])
    assert raised - sent < 1.0
    assert not out.exists()
    assert os.listdir(tmp_path) == []


def test_the_stage_commands_and_converge_from_python(tmp_path):
    config = grainmesh.default_config()
    config["tessellation"]["grains"] = 12
    t = grainmesh.tessellate(config, tmp_path / "t", quiet=True)
    assert len(t.tessellation["grains"]) == 12
    m = grainmesh.mesh(tmp_path / "t" / "tessellation.json", tmp_path / "m", set={"mesh.triangles_per_grain": 30},
                       quiet=True)
    assert set(np.unique(m.mesh.cell_data["grain"])) == set(range(12))
    case = grainmesh.export(tmp_path / "m" / "mesh.vtu", tmp_path / "c", quiet=True)
    assert os.path.exists(os.path.join(case, "system", "controlDict"))
    study = grainmesh.converge(config, tmp_path / "cv", levels=3, start=12, quiet=True,
                               set={"homogenise.boundary": "periodic"})
    assert len(study.report["levels"]) == 3
    with pytest.raises(grainmesh.ConfigError, match="levels"):
        grainmesh.converge(config, tmp_path / "bad", levels=9, quiet=True)
    assert not (tmp_path / "bad").exists()
