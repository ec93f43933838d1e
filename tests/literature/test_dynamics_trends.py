"""Trends the dynamic-model papers report (not single numbers).

Seed 003, part 7 sec. 5 (figs. 14-16): with a compound fault (ball + outer race, ER-16K),
the amplitudes of the defect lines grow with radial load (10-150 N), defect size
(0.6-1.5 mm) and speed (1550-1850 rpm), while the line frequencies stay put.
Seed 004 (table 2): the ball-defect line sits below the kinematic value, and nearer to it
at the larger load (the calibrated slip model of bearinglab.validation.seed004).
"""

import itertools
import math

import numpy as np
import pytest

from bearinglab.dynamics import Defect, simulate
from bearinglab.operating import OperatingCondition
from bearinglab.signal import envelope_spectrum
from bearinglab.validation.dynamics import ER16K
from bearinglab.validation.seed004 import SPEED, seed004_ball_line


def _bpfo_line(load=50.0, size=1.2e-3, rpm=1750.0):
    """Amplitude and frequency of the envelope line at BPFO (unfiltered envelope, so that
    every case is demodulated the same way)."""
    sim = simulate(
        ER16K,
        OperatingCondition(radial_load=load, shaft_speed=rpm * math.pi / 30),
        [Defect("ball", size), Defect("outer", size, 0.25e-3)],
        duration=1.0,
        sample_rate=20e3,
    )
    spec = envelope_spectrum(sim.signal.channels["acc_y"], 20e3, band=None)
    f0 = sim.kinematic.hz("bpfo")
    near = np.abs(spec.frequency - f0) < 0.02 * f0
    k = np.argmax(np.where(near, spec.amplitude, 0))
    return spec.amplitude[k], spec.frequency[k] / f0


@pytest.mark.parametrize(
    "name, cases",
    [
        ("load", [{"load": 10.0}, {"load": 50.0}, {"load": 150.0}]),
        ("defect size", [{"size": 0.6e-3}, {"size": 1.2e-3}, {"size": 1.5e-3}]),
        pytest.param(
            "speed",
            [{"rpm": 1550.0}, {"rpm": 1750.0}, {"rpm": 1850.0}],
            marks=pytest.mark.xfail(
                strict=True,
                reason=(
                    "not reproduced: our BPFO envelope line falls with speed (about 51, 42, "
                    "38 m/s^2 at 1550, 1750, 1850 rpm). With massless balls the drop into "
                    "the pit is fixed by geometry and the ball spends less time in it as "
                    "the speed rises; the paper's growth needs the ball inertia and impact "
                    "physics of a model with ball masses (the slip model has them)"
                ),
            ),
        ),
    ],
)
def test_seed003_compound_fault_lines_grow(name, cases):
    lines = [_bpfo_line(**c) for c in cases]
    amplitudes = [a for a, _ in lines]
    assert all(b > a for a, b in itertools.pairwise(amplitudes)), (name, amplitudes)
    assert all(abs(ratio - 1) < 0.01 for _, ratio in lines)  # the line does not move


def test_seed004_more_load_less_slip():
    kinematic = 93.40
    low, high = seed004_ball_line(500.0), seed004_ball_line(1000.0)
    assert low < high < kinematic


def test_seed004_slip_model_ball_line_in_the_envelope_spectrum():
    """Seed 004 fig. 7: the ball-defect line of the slip model, read off the envelope
    spectrum of a 1 s record (1 Hz bins) by the same diagnosis a measured signal gets,
    sits where the balls' mean spin speed puts it (2 BSF x spin ratio, within one bin)
    and below the kinematic 2 BSF = 186.8 Hz, whose nearest bin would be 187 Hz."""
    from bearinglab.diagnosis import analyze_signal, measured_ball_defect_frequency
    from bearinglab.validation.seed004 import DEFECT_WIDTH, SKF6205

    cond = OperatingCondition(radial_load=500.0, shaft_speed=SPEED)
    sim = simulate(
        SKF6205, cond, [Defect("ball", DEFECT_WIDTH)], model="slip", duration=1.0, sample_rate=20e3
    )
    diagnosis = analyze_signal(sim.signal, None, sim.kinematic)
    assert diagnosis.primary_fault == "ball"
    measured = measured_ball_defect_frequency(diagnosis.to_dict()["peaks"])
    kinematic = sim.kinematic.hz("ball_defect")
    assert measured == pytest.approx(kinematic * sim.spin_speed_ratio, abs=1.0)
    assert measured < round(kinematic)
