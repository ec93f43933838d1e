"""The on-disk layout of the ``bearing-datasets`` package (PyPI ``bearing-datasets`` 0.3,
``bearing_datasets/schema.py``, schema version 2), written without importing it:

    <root>/<name>/manifest.json       name, counts, column descriptions, schema_version
    <root>/<name>/metadata.parquet    one row per signal, the schema's standard columns
    <root>/<name>/signals/part-*.parquet   ``signal_id`` and ``signal`` (list of samples);
                                      a signal is row ``signal_row`` of row group
                                      ``signal_row_group`` of ``signal_file``

so that ``bearing_datasets.open(name, root=<root>)`` reads it like a public data set.
Each partition of records is one signal file (one row group); bearinglab's own files
(what the set is, per-partition metadata) sit in ``_bearinglab/``, which the reader
ignores. Column names are the schema's (``fault_type``, ``speed_rpm``, ``bpfo`` as an
order of the shaft speed, ...); the ground truth the schema has no name for gets
bearinglab names with their unit (``bpfo_hz``, ``fault_depth_mm``), each described in the
manifest as the schema asks.
"""

from __future__ import annotations

import hashlib
import json

import numpy as np

#: Layout version of bearing-datasets' schema.py this writes.
SCHEMA_VERSION = 2
CHANNEL = "acc_y"
DTYPE = "float32"
#: Our fault class -> the schema's fault_type part (ISO 5593 names: a ball is a rolling
#: element).
FAULT_TYPE = {"outer": "outer", "inner": "inner", "ball": "rolling_element"}

#: Description of every column written (the manifest's ``columns``).
COLUMNS = {
    "dataset": "dataset name",
    "signal_id": "unique id of the signal: <recording_id>/<channel>",
    "recording_id": "id of the simulated record",
    "native_label": "bearinglab's fault class: normal, outer, inner, ball or a '+'-joined "
    "compound (e.g. outer+ball)",
    "channel": "acc_y: acceleration in the load direction at the sensor (after the transfer "
    "path and the measurement noise)",
    "sensor_location": "the sensor measures the simulated test bearing",
    "fs": "sampling rate in Hz",
    "n_samples": "number of samples",
    "fault_type": "fault(s) in the bearing, '+'-joined: normal, outer, inner, rolling_element",
    "fault_location": "test_bearing for each fault part; none if normal",
    "sensor_at_fault": "True when the bearing has a fault (the sensor is on it)",
    "signal_file": "signals/ file holding the samples",
    "signal_row_group": "row group of signal_file holding the samples",
    "signal_row": "row inside that row group",
    "quantity": "acceleration",
    "unit": "m/s^2",
    "sensitivity": "none: the values are in m/s^2",
    "axis": "vertical: the direction of the radial load",
    "sensor_mounting": "pedestal: the model's outer ring and housing mass",
    "speed_rpm": "true shaft (inner ring) speed in rpm, constant over the record",
    "speed_profile": "constant",
    "load": "radial load on the shaft, in load_unit",
    "load_unit": "N",
    "fault_origin": "artificial: a defect of given size put in the model; none if healthy",
    "fault_size_mm": "width of the defect along the rolling direction in mm (compound: the "
    "widest); 0 if healthy",
    "fault_severity": "not graded (see fault_size_mm); none if healthy",
    "fault_severity_level": "0 healthy, 1 faulty (not graded)",
    "bearing_id": "each simulated record is its own bearing: the recording_id",
    "bearing_model": "bearing designation (or 'user geometry')",
    "bpfo": "ball pass frequency, outer race, in orders of the shaft speed (kinematic)",
    "bpfi": "ball pass frequency, inner race, in orders of the shaft speed (kinematic)",
    "bsf": "ball spin frequency (1x) in orders of the shaft speed (kinematic)",
    "ftf": "cage frequency in orders of the shaft speed (kinematic)",
    "bpfo_hz": "kinematic BPFO at the true speed [Hz]",
    "bpfi_hz": "kinematic BPFI at the true speed [Hz]",
    "bsf_hz": "kinematic ball spin frequency at the true speed [Hz]",
    "ftf_hz": "kinematic cage frequency at the true speed [Hz]",
    "ball_defect_hz": "kinematic ball-defect rate 2 x BSF at the true speed [Hz]",
    "fault_depth_mm": "depth of the (first) defect in mm; 0 if healthy",
    "fault_position_deg": "position of the (first) defect: outer race, fixed angle from +x "
    "towards +y (-90 = bottom of the load zone); inner race, its angle "
    "at t = 0; ball, its spin phase at t = 0; 0 if healthy",
    "defects_json": "every defect of the record (location, width_mm, depth_mm, angle_deg, "
    "ball) as JSON",
    "simulation_model": "bearinglab dynamic model: rigid (seed 003) or slip (seed 004)",
    "noise_rms_m_s2": "RMS of the white measurement noise added at the sensor [m/s^2]",
    "transfer_path_json": "resonances of the path to the sensor: frequencies [Hz] and damping "
    "ratios, as JSON",
    "waviness_amplitude_um": "amplitude of the outer and inner raceway waviness [um]",
    "waviness_json": "raceway waviness (race, order, phase_deg) as JSON",
    "ball_size_error_band_um": "band of the random ball diameter errors [um]",
    "record_seed": "seed of the record's noise and ball-size errors",
}


def digest(x: np.ndarray) -> str:
    """SHA-256 of a signal as bearing-datasets hashes it (dtype name, then the bytes)."""
    return hashlib.sha256(x.dtype.name.encode() + np.ascontiguousarray(x).tobytes()).hexdigest()


def content_hash(digests: dict) -> str:
    """The manifest's content hash: SHA-256 over sorted ``signal_id:digest`` lines."""
    h = hashlib.sha256()
    for sid in sorted(digests):
        h.update(f"{sid}:{digests[sid]}\n".encode())
    return h.hexdigest()


def metadata_row(
    name: str, recording: str, record: dict, bearing, kinematic, n: int, sample_rate: float
) -> dict:
    """One metadata row (without the signal location) of a record."""
    defects = record["defects"]
    parts = [FAULT_TYPE[d["location"]] for d in defects]
    fault_type = "+".join(parts) if parts else "normal"
    faulty = bool(parts)
    first = defects[0] if defects else {}
    orders = kinematic.orders
    return {
        "dataset": name,
        "signal_id": f"{recording}/{CHANNEL}",
        "recording_id": recording,
        "native_label": "+".join(d["location"] for d in defects) or "normal",
        "channel": CHANNEL,
        "sensor_location": "test_bearing",
        "fs": float(sample_rate),
        "n_samples": int(n),
        "fault_type": fault_type,
        "fault_location": "+".join(["test_bearing"] * len(parts)) or "none",
        "sensor_at_fault": faulty,
        "quantity": "acceleration",
        "unit": "m/s^2",
        "sensitivity": "none",
        "axis": "vertical",
        "sensor_mounting": "pedestal",
        "speed_rpm": float(record["speed_rpm"]),
        "speed_profile": "constant",
        "load": float(record["radial_load_n"]),
        "load_unit": "N",
        "fault_origin": "artificial" if faulty else "none",
        "fault_size_mm": max((d["width_mm"] for d in defects), default=0.0),
        "fault_severity": "not graded" if faulty else "none",
        "fault_severity_level": int(faulty),
        "bearing_id": recording,
        "bearing_model": bearing.name or "user geometry",
        "bpfo": float(orders["bpfo"]),
        "bpfi": float(orders["bpfi"]),
        "bsf": float(orders["bsf"]),
        "ftf": float(orders["ftf"]),
        **{f"{k}_hz": kinematic.hz(k) for k in ("bpfo", "bpfi", "bsf", "ftf", "ball_defect")},
        "fault_depth_mm": float(first.get("depth_mm", 0.0)),
        "fault_position_deg": float(first.get("angle_deg", 0.0)),
        "defects_json": json.dumps(defects),
        "simulation_model": record["model"],
        "noise_rms_m_s2": float(record["noise_ms2"]),
        "transfer_path_json": json.dumps(
            {
                "resonances_hz": [f for f, _ in record["resonances"]],
                "damping_ratios": [z for _, z in record["resonances"]],
            }
        ),
        "waviness_amplitude_um": float(record["waviness_amplitude_um"]),
        "waviness_json": json.dumps(record["waviness"] if record["waviness_amplitude_um"] else []),
        "ball_size_error_band_um": float(record["ball_size_error_um"]),
        "record_seed": int(record["seed"]),
    }


def signal_table(ids: list[str], signals: list[np.ndarray]):
    """The Arrow table of one signal file: ``signal_id`` and ``signal`` (list<float32>)."""
    import pyarrow as pa

    offsets = np.concatenate([[0], np.cumsum([len(x) for x in signals])]).astype(np.int32)
    values = pa.array(np.concatenate(signals) if signals else np.zeros(0, np.float32))
    return pa.table(
        {
            "signal_id": pa.array(ids, pa.string()),
            "signal": pa.ListArray.from_arrays(pa.array(offsets), values),
        }
    )


def manifest(name: str, meta, bearinglab_version: str, citation: str, digests: dict) -> dict:
    """manifest.json of the finished set."""
    import time

    return {
        "dataset": name,
        "title": f"bearinglab synthetic bearing-fault data set {name}",
        "license": "CC0-1.0 (synthetic data generated by the user with bearinglab)",
        "citation": citation,
        "generator": f"bearinglab {bearinglab_version}",
        "schema_version": SCHEMA_VERSION,
        "built_at": time.strftime("%Y-%m-%dT%H:%M:%S"),
        "content_hash": content_hash(digests),
        "n_recordings": int(meta["recording_id"].nunique()),
        "n_signals": len(meta),
        "columns": {c: COLUMNS[c] for c in meta.columns},
    }


def order_columns(meta):
    """Columns in the order of COLUMNS (the schema's required ones first)."""
    return meta[[c for c in COLUMNS if c in meta.columns]]
