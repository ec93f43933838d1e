"""ISO 5753-1 radial internal clearance of deep-groove ball bearings, as maker catalogues print it.

The shipped table (``catalog/data/iso5753_radial_clearance.csv``) against the reprints of
the ISO 5753-1 table for deep-groove ball bearings with cylindrical bore it was checked on:

* NTN, "Ball and Roller Bearings", sec. 8 "Bearing internal clearance and preload",
  pp. A-58/A-59, radial internal clearance of deep groove ball bearings (copy read:
  scribd.com/document/174785772, "Clearance and Preload"): every row 2.5-140 mm;
* NSK, "Rolling Bearings" CAT. E1102m, Table 9.9 "Radial Internal Clearances in Deep
  Groove Ball Bearings" (nsk.com.br flipbook NSK_CAT_E1102m, page 42): rows up to 24 mm;
  NSK prints one row "up to 10 mm".

Values in micrometres, as printed.
"""

import pytest

from bearinglab.catalog import radial_clearance

UM = 1e-6
MM = 1e-3

# bore over, incl [mm], group, (min, max) [um] as printed
NTN_A59 = [
    (2.5, 6, "C2", (0, 7)),
    (2.5, 6, "CN", (2, 13)),
    (2.5, 6, "C3", (8, 23)),
    (6, 10, "C4", (14, 29)),
    (6, 10, "C5", (20, 37)),
    (10, 18, "CN", (3, 18)),
    (18, 24, "C3", (13, 28)),
    (24, 30, "CN", (5, 20)),  # 6205
    (24, 30, "C3", (13, 28)),
    (24, 30, "C4", (23, 41)),
    (30, 40, "C5", (40, 64)),
    (40, 50, "CN", (6, 23)),
    (50, 65, "C5", (55, 90)),
    (65, 80, "C3", (25, 51)),
    (80, 100, "C4", (53, 84)),
    (100, 120, "C2", (2, 20)),
    (100, 120, "CN", (15, 41)),
    (100, 120, "C5", (90, 140)),
    (120, 140, "C3", (41, 81)),
    (120, 140, "C5", (105, 160)),
]

# NSK Table 9.9: "up to 10 mm" (NTN splits it at 6 mm; the 6-10 row is the same), 10-18, 18-24
NSK_9_9 = [
    (10, {"C2": (0, 7), "CN": (2, 13), "C3": (8, 23), "C4": (14, 29), "C5": (20, 37)}),
    (18, {"C2": (0, 9), "CN": (3, 18), "C3": (11, 25), "C4": (18, 33), "C5": (25, 45)}),
    (24, {"C2": (0, 10), "CN": (5, 20), "C3": (13, 28), "C4": (20, 36), "C5": (28, 48)}),
]


def _um(bore_mm, group):
    low, high = radial_clearance(bore_mm * MM, group)
    return round(low / UM, 6), round(high / UM, 6)


@pytest.mark.parametrize("over,incl,group,printed", NTN_A59)
def test_ntn_ball_and_roller_bearings_a59(over, incl, group, printed):
    # both ends of the band and its middle give the printed row
    for bore in (over + 0.001, (over + incl) / 2, incl):
        assert _um(bore, group) == printed


@pytest.mark.parametrize("incl,printed", NSK_9_9)
def test_nsk_e1102m_table_9_9(incl, printed):
    for group, values in printed.items():
        assert _um(incl, group) == values


def test_6205_normal_clearance():
    # 6205 (d = 25 mm): Normal (CN) 5-20 um, C3 13-28 um -- NTN p. A-59 and the
    # ktaiballbearing.com reprint of the same table
    assert _um(25, "CN") == (5, 20)
    assert _um(25, "C3") == (13, 28)
