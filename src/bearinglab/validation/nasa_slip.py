"""Published slip (skidding) anchors from NASA, kept as targets the slip model cannot run.

Bamberger E. N., Zaretsky E. V., Signer H., *Effect of speed and load on ultra-high-speed
ball bearings*, NASA TN D-7870, January 1975 (its abstract, as on the report documentation
page of the scanned note and in library catalogue records): 120-mm-bore
angular-contact ball bearings at speeds to 25 000 rpm (3 million DN) under thrust loads
to 22 240 N; skidding "generally increasing with speed at a given load", the highest,
6 percent, at the highest speed, 25 000 rpm.

bearinglab's slip model (seed 004, :mod:`bearinglab.dynamics.slip`) is planar: deep-groove
bearings under radial load (it refuses contact angles above 1 deg), so it cannot run a
thrust-loaded angular-contact bearing, and the note's internal geometry (ball count and
size, groove radii, contact angle) is not in its abstract, the only part of it we have
read. The case is listed so that `bearinglab validate` shows the anchor and why it is not
computed; its value is NaN until both change.
"""

from __future__ import annotations

import math

from .case import Case


def _not_computed() -> float:
    """NaN: see the module docstring (model scope, geometry not read)."""
    return math.nan


CASES = [
    Case(
        "NASA TN D-7870 (Bamberger, Zaretsky & Signer 1975)",
        "highest skidding of a 120-mm-bore angular-contact ball bearing, 25 000 rpm",
        6.0,
        "%",
        _not_computed,
        0.5 / 6.0,
        "printed as a whole per cent: half a unit",
        known_failure="not computed: the slip model is planar (deep-groove bearings under "
        "radial load) and the note's bearing is an angular-contact bearing "
        "under thrust whose geometry its abstract does not give",
    ),
]
