"""Seed 004 (Hou et al. 2024): kinematic ball spin frequency of the SKF 6205 at 2400 rpm.

Eq. (25) there is f_bsf = d_m / (2 d_b) (1 - (d_b/d_m)^2) n_i / 60 (the 1 x BSF
convention), with d_m = 39 mm, d_b = 8 mm (its table of bearing parameters) giving
93.40 Hz (line 310 and the results table). The simulated and measured lines (87.41,
90.17, 87.06, 89.97 Hz) need the slip model and are not kinematic cases.
"""

from __future__ import annotations

import math

from ..geometry import BallBearing
from ..kinematics import defect_frequencies
from . import Case

# d 25 and D 52 mm from the seed's table 1; the width 15 mm is ISO 15's for a 6205
SKF6205 = BallBearing(ball_count=9, ball_diameter=8e-3, pitch_diameter=39e-3, bore=25e-3,
                      outside_diameter=52e-3, width=15e-3, name="6205 (seed 004)")

CASES = [
    Case("seed 004 (6205, eq. 25)", "ball spin frequency 1xBSF at 2400 rpm", 93.40, "Hz",
         lambda: defect_frequencies(SKF6205, 2400 * math.pi / 30).hz("bsf"), 1e-4,
         "printed to 0.01 Hz: half a unit in the last place is 5e-5 relative"),
]
