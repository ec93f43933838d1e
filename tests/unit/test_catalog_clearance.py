"""ISO 5753-1 radial internal clearance of deep-groove ball bearings in the catalogue."""

import pytest

from bearinglab.catalog import bearing_from_designation, radial_clearance
from bearinglab.catalog._data import TABLES, read_table, source_lines
from bearinglab.catalog.build import _table_clearance
from bearinglab.catalog.lookup import CLEARANCE_GROUPS, CLEARANCE_TABLE
from bearinglab.errors import CatalogError, InputError
from bearinglab.geometry import Source

UM = 1e-6
MM = 1e-3


# ------------------------------------------------------------------ the shipped table


def test_table_is_registered_and_names_iso_5753():
    assert CLEARANCE_TABLE in TABLES
    lines = source_lines(CLEARANCE_TABLE)
    assert lines[0].startswith("ISO 5753-1")
    assert any("NTN" in line for line in lines) and any("NSK" in line for line in lines)


def test_table_columns_and_groups():
    t = read_table(CLEARANCE_TABLE)
    assert list(t.columns) == ["bore_over_mm", "bore_incl_mm", "group", "min_um", "max_um"]
    assert set(t["group"]) == set(CLEARANCE_GROUPS)
    assert not t.isna().any().any()
    assert not t.duplicated(["bore_over_mm", "group"]).any()
    assert (t["bore_incl_mm"] > t["bore_over_mm"]).all()


def test_ranges_are_not_empty():
    t = read_table(CLEARANCE_TABLE)
    assert (t["min_um"] >= 0).all()
    assert (t["max_um"] > t["min_um"]).all()


def test_covers_2_5_to_at_least_120_mm():
    t = read_table(CLEARANCE_TABLE)
    for group in ("C2", "CN", "C3"):
        rows = t[t["group"] == group]
        assert rows["bore_over_mm"].min() == 2.5 and rows["bore_incl_mm"].max() >= 120
    for group in ("C4", "C5"):  # ISO gives C4 and C5 only from 6 mm on
        rows = t[t["group"] == group]
        assert rows["bore_over_mm"].min() == 6 and rows["bore_incl_mm"].max() >= 120


@pytest.mark.parametrize("group", CLEARANCE_GROUPS)
def test_bands_are_contiguous(group):
    rows = read_table(CLEARANCE_TABLE).query("group == @group").sort_values("bore_over_mm")
    over, incl = list(rows["bore_over_mm"]), list(rows["bore_incl_mm"])
    assert over[1:] == incl[:-1]


def test_groups_are_ordered_in_every_band():
    t = read_table(CLEARANCE_TABLE)
    order = {g: i for i, g in enumerate(CLEARANCE_GROUPS)}
    for _, band in t.groupby("bore_over_mm"):
        band = band.sort_values("group", key=lambda s: s.map(order))
        assert band["min_um"].is_monotonic_increasing
        assert band["max_um"].is_monotonic_increasing
        # each group starts above the one below it and ends above it
        assert (band["min_um"].diff().dropna() > 0).all()
        assert (band["max_um"].diff().dropna() > 0).all()


def test_clearance_grows_with_the_bore():
    t = read_table(CLEARANCE_TABLE)
    for group in CLEARANCE_GROUPS:
        rows = t[t["group"] == group].sort_values("bore_over_mm")
        assert rows["min_um"].is_monotonic_increasing
        assert rows["max_um"].is_monotonic_increasing


# ------------------------------------------------------------------ radial_clearance


@pytest.mark.parametrize(
    "bore_mm,group,expected_um",
    [
        (25, "CN", (5, 20)),
        (25, "C3", (13, 28)),
        (24, "CN", (5, 20)),  # 24 is the upper end of "over 18 incl 24"
        (24.001, "C4", (23, 41)),  # just over 24: the next band
        (10, "C2", (0, 7)),
        (17, "C5", (25, 45)),
        (40, "C3", (15, 33)),
        (100, "CN", (12, 36)),
        (120, "C5", (90, 140)),
        (3, "C3", (8, 23)),
    ],
)
def test_lookup_of_rows(bore_mm, group, expected_um):
    low, high = radial_clearance(bore_mm * MM, group)
    assert (low, high) == pytest.approx((expected_um[0] * UM, expected_um[1] * UM), abs=1e-12)


def test_default_group_is_cn_and_group_spelling_is_lenient():
    assert radial_clearance(0.025) == radial_clearance(0.025, "CN")
    assert radial_clearance(0.025, " c3 ") == radial_clearance(0.025, "C3")
    assert radial_clearance(0.025, "Normal") == radial_clearance(0.025, "CN")
    assert radial_clearance(0.025, "C0") == radial_clearance(0.025, "CN")


@pytest.mark.parametrize("group", ["C1", "C6", "X", "", None, 3])
def test_unknown_group_is_an_input_error(group):
    with pytest.raises(InputError, match="group"):
        radial_clearance(0.025, group)


@pytest.mark.parametrize(
    "bore,group,match",
    [
        (0.0025, "CN", "over 2.5 incl 140"),  # 2.5 mm itself is not "over 2.5"
        (0.001, "C2", "over 2.5 incl 140"),
        (0.150, "CN", "over 2.5 incl 140"),
        (0.004, "C4", "over 6 incl 140"),  # ISO gives no C4 below 6 mm
        (25.0, "CN", "in metres"),  # millimetres passed by mistake
    ],
)
def test_bore_outside_the_table_is_a_catalog_error(bore, group, match):
    with pytest.raises(CatalogError, match=match):
        radial_clearance(bore, group)


@pytest.mark.parametrize("bore", [0.0, -0.025, float("nan"), "25", True])
def test_bad_bore_is_an_input_error(bore):
    with pytest.raises(InputError, match="bore"):
        radial_clearance(bore)


# ------------------------------------------------------------------ bearing_from_designation


def _mean(low_um, high_um):
    return (low_um + high_um) / 2 * UM


def test_6205_gets_the_cn_mean():
    b, _ = bearing_from_designation("6205")
    assert b.diametral_clearance == pytest.approx(_mean(5, 20))
    src = b.sources["diametral_clearance"]
    assert src.kind == "estimated"
    assert src.reference.startswith("ISO 5753-1 group CN: mean of 5-20 um (")
    assert "CN (normal) assumed" in src.reference


def test_6205_c3_gets_the_c3_mean():
    b, des = bearing_from_designation("6205 C3")
    assert "C3" in [code for code, _ in des.suffixes]
    assert b.diametral_clearance == pytest.approx(_mean(13, 28))
    assert b.sources["diametral_clearance"].reference.startswith(
        "ISO 5753-1 group C3: mean of 13-28 um ("
    )
    assert "suffix C3" in b.sources["diametral_clearance"].reference


def test_6205_2rs_c4_gets_the_c4_mean():
    b, des = bearing_from_designation("6205-2RS C4")
    assert des.closures == "2seals"
    assert b.diametral_clearance == pytest.approx(_mean(23, 41))
    assert "group C4: mean of 23-41 um" in b.sources["diametral_clearance"].reference


@pytest.mark.parametrize(
    "text,expected_um",
    [
        ("6205-2RS/C3", (13, 28)),
        ("6205 P63", (13, 28)),  # SKF: tolerance class 6 + C3
        ("6205 C2", (1, 11)),
        ("6310 C5", (45, 73)),  # 50 mm: the upper end of "over 40 incl 50"
        ("6311 C5", (55, 90)),  # 55 mm: "over 50 incl 65"
        ("608", (2, 13)),
        ("6000", (2, 13)),  # 10 mm: the upper end of "over 6 incl 10"
        ("6200 C2", (0, 7)),
    ],
)
def test_group_and_bore_pick_the_row(text, expected_um):
    b, _ = bearing_from_designation(text)
    assert b.diametral_clearance == pytest.approx(_mean(*expected_um))


def test_published_row_without_clearance_gets_the_table_value():
    b, _ = bearing_from_designation("6205-2RS")  # the CWRU drive-end row
    assert b.sources["ball_count"].kind == "catalog"
    assert b.diametral_clearance == pytest.approx(_mean(5, 20))
    assert b.sources["diametral_clearance"].kind == "estimated"


def test_published_clearance_wins():
    b, _ = bearing_from_designation("209 (Harris)")  # P_d = 15 um published
    assert b.diametral_clearance == pytest.approx(15 * UM)
    assert b.sources["diametral_clearance"].kind == "catalog"


def test_overrides_win():
    b, _ = bearing_from_designation("6205 C3", overrides={"diametral_clearance": 40e-6})
    assert b.diametral_clearance == pytest.approx(40e-6)
    assert b.sources["diametral_clearance"] == Source("user", "command line or caller")
    # an explicit group the table cannot give does not matter once the caller gives P_d
    c, _ = bearing_from_designation("6205 C1", overrides={"diametral_clearance": 3e-6})
    assert c.diametral_clearance == pytest.approx(3e-6)


def test_contact_angle_override_keeps_the_table_clearance():
    b, _ = bearing_from_designation("6205 C3", overrides={"contact_angle": 0.1})
    assert b.contact_angle == pytest.approx(0.1)
    assert b.sources["contact_angle"].kind == "user"
    assert b.diametral_clearance == pytest.approx(_mean(13, 28))
    assert b.sources["diametral_clearance"].kind == "estimated"


def test_angular_contact_keeps_the_clearance_from_its_angle():
    b, _ = bearing_from_designation("7205 B")
    assert b.sources["diametral_clearance"].kind == "default"
    assert b.free_contact_angle == pytest.approx(b.contact_angle)


def test_gost_designations_get_cn_with_a_note():
    plain, des = bearing_from_designation("180205")
    assert des.system == "gost"
    assert plain.diametral_clearance == pytest.approx(_mean(5, 20))
    assert "CN (normal) assumed" in plain.sources["diametral_clearance"].reference
    grouped, des = bearing_from_designation("А125-205")  # clearance group 2 in the prefix
    assert des.system == "gost"
    assert grouped.diametral_clearance == pytest.approx(_mean(5, 20))
    ref = grouped.sources["diametral_clearance"].reference
    assert ref.startswith("ISO 5753-1 group CN") and "GOST clearance group 2" in ref
    assert "not verified" in ref


@pytest.mark.parametrize(
    "text,match",
    [
        ("6205 C1", "C1"),  # no C1 group for deep-groove ball bearings
        ("623 C4", "over 6"),  # ISO gives no C4 below 6 mm
    ],
)
def test_explicit_group_the_table_cannot_give_is_an_error(text, match):
    with pytest.raises(CatalogError, match=match) as info:
        bearing_from_designation(text)
    assert "override" in str(info.value)


def test_the_nominal_bore_of_the_designation_picks_the_row():
    b, _ = bearing_from_designation("6205", overrides={"bore": 0.0245})
    assert b.bore == pytest.approx(0.0245)
    assert b.diametral_clearance == pytest.approx(_mean(5, 20))
    assert "bore 25 mm" in b.sources["diametral_clearance"].reference


def test_implied_cn_outside_the_table_keeps_the_default():
    class Tiny:  # the Designation fields the clearance look-up reads
        system, bore, suffixes, prefixes = "iso", 0.002, (), ()

    value, source = _table_clearance(Tiny(), "tiny")
    assert value is None and source.kind == "default" and "ISO 5753-1" in source.reference

    class Explicit(Tiny):
        suffixes = (("C3", "radial internal clearance C3"),)

    with pytest.raises(CatalogError, match="C3"):
        _table_clearance(Explicit(), "explicit")
