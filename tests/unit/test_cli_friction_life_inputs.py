"""Bad and idle inputs of ``friction`` and ``life`` (issue 12, "bad input keeps its
quality"): SKF constants outside their plausible range are refused naming
--skf-constants; options without effect (R3,S3 of a deep-groove bearing, inputs the
chosen friction model does not use, --outer-rotating with iso281, --ep-additives without
a viscosity) are named by their flags; given load ratings far from ISO 281/76's are
flagged."""

import json
import math

import pytest
from conftest import run_json

from bearinglab.catalog import bearing_from_designation
from bearinglab.cli import main
from bearinglab.errors import InputError
from bearinglab.friction import DEEP_GROOVE_CONSTANTS, SkfGeometryConstants, skf_friction
from bearinglab.friction.ranges import PLAUSIBLE_CONSTANTS, check_constants
from bearinglab.life import load_ratings

RPM = math.pi / 30.0
SKF_6205 = ("friction", "6205", "--speed-rpm", "3000", "--radial-load-n", "1000")
SKF_7206 = ("friction", "7206", "--speed-rpm", "3000", "--radial-load-n", "1000")
LIFE_6205 = ("life", "6205", "--speed-rpm", "1500", "--radial-load-n", "1400")
#: The 62 series' shipped constants, as a user would type them.
C62 = "3.9e-7,1.7,3.23e-3,36.5"


def run(capsys, *args):
    """(exit code, stdout, stderr) of the command line."""
    code = main(list(args))
    out, err = capsys.readouterr()
    return code, out, err


def refused(capsys, *args):
    """The one-line error of a refused command line, which prints nothing else."""
    code, out, err = run(capsys, *args)
    assert code == 2 and out == "" and "Traceback" not in err, (out, err)
    assert err.startswith("error: ") and err.count("\n") == 1, err
    return err


# ------------------------------------------------------------------ --skf-constants range
@pytest.mark.parametrize(
    "args, typed, words",
    [
        # the audit's typo: R1 3.9e-1 for 3.9e-7 gave this 6205 8.3 MW of friction power
        ((*SKF_6205, "--model", "skf"), "3.9e-1,1.7,3.23e-3,36.5", "R1 in [3.6e-08, 5.4e-06]"),
        ((*SKF_6205, "--model", "skf"), "3.9e-7,1.7,3.23e-3,36500", "S2 in [0.078, 1.98e+03]"),
        ((*SKF_6205, "--model", "skf"), "3.9e-7,0,3.23e-3,36.5", "R2 in [0.096, 17]"),
        ((*SKF_7206, "--model", "skf"), "5e-7,2,1e-2,0.7,2e-2,2e-12", "R3 in [7.8e-14, 1.9e-11]"),
        # checked with the constant model too, which does not use them
        (SKF_6205, "3.9e-1,1.7,3.23e-3,36.5", "R1 in [3.6e-08, 5.4e-06]"),
    ],
)
def test_implausible_skf_constants_are_refused_naming_the_option(capsys, args, typed, words):
    err = refused(capsys, *args, "--skf-constants", typed)
    assert f"--skf-constants = '{typed}' is not allowed" in err and words in err
    assert "ball bearing" in err and "SKF's table" in err


def test_plausible_ranges_hold_the_shipped_table_and_refuse_an_exponent_slip():
    for series, c in DEEP_GROOVE_CONSTANTS.items():
        check_constants("radial_ball", c)  # every shipped series passes
        slipped = SkfGeometryConstants(c.r1 * 1e6, c.r2, c.s1, c.s2)
        with pytest.raises(InputError) as info:
            check_constants("radial_ball", slipped)
        assert info.value.parameter == "constants" and "R1" in info.value.allowed, series
    operating_point = (0.025, 0.052, 1000.0, 0.0, 3000 * RPM, 20e-6)  # d, D, F_r, F_a, n, nu
    typo = SkfGeometryConstants(0.39, 1.7, 3.23e-3, 36.5)
    with pytest.raises(InputError, match="R1 in"):
        skf_friction("radial_ball", *operating_point, typo)


def test_angular_contact_r3_s3_range_holds_the_balls_centrifugal_load():
    # F_g = R3 d_m^4 n^2 is the balls' centrifugal load: by hand for a 7206, Z m omega_c^2
    # D_pw / 2 with the cage speed omega_c = omega (1 - gamma) / 2, in SKF units
    b, _ = bearing_from_designation("7206")
    n = 1000.0
    omega_c = 0.5 * n * RPM * (1.0 - b.gamma)
    f_g = b.ball_count * b.ball_mass * omega_c**2 * 0.5 * b.pitch_diameter
    d_m = 0.5 * (b.bore + b.outside_diameter) * 1e3
    k = f_g / (d_m**4 * n**2)
    for name in ("r3", "s3"):
        low, high = PLAUSIBLE_CONSTANTS["angular_contact_ball"][name]
        assert low <= k <= high, (name, k)


# ------------------------------------------------------------------ options without effect
def test_r3_s3_of_a_deep_groove_bearing_are_named_as_without_effect(capsys):
    four = (*SKF_6205, "--model", "skf", "--skf-constants", C62)
    six = (*SKF_6205, "--model", "skf", "--skf-constants", C62 + ",1e-12,1e-12")
    said = "R3,S3 of --skf-constants: no effect for a deep-groove ball bearing"
    code, out, _ = run(capsys, *four, "--json")
    plain = json.loads(out)
    code6, out6, _ = run(capsys, *six, "--json")
    d = json.loads(out6)
    assert code == code6 == 0
    assert d["friction_torque_n_mm"] == plain["friction_torque_n_mm"]  # no effect indeed
    assert any(w.startswith(said) for w in d["warnings"])
    assert not any("R3" in w for w in plain["warnings"])
    code, out, err = run(capsys, *six)
    assert code == 0 and "R3,S3 of --skf-constants" in out and "Traceback" not in err


def test_unused_inputs_are_named_by_their_options(capsys):
    moot = ("--viscosity-mm2-s", "20", "--skf-constants", C62)
    constant = run_json(capsys, *SKF_6205, *moot)["warnings"]
    # --model (the option's old name, still accepted) is worded as its name, --friction-model
    assert (
        "--viscosity-mm2-s and --skf-constants: no effect with --friction-model constant"
        in constant
    )
    skf = run_json(
        capsys,
        *SKF_6205,
        "--model",
        "skf",
        "--equivalent-load-n",
        "900",
        "--seal-diameter-mm",
        "30",
    )["warnings"]
    assert "--equivalent-load-n: no effect with --friction-model skf" in skf
    assert "--seal-diameter-mm: no effect without --seal-constants" in skf
    # the library's own note, in parameter names, is not shown beside them
    for library_words in ("does not use", "equivalent_load", "seal_diameter"):
        assert not any(library_words in w for w in constant + skf), library_words
    code, out, _ = run(capsys, *SKF_6205, "--model", "skf", "--equivalent-load-n", "900")
    assert code == 0 and "--equivalent-load-n: no effect" in out


@pytest.mark.parametrize(
    "options, said",
    [
        (["--outer-rotating"], "--outer-rotating: no effect with --life-method iso281"),
        (["--ep-additives"], "--ep-additives: no effect without --viscosity-mm2-s"),
    ],
)
def test_life_options_without_effect_are_named(capsys, options, said):
    assert any(w.startswith(said) for w in run_json(capsys, *LIFE_6205, *options)["warnings"])
    code, out, _ = run(capsys, *LIFE_6205, *options)
    assert code == 0 and said.split(":")[0] + ":" in out


def test_life_options_with_effect_are_not_named(capsys):
    used = run_json(
        capsys,
        *LIFE_6205,
        "--outer-rotating",
        "--method",
        "iso16281",
        "--ep-additives",
        "--viscosity-mm2-s",
        "10",
    )["warnings"]
    assert not any("no effect" in w for w in used)


# ------------------------------------------------------------------ given ratings
def test_given_ratings_far_from_iso_are_flagged(capsys):
    b, _ = bearing_from_designation("6205")
    iso = load_ratings(b)  # ISO 281/76 from the geometry
    far = run_json(capsys, *LIFE_6205, "--dynamic-load-rating-kn", "140")["warnings"]
    said = f"the given C = 140 kN is {140e3 / iso.dynamic:.3g} times ISO 281's"
    assert any(w.startswith(said) and f"{iso.dynamic * 1e-3:.4g} kN" in w for w in far), far
    # a maker's rating, 5 % above ISO 281's (SKF Explorer), says nothing
    maker = run_json(capsys, *LIFE_6205, "--dynamic-load-rating-kn", f"{iso.dynamic * 1.05e-3}")[
        "warnings"
    ]
    assert not any("the given C" in w for w in maker)
    typo = 0.1 * iso.static  # C0 typed a decade low
    r = load_ratings(b, static_load_rating=typo)
    said = f"the given C0 = {typo * 1e-3:.4g} kN is 0.1 times ISO 76's"
    assert any(w.startswith(said) for w in r.warnings), r.warnings
    assert not load_ratings(b, static_load_rating=1.05 * iso.static).warnings
