"""Waviness selection rules, as they come out of the quasi-static orbit model.

The classic rules for the vibration a ball bearing's waviness excites (inner ring turning
at f_i, outer ring fixed, cage at f_c, balls spinning at f_b relative to the cage, Z
balls, q waves round the circumference, k = 1, 2, ...) are those of Wardle F. P.,
"Vibration forces produced by waviness of the rolling surfaces of thrust loaded ball
bearings, Part 1: Theory", Proc. IMechE Part C 202(C5), 1988, 305-312, and of Yhland E.,
"A linear theory of vibrations caused by ball bearings with form errors operating at
moderate speed", ASME J. Tribology 114, 1992, 348-359 (seed 002's ref. [1]):

- outer race, q = kZ +- 1: radial vibration at kZ f_c;
- outer race, q = kZ: axial vibration at kZ f_c, no radial vibration;
- inner race, q = kZ +- 1: radial vibration at kZ (f_i - f_c) +- f_i;
- inner race, q = kZ: axial vibration at kZ (f_i - f_c), no radial vibration;
- ball, q = 2k (even orders only): radial vibration at 2k f_b +- f_c.

Nothing here codes them in: each test runs ``inner_ring_orbit`` in time with one waviness
and finds the lines in the spectrum of the inner-ring centre displacement. The load case
makes the statements clean: an axial preload (20 N) with no radial load, so every ball is
loaded alike and a perfect bearing does not move radially at all (Wardle's thrust-loaded
bearing). Under a radial load, q = kZ also moves the ring radially (along the load) at
kZ f_c, since the load zone breaks the symmetry: the "axial only" rule is a statement
about a uniformly loaded ball set. Bearing: a 608 (Z = 7, seed 003's example) at 720 rpm.
Record: 8 shaft revolutions, 24 samples per revolution (resolution f_i / 8), Hann window.
"""

import math

import numpy as np
import pytest

from bearinglab.geometry import BallBearing
from bearinglab.imperfections import Imperfections, Waviness
from bearinglab.operating import OperatingCondition
from bearinglab.quasistatic.orbit import inner_ring_orbit

B608 = BallBearing(
    ball_count=7, ball_diameter=3.969e-3, pitch_diameter=15e-3, diametral_clearance=10e-6
)
PRELOAD = OperatingCondition(axial_load=20.0, shaft_speed=720 * math.pi / 30)
Z = B608.ball_count
AMPLITUDE = 0.1e-6


def run(waviness):
    """The orbit over 8 shaft revolutions and the kinematic frequencies it ran at: shaft
    f_i, cage f_c, ball spin f_b [Hz]."""
    orbit = inner_ring_orbit(
        B608, PRELOAD, imperfections=Imperfections([waviness]), revolutions=8, points=192
    )
    f = orbit.frequencies
    return orbit, {"i": f["shaft_hz"], "c": f["cage_hz"], "b": f["ball_spin_hz"]}


def spectrum(signal, time):
    """Single-sided amplitude spectrum (Hann window, amplitude-corrected, window-weighted
    mean removed) [m]."""
    window = np.hanning(len(signal))
    mean = np.sum(window * signal) / window.sum()
    amp = 2 * np.abs(np.fft.rfft((signal - mean) * window)) / window.sum()
    return np.fft.rfftfreq(len(signal), time[1] - time[0]), amp


def lines(signal, time, predicted):
    """Peak amplitude within 1.5 bins of each predicted frequency, the largest amplitude
    more than 3 bins from all of them (and from 0 Hz: the record is not periodic, the
    mean leaks into the first bins), and the largest overall."""
    f, amp = spectrum(signal, time)
    df = f[1]
    peaks = [float(amp[np.abs(f - f0) <= 1.5 * df].max()) for f0 in predicted]
    away = np.all([np.abs(f - f0) > 3 * df for f0 in [0.0, *predicted]], axis=0)
    return peaks, float(amp[away].max()), float(amp.max())


def assert_lines(signal, time, predicted, cleanliness=0.05):
    peaks, other, top = lines(signal, time, predicted)
    assert max(peaks) == pytest.approx(top)  # the strongest line is predicted
    assert min(peaks) > 0.3 * top  # every predicted line is there
    assert other < cleanliness * min(peaks), (peaks, other)  # nothing else of note


@pytest.mark.parametrize("k, sign", [(1, -1), (1, +1), (2, -1)])
def test_outer_race_q_kz_pm_1_gives_radial_lines_at_kz_fc(k, sign):
    orbit, f = run(Waviness("outer", k * Z + sign, AMPLITUDE))
    assert_lines(orbit.x, orbit.time, [k * Z * f["c"]])
    assert_lines(orbit.y, orbit.time, [k * Z * f["c"]])
    assert np.ptp(orbit.z) < 1e-3 * np.ptp(orbit.x)  # and hardly any axial motion


@pytest.mark.parametrize("k, sign", [(1, -1), (1, +1)])
def test_inner_race_q_kz_pm_1_gives_radial_lines_at_kz_fi_minus_fc_pm_fi(k, sign):
    orbit, f = run(Waviness("inner", k * Z + sign, AMPLITUDE))
    # q = kZ - 1 -> kZ (f_i - f_c) - f_i, q = kZ + 1 -> kZ (f_i - f_c) + f_i
    assert_lines(orbit.x, orbit.time, [k * Z * (f["i"] - f["c"]) + sign * f["i"]])


@pytest.mark.parametrize("race", ["outer", "inner"])
def test_q_equal_kz_moves_the_ring_axially_only(race):
    orbit, f = run(Waviness(race, Z, AMPLITUDE))
    base = Z * f["c"] if race == "outer" else Z * (f["i"] - f["c"])
    assert_lines(orbit.z, orbit.time, [base])
    # every ball meets the same phase of the waves at once: the ball set stays Z-fold
    # symmetric, so there is no radial line at all (zero to the solver's precision)
    assert np.max(np.hypot(orbit.x, orbit.y)) < 1e-6 * np.ptp(orbit.z)


@pytest.mark.parametrize("order", [2, 4])
def test_even_ball_waviness_gives_lines_at_2k_fb_pm_fc(order):
    # one wavy ball (a ball set whose balls all carry the same waves in the same phase
    # would keep the Z-fold symmetry and move the ring axially only)
    orbit, f = run(Waviness("ball", order, AMPLITUDE, ball=0))
    assert_lines(orbit.x, orbit.time, [order * f["b"] - f["c"], order * f["b"] + f["c"]])
    assert_lines(orbit.z, orbit.time, [order * f["b"]])  # its diameter pulses at 2k f_b


def test_odd_ball_waviness_does_not_move_the_ring():
    orbit, _ = run(Waviness("ball", 3, AMPLITUDE, ball=0))
    assert np.max(np.abs(orbit.x)) < 1e-15 and np.ptp(orbit.z) < 1e-15
    assert np.ptp(orbit.ball_radial_displacement[:, 0]) > 0.5 * AMPLITUDE  # the ball does
