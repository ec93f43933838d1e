"""The ``dataset`` command: labelled synthetic vibration records in the bearing-datasets
layout, made on dask (bearinglab.dataset.make_dataset)."""

from pathlib import Path
from typing import Annotated

import typer
from rich.markup import escape

from ..errors import InputError
from ..inputs import no_effect
from ._app import command_app, console
from ._inputs import (
    JsonOpt,
    OptionError,
    SchedulerOpt,
    WorkersOpt,
    _print_warnings,
    typed,
)
from ._output import _emit_json, _table, progress_bar
from ._preflight import scheduler as preflight_scheduler
from .study import resume_line, run_rows, runner_warnings

app = command_app()

#: More records than this need --yes.
CONFIRM_RECORDS = 1000
_RANGE = "V, LOW:HIGH (uniform) or A,B,C (one of)"
#: Library parameter -> the option the user typed.
_FLAGS = {
    "output": "OUTPUT",
    "records": "--records",
    "scheduler": "--scheduler",
    "workers": "--workers",
    "seed": "--seed",
    "partition_size": "--partition-size",
    "bearings": "--bearings",
    "faults": "--faults",
    "model": "--model",
    "resonances": "--resonance",
    "resonance frequency": "--resonance",
    "damping ratio": "--resonance",
    "waviness_amplitude_um": "--waviness-um",
}


def _ranged(flag: str, what: str):
    """The option of an input drawn per record from V, LOW:HIGH or A,B,C (_RANGE)."""
    return typer.Option(flag, help=f"{what}: {_RANGE}.")


def _resonance(text: str):
    freq, at, zeta = text.partition("@")
    if not at or not freq.strip() or not zeta.strip():
        raise OptionError(
            "--resonance",
            text,
            "FREQ_HZ@DAMPING, each a value or LOW:HIGH, e.g. 2500:4500@0.02:0.08",
        )
    return freq.strip(), zeta.strip()


def _remap(exc: InputError) -> InputError:
    if exc.parameter == "records" and "confirmation" in exc.allowed:
        return OptionError(
            "--records",
            exc.value,
            f"at most {CONFIRM_RECORDS} without --yes",
            "add --yes to make them all",
        )
    flag = _FLAGS.get(exc.parameter, _flag(exc.parameter))
    return OptionError(flag, exc.value, exc.allowed, exc.hint)


def _warnings(spec, given: set) -> list[str]:
    """The options the set's faults and amplitudes make moot (``given``: the parameters
    typed)."""
    where = spec.defect_locations
    defects = ("defect_width_mm", "defect_depth_mm", "defect_position_deg")
    out = no_effect(
        [(_flag(n), not where and n in given) for n in defects],
        "with --faults none (no record has a defect)",
    )
    out += no_effect(
        [(_flag(defects[2]), bool(where) and "outer" not in where and defects[2] in given)],
        "without outer or compound in --faults (it places outer-race defects only)",
    )
    return out + no_effect(
        [("--waviness-orders", not spec.has_waviness and "waviness_orders" in given)],
        "at --waviness-um 0 (no waviness)",
    )


def _failures(result) -> list[str]:
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


def _flag(name: str) -> str:
    return "--" + name.replace("_", "-")


@app.command("dataset")
def dataset(
    ctx: typer.Context,
    output: Annotated[
        Path,
        typer.Argument(
            help="Folder of the data set; its name is the data set's name "
            "(bearing_datasets.open(NAME, root=PARENT) reads it).",
        ),
    ],
    records: Annotated[int, typer.Option("--records", help="Number of records.")] = 100,
    bearings: Annotated[
        str, typer.Option("--bearings", help="Designations, A,B,C (one drawn per record).")
    ] = "6205-2RS",
    speed_rpm: Annotated[str, _ranged("--speed-rpm", "Speed [rpm]")] = "1700:1800",
    radial_load_n: Annotated[str, _ranged("--radial-load-n", "Radial load [N]")] = "200:2000",
    faults: Annotated[
        str,
        typer.Option(
            "--faults",
            help="Fault classes, A,B,C among none, outer, inner, ball, compound "
            "(two defects); cage is refused: the models have no cage defect.",
        ),
    ] = "none,outer,inner,ball",
    defect_width_mm: Annotated[str, _ranged("--defect-width-mm", "Defect width [mm]")] = "0.2:1.5",
    defect_depth_mm: Annotated[str, _ranged("--defect-depth-mm", "Defect depth [mm]")] = "0.1:0.3",
    defect_position_deg: Annotated[
        str,
        _ranged(
            "--defect-position-deg",
            "Outer-race defect position from +x towards +y [deg] (-90: bottom of the load zone)",
        ),
    ] = "-135:-45",
    waviness_um: Annotated[str, _ranged("--waviness-um", "Raceway waviness amplitude [um]")] = "0",
    waviness_orders: Annotated[str, _ranged("--waviness-orders", "Waviness orders")] = "2:30",
    ball_size_error_um: Annotated[
        str, _ranged("--ball-size-error-um", "Band of ball diameter errors [um]")
    ] = "0",
    noise_ms2: Annotated[
        str, _ranged("--noise-ms2", "RMS of the measurement noise [m/s^2]")
    ] = "0.5:5",
    resonance: Annotated[
        list[str] | None,
        typer.Option(
            "--resonance",
            help="A resonance of the path to the sensor, repeatable: "
            "FREQ_HZ@DAMPING_RATIO, each a value or LOW:HIGH (default 2500:4500@0.02:0.08).",
        ),
    ] = None,
    sample_rate_hz: Annotated[
        str, typer.Option("--sample-rate-hz", help="Sample rate [Hz]: V or A,B,C.")
    ] = "20000",
    duration_s: Annotated[str, _ranged("--duration-s", "Record length [s]")] = "1",
    model: Annotated[
        str, typer.Option("--model", help="rigid (seed 003) or slip (seed 004), or rigid,slip.")
    ] = "rigid",
    seed: Annotated[
        int, typer.Option("--seed", help="Record i's inputs come from the seed and i.")
    ] = 0,
    partition_size: Annotated[
        int | None,
        typer.Option("--partition-size", help="Records per partition."),
    ] = None,
    scheduler: SchedulerOpt = None,
    workers: WorkersOpt = None,
    yes: Annotated[
        bool, typer.Option("--yes", help=f"Make more than {CONFIRM_RECORDS} records.")
    ] = False,
    json_output: JsonOpt = False,
):
    """Make labelled synthetic vibration records in the bearing-datasets layout, on dask.

    Example: bearinglab dataset data/synth --records 40 --duration-s 0.25
    """
    from ..dataset import make_dataset

    paths = [_resonance(r) for r in resonance] if resonance else None
    ranges = {
        "bearings": bearings,
        "speed_rpm": speed_rpm,
        "radial_load_n": radial_load_n,
        "faults": faults,
        "defect_width_mm": defect_width_mm,
        "defect_depth_mm": defect_depth_mm,
        "defect_position_deg": defect_position_deg,
        "waviness_amplitude_um": waviness_um,
        "waviness_orders": waviness_orders,
        "ball_size_error_um": ball_size_error_um,
        "noise_ms2": noise_ms2,
        "sample_rate_hz": sample_rate_hz,
        "duration_s": duration_s,
        "model": model,
    }
    if paths is not None:
        ranges["resonances"] = paths
    preflight_scheduler(scheduler)
    from ..engine import Interrupted

    try:
        with progress_bar("records", enabled=not json_output, unit="records") as progress:
            result = make_dataset(
                output,
                records,
                seed=seed,
                partition_size=partition_size,
                scheduler=scheduler,
                workers=workers,
                max_records=None if yes else CONFIRM_RECORDS,
                progress=progress,
                **ranges,
            )
    except InputError as exc:
        raise _remap(exc) from None
    except Interrupted as exc:
        exc.resume = resume_line(exc, "records", output, "make")
        raise
    warnings = _failures(result) + _warnings(result.spec, typed(ctx))
    warnings += runner_warnings(scheduler, workers)
    d = {**result.to_dict(), "warnings": warnings}
    if json_output:
        _emit_json(d)
        return
    console.print(
        _table(
            f"data set {d['name']}",
            ["", "value", "unit"],
            [
                ["records written", d["records_written"], ""],
                ["records failed", d["records_failed"], ""],
                *run_rows(d, "records"),
            ],
        )
    )
    counts = result.to_pandas()["fault_type"].value_counts().sort_index()
    console.print(
        _table(
            "records per fault type",
            ["fault_type", "records"],
            [[k, int(v)] for k, v in counts.items()],
        )
    )
    console.print(f"[dim]read it with {escape(d['open_with'])}[/dim]")
    _print_warnings(warnings)
