"""grainmesh from Python: microstructures to conforming meshes, OpenFOAM cases and
effective properties with their errors — the grainmesh command's own code, its config keys
and checks (docs/python.md).

    import grainmesh
    run = grainmesh.run(out="out/cell")            # the default cell (data/default.ini)
    run.report["effective"]["stiffness"]           # the answer, as report.json has it
    run.mesh.points, run.mesh.cells["triangle"]    # numpy arrays of mesh.vtu
"""

from .commands import (ConfigError, Error, FileError, GeometryError, SolveError, TimeLimitError, command, converge,
                       export, mesh, run, sweep, tessellate)
from .config import default_config, read_config
from .results import Mesh, Run, Sweep, read_mesh

__all__ = ["ConfigError", "Error", "FileError", "GeometryError", "SolveError", "TimeLimitError", "command", "converge",
           "export", "mesh", "run", "sweep", "tessellate", "default_config", "read_config", "Mesh", "Run", "Sweep", "read_mesh"]
