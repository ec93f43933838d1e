"""Waviness and ball-size errors in the dynamic models (issue 5, through the surface
table of issue 4): the classical selection rules must come out of the rigid-ring model.

Rules (Wardle, Proc. IMechE C 202 (1988) 305-312; Yhland, J. Tribol. 114 (1992)
348-359), Z balls, inner ring turning at f_i, cage at f_c, radial vibration only:
outer-race order q = kZ +- 1 -> k Z f_c; inner-race order q = kZ +- 1 ->
k Z (f_i - f_c) +- f_i; q = kZ -> no radial line (the balls move in and out together).
A preloaded bearing (negative clearance) without radial load keeps every ball in
contact, the condition the rules assume.
"""

import math

import numpy as np
import pytest
from conftest import simulate_seed004_slip

from bearinglab.dynamics import simulate
from bearinglab.geometry import BallBearing
from bearinglab.imperfections import BallSizeErrors, Imperfections, Waviness
from bearinglab.kinematics import defect_frequencies
from bearinglab.operating import OperatingCondition

PRELOADED = BallBearing(
    ball_count=9, ball_diameter=7.94e-3, pitch_diameter=38.51e-3, diametral_clearance=-10e-6
)
CONDITION = OperatingCondition(radial_load=0.0, shaft_speed=1750 * math.pi / 30)
RATE = 5000.0


def _spectrum(imperfections):
    sim = simulate(
        PRELOADED,
        CONDITION,
        (),
        imperfections=imperfections,
        duration=1.0,
        sample_rate=RATE,
        settle=0.2,
    )
    x = sim.signal.channels["disp_x"]
    x = x - x.mean()
    return np.fft.rfftfreq(x.size, 1 / RATE), np.abs(np.fft.rfft(x * np.hanning(x.size)))


def _line(freq, spec, f0):
    return spec[np.abs(freq - f0) <= 1.5].max()


def _rates():
    kin = defect_frequencies(PRELOADED, CONDITION.shaft_speed)
    return kin.hz("ftf"), CONDITION.shaft_speed / (2 * math.pi)


@pytest.mark.parametrize(
    "race, order, sign", [("outer", 8, 0), ("outer", 10, 0), ("inner", 8, -1), ("inner", 10, 1)]
)
def test_waviness_orders_z_pm_1_excite_the_predicted_radial_line(race, order, sign):
    f_c, f_i = _rates()
    target = 9 * f_c if race == "outer" else 9 * (f_i - f_c) + sign * f_i
    freq, spec = _spectrum(Imperfections([Waviness(race, order, 1e-6)]))
    line = _line(freq, spec, target)
    away = np.abs(freq - target) > 3
    assert line > 20 * spec[away & (freq > 5)].max()  # the one clear line


@pytest.mark.parametrize("race", ["outer", "inner"])
def test_waviness_order_z_gives_no_radial_line(race):
    moved = _spectrum(Imperfections([Waviness(race, 10, 1e-6)]))[1].max()
    still = _spectrum(Imperfections([Waviness(race, 9, 1e-6)]))[1].max()
    assert still < 1e-4 * moved


def test_a_ball_size_error_turns_with_the_cage():
    f_c, _ = _rates()
    errors = np.zeros(9)
    errors[2] = 2e-6
    freq, spec = _spectrum(Imperfections(ball_size_errors=BallSizeErrors(errors)))
    assert freq[np.argmax(spec)] == pytest.approx(f_c, abs=1.5)


def test_slip_model_takes_the_same_imperfections():
    runs = [
        simulate_seed004_slip(duration=0.005, sample_rate=20e3, settle=0.005, imperfections=imp)
        for imp in (None, Imperfections([Waviness("outer", 10, 2e-6)]))
    ]
    plain, wavy = (r.signal.channels["disp_y"] for r in runs)
    assert np.all(np.isfinite(wavy)) and np.ptp(wavy - plain) > 1e-7
