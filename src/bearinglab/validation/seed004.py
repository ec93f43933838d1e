"""Seed 004 (Hou et al. 2024): the SKF 6205 at 2400 rpm, its ball-defect lines with slip.

Hou X., Fan J., Ma J., Fu X., *J. Mech. Electr. Eng.* 41(2) (2024) 271-279.

Kinematic: eq. (25), f_bsf = d_m / (2 d_b) (1 - (d_b/d_m)^2) n_i / 60 (1 x BSF), with
d_m = 39 mm, d_b = 8 mm (table 1) gives 93.40 Hz (line 310 and table 2).

With slip (table 2): the simulated ball-defect line f_bsf is 87.41 Hz at 500 N (93.6 % of
kinematic) and 90.17 Hz at 1000 N (96.5 %); measured 87.06 and 89.97 Hz (table 3). Our
line is the slip model's spin ratio (from the balls' spin phases, the rate at which a
ball defect strikes the races, eqs. 18-19) times the kinematic 93.40 Hz.

The paper does not print several values its result depends on. We calibrated them on
the 500 N line within their literature ranges (:data:`CALIBRATION`; the study is
:func:`calibration_study`, ``python -m bearinglab.validation.seed004`` prints it) and
predict 1000 N. The ranges do not reach 93.6 % at 500 N, and no physical set gives the
paper's rise from 500 to 1000 N: see docs/capabilities/dynamics.md, "Seed 004: the
calibration".
"""

from __future__ import annotations

import dataclasses
import math
from functools import cache

from ..geometry import BallBearing
from ..kinematics import defect_frequencies
from ..operating import OperatingCondition
from .case import Case

# d 25 and D 52 mm from the seed's table 1; the width 15 mm is ISO 15's for a 6205
SKF6205 = BallBearing(
    ball_count=9,
    ball_diameter=8e-3,
    pitch_diameter=39e-3,
    bore=25e-3,
    outside_diameter=52e-3,
    width=15e-3,
    name="6205 (seed 004)",
)
SPEED = 2400 * math.pi / 30
#: seed 004's 1 deg defect read as the chord it subtends on the inner race, d_i sin(0.5 deg)
DEFECT_WIDTH = 30.6e-3 * math.sin(math.radians(0.5))

#: The unprinted values, calibrated on the 500 N line within their literature ranges. The
#: spin ratio falls monotonically as each of them rises, so the closest approach to the
#: paper's 93.6 % is every one at the top of its range:
#: - diametral clearance 20 um: the top of ISO 5753-1 group N (CN) for a 6205, 5-20 um
#:   (the paper names an SKF 6205 without a clearance suffix, so group N);
#: - cage_friction 0.3: the top of SlipParameters' range (lubricated pockets 0.05-0.2);
#: - spin drag on, oil_fraction 0.05: the top of Harris & Kotzalas' 1-5 % oil in the
#:   oil-air mixture of a jet- or grease-lubricated bearing.
CALIBRATION = {
    "diametral_clearance": 20e-6,
    "cage_friction": 0.3,
    "spin_drag": True,
    "oil_fraction": 0.05,
}
#: Paper's lines [Hz] (table 2) and its kinematic 1 x BSF.
PUBLISHED = {500.0: 87.41, 1000.0: 90.17}
KINEMATIC_HZ = 93.40


def calibrated(**changes):
    """(bearing, SlipParameters) of the calibration, with ``changes`` applied (names of
    SlipParameters fields, or ``diametral_clearance`` [m])."""
    from ..dynamics import SlipParameters

    values = {**CALIBRATION, **changes}
    bearing = dataclasses.replace(SKF6205, diametral_clearance=values.pop("diametral_clearance"))
    return bearing, SlipParameters(**values)


def ball_line_ratio(
    load: float,
    bearing=None,
    parameters=None,
    *,
    duration: float = 0.3,
    settle: float | None = None,
    sample_rate: float = 5e3,
):
    """Spin ratio of the seed-004 case at ``load`` [N] and the Simulation it came from
    (the record's halves check and warnings included)."""
    from ..dynamics import Defect, simulate

    bearing, parameters = (bearing, parameters) if bearing else calibrated()
    sim = simulate(
        bearing,
        OperatingCondition(radial_load=load, shaft_speed=SPEED),
        [Defect("ball", DEFECT_WIDTH)],
        model="slip",
        duration=duration,
        sample_rate=sample_rate,
        settle=settle,
        parameters=parameters,
    )
    return sim.spin_speed_ratio, sim


#: Settling of the validation runs [s]: with the cage friction at 0.3 the pocket forces
#: creep for about a second (time constant ~0.4 s) after the spins have settled, which
#: the default rule (a few cage turns, :func:`bearinglab.dynamics.slip.settle`) does not
#: wait for: at 500 N it stops after five turns, 1.7e-3 below the spin ratio after 1 s.
VALIDATION_SETTLE = 0.6


@cache
def seed004_ball_line(load: float) -> float:
    """Ball-defect line of the calibrated slip model at ``load`` [N] [Hz]: spin ratio x
    the kinematic 1 x BSF (0.6 s settle, 0.2 s record)."""
    ratio, sim = ball_line_ratio(load, duration=0.2, settle=VALIDATION_SETTLE)
    return ratio * sim.kinematic.hz("bsf")


#: One-at-a-time variations from the seed's defaults (zero clearance, cage_friction 0.1,
#: no spin drag), then the calibration, for :func:`calibration_study`.
STUDY = [
    (
        "seed defaults",
        {
            "diametral_clearance": 0.0,
            "cage_friction": 0.1,
            "spin_drag": False,
            "oil_fraction": 0.03,
        },
    ),
    (
        "cage_friction 0.2",
        {
            "diametral_clearance": 0.0,
            "cage_friction": 0.2,
            "spin_drag": False,
            "oil_fraction": 0.03,
        },
    ),
    (
        "cage_friction 0.3",
        {
            "diametral_clearance": 0.0,
            "cage_friction": 0.3,
            "spin_drag": False,
            "oil_fraction": 0.03,
        },
    ),
    (
        "spin drag, oil 3 %",
        {"diametral_clearance": 0.0, "cage_friction": 0.1, "spin_drag": True, "oil_fraction": 0.03},
    ),
    (
        "spin drag, oil 5 %",
        {"diametral_clearance": 0.0, "cage_friction": 0.1, "spin_drag": True, "oil_fraction": 0.05},
    ),
    (
        "clearance 5 um",
        {
            "diametral_clearance": 5e-6,
            "cage_friction": 0.1,
            "spin_drag": False,
            "oil_fraction": 0.03,
        },
    ),
    (
        "clearance 20 um",
        {
            "diametral_clearance": 20e-6,
            "cage_friction": 0.1,
            "spin_drag": False,
            "oil_fraction": 0.03,
        },
    ),
    ("calibration", {}),
    ("calibration, flow index 0.7", {"flow_index": 0.7}),
    ("calibration, Bair-Winer traction", {"traction": "bair_winer"}),
    ("calibration, pocket clearance 0.1 mm", {"pocket_clearance": 1e-4}),
    ("calibration, cage mass ratio 0.6", {"cage_mass_ratio": 0.6}),
    ("calibration, cage drag C_b x10", {"cage_drag_coefficient": 5e-2}),
    ("calibration, ball drag C_d 1.0", {"ball_drag_coefficient": 1.0}),
    ("calibration, no unbalance", {"unbalance": 0.0}),
]


def calibration_study(
    cases=STUDY, loads=(500.0, 1000.0), settle: float = 1.0, duration: float = 0.5
):
    """Spin ratios of the seed-004 case for each (label, changes) of ``cases`` at each
    load [N], after ``settle`` [s] (a fixed, long settle: the pocket forces creep for
    about a second when the cage friction is high), over ``duration`` [s]. Returns rows
    (label, {load: spin ratio}, {load: halves difference})."""
    rows = []
    for label, changes in cases:
        bearing, parameters = calibrated(**changes)
        ratios, halves = {}, {}
        for load in loads:
            ratio, sim = ball_line_ratio(
                load, bearing, parameters, duration=duration, settle=settle
            )
            ratios[load], halves[load] = ratio, sim.halves["difference"]
        rows.append((label, ratios, halves))
    return rows


_CALIBRATED = (
    "calibrated within the literature ranges (clearance 20 um, the top of ISO "
    "5753-1 group N; cage friction 0.3; spin drag with 5 % oil), the model's "
    "line at 500 N is 95.6-95.7 % of kinematic, not the paper's 93.6 %: with "
    "the printed limiting shear coefficient the races lock the loaded balls "
    "to rolling, and the spin is lost only in the unloaded zone, braked by "
    "pocket friction and drag against the weak traction of a ball held on the "
    "outer race by its centrifugal force alone. 93.6 % needs a cage friction "
    "near 0.47 or a clearance near 100 um"
)
_RISE = (
    "the line rises by about 0.7 Hz from 500 to 1000 N (paper 2.76): load acts only "
    "through the width of the load zone, which a clearance of 20 um changes little "
    "(the unloaded passage shortens by a few per cent); the paper's rise needs "
    "balls that slip in the load zone, which its own limiting shear coefficient "
    "0.0434 does not allow at these contact loads"
)

CASES = [
    Case(
        "seed 004 (6205, eq. 25)",
        "ball spin frequency 1xBSF at 2400 rpm",
        KINEMATIC_HZ,
        "Hz",
        lambda: defect_frequencies(SKF6205, SPEED).hz("bsf"),
        1e-4,
        "printed to 0.01 Hz: half a unit in the last place is 5e-5 relative",
    ),
    Case(
        "seed 004 (6205, table 2)",
        "simulated ball-defect line at 500 N, 2400 rpm (calibrated)",
        PUBLISHED[500.0],
        "Hz",
        lambda: seed004_ball_line(500.0),
        0.01,
        "1 %: the paper's simulated and measured lines differ by 0.4 %",
        known_failure=_CALIBRATED,
    ),
    Case(
        "seed 004 (6205, table 2)",
        "simulated ball-defect line at 1000 N, 2400 rpm (predicted from the 500 N calibration)",
        PUBLISHED[1000.0],
        "Hz",
        lambda: seed004_ball_line(1000.0),
        0.01,
        "1 %: the paper's simulated and measured lines differ by 0.2 %",
    ),
    Case(
        "seed 004 (6205, table 2)",
        "rise of the ball-defect line from 500 to 1000 N",
        PUBLISHED[1000.0] - PUBLISHED[500.0],
        "Hz",
        lambda: seed004_ball_line(1000.0) - seed004_ball_line(500.0),
        0.15,
        "15 %: the paper's measured rise (2.91 Hz, table 3) is 5 % above its simulated "
        "one; three times that",
        known_failure=_RISE,
    ),
]


if __name__ == "__main__":  # regenerate the table of docs/capabilities/dynamics.md
    print("| variant | 500 N | 1000 N | rise [Hz] |\n|---|---|---|---|")
    for label, ratios, _ in calibration_study():
        low, high = ratios[500.0], ratios[1000.0]
        print(f"| {label} | {low:.4f} | {high:.4f} | {(high - low) * KINEMATIC_HZ:.2f} |")
