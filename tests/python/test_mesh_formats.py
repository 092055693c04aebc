"""export.format = gmsh, abaqus: mesh.msh and mesh.inp of a periodic 2D and 3D cell, read
back by meshio (an independent reader) with the same cells, grains, phases and sides as
mesh.vtu, accepted by `gmsh -check`, and each periodic pair written exactly once: in the
MSH's $Periodic links and as the INP's *Equations (each high-side point tied once)."""

import configparser
import os
import re
import shutil
import subprocess

import meshio
import numpy as np
import pytest

# meshio 5.0 (Debian 12) reads Abaqus' plane-stress triangles but does not know the
# plane-strain ones (CPE3, the same three-node triangle); later meshio versions do.
meshio.abaqus._abaqus.abaqus_to_meshio_type.setdefault("CPE3", "triangle")

CELLS = {
    "2d": ["tessellation.grains=12", "mesh.triangles_per_grain=40"],
    "3d": ["tessellation.grains=6", "mesh.tets_per_grain=120"],
}
COMMON = ["homogenise.boundary=periodic", "homogenise.solver=openfoam", "output.pictures=none",
          "export.format=gmsh, abaqus"]


@pytest.fixture(scope="module", params=sorted(CELLS))
def run(request, tmp_path_factory, run_binary):
    out = tmp_path_factory.mktemp(request.param) / "run"
    config = [] if request.param == "2d" else [os.path.join(os.path.dirname(__file__), "..", "..", "data",
                                                             "examples", "grains_3d_wc_co.ini")]
    sets = [a for s in CELLS[request.param] + COMMON for a in ("--set", s)]
    done = run_binary("run", *config, "-o", out, "--quiet", *sets)
    assert done.returncode == 0, done.stderr
    return out, 2 if request.param == "2d" else 3


def names(field):
    """mesh.vtu's labels: bytes, each name ended by a NUL."""
    return bytes(np.asarray(field, dtype=np.uint8)).decode().split("\0")[:-1]


def reference(out, dim):
    """mesh.vtu's cells (by their corners' coordinates) with their grain and phase name."""
    vtu = meshio.read(out / "mesh.vtu")
    phases = names(vtu.field_data["phase_names"])
    cells = np.concatenate([b.data for b in vtu.cells])
    grain = np.concatenate(vtu.cell_data["grain"])
    phase = np.concatenate(vtu.cell_data["phase"])
    points = vtu.points[:, :dim]
    return {key(points, c): (int(g), phases[p]) for c, g, p in zip(cells, grain, phase)}, points


def key(points, cell):
    return tuple(sorted(tuple(points[i]) for i in cell))


def labelled(mesh, dim, cell_type, grain_set, phase_set):
    """A meshio mesh's cells of `cell_type` with the grain and phase its named sets give."""
    found = {}
    for b, block in enumerate(mesh.cells):
        if block.type != cell_type:
            continue
        grain = np.full(len(block.data), -1)
        phase = np.full(len(block.data), "", dtype=object)
        for name, per_block in mesh.cell_sets.items():
            members = per_block[b] if per_block[b] is not None else []
            if (m := grain_set.fullmatch(name)):
                assert (grain[members] == -1).all(), f"a cell in two grain sets ({name})"
                grain[members] = int(m.group(1))
            elif (m := phase_set.fullmatch(name)):
                assert (phase[members] == "").all(), f"a cell in two phase sets ({name})"
                phase[members] = m.group(1)
        for c, g, p in zip(block.data, grain, phase):
            found[key(mesh.points[:, :dim], c)] = (int(g), p)
    return found


def on_side(points, dim):
    """Per side (left, right, bottom, top, back, front): the points on it."""
    lo, hi = points.min(axis=0), points.max(axis=0)
    sides = []
    for axis in range(dim):
        sides += [set(np.flatnonzero(points[:, axis] == lo[axis])), set(np.flatnonzero(points[:, axis] == hi[axis]))]
    return sides, hi - lo


SIDES = ["left", "right", "bottom", "top", "back", "front"]


def test_msh_has_the_cells_grains_phases_and_sides_and_gmsh_accepts_it(run):
    out, dim = run
    cells, points = reference(out, dim)
    msh = meshio.read(out / "mesh.msh")
    # The same nodes (numbered side by side and grain by grain, as Gmsh numbers them).
    assert len(msh.points) == len(points)
    assert {tuple(p) for p in msh.points[:, :dim]} == {tuple(p) for p in points}
    phase_names = {p for _, p in cells.values()}
    found = labelled(msh, dim, "triangle" if dim == 2 else "tetra", re.compile(r"grain_(\d+)"),
                     re.compile("(" + "|".join(map(re.escape, phase_names)) + ")"))
    assert found == cells
    # Each side's facets lie on it and cover it exactly once.
    sides, size = on_side(msh.points[:, :dim], dim)
    facet_type = "line" if dim == 2 else "triangle"
    for s, name in enumerate(SIDES[:2 * dim]):
        facets = np.concatenate([b.data[m] for b, m in zip(msh.cells, msh.cell_sets[name])
                                 if b.type == facet_type and m is not None and len(m)])
        assert set(facets.ravel()) == sides[s], name
        p = msh.points[facets]
        measure = (np.linalg.norm(p[:, 1] - p[:, 0], axis=1) if dim == 2
                   else 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1))
        whole = np.prod([size[a] for a in range(dim) if a != s // 2])
        assert measure.sum() == pytest.approx(whole, rel=1e-12), name
    check = subprocess.run(["gmsh", "-check", str(out / "mesh.msh")], capture_output=True, text=True, timeout=300)
    assert check.returncode == 0, check.stdout + check.stderr
    assert "Error" not in check.stdout + check.stderr, check.stdout + check.stderr


def test_msh_lists_each_periodic_pair_once(run):
    out, dim = run
    msh = meshio.read(out / "mesh.msh")
    points = msh.points[:, :dim]
    sides, size = on_side(points, dim)
    links = {(edim, tags): (affine, pairs) for edim, tags, affine, pairs in msh.gmsh_periodic}
    assert len(links) == dim == len(msh.gmsh_periodic)
    for axis in range(dim):
        affine, pairs = links[(dim - 1, (2 * axis + 2, 2 * axis + 1))]
        assert np.asarray(affine).reshape(4, 4)[axis, 3] == size[axis]
        slaves, masters = pairs[:, 0], pairs[:, 1]
        assert len(set(slaves)) == len(slaves) and set(slaves) == sides[2 * axis + 1], SIDES[2 * axis + 1]
        assert set(masters) == sides[2 * axis], SIDES[2 * axis]
        shift = np.zeros(dim)
        shift[axis] = size[axis]
        assert np.array_equal(points[slaves], points[masters] + shift)


def equations(path):
    """The *Equation blocks of an .inp: each a list of (node, dof, coefficient), 1-based."""
    found, lines, k = [], open(path).read().splitlines(), 0
    while k < len(lines):
        if lines[k].lower().startswith("*equation"):
            k += 1
            while k < len(lines) and not lines[k].startswith("*"):
                count, terms = int(lines[k]), []
                k += 1
                while len(terms) < count:
                    v = [x.strip() for x in lines[k].split(",") if x.strip()]
                    terms += [(int(v[i]), int(v[i + 1]), float(v[i + 2])) for i in range(0, len(v), 3)]
                    k += 1
                assert len(terms) == count
                found.append(terms)
        else:
            k += 1
    return found


def test_inp_has_the_cells_sets_materials_and_ties_each_periodic_point_once(run):
    out, dim = run
    cells, points = reference(out, dim)
    inp = meshio.read(out / "mesh.inp")
    n = len(points)
    assert np.array_equal(inp.points[:n], points), "the nodes in mesh.vtu's order, then the reference nodes"
    phase_names = {p for _, p in cells.values()}
    found = labelled(inp, dim, "triangle" if dim == 2 else "tetra", re.compile(r"GRAIN_(\d+)"),
                     re.compile("PHASE_(" + "|".join(map(re.escape, phase_names)) + ")"))
    assert found == cells
    sides, size = on_side(points, dim)
    for s, name in enumerate(SIDES[:2 * dim]):
        assert set(inp.point_sets[name.upper()]) == sides[s], name
    text = open(out / "mesh.inp").read()
    # Each phase's material carries the config's E and nu (config.ini as the run resolved it).
    config = configparser.ConfigParser(inline_comment_prefixes=("#",))
    config.read(out / "config.ini")
    for p in phase_names:
        elastic = re.search(rf"\*Material, name={p}\n\*Elastic\n([^\n]*)\n", text)
        assert elastic, p
        E, nu = (float(v) for v in elastic.group(1).split(","))
        assert (E, nu) == (float(config[f"phase.{p}"]["E"]), float(config[f"phase.{p}"]["nu"]))
    assert ("*Element, type=CPE3" if dim == 2 else "*Element, type=C3D4") in text
    # The equations: u(point) - u(root) - u(RP of each axis crossed) = 0, per direction.
    reference_node = {axis: int(inp.point_sets["RP_" + "XYZ"[axis]][0]) + 1 for axis in range(dim)}
    assert sorted(reference_node.values()) == list(range(n + 1, n + dim + 1))
    axis_of = {node: axis for axis, node in reference_node.items()}
    high = set().union(*(sides[2 * a + 1] for a in range(dim)))
    tied = {}
    for terms in equations(out / "mesh.inp"):
        (point, dof, one), (root, dof2, minus_one), *rps = terms
        assert one == 1.0 and minus_one == -1.0 and dof == dof2 and 1 <= dof <= dim
        assert all(d == dof and c == -1.0 and node in axis_of for node, d, c in rps)
        shift = np.zeros(dim)
        for node, _, _ in rps:
            shift[axis_of[node]] = size[axis_of[node]]
        assert np.array_equal(points[point - 1], points[root - 1] + shift)
        assert root - 1 not in high, "tied straight to a point on no high side"
        tied.setdefault(point - 1, []).append(dof)
    assert set(tied) == high, "every point on a high side tied"
    assert all(sorted(dofs) == list(range(1, dim + 1)) for dofs in tied.values()), "once per direction"


def test_a_bad_format_is_refused_naming_the_key(tmp_path, run_binary):
    done = run_binary("run", "-o", tmp_path / "bad", "--set", "export.format=ascii, stl")
    assert done.returncode != 0
    assert done.stderr.count("\n") == 1 and "export.format" in done.stderr and "stl" in done.stderr
    assert not (tmp_path / "bad").exists()


def test_export_writes_them_from_a_mesh_file_and_refuses_polygons(tmp_path, run_binary):
    default = os.path.join(os.path.dirname(__file__), "..", "..", "data", "default.ini")
    assert run_binary("tessellate", default, "-o", tmp_path / "t", "--set", "tessellation.grains=8").returncode == 0
    assert run_binary("mesh", tmp_path / "t" / "tessellation.json", "-o", tmp_path / "m").returncode == 0
    done = run_binary("export", tmp_path / "m" / "mesh.vtu", "-o", tmp_path / "e", "--set", "export.cells=polygons",
                      "--set", "export.format=binary, gmsh, abaqus")
    assert done.returncode == 0, done.stderr
    cells, _ = reference(tmp_path / "m", 2)
    phase_names = {p for _, p in cells.values()}
    msh = meshio.read(tmp_path / "e" / "mesh.msh")
    assert labelled(msh, 2, "triangle", re.compile(r"grain_(\d+)"),
                    re.compile("(" + "|".join(map(re.escape, phase_names)) + ")")) == cells, "the triangles, not the polygons"
    inp = meshio.read(tmp_path / "e" / "mesh.inp")
    assert labelled(inp, 2, "triangle", re.compile(r"GRAIN_(\d+)"),
                    re.compile("PHASE_(" + "|".join(map(re.escape, phase_names)) + ")")) == cells
    # The export's own mesh.vtu holds polygons: they are not finite elements.
    (tmp_path / "polygons").mkdir()
    shutil.copy(tmp_path / "e" / "mesh.vtu", tmp_path / "polygons")
    shutil.copy(tmp_path / "m" / "mesh.json", tmp_path / "polygons")
    refused = run_binary("export", tmp_path / "polygons" / "mesh.vtu", "-o", tmp_path / "p", "--set",
                         "export.cells=polygons", "--set", "export.format=gmsh")
    assert refused.returncode != 0 and refused.stderr.count("\n") == 1 and "export.format" in refused.stderr
    assert not (tmp_path / "p").exists()
