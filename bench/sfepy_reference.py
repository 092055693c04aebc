#!/usr/bin/python3
"""The peer of grainmesh's finite elements (analysis/fe_homogenise.hpp): SfePy's periodic
homogenisation (Debian python3-sfepy) on the mesh a grainmesh run solved them on.

usage: sfepy_reference.py OUT [ANSWER.json]

OUT is a periodic `grainmesh run` whose fe_mesh.vtu (the finite elements' fine level) holds
triangles (2D) or tetrahedra (3D):
its cells, their phases (cell array `phase`, names in field data `phase_names`), the
phases' E and nu from OUT/config.ini and the plane state from OUT/report.json. SfePy
solves its own corrector problems on the same cells with quadratic Lagrange elements
(field order 2), ties the sides by matching coordinates (its match_*_plane), holds the
corners, and returns the homogenised stiffness. Written as JSON to ANSWER.json (or
stdout), named as
grainmesh names the stiffness's entries (C11, C12, ..., Voigt 1..3 the normals, then
yz, xz, xy in 3D; xy is 6 in 2D), with engineering shear strains as grainmesh's.
"""
import configparser
import contextlib
import json
import os
import sys
import tempfile

import numpy as np
import vtk

from sfepy.base.base import output as sfepy_output
from sfepy.base.conf import ProblemConf, get_standard_keywords
from sfepy.discrete.fem import Mesh
import sfepy.discrete.fem.periodic as periodic
import sfepy.homogenization.coefs_base as cb
from sfepy.homogenization.homogen_app import HomogenizationApp
from sfepy.homogenization.utils import define_box_regions
from sfepy.mechanics.matcoefs import stiffness_from_youngpoisson


def read_run(out):
    """The mesh (points, cells, phase per cell), the phases' (E, nu) and the plane state."""
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(os.path.join(out, "fe_mesh.vtu"))
    reader.Update()
    grid = reader.GetOutput()
    types = {grid.GetCellType(i) for i in range(grid.GetNumberOfCells())}
    if types not in ({vtk.VTK_TRIANGLE}, {vtk.VTK_TETRA}):
        sys.exit("sfepy_reference: %s/fe_mesh.vtu: triangles or tetrahedra only" % out)
    dim = 2 if types == {vtk.VTK_TRIANGLE} else 3
    points = np.array([grid.GetPoint(i)[:dim] for i in range(grid.GetNumberOfPoints())])
    cells = np.array([[grid.GetCell(i).GetPointId(k) for k in range(dim + 1)]
                      for i in range(grid.GetNumberOfCells())], dtype=np.int32)
    phase_array = grid.GetCellData().GetArray("phase")
    phases = np.array([int(phase_array.GetValue(i)) for i in range(grid.GetNumberOfCells())], dtype=np.int32)
    names_array = grid.GetFieldData().GetAbstractArray("phase_names")
    values = [names_array.GetValue(i) for i in range(names_array.GetNumberOfValues())]
    # The names as NUL-ended bytes (view/vtu.cpp writes them so, for meshio and VTK alike).
    names = [n.decode() for n in bytes(values).split(b"\0")[:-1]] if values and isinstance(values[0], int) else values
    config = configparser.ConfigParser(inline_comment_prefixes=("#", ";"))
    config.read(os.path.join(out, "config.ini"))
    materials = [(float(config["phase." + n]["E"]), float(config["phase." + n]["nu"])) for n in names]
    with open(os.path.join(out, "report.json")) as f:
        plane = "stress" if "stress" in str(json.load(f).get("plane_state")) else "strain"
    return dim, points, cells, phases, materials, plane


def homogenise(dim, points, cells, phases, materials, plane, workdir):
    """SfePy's homogenised stiffness, in its Voigt order (2D 11 22 12; 3D 11 22 33 12 13 23)."""
    mesh_file = os.path.join(workdir, "cell.mesh")
    mesh = Mesh.from_data("cell", points, None, [cells], [phases + 1], ["%d_%d" % (dim, dim + 1)])
    mesh.write(mesh_file, io="auto")
    low, high = points.min(axis=0), points.max(axis=0)
    regions = {"Y": "all"}
    stiffness = {}
    for k, (young, poisson) in enumerate(materials):
        if np.any(phases == k):
            regions["Y%d" % k] = "cells of group %d" % (k + 1)
            stiffness["Y%d" % k] = stiffness_from_youngpoisson(dim, young, poisson, plane=plane)
    regions.update(define_box_regions(dim, tuple(low), tuple(high), eps=1e-7))
    sides = [("periodic_x", ["Left", "Right"], "match_x_plane"),
             ("periodic_y", ["Bottom", "Top"] if dim == 2 else ["Near", "Far"], "match_y_plane"),
             ("periodic_z", ["Bottom", "Top"], "match_z_plane")][:dim]
    define = {
        "filename_mesh": mesh_file,
        "regions": regions,
        "materials": {"mat": ({"D": stiffness},)},
        "fields": {"corrector": ("real", dim, "Y", 2)},  # quadratic, as grainmesh's reference
        "variables": {
            "u": ("unknown field", "corrector", 0),
            "v": ("test field", "corrector", "u"),
            "Pi": ("parameter field", "corrector", "u"),
            "Pi1": ("parameter field", "corrector", "(set-to-None)"),
            "Pi2": ("parameter field", "corrector", "(set-to-None)"),
        },
        "functions": {
            "match_x_plane": (periodic.match_x_plane,),
            "match_y_plane": (periodic.match_y_plane,),
            "match_z_plane": (periodic.match_z_plane,),
        },
        "ebcs": {"fixed_u": ("Corners", {"u.all": 0.0})},
        "epbcs": {name: (pair, {"u.all": "u.all"}, match) for name, pair, match in sides},
        "integrals": {"i": 2},  # exact for the stiffness of quadratic elements on straight cells
        "options": {
            "coefs": "coefs",
            "requirements": "requirements",
            "ls": "ls",
            "volume": {"expression": "ev_volume.i.Y(u)"},
            "output_dir": workdir,
            "coefs_filename": "coefs",
        },
        "coefs": {
            "D": {
                "requires": ["pis", "corrs_rs"],
                "expression": "dw_lin_elastic.i.Y(mat.D, Pi1, Pi2)",
                "set_variables": [("Pi1", ("pis", "corrs_rs"), "u"), ("Pi2", ("pis", "corrs_rs"), "u")],
                "class": cb.CoefSymSym,
            },
            "filenames": {},
        },
        "requirements": {
            "pis": {"variables": ["u"], "class": cb.ShapeDimDim},
            "corrs_rs": {
                "requires": ["pis"],
                "ebcs": ["fixed_u"],
                "epbcs": [name for name, _, _ in sides],
                "equations": {"balance": "dw_lin_elastic.i.Y(mat.D, v, u) = - dw_lin_elastic.i.Y(mat.D, v, Pi)"},
                "set_variables": [("Pi", "pis", "u")],
                "class": cb.CorrDimDim,
                "is_linear": True,
            },
        },
        "solvers": {"ls": ("ls.scipy_direct", {}), "newton": ("nls.newton", {"i_max": 1, "eps_a": 1e-4})},
    }
    required, other = get_standard_keywords()
    required.remove("equations")
    conf = ProblemConf.from_dict(define, sys.modules[__name__], required, other, verbose=False)
    options = type("Options", (), {"output_filename_trunk": None})()
    app = HomogenizationApp(conf, options, "sfepy_reference:")
    return np.array(app().D)


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__.strip().splitlines()[2])
    sfepy_output.set_output(quiet=True)
    dim, points, cells, phases, materials, plane = read_run(sys.argv[1])
    with tempfile.TemporaryDirectory(prefix="grainmesh-sfepy-") as workdir, \
            contextlib.redirect_stdout(sys.stderr):  # SfePy's and meshio's chatter: stdout is the answer's
        d = homogenise(dim, points, cells, phases, materials, plane, workdir)
    voigt = [1, 2, 6] if dim == 2 else [1, 2, 3, 6, 5, 4]  # SfePy's order, as grainmesh numbers it
    stiffness = {}
    for i in range(len(voigt)):
        for j in range(len(voigt)):
            a, b = sorted((voigt[i], voigt[j]))
            stiffness["C%d%d" % (a, b)] = float(d[i, j])
    answer = {"stiffness": stiffness, "cells": int(len(cells)), "plane": plane if dim == 2 else None}
    if len(sys.argv) == 3:
        with open(sys.argv[2], "w") as f:
            json.dump(answer, f)
    else:
        json.dump(answer, sys.stdout)
        sys.stdout.write("\n")


if __name__ == "__main__":
    main()
