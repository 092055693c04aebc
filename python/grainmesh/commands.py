"""The grainmesh commands from Python: each runs as the command line runs it (the same
checks, errors, outputs and exit codes: the native part forks the same code), its errors
raised as exceptions naming the key, file or value at fault, Ctrl-C as KeyboardInterrupt
with nothing half-written."""

import os
import shutil
import tempfile

from . import _grainmesh, paths
from .config import ini_text, set_arguments
from .results import Run, Sweep


class Error(Exception):
    """A grainmesh command failed; `exit_code` is the program's (docs/errors.md)."""

    def __init__(self, message, exit_code):
        super().__init__(message)
        self.exit_code = exit_code


class ConfigError(Error, ValueError):
    """A bad key, value or file name: the message names it."""


class GeometryError(Error):
    """A geometry the command cannot mesh, conform or solve."""


class FileError(Error, OSError):
    """A file that cannot be read or written."""


class TimeLimitError(Error, TimeoutError):
    """limits.seconds ran out."""


class SolveError(Error):
    """OpenFOAM's solve failed or did not converge."""


_ERRORS = {
    "config": ConfigError,
    "geometry": GeometryError,
    "io": FileError,
    "time_limit": TimeLimitError,
    "solve": SolveError,
}
_BY_CODE = {code: _ERRORS[name] for name, code in _grainmesh.exit_codes.items()}


def binary():
    """The grainmesh program the commands run: $GRAINMESH_BINARY, else the one this package
    was built or installed with."""
    path = os.environ.get("GRAINMESH_BINARY") or paths.BINARY
    if not os.access(path, os.X_OK):
        raise FileError(f"{path}: no grainmesh program there (build it, or set GRAINMESH_BINARY)", 4)
    return path


def _error_line(stderr):
    """The one line the command printed for its error."""
    lines = [line for line in stderr.splitlines() if line.startswith("grainmesh: ")]
    line = lines[-1] if lines else (stderr.strip().splitlines() or ["grainmesh: failed"])[-1]
    return line[len(_grainmesh.error_prefix):] if line.startswith(_grainmesh.error_prefix) else line


class _Config:
    """A config argument as the command takes it: None (the command's default), a file, or
    a dict written to a private temporary file for the run's length (its name in errors
    said as 'the config dict')."""

    def __init__(self, config):
        self.config = config
        self.dir = None
        self.path = None

    def __enter__(self):
        if self.config is None:
            return self
        if isinstance(self.config, dict):
            text = ini_text(self.config)  # a bad value raises before anything is written
            self.dir = tempfile.mkdtemp(prefix="grainmesh-config-")
            self.path = os.path.join(self.dir, "config.ini")
            with open(self.path, "w", encoding="utf-8") as f:
                f.write(text)
        elif isinstance(self.config, (str, os.PathLike)):
            self.path = os.fspath(self.config)
        else:
            raise TypeError(f"config: a dict, a file name or None, not {type(self.config).__name__}")
        return self

    def __exit__(self, *exc):
        if self.dir:
            shutil.rmtree(self.dir, ignore_errors=True)

    def message(self, text):
        return text.replace(self.path, "the config dict") if self.dir else text


def command(args, config=None, overrides=None, quiet=False, flag=None):
    """Runs `grainmesh ARGS... [CONFIG] [--set ...]` (`flag` CONFIG for a command that
    takes its config as an option, --config); raises on failure."""
    with _Config(config) as c:
        given = ([flag] if flag else []) + [c.path] if c.path else []
        full = [str(a) for a in args] + given + set_arguments(overrides)
        code, stderr = _grainmesh.command(binary(), full, quiet)
        if code != 0:
            raise _BY_CODE.get(code, Error)(c.message(_error_line(stderr)), code)


def _out(out):
    if out is None:
        raise ConfigError("out: the output directory is required (the command's -o)", 2)
    return os.fspath(out)


def run(config=None, out=None, *, solve=False, set=None, quiet=False, force=False):
    """`grainmesh run`: tessellate, mesh and export (and with `solve` solve) a cell.
    `config`: None (the embedded default), an INI file or a dict; `set`: overrides as
    --set. Returns the Run (report, mesh, tessellation)."""
    args = ["run", "-o", _out(out)] + (["--solve"] if solve else []) + (["--force"] if force else [])
    command(args, config, set, quiet)
    return Run(out)


def converge(config=None, out=None, *, levels=None, start=None, set=None, quiet=False):
    """`grainmesh converge`: the effective properties over nested levels; its report."""
    args = ["converge", "-o", _out(out)]
    args += ["--levels", str(levels)] if levels is not None else []
    args += ["--start", str(start)] if start is not None else []
    command(args, config, set, quiet)
    return Run(out)


def sweep(config, out=None, *, jobs=1, solve=False, set=None, quiet=False):
    """`grainmesh sweep`: every run of the [sweep] lists, then their summary."""
    args = ["sweep", "-o", _out(out), "--jobs", str(jobs)] + (["--solve"] if solve else [])
    command(args, config, set, quiet)
    command(["sweep", "--collect", _out(out)], None, None, quiet=True)
    return Sweep(out)


def tessellate(config, out=None, *, set=None, quiet=False):
    """`grainmesh tessellate`: grains and phases; the Run's tessellation."""
    command(["tessellate", "-o", _out(out)], config, set, quiet)
    return Run(out)


def mesh(tessellation, out=None, *, config=None, set=None, quiet=False):
    """`grainmesh mesh TESSELLATION.json`: the conforming mesh; the Run's mesh."""
    command(["mesh", os.fspath(tessellation), "-o", _out(out)], config, set, quiet, flag="--config")
    return Run(out)


def export(mesh_file, out=None, *, config=None, set=None, quiet=False):
    """`grainmesh export MESH.vtu`: the OpenFOAM case."""
    command(["export", os.fspath(mesh_file), "-o", _out(out)], config, set, quiet, flag="--config")
    return os.fspath(out)
