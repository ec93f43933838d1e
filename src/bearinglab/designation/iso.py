"""Reader of ISO 15 style designations (``6205-2RS``, ``NU206 E``, ``7206 BECBP``...).

The basic designation is a family key (type code and ISO 15 dimension series, e.g. ``62``,
``NU22``, ``302``, ``QJ2``) followed by a bore code -- 00 = 10, 01 = 12, 02 = 15, 03 = 17 mm,
04 to 96 times 5 mm --, a single digit d in mm for small deep-groove and self-aligning
bearings (``608``, ``625``) or ``/d`` (``62/22``, ``618/500``).  Suffixes, separated by
``-``, ``/``, a space or nothing, are the common SKF / Schaeffler / NSK / NTN codes
(closures, snap ring, clearance, precision, cage, internal design, contact angle).  The
GOST 3189-89 equivalents follow the cross references used for seed 003's system (106 =
6006, 7000106 = 16006, 180205 = 6205-2RS).

Designations with a GOST precision prefix (``6-36209``), Cyrillic letters or six- and
seven-digit numbers are not ISO designations and are refused here.

>>> d = parse_iso("6205-2RS")
>>> d.series, d.bore_mm, d.closures, d.gost_equivalent
('62', 25.0, '2seals', '180205')
>>> parse_iso("7308 AC").contact_angle_deg
25.0
"""

from __future__ import annotations

import math
import re

from ._common import DASHES, ReadError, format_iso, nfkc_chars, original_slice
from ._suffixes import IsoSuffix, suffix_table
from ._tables import (
    CLOSURE_WORDS,
    FAMILIES,
    ISO_DIAMETER_NAMES,
    ISO_PREFIXES,
    ISO_WIDTH_NAMES,
    TYPE_NAMES,
    Family,
    bore_from_code,
    bore_meaning,
    format_mm,
    gost_iso_dims,
)
from .model import Designation

__all__ = ["parse_iso"]

_BASIC_RE = re.compile(r"(?P<pre>[A-Z]*) ?(?P<digits>[0-9]+)(?:/(?P<d>[0-9]+(?:[.,][0-9]+)?))?")
#: Separators with no suffix between them, or after the last one ("6205--2RS", "6205-").
_EMPTY_GROUP_RE = re.compile(r"[-/](?: ?[-/])+| ?[-/] ?$")
_GROUP_RE = re.compile(r"[^-/ ]+")
_WIDTH_ORDER = "0172345689"
_BORE_SHAPE = ("K", "K30")


def _normalise(text: str) -> tuple[str, list[int]]:
    """NFKC-normalise, upper-case, unify dashes, collapse white space; keep the map to the
    original.  Digits other than ASCII 0-9 are refused (:func:`nfkc_chars`)."""
    out: list[str] = []
    index: list[int] = []
    for i, ch in nfkc_chars(text):
        if ch.isspace():
            if out and out[-1] != " ":
                out.append(" ")
                index.append(i)
            continue
        for up in "-" if ch in DASHES else ch.upper():
            out.append(up)
            index.append(i)
    while out and out[-1] == " ":
        out.pop()
        index.pop()
    while out and out[0] == " ":
        out.pop(0)
        index.pop(0)
    return "".join(out), index


def _find_family(pre: str, digits: str, slash: str | None) -> tuple[Family, str] | None:
    """Return (family, bore text) for the basic number, or None."""
    full = pre + digits
    best: tuple[Family, str] | None = None
    for fam in FAMILIES.values():
        letters = fam.key.rstrip("0123456789")
        if letters != pre or not full.startswith(fam.key):
            continue
        rest = full[len(fam.key) :]
        ok = (
            rest == ""
            if slash is not None
            else len(rest) == 2 or (len(rest) == 1 and fam.small_bore and rest != "0")
        )
        if ok and (best is None or len(fam.key) > len(best[0].key)):
            best = (fam, rest)
    return best


def _decode_group(group: str, table: dict[str, IsoSuffix]) -> list[tuple[str, IsoSuffix | None]]:
    """Split one suffix group into known codes, longest first; a tail left is not decoded."""
    codes = sorted(table, key=len, reverse=True)
    out: list[tuple[str, IsoSuffix | None]] = []
    i = 0
    while i < len(group):
        code = next((c for c in codes if group.startswith(c, i)), None)
        if code is None:
            out.append((group[i:], None))
            break
        out.append((code, table[code]))
        i += len(code)
    return out


def _gost_number(fam: Family, variant: str, bore_text: str, slash: str | None) -> str | None:
    """Compose the GOST 3189-89 basic number of an ISO family, or None if not possible."""
    assert fam.gost is not None
    type_digit = fam.gost[0]
    for width in _WIDTH_ORDER:
        for dia in "1723489560":
            if gost_iso_dims(type_digit, variant, dia, width) == fam.dims:
                head = width + variant.zfill(2) + type_digit
                if slash is not None:
                    return (head + dia).lstrip("0") + "/" + slash
                if len(bore_text) == 1:
                    return (head + "0" + dia + bore_text).lstrip("0")
                return (head + dia + bore_text).lstrip("0")
    return None


def parse_iso(text: str) -> Designation:
    """Read an ISO 15 style designation such as ``"6205-2RS"`` or ``"NU206 E"``.

    Parameters
    ----------
    text : str
        The designation; any case, separators ``-``, ``/`` or space [-]

    Returns
    -------
    Designation
        The reading, in SI units (bore in metres, contact angle in radians).

    Raises
    ------
    bearinglab.errors.DesignationError
        Naming the part that is not understood.

    Examples
    --------
    >>> parse_iso("16006").gost_equivalent, parse_iso("61904").gost_equivalent
    ('7000106', '1000904')
    >>> parse_iso("62/22").bore_mm
    22.0
    """
    if not isinstance(text, str):
        raise ReadError(repr(text), repr(text), "a designation must be a string")
    norm, index = _normalise(text)
    if not norm:
        raise ReadError(text, text, "empty designation")
    if re.search(r"[А-ЯЁ]", norm):
        raise ReadError(
            text, text, "Cyrillic letters: not an ISO designation (GOST 3189-89?)", progress=-1
        )
    m = _BASIC_RE.match(norm)
    if not m:
        raise ReadError(
            text, text, "expected an ISO basic designation (type, series and bore code, e.g. 6205)"
        )
    pre, digits, slash = m["pre"], m["digits"], m["d"]
    if pre and pre not in ISO_PREFIXES:
        raise ReadError(
            text,
            original_slice(text, index, 0, len(pre)),
            "unknown ISO type prefix (N, NU, NJ, NUP, NF, NN, NA, QJ)",
        )
    found = _find_family(pre, digits, slash)
    end = m.end()
    if found is None and slash is not None:
        # "6205/2RS": the slash separates a suffix, it does not introduce a bore
        found, slash, end = _find_family(pre, digits, None), None, m.end("digits")
    if found is None:
        raise ReadError(
            text,
            original_slice(text, index, 0, m.end()),
            "not a known ISO family followed by a bore code",
        )
    fam, bore_text = found
    if slash is not None:
        bore_mm = float(slash.replace(",", "."))
        bore_code = "/" + format_mm(bore_mm)
    elif len(bore_text) == 1:
        bore_mm, bore_code = float(bore_text), bore_text
    else:
        if int(bore_text) > 96:
            raise ReadError(
                text,
                bore_text,
                "bore codes run from 00 to 96; larger bores are written '/d'",
                m.start("digits") + len(fam.key) - len(pre),
            )
        bore_mm, bore_code = bore_from_code(bore_text), bore_text
    if not bore_mm > 0.0:
        raise ReadError(text, slash or bore_text, "the bore must be a positive diameter")

    empty = _EMPTY_GROUP_RE.search(norm, end)
    if empty is not None:
        raise ReadError(
            text,
            original_slice(text, index, empty.start(), empty.end()),
            "a separator with no suffix after it",
            empty.start(),
        )
    table = suffix_table(fam.group)
    groups: list[list[tuple[str, IsoSuffix | None]]] = []
    seen: set[str] = set()
    for g in _GROUP_RE.finditer(norm, end):
        decoded = _decode_group(g.group(), table)
        if decoded[0][1] is None:
            raise ReadError(
                text,
                original_slice(text, index, g.start(), g.end()),
                f"unknown suffix for an ISO {fam.key} bearing",
                g.start(),
            )
        for code, _ in decoded:
            if code in seen:
                raise ReadError(text, code, "repeated suffix: the code is written twice", g.start())
            seen.add(code)
        groups.append(decoded)
    return _build(text, fam, pre, digits, slash, bore_text, bore_code, bore_mm, groups)


def _build(
    text: str,
    fam: Family,
    pre: str,
    digits: str,
    slash: str | None,
    bore_text: str,
    bore_code: str,
    bore_mm: float,
    groups: list[list[tuple[str, IsoSuffix | None]]],
) -> Designation:
    notes: list[str] = list(fam.notes)
    thrust = fam.bearing_type.startswith("thrust")
    w, d = fam.dims[0], fam.dims[1]
    dia_name = ISO_DIAMETER_NAMES.get(d)
    width_name = None if thrust else ISO_WIDTH_NAMES.get(w)
    wword = "height" if thrust else "width"
    parts: list[tuple[str, str]] = []
    dims_meaning = (
        f"dimension series {fam.dims}: {wword} series {w}"
        f"{' (not written)' if len(fam.dims_text) == 1 else ''}, diameter series {d}"
        f" ({dia_name})"
    )
    if fam.type_text:
        parts.append((fam.type_text, fam.type_meaning))
        if fam.dims_text:
            parts.append((fam.dims_text, dims_meaning))
    else:
        parts.append((fam.key, f"{fam.type_meaning}, {dims_meaning}"))
    if slash is not None:
        parts.append(("/" + slash, f"bore d = {format_mm(bore_mm)} mm written after '/'"))
    elif len(bore_text) == 1:
        parts.append((bore_text, f"bore d = {bore_text} mm (single digit: small bore)"))
    else:
        parts.append((bore_text, bore_meaning(bore_text, bore_mm)))

    suffixes: list[tuple[str, str]] = []
    shields = seals = 0
    precision = "0"
    angles: list[float] = []
    closure_codes: list[str] = []
    snap_codes: list[str] = []
    other_groups: list[str] = []
    for group in groups:
        other = ""
        for code, info in group:
            meaning = info.meaning if info else f"suffix {code} (not decoded)"
            suffixes.append((code, meaning))
            parts.append((code, meaning))
            if info is None:
                other += code
                notes.append(f"suffix {code}: not decoded (maker-specific)")
                continue
            if info.kind == "closure":
                if shields + seals + sum(info.closure) > 2:
                    raise ReadError(
                        text,
                        code,
                        f"conflicts with {'-'.join(closure_codes)}: closures on more than "
                        "the two sides of a bearing",
                        len(text),
                    )
                shields += info.closure[0]
                seals += info.closure[1]
                closure_codes.append(code)
            elif info.kind == "snap":
                snap_codes.append(code)
            else:
                other += code
            if info.kind == "precision" and info.precision:
                precision = info.precision
            if info.kind == "clearance":
                notes.append(f"radial internal clearance group {code}: {info.meaning}")
            if info.angle_deg is not None:
                angles.append(info.angle_deg)
        other_groups.append(other)
    true_closures = list(closure_codes)
    if closure_codes:
        closure_codes += snap_codes
    else:
        other_groups = [" ".join(snap_codes)] + other_groups

    if shields == 0 and seals == 0:
        closures = "open"
    elif seals == 0 and shields in (1, 2):
        closures = "shield" if shields == 1 else "2shields"
    elif shields == 0 and seals in (1, 2):
        closures = "seal" if seals == 1 else "2seals"
    else:
        closures = "unknown"
        notes.append(
            "closure codes combine shields and seals or give more than two: "
            "kind of closure not summarised"
        )

    contact = None
    if angles:
        contact = math.radians(angles[-1])
        if len(set(angles)) > 1:
            notes.append("more than one contact-angle code; the last one is used")
    elif fam.group == "angular":
        notes.append(
            "contact angle not in the designation: it depends on the maker (SKF: B = "
            "40 deg, A = 30 deg, AC = 25 deg, C = 15 deg; some makers write no letter "
            "for 30 deg); ISO 15 fixes only the boundary dimensions"
        )
    elif fam.group == "four":
        contact = math.radians(35.0)
        notes.append(
            "contact angle 35 deg is the nominal value of SKF/Schaeffler QJ designs, "
            "not part of the designation"
        )

    basic = fam.key + (bore_text if slash is None else "/" + slash)
    canonical = format_iso(basic, closure_codes, other_groups)
    gost_eq = _gost_equivalent(
        fam, bore_text, slash, precision, closure_codes, snap_codes, suffixes, notes
    )
    name = TYPE_NAMES[fam.bearing_type]
    if fam.type_text == "" and fam.group == "angular":
        name = "double-row " + name
    elif fam.type_text.isalpha():
        name += f" {fam.type_text}"
    bits = [
        name,
        f"{dia_name} diameter series {d}",
        f"{wword} series {w}",
        f"bore {format_mm(bore_mm)} mm",
    ]
    if closures not in ("open", "unknown"):
        bits.append(CLOSURE_WORDS[closures])
    if contact is not None:
        bits.append(f"contact angle {format_mm(round(math.degrees(contact), 6))} deg")
    if precision != "0":
        bits.append(f"precision class {precision}")
    bits.extend(
        m.split(" (")[0]
        for c, m in suffixes
        if c not in true_closures
        and not m.endswith("(not decoded)")
        and "contact angle" not in m
        and "tolerance class" not in m
    )
    design = fam.type_text if fam.type_text.isalpha() else None
    return Designation(
        text=text,
        system="iso",
        bearing_type=fam.bearing_type,
        bore=bore_mm / 1000.0,
        bore_code=bore_code,
        series=_series_key(fam),
        dimension_series=fam.dims,
        diameter_series=d,
        diameter_series_name=dia_name,
        width_series=w,
        width_series_name=width_name,
        design_variant=design,
        design_variant_meaning=fam.type_meaning if design else None,
        precision_class=precision,
        category=None,
        contact_angle=contact,
        closures=closures,
        prefixes=((pre, fam.type_meaning),) if pre else (),
        suffixes=tuple(suffixes),
        parts=tuple(parts),
        iso_equivalent=canonical,
        gost_equivalent=gost_eq,
        notes=tuple(dict.fromkeys(notes)),
        description=", ".join(bits),
    )


def _series_key(fam: Family) -> str:
    """Catalogue series key: the older 68/69 spellings look up as 618/619."""
    return {"68": "618", "69": "619"}.get(fam.key, fam.key)


def _gost_equivalent(
    fam: Family,
    bore_text: str,
    slash: str | None,
    precision: str,
    closure_codes: list[str],
    snap_codes: list[str],
    suffixes: list[tuple[str, str]],
    notes: list[str],
) -> str | None:
    """GOST 3189-89 designation of the same bearing, or None (with a note saying why)."""
    if fam.gost is None or not fam.exact:
        if fam.gost is None:
            notes.append(f"no GOST 3189-89 equivalent known here for ISO {fam.key}")
        return None
    variant = fam.gost[1]
    table = suffix_table(fam.group)
    special = closure_codes + [c for c in snap_codes if c not in closure_codes]
    if special:
        gvars = {table[c].gost_variant for c in special}
        if fam.group != "deep" or len(special) != 1 or None in gvars:
            notes.append("no GOST 3189-89 design variant known here for " + "".join(special))
            return None
        variant = gvars.pop() or ""
    codes = [c for c, _ in suffixes]
    if any(c in _BORE_SHAPE for c in codes):
        notes.append("tapered-bore variant: no GOST 3189-89 equivalent given here")
        return None
    number = _gost_number(fam, variant, bore_text, slash)
    if number is None:
        return None
    dropped = [
        c for c in codes if c not in special and table.get(c, IsoSuffix("")).kind != "precision"
    ]
    if dropped:
        notes.append("not carried into the GOST equivalent: " + ", ".join(dropped))
    if slash is not None:
        notes.append("GOST '/d' spelling follows GOST 3189-89 as usually quoted (uncertain)")
    return (precision + "-" if precision != "0" else "") + number
