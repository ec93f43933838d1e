"""ISO bearing families: which standard and which shipped table give their dimensions.

A family key is the series part of an ISO designation, as
:attr:`bearinglab.designation.Designation.series` gives it (``"62"`` of 6205, ``"NU22"``
of NU2210, ``"302"`` of 30205).  Radial bearings take their boundary dimensions from the
ISO 15 dimension plan (``iso15_radial.csv``) by dimension series; metric tapered roller
bearings from ISO 355 (``iso355_tapered.csv``) by series; single-direction thrust ball
bearings from ISO 104 (``iso104_thrust.csv``) by series.  Families listed here whose
dimension series has no rows in the shipped tables (needle rollers, thrust roller
bearings, spherical series 231/240/241 below 110 mm bore...) resolve to a
:class:`~bearinglab.errors.CatalogError` that says so.

The dimension series of each family is the one printed in maker catalogues (SKF, KOYO):
deep-groove 62 = 02, 60 = 10, 160 = 00, 618 = 18; self-aligning 12 = 02, 22 = 22;
angular contact 72 = 02; cylindrical NU2 = 02, NU22 = 22; spherical 222 = 22, 230 = 30.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

#: Shipped table of each standard.
TABLE_FILES = {
    "iso15": "iso15_radial.csv",
    "iso355": "iso355_tapered.csv",
    "iso104": "iso104_thrust.csv",
}
#: Standard named for each table.
STANDARDS = {"iso15": "ISO 15:2017", "iso355": "ISO 355:2019", "iso104": "ISO 104:2015"}


@dataclass(frozen=True)
class Family:
    """One ISO bearing family.

    Parameters
    ----------
    key : str
        Series key, e.g. ``"62"``, ``"NU22"``, ``"302"`` [-].
    bearing_type : str
        One of the designation reader's bearing types [-].
    dimension_series : str
        ISO two-digit dimension series (width or height digit, diameter digit) [-].
    table : str
        ``"iso15"``, ``"iso355"`` or ``"iso104"``: where the dimensions are [-].
    rows : int
        Number of rows of rolling elements [-].
    default_contact_angle : float or None
        Nominal contact angle used when the designation gives none [rad].
    """

    key: str
    bearing_type: str
    dimension_series: str
    table: str
    rows: int = 1
    default_contact_angle: float | None = None

    @property
    def standard(self) -> str:
        """The standard whose dimension plan holds the family [-]."""
        return STANDARDS[self.table]


def _families() -> dict[str, Family]:
    out: dict[str, Family] = {}

    def add(
        key: str,
        btype: str,
        dims: str,
        table: str = "iso15",
        rows: int = 1,
        angle_deg: float | None = None,
    ) -> None:
        angle = None if angle_deg is None else math.radians(angle_deg)
        out[key] = Family(key, btype, dims, table, rows, angle)

    for key, dims in (
        ("618", "18"),
        ("619", "19"),
        ("160", "00"),
        ("60", "10"),
        ("62", "02"),
        ("63", "03"),
        ("64", "04"),
        ("68", "18"),
        ("69", "19"),
    ):
        add(key, "radial_ball", dims, angle_deg=0.0)
    for key, dims in (("12", "02"), ("13", "03"), ("22", "22"), ("23", "23")):
        add(key, "self_aligning_ball", dims, rows=2)
    # Single-row angular contact: without a suffix the family default is the 40 deg
    # ("B") design, the standard SKF/FAG execution of the 72 and 73 series.
    for key, dims in (("70", "10"), ("72", "02"), ("73", "03"), ("718", "18"), ("719", "19")):
        add(key, "angular_contact_ball", dims, angle_deg=40.0)
    for key in ("32", "33"):
        add(key, "angular_contact_ball", key, rows=2, angle_deg=30.0)
    # Four-point contact (QJ): 35 deg nominal contact angle (SKF QJ series).
    for key, dims in (("QJ2", "02"), ("QJ3", "03")):
        add(key, "four_point_contact_ball", dims, angle_deg=35.0)
    for prefix in ("N", "NU", "NJ", "NUP", "NF"):
        for series, dims in (
            ("10", "10"),
            ("2", "02"),
            ("3", "03"),
            ("4", "04"),
            ("22", "22"),
            ("23", "23"),
        ):
            add(prefix + series, "cylindrical_roller", dims)
    add("NN30", "cylindrical_roller", "30", rows=2)
    for key, dims in (("NA48", "48"), ("NA49", "49"), ("NA69", "69")):
        add(key, "needle_roller", dims)
    for key, dims in (
        ("213", "03"),
        ("222", "22"),
        ("223", "23"),
        ("230", "30"),
        ("231", "31"),
        ("232", "32"),
        ("238", "38"),
        ("239", "39"),
        ("240", "40"),
        ("241", "41"),
        ("248", "48"),
        ("249", "49"),
    ):
        add(key, "spherical_roller", dims, rows=1 if key == "213" else 2)
    for key in ("302", "303", "313", "320", "322", "323", "329", "330", "331", "332"):
        add(key, "tapered_roller", key[1:], table="iso355")
    for key in ("511", "512", "513", "514"):
        add(key, "thrust_ball", key[1:], table="iso104", angle_deg=90.0)
    for key in ("811", "812", "292", "293", "294"):
        add(key, "thrust_roller", key[1:], table="iso104")
    return out


#: All families, by series key.
FAMILIES: dict[str, Family] = _families()


def families_table():
    """The family table as a pandas DataFrame (one row per family; contact angle in degrees).

    >>> families_table().set_index("family").loc["NU22", "dimension_series"]
    '22'
    """
    import pandas as pd

    rows = [
        {
            "family": f.key,
            "bearing_type": f.bearing_type,
            "dimension_series": f.dimension_series,
            "standard": f.standard,
            "table": TABLE_FILES[f.table],
            "rows": f.rows,
            "default_contact_angle_deg": (
                None
                if f.default_contact_angle is None
                else round(math.degrees(f.default_contact_angle), 6)
            ),
        }
        for f in FAMILIES.values()
    ]
    return pd.DataFrame(rows)
