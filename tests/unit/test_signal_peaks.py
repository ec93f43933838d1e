"""Peak picking, matching to defect frequencies and diagnosis (bearinglab.signal.peaks)."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from bearinglab.catalog import bearing_from_designation
from bearinglab.errors import InputError
from bearinglab.kinematics import defect_frequencies
from bearinglab.signal import Spectrum, find_peaks, match_peaks

# CWRU drive-end 6205 at 1797 rpm: orders 0.39828, 3.5848, 5.4152, 2 BSF 4.7135
SHAFT = 1797.0 / 60.0
FREQS = {
    "shaft": SHAFT,
    "ftf": 0.39828 * SHAFT,
    "bpfo": 3.5848 * SHAFT,
    "bpfi": 5.4152 * SHAFT,
    "bsf": 4.7135 / 2 * SHAFT,
    "ball_defect": 4.7135 * SHAFT,
}


# ER-16K at 1750 rpm (seed 003): BPFO 104.19, BPFI 158.31, ball defect 135.45, FTF 11.58 Hz.
# BPFI lies 0.2 % from ball defect + 2 FTF, 6 BPFO 1.3 % below 4 BPFI, 3 BPFO 1.3 % below 2 BPFI.
_ER16K = defect_frequencies(bearing_from_designation("ER-16K")[0], 1750 * math.pi / 30)
ER16K = {name: _ER16K.hz(name) for name in FREQS}


def _labels(matched):
    return [
        (p["matched"], p["harmonic"])
        if p["matched"]
        else (p.get("sideband_of"), p.get("sideband_order"))
        for p in matched
    ]


def _spectrum(lines, noise=0.01, seed=0):
    """A 0.25 Hz-resolution spectrum: Rayleigh noise floor plus 3-bin lines."""
    f = np.arange(0.0, 1000.0, 0.25)
    a = noise * np.random.default_rng(seed).rayleigh(size=f.size)
    for freq, amp in lines:
        k = np.argmin(np.abs(f - freq))
        a[k - 1 : k + 2] += amp * np.array([0.5, 1.0, 0.5])
    return Spectrum(f, a)


# ---------------------------------------------------------------- find_peaks


def test_find_peaks_picks_the_lines_above_the_floor():
    lines = [(107.4, 1.0), (214.8, 0.5), (322.2, 0.2), (600.0, 0.08)]
    peaks = find_peaks(_spectrum(lines), count=10)
    assert [p["frequency_hz"] for p in peaks] == pytest.approx(
        [107.5, 214.75, 322.25, 600.0], abs=0.25
    )
    assert [p["amplitude"] for p in peaks] == sorted((p["amplitude"] for p in peaks), reverse=True)
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


@pytest.mark.parametrize(
    ("kwargs", "parameter"),
    [
        ({"count": 0}, "count"),
        ({"prominence": 0.0}, "prominence"),
        ({"min_frequency": 500.0, "max_frequency": 100.0}, "max_frequency"),
    ],
)
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
    assert (match_peaks(line, FREQS)[0]["matched"], match_peaks(line, FREQS)[0]["harmonic"]) == (
        "ball_defect",
        1,
    )
    strict = match_peaks(line, FREQS, slip_tolerance=0.0)[0]
    assert strict["matched"] is None and strict["harmonic"] is None


def test_slip_window_is_one_sided():
    above = match_peaks([(1.05 * FREQS["bpfo"], 1.0)], {"bpfo": FREQS["bpfo"]})[0]
    below = match_peaks([(0.95 * FREQS["bpfo"], 1.0)], {"bpfo": FREQS["bpfo"]})[0]
    assert above["matched"] is None and below["matched"] == "bpfo"
    shaft = match_peaks([(0.95 * SHAFT, 1.0)], {"shaft": SHAFT})[0]
    assert shaft["matched"] is None  # the shaft does not slip


def test_candidate_choice_family_then_distance_then_order():
    # alone, 100 Hz is BPFO 1 % slow rather than a lone 2x shaft (no 50 Hz line) ...
    m = match_peaks([(100.0, 1.0)], {"shaft": 50.0, "bpfo": 101.0})[0]
    assert (m["matched"], m["harmonic"]) == ("bpfo", 1)
    # ... but with a stronger 50 Hz line both families are present, and 2 x 50 is exact
    m = match_peaks([(50.0, 2.0), (100.0, 1.0)], {"shaft": 50.0, "bpfo": 101.0})[1]
    assert (m["matched"], m["harmonic"]) == ("shaft", 2)
    # 2 bsf ties with 1 ball_defect: the lower order wins
    m = match_peaks([(2 * FREQS["bsf"], 1.0)], FREQS)[0]
    assert (m["matched"], m["harmonic"]) == ("ball_defect", 1)


def test_bpfo_series_keeps_its_high_harmonics():
    # issue: 6 x BPFO (625.1 Hz) sits 1.3 % below 4 x BPFI and took its label; 3 x BPFO
    # likewise 2 x BPFI once the BPFO line slips 1 %
    for slip in (1.0, 0.99):
        lines = [(n * slip * ER16K["bpfo"], 1.0 / n) for n in range(1, 9)]
        m = match_peaks(lines, ER16K, harmonics=8)
        assert _labels(m) == [("bpfo", n) for n in range(1, 9)], slip
    # a lone line 0.6 % above 6 BPFO is 0.7 % below 4 BPFI: relatively nearer to 6 BPFO,
    # but nearer to 4 BPFI in units of the fundamental (4 x 0.7 % < 6 x 0.6 %)
    m = match_peaks([(1.006 * 6 * ER16K["bpfo"], 1.0)], ER16K, harmonics=8)
    assert _labels(m) == [("bpfi", 4)] and m[0]["deviation"] == pytest.approx(-0.0068, abs=1e-4)


def test_one_slip_per_family():
    # the strongest BPFI line is at the kinematic value: a weaker line 7 % below 2 BPFI
    # (inside the slip window) cannot be its 2nd harmonic
    lines = [(ER16K["bpfi"], 1.0), (0.93 * 2 * ER16K["bpfi"], 0.5)]
    assert _labels(match_peaks(lines, ER16K))[1] != ("bpfi", 2)
    lines = [(0.95 * ER16K["bpfi"], 1.0), (0.95 * 2 * ER16K["bpfi"], 0.5)]  # same slip
    assert _labels(match_peaks(lines, ER16K)) == [("bpfi", 1), ("bpfi", 2)]


def test_a_weak_line_does_not_claim_a_stronger_harmonic():
    # issue: a strong BPFI line (1 % slow) sat nearer to ball defect + 2 FTF of a weaker
    # ball line than to BPFI, and became its sideband (and 2 BPFI became 3 BPFO)
    s = 0.99
    lines = [
        (s * ER16K["bpfi"], 1.0),
        (2 * s * ER16K["bpfi"], 0.5),
        (s * ER16K["ball_defect"], 0.3),
        (2 * s * ER16K["ball_defect"], 0.2),
        (s * ER16K["ball_defect"] - ER16K["ftf"], 0.1),
    ]
    assert _labels(match_peaks(lines, ER16K)) == [
        ("bpfi", 1),
        ("bpfi", 2),
        ("ball_defect", 1),
        ("ball_defect", 2),
        ("ball_defect", -1),
    ]


def test_a_sideband_may_outgrow_its_carrier_if_it_matches_nothing_well():
    # a cage-modulated ball defect: the -1 FTF sideband is stronger than the carrier
    ball = ER16K["ball_defect"]
    lines = [(ball - ER16K["ftf"], 1.0), (ball, 0.8), (ball + ER16K["ftf"], 0.7)]
    assert _labels(match_peaks(lines, ER16K)) == [
        ("ball_defect", -1),
        ("ball_defect", 1),
        ("ball_defect", 1),
    ]


def test_resolution_widens_the_match_window():
    # issue: with 2 Hz bins (0.5 s) the FTF line (11.58 Hz) shows at 12 Hz, 3.6 % high,
    # outside the 2 % window; one bin of slack takes it
    f = np.arange(0.0, 200.0, 2.0)
    ftf_bin, ftf2_bin = (float(f[np.argmin(np.abs(f - k * ER16K["ftf"]))]) for k in (1, 2))
    lines = [(ftf_bin, 1.0), (ftf2_bin, 0.5)]
    assert _labels(match_peaks(lines, ER16K)) == [(None, None), (None, None)]
    assert _labels(match_peaks(lines, ER16K, resolution=2.0)) == [("ftf", 1), ("ftf", 2)]
    # the relative window still rules where it is wider than a bin
    m = match_peaks([(1.015 * ER16K["bpfi"], 1.0)], ER16K, resolution=0.1)
    assert _labels(m) == [("bpfi", 1)]


def test_inner_race_sidebands_around_the_observed_carrier():
    carrier = 0.99 * FREQS["bpfi"]  # slipped by 1 %
    peaks = [
        (carrier, 1.0),
        (carrier - SHAFT, 0.4),
        (carrier + SHAFT, 0.4),
        (carrier + 2 * SHAFT, 0.2),
    ]
    m = match_peaks(peaks, FREQS)
    assert (m[0]["matched"], m[0]["harmonic"]) == ("bpfi", 1)
    assert [(p.get("sideband_of"), p.get("sideband_order")) for p in m[1:]] == [
        ("bpfi", -1),
        ("bpfi", 1),
        ("bpfi", 2),
    ]
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


@pytest.mark.parametrize(
    ("kwargs", "parameter"),
    [
        ({"frequencies": {"bpfx": 100.0}}, "frequencies"),
        ({"frequencies": {}}, "frequencies"),
        ({"frequencies": {"bpfo": -1.0}}, "frequencies['bpfo']"),
        ({"harmonics": 0}, "harmonics"),
        ({"tolerance": 0.0}, "tolerance"),
        ({"slip_tolerance": -0.1}, "slip_tolerance"),
        ({"resolution": -0.5}, "resolution"),
        ({"peaks": [(-5.0, 1.0)]}, "peaks"),
        ({"peaks": [{"amplitude": 1.0}]}, "peaks"),
    ],
)
def test_match_bad_inputs(kwargs, parameter):
    args = {"peaks": [(100.0, 1.0)], "frequencies": FREQS} | kwargs
    with pytest.raises(InputError) as err:
        match_peaks(**args)
    assert err.value.parameter == parameter
