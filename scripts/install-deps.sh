#!/usr/bin/env bash
# Installs the Debian packages grainmesh builds and tests with, only those missing.
# With --bench, also the peer `make bench` compares against (SfePy, read through VTK's Python).
# Idempotent: a second run installs nothing and takes well under a second.
set -euo pipefail

packages=(
  build-essential cmake ccache pkg-config
  libcgal-dev libgmp-dev libmpfr-dev    # Delaunay, exact predicates
  libvtk9-dev                           # mesh.vtu
  libboost-program-options-dev          # command line and INI configs
  catch2                                # unit tests (v2, catch2/catch.hpp)
  libmuparser-dev                       # size functions as user expressions
  libtbb-dev                            # parallel loops
  libcairo2-dev                         # pictures
  nlohmann-json3-dev                    # reports
  python3-jsonschema                    # the tests check every report against docs/report.schema.json
  openfoam                              # checkMesh and solidDisplacementFoam in the tests (Open MPI with it)
  libtet1.5-dev                         # TetGen's library: fills 3D grains with tetrahedra
  libeigen3-dev libsuitesparse-dev      # the finite-element reference solve (sparse Cholesky: CHOLMOD)
  libopenblas0-pthread                  # ... its dense blocks: CHOLMOD on the reference BLAS is 20x slower
  slurm-wlm                             # a one-node SLURM cluster for the sweep's job-array test
  clang libclang-rt-dev                 # the sanitizer build and libFuzzer (make test, make fuzz)
  python3-dev python3-pybind11 python3-numpy   # the Python module (python/)
  python3-pytest python3-meshio python3-matplotlib python3-vtk9  # its tests and examples
  gmsh                                  # gmsh -check reads the mesh.msh files the tests write (make bench's peer too)
)
if [[ "${1:-}" == "--bench" ]]; then
  packages+=(python3-sfepy)             # make bench's peer of the finite-element reference (VTK's Python above)
fi

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done

if [[ ${#missing[@]} -eq 0 ]]; then
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "install-deps: need root or sudo to install ${missing[*]}" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
