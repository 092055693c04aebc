"""A grainmesh mesh handed to meshio and written in Gmsh's format (MSH 2.2, which every
Gmsh reads), its phases as physical groups named after them.

    PYTHONPATH=build/python python3 examples/mesh_to_gmsh.py [OUT]
"""

import os
import sys

import meshio
import numpy as np

import grainmesh

out = sys.argv[1] if len(sys.argv) > 1 else "out/examples/mesh_to_gmsh"
run = grainmesh.run(out=out, quiet=True, set={"tessellation.grains": 30, "output.pictures": "none"})
mesh = run.mesh
phase = mesh.cell_data["phase"]
# Gmsh's physical groups: tags from 1, one per phase, named as in the config.
physical = (phase + 1).astype(np.int32)
gmsh_mesh = meshio.Mesh(mesh.points, [("triangle", mesh.cells["triangle"])], cell_data={
    "gmsh:physical": [physical], "gmsh:geometrical": [mesh.cell_data["grain"].astype(np.int32) + 1]},
    field_data={name: np.array([k + 1, 2]) for k, name in enumerate(mesh.phase_names)})
target = os.path.join(out, "mesh.msh")
meshio.write(target, gmsh_mesh, file_format="gmsh22", binary=False)
back = meshio.read(target)
print(f"{target}: {len(back.points)} points, {len(back.cells_dict['triangle'])} triangles, "
      f"physical groups {sorted(back.field_data)}")
