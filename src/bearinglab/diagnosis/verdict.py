"""The verdict: which fault families stand out of the noise, and which lines they explain.

1. Discrete lines that are not the bearing's - the shaft frequency and its harmonics, of
   any order, and the harmonics of the supply and gear-mesh frequencies when given - are
   masked, over the reach of their Hann leakage (1 to MAX_MASK_BINS bins either side),
   in every method's spectrum.
2. Every family is tested in every method (:func:`series_test`). With F families and M
   methods the level of each test is P_FA / (F M) (Bonferroni), so that the chance of
   any false alarm on a record with no fault is at most P_FA.
3. The most significant family that passes (its p-value below that level, its harmonics
   alone below SUPPORT_ALPHA, and still below SUPPORT_ALPHA without its strongest line,
   all by one method: the most significant method that passes them all) is accepted;
   its lines
   and their intermodulation with the shaft and cage rates (:func:`explained`) are
   masked and the others are tested again: a second fault is reported only with lines
   of its own (a compound fault), never with lines the first one explains (3 x BPFO of
   a 6205 lies 0.7 % from 2 x BPFI), and with at least MIN_HARMONICS of its harmonics
   shown at LINE_ALPHA.
4. FTF lines beside an accepted ball or outer-race series are that fault's cage-rate
   modulation, not a cage fault. A cage-rate series whose ball lines reach
   BALL_GIVEN_CAGE is a ball fault: the cage carries the defective ball through the
   load zone (Randall & Antoni 2011, sec. 2), ball defects are far commoner than cage
   failures, and a ball's own lines are often weak (issue 11: four CWRU ball records
   were called "cage" from FTF lines alone).

``no fault detected`` is the verdict when no family passes.
"""

from __future__ import annotations

import math

import numpy as np

from .families import FREQUENCY, SIDEBANDS, Family
from .series import LINE_ALPHA, SUPPORT_ALPHA, Line, series_test
from .speed import supply_line
from .statistics import decades, fisher_logp, normalised

#: Fewest harmonics of a family that must show at LINE_ALPHA for it to be called as a
#: second fault beside a first (issue 27: no family is added from a single harmonic) [-].
MIN_HARMONICS = 2
#: Verdict when no family passes.
NO_FAULT = "no fault detected"
#: Level the ball series must reach beside a significant cage-rate series for the verdict
#: to be "ball" rather than "cage" [-] (the cage series already shows the periodicity).
BALL_GIVEN_CAGE = 0.05


#: Widest mask either side of a line [bins].
MAX_MASK_BINS = 12


def leakage_halfwidth(z_peak: float) -> int:
    """Bins either side of a line of normalised power ``z_peak`` within which its Hann
    leakage can still exceed the mean noise level [bins, 1 .. MAX_MASK_BINS].

    The Hann window's power response d bins from a line falls as
    1 / (pi d (d^2 - 1))^2 (d >= 2; Harris F. J., Proc. IEEE 66 (1978) 51-83, the Hann
    kernel); the mask reaches the first d where z_peak times that is below 1.

    >>> leakage_halfwidth(5.0), leakage_halfwidth(1e6)
    (2, 7)
    """
    if not z_peak > 1.0:
        return 1
    for d in range(2, MAX_MASK_BINS + 1):
        if z_peak / (math.pi * d * (d * d - 1)) ** 2 < 1.0:
            return d
    return MAX_MASK_BINS


def mask_line(valid: np.ndarray, z: np.ndarray, i: int) -> None:
    """Mask bin ``i`` and the bins its leakage reaches (in place)."""
    lo, hi = max(i - 1, 0), min(i + 2, z.size)
    if lo >= hi:
        return
    d = leakage_halfwidth(float(np.max(z[lo:hi])))
    valid[max(i - d, 0) : min(i + d + 1, valid.size)] = False


def discrete_mask(
    spectra, lines: dict[str, float | None], max_frequency: float
) -> tuple[dict, dict]:
    """Per method, the bins that may be read (True) once the harmonics of each frequency
    in ``lines`` (name -> Hz: shaft, supply, mesh) are masked with their leakage; and the
    harmonics masked, name -> list of (order, Hz)."""
    valid = {s.method: np.ones(s.frequency.size, bool) for s in spectra}
    resolution = spectra[0].resolution
    masked: dict[str, list] = {}
    for name, f in lines.items():
        if not f or f <= 0:
            continue
        orders = np.arange(1, int(max_frequency / f) + 2)
        for spec in spectra:
            for k in orders:
                i = int(round(k * f / resolution))
                if i < spec.z.size:
                    mask_line(valid[spec.method], spec.z, i)
        masked[name] = [(int(k), float(k * f)) for k in orders if k * f <= max_frequency]
    return valid, masked


def series_shape(lines, second: bool = False) -> str | None:
    """Why the harmonic ``lines`` of a family's best template (:class:`.series.Line`)
    make no fault's series, or None.

    - A fault's series shows in its harmonics: for a first fault, their Fisher
      combination (the harmonics alone, at the best fundamental) reaches LINE_ALPHA - its
      sidebands may carry a weak carrier, but not alone: the ball's sidebands
      n (2 BSF) - n FTF are themselves a harmonic series at 2 BSF - FTF, and the
      drive-end outer-race series of CWRU 130 and 131 (BPFO 107 Hz), read on the
      fan-end channel for the 6203 (2 BSF - FTF = 108 Hz), made a "ball" from them; a
      second fault shows as a series of its own, at least MIN_HARMONICS of its
      harmonics at LINE_ALPHA each (a compound verdict had added an outer race from one
      BPFO harmonic and its sidebands, beside an inner race whose intermodulation puts
      lines there).
    - Harmonics shown that are all multiples of one k >= 2 are a series at k x the
      fundamental, not the family's: a record whose sample rate was given 4 times too
      high reads a BPFO series as BPFO's harmonics 4 and 8.

    >>> from .series import Line
    >>> h = lambda n, p: Line("harmonic", n, 0, 0.0, 0.0, 0.0, math.log(p))
    >>> series_shape([h(1, 1e-3), h(2, 1e-3)]) is None, series_shape([h(1, 0.3), h(2, 0.5)])
    (True, 'its harmonics alone reach only 0.362')
    >>> series_shape([h(1, 1e-3), h(2, 0.5)], second=True)
    'fewer than 2 of its harmonics show at 1 %'
    >>> series_shape([h(4, 1e-9), h(8, 1e-9), h(1, 0.5)])
    'its harmonics shown at 1 %, [4, 8], are those of a series at 4 x it'
    """
    harmonics = [ln for ln in lines if ln.kind == "harmonic" and ln.n >= 1]
    shown = {ln.n for ln in harmonics if ln.log_p < math.log(LINE_ALPHA)}
    if second and len(shown) < MIN_HARMONICS:
        return f"fewer than {MIN_HARMONICS} of its harmonics show at {100 * LINE_ALPHA:g} %"
    together = float(fisher_logp([ln.log_p for ln in harmonics])) if harmonics else 0.0
    if together >= math.log(LINE_ALPHA):
        return f"its harmonics alone reach only {decades(together):.3g}"
    common = math.gcd(*shown) if len(shown) >= 2 else 1
    if common > 1:
        return (
            f"its harmonics shown at {100 * LINE_ALPHA:g} %, {sorted(shown)}, are those of a "
            f"series at {common} x it"
        )
    return None


def _reach(reference, spec):
    """The top of the tail's reference for a method's spectrum [Hz]: ``reference``, or the
    demodulation band's width where that is narrower (the squared envelope of a band holds
    cyclic frequencies up to its width only: beyond, drs-sk's spectrum is its own roll-off)."""
    band = getattr(spec, "band", None)
    if reference is None or band is None:
        return reference
    return min(reference, float(band[1]) - float(band[0]))


def read_families(
    spectra,
    fams: list[Family],
    valid: dict,
    max_frequency: float,
    harmonics: int,
    bottom: float = 0.0,
    reference: float | None = None,
) -> dict:
    """(method, family) -> SeriesTest for every method spectrum and family, each line read
    against the positions from ``bottom`` [Hz] up to ``reference`` [Hz] (default
    ``max_frequency``) by the tail's reading (:func:`series_test` with ``tail``)."""
    out = {}
    for spec in spectra:
        z = spec.z
        shared: dict = {}  # what the families' tests share on this spectrum and mask
        for fam in fams:
            out[spec.method, fam.name] = series_test(
                z,
                spec.resolution,
                spec.nu,
                fam.frequency,
                fam.below,
                fam.above,
                harmonics,
                max_frequency,
                fam.modulation,
                fam.orders,
                valid[spec.method],
                fam.gate_orders,
                bottom,
                fam.gate_carriers,
                tail=True,
                reference=_reach(reference, spec),
                shared=shared,
            )
    return out


def explained(test, modulations: tuple, beyond: float | None = None) -> list[float]:
    """Frequencies an accepted series explains [Hz]: its lines, and around each harmonic
    found its intermodulation with the shaft (+-1, 2 orders) and the cage (+-1): a
    fault's impacts are modulated at both rates (load zone, unbalance, unequal balls),
    and these products must not become the evidence of a second fault. With ``beyond``
    [Hz], its harmonics above those read, up to there, and theirs: the tail's reference
    runs beyond the search limit (:func:`.tail.tail_tables`), where a strong
    series' higher harmonics are no clutter against a second fault's lines (the README's
    ER-16K with an outer-race and a ball defect read "outer race" alone: 22 harmonics of
    BPFO at z 80-140 against the ball's at z 8)."""
    harmonics = [line.frequency_hz for line in test.lines if line.kind == "harmonic"]
    out = [line.frequency_hz for line in test.lines]
    if beyond and test.fundamental_hz > 0 and test.lines:
        last = max(line.n for line in test.lines)
        more = np.arange(last + 1, int(beyond / test.fundamental_hz) + 1) * test.fundamental_hz
        harmonics += list(more)
        out += list(more)
    shaft, ftf = modulations
    for f in harmonics:
        for fm, orders in ((shaft, (1, 2)), (ftf, (1,))):
            out += [f + s * k * fm for k in orders for s in (-1, 1)]
    return out


def decide(
    spectra,
    fams: list[Family],
    base_valid: dict,
    max_frequency: float,
    harmonics: int,
    false_alarm: float,
    modulations: tuple = (0.0, 0.0),
    reference: float | None = None,
    prior: tuple = (),
    alpha: float | None = None,
    bottom: float | None = None,
) -> dict:
    """The greedy verdict over all methods (see the module docstring).

    Returns a dict with ``faults`` (accepted, most significant first), ``tests``
    (family -> its best SeriesTest and method, from the round that accepted it or, for
    the others, the last round), ``alpha`` (level of each test) and ``modulation``
    (FTF lines counted as the cage-rate modulation of an accepted fault).

    ``prior`` names faults already accepted on the record (:mod:`.residual`: the spectra
    are then what is left once the first fault's impacts are removed): every family of
    ``fams`` is read as a second fault, at the level ``alpha`` of the record's first
    reading, against the positions from ``bottom`` [Hz] (default: the lowest of ``fams``).
    """
    if alpha is None:
        alpha = false_alarm / (len(fams) * len(spectra))
    log_alpha, log_support = math.log(alpha), math.log(SUPPORT_ALPHA)
    valid = {m: v.copy() for m, v in base_valid.items()}
    # every family's lines are read against the same positions: where any of them may stand
    if bottom is None:
        bottom = min(f.lowest for f in fams)
    accepted: list[str] = []
    best: dict[str, tuple] = {}
    remaining = [f.name for f in fams]

    def passes(test) -> bool:
        return (
            test.log_p < log_alpha
            and test.harmonic_log_p < log_support
            and test.support_log_p < log_support
            and series_shape(test.lines, bool(accepted or prior)) is None
        )

    ball_beside_cage = None
    while remaining:
        tests = read_families(
            spectra,
            [f for f in fams if f.name in remaining],
            valid,
            max_frequency,
            harmonics,
            bottom,
            reference,
        )
        for name in remaining:
            # the most significant method among those whose test passes every gate (the
            # gates of one method are no reason to drop another's series); else the most
            # significant
            runs = [(m, t) for (m, f), t in tests.items() if f == name]
            runs = [mt for mt in runs if passes(mt[1])] or runs
            best[name] = min(runs, key=lambda mt: (mt[1].log_p, mt[1].support_log_p))
        passing = [n for n in remaining if passes(best[n][1])]
        if not passing:
            break
        winner = min(passing, key=lambda n: (best[n][1].log_p, best[n][1].support_log_p))
        if winner == "cage":
            # the ball test as it stood beside the cage's lines, before they are masked
            ball_beside_cage = best.get("ball")
        accepted.append(winner)
        remaining.remove(winner)
        resolution = spectra[0].resolution
        for f in explained(best[winner][1], modulations, reference):
            i = int(round(f / resolution))
            for spec in spectra:
                if 0 < i < spec.z.size:
                    mask_line(valid[spec.method], spec.z, i)
    modulation = []
    if "cage" in accepted and ({"ball", "outer_race"} & set(accepted + list(prior))):
        accepted.remove("cage")
        modulation = ["cage"]
    elif (
        "cage" in accepted
        and ball_beside_cage is not None
        and ball_beside_cage[1].log_p < math.log(BALL_GIVEN_CAGE)
    ):
        # a cage-rate series with ball lines beside it: the cage carries a ball defect
        accepted[accepted.index("cage")] = "ball"
        best["ball"] = ball_beside_cage
        modulation = ["cage"]
    return {"faults": accepted, "tests": best, "alpha": alpha, "modulation": modulation}


#: Fewest harmonics a fundamental must show to count as a stray series [-].
STRAY_HARMONICS = 3
#: Series explained by a family that are masked before an octave is given up [-].
STRAY_TRIES = 3


def stray_series(
    spec,
    fams: list[Family],
    valid: np.ndarray,
    max_frequency: float,
    level,
    shaft=None,
    supply=None,
):
    """The strongest harmonic series of ``spec`` that none of ``fams`` explains, or None.

    A record analysed with the wrong bearing, or at the wrong speed, hides its fault: the
    families read their lines where there are none. This asks the envelope spectrum
    blindly for any harmonic series (harmonics alone, read as the families' are, the
    machine's lines masked: ``valid``) over fundamentals from the lowest family line to a
    third of the search limit, in octaves, each octave's p-value multiplied by the number
    of octaves (Bonferroni). A series whose fundamental, or its double or half, lies in a
    family's window is the family's (it failed that family's own test), and one within 2 %
    of 1/4 .. 2 x the ``shaft`` rate [Hz] or of a whole multiple of it, or on a harmonic of
    the supply (50 Hz, 60 Hz or ``supply`` [Hz]: :func:`.speed.supply_line`), the
    machine's: its lines are masked and the
    octave is searched again (up to STRAY_TRIES times). Returns ``(fundamental [Hz],
    SeriesTest, ln p)`` of the most significant series that passes ``level`` and both
    gates with at least STRAY_HARMONICS harmonics at LINE_ALPHA, its first and second
    among them (odd orders alone are a ladder of sidebands), else None.
    """
    res = spec.resolution
    low = min(f.lowest for f in fams)
    octaves = []
    while low < max_frequency / STRAY_HARMONICS:
        octaves.append((low, min(2 * low, max_frequency / STRAY_HARMONICS)))
        low *= 2
    log_bands = math.log(max(len(octaves), 1))

    # (name, frequency, below, above) of what explains a series: the families, and the
    # shaft (whose harmonics are masked, but not the leakage beside them that a series
    # drifting off them reads) at its sub- and low multiples
    known = [(f.frequency, f.below, f.above, (0.5, 1.0, 2.0)) for f in fams]
    if shaft:
        known.append((shaft, 0.02, 0.02, (0.25, 1 / 3, 0.5, 1.0, 2.0)))

    def explained(f: float) -> bool:
        # a family's, the shaft's (at 1/4 .. 2 x, or any whole multiple: the machine's
        # harmonics), or the supply's (50, 60 Hz and the supply given, to the 4th
        # harmonic: Normal_600 of the second laboratory showed a series at 60.4 Hz)
        if shaft and f > shaft and abs(f / shaft - round(f / shaft)) <= 0.02 * f / shaft:
            return True
        if supply_line(f, supply):
            return True
        return any(
            fk * (1 - below) <= f * k <= fk * (1 + above)
            for fk, below, above, multiples in known
            for k in multiples
        )

    best = None
    for lo, hi in octaves:
        mid, free = 0.5 * (lo + hi), valid.copy()
        for _ in range(STRAY_TRIES):
            test = series_test(
                spec.z,
                res,
                spec.nu,
                mid,
                1 - lo / mid,
                hi / mid - 1,
                8,
                max_frequency,
                valid=free,
                tail=False,
            )
            if not test.lines or not explained(test.fundamental_hz):
                break
            for line in test.lines:
                mask_line(free, spec.z, int(round(line.frequency_hz / res)))
        shown = {ln.n for ln in test.lines if ln.log_p < math.log(LINE_ALPHA)}
        log_p = test.log_p + log_bands
        if (
            test.lines
            and not explained(test.fundamental_hz)
            and log_p < math.log(level)
            and test.harmonic_log_p + log_bands < math.log(SUPPORT_ALPHA)
            and test.support_log_p + log_bands < math.log(SUPPORT_ALPHA)
            and len(shown) >= STRAY_HARMONICS
            and {1, 2} <= shown  # a series, not a ladder of sidebands (odd orders only)
            and (best is None or log_p < best[2])
        ):
            best = (test.fundamental_hz, test, log_p)
    return best


def with_z(spec):
    """The MethodSpectrum with its normalised power ``z`` [-] filled in (kept when the
    method set its own: ``ies``)."""
    import dataclasses

    if spec.z is not None:
        return spec
    return dataclasses.replace(spec, z=normalised(spec.power, spec.nu))


def label_peaks(
    spec, decision: dict, fams: list[Family], masked: dict, count: int, max_frequency: float
) -> list[dict]:
    """The ``count`` most significant local maxima of ``spec`` up to ``max_frequency``,
    labelled by the accepted families' lines or as a masked discrete line (shaft,
    supply, mesh harmonic of any order)."""
    from ..signal.peaks import local_maxima
    from .statistics import bin_logp

    z, f = spec.z, spec.frequency
    res = spec.resolution
    inside = np.flatnonzero((f > 0) & (f <= max_frequency))
    if inside.size < 3:
        return []
    zi = z[inside]
    index = local_maxima(zi)
    logp = bin_logp(zi[index], spec.nu)
    keep = set(index[logp + math.log(inside.size) < math.log(0.01)].tolist())
    by_name = {fam.name: fam for fam in fams}
    known = {}
    for name in decision["faults"]:
        test = decision["tests"][name][1]
        fam = by_name[name]
        for line in test.lines:
            i = int(round(line.frequency_hz / res))
            known[i] = (fam, line)
            if line.log_p < math.log(LINE_ALPHA) and i <= inside[-1]:
                keep.add(i - int(inside[0]))  # the fault's own lines are listed too
        # every harmonic of the fault found is its line, also those the test did not read
        # (beyond its harmonics, or masked where a shaft harmonic coincides: 7 x BPFO of
        # an ER-16K at 1750 rpm is 25 x shaft)
        f0 = test.fundamental_hz
        for n in range(1, int(max_frequency / f0) + 1):
            i = int(round(n * f0 / res))
            for j in (i, i - 1, i + 1):
                if j not in known:
                    known[j] = (fam, Line("harmonic", n, 0, n * f0, j * res, 0.0, 0.0))
    keep = np.array(sorted(keep), dtype=int)
    keep = keep[np.argsort(zi[keep])[::-1][:count]]
    amplitude = spec.amplitude
    out = []
    for j in keep:
        i = int(inside[j])
        peak = {
            "frequency_hz": float(f[i]),
            "amplitude": float(amplitude[i]),
            "z": float(z[i]),
            "significance": decades(bin_logp(z[i], spec.nu)),
            "matched": None,
            "harmonic": None,
            "deviation": None,
        }
        hit = next((known[k] for k in (i, i - 1, i + 1) if k in known), None)
        if hit is not None:
            fam, line = hit
            name = FREQUENCY[fam.name]
            modulation = SIDEBANDS[fam.name][0]
            if line.n == 0:  # the modulation's own line, k x f_m
                k = abs(int(round(line.k)))
                peak.update(
                    matched=modulation,
                    harmonic=k,
                    deviation=float(f[i] / (k * fam.modulation) - 1.0),
                )
            elif line.kind == "harmonic":
                peak.update(
                    matched=name,
                    harmonic=line.n,
                    deviation=float(f[i] / (line.n * fam.frequency) - 1.0),
                )
            else:
                peak.update(
                    sideband_of=name,
                    sideband_harmonic=line.n,
                    sideband_order=int(round(line.k)),
                    modulation=modulation,
                )
        else:
            for name, orders in masked.items():
                near = [k for k, fk in orders if abs(f[i] - fk) <= 1.5 * res]
                if near:
                    k = near[0]
                    base = orders[0][1]
                    peak.update(matched=name, harmonic=k, deviation=float(f[i] / (k * base) - 1.0))
                    break
        out.append(peak)
    return out


def significance(p: float) -> float:
    """-log10 p [-] of a probability (floored at 1e-300), as :func:`.statistics.decades`
    reads a logarithm."""
    return decades(math.log(max(p, 1e-300)))
