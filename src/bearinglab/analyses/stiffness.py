"""The stiffness analyses: the radial and axial stiffness and displacements of one load
case (``stiffness``, which a study runs as warm-started stiffness_map lines) and over a
grid of loads and speeds (``stiffness-map``, with :func:`grid` and its result
:class:`StiffnessMap`). Each builds the models from the request
(:mod:`bearinglab.inputs`) and calls :func:`bearinglab.quasistatic.study.stiffness_map`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..engine import reraise_interrupt
from ..errors import InputError
from ..inputs import INPUTS, bearing_from, bearing_warnings, condition_from, restate
from .base import BEARING_INPUTS, FILES, LOADS, SPEED_AT_REST, Analysis, inputs, plot_file

# ------------------------------------------------------------------ stiffness over loads
_STIFFNESS_OUT = {
    "radial_displacement_um": "f",
    "axial_displacement_um": "f",
    "radial_stiffness_n_per_um": "f",
    "axial_stiffness_n_per_um": "f",
    "max_ball_load_n": "f",
    "max_roller_load_n": "f",
}


def _stiffness_line(case: dict, radial: list[float]) -> list:
    """One stiffness_map line: the cases' radial loads at one (bearing, axial load, speed,
    direction); results in the order of ``radial``."""
    from ..quasistatic.study import stiffness_map
    from .base import pick

    bearing, _ = bearing_from(case)
    condition_from(case)  # the checks of the loads and the speed
    table = stiffness_map(
        bearing,
        radial,
        [case.get("axial_load_n") or 0.0],
        [case.get("speed_rpm") or 0.0],
        radial_load_angle=math.radians(case.get("radial_load_angle_deg", -90.0)),
        workers=1,
        gyroscopic=bool(case.get("gyroscopic")),
        race_control=case.get("race_control") or "outer",
    )
    # stiffness_map returns the loads sorted: put the rows back in the cases' order
    order = np.argsort(np.asarray(radial, float), kind="stable")
    out: list = [None] * len(radial)
    for row, i in zip(table.to_dict(orient="records"), order, strict=True):
        if row["status"] == "ok":
            out[i] = pick(row, _STIFFNESS_OUT)
        else:
            out[i] = InputError(
                "radial_load_n", row["radial_load_n"], "a load the bearing carries", row["status"]
            )
    return out


@dataclass(frozen=True)
class _Row:
    """One stiffness case's columns, as a result."""

    row: dict

    def to_dict(self) -> dict:
        return dict(self.row)


def _stiffness(values: dict) -> _Row:
    result = _stiffness_line(values, [values.get("radial_load_n") or 0.0])[0]
    if isinstance(result, Exception):
        raise result
    return _Row(result)


def _stiffness_batch(cases: list[dict], seed: int) -> list:
    """Group a partition's cases into stiffness_map lines; a line that fails as a whole
    (a bad bearing, a negative load) is retried case by case so only bad cases fail."""
    lines: dict = {}
    for i, case in enumerate(cases):
        key = tuple((k, v) for k, v in case.items() if k not in ("case", "radial_load_n"))
        lines.setdefault(key, []).append(i)
    out: list = [None] * len(cases)
    for members in lines.values():
        first = cases[members[0]]
        try:
            results = _stiffness_line(first, [cases[i].get("radial_load_n", 0.0) for i in members])
        except Exception as exc:  # noqa: BLE001 - retried case by case below
            reraise_interrupt(exc)  # a Ctrl-C is no failed line
            results = []
            for i in members:
                try:
                    results.append(_stiffness(cases[i]).row)
                except Exception as exc:  # noqa: BLE001 - a failed case never stops a study
                    reraise_interrupt(exc)
                    results.append(exc)
        for i, r in zip(members, results, strict=True):
            out[i] = r
    return out


STIFFNESS = Analysis(
    "stiffness",
    "Radial and axial stiffness and displacements (stiffness_map lines, warm-started).",
    {
        **BEARING_INPUTS,
        **LOADS,
        **SPEED_AT_REST,
        **inputs("radial_load_angle_deg", "gyroscopic", "race_control"),
    },
    run=_stiffness,
    outputs=_STIFFNESS_OUT,
    largest=2000,
    batch=_stiffness_batch,
    warm=("bearinglab.quasistatic.study",),
)


# ------------------------------------------------------------------ stiffness map
#: Most cases of one stiffness map.
MAX_MAP_CASES = 1_000_000
#: The forms a grid of values is given in.
_GRID = "START:STOP:COUNT (COUNT 1..10000), a list A,B,C or one value"


def grid(name: str, text) -> np.ndarray:
    """The values of input ``name`` given as a grid ``text`` ('a:b:n': n values from a to
    b, 'a,b,c' or one value), each checked against the input's range in the table.

    >>> grid("speed_rpm", "0:3000:4").tolist()
    [0.0, 1000.0, 2000.0, 3000.0]
    """
    text = str(text)
    try:
        if ":" in text:
            a, b, n = text.split(":")
            if not 1 <= int(n) <= 10000:
                raise ValueError
            values = np.linspace(float(a), float(b), int(n))
        else:
            values = np.array([float(v) for v in text.split(",")])
    except ValueError:
        raise InputError(name, text, _GRID) from None
    for v in values:
        INPUTS[name].check(name, float(v))
    return values


@dataclass(frozen=True)
class StiffnessMap:
    """Stiffness and displacements over a grid of loads and speeds
    (:func:`bearinglab.quasistatic.study.stiffness_map`): the ``table`` (one row per case,
    ``status`` "ok", "no load" or why not), the ``bearing``, the request's
    ``designation`` and the ``warnings``."""

    table: object
    bearing: object
    designation: str | None = None
    warnings: tuple = field(default_factory=tuple)

    @property
    def solved(self):
        """The rows that solved."""
        return self.table[self.table["status"] == "ok"]

    def to_dict(self) -> dict:
        """The cases, how many solved, every row (non-finite values as null), warnings."""
        rows = [
            {
                k: (None if isinstance(v, float) and not math.isfinite(v) else v)
                for k, v in r.items()
            }
            for r in self.table.to_dict(orient="records")
        ]
        return {
            "designation": self.designation,
            "cases": len(rows),
            "solved": len(self.solved),
            "rows": rows,
            "warnings": list(self.warnings),
        }

    def to_pandas(self):
        """The table, one row per case."""
        return self.table

    def plot(self, ax=None):
        """C_r and C_a over the radial load, one line per (axial load, speed); (fig, axes)."""
        from ..plotting import stiffness_map_figure

        if not len(self.solved):
            raise InputError(
                "radial_load_n",
                None,
                "a map with at least one solved case to draw",
                "no case of the map solved, status: "
                + ", ".join(sorted(set(self.table["status"]))),
            )
        return stiffness_map_figure(self.solved, ax)


def stiffness_map_request(values: dict, progress=None) -> StiffnessMap:
    """The ``stiffness-map`` request: the stiffness over the grids ``radial_load_n``,
    ``axial_load_n`` and ``speed_rpm``, every value checked before any work;
    ``progress(done, total)`` in cases."""
    from ..quasistatic.study import stiffness_map

    radial, axial, speeds = (
        grid(n, values.get(n) if values.get(n) is not None else STIFFNESS_MAP.options[n].default)
        for n in ("radial_load_n", "axial_load_n", "speed_rpm")
    )
    total = len(radial) * len(axial) * len(speeds)
    if total > MAX_MAP_CASES:
        raise InputError(
            "radial_load_n",
            values.get("radial_load_n"),
            f"a grid of at most {MAX_MAP_CASES:g} cases in all (radial x axial x speed counts)",
        )
    workers = values.get("workers") or 0
    bearing, decoded = bearing_from(values)
    from ..quasistatic import check_speed

    try:  # every speed of the grid, before any work
        check_speed(bearing, float(np.max(speeds)) * math.pi / 30.0)
    except InputError as exc:
        raise restate(exc, values, STIFFNESS_MAP.options) from None
    table = stiffness_map(
        bearing,
        radial,
        axial,
        speeds,
        workers=workers or None,
        progress=progress,
        gyroscopic=bool(values.get("gyroscopic")),
        race_control=values.get("race_control") or "outer",
    )
    return StiffnessMap(
        table, bearing, values.get("designation"), tuple(bearing_warnings(bearing, decoded))
    )


STIFFNESS_MAP = Analysis(
    "stiffness-map",
    "Radial and axial stiffness over a grid of loads and speeds (stiffness_map).",
    {
        **BEARING_INPUTS,
        "radial_load_n": INPUTS["radial_load_n"].with_(
            kind="text",
            default="0:2000:21",
            help="Radial loads: START:STOP:COUNT, A,B,C or one value [N].",
        ),
        "axial_load_n": INPUTS["axial_load_n"].with_(
            kind="text", default="0", help="Axial loads [N], same forms."
        ),
        "speed_rpm": INPUTS["speed_rpm"].with_(
            kind="text", default="0", help="Speeds [rpm], same forms."
        ),
        **inputs("gyroscopic", "race_control"),
        "workers": INPUTS["workers"].with_(
            default=0, help="Worker processes (default 0: all cores).", low=0, high=64
        ),
    },
    run=stiffness_map_request,
    files={
        "output": FILES["output"].with_(help="Write the table to this CSV file."),
        **plot_file("the radial and axial stiffness over the radial load"),
    },
)
