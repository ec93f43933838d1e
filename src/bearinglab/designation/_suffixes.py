"""Tables of prefixes, suffixes, types, series names and design variants of both systems.

GOST 3189-89 entries cite seed 003 by line where the seed states them (types lines 145-154,
diameter series 141 and 575, width series 160 and 581, precision classes 164-166 and
336-341, categories 168-172, suffixes 174-177 and 319-323, design variants 158, 183, 185,
247-248).  Entries from the usual GOST reading that seed 003 does not state say so in their
meaning or carry ``uncertain=True``, and the readers copy that into the notes.  ISO suffixes
are the common SKF / Schaeffler (FAG) / NSK / NTN meanings.

>>> ISO_SUFFIXES["2RS"].closure
(0, 2)
>>> GOST_VARIANTS["0"]["18"].iso_suffix
'2RS'
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class IsoSuffix:
    """One ISO / maker suffix code.

    Parameters
    ----------
    meaning : str
        What the code means [-]
    kind : str
        ``closure``, ``snap``, ``clearance``, ``precision``, ``angle`` or ``other`` [-]
    closure : tuple of (int, int)
        Number of (shields, seals) the code adds [-]
    precision : str or None
        Precision class it sets (``"6"``, ``"5"``...) [-]
    angle_deg : float or None
        Contact angle it sets [deg]
    gost_variant : str or None
        GOST 3189-89 design variant of a deep-groove bearing with this closure [-]
    """

    meaning: str
    kind: str = "other"
    closure: tuple[int, int] = (0, 0)
    precision: str | None = None
    angle_deg: float | None = None
    gost_variant: str | None = None


def _closure(meaning: str, shields: int, seals: int, gost: str | None = None) -> IsoSuffix:
    return IsoSuffix(meaning, "closure", (shields, seals), gost_variant=gost)


#: Suffixes valid after any ISO basic designation.
ISO_SUFFIXES: dict[str, IsoSuffix] = {
    "Z": _closure("one pressed-steel shield (non-contact)", 1, 0, "6"),
    "ZR": _closure("one shield (Schaeffler)", 1, 0, "6"),
    "2Z": _closure("two pressed-steel shields (non-contact)", 2, 0, "8"),
    "ZZ": _closure("two pressed-steel shields (non-contact)", 2, 0, "8"),
    "2ZR": _closure("two shields (Schaeffler)", 2, 0, "8"),
    "RS": _closure("one contact rubber seal", 0, 1, "16"),
    "2RS": _closure("two contact rubber seals", 0, 2, "18"),
    "RS1": _closure("one contact seal of NBR (SKF)", 0, 1, "16"),
    "2RS1": _closure("two contact seals of NBR (SKF)", 0, 2, "18"),
    "RSH": _closure("one contact seal of NBR, improved design (SKF)", 0, 1, "16"),
    "2RSH": _closure("two contact seals of NBR, improved design (SKF)", 0, 2, "18"),
    "RSR": _closure("one contact seal (Schaeffler)", 0, 1, "16"),
    "2RSR": _closure("two contact seals (Schaeffler)", 0, 2, "18"),
    "RZ": _closure("one low-friction (non-contact) NBR seal (SKF)", 0, 1),
    "2RZ": _closure("two low-friction (non-contact) NBR seals (SKF)", 0, 2),
    "RSL": _closure("one low-friction seal (SKF)", 0, 1),
    "2RSL": _closure("two low-friction seals (SKF)", 0, 2),
    "DU": _closure("one contact rubber seal (NSK)", 0, 1, "16"),
    "DDU": _closure("two contact rubber seals (NSK)", 0, 2, "18"),
    "VV": _closure("two non-contact rubber seals (NSK)", 0, 2),
    "LU": _closure("one contact seal (NTN)", 0, 1, "16"),
    "LLU": _closure("two contact seals (NTN)", 0, 2, "18"),
    "LB": _closure("one non-contact seal (NTN)", 0, 1),
    "LLB": _closure("two non-contact seals (NTN)", 0, 2),
    "N": IsoSuffix("snap-ring groove in the outer ring", "snap", gost_variant="5"),
    "NR": IsoSuffix(
        "snap-ring groove in the outer ring, with snap ring", "snap", gost_variant="15"
    ),
    "C1": IsoSuffix("radial internal clearance C1 (smaller than C2, ISO 5753-1)", "clearance"),
    "C2": IsoSuffix("radial internal clearance C2 (smaller than normal, ISO 5753-1)", "clearance"),
    "CN": IsoSuffix("radial internal clearance normal (CN, ISO 5753-1)", "clearance"),
    "C3": IsoSuffix("radial internal clearance C3 (greater than normal, ISO 5753-1)", "clearance"),
    "C4": IsoSuffix("radial internal clearance C4 (greater than C3, ISO 5753-1)", "clearance"),
    "C5": IsoSuffix("radial internal clearance C5 (greater than C4, ISO 5753-1)", "clearance"),
    "P0": IsoSuffix("normal tolerance class (ISO 492 class Normal)", "precision", precision="0"),
    "PN": IsoSuffix("normal tolerance class (ISO 492 class Normal)", "precision", precision="0"),
    "P6": IsoSuffix("tolerance class 6 (ISO 492)", "precision", precision="6"),
    "P5": IsoSuffix("tolerance class 5 (ISO 492)", "precision", precision="5"),
    "P4": IsoSuffix("tolerance class 4 (ISO 492)", "precision", precision="4"),
    "P2": IsoSuffix("tolerance class 2 (ISO 492)", "precision", precision="2"),
    "P62": IsoSuffix(
        "tolerance class 6 and clearance C2 (SKF P6 + C2)", "precision", precision="6"
    ),
    "P63": IsoSuffix(
        "tolerance class 6 and clearance C3 (SKF P6 + C3)", "precision", precision="6"
    ),
    "P52": IsoSuffix(
        "tolerance class 5 and clearance C2 (SKF P5 + C2)", "precision", precision="5"
    ),
    "P53": IsoSuffix(
        "tolerance class 5 and clearance C3 (SKF P5 + C3)", "precision", precision="5"
    ),
    "J": IsoSuffix("pressed steel cage"),
    "Y": IsoSuffix("pressed brass cage"),
    "M": IsoSuffix("machined brass cage"),
    "MA": IsoSuffix("machined brass cage, outer-ring centred"),
    "MB": IsoSuffix("machined brass cage, inner-ring centred"),
    "F": IsoSuffix("machined steel cage"),
    "P": IsoSuffix("glass-fibre reinforced polyamide 66 cage (SKF)"),
    "TN": IsoSuffix("injection-moulded polyamide cage (SKF)"),
    "TN9": IsoSuffix("glass-fibre reinforced polyamide 66 cage (SKF)"),
    "TNH": IsoSuffix("glass-fibre reinforced PEEK cage (SKF)"),
    "TVH": IsoSuffix("glass-fibre reinforced polyamide cage (Schaeffler)"),
    "TVP": IsoSuffix("glass-fibre reinforced polyamide cage (Schaeffler)"),
    "TVP2": IsoSuffix("glass-fibre reinforced polyamide cage (Schaeffler)"),
    "E": IsoSuffix("reinforced internal design (optimised, higher load rating)"),
    "EC": IsoSuffix("optimised internal design with reinforced roller set (SKF)"),
    "E1": IsoSuffix("reinforced internal design (Schaeffler)"),
    "XL": IsoSuffix("X-life quality (Schaeffler)"),
    "K": IsoSuffix("tapered bore, taper 1:12"),
    "K30": IsoSuffix("tapered bore, taper 1:30"),
    "W33": IsoSuffix("annular groove and three lubrication holes in the outer ring"),
    "S0": IsoSuffix("rings heat-stabilised for up to 150 degC"),
    "S1": IsoSuffix("rings heat-stabilised for up to 200 degC"),
    "S2": IsoSuffix("rings heat-stabilised for up to 250 degC"),
}

#: Extra suffixes of single- and double-row angular contact ball bearings.
ANGULAR_SUFFIXES: dict[str, IsoSuffix] = {
    "A": IsoSuffix("contact angle 30 deg", "angle", angle_deg=30.0),
    "B": IsoSuffix("contact angle 40 deg", "angle", angle_deg=40.0),
    "C": IsoSuffix("contact angle 15 deg", "angle", angle_deg=15.0),
    "AC": IsoSuffix("contact angle 25 deg", "angle", angle_deg=25.0),
    "A5": IsoSuffix("contact angle 25 deg (NSK)", "angle", angle_deg=25.0),
    "BE": IsoSuffix(
        "contact angle 40 deg, optimised internal design (SKF)", "angle", angle_deg=40.0
    ),
    "CA": IsoSuffix("universally matchable, axial clearance smaller than normal (SKF)"),
    "CB": IsoSuffix("universally matchable, normal axial clearance (SKF)"),
    "CC": IsoSuffix("universally matchable, axial clearance larger than normal (SKF)"),
    "GA": IsoSuffix("universally matchable, light preload (SKF)"),
    "GB": IsoSuffix("universally matchable, moderate preload (SKF)"),
    "GC": IsoSuffix("universally matchable, heavy preload (SKF)"),
    "DB": IsoSuffix("matched pair, back-to-back arrangement"),
    "DF": IsoSuffix("matched pair, face-to-face arrangement"),
    "DT": IsoSuffix("matched pair, tandem arrangement"),
}

#: Extra suffixes of spherical roller bearings.
SPHERICAL_SUFFIXES: dict[str, IsoSuffix] = {
    "CC": IsoSuffix("SKF internal design CC (two window-type steel cages, guide ring)"),
    "CA": IsoSuffix("SKF internal design CA (machined brass cage)"),
}

#: Extra suffixes of four-point contact ball bearings.
FOUR_POINT_SUFFIXES: dict[str, IsoSuffix] = {
    "N2": IsoSuffix("two locating slots in the outer ring"),
}


def suffix_table(group: str) -> dict[str, IsoSuffix]:
    """Return the suffixes valid for a family group (see ``_tables.Family.group``).

    Parameters
    ----------
    group : str
        ``"angular"``, ``"sph"``, ``"four"``, ``"deep"``, ``"cyl"`` or ``"other"`` [-]

    Examples
    --------
    >>> "BE" in suffix_table("angular"), "BE" in suffix_table("deep")
    (True, False)
    """
    table = dict(ISO_SUFFIXES)
    table.update(
        {"angular": ANGULAR_SUFFIXES, "sph": SPHERICAL_SUFFIXES, "four": FOUR_POINT_SUFFIXES}.get(
            group, {}
        )
    )
    return table


# ---------------------------------------------------------------- GOST 3189-89 tables

#: GOST 3189-89 type digit -> (bearing_type, meaning with the Russian name and seed-003 line).
GOST_TYPES: dict[str, tuple[str, str]] = {
    "0": (
        "radial_ball",
        ("radial ball bearing, single row ('шариковый радиальный', seed 003 line 145)"),
    ),
    "1": (
        "self_aligning_ball",
        (
            "self-aligning ball bearing, double row ('шариковый радиальный "
            "сферический двухрядный', seed 003 line 146)"
        ),
    ),
    "2": (
        "cylindrical_roller",
        ("radial roller bearing with short cylindrical rollers (seed 003 line 147)"),
    ),
    "3": (
        "spherical_roller",
        (
            "spherical roller bearing, double row ('роликовый радиальный "
            "сферический двухрядный', seed 003 line 148)"
        ),
    ),
    "4": ("needle_roller", "needle roller bearing, single row (seed 003 line 149)"),
    "5": ("spiral_roller", "radial roller bearing with spiral (wound) rollers (seed 003 line 150)"),
    "6": (
        "angular_contact_ball",
        (
            "angular contact ball bearing, single row ('шариковый "
            "радиально-упорный однорядный', seed 003 line 151)"
        ),
    ),
    "7": ("tapered_roller", "tapered roller bearing ('роликовый конический', seed 003 line 152)"),
    "8": ("thrust_ball", "thrust or angular-contact thrust ball bearing (seed 003 line 153)"),
    "9": ("thrust_roller", "thrust or angular-contact thrust roller bearing (seed 003 line 154)"),
}

#: GOST diameter-series digit -> name (seed 003 lines 141 and 575).
GOST_DIAMETER_NAMES: dict[str, str] = {
    "0": "ultra light",
    "8": "ultra light",
    "9": "ultra light",
    "1": "extra light",
    "7": "extra light",
    "2": "light",
    "5": "light wide",
    "3": "medium",
    "6": "medium wide",
    "4": "heavy",
}

#: GOST width-series digit -> name (seed 003 line 160: 0, 1, 2, 3 in increasing width;
#: line 581: 7 narrow, 1 normal, 2 wide, 3-6 extra wide; 0 is the default, not written).
GOST_WIDTH_NAMES: dict[str, str] = {
    "7": "narrow",
    "8": "narrow",
    "9": "narrow",
    "0": "normal",
    "1": "normal",
    "2": "wide",
    "3": "extra wide",
    "4": "extra wide",
    "5": "extra wide",
    "6": "extra wide",
}


#: GOST precision class -> meaning (seed 003 lines 164-166 and 336-341).
GOST_CLASSES: dict[str, str] = {
    "8": "precision class 8: lower than normal ('пониженный', seed 003 line 341)",
    "7": "precision class 7: lower than normal ('пониженный', seed 003 line 341)",
    "0": "precision class 0: normal (seed 003 lines 164, 336)",
    "6": "precision class 6: raised ('повышенный', seed 003 line 340)",
    "5": "precision class 5: high ('высокий', seed 003 line 339)",
    "4": "precision class 4: especially high ('особо высокий', seed 003 line 338)",
    "Т": "precision class T: higher than 4 (GOST 520; seed 003 line 166 only mentions "
    "'more elevated' classes)",
    "2": "precision class 2: super high ('сверхвысокий', seed 003 line 337)",
}

#: GOST category letter -> meaning (seed 003 lines 168-172).
GOST_CATEGORIES: dict[str, str] = {
    "А": "category A: raised regulated norms of vibration, form deviations, friction moment "
    "(seed 003 line 169)",
    "В": "category B: regulated norms (seed 003 line 170)",
    "С": "category C: no additional requirements (seed 003 line 171)",
}


@dataclass(frozen=True)
class GostVariant:
    """Meaning of GOST 3189-89 digits 5-6 (design variant) for one type.

    Parameters
    ----------
    meaning : str
        What the variant means [-]
    closures : str or None
        Closure it implies (``"shield"``, ``"2seals"``...) [-]
    iso_suffix : str or None
        ISO suffix of the same feature (``"2RS"``, ``"N"``...) [-]
    angle_deg : float or None
        Contact angle it implies [deg]
    bearing_type : str or None
        Bearing type it turns the bearing into, if different [-]
    uncertain : bool
        True if taken from the usual GOST reading, not from seed 003 [-]
    """

    meaning: str
    closures: str | None = None
    iso_suffix: str | None = None
    angle_deg: float | None = None
    bearing_type: str | None = None
    uncertain: bool = False


_U = " (usual GOST reading, not stated in seed 003)"

#: GOST type digit -> design variant (leading zeros stripped) -> meaning.
GOST_VARIANTS: dict[str, dict[str, GostVariant]] = {
    "0": {
        "5": GostVariant("snap-ring groove on the outer ring" + _U, iso_suffix="N"),
        "15": GostVariant(
            "snap-ring groove on the outer ring, with snap ring" + _U, iso_suffix="NR"
        ),
        "6": GostVariant("one steel shield (seed 003 line 247: 60205)", "shield", "Z"),
        "8": GostVariant("two steel shields (seed 003 line 247: 80205)", "2shields", "2Z"),
        "16": GostVariant("one rubber contact seal (seed 003 line 248: 160205)", "seal", "RS"),
        "18": GostVariant("two rubber contact seals (seed 003 line 248: 180205)", "2seals", "2RS"),
    },
    "1": {
        "11": GostVariant("tapered bore 1:12" + _U, uncertain=True),
    },
    "2": {
        "1": GostVariant("one rib on the outer ring (seed 003 line 185: 4-12210), ISO NF"),
        "3": GostVariant("no ribs on the inner ring, ISO NU" + _U, uncertain=True),
        "4": GostVariant("one rib on the inner ring, ISO NJ" + _U, uncertain=True),
        "9": GostVariant(
            "one rib and a loose flat rib on the inner ring, ISO NUP" + _U, uncertain=True
        ),
    },
    "3": {
        "5": GostVariant(
            "lubrication groove and holes in the outer ring, ISO W33" + _U,
            iso_suffix="W33",
            uncertain=True,
        ),
    },
    "6": {
        "3": GostVariant("contact angle 12 deg (seed 003 line 183: 6-36209)", angle_deg=12.0),
        "4": GostVariant("contact angle 26 deg" + _U, angle_deg=26.0, uncertain=True),
        "6": GostVariant("contact angle 36 deg" + _U, angle_deg=36.0, uncertain=True),
        "17": GostVariant(
            "four-point contact with split inner ring (176000 series)" + _U,
            bearing_type="four_point_contact_ball",
            uncertain=True,
        ),
    },
    "7": {
        "6": GostVariant("thrust flange on the outer ring (seed 003 line 158: 67206)"),
        "2": GostVariant("steep contact angle (27000 series, ISO 313)" + _U, uncertain=True),
    },
    "8": {
        "3": GostVariant(
            "double-direction thrust ball bearing (38000 series)" + _U, uncertain=True
        ),
    },
}


@dataclass(frozen=True)
class GostSuffix:
    """Meaning of one GOST 3189-89 letter written right of the basic number.

    Parameters
    ----------
    meaning : str
        What the letter means, or ``"suffix X (not decoded)"`` [-]
    decoded : bool
        False if the letter is accepted but its meaning is not given [-]
    uncertain : bool
        True if the meaning is not from seed 003 and not certain [-]
    """

    meaning: str
    decoded: bool = True
    uncertain: bool = False


_NOT_SEED = " (usual GOST 3189-89 reading, not in seed 003)"

#: GOST suffix letters whose meaning is decoded (seed 003 lines 174-177 and usual readings).
GOST_SUFFIXES: dict[str, GostSuffix] = {
    "Е": GostSuffix("cage of plastic materials (seed 003 line 175)"),
    "Р": GostSuffix(
        "bearing parts of heat-resistant steels (seed 003 line 187 'теплостойких'; "
        "line 176 prints 'теплопроводных')"
    ),
    "С": GostSuffix("closed bearing filled with lubricant (seed 003 line 177)"),
    "Л": GostSuffix("brass cage" + _NOT_SEED),
    "Ю": GostSuffix("parts of corrosion-resistant (stainless) steel" + _NOT_SEED),
    "К": GostSuffix("design changes of bearing parts" + _NOT_SEED),
    "М": GostSuffix("rollers with modified contact profile" + _NOT_SEED, uncertain=True),
}

#: Further letters GOST 3189-89 uses right of the basic number; accepted, not decoded.
GOST_UNDECODED_LETTERS: str = "БГДНТУФХШЭЯ"

#: Latin look-alikes of Cyrillic letters (upper case), accepted in GOST designations.
LATIN_TO_CYRILLIC: dict[str, str] = {
    "A": "А",
    "B": "В",
    "C": "С",
    "E": "Е",
    "K": "К",
    "M": "М",
    "P": "Р",
    "T": "Т",
    "H": "Н",
    "X": "Х",
    "Y": "У",
    "O": "О",
}
