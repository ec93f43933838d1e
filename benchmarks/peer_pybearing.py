"""Peer comparison: fault calls of pybearing 1.0.4 on a folder of labelled recordings.

A standalone script for the comparison in docs/capabilities/diagnosis.md (issue 11, item 6).
It does not import bearinglab and is not run by the tests or CI: pybearing lives in its own
virtual environment, never in the project's.

Set-up and run::

    python3 -m venv /tmp/pybvenv
    /tmp/pybvenv/bin/pip install pybearing==1.0.4   # or its wheel; pulls numpy, scipy, ...
    /tmp/pybvenv/bin/python benchmarks/peer_pybearing.py ../shared/data/real
    # optional: the same records' counts from a `bearinglab benchmark --json` file
    /tmp/pybvenv/bin/python benchmarks/peer_pybearing.py ../shared/data/real \
        --bearinglab-json real.json

The folder holds ``labels.csv`` in the format of ``shared/data/real`` (read its README):
CWRU .mat files (variable ``{record_variable}_{channel}_time``) and MFPT .mat files (a
struct ``bearing`` with ``gs``, ``sr`` and ``rate``). A record whose file lacks the labelled
channel is skipped and listed.

How pybearing is scored, with its own functions as they are meant to be used:

1. Defect frequencies: ``pybearing.analysis.get_fault_frequencies`` (its geometry method,
   inner ring rotating) from the label row: designation 6205-2RS is Z = 9, D_w = 7.94 mm,
   d_m = 39.04 mm, 0 deg (the CWRU README's values, also used for the fan-end and base
   channels because the seeded faults are in the drive-end bearing); otherwise the
   ``balls``, ``ball_diameter_mm``, ``pitch_diameter_mm`` and ``contact_angle_deg`` columns.
   pybearing's ``f_rolling_element`` is 2 x its ball-spin frequency, i.e. CWRU's published
   ball order 4.7135 (pybearing gives 4.7134 at 1 Hz); that is the ball family here.
2. Envelope and score: ``pybearing.analysis.filter_search_for_envelope_extraction`` with
   ``max_level=1``, which evaluates one band only, its full band [0.001 fs, 0.499 fs] (a
   2nd-order Butterworth band-pass of the raw signal, then ``envelope_extraction``: the
   modulus of the analytic signal), takes the envelope's periodogram and scores every
   defect frequency by its harmonics score: with n_harmonics = 3 bands of width
   max(absolute_error, relative_error * k f, 2 bins) centred on k f,
   score = rms(bands) / rms(rest of the spectrum) * log(1 + rms(bands)).
   Defaults: relative_error = 0.02 (pybearing's "relative error tolerance": the band is
   2 % of k f wide, i.e. +-1 %), absolute_error = 1 Hz (pybearing's default).
3. Verdict: the family with the largest score among outer race (BPFO), inner race (BPFI),
   ball (2 x BSF) and cage (FTF). The score is the same ratio of the same spectrum for every
   family, so it is compared as it is (pybearing's only normalisation, a z-score over the
   bands of a filter search, applies across bands of one family, not across families).
   pybearing has no "no fault" answer: every record, the healthy one too, gets a fault.
"""

from __future__ import annotations

import argparse
import csv
import json
import sys
from pathlib import Path

import numpy as np
import scipy.io
from pybearing.analysis import filter_search_for_envelope_extraction, get_fault_frequencies
from pybearing.core import Bearing

# The CWRU README's drive-end bearing (SKF 6205-2RS JEM).
DESIGNATIONS = {"6205-2RS": {"N_b": 9, "D_b": 7.94, "D_m": 39.04, "theta": 0.0}}
# pybearing's score attribute -> the label's fault name.
FAMILIES = {"outer_ring": "outer", "inner_ring": "inner", "rolling_element": "ball", "cage": "cage"}
# bearinglab's verdict -> the label's fault name.
BEARINGLAB_NAMES = {"outer_race": "outer", "inner_race": "inner", "ball": "ball", "cage": "cage"}


def bearing_from_row(row: dict) -> Bearing:
    """The bearing of a label row, in pybearing's dataclass (mm, radians)."""
    name = row.get("designation") or ""
    if name:
        geometry = DESIGNATIONS[name]
    else:
        geometry = {
            "N_b": int(row["balls"]),
            "D_b": float(row["ball_diameter_mm"]),
            "D_m": float(row["pitch_diameter_mm"]),
            "theta": np.radians(float(row["contact_angle_deg"] or 0.0)),
        }
    # Bore, outside diameter and width do not enter the defect frequencies.
    return Bearing(name=name or "label geometry", d=1.0, D=2.0, B=1.0, **geometry)


def load_signal(folder: Path, row: dict) -> tuple[np.ndarray | None, float, str]:
    """The record's channel and sample rate, or None and the reason it is missing."""
    mat = scipy.io.loadmat(folder / row["file"])
    fs = float(row["sample_rate_hz"])
    if "bearing" in mat:  # MFPT: a struct with the signal and its sample rate
        struct = mat["bearing"][0, 0]
        channel = row["channel"]
        if channel not in struct.dtype.names:
            return None, fs, f"no field bearing.{channel}"
        fs = float(np.squeeze(struct["sr"]))
        return np.asarray(struct[channel], dtype=float).ravel(), fs, ""
    key = f"{row['record_variable']}_{row['channel']}_time"
    if key not in mat:
        return None, fs, f"no variable {key}"
    return np.asarray(mat[key], dtype=float).ravel(), fs, ""


def pybearing_scores(
    x: np.ndarray, fs: float, row: dict, relative_error: float, absolute_error: float
) -> dict[str, float]:
    """pybearing's harmonics score of each family on the envelope of the full band."""
    frequencies = get_fault_frequencies(bearing_from_row(row), float(row["speed_rpm"]))
    result = filter_search_for_envelope_extraction(
        x,
        fs,
        frequencies,
        max_level=1,
        n_harmonics=3,
        absolute_error=absolute_error,
        relative_error=relative_error,
    )
    assert len(result.level) == 1  # one band: the full band
    scores = result.harmonics_score
    return {family: float(getattr(scores, family)[0]) for family in FAMILIES}


def outcome(label: str, call: str | None) -> str:
    """right, wrong fault (a fault that is not the label) or no fault."""
    if call is None:
        return "right" if label == "normal" else "no fault"
    return "right" if call == label else "wrong fault"


def bearinglab_call(verdict: str) -> str | None:
    """bearinglab's verdict as a label name (None: no fault; compound: as written)."""
    if verdict == "no fault detected":
        return None
    return BEARINGLAB_NAMES.get(verdict, verdict)


def counts(outcomes: list[str]) -> str:
    return ", ".join(f"{outcomes.count(k)} {k}" for k in ("right", "wrong fault", "no fault"))


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder", type=Path, help="folder holding labels.csv and the files")
    parser.add_argument("--relative-error", type=float, default=0.02)
    parser.add_argument("--absolute-error", type=float, default=1.0)
    parser.add_argument("--bearinglab-json", type=Path, help="bearinglab benchmark --json")
    args = parser.parse_args(argv)

    with open(args.folder / "labels.csv", newline="", encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    records, skipped = [], []
    print(
        f"pybearing 1.0.4 on {args.folder} (relative_error {args.relative_error}, "
        f"absolute_error {args.absolute_error} Hz, 3 harmonics, full-band envelope)"
    )
    print(
        f"{'file':34s} {'channel':7s} {'label':6s} {'pybearing':9s} {'':5s} "
        "scores: outer inner ball cage"
    )
    for row in rows:
        x, fs, reason = load_signal(args.folder, row)
        if x is None:
            skipped.append((row["file"], reason))
            continue
        scores = pybearing_scores(x, fs, row, args.relative_error, args.absolute_error)
        call = FAMILIES[max(scores, key=scores.get)]
        result = outcome(row["fault"], call)
        records.append(
            {"file": row["file"], "label": row["fault"], "call": call, "outcome": result}
        )
        marks = " ".join(f"{scores[f]:.3g}" for f in FAMILIES)
        print(
            f"{row['file']:34s} {row['channel']:7s} {row['fault']:6s} {call:9s} "
            f"{'right' if result == 'right' else 'WRONG':5s} {marks}"
        )
    for file, reason in skipped:
        print(f"{file:34s} skipped: {reason}")
    peer = [r["outcome"] for r in records]
    print(f"pybearing: {peer.count('right')} right of {len(records)} ({counts(peer)})")

    if args.bearinglab_json:
        report = json.loads(args.bearinglab_json.read_text(encoding="utf-8"))
        by_file = {r["file"]: r for r in report["records"]}
        done = [r for r in records if r["file"] in by_file and by_file[r["file"]]["error"] is None]
        print(f"bearinglab ({args.bearinglab_json.name}) on the same {len(done)} records:")
        for column in report["columns"]:
            got = [outcome(r["label"], bearinglab_call(by_file[r["file"]][column])) for r in done]
            print(f"  {column:15s} {counts(got)}")
        print(f"  {'pybearing':15s} {counts([r['outcome'] for r in done])}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
