"""PKM Studio from Python: design and analyse parallel-kinematic mechanisms.

The numbers are those of the ``pkm`` command line, computed by the same code in this
process: ``design.evaluate()`` gives the groups and keys of ``pkm eval --json``, sweeps the
columns of ``pkm sweep --csv`` and maps the cells of ``pkm map``. Units are the display units
of PKM Studio (mm, degrees, N, N·mm …), as in design files and on the command line.

A quick tour::

    import numpy as np
    import pkmstudio

    [p["id"] for p in pkmstudio.presets()]        # the built-in designs
    prototype = pkmstudio.load("pjoint-prototype")   # a preset, or a .pkm.json file
    prototype.parameters                           # {'a': 100.0, 'b': ..., ...}
    report = prototype.evaluate()                  # as `pkm eval pjoint-prototype --json`
    report["jacobian"]                             # NumPy arrays where pkm gives matrices
    at30 = prototype.at(theta=30)                  # the design at another pose (inverse kinematics)
    sweep = prototype.sweep("theta", np.linspace(-60, 60, 1001))
    sweep["d"], sweep["singularity"]               # one NumPy array per CSV column

    moma = pkmstudio.load("moma-3a")
    det = moma.map("det", grid=1000)               # as `pkm map moma-3a --quantity det --grid 1000`
    det.values                                     # float32 rows × columns, no copy; NaN outside
    # matplotlib: plt.imshow(det.values, origin="lower", extent=det.extent)

    wider = moma.with_parameters(l1=210)           # a new design; ValueError for a bad value
    wider.workspace(grid=400).summary["area"]      # as `pkm workspace … --json`

Errors: a bad parameter value, an unknown name or a bad option raises ValueError with the
command line's message; a pose out of range, unreachable or singular raises NoSolution (a
ValueError); a design file that cannot be written raises OSError.
"""

from __future__ import annotations

import json as _json
from typing import Any, Iterable, Optional, Sequence

import numpy as _np

from . import _core
from ._core import Design, Map, NoSolution, Pose, Workspace, kinds, presets

__version__: str = _core.__version__
__all__ = ["Design", "Map", "NoSolution", "Pose", "Workspace", "kinds", "load", "presets"]


def load(preset_or_path: str) -> Design:
    """Loads a preset (by its id: see presets()) or a .pkm.json design file."""
    return Design.load(str(preset_or_path))


def _numeric(value: Any) -> bool:
    return value is None or (isinstance(value, (int, float)) and not isinstance(value, bool))


def _as_array(value: Any) -> Any:
    """A JSON vector or matrix of numbers as a float64 array (null → NaN); anything else as is."""
    if not isinstance(value, list) or not value:
        return value
    if all(_numeric(v) for v in value) or all(
        isinstance(row, list) and row and all(_numeric(v) for v in row) for row in value
    ):
        return _np.array(value, dtype=float)
    return value


def _evaluate(self: Design, pose: Any = None, *, all_modes: bool = False, equations: bool = False) -> dict:
    """The report of a pose: the groups and keys of `pkm eval --json`, in its order.

    pose: None (the design's pose), a Pose of this design, or a dict of pose variables
    (solved as solve() solves them). Matrices and vectors of the pose, jacobian, derived and
    capability groups are NumPy float arrays, with NaN where pkm writes null; a scalar that
    is not finite at this pose is None, and report["singularity"]["undefined"] says which
    and why. all_modes adds "assembly_modes", equations the governing equations.
    """
    report = _json.loads(self._eval_json(pose, all_modes, equations))
    for group in ("pose", "jacobian", "derived", "capability"):
        values = report.get(group)
        if isinstance(values, dict):
            for key, value in values.items():
                values[key] = _as_array(value)
    return report


def _sweep(self: Design, var: str, values: Iterable[float]) -> dict:
    """The design at each of `values` of one pose variable or parameter (display units).

    Returns {column: NumPy array}, the columns of `pkm sweep --csv` (a matrix M gives columns
    "M[i][j]"), NaN where the CSV leaves a field empty; "singularity" is an array of the
    class names. Every step is solved from the previous one in C++, as `pkm sweep` does;
    a step without a solution raises NoSolution naming it. The arrays share one buffer.
    """
    names, table, singularity = self._sweep(var, _np.asarray(values, dtype=float))
    columns = {name: table[i] for i, name in enumerate(names)}
    labels = _np.asarray(_core.singularity_names())
    columns[names[singularity]] = labels[table[singularity].astype(_np.intp)]
    return columns


def _map(self: Design, quantity: Optional[str] = None, grid: int = 400, require: Sequence[str] = ()) -> Map:
    """A map over the workspace, as `pkm map --quantity QUANTITY --grid GRID [--require …]`.

    quantity: "det" (the default; "spec" when only `require` is given), "cond", "range" (a platform that turns), "force_worst", "speed_worst",
    "resolution_worst", "stiffness_worst" or "spec" (where every requirement holds).
    grid: cells along the longer side of the workspace (10 … 4000). require: texts such as
    "force_worst>=50", as --require takes them. The Map's values share its memory.
    """
    return _core._map(self, quantity, int(grid), list(require))


def _workspace(self: Design, grid: int = 400, require: Sequence[str] = ()) -> Workspace:
    """The reachable workspace, as `pkm workspace --grid GRID --json`: see Workspace.summary."""
    return _core._workspace(self, int(grid), list(require))


def _show(self: Design) -> dict:
    """The design's parameters, variables and ranges, as `pkm show --json`."""
    return _json.loads(self._show_json())


def _summary(self: Workspace) -> dict:
    """What `pkm workspace --json` prints: area (exact where known, with area_grid), bounds,
    grid, modes, exact_areas, specification …"""
    return _json.loads(self._json)


Design.evaluate = _evaluate
Design.sweep = _sweep
Design.map = _map
Design.workspace = _workspace
Design.show = _show
Workspace.summary = property(_summary)
Workspace.area = property(lambda self: _summary(self)["area"], doc="The area, mm²: exact where it is known.")

# The types are the package's: help() and tracebacks name them pkmstudio.Design, not _core's.
for _type in (Design, Map, NoSolution, Pose, Workspace):
    _type.__module__ = __name__
del _type
