"""Every VTU a run writes is read alike by meshio and by VTK (and by the module): the same
points, cells and cell arrays, the phases' names decoded from the field data."""

import glob
import os

import meshio
import numpy as np
import pytest
import vtk
from vtk.util.numpy_support import vtk_to_numpy

import grainmesh

CELLS = {
    "2d": ["tessellation.grains=12", "mesh.triangles_per_grain=40", "homogenise.boundary=periodic"],
    "3d": ["tessellation.grains=6", "mesh.tets_per_grain=120", "homogenise.boundary=periodic"],
}


@pytest.fixture(scope="module", params=sorted(CELLS))
def solved(request, tmp_path_factory, run_binary):
    out = tmp_path_factory.mktemp(request.param) / "run"
    config = [] if request.param == "2d" else [os.path.join(os.path.dirname(__file__), "..", "..", "data",
                                                             "examples", "grains_3d_wc_co.ini")]
    sets = [a for s in CELLS[request.param] for a in ("--set", s)]
    done = run_binary("run", *config, "-o", out, "--solve", "--quiet", *sets)
    assert done.returncode == 0, done.stderr
    files = sorted(glob.glob(str(out / "*.vtu")))
    assert {"mesh.vtu", "results.vtu", "fe_mesh.vtu"} <= {os.path.basename(f) for f in files}
    return files


def read_with_vtk(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    cells = grid.GetCells()
    out = {
        "points": vtk_to_numpy(grid.GetPoints().GetData()),
        "types": vtk_to_numpy(grid.GetCellTypesArray()),
        "connectivity": vtk_to_numpy(cells.GetConnectivityArray()),
        "cell_data": {grid.GetCellData().GetArrayName(a): vtk_to_numpy(grid.GetCellData().GetArray(a))
                      for a in range(grid.GetCellData().GetNumberOfArrays())},
        "field_data": {grid.GetFieldData().GetArrayName(a): vtk_to_numpy(grid.GetFieldData().GetArray(a))
                       for a in range(grid.GetFieldData().GetNumberOfArrays())},
    }
    return out


def names(field):
    """Labels written as bytes, each name ended by a NUL (docs/python.md, Files other tools read)."""
    return bytes(np.asarray(field, dtype=np.uint8)).decode().split("\0")[:-1]


def corners(block):
    """A meshio block's cells as their points, in order (a polyhedron's: its faces' points
    in turn, as VTK lists them)."""
    if block.type.startswith("polyhedron"):
        return [np.concatenate([np.asarray(face).ravel() for face in cell]) for cell in block.data]
    return list(block.data)


def test_meshio_and_vtk_read_every_vtu_alike(solved):
    for path in solved:
        by_vtk = read_with_vtk(path)
        by_meshio = meshio.read(path)
        ours = grainmesh.read_mesh(path)
        assert np.array_equal(by_meshio.points, by_vtk["points"]), path
        assert np.array_equal(ours.points, by_vtk["points"]), path
        # meshio keeps the file's cells in blocks of one type, in the file's order.
        cells = [c for block in by_meshio.cells for c in corners(block)]
        assert len(cells) == len(by_vtk["types"]), path
        if not any(b.type.startswith("polyhedron") for b in by_meshio.cells):
            assert np.array_equal(np.concatenate(cells), by_vtk["connectivity"]), path
        else:  # VTK lists a polyhedron's corners once each; meshio its faces' points
            assert set(np.concatenate(cells)) == set(by_vtk["connectivity"]), path
        assert set(by_meshio.cell_data) == set(by_vtk["cell_data"]) == set(ours.cell_data), path
        for name, values in by_vtk["cell_data"].items():
            assert np.array_equal(np.concatenate(by_meshio.cell_data[name]), values), (path, name)
            assert np.array_equal(ours.cell_data[name], values), (path, name)
        assert names(by_meshio.field_data["phase_names"]) == names(by_vtk["field_data"]["phase_names"])
        assert names(by_meshio.field_data["phase_names"]) == ours.phase_names != []
