"""Seed 003, bearing friction: the coefficients of friction of Table III.

The compilation's friction section (an American Roller Bearing Company article in
translation) prints Table III, "bearing type / coefficient of friction mu" (seed lines
1087-1097); :func:`bearinglab.friction.friction_coefficient` must return each value as
printed. The section has no worked torque example, and no published worked example of the
SKF model was found in the stored sources (see tests/literature/test_friction_published.py),
so these are the friction cases.
"""

from __future__ import annotations

from functools import partial

from ..friction import friction_coefficient
from .case import Case

SOURCE = "seed 003 (bearing friction, Table III)"
#: (row as printed in the seed, friction type, value as printed)
TABLE_III = (
    ("Радиальный шарикоподшипник", "radial_ball", 0.0015),
    ("Радиально-упорный подшипник", "angular_contact_ball", 0.0020),
    ("Цилиндрический роликоподшипник, сепаратор", "cylindrical_roller", 0.0010),
    ("Цилиндрический роликоподшипник, полный комп.", "cylindrical_roller_full_complement", 0.0020),
    ("Конический роликоподшипник", "tapered_roller", 0.0020),
    ("Сферический роликовый подшипник", "spherical_roller", 0.0020),
    ("Шаровой упорный подшипник", "thrust_ball", 0.0015),
    ("Цилиндрический роликовый упорный подшипник", "cylindrical_roller_thrust", 0.0050),
    ("Конический роликовый упор, клетка", "tapered_roller_thrust", 0.0020),
    ("Конический роликовый упор, полный комп.", "tapered_roller_thrust_full_complement", 0.0050),
)

# The table is stored exactly as printed (four decimals): only floating-point round-off
# is allowed.
CASES = [
    Case(
        SOURCE,
        f"coefficient of friction, {kind} ({row})",
        value,
        "-",
        partial(friction_coefficient, kind),
        1e-12,
        "stored exactly as printed",
    )
    for row, kind, value in TABLE_III
]
