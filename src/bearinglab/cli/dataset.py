"""The ``dataset`` command: labelled synthetic vibration records in the bearing-datasets
layout, made on dask (the registry's ``dataset``: bearinglab.dataset.request)."""

from rich.markup import escape

from ..dataset.request import DATASET
from ._app import command_app, console
from ._inputs import JsonOpt, _print_warnings, given, takes
from ._output import _emit_json, _table, progress_bar
from ._preflight import scheduler as preflight_scheduler
from .study import run_rows

app = command_app()


@app.command("dataset")
@takes(argument="output", **DATASET.command_options)
def dataset(values, json_output: JsonOpt = False):
    """Make labelled synthetic vibration records in the bearing-datasets layout, on dask.

    Example: bearinglab dataset data/synth --records 40 --duration-s 0.25
    """
    preflight_scheduler(values["scheduler"])
    typed_ = given()
    with progress_bar("records", enabled=not json_output, unit="records") as progress:
        r = DATASET(values, progress=progress, given=typed_)
    result, warnings = r.result, list(r.warnings)
    d = r.to_dict()
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
