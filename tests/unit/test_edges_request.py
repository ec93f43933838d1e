"""Edges a new user found in the commands (issue 30, point 9), each failing on the code
before the fix: one line naming the option, no internal error, no raw warning."""

import pickle

import pytest

from bearinglab.cli import main
from bearinglab.errors import InputError


def _error_line(capsys, args) -> str:
    assert main(args) == 2
    captured = capsys.readouterr()
    lines = captured.err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), captured.err
    assert "internal error" not in lines[0] and "Warning" not in captured.err
    return lines[0]


def test_a_stiffness_map_speed_past_the_model_is_refused_before_work(capsys):
    """It was an internal error (BrokenProcessPool: a worker's error did not unpickle),
    and with one bad value the error named the internal `shaft_speed`."""
    line = _error_line(
        capsys, ["stiffness-map", "6205", "--radial-load-n", "100", "--speed-rpm", "0,1e6"]
    )
    assert line.startswith("error: --speed-rpm = '0,1e6' is not allowed")
    assert "at most 76844.7 rpm" in line


def test_errors_survive_a_trip_to_a_worker_process():
    e = InputError("pitch_diameter", 0.005, "more than {d}", unit="m", numbers={"d": 0.00794})
    back = pickle.loads(pickle.dumps(e))
    assert str(back) == str(e) and back.numbers == {"d": 0.00794} and back.unit == "m"


def test_a_simulation_without_load_is_refused_in_its_terms(capsys):
    """It was blamed on "a dead or disconnected sensor" (the diagnosis of a flat record)."""
    line = _error_line(capsys, ["simulate", "6205", "--speed-rpm", "1000", "--radial-load-n", "0"])
    assert line.startswith("error: --radial-load-n = 0 is not allowed: expected a load in (0")


def test_a_field_point_past_any_room_is_refused(capsys):
    """1e300 mm was an internal error (a NaN turned into an integer)."""
    line = _error_line(
        capsys,
        ["noise", "608", "--speed-rpm", "720", "--radial-load-n", "50", "--distance-mm", "1e300"],
    )
    assert line.startswith("error: --distance-mm = 1e+300 is not allowed")


@pytest.mark.slow
def test_noise_at_a_high_speed_is_computed_without_raw_warnings(capsys):
    """At 70 000 rpm the retarded-time series overflowed ((j omega)^m at 60 kHz): raw
    RuntimeWarnings, then "x = 'an array with NaN or inf'"."""
    code = main(["noise", "6205", "--speed-rpm", "70000", "--radial-load-n", "1000", "--json"])
    captured = capsys.readouterr()
    assert code == 0 and "RuntimeWarning" not in captured.err


def test_validate_reads_at_80_columns(monkeypatch):
    """At 80 columns the seven-column table folded the quantity into 7-letter scraps."""
    import io

    from rich.console import Console

    from bearinglab.cli import _app
    from bearinglab.cli.validate import _print

    out = io.StringIO()
    monkeypatch.setattr(_app._LazyConsole, "_console", Console(width=80, file=out))
    case = {
        "source": "seed 000 (Balmont & Varlamov 1986, bearing 106)",
        "quantity": "m=2 approx, text 7.31",
        "published": 7.31,
        "computed": 7.306,
        "unit": "kHz",
        "error_percent": -0.0545,
        "tolerance_percent": 0.177,
        "verdict": "pass",
        "known_failure": None,
        "error": None,
    }
    summary = {
        "total": 1,
        "passed": 1,
        "known_failures": 0,
        "failed": 0,
        "unexpected_passes": 0,
        "errors": 0,
        "duration_s": 0.1,
        "ok": True,
    }
    _print([case], summary)
    lines = out.getvalue().splitlines()
    assert max(len(line) for line in lines) <= 80
    assert any("m=2 approx, text 7.31: 7.31 -> 7.306" in line for line in lines)


def test_a_replaced_option_is_refused_naming_its_replacement(capsys):
    line = _error_line(capsys, ["trend", "some-folder", "--false-alarm", "1e-6"])
    assert "--false-alarm-per-hour" in line and "per record" in line


@pytest.mark.parametrize(
    "args",
    [
        ["static", "6205", "--radial-load-n", "100", "--no-film", "--no-gyroscopic"],
        ["life", "6205", "--speed-rpm", "1000", "--radial-load-n", "100", "--method", "iso281"],
        ["contact", "6205", "--ball-load-n", "100", "--method", "exact"],
        ["friction", "6205", "--speed-rpm", "1000", "--model", "constant", "--type", "radial_ball"],
    ],
)
def test_negations_and_the_old_names_still_work(capsys, args):
    """`static --no-film` failed with "No such option"; the renamed inputs keep their
    old flags as aliases."""
    assert main([*args, "--json"]) == 0
    capsys.readouterr()


@pytest.mark.parametrize("cell", ["", "nan"])
def test_a_cases_table_with_an_empty_or_nan_load_is_refused(capsys, tmp_path, cell):
    """An empty cell or a nan became the default 0 N silently, where `--set` refused nan."""
    cases = tmp_path / "cases.csv"
    cases.write_text(f"designation,radial_load_n\n6205,1000\n6205,{cell}\n")
    line = _error_line(
        capsys, ["study", "static", "--cases", str(cases), "-o", str(tmp_path / "s")]
    )
    assert line.startswith("error: --cases radial_load_n (row 2 of cases.csv) = ")
    assert not (tmp_path / "s").exists()


def test_an_empty_cell_of_an_optional_input_leaves_it_not_given(tmp_path):
    from bearinglab.analyses import ANALYSES
    from bearinglab.study.cases import CaseTable

    cases = tmp_path / "cases.csv"
    cases.write_text("designation,clearance_um\n6205,\n6205,20\n")
    table = CaseTable(cases, ANALYSES["static"].options, "static")
    assert [r["clearance_um"] for r in table.rows(0, 2)] == [None, 20.0]


def test_a_data_set_load_past_the_elastic_limit_is_refused_before_any_record(capsys, tmp_path):
    """1e7 N on a 6205 made a data set without a word."""
    line = _error_line(
        capsys, ["dataset", str(tmp_path / "d"), "--records", "2", "--radial-load-n", "1e7"]
    )
    assert line.startswith("error: --radial-load-n = '1e7' is not allowed") and "C0" in line
    assert not (tmp_path / "d").exists()


def test_the_first_compile_in_a_process_is_told(caplog, monkeypatch):
    """The first run after install sat silent for 23 s while numba compiled."""
    import numba

    from bearinglab.engine import compiling

    compiling.watch()
    monkeypatch.setitem(compiling._state, "told", False)

    @numba.njit(cache=False)
    def twice(x):
        return 2 * x

    with caplog.at_level("WARNING", logger="bearinglab.engine.compiling"):
        assert twice(2) == 4 and twice(3) == 6
    told = [r for r in caplog.records if r.name == "bearinglab.engine.compiling"]
    assert len(told) == 1 and "first run after install" in told[0].getMessage()
