"""Peak picking, matching to defect frequencies and diagnosis (bearinglab.signal.peaks)."""

from __future__ import annotations

import json

import numpy as np
import pytest

from bearinglab.errors import InputError
from bearinglab.signal import Spectrum, diagnose, find_peaks, match_peaks

# CWRU drive-end 6205 at 1797 rpm: orders 0.39828, 3.5848, 5.4152, 2 BSF 4.7135
SHAFT = 1797.0 / 60.0
FREQS = {"shaft": SHAFT, "ftf": 0.39828 * SHAFT, "bpfo": 3.5848 * SHAFT,
         "bpfi": 5.4152 * SHAFT, "bsf": 4.7135 / 2 * SHAFT, "ball_defect": 4.7135 * SHAFT}


def _spectrum(lines, noise=0.01, seed=0):
    """A 0.25 Hz-resolution spectrum: Rayleigh noise floor plus 3-bin lines."""
    f = np.arange(0.0, 1000.0, 0.25)
    a = noise * np.random.default_rng(seed).rayleigh(size=f.size)
    for freq, amp in lines:
        k = np.argmin(np.abs(f - freq))
        a[k - 1:k + 2] += amp * np.array([0.5, 1.0, 0.5])
    return Spectrum(f, a)


# ---------------------------------------------------------------- find_peaks

def test_find_peaks_picks_the_lines_above_the_floor():
    lines = [(107.4, 1.0), (214.8, 0.5), (322.2, 0.2), (600.0, 0.08)]
    peaks = find_peaks(_spectrum(lines), count=10)
    assert [p["frequency_hz"] for p in peaks] == pytest.approx([107.5, 214.75, 322.25, 600.0],
                                                                abs=0.25)
    assert [p["amplitude"] for p in peaks] == sorted((p["amplitude"] for p in peaks),
                                                     reverse=True)
    json.dumps(peaks)  # plain floats


def test_find_peaks_count_and_range():
    lines = [(107.4, 1.0), (214.8, 0.5), (322.2, 0.2), (600.0, 0.08)]
    s = _spectrum(lines)
    top = find_peaks(s, count=2)
    assert [p["frequency_hz"] for p in top] == pytest.approx([107.4, 214.8], abs=0.25)
    inside = find_peaks(s, min_frequency=150.0, max_frequency=400.0)
    assert [p["frequency_hz"] for p in inside] == pytest.approx([214.8, 322.2], abs=0.25)


def test_find_peaks_of_pure_noise_is_short():
    assert len(find_peaks(_spectrum([]), prominence=6.0)) <= 1


@pytest.mark.parametrize(("kwargs", "parameter"), [
    ({"count": 0}, "count"), ({"prominence": 0.0}, "prominence"),
    ({"min_frequency": 500.0, "max_frequency": 100.0}, "max_frequency"),
])
def test_find_peaks_bad_inputs(kwargs, parameter):
    with pytest.raises(InputError) as err:
        find_peaks(_spectrum([]), **kwargs)
    assert err.value.parameter == parameter


def test_find_peaks_bad_spectrum():
    with pytest.raises(InputError) as err:
        find_peaks((np.arange(10.0), np.ones(9)))
    assert err.value.parameter == "spectrum"


# ---------------------------------------------------------------- match_peaks

def test_bpfo_harmonic_is_labelled():
    m = match_peaks([(2 * FREQS["bpfo"] * 1.005, 1.0)], FREQS)
    assert (m[0]["matched"], m[0]["harmonic"]) == ("bpfo", 2)
    assert m[0]["deviation"] == pytest.approx(0.005)


def test_slipping_ball_line_needs_slip_tolerance():
    line = [{"frequency_hz": 0.936 * 2 * FREQS["bsf"], "amplitude": 0.4}]  # seed 004: 93.6 %
    assert (match_peaks(line, FREQS)[0]["matched"], match_peaks(line, FREQS)[0]["harmonic"]) \
        == ("ball_defect", 1)
    strict = match_peaks(line, FREQS, slip_tolerance=0.0)[0]
    assert strict["matched"] is None and strict["harmonic"] is None


def test_slip_window_is_one_sided():
    above = match_peaks([(1.05 * FREQS["bpfo"], 1.0)], {"bpfo": FREQS["bpfo"]})[0]
    below = match_peaks([(0.95 * FREQS["bpfo"], 1.0)], {"bpfo": FREQS["bpfo"]})[0]
    assert above["matched"] is None and below["matched"] == "bpfo"
    shaft = match_peaks([(0.95 * SHAFT, 1.0)], {"shaft": SHAFT})[0]
    assert shaft["matched"] is None  # the shaft does not slip


def test_nearest_candidate_then_lowest_harmonic_wins():
    # 2 x 50 = 100 (exact) beats 1 x 101 (1 % off); 2 bsf ties with 1 ball_defect
    m = match_peaks([(100.0, 1.0)], {"shaft": 50.0, "bpfo": 101.0})[0]
    assert (m["matched"], m["harmonic"]) == ("shaft", 2)
    m = match_peaks([(2 * FREQS["bsf"], 1.0)], FREQS)[0]
    assert (m["matched"], m["harmonic"]) == ("ball_defect", 1)


def test_inner_race_sidebands_around_the_observed_carrier():
    carrier = 0.99 * FREQS["bpfi"]  # slipped by 1 %
    peaks = [(carrier, 1.0), (carrier - SHAFT, 0.4), (carrier + SHAFT, 0.4),
             (carrier + 2 * SHAFT, 0.2)]
    m = match_peaks(peaks, FREQS)
    assert (m[0]["matched"], m[0]["harmonic"]) == ("bpfi", 1)
    assert [(p.get("sideband_of"), p.get("sideband_order")) for p in m[1:]] == [
        ("bpfi", -1), ("bpfi", 1), ("bpfi", 2)]
    assert all(p["matched"] is None and p["modulation"] == "shaft" for p in m[1:])
    plain = match_peaks(peaks, FREQS, sidebands=False)
    assert all("sideband_of" not in p for p in plain)
    orphans = match_peaks(peaks[1:], FREQS)  # no carrier line: no sidebands
    assert all("sideband_of" not in p for p in orphans)


def test_match_keeps_the_peak_keys_and_order():
    peaks = find_peaks(_spectrum([(FREQS["bpfo"], 1.0), (2 * FREQS["bpfo"], 0.6)]))
    m = match_peaks(peaks, FREQS)
    assert [p["frequency_hz"] for p in m] == [p["frequency_hz"] for p in peaks]
    assert all("prominence" in p for p in m)
    json.dumps(m)


@pytest.mark.parametrize(("kwargs", "parameter"), [
    ({"frequencies": {"bpfx": 100.0}}, "frequencies"),
    ({"frequencies": {}}, "frequencies"),
    ({"frequencies": {"bpfo": -1.0}}, "frequencies['bpfo']"),
    ({"harmonics": 0}, "harmonics"),
    ({"tolerance": 0.0}, "tolerance"),
    ({"slip_tolerance": -0.1}, "slip_tolerance"),
    ({"peaks": [(-5.0, 1.0)]}, "peaks"),
    ({"peaks": [{"amplitude": 1.0}]}, "peaks"),
])
def test_match_bad_inputs(kwargs, parameter):
    args = {"peaks": [(100.0, 1.0)], "frequencies": FREQS} | kwargs
    with pytest.raises(InputError) as err:
        match_peaks(**args)
    assert err.value.parameter == parameter


# ---------------------------------------------------------------- diagnose

def test_bpfo_series_is_an_outer_race_fault():
    # at the kinematic BPFO: with 1 % slip, 2 BPFO of this bearing is nearer to 3 BSF
    s = _spectrum([(SHAFT, 0.3)] + [(n * FREQS["bpfo"], 1.0 / n) for n in (1, 2, 3, 4)])
    d = diagnose(match_peaks(find_peaks(s), FREQS))
    assert d["likely_fault"] == "outer race"
    assert d["lines"]["outer race"] == 4
    assert d["scores"]["outer race"] > 0 and d["scores"]["inner race"] == 0
    assert "bpfo" in d["reason"]
    json.dumps(d)


def test_inner_race_with_sidebands():
    c = FREQS["bpfi"]
    s = _spectrum([(c, 1.0), (c - SHAFT, 0.4), (c + SHAFT, 0.4), (2 * c, 0.5)])
    assert diagnose(match_peaks(find_peaks(s), FREQS))["likely_fault"] == "inner race"


def test_compound_fault():
    s = _spectrum([(FREQS["bpfo"], 1.0), (2 * FREQS["bpfo"], 0.5),
                   (FREQS["bpfi"], 0.9), (2 * FREQS["bpfi"], 0.5)])
    d = diagnose(match_peaks(find_peaks(s), FREQS))
    assert d["likely_fault"] == "compound: outer race + inner race"


def test_shaft_lines_alone_are_no_fault():
    s = _spectrum([(n * SHAFT, 1.0 / n) for n in (1, 2, 3)])
    d = diagnose(match_peaks(find_peaks(s), FREQS))
    assert d["likely_fault"] is None
    assert "shaft" in d["reason"]


def test_one_line_is_not_enough():
    d = diagnose(match_peaks([(FREQS["bpfo"], 1.0)], FREQS))
    assert d["likely_fault"] is None and d["lines"]["outer race"] == 1
    assert diagnose(match_peaks([(FREQS["bpfo"], 1.0)], FREQS), min_lines=1)[
        "likely_fault"] == "outer race"


def test_diagnose_bad_inputs():
    with pytest.raises(InputError) as err:
        diagnose([], compound_ratio=0.0)
    assert err.value.parameter == "compound_ratio"
    with pytest.raises(InputError) as err:
        diagnose([{"frequency_hz": 1.0}])
    assert err.value.parameter == "matched_peaks"
