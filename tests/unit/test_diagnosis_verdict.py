"""The verdict's rules and the family test's line accounting (fifth-session review)."""

import math

import numpy as np
import pytest

import bearinglab.diagnosis.verdict as verdict
from bearinglab.diagnosis.families import Family, families, tolerances
from bearinglab.diagnosis.series import LINE_BINS, Line, SeriesTest, series_test
from bearinglab.diagnosis.statistics import welch_dof

LN10 = math.log(10.0)


def _test(significance, harmonics, support):
    """A SeriesTest with these -log10 p-values (series, harmonics, without its strongest),
    its first harmonic shown (a fault's series shows one of its carriers)."""
    line = Line("harmonic", 1, 0, 100.0, 100.0, 10.0, -3 * LN10)
    return SeriesTest(
        -significance * LN10, -support * LN10, -harmonics * LN10, 100.0, 0.0, (line,), 10
    )


class _Spectrum:
    def __init__(self, method):
        self.method, self.resolution, self.z = method, 1.0, np.zeros(64)


def _decide(monkeypatch, rounds, fams, methods=("raw", "cpw")):
    """decide() on made-up tests: ``rounds`` is one {(method, family): SeriesTest} per round
    of the greedy verdict (the last repeats)."""
    calls = iter(range(100))

    def read_families(spectra, fams_left, *args, **kwargs):
        table = rounds[min(next(calls), len(rounds) - 1)]
        names = {f.name for f in fams_left}
        return {key: t for key, t in table.items() if key[1] in names}

    monkeypatch.setattr(verdict, "read_families", read_families)
    spectra = [_Spectrum(m) for m in methods]
    valid = {m: np.ones(64, bool) for m in methods}
    return verdict.decide(spectra, fams, valid, 50.0, 8, 0.01)


def test_a_family_passing_every_gate_by_one_method_is_not_dropped_for_another(monkeypatch):
    # raw is the more significant but fails the harmonic gate; cpw passes all three
    fams = [Family("outer_race", 20.0, 0.02, 0.02, 5.0, 2)]
    table = {("raw", "outer_race"): _test(9.0, 1.0, 8.0), ("cpw", "outer_race"): _test(6, 4, 5)}
    d = _decide(monkeypatch, [table], fams)
    assert d["faults"] == ["outer_race"]
    assert d["tests"]["outer_race"][0] == "cpw"
    # with no method passing, the most significant is reported (and nothing accepted)
    table[("cpw", "outer_race")] = _test(6.0, 1.0, 5.0)
    d = _decide(monkeypatch, [table], fams)
    assert d["faults"] == [] and d["tests"]["outer_race"][0] == "raw"


def _with_harmonics(test, shown):
    """``test`` with harmonics ``shown`` at 10^-3 (and the 2nd, if not shown, at 0.5)."""
    lines = tuple(
        Line("harmonic", n, 0, 100.0 * n, 100.0 * n, 5.0, math.log(1e-3 if n in shown else 0.5))
        for n in sorted(set(shown) | {2})
    )
    return SeriesTest(test.log_p, test.support_log_p, test.harmonic_log_p, 100.0, 0.0, lines, 10)


def test_a_second_fault_needs_two_harmonics_of_its_own(monkeypatch):
    # issue 27: MFPT inner-race files 4 and 6 got "compound: inner race + outer race"
    # from one BPFO harmonic (and its sidebands) beside the inner-race series
    fams = [
        Family("inner_race", 30.0, 0.02, 0.02, 5.0, 2),
        Family("outer_race", 20.0, 0.02, 0.02, 5.0, 2),
    ]
    first = {
        ("raw", "inner_race"): _with_harmonics(_test(12.0, 9.0, 8.0), (1, 2)),
        ("raw", "outer_race"): _with_harmonics(_test(5.0, 4.0, 3.0), (1,)),
    }
    second = {("raw", "outer_race"): first[("raw", "outer_race")]}
    d = _decide(monkeypatch, [first, second], fams, methods=("raw",))
    assert d["faults"] == ["inner_race"]
    # with two of its harmonics shown it is a compound fault
    second = {("raw", "outer_race"): _with_harmonics(_test(5.0, 4.0, 3.0), (1, 2))}
    d = _decide(monkeypatch, [first, second], fams, methods=("raw",))
    assert d["faults"] == ["inner_race", "outer_race"]


def test_a_first_fault_shows_one_of_its_harmonics(monkeypatch):
    # the drive-end outer-race series of CWRU 130 read on the fan-end channel for the
    # 6203 sat on its ball sidebands n (2 BSF) - n FTF: "ball" from sidebands alone
    fams = [Family("ball", 30.0, 0.07, 0.02, 2.0, 2)]
    table = {("raw", "ball"): _with_harmonics(_test(16.9, 5.4, 5.4), ())}
    assert _decide(monkeypatch, [table], fams, methods=("raw",))["faults"] == []
    table = {("raw", "ball"): _with_harmonics(_test(16.9, 5.4, 5.4), (2,))}
    assert _decide(monkeypatch, [table], fams, methods=("raw",))["faults"] == ["ball"]


def test_a_ball_beside_a_cage_series_is_read_before_the_cage_lines_are_masked(monkeypatch):
    fams = [
        Family("ball", 30.0, 0.07, 0.02, 2.0, 2),
        Family("cage", 2.0, 0.02, 0.02, None, 0),
    ]
    before = {("raw", "cage"): _test(5.0, 5.0, 4.0), ("raw", "ball"): _test(1.8, 0.5, 0.5)}
    # the cage's lines masked, the ball's reference shrinks or its lines go: 10^-0.3
    after = {("raw", "ball"): _test(0.3, 0.1, 0.1)}
    d = _decide(monkeypatch, [before, after], fams, methods=("raw",))
    assert d["faults"] == ["ball"] and d["modulation"] == ["cage"]
    assert d["tests"]["ball"][1].significance == pytest.approx(1.8)
    # a ball series short of BALL_GIVEN_CAGE (5 %) beside it: a cage fault
    before[("raw", "ball")] = _test(1.0, 0.5, 0.5)
    d = _decide(monkeypatch, [before, after], fams, methods=("raw",))
    assert d["faults"] == ["cage"]


def test_lines_reading_the_same_bins_are_counted_once():
    # sidebands at f/3: n f + 2 f_m and (n + 1) f - f_m fall on the same bin (as for the
    # BPFO of a 6203, 3.053 x shaft); one strong bin there must not count twice
    f, fm, res = 100.0, 100.0 / 3.0, 0.5
    z = np.ones(4000)
    z[round((f + 2 * fm) / res)] = 40.0
    test = series_test(z, res, 2.0, f, 0.0, 0.0, 6, 1500.0, fm, 2)
    read = sorted(round(line.expected_hz / res) for line in test.lines)
    assert all(b - a >= LINE_BINS for a, b in zip(read, read[1:], strict=False))
    expected = {(1, 2), (2, -1)}  # the same bin: the first in the template is kept
    kept = {(line.n, line.k) for line in test.lines} & expected
    assert kept == {(1, 2)}


def test_welch_degrees_of_freedom_match_a_monte_carlo():
    import scipy.signal

    rng = np.random.default_rng(1)
    n, nperseg = 2560, 256
    x = rng.standard_normal((3000, n))
    _, p = scipy.signal.welch(x, nperseg=nperseg, noverlap=128, window="hann", axis=-1)
    bins = p[:, 10:100]  # away from 0 Hz and Nyquist
    nu_mc = 2.0 * np.mean(bins) ** 2 / np.var(bins)
    assert welch_dof(nperseg, 128, n) == pytest.approx(nu_mc, rel=0.03)


def test_sidebands_are_spaced_by_the_rates_the_signal_shows():
    freqs = {"shaft": 30.0, "ftf": 12.0, "bpfo": 107.0, "bpfi": 162.0, "ball_defect": 141.0}
    rates = {"shaft": 29.7, "ftf": 11.88}
    by_name = {f.name: f for f in families(freqs, tolerances(), rates)}
    assert by_name["inner_race"].modulation == 29.7 and by_name["ball"].modulation == 11.88
    # the fundamentals stay at the speed given
    assert by_name["inner_race"].frequency == 162.0 and by_name["cage"].frequency == 12.0
    assert families(freqs, tolerances())[1].modulation == 30.0


def test_an_accepted_series_explains_its_harmonics_beyond_the_search_limit():
    # the tail's reference runs beyond the search limit: an accepted fault's higher
    # harmonics are masked there too, or they stand as clutter against a second fault
    lines = tuple(Line("harmonic", n, 0, 100.0 * n, 100.0 * n, 50.0, -20.0) for n in (1, 2, 3))
    test = SeriesTest(-50.0, -40.0, -45.0, 100.0, 0.0, lines, 10)
    near = verdict.explained(test, (29.0, 11.6))
    far = verdict.explained(test, (29.0, 11.6), 1000.0)
    assert 1000.0 not in near and {400.0, 1000.0} <= set(far)
    assert 1000.0 - 29.0 in far and 400.0 + 11.6 in far  # with their intermodulation
