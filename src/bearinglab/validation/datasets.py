"""Defect-frequency tables of public bearing data sets.

- Case Western Reserve University Bearing Data Center, "Bearing information" page:
  drive-end 6205-2RS JEM SKF (ball 0.3126 in, pitch 1.537 in) and fan-end 6203-2RS JEM
  SKF (ball 0.2656 in, pitch 1.122 in); defect frequencies as multiples of running speed
  (inner ring, outer ring, cage train, rolling element). Its "rolling element" column
  is 2 x BSF. Ball counts (9 and 8) are not printed; they are the ones the multipliers fit.
- IMS/NASA prognostics data (Rexnord ZA-2115, 16 rollers per row, pitch 2.815 in,
  roller 0.331 in, contact angle 15.17 deg) at 2000 rpm: BPFO 236.4, BPFI 296.9,
  BSF 139.9, FTF 14.8 Hz as quoted with the data set from Qiu H. et al., J. Sound Vib.
  289 (2006) 1066-1090. Its BSF is 1 x BSF.
"""

from __future__ import annotations

import math

from ..kinematics import frequency_orders
from .case import Case

INCH = 25.4e-3


def _order(name: str, z: int, ball_in: float, pitch_in: float, angle_deg: float = 0.0):
    return lambda: float(
        frequency_orders(z, ball_in * INCH, pitch_in * INCH, math.radians(angle_deg))[name]
    )


def _at_rpm(order, rpm: float):
    return lambda: order() * rpm / 60


# The CWRU multipliers are printed to 4-5 significant figures and computed by CWRU from the
# printed inch values; 3e-4 relative covers the last printed digit (3.9874 vs 3.98768).
_CWRU_TOL = (3e-4, "printed to 4-5 significant figures from rounded inch dimensions")
CASES = []
for label, z, ball, pitch, table in (
    (
        "drive-end 6205-2RS",
        9,
        0.3126,
        1.537,
        {"bpfi": 5.4152, "bpfo": 3.5848, "ftf": 0.39828, "ball_defect": 4.7135},
    ),
    (
        "fan-end 6203-2RS",
        8,
        0.2656,
        1.122,
        {"bpfi": 4.9469, "bpfo": 3.0530, "ftf": 0.3817, "ball_defect": 3.9874},
    ),
):
    for name, value in table.items():
        CASES.append(
            Case(
                f"CWRU bearing data centre ({label})",
                f"{name.upper() if name != 'ball_defect' else 'rolling element (2xBSF)'} order",
                value,
                "x shaft",
                _order(name, z, ball, pitch),
                *_CWRU_TOL,
            )
        )

for name, value in (("bpfo", 236.4), ("bpfi", 296.9), ("bsf", 139.9), ("ftf", 14.8)):
    CASES.append(
        Case(
            "IMS/NASA bearing data (Rexnord ZA-2115, Qiu et al. 2006)",
            f"{name.upper()} at 2000 rpm",
            value,
            "Hz",
            _at_rpm(_order(name, 16, 0.331, 2.815, 15.17), 2000),
            # half a unit of the printed 0.1 Hz: 0.34 % of 14.8 Hz, 0.04 % of 139.9 Hz
            0.05 / value,
            "printed to 0.1 Hz",
        )
    )
