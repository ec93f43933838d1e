"""Train on physics, test on reality: a classifier trained only on synthetic records of the
CWRU drive-end bearing, scored on the real CWRU recordings.

1. ``bearinglab.dataset.make_dataset`` makes labelled records of the 6205-2RS (9 balls) at
   1720-1800 rpm, 12 kHz, 1 s each, faults none / outer / inner / ball with widths of the
   CWRU EDM faults (0.18-0.71 mm), outer-race defects in the load zone (where the rigid
   model makes them strike), random load, raceway waviness, measurement noise and one
   resonance of the path to the sensor (2-5 kHz, damping 0.02-0.1); rigid model. It is read
   back with ``bearing_datasets.open`` like any public set.
2. Features with a physical meaning, the same for both: ``diagnosis.analyze_signal``
   demodulates each 1 s segment in its band of largest spectral kurtosis and labels the
   envelope lines; for each fault (outer race, inner race, ball, cage) the feature is its
   diagnosis score (sum of A/n over its lines and sidebands) over the spectrum's median,
   and the same for the shaft's harmonics 1-3, all as log10(1 + ratio).
3. A scikit-learn logistic regression (standardised features) trained on the synthetic
   segments; scored on every 1 s segment of the CWRU drive-end records listed in
   ``labels.csv`` (12 kHz, and the 48 kHz healthy record), and per record by majority vote.

The confusion matrices are a measurement, not a target: nothing here is tuned to the real
records. Run: .venv/bin/python examples/synthetic_to_real.py [REAL_DIR] [--records N]
(REAL_DIR defaults to ../shared/data/real relative to the repository).
"""

import argparse
import math
import tempfile
from pathlib import Path

import numpy as np
import pandas as pd

from bearinglab.catalog import bearing_from_designation
from bearinglab.dataset import make_dataset
from bearinglab.diagnosis import analyze_signal
from bearinglab.kinematics import defect_frequencies
from bearinglab.signal import read_signal

CLASSES = ("normal", "outer", "inner", "ball")
FAULTS = ("outer_race", "inner_race", "ball", "cage")
FAMILIES = ("outer_score", "inner_score", "ball_score", "cage_score", "shaft")
SEGMENT_S = 1.0
REPO = Path(__file__).resolve().parents[1]


def features(x: np.ndarray, fs: float, kin) -> list[float]:
    """Per fault family, log10(1 + score / median envelope amplitude), where the score is
    analyze_signal's (sum of A/n over the envelope lines matched to that family, each line
    labelled once: a BPFO harmonic is not also counted as a ball line); and the same for
    the shaft's harmonics 1-3 (lines within 2 %)."""
    d = analyze_signal(x, fs, kin)
    f, a = d.spectrum.frequency, d.spectrum.amplitude
    shown = (f > 0) & (f <= d.max_frequency)
    floor = float(np.median(a[shown])) or 1e-30
    out = [math.log10(1.0 + d.scores.get(fault, 0.0) / floor) for fault in FAULTS]
    shaft = 0.0
    for n in (1, 2, 3):
        window = (f >= 0.98 * n * kin.shaft_hz) & (f <= 1.02 * n * kin.shaft_hz)
        shaft += float(a[window].max()) / n if window.any() else 0.0
    return [*out, math.log10(1.0 + shaft / floor)]


def segments(x: np.ndarray, fs: float):
    n = int(SEGMENT_S * fs)
    for start in range(0, len(x) - n + 1, n):
        yield x[start : start + n]


def synthetic(out: Path, records: int, seed: int) -> pd.DataFrame:
    import bearing_datasets

    make_dataset(
        out,
        records,
        seed=seed,
        progress=None,
        bearings=["6205-2RS"],
        speed_rpm=(1720.0, 1800.0),
        radial_load_n=(100.0, 1500.0),
        faults=["none", "outer", "inner", "ball"],
        defect_width_mm=(0.18, 0.71),
        defect_depth_mm=(0.1, 0.3),
        defect_position_deg=(-135.0, -45.0),
        waviness_amplitude_um=(0.0, 0.3),
        noise_ms2=(0.5, 10.0),
        resonances=[((2000.0, 5000.0), (0.02, 0.1))],
        sample_rate_hz=12000.0,
        duration_s=SEGMENT_S,
        model="rigid",
    )
    ds = bearing_datasets.open(out.name, root=out.parent)
    meta = ds.metadata()
    bearing, _ = bearing_from_designation("6205-2RS")
    rows = []
    for _, r in meta.iterrows():
        kin = defect_frequencies(bearing, r["speed_rpm"] * math.pi / 30)
        label = {"rolling_element": "ball"}.get(r["fault_type"], r["fault_type"])
        rows.append([label, *features(ds.signal(r["signal_id"]).astype(float), r["fs"], kin)])
    return pd.DataFrame(rows, columns=["label", *FAMILIES])


def real(folder: Path) -> pd.DataFrame:
    labels = pd.read_csv(folder / "labels.csv")
    labels = labels[labels["dataset"] == "CWRU"]
    bearing, _ = bearing_from_designation("6205-2RS")
    rows = []
    for _, r in labels.iterrows():
        s = read_signal(folder / r["file"], sample_rate=r["sample_rate_hz"])
        kin = defect_frequencies(bearing, r["speed_rpm"] * math.pi / 30)
        for x in segments(s.channel("DE"), s.sample_rate):
            rows.append([r["file"], r["fault"], *features(x, s.sample_rate, kin)])
    return pd.DataFrame(rows, columns=["file", "label", *FAMILIES])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument(
        "real", nargs="?", type=Path, default=REPO / ".." / "shared" / "data" / "real"
    )
    parser.add_argument("--records", type=int, default=400)
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()
    from sklearn.linear_model import LogisticRegression
    from sklearn.metrics import confusion_matrix
    from sklearn.pipeline import make_pipeline
    from sklearn.preprocessing import StandardScaler

    with tempfile.TemporaryDirectory() as tmp:
        train = synthetic(Path(tmp) / "cwru_synthetic", args.records, args.seed)
    test = real(args.real)
    model = make_pipeline(StandardScaler(), LogisticRegression(max_iter=2000))
    model.fit(train[list(FAMILIES)], train["label"])
    test["predicted"] = model.predict(test[list(FAMILIES)])
    labels = list(CLASSES)

    def show(title, truth, predicted):
        m = confusion_matrix(truth, predicted, labels=labels)
        print(
            f"\n{title}: rows true, columns predicted "
            f"(accuracy {np.trace(m) / m.sum():.2f}, {m.sum()} items)"
        )
        print(pd.DataFrame(m, index=labels, columns=labels).to_string())

    print(
        f"trained on {len(train)} synthetic records "
        f"({', '.join(f'{k} {v}' for k, v in train['label'].value_counts().items())})"
    )
    show(
        "synthetic training set (resubstitution)",
        train["label"],
        model.predict(train[list(FAMILIES)]),
    )
    show("real CWRU drive-end, 1 s segments", test["label"], test["predicted"])
    votes = test.groupby("file").agg(
        label=("label", "first"), predicted=("predicted", lambda p: p.mode().iloc[0])
    )
    show("real CWRU drive-end, per record (majority vote)", votes["label"], votes["predicted"])
    print("\nper record:")
    print(votes.to_string())


if __name__ == "__main__":
    main()
