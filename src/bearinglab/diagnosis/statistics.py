"""Significance of a harmonic series in an envelope spectrum, above its local noise floor.

Layer 1 (NumPy and ``scipy.stats``). The squared envelope spectrum (SES) is estimated by
Welch averaging (Hann segments, 50 % overlap). Where the signal holds no periodic
modulation - noise, or a healthy machine away from its discrete lines - the SES at a
non-zero frequency is the estimate of a spectral density, and its value in each bin
follows a scaled chi-square law with nu equivalent degrees of freedom (the spectral
correlation at cyclic frequency alpha != 0 of a stationary signal is zero, and its
estimate is asymptotically complex Gaussian: Antoni J., "Cyclic spectral analysis in
practice", MSSP 21 (2007) 597-630, sec. 4; Antoni J., "Cyclic spectral analysis of
rolling-element bearing signals: facts and fictions", JSV 304 (2007) 497-529). nu follows
from the window and the overlap (Percival D. B., Walden A. T., Spectral Analysis for
Physical Applications, Cambridge 1993, eq. 292b; Welch P. D., IEEE Trans. Audio
Electroacoust. 15 (1967) 70-73).

The test of a fault family (outer race, inner race, ball, cage):
1. the noise floor is the running median of the SES over FLOOR_BINS bins, turned into
   the mean of the chi-square law (median / mean = chi2.median(nu) / nu); a few lines
   barely move a median;
2. a line expected at frequency f is read as the largest normalised value z over the
   bin nearest f and its two neighbours (the line's own width under a Hann window); its
   p-value (:func:`.tail.tail_tables`, the diagnosis' reading, ``series_test(tail=True)``) is
   its rank among the same reading at every position where a line may stand, up to the
   reference's upper TAIL_Q, and beyond that a peaks-over-threshold law fitted to the
   positions that are not the family's own lines at that fundamental - the noise's
   exceedances, exponential with an estimated scale (their predictive, Lomax, law), plus
   the record's clutter of discrete lines of other origin, counted. An empirical null in
   the body, because the envelope spectrum of a real machine holds far more, and larger,
   lines than the chi-square law of noise allows (on the healthy CWRU record 97 the
   chi-square p-values put some family beyond 1e-900); a law in the tail, because the
   rank alone floors at 1 / positions (10^-2.7 for a 6205 record): a line 20 times the
   floor scored as one at 4 (issue 27). The reference runs beyond the search limit to
   REFERENCE_POSITIONS positions where what lies beyond is no heavier than the family's
   own region. The speed check and the stray-series search read the rank alone
   (:func:`.tail.line_rank_logp`, ``tail=False``);
3. the family's lines are its harmonics n f' (n = 1 .. N), the modulation sidebands
   n f' +- k f_m that the physics puts there, and the modulation's own lines k f_m (the
   sidebands of the 0th harmonic: an impact train whose amplitude varies at f_m has
   envelope lines at k f_m as well as around each harmonic - the envelope spectrum is
   the modulation's spectrum convolved with the train's, whose 0 Hz line is its mean;
   Randall & Antoni 2011, sec. 2); one fundamental f' = (1 + s) f_kin with one
   slip s for all of them (the cage has one mean speed over a record), scanned over the
   family's tolerance window on a grid fine enough to move the N-th harmonic by half a
   bin;
4. the lines' p-values are combined by Fisher's method (-2 sum ln p ~ chi2 with 2L
   degrees of freedom for L independent lines: Fisher R. A., Statistical Methods for
   Research Workers, 1932, sec. 21.1; a line whose three bins overlap an earlier line's
   is read once), and the best fundamental is kept. The depth of modulation is not
   known beforehand (an outer-race defect under a fixed load is not modulated at all,
   the same defect under a rotating load or away from the load line is; Randall &
   Antoni 2011, sec. 2 and fig. 4), and Fisher's combination is diluted by lines that
   carry nothing: so the template is tested nested - harmonics alone, then with the
   sidebands up to order 1, 2, ... - and the best of the K templates is kept (on 12
   synthetic outer-race faults in the load zone at 0 dB, raw method, the +-1 x shaft
   template scored 10^-1.7 to 10^-7.9, the harmonics alone 10^-4.1 to 10^-10.9:
   docs/capabilities/diagnosis.md). The scan over fundamentals and templates is a
   multiple comparison: with ``tail`` its best p-value is bounded by the union bound
   along the chain of consecutive fundamentals of each template
   (:func:`bearinglab.diagnosis.chain.chain_logp`: within 10-25 % of the scan's true law
   for harmonics alone, 2-3 times above it with the sidebands' templates, where the
   count of distinct sets of lines, Bonferroni, is 3-5 times above); the rank's reading
   multiplies it by the count of distinct sets of lines and templates (Bonferroni);
5. the harmonics must be significant by themselves, at SUPPORT_ALPHA (sidebands support a
   series, they do not make one: a flexible template of harmonics and two orders of sidebands fits
   stray lines, e.g. BPFO as a ball line's second cage sideband; the modulation's own
   lines never count here, FTF lines alone are no ball fault) - for ball and inner-race
   faults alone or with their first sidebands, since the load zone modulates those
   defects deeply (:data:`bearinglab.diagnosis.families.GATE_ORDERS`), and for the outer
   race alone or with the first sidebands of the carriers that show (a defect away from
   the load line, or under a rotating load; its load is never negative, so that no
   sideband exceeds its carrier: ``gate_carriers``), by how much is
   not known beforehand: nested as the templates are, at the best fundamental whichever
   template won, the better of the two times 2 (Bonferroni; 1 where no sideband can be
   read, the two sets of lines then being one; CWRU 3005, ball, shows 1, 2, 3 x 2 BSF
   and nearly nothing beside them, and its harmonics with their sidebands fell short:
   docs/capabilities/diagnosis.md);
   and the series must
   not rest on one line: combined again without its strongest line (the best template
   without it, over the fundamentals that read that line where it stands), it must still
   reach SUPPORT_ALPHA (an isolated line is more often a discrete component
   of the machine than a bearing fault; Randall & Antoni 2011, sec. 2: a fault shows as
   a series of harmonics).

Probabilities are carried as logarithms (a strong series has p ~ 1e-1000). Under the
null hypothesis the family's p-value is thus an upper bound of its false-alarm
probability.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .tail import OWN_BINS, line_hills, line_rank_logp, tail_tables

#: Bins of the running median that estimates the noise floor (odd): wide against the
#: lines (3 bins each) so that even a dense family (harmonics with two orders of
#: sidebands) covers less than half of it.
FLOOR_BINS = 61
#: Bins read around each expected line (the nearest and its two neighbours).
LINE_BINS = 3
#: Level the family must still reach without its strongest line [-].
SUPPORT_ALPHA = 0.01
#: Level at which a single line shows: a line of an accepted family is listed at it, and
#: a carrier must reach it for its sidebands to count in a carrier-gated harmonic test [-].
LINE_ALPHA = 0.01
#: Smallest p-value carried in the arithmetic (keeps logarithms finite).
TINY = 1e-300


def welch_dof(nperseg: int, noverlap: int, n: int, window: np.ndarray | None = None) -> float:
    """Equivalent degrees of freedom nu of a Welch average (Percival & Walden eq. 292b).

    nu = 2 K / (1 + 2 sum_{m=1}^{K-1} (1 - m/K) rho(m)^2), rho(m) = sum_t h_t h_{t+m D}
    the overlap correlation of the window normalised to sum_t h_t^2 = 1 with itself
    shifted by m hops D, K the segments (Hann at 50 % overlap: rho(1) = 1/6).

    >>> round(welch_dof(256, 0, 256), 6)                  # one segment: chi-square 2
    2.0
    >>> round(welch_dof(256, 128, 256 * 10), 2)           # 19 Hann segments, 50 % overlap
    36.1
    """
    if window is None:
        window = np.hanning(nperseg + 1)[:-1] if nperseg > 1 else np.ones(1)  # periodic Hann
    hop = max(nperseg - noverlap, 1)
    k = max(1 + (n - nperseg) // hop, 1)
    total = float(np.sum(window**2))
    rho = [
        float(np.sum(window[m * hop :] * window[: nperseg - m * hop])) / total
        if m * hop < nperseg
        else 0.0
        for m in range(1, k)
    ]
    correction = 1.0 + 2.0 * sum((1.0 - m / k) * r**2 for m, r in enumerate(rho, start=1))
    return 2.0 * k / correction


def normalised(power: np.ndarray, nu: float, floor_bins: int = FLOOR_BINS) -> np.ndarray:
    """Power over its local mean noise level, from a running median [-].

    The running median (``scipy.ndimage.median_filter``, reflected at the ends) of a
    scaled chi2_nu variable is scaled to its mean by nu / chi2.median(nu). The 0 Hz bin,
    which holds the record's mean, gets the value of its neighbour.
    """
    import scipy.ndimage
    import scipy.special

    p = np.asarray(power, dtype=float).copy()
    if p.size > 1:
        p[0] = p[1]
    size = min(floor_bins, p.size - (1 - p.size % 2))
    median = scipy.ndimage.median_filter(p, size=max(size, 1), mode="reflect")
    chi2_median = 2.0 * float(scipy.special.gammaincinv(nu / 2.0, 0.5))  # = chi2(nu).median()
    mean = median * nu / chi2_median
    tiny = 1e-300 + 1e-12 * float(np.max(mean)) if mean.size else 1e-300
    return p / np.maximum(mean, tiny)


def standardised(power: np.ndarray, nu: float, floor_bins: int = FLOOR_BINS) -> np.ndarray:
    """Power standardised against its local median and spread, on the scale of a
    chi2_nu / nu variable [-]: z = 1 + sqrt(2 / nu) (P - m) / s, m the running median over
    ``floor_bins`` bins and s = 1.4826 x the running median of |P - m| (the spread a
    Gaussian's median absolute deviation estimates), floored at 0.

    For a spectrum whose spread is proportional to its level - a Welch estimate,
    chi-square - this orders the bins as :func:`normalised` does. The improved envelope
    spectrum averages a hundred spectral frequencies, so that its estimation noise is a
    few percent of its level, and what spreads it is the record's own weak cyclic
    content, more of it at some cyclic frequencies than at others (the low ones): its
    spread is not proportional to its level, and the ratio to the local median alone
    reads a bin of a busy stretch as a line (on CWRU 197 and 198, "cage" from FTF lines
    of z 1.1). Putting z on the chi2_nu / nu scale keeps the masks of discrete lines
    (:func:`bearinglab.diagnosis.verdict.leakage_halfwidth`) and the peaks' reading as
    they are for the Welch spectra of the other methods.
    """
    import scipy.ndimage

    p = np.asarray(power, dtype=float).copy()
    if p.size > 1:
        p[0] = p[1]
    size = max(min(floor_bins, p.size - (1 - p.size % 2)), 1)
    median = scipy.ndimage.median_filter(p, size=size, mode="reflect")
    spread = 1.4826 * scipy.ndimage.median_filter(np.abs(p - median), size=size, mode="reflect")
    tiny = 1e-300 + 1e-12 * float(np.max(np.abs(p))) if p.size else 1e-300
    z = 1.0 + math.sqrt(2.0 / nu) * (p - median) / np.maximum(spread, tiny)
    return np.maximum(z, 0.0)


def chi2_logsf(x, dof) -> np.ndarray:
    """ln P(chi2_dof > x), finite far into the tail.

    ln of the regularised upper incomplete gamma function Q(dof/2, x/2)
    (``scipy.special.chdtrc``, what ``scipy.stats.chi2.sf`` computes; scipy.stats is not
    imported, it costs ~0.5 s at start-up). It underflows to -inf beyond ~700 nats; there
    the leading term of the upper incomplete gamma function, Gamma(s, y) ~ y^(s-1) e^-y
    (s = dof/2, y = x/2; Abramowitz & Stegun 6.5.32), takes over.

    >>> float(np.round(chi2_logsf(4.0, 2), 12)), bool(np.isfinite(chi2_logsf(1e6, 20)))
    (-2.0, True)
    """
    import scipy.special

    x = np.asarray(x, dtype=float)
    dof = np.asarray(dof, dtype=float)
    with np.errstate(divide="ignore"):
        out = np.asarray(np.log(scipy.special.chdtrc(dof, x)), dtype=float)
    far = ~np.isfinite(out)
    if np.any(far):
        s, y = np.broadcast_to(dof / 2.0, x.shape)[far], x[far] / 2.0
        out = out.copy()
        out[far] = (s - 1.0) * np.log(y) - y - scipy.special.gammaln(s)
    return out


def decades(log_p: float) -> float:
    """-log10 p from ln p [-] (0.0, not -0.0, for p = 1).

    >>> round(decades(math.log(1e-3)), 12), decades(0.0)
    (3.0, 0.0)
    """
    return 0.0 - float(log_p) / math.log(10.0)


def bin_logp(z, nu: float) -> np.ndarray:
    """ln P(chi2_nu / nu > z): the chance that noise alone reaches z in one bin."""
    return chi2_logsf(np.asarray(z, dtype=float) * nu, nu)


def bin_pvalue(z, nu: float) -> np.ndarray:
    """P(chi2_nu / nu > z) [-] (may underflow to 0; see :func:`bin_logp`)."""
    return np.exp(bin_logp(z, nu))


def fisher_logp(logps, axis=-1):
    """ln of Fisher's combined p-value P(chi2_2L > -2 sum ln p) of L p-values."""
    logps = np.asarray(logps, dtype=float)
    return chi2_logsf(-2.0 * np.sum(logps, axis=axis), 2 * logps.shape[axis])


@dataclass(frozen=True)
class Line:
    """One line of a family as found: ``kind`` ("harmonic" or "sideband"), harmonic
    ``n`` (0 for the modulation's own lines k f_m), sideband order ``k`` (0 for a
    harmonic), ``expected_hz`` (on the fitted fundamental) and ``frequency_hz`` (bin of
    the largest value read) [Hz], normalised power ``z`` [-] and ``log_p`` (natural log
    of its p-value) [-]."""

    kind: str
    n: int
    k: int
    expected_hz: float
    frequency_hz: float
    z: float
    log_p: float

    @property
    def p_value(self) -> float:
        """p-value of the line [-]."""
        return math.exp(self.log_p)


@dataclass(frozen=True)
class SeriesTest:
    """Result of :func:`series_test` for one fault family.

    ``log_p`` (natural log of the p-value: Fisher's, times ``candidates`` and the number
    of nested templates), ``support_log_p`` (the same without the strongest line),
    ``harmonic_log_p`` (the harmonics alone or with their sidebands up to order
    ``gate_orders``, read at the best fundamental whichever template won, the better
    times the number of distinct sets of lines, and times the factors of
    ``log_p``), ``fundamental_hz`` (the best
    f') and ``slip`` (f'/f_kin - 1) [-], the ``lines`` read, and ``candidates`` (M).
    ``log_p`` is 0 (p = 1) when no line could be read (all masked or above the limit).
    """

    log_p: float
    support_log_p: float
    harmonic_log_p: float
    fundamental_hz: float
    slip: float
    lines: tuple[Line, ...]
    candidates: int

    @property
    def p_value(self) -> float:
        """p-value [-] (0.0 when it underflows; see ``significance``)."""
        return math.exp(self.log_p)

    @property
    def support_p_value(self) -> float:
        """p-value without the strongest line [-]."""
        return math.exp(self.support_log_p)

    @property
    def significance(self) -> float:
        """-log10 of the p-value [-] (10: one chance in 10^10 from noise alone)."""
        return decades(self.log_p)


def _distinct_rows(a: np.ndarray) -> int:
    """Number of distinct rows of the 2-D integer array ``a`` (each row seen as one
    value, so that NumPy's unique compares them at C speed)."""
    rows = np.ascontiguousarray(a).view(np.dtype((np.void, a.dtype.itemsize * a.shape[1])))
    return int(np.unique(rows).size)


def _window_max(z: np.ndarray, valid: np.ndarray):
    """Largest valid z over each bin and its neighbours, the number of valid bins there,
    and the offset (-1, 0, 1) of the largest (the first of equals)."""
    padded = np.pad(np.where(valid, z, -np.inf), 1, constant_values=-np.inf)
    left, mid, right = padded[:-2], padded[1:-1], padded[2:]
    largest = np.maximum(np.maximum(left, mid), right)
    count = np.isfinite(left).astype(int) + np.isfinite(mid) + np.isfinite(right)
    offset = np.where(left == largest, -1, np.where(mid == largest, 0, 1))
    return largest, count, offset


def series_test(
    z: np.ndarray,
    resolution: float,
    nu: float,
    fundamental: float,
    below: float,
    above: float,
    harmonics: int,
    max_frequency: float,
    modulation: float | None = None,
    orders: int = 0,
    valid: np.ndarray | None = None,
    gate_orders: int = 0,
    bottom: float = 0.0,
    gate_carriers: bool = False,
    tail: bool = False,
    reference: float | None = None,
) -> SeriesTest:
    """Significance of the harmonic series n f' (n = 1..``harmonics``) with its sidebands
    n f' +- k ``modulation`` and the modulation's lines k ``modulation``
    (k = 1..``orders``), f' scanned over
    [(1 - below) f, (1 + above) f] (see the module docstring).

    Parameters
    ----------
    z : numpy.ndarray
        Normalised SES (:func:`normalised`), bin k at k x ``resolution`` [Hz].
    resolution : float
        Bin spacing [Hz].
    nu : float
        Degrees of freedom of the SES estimate.
    fundamental : float
        Kinematic fundamental f [Hz].
    below, above : float
        Tolerance window of the fundamental [-, fractions].
    harmonics : int
        Highest harmonic order read.
    max_frequency : float
        No line above this frequency is read [Hz].
    modulation : float, optional
        Modulating frequency of the sidebands [Hz].
    orders : int
        Sideband orders either side.
    valid : numpy.ndarray of bool, optional
        Bins that may be read (False: masked discrete lines or another fault's lines).
    gate_orders : int
        Deepest sideband order counted with the harmonics in ``harmonic_log_p`` (0:
        harmonics alone; 1: alone or with the first sidebands, the better).
    bottom : float
        Lowest frequency at which a line is sought [Hz]: the reference of each line's
        p-value starts there (:func:`.tail.line_logp`).
    gate_carriers : bool
        Count a sideband in ``harmonic_log_p`` only where its carrier (the harmonic it
        flanks) shows at LINE_ALPHA.
    tail : bool
        True: each line read by the rank up to the reference's upper TAIL_Q and beyond by
        the tail law of the positions that are not the candidate's own
        (:func:`.tail.tail_tables`), each scan's best p-value bounded by its chain of
        consecutive fundamentals (:func:`bearinglab.diagnosis.chain.chain_logp`) - the
        diagnosis' test. False (default): the rank alone, floored at 1 / positions, each
        candidate's own positions left out of its reference (:func:`.tail.line_rank_logp`),
        and a Bonferroni count of the scan's distinct sets of lines - the speed check's
        and the stray-series search's reading.
    reference : float, optional
        With ``tail``: the positions up to this frequency [Hz] (at least
        ``max_frequency``) are the reference of the tail law, when those above
        ``max_frequency`` are no heavier than those below (:func:`.tail.tail_tables`); default
        ``max_frequency``.

    Returns
    -------
    SeriesTest
    """
    valid = np.ones(z.shape, bool) if valid is None else valid
    top = min(max_frequency, (z.size - 2) * resolution)
    ref_top = top
    if tail and reference is not None:
        ref_top = max(top, min(float(reference), (z.size - 2) * resolution))
    # nothing above the reference is read, as a line or as reference: leave those bins
    # out (with a margin: lines beyond the limit are clipped to the last bins)
    keep = int(math.floor(ref_top / resolution)) + 4 + OWN_BINS
    z, valid = z[:keep], valid[:keep]
    n_max = int(min(harmonics, math.floor(top / (fundamental * (1 + above)))))
    if n_max < 1:
        return SeriesTest(0.0, 0.0, 0.0, fundamental, 0.0, (), 0)
    step = resolution / (2.0 * n_max)
    grid = np.arange(fundamental * (1 - below), fundamental * (1 + above) + step / 2, step)
    # expected lines: (kind, n, k) rows, frequencies = n f' + k f_m
    spec = [("harmonic", n, 0) for n in range(1, n_max + 1)]
    if modulation and orders:
        spec += [
            ("sideband", n, s * k)
            for n in range(1, n_max + 1)
            for k in range(1, orders + 1)
            for s in (-1, 1)
        ]
        spec += [("sideband", 0, k) for k in range(1, orders + 1)]
    n_arr = np.array([r[1] for r in spec], float)
    k_arr = np.array([r[2] for r in spec], float)
    zmax, count, offset = _window_max(z, valid)
    live = count > 0
    index, readable = _read(grid, n_arr, k_arr, modulation, top, resolution, live)
    if not np.any(readable):
        return SeriesTest(0.0, 0.0, 0.0, fundamental, 0.0, (), 0)
    values = zmax[index]
    # nested templates: harmonics alone, then with sidebands up to each order (the depth
    # of modulation is unknown: none for a fixed defect under a fixed load)
    depths = tuple(range(0, int(orders) + 1)) if (modulation and orders) else (0,)
    uses = {d: readable & (np.abs(k_arr) <= d)[None, :] for d in depths}
    if tail:
        hills = line_hills(np.where(valid, z, 0.0), offset)
        # the family's own region: up to its highest line (the cage's lines all lie in
        # the lowest tenth of the search range, where an envelope spectrum is busiest)
        region = min(float(np.max(np.where(readable, index, 0))) + 2 * LINE_BINS, top / resolution)
        # beyond the search limit the family's series goes on: its harmonics (and their
        # sidebands) up to the reference's top are its own there too
        own = _continuation(grid, n_max, orders, modulation, top, ref_top, resolution, live)
        tables = tail_tables(
            np.where(valid, z, 0.0),
            zmax,
            count,
            bottom / resolution,
            region,
            ref_top / resolution,
            values,
            index,
            uses,
            hills,
            own,
            nu,
        )
        found = _tail_scan(tables, uses, index, n_arr, k_arr, gate_orders, gate_carriers)
        log_p, support, harmonic, best, depth = found
        logp = tables[depth]
        candidates = _distinct_rows(np.where(uses[depth], index, -1))
    else:
        # the rank alone, each candidate's own positions left out of its reference (a
        # strong series, with its leakage, is not measured against itself)
        logp = np.where(
            readable,
            line_rank_logp(
                zmax,
                count,
                top / resolution,
                np.where(readable, values, 0.0),
                index,
                bottom / resolution,
            ),
            0.0,
        )
        # the best template by its Bonferroni-corrected p-value: the scan's distinct
        # sets of lines x the templates (x the gate's sets)
        trials = []
        for d in depths:
            if uses[d].any():
                c = _fisher_rows(logp, uses[d])
                r = int(np.argmin(c))
                m = _distinct_rows(np.where(uses[d], index, -1))
                trials.append((float(c[r]) + math.log(m), float(c[r]), r, d, m))
        _, raw_log_p, best, depth, candidates = min(trials)
        use = uses[depth]
        raw_support, raw_harmonic, n_gates = _gates(
            logp[best], use[best], readable[best], n_arr, k_arr, gate_orders, gate_carriers
        )
        log_m = math.log(candidates) + math.log(len(trials))
        log_p = min(0.0, raw_log_p + log_m)
        support = min(0.0, raw_support + log_m) if use[best].sum() > 1 else 0.0
        harmonic = min(0.0, raw_harmonic + log_m + math.log(n_gates)) if n_gates else 0.0
    row = uses[depth][best]
    freq = grid[best] * n_arr + k_arr * (modulation or 0.0)
    lines = []
    for j in np.flatnonzero(row):
        kind, n, k = spec[j]
        i = int(index[best, j]) + int(offset[index[best, j]])
        lines.append(
            Line(
                kind,
                n,
                k,
                float(freq[j]),
                i * resolution,
                float(values[best, j]),
                float(logp[best, j]),
            )
        )
    f_best = float(grid[best])
    return SeriesTest(
        log_p, support, harmonic, f_best, f_best / fundamental - 1.0, tuple(lines), candidates
    )


def _gates(logp, use, readable, n_arr, k_arr, gate_orders, gate_carriers):
    """ln p of the support and the harmonic gate at one fundamental, before the scan's
    correction, and the number of sets of lines the harmonic gate tried (the rank's
    reading: ``series_test(tail=False)``).

    Support: the series without its strongest line, by Fisher's combination. Harmonic
    gate: the harmonics alone, then with their sidebands up to ``gate_orders`` (nested as
    the templates are: the depth of modulation is unknown), the better; with
    ``gate_carriers`` a sideband counts only beside a carrier that shows at LINE_ALPHA."""
    lps = logp[use]
    support = 0.0
    if lps.size > 1:
        support = float(fisher_logp(np.delete(lps, int(np.argmin(lps)))))
    sets = _gate_masks(logp, readable, n_arr, k_arr, gate_orders, gate_carriers)
    values = [float(fisher_logp(logp[m])) for m in sets]
    return support, (min(values) if values else 0.0), len(sets)


def _gate_masks(logp_row, readable_row, n_arr, k_arr, gate_orders, gate_carriers) -> list:
    """The distinct sets of lines (masks over the template's lines) of the harmonic gate
    at one fundamental: the harmonics alone, then with their sidebands up to
    ``gate_orders``; with ``gate_carriers`` a sideband only beside a carrier that shows at
    LINE_ALPHA (the load that modulates a fixed defect's impacts is never negative, and
    the Fourier coefficients of a non-negative function are at most its mean,
    |c_k| <= c_0, so that no sideband of a real series stands without its carrier)."""
    own = readable_row & (n_arr >= 1)
    if gate_carriers:
        shown = n_arr[own & (k_arr == 0) & (logp_row < math.log(LINE_ALPHA))]
        own = own & ((k_arr == 0) | np.isin(n_arr, shown))
    out, seen = [], set()
    for d in range(int(gate_orders) + 1):
        m = own & (np.abs(k_arr) <= d)
        key = tuple(np.flatnonzero(m))
        if key and key not in seen:
            seen.add(key)
            out.append(m)
    return out


def _tail_scan(tables, uses, index, n_arr, k_arr, gate_orders, gate_carriers):
    """The family's p-value and its gates from the tail's line p-values (``tables``,
    one per nested template), each scan bounded by its chain (``series_test(tail=True)``).

    - The series: the best (fundamental, template) by Fisher's combination; the chain
      bound of every template's scan at that level.
    - The support: the best template's lines without the strongest line, at the best
      fundamental; its scan is the fundamentals that read that line where it stands (it
      fixes the fundamental), with every template's chain over them.
    - The harmonic gate: the harmonics alone, or with their first sidebands (as
      ``gate_orders``, ``gate_carriers`` say), the better, each set's chain over the whole
      scan.

    Returns (ln p, support ln p, harmonic ln p, best row, best template)."""
    from .chain import chain_logp, chain_steps

    depths = tuple(tables)
    combos = {d: _fisher_rows(tables[d], uses[d]) for d in depths}
    depth = min(depths, key=lambda d: float(np.min(combos[d])))
    best = int(np.argmin(combos[depth]))
    log_p = chain_logp(float(combos[depth][best]), [chain_steps(index, uses[d]) for d in depths])
    row = uses[depth][best]
    support = 0.0
    if row.sum() > 1:
        strongest = int(np.flatnonzero(row)[np.argmin(tables[depth][best][row])])
        keep = np.ones(n_arr.size, bool)
        keep[strongest] = False
        raw = min(
            float(fisher_logp(tables[d][best][uses[d][best] & keep]))
            for d in depths
            if (uses[d][best] & keep).any()
        )
        rows = np.abs(index[:, strongest] - index[best, strongest]) <= 1
        sub = [chain_steps(index[rows], uses[d][rows] & keep[None, :]) for d in depths]
        support = chain_logp(raw, sub)
    harmonic = 0.0
    readable = uses[depths[-1]]
    gate = _gate_masks(tables[0][best], readable[best], n_arr, k_arr, gate_orders, gate_carriers)
    if gate:
        raw = min(
            float(fisher_logp(tables[min(int(np.max(np.abs(k_arr[m]))), depths[-1])][best][m]))
            for m in gate
        )
        harmonic = chain_logp(raw, [chain_steps(index, readable & m[None, :]) for m in gate])
    return log_p, support, harmonic, best, depth


def _read(grid, n_arr, k_arr, modulation, top, resolution, live):
    """Bins and readability of the template's lines (n f' + k f_m) at each fundamental of
    ``grid`` (rows): a line is read where a valid bin lies within one bin of it, below
    ``top`` [Hz], and once (a line whose three bins overlap an earlier line's is not read
    again: Fisher's combination needs independent lines)."""
    freq = grid[:, None] * n_arr[None, :] + k_arr[None, :] * (modulation or 0.0)
    index = np.rint(freq / resolution).astype(int)
    size = live.size
    inside = (freq > 0.5 * resolution) & (freq <= top) & (index >= 1) & (index < size - 1)
    index = np.clip(index, 1, size - 2)
    readable = inside & live[index]
    # (BPFO of a 6203 is 3.053 x shaft: n BPFO + 2 shaft and (n + 1) BPFO - shaft fall in
    # one bin, and white noise then passed the outer race's test 7 x too often)
    # only pairs of lines that come within LINE_BINS of each other somewhere on the grid
    # (their distance is linear in f': its smallest modulus over the grid's range)
    dn = n_arr[None, :] - n_arr[:, None]
    dk = (k_arr[None, :] - k_arr[:, None]) * (modulation or 0.0)
    lo, hi = dn * float(np.min(grid)) + dk, dn * float(np.max(grid)) + dk
    near = np.where(lo * hi <= 0, 0.0, np.minimum(np.abs(lo), np.abs(hi)))
    first, later = np.nonzero(np.triu(near < (LINE_BINS + 1) * resolution, k=1))
    if first.size:
        hit = (np.abs(index[:, first] - index[:, later]) < LINE_BINS) & readable[:, first]
        blocked = np.zeros(readable.shape, bool)
        for j in np.unique(later):
            blocked[:, j] = np.any(hit[:, later == j], axis=1)
        readable &= ~blocked
    return index, readable


def _continuation(grid, n_max, orders, modulation, top, ref_top, resolution, live):
    """The family's lines beyond the search limit ``top`` up to ``ref_top`` [Hz]: its
    harmonics n > ``n_max`` and their sidebands at each fundamental of ``grid`` - bins
    (rows x lines, -1 where none reads) and sideband orders (lines)."""
    if ref_top <= top * (1 + 1e-9):
        return None
    n_top = int(math.floor(ref_top / float(np.min(grid))))
    if n_top <= n_max:
        return None
    ns = np.arange(n_max + 1, n_top + 1)
    ks = [0] + ([s * k for k in range(1, int(orders) + 1) for s in (-1, 1)] if modulation else [])
    n_arr = np.repeat(ns, len(ks)).astype(float)
    k_arr = np.tile(np.array(ks, float), ns.size)
    freq = grid[:, None] * n_arr[None, :] + k_arr[None, :] * (modulation or 0.0)
    index = np.rint(freq / resolution).astype(int)
    ok = (freq > top) & (freq <= ref_top) & (index >= 1) & (index < live.size - 1)
    return np.where(ok, index, -1), k_arr


def _fisher_rows(logp: np.ndarray, readable: np.ndarray) -> np.ndarray:
    """ln of Fisher's combination, row by row, over the readable entries only."""
    lines = readable.sum(axis=1)
    out = np.zeros(logp.shape[0])
    live = lines > 0
    statistic = -2.0 * np.where(readable, logp, 0.0)[live].sum(axis=1)
    out[live] = chi2_logsf(statistic, 2 * lines[live])
    return out
