"""Significance of a fault family's harmonic series in an envelope spectrum, above its
local noise floor.

Layer 1 (NumPy and ``scipy.special``). :func:`series_test` reads a family's lines on the
squared envelope spectrum normalised to its noise floor (:mod:`.statistics`), each line's
p-value from the line statistic (:mod:`.tail`), and combines them into the family's
p-value, scanned over its fundamental and bounded for the scan (:mod:`.chain`).

The test of a fault family (outer race, inner race, ball, cage):
1. the noise floor is the running median of the SES over FLOOR_BINS bins, turned into
   the mean of the chi-square law (:func:`bearinglab.diagnosis.statistics.normalised`);
2. a line expected at frequency f is read as the largest normalised value z over the
   bin nearest f and its two neighbours (the line's own width under a Hann window); its
   p-value is its rank among the same reading at every position where a line may stand
   and, beyond the reference's upper quantile, a peaks-over-threshold law fitted to the
   positions that are not the family's own lines at that fundamental
   (:func:`bearinglab.diagnosis.tail.tail_tables`, ``tail=True``, the diagnosis'
   reading); the speed check and the stray-series search read the rank alone
   (:func:`bearinglab.diagnosis.tail.line_rank_logp`, ``tail=False``);
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
   (:func:`bearinglab.diagnosis.chain.chain_logp`, after Hunter D., J. Appl. Prob. 13
   (1976) 597-603 and Worsley K. J., Biometrika 69 (1982) 297-302: within 10-25 % of the
   scan's true law for harmonics alone, 2-3 times above it with the sidebands'
   templates, where the count of distinct sets of lines, Bonferroni, is 3-5 times
   above); the rank's reading multiplies it by the count of distinct sets of lines and
   templates (Bonferroni);
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
probability. Source of the envelope analysis: Randall R. B., Antoni J., "Rolling element
bearing diagnostics - A tutorial", MSSP 25(2) (2011) 485-520.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .statistics import chi2_logsf, decades, fisher_logp
from .tail import OWN_BINS, line_hills, line_rank_logp, tail_tables

#: Bins read around each expected line (the nearest and its two neighbours).
LINE_BINS = 3
#: Level the family must still reach without its strongest line [-].
SUPPORT_ALPHA = 0.01
#: Level at which a single line shows: a line of an accepted family is listed at it, and
#: a carrier must reach it for its sidebands to count in a carrier-gated harmonic test [-].
LINE_ALPHA = 0.01


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
    shared: dict | None = None,
) -> SeriesTest:
    """Significance of the harmonic series n f' (n = 1..``harmonics``) with its sidebands
    n f' +- k ``modulation`` and the modulation's lines k ``modulation``
    (k = 1..``orders``), f' scanned over
    [(1 - below) f, (1 + above) f] (see the module docstring).

    Parameters
    ----------
    z : numpy.ndarray
        Normalised SES (:func:`.statistics.normalised`), bin k at k x ``resolution`` [Hz].
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
    shared : dict, optional
        A store for what does not depend on the family - the three-bin readings, the
        lines' hills, the reference and its tail's fit - kept by the caller across the
        families tested on one spectrum with one ``valid`` (it must be new, or empty,
        whenever ``z`` or ``valid`` change); the results are the same without it.

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
    shared = {} if shared is None else shared
    key = ("window", keep)
    if key not in shared:
        shared[key] = _window_max(z, valid)
    zmax, count, offset = shared[key]
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
        if ("hills", keep) not in shared:
            shared["hills", keep] = line_hills(np.where(valid, z, 0.0), offset)
        hills = shared["hills", keep]
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
            shared,
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
    from .chain import chain_bounds, chain_counts

    depths = tuple(tables)
    # every template's Fisher combinations in one pass (the templates share one table of
    # line p-values when the tail reads them: tail_tables)
    same = all(tables[d] is tables[depths[0]] for d in depths)
    stacked = tables[depths[0]][None] if same else np.stack([tables[d] for d in depths])
    combined = _fisher_rows(stacked, np.stack([uses[d] for d in depths]))
    combos = dict(zip(depths, combined, strict=True))
    depth = min(depths, key=lambda d: float(np.min(combos[d])))
    best = int(np.argmin(combos[depth]))
    # the three scans' levels first, then their chain bounds together
    levels = [float(combos[depth][best])]
    chains = [chain_counts(index, np.stack([uses[d] for d in depths]))]
    row = uses[depth][best]
    if row.sum() > 1:
        strongest = int(np.flatnonzero(row)[np.argmin(tables[depth][best][row])])
        keep = np.ones(n_arr.size, bool)
        keep[strongest] = False
        levels.append(
            min(
                float(fisher_logp(tables[d][best][uses[d][best] & keep]))
                for d in depths
                if (uses[d][best] & keep).any()
            )
        )
        rows = np.abs(index[:, strongest] - index[best, strongest]) <= 1
        sub = np.stack([uses[d][rows] & keep[None, :] for d in depths])
        chains.append(chain_counts(index[rows], sub))
    readable = uses[depths[-1]]
    gate = _gate_masks(tables[0][best], readable[best], n_arr, k_arr, gate_orders, gate_carriers)
    if gate:
        levels.append(
            min(
                float(fisher_logp(tables[min(int(np.max(np.abs(k_arr[m]))), depths[-1])][best][m]))
                for m in gate
            )
        )
        chains.append(chain_counts(index, np.stack([readable & m[None, :] for m in gate])))
    bounds = chain_bounds(levels, chains)
    log_p = bounds[0]
    support = bounds[1] if row.sum() > 1 else 0.0
    harmonic = bounds[-1] if gate else 0.0
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
    index = np.minimum(np.maximum(index, 1), size - 2)
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
    """ln of Fisher's combination, row by row (the last axis: lines), over the readable
    entries only; ``readable`` (rows x lines, or stacked: templates x rows x lines)
    broadcast against ``logp``."""
    lines = readable.sum(axis=-1)
    out = np.zeros(lines.shape)
    live = lines > 0
    statistic = -2.0 * np.where(readable, logp, 0.0)[live].sum(axis=-1)
    out[live] = chi2_logsf(statistic, 2 * lines[live])
    return out
