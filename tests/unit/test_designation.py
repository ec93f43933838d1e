"""Unit tests of bearinglab.designation: bore codes, ISO families and suffixes, GOST <-> ISO
equivalents, Cyrillic/Latin spellings, ambiguity reporting and errors.

The GOST system is the one of seed 003 (lines 129-187, 240-350); the ISO equivalents are
the usual catalogue cross references (106 = 6006, 7000106 = 16006, 180205 = 6205-2RS).
"""

from __future__ import annotations

import dataclasses
import json
import math

import pytest

from bearinglab.designation import (
    BEARING_TYPES,
    Designation,
    gost_equivalent,
    iso_equivalent,
    parse,
    parse_gost,
    parse_iso,
)
from bearinglab.errors import DesignationError, InputError

# ---------------------------------------------------------------- bore codes

GOST_BORES = [
    ("100", 10.0),
    ("101", 12.0),
    ("102", 15.0),
    ("103", 17.0),
    ("104", 20.0),
    ("196", 480.0),
    ("299", 495.0),  # seed 003 line 137: d = 20...495 mm
    ("25", 5.0),
    ("1000096", 6.0),
    ("18", 8.0),  # small bores: digit 1 = d
    ("2/22", 22.0),
    ("10078/850", 850.0),
    ("7601/2,5", 2.5),  # "/d" form
]


@pytest.mark.parametrize("text, bore_mm", GOST_BORES, ids=[b[0] for b in GOST_BORES])
def test_gost_bore_codes(text: str, bore_mm: float) -> None:
    d = parse_gost(text)
    assert d.bore == pytest.approx(bore_mm * 1e-3, rel=1e-12)
    assert d.to_dict()["bore_mm"] == bore_mm


ISO_BORES = [
    ("6200", 10.0),
    ("6201", 12.0),
    ("6202", 15.0),
    ("6203", 17.0),
    ("6204", 20.0),
    ("6296", 480.0),
    ("608", 8.0),
    ("625", 5.0),
    ("629", 9.0),
    ("62/22", 22.0),
    ("60/28", 28.0),
    ("618/500", 500.0),
]


@pytest.mark.parametrize("text, bore_mm", ISO_BORES, ids=[b[0] for b in ISO_BORES])
def test_iso_bore_codes(text: str, bore_mm: float) -> None:
    assert parse_iso(text).bore == pytest.approx(bore_mm * 1e-3, rel=1e-12)


def test_small_bore_series_sits_in_digit_2() -> None:
    d = parse_gost("25")  # GOST 3189-89 small-bore scheme: d = 5 mm, diameter series 2
    assert (d.diameter_series, d.bore_code, d.iso_equivalent) == ("2", "5", "625")
    assert any("small-bore" in n for n in d.notes)
    assert parse_gost("1000096").iso_equivalent == "619/6"


def test_iso_bore_code_above_96_is_refused() -> None:
    with pytest.raises(DesignationError) as err:
        parse_iso("6297")
    assert err.value.part == "97"


# ---------------------------------------------------------------- ISO families, suffixes

ISO_CASES = [
    (
        "6205-2RS",
        {
            "bearing_type": "radial_ball",
            "series": "62",
            "dimension_series": "02",
            "bore": 25,
            "closures": "2seals",
        },
    ),
    ("6205-2Z", {"series": "62", "closures": "2shields"}),
    ("6205 ZZ", {"series": "62", "closures": "2shields"}),
    ("6205-Z", {"closures": "shield"}),
    ("6205-RS1", {"closures": "seal"}),
    ("6205 2rs", {"closures": "2seals"}),
    ("6205/2RS", {"closures": "2seals"}),
    ("6205 DDU", {"closures": "2seals"}),
    ("6205 LLB", {"closures": "2seals"}),
    (
        "7206 BECBP",
        {
            "bearing_type": "angular_contact_ball",
            "series": "72",
            "angle": 40.0,
            "suffix_codes": ("BE", "CB", "P"),
        },
    ),
    ("7308 AC", {"series": "73", "bore": 40, "angle": 25.0}),
    ("7205 C", {"angle": 15.0}),
    ("7310 B", {"angle": 40.0}),
    (
        "QJ210",
        {
            "bearing_type": "four_point_contact_ball",
            "series": "QJ2",
            "bore": 50,
            "design_variant": "QJ",
        },
    ),
    (
        "NU206 E",
        {
            "bearing_type": "cylindrical_roller",
            "series": "NU2",
            "bore": 30,
            "design_variant": "NU",
            "suffix_codes": ("E",),
        },
    ),
    ("NJ2210", {"series": "NJ22", "dimension_series": "22", "bore": 50, "design_variant": "NJ"}),
    ("NUP311 E", {"series": "NUP3", "bore": 55}),
    (
        "30206",
        {"bearing_type": "tapered_roller", "series": "302", "dimension_series": "02", "bore": 30},
    ),
    (
        "32210",
        {"bearing_type": "tapered_roller", "series": "322", "dimension_series": "22", "bore": 50},
    ),
    ("22210 E", {"bearing_type": "spherical_roller", "series": "222", "bore": 50}),
    ("22310 CC", {"bearing_type": "spherical_roller", "series": "223", "suffix_codes": ("CC",)}),
    (
        "51205",
        {"bearing_type": "thrust_ball", "series": "512", "dimension_series": "12", "bore": 25},
    ),
    ("1205 K", {"bearing_type": "self_aligning_ball", "series": "12", "suffix_codes": ("K",)}),
    ("2310", {"bearing_type": "self_aligning_ball", "series": "23", "bore": 50}),
    ("608-2RS", {"series": "60", "bore": 8, "closures": "2seals"}),
    ("62/22", {"series": "62", "bore": 22, "bore_code": "/22"}),
    ("6310 C3", {"series": "63", "bore": 50, "suffix_codes": ("C3",)}),
    ("16006", {"series": "160", "dimension_series": "00"}),
    ("61904", {"series": "619", "dimension_series": "19", "bore": 20}),
    ("6205 P6", {"precision_class": "6"}),
    ("NA4906", {"bearing_type": "needle_roller", "series": "NA49"}),
]


@pytest.mark.parametrize("text, expected", ISO_CASES, ids=[c[0] for c in ISO_CASES])
def test_iso_families_and_suffixes(text: str, expected: dict) -> None:
    d = parse_iso(text)
    assert d.system == "iso"
    for name in (
        "bearing_type",
        "series",
        "dimension_series",
        "closures",
        "design_variant",
        "bore_code",
        "precision_class",
    ):
        if name in expected:
            assert getattr(d, name) == expected[name], name
    if "bore" in expected:
        assert d.bore == pytest.approx(expected["bore"] * 1e-3)
    if "angle" in expected:
        assert math.degrees(d.contact_angle) == pytest.approx(expected["angle"])
    if "suffix_codes" in expected:
        assert tuple(c for c, _ in d.suffixes) == expected["suffix_codes"]


def test_clearance_group_is_exposed() -> None:
    d = parse_iso("6310 C3")
    assert "greater than normal" in dict(d.suffixes)["C3"]
    assert ("C3", dict(d.suffixes)["C3"]) in d.parts
    assert any("clearance group C3" in n for n in d.notes)


def test_bare_angular_contact_has_no_angle_but_a_note() -> None:
    d = parse_iso("7206")
    assert d.contact_angle is None
    assert any("depends on the maker" in n for n in d.notes)


def test_trailing_unknown_letters_are_kept_not_decoded() -> None:
    d = parse_iso("7206 BEXY")
    assert d.suffixes[0][0] == "BE" and d.suffixes[1] == ("XY", "suffix XY (not decoded)")


def test_iso_parts_reading_order() -> None:
    d = parse_iso("6205-2RS")
    assert [t for t, _ in d.parts] == ["6", "2", "05", "2RS"]
    assert "25 mm" in d.parts[2][1]


# ---------------------------------------------------------------- GOST <-> ISO

EQUIVALENTS = [
    ("106", "6006"),
    ("310", "6310"),
    ("180205", "6205-2RS"),
    ("80205", "6205-2Z"),
    ("160205", "6205-RS"),
    ("60205", "6205-Z"),
    ("7000106", "16006"),
    ("1000904", "61904"),
    ("1205", "1205"),
    ("1505", "2205"),
    ("8205", "51205"),
    ("12210", "NF210"),
    ("7206", "30206"),
    ("3003124", "23024"),
    ("150205", "6205 NR"),
]


@pytest.mark.parametrize("gost, iso", EQUIVALENTS, ids=[e[0] for e in EQUIVALENTS])
def test_gost_to_iso(gost: str, iso: str) -> None:
    assert parse_gost(gost).iso_equivalent == iso
    assert iso_equivalent(gost, system="gost") == iso


@pytest.mark.parametrize("gost, iso", EQUIVALENTS, ids=[e[1] for e in EQUIVALENTS])
def test_iso_to_gost(gost: str, iso: str) -> None:
    assert parse_iso(iso).gost_equivalent == gost
    assert gost_equivalent(iso, system="iso") == gost


def test_precision_carried_over() -> None:
    assert parse_gost("6-180205").iso_equivalent == "6205-2RS P6"
    assert parse_iso("6205-2RS P6").gost_equivalent == "6-180205"


def test_angular_contact_has_no_exact_equivalent() -> None:
    g = parse_gost("36209")
    assert g.iso_equivalent is None and g.series == "72"
    assert any("contact angle differs" in n for n in g.notes)
    assert parse_iso("7209 B").gost_equivalent is None


@pytest.mark.parametrize("text, angle", [("36209", 12.0), ("46209", 26.0), ("66209", 36.0)])
def test_gost_angular_contact_angles(text: str, angle: float) -> None:
    assert math.degrees(parse_gost(text).contact_angle) == pytest.approx(angle)


def test_four_point_contact_variant() -> None:
    d = parse_gost("176214")
    assert d.bearing_type == "four_point_contact_ball" and d.iso_equivalent == "QJ214"
    assert any("verify" in n for n in d.notes)


# ---------------------------------------------------------------- spellings

SPELLINGS = [
    ("4-3003124Р", "4-3003124P"),
    ("6-18030ПР20П", "6-18030PR20P"),
    ("180205С", "180205C"),
    ("А5-205", "A5-205"),
    ("В-205", "B-205"),
    ("205Е", "205E"),
    ("205К", "205k"),
    ("Т-205", "T-205"),
    ("205М", "205M"),
]


@pytest.mark.parametrize("cyrillic, latin", SPELLINGS, ids=[s[1] for s in SPELLINGS])
def test_cyrillic_and_latin_give_identical_results(cyrillic: str, latin: str) -> None:
    a = parse(cyrillic).to_dict()
    b = parse(latin).to_dict()
    assert a["system"] == b["system"] == "gost"
    for key in ("text", "notes"):
        a.pop(key), b.pop(key)
    assert a == b


def test_transliteration_is_noted() -> None:
    assert any("transliteration" in n for n in parse_gost("6-18030PR20P").notes)


@pytest.mark.parametrize(
    "text", ["6-36209", "6\u201336209", "6\u201436209", "6\u221236209", "6 - 36209", " 6-36209 "]
)
def test_dash_variants_and_spaces(text: str) -> None:
    d = parse(text)
    assert (d.system, d.precision_class, d.gost_equivalent) == ("gost", "6", "6-36209")


def test_gost_prefix_category_clearance_class() -> None:
    d = parse_gost("А125-205")
    assert (d.category, d.precision_class) == ("A", "5")
    assert [c for c, _ in d.prefixes] == ["А", "1", "2", "5"]
    assert "clearance group 2" in d.prefixes[2][1]


def test_gost_unknown_variant_and_suffix_are_not_errors() -> None:
    d = parse_gost("200205Ш")
    assert d.design_variant_meaning == "design variant 20 (not decoded)"
    assert d.suffixes == (("Ш", "suffix Ш (not decoded)"),)


def test_gost_brass_cage_suffix() -> None:
    assert "brass" in dict(parse_gost("6-46310Л").suffixes)["Л"]


# ---------------------------------------------------------------- ambiguity


@pytest.mark.parametrize(
    "text, iso_type, gost_type",
    [
        ("6205", "radial_ball", "angular_contact_ball"),
        ("7206", "angular_contact_ball", "tapered_roller"),
        ("2205", "self_aligning_ball", "cylindrical_roller"),
    ],
)
def test_ambiguous_text_returns_iso_with_gost_alternative(
    text: str, iso_type: str, gost_type: str
) -> None:
    d = parse(text)
    assert (d.system, d.bearing_type) == ("iso", iso_type)
    assert len(d.alternatives) == 1
    alt = d.alternatives[0]
    assert (alt.system, alt.bearing_type) == ("gost", gost_type)
    note = [n for n in d.notes if n.startswith("also reads as GOST 3189-89")]
    assert len(note) == 1 and alt.description in note[0] and "`system` gost" in note[0]


def test_same_bearing_in_both_systems_has_no_ambiguity_note() -> None:
    d = parse("1205")
    assert d.system == "iso" and d.alternatives[0].system == "gost"
    assert not any("also reads" in n for n in d.notes)


def test_forced_systems() -> None:
    g = parse("6205", system="gost")
    assert (g.system, g.bearing_type, g.alternatives) == ("gost", "angular_contact_ball", ())
    i = parse("6205", system="iso")
    assert (i.system, i.bearing_type, i.alternatives) == ("iso", "radial_ball", ())
    assert not any("also reads" in n for n in i.notes)
    with pytest.raises(DesignationError):
        parse("6-36209", system="iso")
    with pytest.raises(DesignationError):
        parse("6205-2RS", system="gost")


@pytest.mark.parametrize("text", ["6-36209", "180205", "3003124", "4-12210Е", "311"])
def test_gost_only_texts(text: str) -> None:
    d = parse(text)
    assert d.system == "gost" and d.alternatives == ()


# ---------------------------------------------------------------- errors


@pytest.mark.parametrize(
    "text, part",
    [
        ("6205-XYZ", "XYZ"),
        ("62A5", "A5"),
        ("", ""),
        ("abc", "abc"),
        ("NX206", "NX"),
        ("6-36209Z", "Z"),
        ("9-205", "9"),
    ],
)
def test_errors_name_the_bad_part(text: str, part: str) -> None:
    with pytest.raises(DesignationError) as err:
        parse(text)
    assert err.value.part == part
    assert err.value.designation == text
    assert repr(part) in str(err.value)


def test_unknown_suffix_message() -> None:
    with pytest.raises(DesignationError, match=r"cannot read 'XYZ': unknown suffix"):
        parse("6205-XYZ")


@pytest.mark.parametrize("system", ["GOST", "din", "", 3])
def test_invalid_system(system: object) -> None:
    with pytest.raises(InputError) as err:
        parse("6205", system=system)  # type: ignore[arg-type]
    assert err.value.parameter == "system"


# ---------------------------------------------------------------- model


def test_to_dict_is_json_ready_in_engineering_units() -> None:
    d = parse("6205")
    data = json.loads(json.dumps(d.to_dict()))
    assert data["bore_mm"] == 25.0 and data["contact_angle_deg"] is None
    assert data["alternatives"][0]["system"] == "gost"
    assert data["parts"][0] == {"text": "6", "meaning": d.parts[0][1]}
    assert parse("7308 AC").to_dict()["contact_angle_deg"] == pytest.approx(25.0)


def test_designation_is_frozen_and_validated() -> None:
    d = parse("6205")
    with pytest.raises(dataclasses.FrozenInstanceError):
        d.bore = 1.0  # type: ignore[misc]
    with pytest.raises(ValueError):
        Designation(text="x", system="din", bearing_type="radial_ball", bore=0.01, bore_code="00")
    assert len(BEARING_TYPES) == 11 and BEARING_TYPES[9] == "thrust_roller"


def test_description_example() -> None:
    assert parse("180205").description == (
        "deep-groove ball bearing, light diameter series 2, "
        "width series 0, bore 25 mm, two rubber seals"
    )


@pytest.mark.parametrize("text", ["6-36209", "180205", "3003124", "1000096", "205Е"])
def test_iso_reader_refuses_gost_only_forms(text: str) -> None:
    with pytest.raises(DesignationError):
        parse_iso(text)


# ---------------------------------------------------------------- review fixes


def test_full_width_digits_are_normalised() -> None:
    # NFKC turns full-width digits and letters into ASCII; the reading is that of "6205"
    for text, plain in (
        ("６２０５", "6205"),
        ("６２０５－２ＲＳ", "6205-2RS"),
        ("１８０２０５", "180205"),
    ):
        a, b = parse(text).to_dict(), parse(plain).to_dict()
        assert a.pop("text") == text
        b.pop("text")
        # notes quote the text as written ("cannot read '－２ＲＳ'")
        assert len(a.pop("notes")) == len(b.pop("notes"))
        for alt in a["alternatives"] + b["alternatives"]:
            alt.pop("text")
        assert a == b


@pytest.mark.parametrize("text, part", [("٦٢٠٥", "٦٢٠٥"), ("62٠5", "٠"), ("۶۲۰۵", "۶۲۰۵")])
def test_other_scripts_digits_are_refused_naming_them(text: str, part: str) -> None:
    for reader in (parse, parse_gost, parse_iso):
        with pytest.raises(DesignationError) as err:
            reader(text)
        assert err.value.part == part and "0-9" in str(err.value)


def test_a_reader_that_fails_says_what_it_could_not_read() -> None:
    d = parse("6205 C")  # С: closed and greased in GOST; no C suffix on an ISO 62 bearing
    assert d.system == "gost" and d.bearing_type == "angular_contact_ball"
    assert any(n.startswith("not an ISO designation: cannot read 'C'") for n in d.notes)
    i = parse("6205-2RS")
    assert any(n.startswith("not a GOST 3189-89 designation: cannot read '-2RS'") for n in i.notes)
    assert not any(n.startswith("not a") for n in parse("1205").notes)  # both readers agree


@pytest.mark.parametrize(
    "text, part, words",
    [
        ("6205 2RS 2Z", "2Z", "conflicts with 2RS"),
        ("6205-Z-2Z", "2Z", "conflicts with Z"),
        ("6205-2RS-Z", "Z", "conflicts"),
        ("7206 B B", "B", "repeated"),
        ("6205 C3 C3", "C3", "repeated"),
        ("180205ЕЕ", "Е", "repeated"),
        ("6205-2RS-", "-", "separator"),
        ("6205/", "/", "separator"),
        ("626 --", "--", "separator"),
        ("6205--2RS", "--", "separator"),
        ("0", "0", "too short"),
        ("00", "00", "too short"),
        ("1", "1", "too short"),
        ("6-0", "0", "too short"),
    ],
)
def test_contradictory_and_junk_designations_are_refused(text: str, part: str, words: str) -> None:
    with pytest.raises(DesignationError) as err:
        parse(text)
    assert err.value.part == part and words in str(err.value)


def test_one_shield_and_one_seal_are_still_read() -> None:
    d = parse("6205 Z RS")  # two sides, two closures: not a contradiction
    assert d.closures == "unknown"


@pytest.mark.parametrize("text", ["6205 ZNR", "6205 NR 2Z", "6205-2ZNR", "6205 NR"])
def test_snap_ring_stays_in_the_description(text: str) -> None:
    assert "snap ring" in parse(text).description


def test_spherical_213_family_is_read() -> None:
    d = parse_iso("21305")
    assert (d.series, d.bearing_type, d.dimension_series, d.bore_mm) == (
        "213",
        "spherical_roller",
        "03",
        25.0,
    )


@pytest.mark.parametrize("text", ["NU205", "180205"])
def test_a_reader_stopped_at_the_first_character_adds_no_note(text) -> None:
    # NU205 is no GOST number from its first letter; 180205 no ISO family: saying so is noise
    assert not any(n.startswith("not a") for n in parse(text).notes)
