"""The diagnosis' fast paths against the plain computations they replace (2026-11-28,
branch diag-speed2): the same numbers, to the bit where the arithmetic is the same.
Cost: well under a second."""

import math

import numpy as np
import pytest

from bearinglab.diagnosis.chain import (
    chain_bounds,
    chain_counts,
    chain_logp,
    chain_steps,
    log_move,
    log_pair,
)


def _scan(rng, rows=40, lines=12):
    """A scan's bins (rising with the fundamental, some lines moving at each row) and
    its readable lines (some coming in and going out)."""
    index = np.cumsum(rng.integers(0, 2, size=(rows, lines)), axis=0) + np.arange(lines) * 50
    use = rng.random((rows, lines)) < 0.8
    return index, use


def _plain_chain_logp(log_t, chains):
    """The chain bound as it was computed before the counts (one level, np.unique)."""
    firsts = sum(1 for first, _, _ in chains if first >= 1)
    moves = np.concatenate([m for _, m, _ in chains])
    pairs = np.concatenate([p for _, _, p in chains])
    count = firsts + moves.size + pairs.size
    if not log_t < 0.0 or count == 0:
        return 0.0
    terms = [log_t + math.log(firsts)] if firsts else []
    for values, term in ((moves, log_move), (pairs, log_pair)):
        if values.size:
            unique, counts = np.unique(values, return_counts=True)
            terms += list(term(log_t, unique) + np.log(counts))
    return min(0.0, float(np.logaddexp.reduce(np.array(terms))), log_t + math.log(count))


@pytest.mark.parametrize("seed", range(5))
def test_chain_counts_are_the_steps_counted(seed):
    rng = np.random.default_rng(seed)
    index, use = _scan(rng)
    uses = np.stack([use, use & (rng.random(use.shape) < 0.7), use[:, ::-1]])
    firsts, moves, pairs = chain_counts(index, uses)
    steps = [chain_steps(index, u) for u in uses]
    assert firsts == sum(1 for f, _, _ in steps if f >= 1)
    all_moves = np.concatenate([m for _, m, _ in steps])
    all_pairs = np.concatenate([p for _, _, p in steps])
    assert moves.tolist() == np.bincount(all_moves, minlength=moves.size).tolist()
    assert pairs.tolist() == np.bincount(all_pairs, minlength=pairs.size).tolist()


@pytest.mark.parametrize("seed", range(5))
def test_chain_bounds_together_equal_each_alone(seed):
    rng = np.random.default_rng(10 + seed)
    index, use = _scan(rng)
    scans = [np.stack([use, use & (rng.random(use.shape) < 0.5)]), use[:7], use & False]
    levels = [math.log(1e-3), math.log(10 ** -rng.uniform(2, 30)), math.log(0.2)]
    counts = [chain_counts(index[: s.shape[-2]], s) for s in scans]
    together = chain_bounds(levels, counts)
    for level, scan, bound in zip(levels, scans, together, strict=True):
        chains = [
            chain_steps(index[: s.shape[0]], s) for s in np.reshape(scan, (-1, *scan.shape[-2:]))
        ]
        assert bound == _plain_chain_logp(level, chains)  # to the bit
        assert bound == chain_logp(level, chains)
    # far beyond any level: the count of tests (Bonferroni)
    far = chain_bounds([-700.0], counts[:1])[0]
    assert far == pytest.approx(
        -700.0 + math.log(counts[0][0] + counts[0][1].sum() + counts[0][2].sum())
    )


@pytest.mark.parametrize("n", [4096, 4095])
def test_the_hann_power_from_the_record_spectrum_is_the_windowed_transform(n):
    from bearinglab.diagnosis.speed import hann_power

    rng = np.random.default_rng(n)
    t = np.arange(n) / 1000.0
    x = np.sin(2 * np.pi * 29.3 * t) + 0.1 * rng.standard_normal(n) + 3.0
    spectrum = np.fft.rfft(x - x.mean())
    fast = hann_power(x, n, 600, spectrum)
    plain = hann_power(x, n, 600)
    window = 0.5 - 0.5 * np.cos(2 * np.pi * np.arange(n) / n)
    assert fast.size == plain.size == 600
    assert np.allclose(plain, np.abs(np.fft.rfft((x - x.mean()) * window)[:600]) ** 2)
    assert np.allclose(fast, plain, rtol=1e-9, atol=1e-12 * plain.max())


def test_the_prewhitening_and_the_speed_reuse_the_record_spectrum():
    from bearinglab.diagnosis.speed import shaft_frequency
    from bearinglab.signal.preprocess import prewhitened

    rng = np.random.default_rng(3)
    fs, n = 4000.0, 16000
    t = np.arange(n) / fs
    x = sum(np.sin(2 * np.pi * k * 24.7 * t) / k for k in (1, 2, 3)) + rng.standard_normal(n)
    spectrum = np.fft.rfft(x - x.mean())
    kept = spectrum.copy()
    y, whitened = prewhitened(x, spectrum)
    y0, whitened0 = prewhitened(x)
    assert np.array_equal(y, y0) and np.array_equal(whitened, whitened0)
    assert np.array_equal(spectrum, kept)  # not changed
    fast = shaft_frequency(x, fs, 23.0, 26.0, spectrum=spectrum)
    plain = shaft_frequency(x, fs, 23.0, 26.0)
    assert fast.frequency == pytest.approx(plain.frequency, rel=1e-12)
    assert fast.p_value == pytest.approx(plain.p_value, rel=1e-9)


def test_the_raw_envelope_reuses_the_record_spectrum():
    from bearinglab.diagnosis.methods import method_spectrum

    x = np.random.default_rng(4).standard_normal(16000)
    fast = method_spectrum("raw", x, 4000.0, 2.0, spectrum=np.fft.rfft(x - x.mean()))
    plain = method_spectrum("raw", x, 4000.0, 2.0)
    assert np.allclose(fast.power, plain.power, rtol=1e-12, atol=0.0)
    assert np.allclose(fast.envelope, plain.envelope, rtol=1e-12, atol=1e-12)


@pytest.mark.parametrize("designation", ["6205-2RS", "6203", "6310", "61800"])
def test_the_ball_series_constant_is_the_two_contacts_computed_alone(designation):
    from bearinglab.catalog import bearing_from_designation
    from bearinglab.contact import hertz
    from bearinglab.diagnosis.spall import ball_series_constant
    from bearinglab.materials import effective_modulus

    bearing = bearing_from_designation(designation)[0]
    e = effective_modulus(bearing.ball_material, bearing.ring_material)
    inner = hertz.load_deflection_constant(*bearing.contact_radii("inner"), e)
    outer = hertz.load_deflection_constant(*bearing.contact_radii("outer"), e)
    assert ball_series_constant(bearing) == float(hertz.series_constant(inner, outer))


def test_refine_peaks_is_refine_peak_row_by_row():
    from bearinglab.diagnosis.events import refine_peak, refine_peaks

    rng = np.random.default_rng(7)
    rows = rng.random((200, 31))
    rows[5] = 1.0  # flat: no parabola
    i = rng.integers(0, 31, size=200)
    i[:3] = (0, 30, 15)  # the ends are not refined
    out = refine_peaks(rows, i)
    assert out.tolist() == [refine_peak(row, int(j)) for row, j in zip(rows, i, strict=True)]


def test_the_bridged_widths_are_each_load_alone():
    from bearinglab.catalog import bearing_from_designation
    from bearinglab.diagnosis.spall import bridged_width, bridged_widths

    bearing = bearing_from_designation("6205-2RS")[0]
    loads = (443.6, 140.0, 1400.0)
    for race in ("inner", "outer"):
        together = bridged_widths(bearing, race, loads)
        assert together == [bridged_width(bearing, race, load) for load in loads]


def _plain_free_count(zmax, region, values, which, lo, hi, ref):
    """The free count as it was before the positions' screening: every own position of
    every row with lines compared with every line of it."""
    out = np.zeros(values.shape)
    r, j = np.nonzero(which)
    if r.size == 0:
        return out
    v = values[r, j]
    total = ref.size - np.searchsorted(ref, v, side="left")
    rows, back = np.unique(r, return_inverse=True)
    width = int(np.max(hi[rows] - lo[rows], initial=-1)) + 1
    if width > 0:
        at = lo[rows][:, :, None] + np.arange(width)[None, None, :]
        inside = at <= hi[rows][:, :, None]
        at = np.clip(at, 0, zmax.size - 1)
        own_z = np.where(inside & region[at], zmax[at], -np.inf).reshape(rows.size, -1)
        total = total - (own_z[back] >= v[:, None]).sum(axis=1)
    out[r, j] = total
    return out


@pytest.mark.parametrize("seed", range(6))
def test_the_free_count_is_the_plain_count(seed):
    from bearinglab.diagnosis.tail import _free_count

    rng = np.random.default_rng(100 + seed)
    size, rows, lines = 600, 30, 9
    zmax = np.round(rng.exponential(1.0, size), 1)  # ties between readings
    region = rng.random(size) < 0.9
    ref = np.sort(zmax[region])
    index = np.sort(rng.integers(0, size, size=(rows, lines)), axis=1)
    values = zmax[index]
    # merged intervals as tail.own_intervals makes them: sorted, apart, some empty
    lo = np.minimum(index, size - 1)
    hi = np.minimum(lo + rng.integers(-1, 20, size=lo.shape), size - 1)
    hi[:, :-1] = np.minimum(hi[:, :-1], lo[:, 1:] - 1)
    which = (values > np.quantile(ref, 0.7)) & (rng.random(values.shape) < 0.8)
    fast = _free_count(zmax, region, values, which, lo, hi, ref)
    assert np.array_equal(fast, _plain_free_count(zmax, region, values, which, lo, hi, ref))


def test_fisher_rows_of_stacked_templates_are_each_template_alone():
    from bearinglab.diagnosis.series import _fisher_rows

    rng = np.random.default_rng(11)
    logp = np.log(rng.random((40, 17)))
    uses = rng.random((3, 40, 17)) < 0.6
    uses[1, 5] = False  # a row with no line
    together = _fisher_rows(logp[None], uses)
    for d in range(3):
        assert np.array_equal(together[d], _fisher_rows(logp, uses[d]))


def test_own_intervals_sorted_by_one_flat_gather():
    from bearinglab.diagnosis.tail import OWN_BINS, own_intervals

    rng = np.random.default_rng(12)
    size = 400
    lo_h = np.maximum(np.arange(size) - rng.integers(0, 4, size), 0)
    hi_h = np.minimum(np.arange(size) + rng.integers(0, 4, size), size - 1)
    index = rng.integers(-3, size + 3, size=(25, 14))
    use = rng.random(index.shape) < 0.7
    lo, hi = own_intervals(index, use, (lo_h, hi_h), size)
    # as before: clipped, the unused empty, each row sorted by take_along_axis
    i = np.clip(index, 0, size - 1)
    a = np.clip(np.minimum(lo_h[i] - 1, index - OWN_BINS), 0, size - 1)
    b = np.clip(np.maximum(hi_h[i] + 1, index + OWN_BINS), 0, size - 1)
    a, b = np.where(use, a, size), np.where(use, b, -1)
    order = np.argsort(a, axis=1, kind="stable")
    a, b = np.take_along_axis(a, order, axis=1), np.take_along_axis(b, order, axis=1)
    reach = np.maximum.accumulate(b, axis=1)
    before = np.concatenate([np.full((b.shape[0], 1), -1), reach[:, :-1]], axis=1)
    assert np.array_equal(lo, np.maximum(a, before + 1)) and np.array_equal(hi, b)
