"""Plausibility checks in the user's terms (issue 14): each fires on an odd input and
stays silent on a normal one (the README's examples)."""

import math

import pytest
from conftest import README_STATIC

from bearinglab import plausibility as P
from bearinglab.catalog import bearing_from_designation
from bearinglab.cli import main
from bearinglab.errors import InputError
from bearinglab.kinematics import defect_frequencies
from bearinglab.operating import OperatingCondition

B, _ = bearing_from_designation("6205")
RPM = math.pi / 30
#: simulate's options up to the ones each bad-input case adds.
SIM_6205 = ("simulate", "6205", "--speed-rpm", "1797", "--radial-load-n", "500")


def test_static_safety_is_c0_over_p0():
    from bearinglab.life import load_ratings

    assert P.static_safety(B, 1000.0) == pytest.approx(load_ratings(B).static / 1000.0)
    assert P.static_safety(B, 0.0) is None


def test_load_past_c0_warns_and_far_past_it_is_an_error():
    assert P.load_warnings(B, 1000.0) == []
    (text,) = P.load_warnings(B, 10_000.0)
    assert "s0 = C0/P0 = 0.789" in text and "C0 = 7886 N" in text
    with pytest.raises(InputError) as err:
        P.load_warnings(B, 1e6)  # 127 C0 (issue 14's example)
    assert err.value.parameter == "radial_load" and "127 times" in str(err.value)


def test_speed_warnings_and_the_model_limit():
    assert P.speed_warnings(B, 1797 * RPM, 1000.0) == []
    texts = P.speed_warnings(B, 30_000 * RPM, 100.0)
    assert any("n d_m = 1.17e+06" in t for t in texts)
    assert any("centrifugal force" in t for t in texts)
    with pytest.raises(InputError) as err:
        P.speed_warnings(B, 1e6 * RPM, 100.0)
    assert err.value.parameter == "shaft_speed"


def test_sampling_nyquist_error_for_the_simulated_family_and_warnings_otherwise():
    kin = defect_frequencies(B, 1797 * RPM)
    assert P.sampling_warnings(kin, 12_000.0, 1.0) == []
    with pytest.raises(InputError) as err:
        P.sampling_warnings(kin, 100.0, 1.0, families=["outer_race"])
    assert err.value.parameter == "sample_rate" and "BPFO" in err.value.hint
    texts = P.sampling_warnings(kin, 300.0, 1.0)  # BPFI 162 Hz > 150 Hz
    assert any(t.startswith("BPFI = 162.19 Hz is above the Nyquist") for t in texts)
    (coarse,) = P.sampling_warnings(kin, 12_000.0, 0.1)
    assert "too coarse to separate the cage sidebands" in coarse


def test_operating_warnings_of_a_condition():
    c = OperatingCondition(radial_load=10_000.0, shaft_speed=1797 * RPM)
    assert len(P.operating_warnings(B, c)) == 1


@pytest.mark.parametrize(
    "argv, flag",
    [
        (["static", "6205", "--radial-load-n", "1e6"], "--radial-load-n"),
        (["static", "6205", "--radial-load-n", "100", "--speed-rpm", "1e6"], "--speed-rpm"),
        (
            [
                *SIM_6205,
                "--defect",
                "outer:width_mm=1",
                "--sample-rate-hz",
                "100",
            ],
            "--sample-rate-hz",
        ),
        (
            [
                *SIM_6205,
                "--sample-rate-hz",
                "10",
            ],
            "--sample-rate-hz",
        ),
        (
            [
                *SIM_6205,
                "--duration-s",
                "0.2",
                "--sample-rate-hz",
                "12000",
            ],
            "--duration-s",
        ),
        (
            [
                "report",
                "6205",
                "--speed-rpm",
                "1797",
                "--radial-load-n",
                "500",
                "--duration-s",
                "0.2",
                "-o",
                "never-written.html",
            ],
            "--duration-s",
        ),
    ],
)
def test_commands_name_the_option(capsys, argv, flag):
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"error: {flag} = ") and err.count("\n") == 1


def test_readme_static_example_has_no_plausibility_warning(capsys):
    assert main([*README_STATIC, "--json"]) == 0
    import json

    warnings = json.loads(capsys.readouterr().out)["warnings"]
    assert not any("s0 =" in w or "n d_m" in w or "Nyquist" in w for w in warnings)


# ------------------------------------------------------- contact pressure of form errors
#: 608 under 50 N: outer waviness of order 2 presses the balls it meets into the rings.
FORMS_608 = {"designation": "608", "radial_load_n": 50.0}


def _static(**values):
    from bearinglab.analyses.mechanics import static

    return static({**FORMS_608, **values})


def _form_warnings(result) -> list[str]:
    return [w for w in result.warnings if w.startswith("the form errors")]


def test_waviness_past_iso76_pressure_warns_naming_waviness():
    r = _static(waviness=["outer:order=2,amplitude_um=50"])
    assert r.distribution.max_ball_load == pytest.approx(1923, rel=2e-3)
    assert r.distribution.max_pressure == pytest.approx(5.06e9, rel=2e-3)
    (text,) = _form_warnings(r)
    assert text.startswith("the form errors (`waviness`) put 1923 N and 5.06 GPa on a ball")
    assert "past the 4.2 GPa of ISO 76 (the static rating C0)" in text
    assert r.to_dict()["warnings"][-1] == text
    # small waviness: the external load's pressures, no warning
    assert _form_warnings(_static(waviness=["outer:order=2,amplitude_um=0.5"])) == []
    # order Z + 1 = 8 of a 7-ball 608 meets the balls as a shift the inner ring follows
    # (cos 8 psi_j = cos(psi_j + const)): 50 um put no extra load on a ball
    r8 = _static(waviness=["outer:order=8,amplitude_um=50"])
    assert r8.distribution.max_ball_load < 50.0 and _form_warnings(r8) == []


def test_ball_size_errors_past_iso76_warn_naming_ball_size_error_um():
    (text,) = _form_warnings(_static(ball_size_error_um="250"))
    assert text.startswith("the form errors (`ball_size_error_um`) put 1215 N and 4.34 GPa")
    assert _form_warnings(_static(ball_size_error_um="60")) == []


def test_form_errors_past_the_pressure_of_8_c0_are_an_error():
    with pytest.raises(InputError) as err:
        _static(waviness=["outer:order=2,amplitude_um=150"])
    assert err.value.parameter == "waviness" and "8.4 GPa" in str(err.value)
    assert "9.03 GPa" in err.value.hint


def test_contact_check_leaves_a_load_past_c0_to_the_load_check():
    from bearinglab.quasistatic import solve_load_distribution

    b608, _ = bearing_from_designation("608")
    r = solve_load_distribution(b608, OperatingCondition(radial_load=2000.0))  # 1.53 C0
    assert r.max_pressure > P.STATIC_RATING_PRESSURE
    assert P.contact_warnings(b608, r, cause={"waviness": ["outer:order=2,amplitude_um=1"]}) == []
    assert len(P.load_warnings(b608, 2000.0)) == 1
    assert P.contact_warnings(b608, r, cause={}) == []  # no form error, no check
    assert P.ELASTIC_LIMIT_PRESSURE == pytest.approx(8.4e9)


def test_orbit_reports_its_worst_instant():
    r = _static(
        waviness=["outer:order=2,amplitude_um=50"], speed_rpm=600.0, orbit=True, orbit_points=32
    )
    assert r.orbit.max_pressure.shape == r.orbit.time.shape
    (text,) = _form_warnings(r)
    assert " ms of the orbit, past the 4.2 GPa" in text


def test_static_command_words_the_form_error_warning_as_flags(capsys):
    import json

    argv = ["static", "608", "--radial-load-n", "50", "--waviness", "outer:order=2,amplitude_um=50"]
    assert main([*argv, "--json"]) == 0
    warnings = json.loads(capsys.readouterr().out)["warnings"]
    sentence = "the form errors (--waviness) put 1923 N and 5.06 GPa on a ball, past the 4.2 GPa"
    assert any(w.startswith(sentence) for w in warnings)
