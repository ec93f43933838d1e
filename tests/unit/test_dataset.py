"""bearinglab.dataset: a small synthetic set written and read back with the real
bearing-datasets package (its open() and its schema's validate())."""

import json
import math

import numpy as np
import pytest
from conftest import require

from bearinglab.catalog import bearing_from_designation
from bearinglab.dataset import TransferPath, draw_record, make_dataset, make_record
from bearinglab.dataset.sampling import DatasetSpec
from bearinglab.errors import InputError
from bearinglab.kinematics import defect_frequencies

bd = require("bearing_datasets")
validate = require("bearing_datasets.schema").validate

RANGES = {
    "faults": ["none", "outer", "inner", "ball", "compound"],
    "sample_rate_hz": [12000.0, 20000.0],
    "duration_s": (0.1, 0.2),
    "speed_rpm": (1700.0, 1800.0),
    "waviness_amplitude_um": (0.0, 0.2),
    "ball_size_error_um": 1.0,
    "resonances": [((2000.0, 4000.0), (0.03, 0.06))],
}


def test_written_set_reads_back_with_bearing_datasets(tmp_path):
    r = make_dataset(tmp_path / "synth", 10, seed=4, scheduler="serial", **RANGES)
    assert (r.written, r.failed, r.partitions) == (10, 0, 10)
    ds = bd.open("synth", root=tmp_path)
    meta = ds.metadata()
    manifest = json.loads((tmp_path / "synth" / "manifest.json").read_text())
    validate(meta, manifest["columns"])  # the schema's own check: names, vocabularies
    assert manifest["n_signals"] == len(meta) == 10 and not ds.outdated
    spec = DatasetSpec(10, **RANGES)
    bearing, _ = bearing_from_designation("6205-2RS")
    for _, row in meta.iterrows():
        i = int(row["recording_id"][3:])
        drawn = draw_record(spec, 4, i)
        x = ds.signal(row["signal_id"])
        assert row["fs"] == drawn["sample_rate_hz"]
        assert x.dtype == np.float32 and len(x) == row["n_samples"] == round(
            drawn["duration_s"] * drawn["sample_rate_hz"]
        )
        parts = [
            {"ball": "rolling_element"}.get(d["location"], d["location"]) for d in drawn["defects"]
        ]
        assert row["fault_type"] == ("+".join(parts) or "normal")
        assert row["fault_size_mm"] == max((d["width_mm"] for d in drawn["defects"]), default=0.0)
        assert row["speed_rpm"] == drawn["speed_rpm"]
        kin = defect_frequencies(bearing, drawn["speed_rpm"] * math.pi / 30)
        assert row["bpfo_hz"] == pytest.approx(kin.hz("bpfo"), rel=1e-12)
        assert row["bpfo"] == pytest.approx(kin.orders["bpfo"], rel=1e-12)
        assert row["sensor_at_fault"] == bool(parts)
    # the stored samples are the record made again from (seed, index) alone
    x, _, _ = make_record(spec, 4, 3)
    np.testing.assert_array_equal(ds.signal("rec000003/acc_y"), x)
    g = ds.signal("rec000003/acc_y", unit="g")
    np.testing.assert_allclose(g, x / 9.80665, rtol=1e-6)


def test_resume_and_refusals(tmp_path):
    out = tmp_path / "set"
    first = make_dataset(out, 4, scheduler="serial", duration_s=0.1, partition_size=2)
    meta = (out / "metadata.parquet").read_bytes()
    again = make_dataset(out, 4, scheduler="serial", duration_s=0.1, partition_size=2)
    assert first.computed == 2 and again.computed == 0
    with pytest.raises(InputError, match="different data set"):
        make_dataset(out, 5, scheduler="serial", duration_s=0.1, partition_size=2)
    assert (out / "metadata.parquet").read_bytes() == meta
    with pytest.raises(InputError, match="no cage defect model"):
        make_dataset(tmp_path / "cage", 2, faults=["outer", "cage"])
    with pytest.raises(InputError, match="resonance frequency"):
        make_dataset(
            tmp_path / "fast", 2, sample_rate_hz=[12000, 20000], resonances=[((3000, 6000), 0.05)]
        )
    with pytest.raises(InputError, match="empty"):
        make_dataset(tmp_path / "e", 2, speed_rpm=(1800, 1700))
    with pytest.raises(InputError, match="`yes`"):
        make_dataset(tmp_path / "many", 2000, max_records=1000)
    assert not (tmp_path / "cage").exists() and not (tmp_path / "many").exists()


def test_transfer_path_resonance_and_low_frequency_gain():
    fs = 20000.0
    t = np.arange(40000) / fs

    def gain(path, f):
        x = np.sin(2 * np.pi * f * t)
        return np.std(path.apply(x, fs)[20000:]) / np.std(x[20000:])

    low, high = TransferPath(((3000.0, 0.05),)), TransferPath(((7000.0, 0.1),))
    # |T| of a base-excited stage: 1 far below omega_n, sqrt(1 + 4 zeta^2) / (2 zeta) at
    # omega_n (the pre-warped bilinear transform keeps the resonance where it is)
    assert gain(low, 20.0) == pytest.approx(1.0, rel=1e-3)
    assert gain(low, 3000.0) == pytest.approx(math.sqrt(1.01) / 0.1, rel=0.01)
    assert gain(high, 7000.0) == pytest.approx(math.sqrt(1.04) / 0.2, rel=0.01)
    both = TransferPath(((3000.0, 0.05), (7000.0, 0.1)))
    for f in (500.0, 3000.0, 7000.0):  # stages in series: the gains multiply
        assert gain(both, f) == pytest.approx(gain(low, f) * gain(high, f), rel=0.01)
    with pytest.raises(InputError, match="damping ratio"):
        TransferPath(((3000.0, 1.5),))


def test_a_record_that_cannot_show_its_label_is_refused():
    """An inner-race record sampled at 300 Hz (BPFI ~160 Hz above Nyquist) or shorter than
    a cage revolution was written and labelled "inner" (an audit); now it is a failed
    record with the reason, before any simulating."""
    slow = DatasetSpec(records=1, faults=("inner",), sample_rate_hz=300.0, resonances=())
    with pytest.raises(InputError, match=r"sample_rate_hz = 300.*BPFI.*Nyquist"):
        make_record(slow, 0, 0)
    short = DatasetSpec(records=1, faults=("inner",), duration_s=0.01, resonances=())
    with pytest.raises(InputError, match="duration_s = 0.01 .* one cage revolution"):
        make_record(short, 0, 0)
