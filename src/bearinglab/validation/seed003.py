"""Seed 003 (compilation), dynamic-model section: bearing ER-16K at 1750 rpm.

Inputs as printed there (lines 1266-1276): inner race 30.59 mm, outer race 46.47 mm,
pitch 38.51 mm, ball 7.94 mm, Z = 9; eq. (22) f_BPFO = 104.19 Hz, eq. (23) ball-defect
rate f_BPB = 135.5 Hz (2 x BSF). The measured lines (104.7 and 136.5 Hz) include slip
and are not kinematic predictions, so they are not cases here.
"""

from __future__ import annotations

import math

from ..geometry import BallBearing
from ..kinematics import defect_frequencies
from .case import Case

SOURCE = "seed 003 (ER-16K, eqs. 22-23)"
ER16K = BallBearing(ball_count=9, ball_diameter=7.94e-3, pitch_diameter=38.51e-3, name="ER-16K")
SPEED = 1750 * math.pi / 30

# The inputs are printed to 3-4 significant figures (7.94 mm, 38.51 mm): +-0.005 mm on the
# ball moves these lines by about 0.06 %; 0.1 % covers that and the printed rounding.
CASES = [
    Case(
        SOURCE,
        "BPFO at 1750 rpm",
        104.19,
        "Hz",
        lambda: defect_frequencies(ER16K, SPEED).hz("bpfo"),
        1e-3,
        "inputs printed to 3-4 significant figures",
    ),
    Case(
        SOURCE,
        "ball defect rate 2xBSF at 1750 rpm",
        135.5,
        "Hz",
        lambda: defect_frequencies(ER16K, SPEED).hz("ball_defect"),
        1e-3,
        "printed to 0.1 Hz; inputs printed to 3-4 significant figures",
    ),
]
