"""Seed 002 (Sun & An, J. East China Univ. Sci. Technol. 47(4) (2021) 494-503): a
deep-groove ball bearing with 3-D random raceway waviness radiates sound whose pressure
spectrum peaks at the ball-pass frequencies and their harmonics, and whose peak and RMS
pressure grow about linearly with the waviness amplitude.

The paper's bearing and surface parameters are not in the seed text; ours are chosen, not
fitted: the C&U 608 of seed 003 (catalogue estimate, 720 rpm, 50 N), random surfaces of
seed 002 eq. 6 on both raceways (RMS 0.1 and 0.2 um, correlation lengths 1.0 mm round and
0.5 mm across, seeds 1 and 2), four shaft revolutions (lines 3 Hz apart), at seed 003's
point A (10 mm from the centre, straight up). A line at a
random frequency would sit within one bin of a candidate about half the time, so eight
lines all matching by chance has odds of about 1 in 400.
On the inner race the ball-pass lines are carried round by the shaft, so they show as
k BPFI +- f_i sidebands too; that is the model's output, not a rule coded in.
"""

import functools

import numpy as np
import pytest

from bearinglab.catalog import bearing_from_designation
from bearinglab.imperfections import Imperfections, RandomSurface
from bearinglab.kinematics import defect_frequencies
from bearinglab.noise import SEED003_POINT_A, bearing_noise
from bearinglab.operating import OperatingCondition
from bearinglab.signal import find_peaks
from bearinglab.units import rpm_to_rad_s

BEARING, _ = bearing_from_designation("608")
CONDITION = OperatingCondition(radial_load=50.0, shaft_speed=rpm_to_rad_s(720.0))


@functools.cache
def _sound(amplitude):
    surfaces = [
        RandomSurface.for_bearing(BEARING, race, amplitude, 1.0e-3, 0.5e-3, seed=s)
        for race, s in (("inner", 1), ("outer", 2))
    ]
    return bearing_noise(
        BEARING,
        CONDITION,
        Imperfections(surfaces=surfaces),
        revolutions=4,
        points=4096,
        point=SEED003_POINT_A,
    ).sound


def test_pressure_peaks_sit_at_ball_pass_frequencies_and_harmonics():
    kin = defect_frequencies(BEARING, CONDITION.shaft_speed)
    bpfo, bpfi, shaft = kin.hz("bpfo"), kin.hz("bpfi"), kin.hz("shaft")
    sound = _sound(0.2e-6)
    spectrum = sound.spectrum(segment_length=sound.pressure().size)  # one segment: 3 Hz
    step = spectrum.frequency[1] - spectrum.frequency[0]
    top = spectrum.frequency[-1]
    candidates = np.array(
        [k * bpfo for k in range(1, int(top / bpfo) + 2)]
        + [k * bpfi + m * shaft for k in range(1, int(top / bpfi) + 2) for m in (-1, 0, 1)]
    )
    lines = find_peaks(spectrum, count=8, min_frequency=2.0)
    assert len(lines) == 8
    for line in lines:
        assert np.min(np.abs(candidates - line["frequency_hz"])) <= step, line


@pytest.mark.parametrize("measure", ["rms", "peak"])
def test_pressure_grows_linearly_with_waviness_amplitude(measure):
    def value(sound):
        p = sound.pressure("total")
        return sound.effective_pressure() if measure == "rms" else np.max(np.abs(p))

    ratio = value(_sound(0.2e-6)) / value(_sound(0.1e-6))
    assert ratio == pytest.approx(2.0, rel=0.1)
