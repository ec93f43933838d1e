"""bearinglab.catalog: shipped tables, look-ups, estimate, bearing_from_designation."""

import math
from dataclasses import dataclass

import pandas as pd
import pytest

from bearinglab.catalog import (
    FAMILIES,
    BoundaryDimensions,
    bearing_from_designation,
    boundary_dimensions,
    catalog_table,
    estimate_internal_geometry,
    published_geometries,
    published_geometry,
)
from bearinglab.catalog._data import TABLES, read_table, source_lines
from bearinglab.catalog.estimate import (
    ESTIMATE_METHOD,
    ball_count_and_pitch,
    ball_diameter_factor,
    diameter_series_group,
)
from bearinglab.errors import CatalogError, InputError
from bearinglab.geometry import BallBearing, Source

#: The standard bore codes 00-20: d = 10, 12, 15, 17, 20, 25, ..., 100 mm.
STANDARD_BORES = [10, 12, 15, 17] + list(range(20, 101, 5))


@dataclass(frozen=True)
class StandIn:
    """The Designation fields the catalogue uses, for tests independent of the reader."""

    text: str
    series: str | None
    bore: float
    dimension_series: str | None = None
    bearing_type: str = "radial_ball"
    contact_angle: float | None = None


# ------------------------------------------------------------------------------ data


@pytest.mark.parametrize("name", sorted(TABLES))
def test_every_table_names_its_source(name):
    lines = source_lines(name)
    assert lines and all(len(line) > 20 for line in lines)


@pytest.mark.parametrize(
    "name,key",
    [
        ("iso15_radial.csv", "dimension_series"),
        ("iso355_tapered.csv", "series"),
        ("iso104_thrust.csv", "series"),
    ],
)
def test_dimension_tables_are_sane(name, key):
    t = read_table(name)
    width = {
        "iso15_radial.csv": "width_mm",
        "iso355_tapered.csv": "total_width_mm",
        "iso104_thrust.csv": "height_mm",
    }[name]
    assert not t.isna().drop(columns=[c for c in t.columns if c == "chamfer_min_mm"]).any().any()
    assert (t["outside_diameter_mm"] > t["bore_mm"]).all()
    assert (t[width] > 0).all()
    assert not t.duplicated([key, "bore_mm"]).any()
    for _, group in t.groupby(key):
        g = group.sort_values("bore_mm")
        # within a series D grows strictly with the bore and the width never shrinks
        assert g["outside_diameter_mm"].is_monotonic_increasing
        assert g["outside_diameter_mm"].diff().dropna().gt(0).all()
        assert g[width].is_monotonic_increasing


def test_radial_chamfers_are_positive_and_small():
    t = read_table("iso15_radial.csv")
    assert (t["chamfer_min_mm"] > 0).all()
    assert (t["chamfer_min_mm"] < t["width_mm"] / 2).all()


def test_tapered_widths_are_ordered():
    t = read_table("iso355_tapered.csv")
    assert (t["total_width_mm"] >= t["cone_width_mm"]).all()
    assert (t["cone_width_mm"] >= t["cup_width_mm"]).all()


def test_dimension_series_keep_their_leading_zero():
    series = set(read_table("iso15_radial.csv")["dimension_series"])
    assert {"00", "02", "03", "04", "10", "18", "19", "22", "23"} <= series


#: Families whose shipped rows do not cover every standard bore 10-100 mm, with the
#: bores that are there.  Everything not listed here must resolve at all 21 bores.
GAPS = {
    "160": STANDARD_BORES[1:],  # 16000 does not exist; 16001 = 12 mm
    "618": [b for b in STANDARD_BORES if b != 95],  # 61819 not in the KOYO tables
    "68": [b for b in STANDARD_BORES if b != 95],
    "718": [b for b in STANDARD_BORES if b != 95],
    "64": STANDARD_BORES[3:],
    "N4": STANDARD_BORES[3:],
    "NU4": STANDARD_BORES[3:],
    "NJ4": STANDARD_BORES[3:],
    "NUP4": STANDARD_BORES[3:],
    "NF4": STANDARD_BORES[3:],
    "302": STANDARD_BORES[2:],
    "303": STANDARD_BORES[2:],
    "213": STANDARD_BORES,
    "320": STANDARD_BORES[4:],
    "322": STANDARD_BORES[3:],
    "323": STANDARD_BORES[3:],
    "511": [b for b in STANDARD_BORES if b != 95],
    "512": [b for b in STANDARD_BORES if b != 95],
    "513": [b for b in STANDARD_BORES[5:] if b != 95],
    "514": [b for b in STANDARD_BORES[5:] if b != 95],
    "230": [100],
    "232": [90, 100],
    "NN30": [100],
    # no shipped rows at 10-100 mm: double-row 33, needle, spherical 231/238-249, tapered
    # 313/329-332, thrust roller
    **{
        k: []
        for k in (
            "33",
            "NA48",
            "NA49",
            "NA69",
            "231",
            "238",
            "239",
            "240",
            "241",
            "248",
            "249",
            "313",
            "329",
            "330",
            "331",
            "332",
            "811",
            "812",
            "292",
            "293",
            "294",
        )
    },
}
GAPS["32"] = [90, 100]  # double-row angular contact 32xx shares dimension series 32


@pytest.mark.parametrize("key", sorted(FAMILIES))
def test_every_family_resolves_for_the_standard_bores(key):
    fam = FAMILIES[key]
    found = []
    for bore in STANDARD_BORES:
        des = StandIn(f"{key} d={bore}", key, bore * 1e-3, fam.dimension_series, fam.bearing_type)
        try:
            dims = boundary_dimensions(des)
        except CatalogError as exc:
            assert key in str(exc) and f"{bore:g} mm" in str(exc)
            continue
        assert dims.bore == pytest.approx(bore * 1e-3)
        assert dims.outside_diameter > dims.bore and dims.width > 0
        found.append(bore)
    assert found == GAPS.get(key, STANDARD_BORES)


# ------------------------------------------------------------------------- look-ups


def test_boundary_dimensions_from_a_stand_in_designation():
    dims = boundary_dimensions(StandIn("6205", "62", 0.025, "02"))
    assert isinstance(dims, BoundaryDimensions)
    assert (dims.bore, dims.outside_diameter, dims.width) == pytest.approx((0.025, 0.052, 0.015))
    assert dims.chamfer_min == pytest.approx(1e-3)
    assert dims.standard.startswith("ISO 15:2017 dimension series 02")
    assert dims.to_dict()["width_mm"] == 15.0


def test_unknown_family_falls_back_on_the_dimension_series():
    dims = boundary_dimensions(StandIn("X205", "X2", 0.025, "02", "radial_ball"))
    assert dims.outside_diameter == pytest.approx(0.052)


def test_tapered_and_thrust_extras():
    t = boundary_dimensions(StandIn("30205", "302", 0.025, "02", "tapered_roller"))
    assert (t.width, t.cone_width, t.cup_width) == pytest.approx((16.25e-3, 15e-3, 13e-3))
    h = boundary_dimensions(StandIn("51205", "512", 0.025, "12", "thrust_ball"))
    assert h.height == h.width == pytest.approx(15e-3)
    assert h.cone_width is None and t.height is None


def test_missing_bore_lists_the_bores_that_are_there():
    with pytest.raises(CatalogError) as err:
        boundary_dimensions(StandIn("6421", "64", 0.105, "04"))
    text = str(err.value)
    assert "family 64" in text and "105 mm" in text and "17, 20, 25" in text and "100" in text


def test_unknown_family_without_series_is_a_catalog_error():
    with pytest.raises(CatalogError, match="no boundary-dimension table"):
        boundary_dimensions(StandIn("?", None, 0.025, None, "thrust_roller"))
    assert issubclass(CatalogError, LookupError)


def test_designation_text_is_parsed():
    assert boundary_dimensions("6205-2RS") == boundary_dimensions("6205")
    gost = boundary_dimensions("180205")
    assert (gost.bore, gost.outside_diameter, gost.width) == pytest.approx((0.025, 0.052, 0.015))


def test_published_geometry_by_name_is_case_and_space_insensitive():
    assert published_geometry("er-16k").name == "ER-16K"
    assert published_geometry("  6205   (SEED 004) ").name == "6205 (seed 004)"
    assert published_geometry(StandIn("6205", "62", 0.025)).name == "6205 (CWRU drive end)"
    assert published_geometry(StandIn("6006", "60", 0.030)) is None  # 106 row: by name only


@pytest.mark.parametrize("text", ["6205", "6205-2RS", "6205 2Z C3", "180205", "205"])
def test_published_geometry_by_designation_ignores_suffixes(text):
    assert published_geometry(text).name == "6205 (CWRU drive end)"


def test_published_rows_are_consistent():
    rows = published_geometries()
    names = [g.name for g in rows]
    assert len(names) == len({n.casefold() for n in names})
    for g in rows:
        assert g.source and g.ball_count is not None
        if g.ball_diameter is not None and g.pitch_diameter is not None:
            assert 0 < g.ball_diameter < g.pitch_diameter
            assert g.ball_count <= math.pi / math.asin(g.ball_diameter / g.pitch_diameter)
    defaults = [g.designation for g in rows if g.default and g.designation]
    assert len(defaults) == len(set(defaults)), "one default row per designation"


def test_catalog_table_kinds():
    dims = catalog_table()
    assert set(dims["table"]) == {"iso15_radial.csv", "iso355_tapered.csv", "iso104_thrust.csv"}
    assert len(dims) == sum(len(read_table(n)) for n in set(dims["table"]))
    assert {"family", "standard", "table"} <= set(catalog_table("families").columns)
    assert "source" in catalog_table("geometry").columns
    with pytest.raises(ValueError):
        catalog_table("nonsense")


# ------------------------------------------------------------------------- estimate


def test_table_1_and_2_lookups():
    assert [diameter_series_group(s) for s in ("18", "19", "00", "10", "02", "22", "03", "04")] == [
        "0",
        "0",
        "0",
        "0",
        "2",
        "2",
        "3",
        "4",
    ]
    assert ball_diameter_factor(0.025, "02") == 0.30  # (0.29 + 0.31) / 2, d <= 35 mm
    assert ball_diameter_factor(0.040, "02") == 0.315  # (0.31 + 0.32) / 2, 35 < d <= 120
    assert ball_diameter_factor(0.130, "10") == 0.27  # (0.24 + 0.30) / 2, d > 120 mm
    with pytest.raises(InputError):
        diameter_series_group("05")


def test_filling_angle_rule_enlarges_the_pitch_then_drops_a_ball():
    # 6205: 9 balls of 8.1 mm fill 194.3 deg > 194 deg, so d_m grows to 38.56 mm (< 3 %)
    z, dm, notes = ball_count_and_pitch(8.1e-3, 38.5e-3, "02")
    assert (z, notes) == (9, ())
    assert 2 * 8 * math.degrees(math.asin(8.1 / (dm * 1e3))) == pytest.approx(194.0)
    # 6308 (D_w = 0.32 x 50 = 16 mm): 8 balls would need d_m + 3.3 %: 7 balls, below 180 deg
    z, dm, notes = ball_count_and_pitch(16e-3, 65e-3, "03")
    assert z == 7 and dm == pytest.approx(65e-3) and "below the 180 deg" in notes[0]


def test_estimate_refuses_what_it_cannot_do():
    with pytest.raises(InputError):
        estimate_internal_geometry(0.05, 0.09, "22", "cylindrical_roller")
    with pytest.raises(InputError):
        estimate_internal_geometry(0.05, 0.04, "02")
    with pytest.raises(InputError):
        estimate_internal_geometry(0.025, 0.052, "02", "angular_contact_ball")  # no angle


def test_angular_contact_estimate_keeps_the_angle_and_says_z_is_a_lower_bound():
    g = estimate_internal_geometry(0.025, 0.052, "02", "angular_contact_ball", math.radians(40))
    assert g.contact_angle == pytest.approx(math.radians(40))
    assert any("lower bound" in n for n in g.notes)


def test_every_ball_bearing_size_gives_a_valid_bearing():
    t = read_table("iso15_radial.csv")
    series = ["18", "19", "00", "10", "02", "03", "04"]
    for _, r in t[t["dimension_series"].isin(series)].iterrows():
        d, big_d = r["bore_mm"] * 1e-3, r["outside_diameter_mm"] * 1e-3
        g = estimate_internal_geometry(d, big_d, r["dimension_series"])
        b = BallBearing(**g.as_kwargs(), bore=d, outside_diameter=big_d, width=r["width_mm"] * 1e-3)
        # thin sections carry many small balls, heavy small-bore sections few large ones
        assert 5 <= b.ball_count <= 27
        assert math.degrees(g.fill_angle) <= 195.0 + 1e-9
        if math.degrees(g.fill_angle) < 180.0:
            assert g.notes and "below the 180 deg" in g.notes[0]
        assert 0.515 == b.inner_groove_factor and 0.525 == b.outer_groove_factor


# ------------------------------------------------------------ bearing_from_designation


def test_published_bearing_keeps_its_sources():
    b, des = bearing_from_designation("6205-2RS")
    assert des.series == "62" and b.name == "6205-2RS"
    assert (b.ball_count, b.ball_diameter, b.pitch_diameter) == pytest.approx(
        (9, 0.3126 * 0.0254, 1.537 * 0.0254)
    )
    assert b.sources["ball_count"].kind == "catalog"
    assert "Case Western" in b.sources["ball_diameter"].reference
    assert b.sources["inner_groove_factor"] == Source("estimated", ESTIMATE_METHOD)
    assert b.inner_groove_factor == 0.515 and b.outer_groove_factor == 0.525
    assert b.sources["bore"].kind == "catalog"
    # the CWRU row prints no clearance: the ISO 5753-1 CN mean fills it in
    assert b.sources["diametral_clearance"].kind == "estimated"
    assert b.sources["diametral_clearance"].reference.startswith("ISO 5753-1 group CN")


def test_catalogue_name_without_designation():
    b, des = bearing_from_designation("ER-16K")
    assert des is None and b.name == "ER-16K"
    assert b.diametral_clearance == pytest.approx(90e-6)
    assert b.bore is None
    assert b.sources["diametral_clearance"].kind == "catalog"
    assert b.sources["contact_angle"].kind == "default"


def test_partial_row_is_completed_by_the_estimate():
    b, _ = bearing_from_designation("310", system="gost")  # seed 000: only Z = 8
    assert b.ball_count == 8 and b.sources["ball_count"].kind == "catalog"
    assert b.sources["ball_diameter"].kind == "estimated"
    assert b.outside_diameter == pytest.approx(0.110)
    assert b.sources["outside_diameter"].reference.startswith("ISO 15:2017")


def test_overrides_win_and_are_marked_user():
    b, _ = bearing_from_designation(
        "6205",
        overrides={"ball_count": 8, "diametral_clearance": 20e-6, "outside_diameter": 0.0521},
    )
    assert b.ball_count == 8 and b.diametral_clearance == pytest.approx(20e-6)
    assert b.outside_diameter == pytest.approx(0.0521)
    for key in ("ball_count", "diametral_clearance", "outside_diameter"):
        assert b.sources[key] == Source("user", "command line or caller")
    assert b.sources["ball_diameter"].kind == "catalog"


def test_overrides_feed_the_estimate():
    plain, _ = bearing_from_designation("6308")
    wide, _ = bearing_from_designation("6308", overrides={"bore": 0.038})
    assert wide.ball_diameter > plain.ball_diameter
    assert wide.sources["ball_diameter"].kind == "estimated"


def test_bad_overrides_are_input_errors():
    with pytest.raises(InputError, match="overrides"):
        bearing_from_designation("6205", overrides={"balls": 9})
    with pytest.raises(InputError, match="ball_count"):
        bearing_from_designation("6205", overrides={"ball_count": 2})


@pytest.mark.parametrize("text", ["NU2210", "22310", "30205", "NA4905", "51205", "2205", "3205"])
def test_non_modelled_types_are_catalog_errors(text):
    with pytest.raises(CatalogError, match="internal-geometry model"):
        bearing_from_designation(text)


def test_roller_bearings_still_have_boundary_dimensions():
    assert boundary_dimensions("NU2210").width == pytest.approx(0.023)


def test_angular_contact_uses_designation_or_family_angle():
    b, _ = bearing_from_designation("7205")
    assert b.contact_angle == pytest.approx(math.radians(40))
    assert b.sources["contact_angle"].kind == "default"
    c, _ = bearing_from_designation("7205 C")
    assert c.contact_angle == pytest.approx(math.radians(15))
    assert c.sources["contact_angle"].kind == "catalog"


def test_no_family_no_estimate():
    with pytest.raises(CatalogError, match="cannot estimate"):
        bearing_from_designation("6421")


def test_result_frame_types():
    assert isinstance(catalog_table(), pd.DataFrame)


# ------------------------------------------------------------------------ review fixes


def test_iso_family_registries_agree():
    # The ISO families live twice: the designation reader's table (type, dimension series,
    # GOST cross reference, suffix group) and the catalogue's (dimension table, rows,
    # default contact angle). Every key in both must name the same type and series.
    from bearinglab.designation._tables import FAMILIES as READER_FAMILIES

    shared = set(READER_FAMILIES) & set(FAMILIES)
    assert "213" in shared and "62" in shared and "511" in shared
    for key in shared:
        assert READER_FAMILIES[key].bearing_type == FAMILIES[key].bearing_type, key
        assert READER_FAMILIES[key].dims == FAMILIES[key].dimension_series, key
    # the catalogue has nothing the reader cannot read; the reader's double-direction
    # thrust series have no dimension table yet
    assert set(FAMILIES) - set(READER_FAMILIES) == set()
    assert set(READER_FAMILIES) - set(FAMILIES) == {"522", "523", "524"}


@pytest.mark.parametrize("text", ["6205", "6306", "6205 C"])  # GOST 7206 is tapered roller
def test_gost_angular_contact_without_angle_variant_gets_no_iso_default(text):
    from bearinglab.catalog import GeometryNeeded

    with pytest.raises(GeometryNeeded) as err:
        bearing_from_designation(text, system="gost" if text != "6205 C" else None)
    assert err.value.needed == ("contact_angle",) and "design variant" in str(err.value)
    b, des = bearing_from_designation(
        text,
        system="gost" if text != "6205 C" else None,
        overrides={"contact_angle": math.radians(26)},
    )
    assert des.system == "gost" and b.contact_angle == pytest.approx(math.radians(26))
    # the angle a GOST variant writes is used; ISO 72 keeps its family default (documented)
    assert bearing_from_designation("6-36209")[0].contact_angle == pytest.approx(math.radians(12))
    assert bearing_from_designation("7206")[0].contact_angle == pytest.approx(math.radians(40))


def test_thrust_ball_bearing_from_explicit_geometry():
    from bearinglab.catalog import GeometryNeeded

    with pytest.raises(GeometryNeeded) as err:
        bearing_from_designation("51105", overrides={"ball_count": 15})
    assert err.value.needed == ("ball_diameter", "pitch_diameter")
    assert "internal-geometry model" in str(err.value)
    b, des = bearing_from_designation(
        "51105", overrides={"ball_count": 15, "ball_diameter": 6e-3, "pitch_diameter": 33.5e-3}
    )
    assert b.bearing_type == des.bearing_type == "thrust_ball"
    assert b.contact_angle == pytest.approx(math.pi / 2)
    assert b.sources["contact_angle"].kind == "default"
    assert (b.bore, b.outside_diameter, b.width) == pytest.approx((0.025, 0.042, 0.011))
    assert b.sources["bore"].reference.startswith("ISO 104")
    assert b.sources["inner_groove_factor"].kind == "default"
    with pytest.raises(CatalogError, match="double-direction"):
        bearing_from_designation(
            "52205", overrides={"ball_count": 15, "ball_diameter": 6e-3, "pitch_diameter": 33.5e-3}
        )


@pytest.mark.parametrize("text", ["NU2210", "22310", "30205", "51205", "2205", "1205"])
def test_catalogue_messages_carry_no_python_api_hint(text):
    with pytest.raises(CatalogError) as err:
        bearing_from_designation(text)
    assert "boundary_dimensions()" not in str(err.value)
