"""The ``dataset`` request: its inputs - the table's inputs it varies per record (read as
V, LOW:HIGH or A,B,C, each value in the table's range) and its own - and
:func:`dataset_from`, which calls :func:`~bearinglab.dataset.generate.make_dataset` once
and says what the request made moot."""

from __future__ import annotations

from dataclasses import dataclass, field

from ..analyses.base import FILES, Analysis
from ..errors import InputError
from ..inputs import INPUTS, Input, input_for, no_effect

#: More records than this need `yes`.
CONFIRM_RECORDS = 1000
#: The forms of an input drawn per record.
_RANGE = "V, LOW:HIGH (uniform) or A,B,C (one of)"


def _ranged(name: str, default: str, help_: str, table: bool = True) -> Input:
    """An input drawn per record: the table's ``name`` read as a range, or the data set's
    own when it is not in the table; it sets the data set's parameter of its name."""
    what = f"{help_}: {_RANGE}."
    if table:
        return INPUTS[name].with_(kind="text", default=default, help=what, sets=name)
    return Input("text", default, what, sets=name)


#: The data set's inputs, in the order the command line lists them.
DATASET_INPUTS: dict[str, Input] = {
    "output": FILES["output"].with_(
        default=...,
        aliases=(),
        help="Folder of the data set; its name is the data set's name "
        "(bearing_datasets.open(NAME, root=PARENT) reads it).",
    ),
    "records": Input("integer", 100, "Number of records.", low=1, what="a number of records"),
    "bearings": Input(
        "text", "6205-2RS", "Designations, A,B,C (one drawn per record).", sets="bearings"
    ),
    "speed_rpm": _ranged("speed_rpm", "1700:1800", "Speed [rpm]"),
    "radial_load_n": _ranged("radial_load_n", "200:2000", "Radial load [N]"),
    "faults": Input(
        "text",
        "none,outer,inner,ball",
        "Fault classes, A,B,C among none, outer, inner, ball, compound (two defects); cage is "
        "refused: the models have no cage defect.",
        sets="faults",
    ),
    "defect_width_mm": _ranged("defect_width_mm", "0.2:1.5", "Defect width [mm]"),
    "defect_depth_mm": _ranged("defect_depth_mm", "0.1:0.3", "Defect depth [mm]"),
    "defect_angle_deg": _ranged(
        "defect_angle_deg",
        "-135:-45",
        "Outer-race defect position from +x towards +y [deg] (-90: bottom of the load zone)",
    ).with_(aliases=("defect_position_deg",), sets="defect_position_deg"),
    "waviness_amplitude_um": _ranged(
        "waviness_amplitude_um", "0", "Raceway waviness amplitude [um]", table=False
    ).with_(aliases=("waviness_um",)),
    "waviness_orders": _ranged("waviness_orders", "2:30", "Waviness orders", table=False),
    "ball_size_error_um": _ranged("ball_size_error_um", "0", "Band of ball diameter errors [um]"),
    "noise_ms2": _ranged("noise_ms2", "0.5:5", "RMS of the measurement noise [m/s^2]"),
    "resonance": Input(
        "texts",
        None,
        "A resonance of the path to the sensor, repeatable: FREQ_HZ@DAMPING_RATIO, each a "
        "value or LOW:HIGH (default 2500:4500@0.02:0.08).",
        sets=("resonances", "resonance frequency", "damping ratio"),
    ),
    "sample_rate_hz": INPUTS["sample_rate_hz"].with_(
        kind="text", default="20000", help="Sample rate [Hz]: V or A,B,C.", sets="sample_rate_hz"
    ),
    "duration_s": _ranged("duration_s", "1", "Record length [s]"),
    "dynamic_model": INPUTS["dynamic_model"].with_(
        choices=(),
        help="rigid (seed 003) or slip (seed 004), or rigid,slip (one drawn per record).",
    ),
    "seed": INPUTS["seed"].with_(default=0, help="Record i's inputs come from the seed and i."),
    "partition_size": INPUTS["partition_size"].with_(help="Records per partition."),
    "scheduler": INPUTS["scheduler"],
    "workers": INPUTS["workers"],
    "yes": INPUTS["yes"].with_(help=f"Make more than {CONFIRM_RECORDS} records."),
}
#: The inputs the data set draws per record.
_DRAWN = (
    "bearings",
    "speed_rpm",
    "radial_load_n",
    "faults",
    "defect_width_mm",
    "defect_depth_mm",
    "defect_angle_deg",
    "waviness_amplitude_um",
    "waviness_orders",
    "ball_size_error_um",
    "noise_ms2",
    "sample_rate_hz",
    "duration_s",
    "dynamic_model",
)


@dataclass(frozen=True)
class DatasetOutcome:
    """A data set made: its ``result`` (:class:`~.generate.DatasetResult`) and the
    ``warnings`` (records that failed, inputs without effect)."""

    result: object
    warnings: tuple = field(default_factory=tuple)

    def to_dict(self) -> dict:
        return {**self.result.to_dict(), "warnings": list(self.warnings)}

    def to_pandas(self):
        return self.result.to_pandas()


def check_values(values: dict) -> None:
    """Each value a table input drawn per record may take lies in the input's range in
    the table: V, LOW:HIGH or A,B,C, every number checked."""
    for name in (
        "speed_rpm",
        "radial_load_n",
        "defect_width_mm",
        "defect_depth_mm",
        "defect_angle_deg",
        "noise_ms2",
        "sample_rate_hz",
        "duration_s",
    ):
        text = values.get(name)
        if text is None:
            continue
        parts = str(text).replace(":", ",").split(",")
        for part in parts:
            try:
                number = float(part)
            except ValueError:
                raise InputError(name, text, _RANGE) from None
            INPUTS[name].check(name, number)


def resonances_of(items) -> list | None:
    """`resonance` FREQ_HZ@DAMPING items -> (frequency range, damping range) texts."""
    if not items:
        return None
    out = []
    for text in items:
        freq, at, zeta = str(text).partition("@")
        if not at or not freq.strip() or not zeta.strip():
            raise InputError(
                "resonance",
                text,
                "FREQ_HZ@DAMPING, each a value or LOW:HIGH, e.g. 2500:4500@0.02:0.08",
            )
        out.append((freq.strip(), zeta.strip()))
    return out


def moot(spec, given: set, values: dict) -> list[str]:
    """The inputs the set's faults and amplitudes make moot, and `workers` off a
    LocalCluster (``given``: the inputs the user gave)."""
    from ..engine import scheduler_of

    where = spec.defect_locations
    defects = ("defect_width_mm", "defect_depth_mm", "defect_angle_deg")
    out = no_effect(
        [(n, not where and n in given) for n in defects],
        "with `faults` none (no record has a defect)",
    )
    out += no_effect(
        [(defects[2], bool(where) and "outer" not in where and defects[2] in given)],
        "without outer or compound in `faults` (it places outer-race defects only)",
    )
    out += no_effect(
        [("waviness_orders", not spec.has_waviness and "waviness_orders" in given)],
        "at `waviness_amplitude_um` 0 (no waviness)",
    )
    scheduler = scheduler_of(values.get("scheduler"))
    return out + no_effect(
        [("workers", values.get("workers") is not None and scheduler != "local")],
        f"with the scheduler {scheduler!r} (it sizes a LocalCluster only)",
    )


def failures(result) -> list[str]:
    """A warning counting the records that failed (left out, listed in failed.csv)."""
    if not result.failed:
        return []
    import csv

    listed = result.path / "_bearinglab" / "failed.csv"
    with open(listed, newline="", encoding="utf-8") as f:
        first = next(csv.DictReader(f), None)
    reason = f"; the first, {first['recording_id']}: {first['error']}" if first else ""
    return [
        f"{result.failed} of {result.records} records failed and were left out (listed in "
        f"{listed}){reason}"
    ]


def dataset_from(values: dict, *, progress=None, given=None) -> DatasetOutcome:
    """The ``dataset`` request: :func:`~.generate.make_dataset` once, every drawn value in
    its input's range first; ``given``: the inputs the user gave (default: those not
    None), for the warnings about inputs without effect."""
    from ..engine import Interrupted
    from .generate import make_dataset

    check_values(values)
    # by the library's name of each (the parameter the input sets)
    ranges = {
        DATASET_INPUTS[name].fields[0]: values[name]
        for name in _DRAWN
        if values.get(name) is not None
    }
    paths = resonances_of(values.get("resonance"))
    if paths is not None:
        ranges["resonances"] = paths
    try:
        result = make_dataset(
            values["output"],
            values["records"],
            seed=values.get("seed") or 0,
            partition_size=values.get("partition_size"),
            scheduler=values.get("scheduler"),
            workers=values.get("workers"),
            max_records=None if values.get("yes") else CONFIRM_RECORDS,
            progress=progress,
            **ranges,
        )
    except InputError as exc:
        if exc.parameter == "records" and "confirmation" in exc.allowed:
            raise InputError(
                "records",
                exc.value,
                f"at most {CONFIRM_RECORDS} without `yes`",
                "confirm with `yes` to make them all",
            ) from None
        name = input_for(exc.parameter, DATASET_INPUTS)
        if name is not None and name != exc.parameter:
            raise InputError(name, exc.value, exc.allowed, exc.hint) from None
        raise
    except Interrupted as exc:
        if exc.total is not None:
            exc.resume = (
                f"{exc.done} of {exc.total} records are kept in {values['output']}; run the "
                f"same command again to make the other {exc.total - exc.done}"
            )
        raise
    given = {k for k, v in values.items() if v is not None} if given is None else set(given)
    warnings = list(result.spec.warnings) + failures(result) + moot(result.spec, given, values)
    return DatasetOutcome(result, tuple(warnings))


DATASET = Analysis(
    "dataset",
    "Labelled synthetic vibration records in the bearing-datasets layout, on dask.",
    DATASET_INPUTS,
    run=dataset_from,
)
