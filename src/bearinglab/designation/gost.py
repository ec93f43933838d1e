"""Reader of GOST 3189-89 bearing designations (the Russian system), after seed 003.

Seed 003 (lines 129-187) describes the system: a basic number of up to seven digits read
from the right -- digits 1-2 bore code (00=10, 01=12, 02=15, 03=17 mm, else x5 for d = 20
to 495 mm), digit 3 diameter series, digit 4 type (0-9), digits 5-6 design variant, digit 7
width series; left of it, after a dash, the precision class (0, 6, 5, 4, 2; also 8, 7 and
T) with the category letter A/B/C further left; right of it letters such as Е (plastic
cage), Р (heat-resistant steel), С (closed, greased).  Its worked examples are 7206, 67206,
311, 6-36209, 4-12210, 4-3003124Р, 60205/80205/160205/180205 (lines 247-248) and
6-18030ПР20П (lines 319-323).  Small bores (d < 10 mm: digit 1 = d, digit 2 = diameter
series, digit 3 = 0) and the ``/d`` form follow GOST 3189-89 as usually quoted.

Cyrillic letters and their Latin look-alikes are both accepted; dashes of any kind and
spaces are normalised ("4- 3003124Р" in seed 003 line 187 has a space).

>>> d = parse_gost("180205")
>>> d.bearing_type, d.bore_mm, d.closures, d.iso_equivalent
('radial_ball', 25.0, '2seals', '6205-2RS')
>>> parse_gost("6-36209").contact_angle_deg
12.0
"""

from __future__ import annotations

import math
import re

from ._common import DASHES, ReadError, format_iso, nfkc_chars, original_slice
from ._suffixes import (
    GOST_CATEGORIES,
    GOST_CLASSES,
    GOST_DIAMETER_NAMES,
    GOST_SUFFIXES,
    GOST_TYPES,
    GOST_UNDECODED_LETTERS,
    GOST_VARIANTS,
    GOST_WIDTH_NAMES,
    LATIN_TO_CYRILLIC,
    GostVariant,
)
from ._tables import (
    CLOSURE_WORDS,
    TYPE_NAMES,
    bore_from_code,
    bore_meaning,
    family_for_gost,
    format_mm,
    gost_iso_dims,
)
from .model import Designation

__all__ = ["parse_gost"]

_PREFIX_RE = re.compile(r"(?P<cat>[АВС])?(?P<sep>-)?(?P<pre>[0-9Т]{1,3})?-")
_DIGITS_RE = re.compile(r"[0-9]+")
_SLASH_RE = re.compile(r"/([0-9]+(?:[.,][0-9]+)?)")
_LETTERS = "".join(GOST_SUFFIXES) + "П" + GOST_UNDECODED_LETTERS
_SUFFIX_RE = re.compile(rf"([{_LETTERS}])([0-9][0-9О]*)?")
_ISO_CLOSURES = ("Z", "2Z", "RS", "2RS")


def _normalise(text: str) -> tuple[str, list[int], list[str]]:
    """NFKC-normalise, upper-case, drop spaces, unify dashes and map Latin look-alikes to
    Cyrillic; digits other than ASCII 0-9 are refused (:func:`nfkc_chars`)."""
    chars = nfkc_chars(text)
    plain = "".join(ch for _, ch in chars)
    translit = any(ch in "Rr" for ch in plain)
    out: list[str] = []
    index: list[int] = []
    for i, ch in chars:
        if ch.isspace():
            continue
        for up in ch.upper():
            if ch in DASHES:
                up = "-"
            elif up == "R":
                up = "Р"
            elif up == "P":
                up = "П" if translit else "Р"
            else:
                up = LATIN_TO_CYRILLIC.get(up, up)
            out.append(up)
            index.append(i)
    notes = []
    if translit and any(ch in "Pp" for ch in plain):
        notes.append(
            "Latin letters read as a transliteration (P = П, R = Р) because 'R' "
            "appears; otherwise a Latin 'P' is read as the look-alike 'Р'"
        )
    return "".join(out), index, notes


def _short(meaning: str) -> str:
    """Meaning without its trailing source remark, for the one-line description."""
    return meaning.split(" (")[0]


def _prefix_parts(
    text: str, cat: str | None, pre: str, notes: list[str], progress: int
) -> tuple[list[tuple[str, str]], str]:
    parts: list[tuple[str, str]] = []
    if cat:
        parts.append((cat, GOST_CATEGORIES[cat]))
    if not pre:
        return parts, "0"
    cls = pre[-1]
    if cls not in GOST_CLASSES:
        raise ReadError(
            text,
            pre,
            "unknown precision class (0, 6, 5, 4, 2, T, 8, 7; seed 003 lines 164, 336-341)",
            progress,
        )
    extra = pre[:-1]
    if "Т" in extra:
        raise ReadError(
            text, pre, "T can only be the precision class, the last sign before the dash", progress
        )
    left = "left additional sign of GOST 3189-89"
    if len(extra) == 2:
        parts.append((extra[0], f"friction-moment row {extra[0]} ({left})"))
    if extra:
        parts.append((extra[-1], f"radial clearance group {extra[-1]} (GOST 24810; {left})"))
        notes.append(
            "radial clearance group and friction-moment row in the prefix follow "
            "the usual GOST 3189-89 order (category, friction-moment row, clearance "
            "group, class); seed 003 describes only class and category"
        )
    parts.append((cls, GOST_CLASSES[cls]))
    return parts, cls


def _suffix_parts(tokens: list[tuple[str, str]], notes: list[str]) -> list[tuple[str, str]]:
    out: list[tuple[str, str]] = []
    seen_p = False
    for letter, digits in tokens:
        if "О" in digits:
            digits = digits.replace("О", "0")
            notes.append(
                f"letter О in '{letter}{digits}' read as the digit 0 (seed 003 "
                "line 322 prints 'Р2О' for Р20)"
            )
        code = letter + digits
        info = GOST_SUFFIXES.get(letter)
        if letter == "П":
            if not seen_p:
                meaning = (
                    "surface roughness grade (as seed 003 line 321 explains, where "
                    "П is called a 'prefix'; not checked against GOST 3189-89)"
                )
            else:
                meaning = (
                    "noise level indicator (as seed 003 line 323 explains; not "
                    "checked against GOST 3189-89)"
                )
            seen_p = True
            if digits:
                meaning += f"; number {digits} not decoded"
        elif letter == "Р" and digits:
            meaning = (
                f"lubricant type {code} (as seed 003 line 322 explains, printed there "
                "as 'Р2О'; not checked against GOST 3189-89)"
            )
        elif info is not None:
            meaning = info.meaning
            if digits:
                meaning += f"; number {digits} (not decoded)"
            if info.uncertain:
                notes.append(
                    f"suffix {letter}: '{_short(info.meaning)}' is the usual GOST "
                    "3189-89 reading, not stated in seed 003: verify"
                )
        else:
            meaning = f"suffix {code} (not decoded)"
        out.append((code, meaning))
    return out


def parse_gost(text: str) -> Designation:
    """Read a GOST 3189-89 designation such as ``"6-36209"`` or ``"4-3003124Р"``.

    Parameters
    ----------
    text : str
        The designation, Cyrillic or Latin look-alike letters, any dash [-]

    Returns
    -------
    Designation
        The reading, in SI units (bore in metres, contact angle in radians).

    Raises
    ------
    bearinglab.errors.DesignationError
        Naming the part that is not a GOST 3189-89 designation.

    Examples
    --------
    >>> parse_gost("4-12210").design_variant_meaning
    'one rib on the outer ring (seed 003 line 185: 4-12210), ISO NF'
    >>> parse_gost("7000106").iso_equivalent, parse_gost("1000096").iso_equivalent
    ('16006', '619/6')
    """
    if not isinstance(text, str):
        raise ReadError(repr(text), repr(text), "a designation must be a string")
    norm, index, notes = _normalise(text)
    if not norm:
        raise ReadError(text, text, "empty designation")

    pos, cat, pre = 0, None, ""
    m = _PREFIX_RE.match(norm)
    if m:
        cat, pre, pos = m["cat"], m["pre"] or "", m.end()
        if not (cat or pre):
            raise ReadError(
                text,
                "-",
                "a leading dash must follow a precision class or "
                "category (seed 003 lines 164, 172)",
                0,
            )
    m = _DIGITS_RE.match(norm, pos)
    if not m:
        raise ReadError(
            text,
            original_slice(text, index, pos) or text,
            "expected the GOST 3189-89 basic number (digits)",
            pos,
        )
    basic = m.group()
    if len(basic) > 7:
        raise ReadError(
            text,
            basic,
            "a GOST 3189-89 basic number has at most seven digits (seed 003 line 135)",
            pos,
        )
    basic_start, pos = pos, m.end()
    slash = None
    m = _SLASH_RE.match(norm, pos)
    if m:
        slash, pos = m.group(1), m.end()
    if slash is None and len(basic.lstrip("0")) < 2:
        raise ReadError(
            text,
            original_slice(text, index, basic_start, pos),
            "too short for a GOST 3189-89 basic number: it needs at least two significant "
            "digits (bore code and diameter series, or bore and diameter series of a small "
            "bore; seed 003 lines 135-141)",
            pos,
        )
    tokens: list[tuple[str, str]] = []
    while pos < len(norm):
        m = _SUFFIX_RE.match(norm, pos)
        if not m:
            raise ReadError(
                text, original_slice(text, index, pos), "not a GOST 3189-89 suffix letter", pos
            )
        code = m.group(1) + (m.group(2) or "")
        if code != "П" and any(letter + digits == code for letter, digits in tokens):
            raise ReadError(
                text,
                original_slice(text, index, m.start(), m.end()),
                "repeated suffix: the same sign is written twice (only П may appear twice, "
                "seed 003 lines 321-323)",
                pos,
            )
        tokens.append((m.group(1), m.group(2) or ""))
        pos = m.end()

    prefix_parts, cls = _prefix_parts(text, cat, pre, notes, 1)
    prefix_text = (cat or "") + pre + "-" if (cat or pre) else ""
    return _decode(text, prefix_text, cat, cls, prefix_parts, basic, slash, tokens, notes)


def _decode(
    text: str,
    prefix_text: str,
    cat: str | None,
    cls: str,
    prefix_parts: list[tuple[str, str]],
    basic: str,
    slash: str | None,
    tokens: list[tuple[str, str]],
    notes: list[str],
) -> Designation:
    n = len(basic)
    parts = list(prefix_parts)
    small = False
    if slash is not None:
        if n > 5:
            raise ReadError(
                text,
                basic,
                "with a '/d' bore the basic number has at most five "
                "digits (width, design variant, type, diameter series)",
                0,
            )
        s = basic.zfill(5)
        width, var_digits, type_digit, dia = s[0], s[1:3], s[3], s[4]
        bore_mm = float(slash.replace(",", "."))
        bore_code = "/" + format_mm(bore_mm)
        var_written = basic[-4:-2] if n >= 4 else None
        written = {"width": n >= 5, "type": n >= 2, "dia": True}
        notes.append(
            "the '/d' scheme (digits: width series, design variant, type, diameter "
            "series; bore in mm after '/') follows GOST 3189-89 as usually quoted; "
            "seed 003 does not describe it"
        )
    else:
        s = basic.zfill(7)
        width, var_digits, type_digit = s[0], s[1:3], s[3]
        var_written = basic[-6:-4] if n >= 5 else None
        written = {"width": n >= 7, "type": n >= 4, "dia": n >= 3}
        if s[4] == "0" and s[6] != "0":
            small = True
            dia, bore_code, bore_mm = s[5], s[6], float(s[6])
            written["dia"] = n >= 2
            notes.append(
                "digit 3 = 0 with a non-zero digit 1: read with the small-bore scheme "
                "of GOST 3189-89 (d < 10 mm: digit 1 = d, digit 2 = diameter series); "
                f"with diameter series 0 it would read as bore code {s[5:7]}"
            )
            if dia == "5":
                notes.append(
                    "for small bores a 5 in digit 2 may mark a fractional bore "
                    "rounded up (GOST 3189-89); read here as diameter series 5"
                )
        else:
            dia, bore_code = s[4], s[5:7]
            bore_mm = bore_from_code(bore_code)
    if not bore_mm > 0.0:
        raise ReadError(text, slash or basic, "the bore must be a positive diameter", 0)
    key = var_digits.lstrip("0")
    btype = GOST_TYPES[type_digit][0]
    variant = GOST_VARIANTS.get(type_digit, {}).get(key)
    if key == "":
        var_meaning = "basic design (seed 003 line 158)"
    elif variant is None:
        var_meaning = f"design variant {var_written or key} (not decoded)"
    else:
        var_meaning = variant.meaning
        btype = variant.bearing_type or btype
        if variant.uncertain:
            notes.append(
                f"design variant {key} of type {type_digit}: '{_short(variant.meaning)}'"
                " is the usual GOST reading, not stated in seed 003: verify"
            )
    if dia == "0" and not small:
        notes.append(
            "diameter series 0 is not named in seed 003; GOST 3478 places it before "
            "8 and 9 (smallest outer diameter)"
        )
    dia_name = GOST_DIAMETER_NAMES[dia]
    width_name = GOST_WIDTH_NAMES[width]

    # basic number, read from left to right
    if written["width"]:
        parts.append(
            (width, (f"width series {width}: {width_name} (digit 7, seed 003 lines 160, 581)"))
        )
    if var_written is not None:
        parts.append(
            (var_written, (f"design variant (digits 5-6, seed 003 line 158): {var_meaning}"))
        )
    if written["type"]:
        parts.append((type_digit, f"type {type_digit}: {GOST_TYPES[type_digit][1]}"))
    if small:
        if n >= 3:
            parts.append(("0", "digit 3 = 0: small-bore scheme (d < 10 mm)"))
        if written["dia"]:
            parts.append(
                (dia, (f"diameter series {dia}: {dia_name} (digit 2 in the small-bore scheme)"))
            )
        parts.append((bore_code, f"bore d = {bore_code} mm (digit 1 in the small-bore scheme)"))
    else:
        if written["dia"]:
            parts.append(
                (dia, (f"diameter series {dia}: {dia_name} (digit 3, seed 003 lines 141, 575)"))
            )
        if slash is None:
            parts.append(
                (bore_code, bore_meaning(bore_code, bore_mm) + " (seed 003 lines 137-139)")
            )
    if slash is not None:
        parts.append(("/" + slash, f"bore d = {format_mm(bore_mm)} mm written after '/'"))
    suffixes = _suffix_parts(tokens, notes)
    parts.extend(suffixes)

    closures = variant.closures if variant and variant.closures else "open"
    if any(code.startswith("С") for code, _ in suffixes) and closures == "open":
        closures = "unknown"
        notes.append(
            "suffix С: closed and greased, but the kind of closure (shields or "
            "seals) is not in the designation"
        )
    contact = None
    if variant is not None and variant.angle_deg is not None:
        contact = math.radians(variant.angle_deg)

    dims = gost_iso_dims(type_digit, key, dia, width)
    series, iso_eq = _iso_cross_reference(
        type_digit,
        key,
        variant,
        dims,
        small,
        bore_code,
        bore_mm,
        slash,
        cls,
        suffixes,
        prefix_parts,
        notes,
    )
    canonical = (
        prefix_text + basic + ("/" + slash if slash else "") + "".join(code for code, _ in suffixes)
    )

    bits = [
        TYPE_NAMES[btype],
        f"{dia_name} diameter series {dia}",
        f"width series {width}",
        f"bore {format_mm(bore_mm)} mm",
    ]
    if closures != "open":
        bits.append(CLOSURE_WORDS[closures])
    if variant is not None and variant.closures is None:
        bits.append(_short(variant.meaning))
    if cls != "0":
        bits.append(f"precision class {cls.replace('Т', 'T')}")
    if cat:
        bits.append(f"category {_LATIN_CAT[cat]}")
    bits.extend(
        _short(m) for c, m in suffixes if not m.endswith("(not decoded)") and not c.startswith("С")
    )
    return Designation(
        text=text,
        system="gost",
        bearing_type=btype,
        bore=bore_mm / 1000.0,
        bore_code=bore_code,
        series=series,
        dimension_series=dims,
        diameter_series=dia,
        diameter_series_name=dia_name,
        width_series=width,
        width_series_name=width_name,
        design_variant=var_written,
        design_variant_meaning=var_meaning,
        precision_class=cls.replace("Т", "T"),
        category=_LATIN_CAT.get(cat or ""),
        contact_angle=contact,
        closures=closures,
        prefixes=tuple(prefix_parts),
        suffixes=tuple(suffixes),
        parts=tuple(parts),
        iso_equivalent=iso_eq,
        gost_equivalent=canonical,
        notes=tuple(dict.fromkeys(notes)),
        description=", ".join(bits),
    )


_LATIN_CAT = {"А": "A", "В": "B", "С": "C"}


def _iso_cross_reference(
    type_digit: str,
    key: str,
    variant: GostVariant | None,
    dims: str | None,
    small: bool,
    bore_code: str,
    bore_mm: float,
    slash: str | None,
    cls: str,
    suffixes: list[tuple[str, str]],
    prefix_parts: list[tuple[str, str]],
    notes: list[str],
) -> tuple[str | None, str | None]:
    """Return (ISO series key, ISO equivalent) of a GOST reading, adding notes."""
    if type_digit == "6" and key in ("", "3", "4", "6"):
        fam = family_for_gost("6", "", dims)
        if fam is not None:
            notes.append(
                f"same dimensions as ISO {fam.key}xx, but the contact angle differs "
                "(GOST 12/26/36 deg against ISO 15/25/30/40 deg): no exact ISO "
                "equivalent"
            )
            return fam.key, None
        return None, None
    iso_suffix = variant.iso_suffix if variant is not None else None
    fam = family_for_gost(type_digit, "" if iso_suffix else key, dims)
    if fam is None:
        return None, None
    if small:
        if not (fam.small_bore or fam.key in ("618", "619", "160")):
            return fam.key, None
        bore = f"{fam.key}/{bore_code}" if len(fam.key) == 3 else fam.key + bore_code
    elif slash is not None:
        bore = f"{fam.key}/{format_mm(bore_mm)}"
    else:
        bore = fam.key + bore_code
    closure = [iso_suffix] if iso_suffix in _ISO_CLOSURES else []
    others = [iso_suffix] if iso_suffix and not closure else []
    if cls in "6542":
        others.append("P" + cls)
    elif cls != "0":
        notes.append(f"precision class {cls.replace('Т', 'T')} has no ISO 492 suffix here")
    dropped = [code for code, meaning in prefix_parts if not meaning.startswith("precision")]
    dropped += [code for code, _ in suffixes]
    if dropped:
        notes.append("not carried into the ISO equivalent: " + ", ".join(dropped))
    notes.extend(fam.notes)
    return fam.key, format_iso(bore, closure, others)
