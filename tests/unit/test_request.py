"""The request layer (issue 22): one input table (bearinglab.inputs), one analysis registry
(bearinglab.analyses), and the command line and the studies built from both."""

import click
import pytest
import typer

from bearinglab.analyses import ANALYSES
from bearinglab.cli._app import app
from bearinglab.errors import CatalogError, InputError
from bearinglab.inputs import INPUTS, bearing_from, condition_from, no_effect
from bearinglab.study.cases import parse_values

#: study analysis -> the command that runs it for one case
COMMANDS = {
    "static": "static",
    "stiffness": "stiffness-map",
    "frequencies": "frequencies",
    "life": "life",
    "friction": "friction",
    "ring-modes": "ring-modes",
    "noise": "noise",
    "simulate": "simulate",
}
#: what a command writes or shows, not what it computes
FRONT_END = {"json_output", "plot", "output", "orbit_plot", "stiffness_csv", "workers"}


def _command(name: str) -> click.Command:
    group = typer.main.get_command(app)
    return group.get_command(click.Context(group), name)


def test_every_analysis_has_a_command():
    assert set(COMMANDS) == set(ANALYSES)


@pytest.mark.parametrize("analysis", sorted(COMMANDS))
def test_a_study_takes_every_input_of_its_command(analysis):
    a = ANALYSES[analysis]
    given = {p.name for p in _command(COMMANDS[analysis]).params} - FRONT_END
    assert given <= set(a.options), sorted(given - set(a.options))


@pytest.mark.parametrize("analysis", sorted(COMMANDS))
def test_a_study_reads_each_input_of_its_command_by_its_kind(analysis):
    # one value of each input as a study column would hold it: parsed by its kind
    samples = {"number": "1.5", "integer": "3", "text": "x", "texts": "x", "bool": "true"}
    for name, spec in ANALYSES[analysis].options.items():
        if spec.kind == "path":
            continue
        text = spec.choices[0] if spec.choices else samples[spec.kind]
        assert parse_values(name, text, spec)


def test_the_study_and_the_command_compute_the_same_static_case(capsys):
    from bearinglab.cli import main

    case = {"designation": "608", "radial_load_n": 50.0, "speed_rpm": 720.0, "gyroscopic": True}
    study = ANALYSES["static"].evaluate(case, 0)
    assert (
        main(
            [
                "static",
                "608",
                "--radial-load-n",
                "50",
                "--speed-rpm",
                "720",
                "--gyroscopic",
                "--json",
            ]
        )
        == 0
    )
    import json

    command = json.loads(capsys.readouterr().out)
    assert study["max_ball_load_n"] == pytest.approx(command["max_ball_load_n"], rel=1e-12)


def test_inputs_are_checked_in_their_units_and_named_by_their_public_name():
    with pytest.raises(
        InputError,
        match=r"^radial_load_n = -5 is not allowed: expected a load "
        r"in \[0, 1e\+07\] N$",
    ):
        condition_from({"radial_load_n": -5})
    with pytest.raises(InputError, match="ball_diameter_mm = 50 .*less than the pitch"):
        bearing_from({"designation": "6205", "ball_diameter_mm": 50})
    with pytest.raises(InputError, match="^poisson_ratio = 0.5 .*\\[0, 0.5\\)"):
        INPUTS["poisson_ratio"].check("poisson_ratio", 0.5)


def test_a_bearing_that_needs_geometry_names_the_inputs_to_give():
    with pytest.raises(CatalogError, match="give `balls`, `ball_diameter_mm` and"):
        bearing_from({"designation": "51105"})


def test_inputs_without_effect_are_named_once_each():
    assert no_effect([("film", True), ("seed", False)], "here") == ["`film`: no effect here"]


def test_the_command_line_words_library_errors_as_its_flags(capsys):
    from bearinglab.cli import main

    assert main(["static", "6205", "--radial-load-n", "-5"]) == 2
    assert capsys.readouterr().err.startswith("error: --radial-load-n = -5 is not allowed")
    assert main(["frequencies", "--speed-rpm", "100"]) == 2
    err = capsys.readouterr().err
    assert "DESIGNATION is not given" in err and "--ball-diameter-mm" in err


def test_a_repeated_option_is_shown_as_typed_not_as_a_python_list(capsys):
    from bearinglab.cli import main

    assert main(["analyze", "x.npz", "--designation", "6205", "--tolerance", "outer=5"]) == 2
    err = capsys.readouterr().err
    assert "[" not in err.split("is not allowed")[0]


@pytest.mark.parametrize(
    "args",
    [
        ["frequencies", "6205", "--speed-rpm", "1797"],
        ["contact", "6205", "--ball-load-n", "1000"],
        ["static", "6205", "--radial-load-n", "1000"],
        ["stiffness-map", "6205", "--radial-load-n", "0:1000:2"],
        ["ring-modes", "6205"],
        ["life", "6205", "--speed-rpm", "3000", "--radial-load-n", "1000"],
        ["friction", "6205", "--speed-rpm", "3000", "--radial-load-n", "1000"],
        [
            "noise",
            "6205",
            "--speed-rpm",
            "1800",
            "--radial-load-n",
            "500",
            "--duration-s",
            "0.01",
            "--bands-from",
            "orbit",
        ],
    ],
)
def test_an_ambiguous_designation_is_said_in_every_command(capsys, args):
    # 6205 is an ISO deep-groove bearing and a GOST angular-contact one: the reading used is
    # said in the JSON warnings of every command that reads a designation
    import json

    from bearinglab.cli import main

    assert main([*args, "--json"]) == 0
    warnings = json.loads(capsys.readouterr().out)["warnings"]
    assert any(w.startswith("also reads as GOST 3189-89") for w in warnings), warnings


def test_ball_size_errors_without_an_equilibrium_are_one_line_not_a_crash(capsys):
    # 300 um on a 608's 3.97 mm balls: within the 5 % input limit, but no ring equilibrium
    # exists (the compiled kernel divided by zero where its NumPy twin finds no solution)
    from bearinglab.cli import main

    argv = ["static", "608", "--radial-load-n", "50", "--ball-size-error-um", "300"]
    assert main(argv) == 2
    assert capsys.readouterr().err.startswith("error: ring equilibrium did not converge")


def test_a_study_case_takes_several_specifications_of_its_command(tmp_path, capsys):
    # one case, two waviness specifications with ';' between them: the same load
    # distribution as the command given both
    import json

    from bearinglab.cli import main
    from bearinglab.study import run_study

    waves = ["outer:order=8,amplitude_um=0.5", "inner:order=7,amplitude_um=0.2"]
    study = run_study(
        "static",
        {
            "designation": "608",
            "radial_load_n": 50.0,
            "speed_rpm": 720.0,
            "waviness": "; ".join(waves),
        },
        output=tmp_path / "st",
        scheduler="serial",
    ).to_pandas()
    argv = ["static", "608", "--radial-load-n", "50", "--speed-rpm", "720", "--json"]
    for w in waves:
        argv += ["--waviness", w]
    assert main(argv) == 0
    command = json.loads(capsys.readouterr().out)
    assert study["error"].isna().all()
    assert study["max_ball_load_n"][0] == pytest.approx(command["max_ball_load_n"], rel=1e-12)


def test_a_study_case_is_checked_against_the_ranges_its_command_checks():
    # orbit_points is static's own input (2..100000): the study refuses 1 as the command does
    with pytest.raises(InputError, match=r"^orbit_points = 1 is not allowed: expected an integer"):
        ANALYSES["static"].evaluate(
            {"designation": "6205", "radial_load_n": 100.0, "orbit": True, "orbit_points": 1}, 0
        )
