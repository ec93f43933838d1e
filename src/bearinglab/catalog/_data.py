"""Loading of the shipped catalogue tables (``catalog/data/*.csv``).

Each CSV names its standard and source in ``# source:`` comment lines and holds lengths in
millimetres (clearance in micrometres, angles in degrees), as printed in the catalogues it
comes from; the functions here read them (with the standard csv module, so that a
look-up does not pay for importing pandas) and keep them in those units.  The conversion
to SI happens where a value leaves the catalogue (:mod:`.lookup`).
"""

from __future__ import annotations

import csv
from functools import cache
from importlib import resources

#: The shipped tables: file name -> (what it holds, string columns).
TABLES: dict[str, tuple[str, tuple[str, ...]]] = {
    "iso15_radial.csv": (
        "boundary dimensions of radial bearings by ISO 15 dimension series",
        ("dimension_series",),
    ),
    "iso355_tapered.csv": (
        "boundary dimensions of metric tapered roller bearings (ISO 355)",
        ("series",),
    ),
    "iso104_thrust.csv": (
        "boundary dimensions of single-direction thrust ball bearings (ISO 104)",
        ("series",),
    ),
    "internal_geometry.csv": (
        "published internal geometry of specific bearings",
        ("name", "designation", "source", "notes"),
    ),
    "roller_geometry.csv": (
        "published internal geometry of specific roller bearings",
        ("name", "designation", "bearing_type", "profile", "source", "notes"),
    ),
    "iso5753_radial_clearance.csv": (
        "deep-groove ball bearing radial clearance (ISO 5753-1)",
        ("group",),
    ),
}


def source_lines(name: str) -> list[str]:
    """The ``# source:`` lines of a shipped table, without the marker.

    Parameters
    ----------
    name : str
        File name in ``catalog/data``, one of :data:`TABLES` [-].

    Examples
    --------
    >>> source_lines("iso15_radial.csv")[0].startswith("ISO 15")
    True
    """
    text = resources.files(__package__).joinpath("data").joinpath(name).read_text(encoding="utf-8")
    return [
        line[len("# source:") :].strip()
        for line in text.splitlines()
        if line.startswith("# source:")
    ]


def _open(name: str):
    if name not in TABLES:
        raise KeyError(f"no shipped table {name!r}; known: {sorted(TABLES)}")
    return resources.files(__package__).joinpath("data").joinpath(name).open("r", encoding="utf-8")


@cache
def rows(name: str) -> tuple[dict, ...]:
    """The rows of one shipped table as dicts, in the units of the file (mm, um, deg).

    Text columns (:data:`TABLES`) are strings (``""`` when empty); the others are floats,
    or None for an empty cell.  Cached: do not modify the dicts.

    Parameters
    ----------
    name : str
        File name in ``catalog/data``, one of :data:`TABLES` [-].

    Examples
    --------
    >>> rows("iso104_thrust.csv")[0]["series"]
    '511'
    """
    text_cols = TABLES[name][1] if name in TABLES else ()
    with _open(name) as fh:
        reader = csv.DictReader(line for line in fh if not line.startswith("#"))
        return tuple(
            {
                k: (v if k in text_cols else (float(v) if v.strip() else None))
                for k, v in row.items()
            }
            for row in reader
        )


def read_table(name: str):
    """One shipped table as a pandas DataFrame, in the units of the file (mm, um, deg).

    Empty numeric cells become NaN; empty text cells become ``""``.

    Parameters
    ----------
    name : str
        File name in ``catalog/data``, one of :data:`TABLES` [-].

    Examples
    --------
    >>> t = read_table("iso104_thrust.csv")
    >>> float(t.query("series == '511' and bore_mm == 10")["height_mm"].iloc[0])
    9.0
    """
    import pandas as pd

    dtypes = {col: str for col in TABLES.get(name, ((), ()))[1]}
    with _open(name) as fh:
        frame = pd.read_csv(fh, comment="#", dtype=dtypes)
    for col in TABLES[name][1]:
        frame[col] = frame[col].fillna("")
    return frame
