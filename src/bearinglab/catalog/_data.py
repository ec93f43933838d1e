"""Loading of the shipped catalogue tables (``catalog/data/*.csv``).

Each CSV names its standard and source in ``# source:`` comment lines and holds lengths in
millimetres (clearance in micrometres, angles in degrees), as printed in the catalogues it
comes from; the functions here read them with pandas and keep them in those units.  The
conversion to SI happens where a value leaves the catalogue (:mod:`.lookup`).
"""

from __future__ import annotations

from functools import cache
from importlib import resources

import pandas as pd

#: The shipped tables: file name -> (what it holds, string columns).
TABLES: dict[str, tuple[str, tuple[str, ...]]] = {
    "iso15_radial.csv": ("boundary dimensions of radial bearings by ISO 15 dimension series",
                         ("dimension_series",)),
    "iso355_tapered.csv": ("boundary dimensions of metric tapered roller bearings (ISO 355)",
                           ("series",)),
    "iso104_thrust.csv": ("boundary dimensions of single-direction thrust ball bearings (ISO 104)",
                          ("series",)),
    "internal_geometry.csv": ("published internal geometry of specific bearings",
                              ("name", "designation", "source", "notes")),
    "iso5753_radial_clearance.csv": ("deep-groove ball bearing radial clearance (ISO 5753-1)",
                                     ("group",)),
}


def source_lines(name: str) -> list[str]:
    """The ``# source:`` lines of a shipped table, without the marker.

    Parameters
    ----------
    name : str
        File name in ``catalog/data``, one of :data:`TABLES` [-].

    >>> source_lines("iso15_radial.csv")[0].startswith("ISO 15")
    True
    """
    text = resources.files(__package__).joinpath("data").joinpath(name).read_text(encoding="utf-8")
    return [line[len("# source:"):].strip() for line in text.splitlines()
            if line.startswith("# source:")]


@cache
def _read(name: str) -> pd.DataFrame:
    if name not in TABLES:
        raise KeyError(f"no shipped table {name!r}; known: {sorted(TABLES)}")
    dtypes = {col: str for col in TABLES[name][1]}
    with resources.files(__package__).joinpath("data").joinpath(name).open("r", encoding="utf-8") as fh:
        frame = pd.read_csv(fh, comment="#", dtype=dtypes)
    for col in TABLES[name][1]:
        frame[col] = frame[col].fillna("")
    return frame


def read_table(name: str) -> pd.DataFrame:
    """A copy of one shipped table, in the units of the file (mm, um, deg).

    Empty numeric cells become NaN; empty text cells become ``""``.

    Parameters
    ----------
    name : str
        File name in ``catalog/data``, one of :data:`TABLES` [-].

    >>> t = read_table("iso104_thrust.csv")
    >>> float(t.query("series == '511' and bore_mm == 10")["height_mm"].iloc[0])
    9.0
    """
    return _read(name).copy()
