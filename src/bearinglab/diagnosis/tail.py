"""The line statistic: the p-value of a line read in an envelope spectrum, against the
same reading at the spectrum's own positions - its rank in the body, a fitted law in the
tail.

Layer 1 (NumPy and ``scipy.special``). A line expected at frequency f is read as the
largest normalised value z over the bin nearest f and its two neighbours (the line's own
width under a Hann window; :func:`bearinglab.diagnosis.statistics.normalised`). Its
p-value (:func:`tail_tables`, the diagnosis' reading, ``series_test(tail=True)`` of
:mod:`.series`) is its rank among the same reading at every position where a line may
stand, up to the reference's upper TAIL_Q, and beyond that a peaks-over-threshold law
fitted to the positions that are not the family's own lines at that fundamental - the
noise's exceedances, exponential with an estimated scale (their predictive, Lomax, law),
plus the record's clutter of discrete lines of other origin, counted. An empirical null
in the body, because the envelope spectrum of a real machine holds far more, and larger,
lines than the chi-square law of noise allows (on the healthy CWRU record 97 the
chi-square p-values put some family beyond 1e-900); a law in the tail, because the rank
alone floors at 1 / positions (10^-2.7 for a 6205 record): a line 20 times the floor
scored as one at 4 (issue 27). The reference runs beyond the search limit to
REFERENCE_POSITIONS positions where what lies beyond is no heavier than the family's own
region. The speed check and the stray-series search read the rank alone
(:func:`line_rank_logp`, ``tail=False``); :func:`line_logp` reads every bin of a record
against all its positions (the statistic's calibration).

Sources: the peaks-over-threshold model of the tail and the declustering of its
exceedances by runs (Coles S., An Introduction to Statistical Modeling of Extreme Values,
Springer 2001, ch. 4 and sec. 5.3.2); a tail law fitted beyond an empirical distribution
to read p-values smaller than its ranks can (Knijnenburg T. A. et al., "Fewer
permutations, more accurate P-values", Bioinformatics 25 (2009) i161-i168).
docs/capabilities/diagnosis.md says what was measured.
"""

from __future__ import annotations

import functools
import math

import numpy as np

#: Bins either side of each of a family's own lines left out of its reference [-].
OWN_BINS = 2
#: Fraction of the reference positions above the tail's threshold u [-].
TAIL_Q = 0.1
#: Level of the one-sided tests that keep the positions below the search limit as the
#: tail's reference alone, when they show more, or larger, exceedances than those above
#: it [-].
POOL_ALPHA = 0.05
#: Widest reach of a line's hill either side of its peak [bins].
HILL_BINS = 12
#: Positions of the tail's reference the analysis asks for (beyond the search limit
#: where the search range holds fewer), up to the anti-aliasing limit f_s / 2.56 [-]:
#: about 200 exceedances, so that the predictive law of the tail is within a factor 2 of
#: its exponential ten scales out.
REFERENCE_POSITIONS = 2000


def line_logp(
    zmax: np.ndarray,
    count: np.ndarray,
    top_bin: float,
    bottom_bin: float = 1.0,
    tail: bool = True,
) -> np.ndarray:
    """ln p of the reading ``zmax`` (largest z over three bins) at every bin, against the
    same reading at every valid position of the spectrum from ``bottom_bin`` (at least 1)
    to ``top_bin`` (:func:`reference_logp`, its rank alone unless ``tail``); 0 where no
    bin is valid. Each bin is read against all the positions, itself included: the
    calibration of the line statistic on records without a line (no candidate's own
    positions are left out; :func:`tail_tables` does that for a family's lines).

    The reference starts where a line may be sought (the analysis passes the lowest
    line of any family, about 0.98 FTF): below it the positions read the main lobe and
    first side lobes of the 0 Hz line (the envelope's mean, the largest value of every
    envelope spectrum), a place no bearing line can stand and which would otherwise
    count against every line of the record.
    """
    stop = int(min(top_bin, zmax.size - 1))
    start = int(min(max(math.floor(bottom_bin), 1), stop))
    live = count[start : stop + 1] > 0
    ref = zmax[start : stop + 1][live]
    above = np.zeros(zmax.size, bool)
    above[start : stop + 1] = live
    out = np.zeros(zmax.size)
    ok = count > 0
    out[ok] = reference_logp(ref, zmax[ok], tail, _cluster(zmax, above, ref))
    return out


def line_rank_logp(
    zmax: np.ndarray,
    count: np.ndarray,
    top_bin: float,
    values,
    index: np.ndarray,
    bottom_bin: float = 1.0,
) -> np.ndarray:
    """ln p (the rank alone, floored at 1 / positions) of lines read as ``values``
    (largest z over three bins, one row per candidate fundamental, at bins ``index``)
    against the same reading at every other valid position of the spectrum from
    ``bottom_bin`` (at least 1) to ``top_bin``: the empirical null
    (1 + #positions reading at least as much) / (1 + #positions).

    The spectrum's own bins are the reference, clutter of unrelated discrete lines
    included: a real machine's envelope spectrum holds many more, and larger, lines than
    the chi-square law of noise allows, and a family must stand out of what this record
    shows elsewhere, not out of an idealised floor. The positions within OWN_BINS of the
    candidate's own lines are left out of its reference, so that a strong series is not
    measured against itself. Exact under the null that the family's line positions are
    no different from any others (exchangeable bins).
    """
    stop = int(min(top_bin, zmax.size - 1))
    start = int(min(max(math.floor(bottom_bin), 1), stop))
    live = count[start : stop + 1] > 0
    ref = np.sort(zmax[start : stop + 1][live])
    values = np.asarray(values, dtype=float)
    above = ref.size - np.searchsorted(ref, values, side="left")
    # the candidate's own positions (deduplicated), and how many of them reach each value
    own = (index[:, :, None] + np.arange(-OWN_BINS, OWN_BINS + 1)).reshape(index.shape[0], -1)
    own = np.sort(own, axis=1)
    fresh = np.ones(own.shape, bool)
    fresh[:, 1:] = own[:, 1:] != own[:, :-1]
    inside = fresh & (own >= start) & (own <= stop)
    own_z = np.where(inside, zmax[np.clip(own, 0, zmax.size - 1)], -np.inf)
    own_live = inside & np.isfinite(own_z)
    own_above = np.sum(own_z[:, None, :] >= values[:, :, None], axis=2)
    n_ref = ref.size - own_live.sum(axis=1)
    return np.log((1.0 + np.maximum(above - own_above, 0)) / (1.0 + np.maximum(n_ref, 0))[:, None])


def _cluster(zmax: np.ndarray, positions: np.ndarray, ref: np.ndarray) -> float:
    """Clusters per exceedance of the upper TAIL_Q of ``ref`` among the ``positions``
    (bool over bins) - runs of consecutive positions above the threshold, 1/3 for lines
    that each read at three positions (declustering by runs: Coles S., An Introduction
    to Statistical Modeling of Extreme Values, Springer 2001, sec. 5.3.2)."""
    if ref.size == 0:
        return 1.0
    u = np.sort(ref)[int((1 - TAIL_Q) * ref.size)]
    above = positions & (zmax > u)
    runs = int(np.sum(above[1:] & ~above[:-1])) + int(above[0])
    return runs / max(float(above.sum()), 1.0)


def reference_logp(
    reference: np.ndarray, values, tail: bool = True, cluster: float = 1.0
) -> np.ndarray:
    """ln p of ``values`` against the readings ``reference`` of the same spectrum at the
    positions where a line may stand: semi-parametric, an empirical null in the body and
    a peaks-over-threshold law in the tail.

    - Up to u, the reference's upper TAIL_Q quantile: the rank, (1 + #positions reading
      at least as much) / (1 + #positions) - exact under the null that a line's position
      is no different from any other (exchangeable positions), whatever the record's
      clutter of unrelated lines.
    - Beyond u: the exceedances of the reference over u taken as exponential (the
      peaks-over-threshold model with shape 0; the chi2_nu / nu law of a Welch bin has an
      exponential tail, and the largest of three bins too; Knijnenburg T. A. et al.,
      Bioinformatics 25 (2009) i161-i168) whose scale is not known: a new exceedance
      then follows the predictive law P(> u + x) = P(> u) (1 + x / (m s))^-m, m the
      number of independent exceedances (their count times ``cluster``: a line reads at
      three positions) and s their mean - the Lomax law, which is the exponential for
      many exceedances and heavier for few.
      The rank alone floors at 1 / (1 + N) (10^-2.7 for the ~500 positions of a 6205
      record): a line 20 times the floor scored the same as one at 4.

    >>> ref = np.random.default_rng(0).exponential(1.0, 2000)
    >>> lp = reference_logp(ref, np.array([0.0, 20.0]))
    >>> round(float(lp[0]), 6), -8.7 < float(lp[1]) / 20 < -0.4
    (0.0, True)
    """
    ref = np.sort(np.asarray(reference, dtype=float))
    values = np.asarray(values, dtype=float)
    n = ref.size
    if n == 0:
        return np.zeros(values.shape)
    rank = np.log((1.0 + n - np.searchsorted(ref, values, side="left")) / (1.0 + n))
    if not tail or n < 20:
        return rank
    u = ref[int((1 - TAIL_Q) * n)]
    over = ref[ref > u] - u
    if over.size == 0:
        return rank
    log_pu = math.log((1.0 + over.size) / (1.0 + n))
    m = max(over.size * cluster, 1.0)
    scale = max(float(np.mean(over)), 1e-12)
    law = log_pu - m * np.log1p(np.maximum(values - u, 0.0) / (m * scale))
    return np.where(values > u, np.minimum(law, 0.0), rank)


def line_hills(z: np.ndarray, offset: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """For the reading at each bin (the largest of three: its peak at bin + ``offset``),
    the first and last bin of the peak's hill: the bins either side down which ``z``
    falls steadily from the peak, at most HILL_BINS - a line's own extent, wider than
    its three bins where it wanders (a ball's random slip spread CWRU 222's 2 BSF line
    over six bins) or leaks."""
    n = z.size
    idx = np.arange(n)
    # run lengths of steady falls going left (z[i-1] < z[i]) and right (z[i+1] < z[i])
    fall_left = np.zeros(n, bool)
    fall_left[1:] = z[:-1] < z[1:]
    fall_right = np.zeros(n, bool)
    fall_right[:-1] = z[1:] < z[:-1]
    last_stop = np.maximum.accumulate(np.where(~fall_left, idx, 0))
    left = idx - last_stop
    rev = fall_right[::-1]
    last_stop_r = np.maximum.accumulate(np.where(~rev, idx, 0))
    right = (idx - last_stop_r)[::-1]
    peak = np.clip(idx + offset, 0, n - 1)
    return peak - np.minimum(left[peak], HILL_BINS), peak + np.minimum(right[peak], HILL_BINS)


def own_intervals(index, use, hills, size: int) -> tuple[np.ndarray, np.ndarray]:
    """The positions each candidate's own lines (``use`` at bins ``index``, rows x lines)
    occupy, as intervals [start, end] per line, rows x lines, merged within each row so
    that none overlaps (an empty one has end < start): each line's bin +- OWN_BINS and its
    hill (:func:`line_hills`) widened by one bin, the positions whose three bins reach
    it."""
    lo, hi = hills
    # (np.minimum and np.maximum: np.clip's wrapper costs several times their call)
    i = np.minimum(np.maximum(index, 0), lo.size - 1)
    a = np.minimum(np.maximum(np.minimum(lo[i] - 1, index - OWN_BINS), 0), size - 1)
    b = np.minimum(np.maximum(np.maximum(hi[i] + 1, index + OWN_BINS), 0), size - 1)
    a = np.where(use, a, size)  # unused lines: empty, sorted last
    b = np.where(use, b, -1)
    # each row sorted by its starts (take_along_axis, by flat indices)
    order = np.argsort(a, axis=1, kind="stable")
    order += np.arange(a.shape[0])[:, None] * a.shape[1]
    a = a.ravel()[order]
    b = b.ravel()[order]
    reach = np.maximum.accumulate(b, axis=1)
    before = np.concatenate([np.full((b.shape[0], 1), -1), reach[:, :-1]], axis=1)
    return np.maximum(a, before + 1), b


def _interval_sums(prefix: np.ndarray, start: np.ndarray, end: np.ndarray) -> np.ndarray:
    """Sums of the columns of a table over the merged intervals of each row, from its
    prefix sums ``prefix`` (bins + 1 x columns, prefix[k] = sum of bins < k): rows x
    columns."""
    empty = end < start
    s = np.where(empty, 0, start)
    e = np.where(empty, -1, end) + 1
    # column by column: a gather of single values and a sum along contiguous rows cost a
    # quarter of the gather of whole rows of the table and its strided sum
    columns = np.ascontiguousarray(prefix.T)
    return np.stack([(c[e] - c[s]).sum(axis=1) for c in columns], axis=-1)


def tail_tables(
    z,
    zmax,
    count,
    bottom_bin,
    near_bin,
    top_bin,
    values,
    index,
    uses,
    hills,
    beyond=None,
    nu=None,
    shared=None,
) -> dict:
    """ln p of every candidate's lines (``uses``: nested template -> rows x lines bool;
    the same table for each), each line read against the positions that are not the
    family's own at its fundamental (:func:`own_intervals`): every line its deepest
    template reads there, and its harmonics continued beyond the search limit
    (``beyond``: :func:`.series._continuation`).

    Up to u, the upper TAIL_Q quantile of the positions from ``bottom_bin`` to
    ``top_bin``: the rank among all of them (the candidate's own included: in-sample,
    cautious). Beyond u, the sum of two parts fitted to the positions that are not the
    candidate's own (a fault's own lines, and the spread of a line that wanders, are not
    its null: they made the upper 5 % of CWRU 223's positions):

    - the noise's: its exceedances over u exponential, the scale s from their median
      (s = median / ln 2: a few large lines of other origin do not move it); as s is
      estimated, a new exceedance follows the predictive (Lomax) law
      (1 + x / (m s))^-m, m the exceedances the noise explains (declustered: a line
      reads at three positions);
    - the clutter's: the peaks beyond x* = s ln(2 M), where the noise law expects fewer
      than half an exceedance of the M - discrete lines of other origin - counted: a
      reading is as likely as the share of positions whose peaks reach it; beyond the
      largest, the chance that a new one exceeds all k of them, 1 / (k + 1), falling off
      by their own predictive law (1 + (v - v_max) / (k c))^-k, c their mean height over
      u + x*. A line is never more significant than the clutter this record shows
      allows.

    Leaving each candidate's lines out of its own tail keeps the p-value of one fixed set
    of lines calibrated; the in-sample rank below u keeps Fisher's combination of lines
    read against the same reference from moving them together (measured in
    docs/capabilities/diagnosis.md). The positions above the family's own region (up to
    ``near_bin``: its highest line) join the reference unless those below show more
    exceedances, or larger ones, than those above (one-sided binomial and F tests at
    POOL_ALPHA, on the declustered counts): a raw envelope spectrum's low cyclic
    frequencies hold more clutter than its high ones, and the cage's lines lie in the
    lowest tenth of the search range, where every envelope spectrum is busiest.

    ``shared`` (optional): a store kept by the caller across the families read on one
    spectrum with one set of valid bins (:func:`.series.series_test`), for what does not
    depend on the family; the results are the same without it.
    """
    import scipy.special

    shared = {} if shared is None else shared
    stop = int(min(top_bin, zmax.size - 1))
    start = int(min(max(math.floor(bottom_bin), 1), stop))
    near = int(min(max(near_bin, start), stop))
    key = ("reference", zmax.size, start, stop)
    if key not in shared:
        ok = np.zeros(zmax.size, bool)
        ok[start : stop + 1] = count[start : stop + 1] > 0
        shared[key] = (ok, None)
        if ok.sum() >= 20:
            # the pooling test's counts: exceedances of the whole reference's threshold
            ref = np.sort(zmax[ok])
            u = ref[int((1 - TAIL_Q) * ref.size)]
            over = ok & (zmax > u)
            excess = np.where(over, zmax - u, 0.0)
            shared[key] = (ok, (_cluster(zmax, ok, ref), over, excess))
    ok, pooled = shared[key]
    if pooled is None:
        return {d: np.zeros(values.shape) for d in uses}
    cluster, over, excess = pooled
    below = np.zeros(zmax.size, bool)
    below[: near + 1] = True
    columns = [over, excess, ok]
    basis = np.stack([c * below for c in columns] + [c * ~below for c in columns]).T
    prefix = np.concatenate([np.zeros((1, 6)), np.cumsum(basis.astype(float), axis=0)])
    totals = prefix[-1]
    regions = {"near": ok & below, "all": ok}
    # the family's own positions at each fundamental: every line its deepest template
    # reads there, and the series' continuation beyond the search limit
    use = uses[max(uses)]
    if beyond is None:
        lo, hi = own_intervals(index, use, hills, zmax.size)
    else:
        more_index, _ = beyond
        lo, hi = own_intervals(
            np.concatenate([index, np.maximum(more_index, 0)], axis=1),
            np.concatenate([use, more_index >= 0], axis=1),
            hills,
            zmax.size,
        )
    m_n, s_n, c_n, m_f, s_f, c_f = (totals[None, :] - _interval_sums(prefix, lo, hi)).T
    # are the exceedances below the limit more frequent, or larger, than above it?
    a, b = np.maximum(m_n * cluster, 0.5), np.maximum(m_f * cluster, 0.5)
    ratio = (s_n / np.maximum(m_n, 1.0)) / np.maximum(s_f / np.maximum(m_f, 1.0), 1e-12)
    p_scale = scipy.special.fdtrc(2.0 * a, 2.0 * b, ratio)
    k = np.round(m_n * cluster).astype(int)
    total = np.maximum(np.round((m_n + m_f) * cluster).astype(int), k)
    share = c_n / np.maximum(c_n + c_f, 1.0)
    p_rate = np.where(k > 0, scipy.special.bdtrc(np.maximum(k - 1, 0), total, share), 1.0)
    alone = (c_f < 1) | (np.minimum(p_scale, p_rate) < POOL_ALPHA)
    lp = np.zeros(values.shape)
    for name, rows in (("near", alone), ("all", ~alone)):
        if rows.any():
            region_key = ("region", key, near if name == "near" else None, nu)
            if region_key not in shared:
                shared[region_key] = _region(z, zmax, regions[name], nu)
            lp[rows] = _region_logp(zmax, shared[region_key], values[rows], lo[rows], hi[rows])
    table = np.where(use, lp, 0.0)
    tables = {d: table for d in uses}
    return tables


@functools.lru_cache(maxsize=64)
def chi2_excess_scale(nu: float) -> float:
    """The exponential scale of the exceedances of the largest of three chi2_nu / nu bins
    over its upper TAIL_Q quantile [-]: their mean excess, the spread a Welch estimate
    with nu degrees of freedom gives any random signal.

    >>> round(chi2_excess_scale(2.0), 2), round(chi2_excess_scale(50.0), 3)
    (1.02, 0.104)
    """
    import scipy.special

    # the upper TAIL_Q quantile u of max of 3 (F(u)^3 = 1 - TAIL_Q), then the mean excess
    # integral_u^inf S3(x) dx / S3(u), S3 = 1 - F^3
    u = float(scipy.special.chdtri(nu, 1.0 - (1.0 - TAIL_Q) ** (1.0 / 3.0))) / nu
    x = u + np.linspace(0.0, 40.0 / math.sqrt(nu) + 40.0 / nu, 2001)
    survival = 1.0 - (1.0 - scipy.special.chdtrc(nu, x * nu)) ** 3
    return float(np.trapezoid(survival, x)) / TAIL_Q


def _region(z, zmax, region, nu=None) -> dict:
    """What the tail of ``region``'s positions is fitted from, whatever the candidate:
    the sorted readings, the threshold u, the clusters per exceedance, the noise's scale,
    x*, the prefix sums of the noise's exceedances and of the positions, and the
    clutter's peaks with their heights (see :func:`tail_tables`)."""
    pos = np.flatnonzero(region)
    ref = np.sort(zmax[pos])
    u = ref[int((1 - TAIL_Q) * ref.size)]
    over = region & (zmax > u)
    excess = np.where(over, zmax - u, 0.0)
    scale = max(float(np.median(excess[over])) / math.log(2.0), 1e-12) if over.any() else 1.0
    if nu:
        # never narrower than the estimation noise of a Welch spectrum of any random
        # signal: a noise-free simulation's deterministic floor spreads far less, and
        # every slight line of it had stood out (a healthy 6205, cpw: 'outer race' from
        # harmonics 6 and 7 at 1.4 x the floor)
        scale = max(scale, chi2_excess_scale(nu))
    cut = scale * math.log(2.0 * max(int(over.sum()), 1))
    basis = np.stack([over & ~(excess > cut), region]).T.astype(float)
    zz = np.where(region, z[: zmax.size], -np.inf)
    peak = np.zeros(zmax.size, bool)
    peak[1:-1] = (zz[1:-1] >= zz[:-2]) & (zz[1:-1] > zz[2:]) & (zz[1:-1] > u + cut)
    peaks = np.flatnonzero(peak)
    return {
        "mask": region,
        "ref": ref,
        "u": u,
        "cluster": _cluster(zmax, region, ref),
        "scale": scale,
        "cut": cut,
        "prefix": np.concatenate([np.zeros((1, 2)), np.cumsum(basis, axis=0)]),
        "peaks": peaks,
        "heights": z[peaks],
    }


def _region_logp(zmax, fit, values, lo, hi) -> np.ndarray:
    """ln p of the lines ``values`` (rows x lines) against the positions of a region
    (``fit``: :func:`_region`) that are not each row's own (merged intervals
    ``lo``..``hi``): see :func:`tail_tables`."""
    u, cut, scale, cluster = fit["u"], fit["cut"], fit["scale"], fit["cluster"]
    prefix, peaks, heights = fit["prefix"], fit["peaks"], fit["heights"]
    m, c = (prefix[-1][None, :] - _interval_sums(prefix, lo, hi)).T
    c = np.maximum(c, 1.0)
    x = np.maximum(values - u, 0.0)
    # the noise's part
    m_eff = np.maximum(m * cluster, 1.0)[:, None]
    law = ((1.0 + m) / (1.0 + c))[:, None] * np.exp(-m_eff * np.log1p(x / (m_eff * scale)))
    # the clutter's part: its peaks (local maxima of z above u + x*, each line once) that
    # are not the row's own: within their range the share of the positions not the row's
    # own that read as much; beyond the largest, the chance to exceed them all, falling
    # off by the peaks' own predictive law
    high = values > u + cut
    if peaks.size and high.any():
        inside = (lo[:, :, None] <= peaks[None, None, :]) & (peaks[None, None, :] <= hi[:, :, None])
        free_peak = ~inside.any(axis=1)
        kc = free_peak.sum(axis=1).astype(float)
        top = np.where(free_peak, heights[None, :], u + cut).max(axis=1)
        mean = np.where(free_peak, heights[None, :] - u - cut, 0.0).sum(axis=1)
        mean = np.maximum(mean / np.maximum(kc, 1.0), 1e-12)
        reach = _free_count(zmax, fit["mask"], values, high, lo, hi, fit["ref"])
        k_c = np.maximum(kc, 1.0)[:, None]
        beyond = np.maximum(values - top[:, None], 0.0)
        fall = np.exp(-k_c * np.log1p(beyond / (k_c * mean[:, None])))
        part = np.where(reach > 0, reach, fall) / (1.0 + c)[:, None]
        law = law + np.where((kc[:, None] > 0) & high, part, 0.0)
    n = fit["ref"].size
    rank = np.log((1.0 + n - np.searchsorted(fit["ref"], values, side="left")) / (1.0 + n))
    return np.where(values > u, np.minimum(np.log(np.maximum(law, 1e-300)), 0.0), rank)


def _free_count(zmax, region, values, which, lo, hi, ref=None) -> np.ndarray:
    """For the lines ``which`` (rows x lines), the positions of ``region`` that are not the
    row's own (merged intervals ``lo``..``hi``) and read at least the line's value
    (``ref``: the region's readings sorted, when at hand).

    Only the positions that read at least the smallest of those values can count: each
    row's own among them are found by their places in the row's intervals, whatever the
    intervals' widths."""
    out = np.zeros(values.shape)
    r, j = np.nonzero(which)
    if r.size == 0:
        return out
    v = values[r, j]
    ref = np.sort(zmax[region]) if ref is None else ref
    total = ref.size - np.searchsorted(ref, v, side="left")
    # the positions of the region that may count, and which of them each row owns (the
    # intervals do not overlap: a position is in at most one of a row's); np.nonzero
    # gives r sorted: its distinct values by their changes
    high = np.flatnonzero(region & (zmax >= v.min()))
    if high.size:
        first = np.empty(r.size, bool)
        first[0] = True
        np.not_equal(r[1:], r[:-1], out=first[1:])
        rows, back = r[first], np.cumsum(first) - 1
        start, end = lo[rows], hi[rows]
        some = end >= start
        a = np.searchsorted(high, start[some], side="left")
        b = np.searchsorted(high, end[some], side="right")
        owner = np.nonzero(some)[0] * (high.size + 1)
        edges = np.bincount(owner + a, minlength=rows.size * (high.size + 1))
        edges -= np.bincount(owner + b, minlength=rows.size * (high.size + 1))
        owned = np.cumsum(edges.reshape(rows.size, high.size + 1), axis=1)[:, :-1] > 0
        total = total - (owned[back] & (zmax[high][None, :] >= v[:, None])).sum(axis=1)
    out[r, j] = total
    return out
