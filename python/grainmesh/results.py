"""What a command leaves, read: the report as a dict, the tessellation (tessellation.json:
grains' polygons or polyhedra, phases, periodic pairs) and the mesh (mesh.vtu, through
meshio) as numpy arrays."""

import csv
import json
import os

# numpy and meshio (Debian's python3-numpy, python3-meshio) are imported where a mesh is
# read: the commands and reports need neither (a Python without them still runs them).


def labels(field):
    """A list of names as grainmesh writes them in a VTU's field data: bytes, each name in
    UTF-8 ended by a NUL (docs/python.md, Files other tools read)."""
    import numpy as np

    return bytes(np.asarray(field, dtype=np.uint8)).decode("utf-8").split("\0")[:-1]


class Mesh:
    """A VTU file's mesh, read by meshio. `points` (n x 3); `cells`: {meshio's cell type:
    connectivity} (`triangle` m x 3, `tetra` m x 4; polygons and polyhedra as meshio gives
    them); `cell_data`: every cell array (`grain`, `phase`, the fields of results.vtu) in
    the file's cell order; `labels`: the lists of names (`phase_names`: the names the
    `phase` numbers index); `meshio`: meshio's own Mesh."""

    def __init__(self, path):
        import meshio
        import numpy as np

        self.path = os.fspath(path)
        self.meshio = meshio.read(self.path)
        self.points = self.meshio.points
        self.cells = {}
        for block in self.meshio.cells:
            if block.type in self.cells:  # one type in several blocks: joined in the file's order
                self.cells[block.type] = np.concatenate([self.cells[block.type], block.data])
            else:
                self.cells[block.type] = block.data
        self.cell_data = {name: blocks[0] if len(blocks) == 1 else np.concatenate(blocks)
                          for name, blocks in self.meshio.cell_data.items()}
        self.labels = {name: labels(v) for name, v in self.meshio.field_data.items()
                       if np.asarray(v).dtype == np.uint8}

    @property
    def phase_names(self):
        return self.labels.get("phase_names", [])

    def __repr__(self):
        kinds = ", ".join(f"{len(v)} {k}" for k, v in self.cells.items())
        return f"<grainmesh.Mesh {self.path}: {len(self.points)} points, {kinds}>"


def read_mesh(path):
    """A VTU file (mesh.vtu, results.vtu, fe_mesh.vtu, the 3D tessellation.vtu) as a Mesh."""
    return Mesh(path)


class Run:
    """A command's output directory: `report` (report.json as a dict), `tessellation`
    (tessellation.json as a dict), `mesh` (mesh.vtu as a Mesh), each read when first asked."""

    def __init__(self, out):
        self.out = os.fspath(out)
        self._report = self._tessellation = self._mesh = None

    def file(self, name):
        return os.path.join(self.out, name)

    def _json(self, name):
        with open(self.file(name), encoding="utf-8") as f:
            return json.load(f)

    @property
    def report(self):
        if self._report is None:
            self._report = self._json("report.json")
        return self._report

    @property
    def tessellation(self):
        if self._tessellation is None:
            self._tessellation = self._json("tessellation.json")
        return self._tessellation

    @property
    def mesh(self):
        if self._mesh is None:
            self._mesh = Mesh(self.file("mesh.vtu"))
        return self._mesh

    @property
    def effective(self):
        """The answer (report["effective"]), or None where the run gave none."""
        return self.report.get("effective")

    def __repr__(self):
        return f"<grainmesh.Run {self.out}>"


def _number(text):
    try:
        return float(text)
    except ValueError:
        return text


class Sweep:
    """A sweep's directory: `rows`, its summary.csv as dicts (numbers as floats)."""

    def __init__(self, out):
        self.out = os.fspath(out)
        with open(os.path.join(self.out, "summary.csv"), encoding="utf-8", newline="") as f:
            self.rows = [{k: _number(v) for k, v in row.items()} for row in csv.DictReader(f)]

    def __repr__(self):
        return f"<grainmesh.Sweep {self.out}: {len(self.rows)} rows>"
