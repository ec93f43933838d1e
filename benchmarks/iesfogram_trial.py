"""The band selector tried for the ``ies`` method and not kept: a family-targeted IESFOgram
paid for by cross-fitting (docs/capabilities/diagnosis.md, "A fourth method").

[Mauricio2020] choose the band of spectral frequencies whose improved envelope spectrum
shows the target fault best, on a 1/3-binary tree. Here, for each fault family, the band
of the kurtogram's tree (at least 3 x the largest defect frequency wide; the spectral
frequencies below the highest cyclic one are not used) whose ``ies`` spectrum gives that
family its largest significance on one half of the record is tested on the other half,
and the other way round: two tests per family, each at P_FA / (4 families x 2), and a
family passes when either passes its three gates. The halves are disjoint, so that the
choice costs nothing on noise. A prototype: each family judged alone, without the greedy
verdict (masks of accepted families, the cage/ball rules).

    python benchmarks/iesfogram_trial.py FOLDER [CHANNEL]     labelled records
    python benchmarks/iesfogram_trial.py --null fan-end|white FOLDER

Prints per record the families passed and their two significances.
"""

from __future__ import annotations

import math
import sys
import time
from pathlib import Path

import numpy as np

import bearinglab.signal.cyclic as cyclic
from bearinglab.catalog import bearing_from_designation
from bearinglab.diagnosis import NO_FAULT, analyze_signal
from bearinglab.diagnosis.benchmark import EXPECTED, _bearing, label_fault, read_labels
from bearinglab.diagnosis.methods import MIN_BAND_FACTOR
from bearinglab.kinematics import defect_frequencies
from bearinglab.signal import read_signal
from bearinglab.signal.kurtogram import USABLE_FRACTION, kurtogram_levels

FAMILIES = ("outer_race", "inner_race", "ball", "cage")
FALSE_ALARM = 0.01
GATE = 2.0  # the harmonic and support gates, -log10 SUPPORT_ALPHA

# the spectral coherence of a half does not depend on the band: compute it once per half
_cache: dict = {}
_coherence = cyclic.spectral_coherence


def _cached(x, *args, **kwargs):
    key = (x.size, float(x[0]), float(x[-1]), float(x[x.size // 3]), args)
    if key not in _cache:
        _cache.clear()
        _cache[key] = _coherence(x, *args, **kwargs)
    return _cache[key]


cyclic.spectral_coherence = _cached


def tree_bands(fs: float, largest: float) -> list[tuple[float, float]]:
    """The kurtogram's 1/3-binary tree down to bands MIN_BAND_FACTOR x ``largest`` wide,
    below the anti-aliasing roll-off, and the whole band."""
    out = [(1.0, 0.4999 * fs)]
    for _level, count in kurtogram_levels(10)[1:]:
        width = fs / 2 / count
        if width < MIN_BAND_FACTOR * largest:
            break
        for i in range(count):
            lo, hi = i * width, (i + 1) * width
            if hi <= USABLE_FRACTION * fs * (1 + 1e-9) and lo > 0:
                out.append((lo, hi))
    return out


def choose(x, fs, kin, largest) -> dict:
    """Family -> the band where its ies test is most significant on ``x``."""
    best = {f: (-1.0, None) for f in FAMILIES}
    for band in tree_bands(fs, largest):
        try:
            d = analyze_signal(x, fs, kin, methods="ies", band=band)
        except Exception:  # a band with too few spectral bins above the cyclic range
            continue
        for f in FAMILIES:
            s = d.families[f]["significance"]
            if s > best[f][0]:
                best[f] = (s, band)
    return {f: b for f, (_, b) in best.items()}


def cross_fitted(x, fs, kin) -> dict:
    """Family -> [(significance, passed)] of the two cross-fitted tests."""
    largest = max(kin.hz(n) for n in ("shaft", "ftf", "bpfo", "bpfi", "ball_defect"))
    half = x.size // 2
    halves = (x[:half].copy(), x[half:].copy())
    level = -math.log10(FALSE_ALARM / (len(FAMILIES) * 2))
    chosen = [choose(h, fs, kin, largest) for h in halves]
    out = {f: [] for f in FAMILIES}
    for i in (0, 1):
        for f in FAMILIES:
            d = analyze_signal(halves[1 - i], fs, kin, methods="ies", band=chosen[i][f])
            t = d.families[f]
            ok = (
                t["significance"] > level
                and t["harmonic_significance"] > GATE
                and t["support_significance"] > GATE
            )
            out[f].append((round(t["significance"], 2), ok))
    return out


def passed(result) -> list[str]:
    return [f for f in FAMILIES if any(ok for _, ok in result[f])]


def _samples(folder, row, channel=None):
    fs = float(row["sample_rate_hz"]) if row.get("sample_rate_hz") else None
    s = read_signal(folder / row["file"], sample_rate=fs, channel=channel or row["channel"])
    return s.channel(s.names[0]), s.sample_rate


def labelled(folder: Path, channel: str | None) -> None:
    for row in read_labels(folder):
        x, fs = _samples(folder, row, channel)
        kin = defect_frequencies(_bearing(row), float(row["speed_rpm"]) * math.pi / 30)
        start = time.perf_counter()
        result = cross_fitted(x, fs, kin)
        got = passed(result)
        want = EXPECTED[label_fault(row["fault"])]
        kind = (
            ("right" if not got else "wrong")
            if want == NO_FAULT
            else ("right" if want in got else "miss" if not got else "wrong")
        )
        print(
            f"{row['file']} {row['fault']} {kind} {got} {time.perf_counter() - start:.0f} s",
            {f: [s for s, _ in result[f]] for f in FAMILIES},
            flush=True,
        )


def null(which: str, folder: Path, seeds: int = 200) -> None:
    bad = total = 0
    if which == "fan-end":
        bearing = bearing_from_designation("6203-2RS")[0]
        for row in read_labels(folder):
            if row["dataset"] != "CWRU":
                continue
            try:
                x, fs = _samples(folder, row, "FE")
            except Exception:  # the file has no fan-end channel
                continue
            got = passed(
                cross_fitted(
                    x, fs, defect_frequencies(bearing, float(row["speed_rpm"]) * math.pi / 30)
                )
            )
            total += 1
            if got:
                bad += 1
                print(row["file"], got, flush=True)
    else:
        kin = defect_frequencies(bearing_from_designation("6205")[0], 1797 * math.pi / 30)
        for seed in range(seeds):
            x = np.random.default_rng(seed).standard_normal(int((1 + seed % 5) * 12000))
            got = passed(cross_fitted(x, 12000.0, kin))
            total += 1
            if got:
                bad += 1
                print(seed, got, flush=True)
    print(f"{which}: {bad} false alarms of {total}")


if __name__ == "__main__":
    args = sys.argv[1:]
    if args and args[0] == "--null":
        null(args[1], Path(args[2] if len(args) > 2 else "../shared/data/real"))
    else:
        labelled(
            Path(args[0] if args else "../shared/data/real"), args[1] if len(args) > 1 else None
        )
