"""Shared tables of the designation readers: bearing names, ISO families, bore codes.

Sources.  The GOST 3189-89 bore code (00=10, 01=12, 02=15, 03=17 mm, else x5 for d = 20 to
495 mm) is from seed 003 lines 137-139; the GOST diameter series of line 141 are mapped
onto the ISO 15 dimension series by :func:`gost_iso_dims`.  The ISO 15 families (``62``,
``NU2``, ``302``...) and the GOST <-> ISO cross references are the usual catalogue
correspondences (e.g. 106 = 6006, 7000106 = 16006, 3003124 = 23024); each family that is a
cross reference rather than a seed-003 statement says so in its notes.  The GOST type,
series-name, variant and suffix tables are in ``_suffixes.py``.

>>> FAMILIES["62"].dims
'02'
>>> gost_iso_dims("0", "", "1", "7")
'00'
"""

from __future__ import annotations

from dataclasses import dataclass

#: English names of the bearing kinds, used in descriptions.
TYPE_NAMES: dict[str, str] = {
    "radial_ball": "deep-groove ball bearing",
    "self_aligning_ball": "self-aligning ball bearing",
    "cylindrical_roller": "cylindrical roller bearing",
    "spherical_roller": "spherical roller bearing",
    "needle_roller": "needle roller bearing",
    "spiral_roller": "spiral (wound) roller bearing",
    "angular_contact_ball": "angular contact ball bearing",
    "tapered_roller": "tapered roller bearing",
    "thrust_ball": "thrust ball bearing",
    "thrust_roller": "thrust roller bearing",
    "four_point_contact_ball": "four-point contact ball bearing",
}

#: Words for :attr:`Designation.closures` in descriptions.
CLOSURE_WORDS: dict[str, str] = {
    "shield": "one steel shield",
    "2shields": "two steel shields",
    "seal": "one rubber seal",
    "2seals": "two rubber seals",
    "unknown": "closed (kind of closure not stated)",
}

#: ISO 15 diameter-series digit -> name (catalogue usage).
ISO_DIAMETER_NAMES: dict[str, str] = {
    "7": "ultra light",
    "8": "ultra light",
    "9": "ultra light",
    "0": "extra light",
    "1": "extra light",
    "2": "light",
    "3": "medium",
    "4": "heavy",
}

#: ISO 15 width-series digit -> name (catalogue usage, e.g. NSK/JIS tables).
ISO_WIDTH_NAMES: dict[str, str] = {
    "8": "extra narrow",
    "0": "narrow",
    "1": "normal",
    "2": "wide",
    "3": "extra wide",
    "4": "extra wide",
    "5": "extra wide",
    "6": "extra wide",
}

#: GOST diameter-series digit -> ISO diameter-series digit (GOST 3478 order 0, 8, 9, 1, 7,
#: 2, 5, 3, 6, 4 against ISO 7, 8, 9, 0, 1, 2, 3, 4; 5 and 6 are the wide 2 and 3).
_GOST_DIA_TO_ISO: dict[str, str] = {
    "8": "8",
    "9": "9",
    "1": "0",
    "7": "1",
    "2": "2",
    "5": "2",
    "3": "3",
    "6": "3",
    "4": "4",
}


def gost_iso_dims(type_digit: str, variant: str, dia: str, width: str) -> str | None:
    """Return the ISO two-digit dimension series of a GOST type/variant/series, or None.

    Parameters
    ----------
    type_digit : str
        GOST type digit 0-9 (digit 4 from the right) [-]
    variant : str
        GOST design variant without leading zeros, ``""`` for the basic design [-]
    dia : str
        GOST diameter-series digit [-]
    width : str
        GOST width-series digit [-]

    Examples
    --------
    >>> gost_iso_dims("3", "", "1", "3"), gost_iso_dims("8", "", "2", "0")
    ('30', '12')
    """
    if type_digit in "89":
        if dia in "1234" and width == "0":
            return ("2" if (type_digit == "8" and variant == "3") else "1") + dia
        return None
    iso_dia = _GOST_DIA_TO_ISO.get(dia)
    if iso_dia is None:
        return None
    if dia in "56":
        return "2" + iso_dia if width == "0" else None
    if width == "0":
        if dia == "1":
            return "10"
        return "0" + iso_dia if dia in "234" else None
    if width == "7" and dia == "1":
        return "00"
    if width == "1" and dia in "89":
        return "1" + dia
    if width in "23456" and dia in "1723489":
        return width + iso_dia
    return None


@dataclass(frozen=True)
class Family:
    """One ISO family (series key) with its GOST 3189-89 cross reference.

    Parameters
    ----------
    key : str
        Series key used for catalogue lookup, e.g. ``"62"``, ``"NU2"``, ``"302"`` [-]
    bearing_type : str
        One of ``BEARING_TYPES`` [-]
    dims : str
        ISO two-digit dimension series (width or height digit, diameter digit) [-]
    type_text : str
        Leading characters naming the type (``"6"``, ``"NU"``); ``""`` if not written [-]
    type_meaning : str
        Meaning of ``type_text`` [-]
    group : str
        Suffix context: ``"deep"``, ``"angular"``, ``"four"``, ``"cyl"``, ``"sph"``, ``"other"`` [-]
    small_bore : bool
        Whether a single digit after the family means d in mm (``608``) [-]
    gost : tuple of (str, str) or None
        GOST (type digit, design variant) of the same bearing, when there is one [-]
    exact : bool
        True if the GOST bearing is the same bearing; False if only the dimensions agree [-]
    notes : tuple of str
        Caveats shown with every reading of this family [-]
    """

    key: str
    bearing_type: str
    dims: str
    type_text: str
    type_meaning: str
    group: str = "other"
    small_bore: bool = False
    gost: tuple[str, str] | None = None
    exact: bool = True
    notes: tuple[str, ...] = ()

    @property
    def dims_text(self) -> str:
        """The characters of the key after the type part, e.g. ``"2"`` of ``"62"`` [-]."""
        return self.key[len(self.type_text) :]


_XREF = "GOST cross reference is the usual catalogue correspondence, not stated in seed 003"
_ANG = (
    "GOST 3189-89 angular contact bearings of the same dimensions (36000, 46000, 66000) "
    "have contact angles 12, 26 or 36 deg, not the ISO 15/25/30/40 deg: no exact GOST "
    "equivalent"
)


def _families() -> dict[str, Family]:
    f: dict[str, Family] = {}

    def add(key: str, btype: str, dims: str, type_text: str, meaning: str, **kw: object) -> None:
        f[key] = Family(key, btype, dims, type_text, meaning, **kw)  # type: ignore[arg-type]

    deep = "single-row deep-groove ball bearing (ISO type 6)"
    for key, dims in (("60", "10"), ("62", "02"), ("63", "03"), ("64", "04")):
        add(key, "radial_ball", dims, "6", deep, group="deep", small_bore=True, gost=("0", ""))
    for key, dims in (("618", "18"), ("619", "19")):
        add(key, "radial_ball", dims, "6", deep, group="deep", gost=("0", ""))
    add(
        "160",
        "radial_ball",
        "00",
        "16",
        "single-row deep-groove ball bearing of dimension series 00 (ISO type 16)",
        group="deep",
        gost=("0", ""),
    )
    for key, dims in (("68", "18"), ("69", "19")):
        add(
            key,
            "radial_ball",
            dims,
            "6",
            deep,
            group="deep",
            small_bore=True,
            gost=("0", ""),
            notes=(f"{key}xx is the older spelling of the 6{dims}xx series",),
        )
    sab = "self-aligning ball bearing (ISO type 1)"
    for key, dims in (("12", "02"), ("13", "03")):
        add(key, "self_aligning_ball", dims, "1", sab, small_bore=True, gost=("1", ""))
    for key in ("22", "23"):
        add(
            key,
            "self_aligning_ball",
            key,
            "",
            "self-aligning ball bearing (type digit 1 not written)",
            gost=("1", ""),
        )
    acb = "single-row angular contact ball bearing (ISO type 7)"
    for key, dims in (("72", "02"), ("73", "03"), ("70", "10"), ("718", "18"), ("719", "19")):
        add(
            key,
            "angular_contact_ball",
            dims,
            "7",
            acb,
            group="angular",
            gost=("6", "") if key in ("72", "73") else None,
            exact=False,
            notes=(_ANG,),
        )
    for key in ("32", "33"):
        add(
            key,
            "angular_contact_ball",
            key,
            "",
            "double-row angular contact ball bearing (32/33 series)",
            group="angular",
            notes=("double row angular contact ball bearing",),
        )
    for key, dims in (("QJ2", "02"), ("QJ3", "03")):
        add(
            key,
            "four_point_contact_ball",
            dims,
            "QJ",
            "four-point contact ball bearing with split inner ring (QJ)",
            group="four",
            gost=("6", "17"),
            notes=(_XREF + " (GOST 176000 series, uncertain)",),
        )
    cyl = {
        "N": (
            "N",
            ("cylindrical roller bearing, two ribs on the inner ring, none on the outer ring (N)"),
            "",
        ),
        "NU": (
            "NU",
            ("cylindrical roller bearing, two ribs on the outer ring, none on the inner ring (NU)"),
            "3",
        ),
        "NJ": (
            "NJ",
            ("cylindrical roller bearing, two ribs on the outer ring, one on the inner ring (NJ)"),
            "4",
        ),
        "NUP": (
            "NUP",
            (
                "cylindrical roller bearing, two ribs on the outer ring, one integral "
                "and one loose rib on the inner ring (NUP)"
            ),
            "9",
        ),
        "NF": (
            "NF",
            ("cylindrical roller bearing, two ribs on the inner ring, one on the outer ring (NF)"),
            "1",
        ),
    }
    for prefix, (text, meaning, variant) in cyl.items():
        for ser, dims in (
            ("2", "02"),
            ("3", "03"),
            ("4", "04"),
            ("10", "10"),
            ("22", "22"),
            ("23", "23"),
        ):
            notes = () if prefix == "NF" else (_XREF + " (GOST 8328 design variants)",)
            add(
                prefix + ser,
                "cylindrical_roller",
                dims,
                text,
                meaning,
                group="cyl",
                gost=("2", variant),
                notes=notes,
            )
    add(
        "NN30",
        "cylindrical_roller",
        "30",
        "NN",
        "double-row cylindrical roller bearing, ribs on the inner ring (NN)",
        group="cyl",
        notes=("double row cylindrical roller bearing",),
    )
    for key, dims in (("NA48", "48"), ("NA49", "49"), ("NA69", "69")):
        add(key, "needle_roller", dims, "NA", "needle roller bearing with inner ring (NA)")
    trb = "tapered roller bearing (ISO type 3)"
    for key, dims in (
        ("302", "02"),
        ("303", "03"),
        ("313", "13"),
        ("320", "20"),
        ("322", "22"),
        ("323", "23"),
        ("329", "29"),
        ("330", "30"),
        ("331", "31"),
        ("332", "32"),
    ):
        variant = "2" if key == "313" else ""
        gost = ("7", variant) if key in ("302", "303", "313", "320", "322", "323") else None
        notes = ("the two-digit series is the ISO 355 old dimension series",)
        if gost:
            notes += (_XREF + " (GOST 7000 series of the same dimensions)",)
        add(key, "tapered_roller", dims, "3", trb, gost=gost, notes=notes)
    srb = "spherical roller bearing (ISO type 2)"
    for key, dims in (
        ("213", "03"),  # the 213 key is written for dimension series 03 (maker catalogues)
        ("222", "22"),
        ("223", "23"),
        ("230", "30"),
        ("231", "31"),
        ("232", "32"),
        ("240", "40"),
        ("241", "41"),
        ("238", "38"),
        ("239", "39"),
        ("248", "48"),
        ("249", "49"),
    ):
        gost = ("3", "") if dims in ("22", "23", "30", "31", "32", "40", "41") else None
        add(
            key,
            "spherical_roller",
            dims,
            "2",
            srb,
            group="sph",
            gost=gost,
            notes=(_XREF,) if gost else (),
        )
    tbb = "single-direction thrust ball bearing (ISO type 5)"
    for key in ("511", "512", "513", "514"):
        add(key, "thrust_ball", key[1:], "5", tbb, gost=("8", ""))
    for key in ("522", "523", "524"):
        add(
            key,
            "thrust_ball",
            key[1:],
            "5",
            "double-direction thrust ball bearing (ISO type 5)",
            gost=("8", "3"),
            notes=(_XREF + " (GOST 38000 double-direction, uncertain)",),
        )
    for key in ("811", "812"):
        add(key, "thrust_roller", key[1:], "8", "cylindrical roller thrust bearing (ISO type 8)")
    for key in ("292", "293", "294"):
        add(key, "thrust_roller", key[1:], "2", "spherical roller thrust bearing (ISO type 29)")
    return f


#: All ISO families, by series key.
FAMILIES: dict[str, Family] = _families()

#: ISO letter prefixes that start a family key.
ISO_PREFIXES: tuple[str, ...] = ("NUP", "NU", "NJ", "NF", "NN", "NA", "QJ", "N")


def family_for_gost(type_digit: str, variant: str, dims: str | None) -> Family | None:
    """Return the ISO family with the given GOST type, design variant and ISO dimensions.

    Parameters
    ----------
    type_digit : str
        GOST type digit [-]
    variant : str
        GOST design variant (leading zeros stripped), ``""`` for basic [-]
    dims : str or None
        ISO two-digit dimension series [-]

    Examples
    --------
    >>> family_for_gost("2", "1", "02").key
    'NF2'
    """
    if dims is None:
        return None
    for fam in FAMILIES.values():
        if fam.gost == (type_digit, variant) and fam.dims == dims:
            return fam
    return None


def bore_from_code(code: str) -> float:
    """Bore in millimetres of a two-digit bore code (00=10, 01=12, 02=15, 03=17, else x5).

    Parameters
    ----------
    code : str
        Two-digit bore code (seed 003 lines 137-139) [-]

    Examples
    --------
    >>> bore_from_code("03"), bore_from_code("96")
    (17.0, 480.0)
    """
    special = {"00": 10.0, "01": 12.0, "02": 15.0, "03": 17.0}
    return special.get(code, 5.0 * int(code))


def format_mm(value: float) -> str:
    """Format a length in millimetres without a trailing ``.0`` (``25.0`` -> ``"25"``).

    Parameters
    ----------
    value : float
        Length [mm]

    Examples
    --------
    >>> format_mm(2.5), format_mm(25.0)
    ('2.5', '25')
    """
    return f"{value:g}"


def bore_meaning(code: str, bore_mm: float) -> str:
    """Explain a bore code for the parts list.

    Parameters
    ----------
    code : str
        Two-digit bore code [-]
    bore_mm : float
        Bore it stands for [mm]
    """
    if code in ("00", "01", "02", "03"):
        return f"bore code {code}: d = {format_mm(bore_mm)} mm (00=10, 01=12, 02=15, 03=17 mm)"
    return f"bore code {code}: d = {int(code)} x 5 = {format_mm(bore_mm)} mm"
