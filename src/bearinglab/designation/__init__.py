"""Bearing designations: read GOST 3189-89 and ISO designations into :class:`Designation`.

:func:`parse` reads a designation in either system.  GOST 3189-89 is the system of seed 003
(lines 129-187 and 240-350); ISO covers the ISO 15 families with the common SKF /
Schaeffler / NSK / NTN suffixes.  Some texts are valid in both systems with different
meanings ("6205" is an ISO deep-groove bearing but a GOST angular contact bearing): then
the ISO reading is returned, the GOST reading is kept in ``alternatives`` and a note says
so -- never silently.

>>> d = parse("6205")
>>> d.system, d.bearing_type, d.alternatives[0].bearing_type
('iso', 'radial_ball', 'angular_contact_ball')
>>> parse("180205").iso_equivalent
'6205-2RS'
>>> gost_equivalent("6205-2RS"), iso_equivalent("7000106")
('180205', '16006')
"""

from __future__ import annotations

from dataclasses import replace

from bearinglab.errors import DesignationError, InputError

from ._common import ReadError
from .gost import parse_gost
from .iso import parse_iso
from .model import BEARING_TYPES, Designation

__all__ = [
    "BEARING_TYPES",
    "Designation",
    "gost_equivalent",
    "iso_equivalent",
    "parse",
    "parse_gost",
    "parse_iso",
]

_SYSTEMS = (None, "gost", "iso")


def parse(text: str, system: str | None = None) -> Designation:
    """Read a bearing designation in the GOST 3189-89 or the ISO system.

    Parameters
    ----------
    text : str
        The designation, e.g. ``"6-36209"``, ``"180205"``, ``"6205-2RS"`` [-]
    system : str or None
        ``"gost"`` or ``"iso"`` to force one reader; None tries both [-]

    Returns
    -------
    Designation
        With ``system=None`` and two differing readings, the ISO one, the GOST reading in
        ``alternatives`` and a note; if both readings are the same bearing ("1205"), the
        ISO one with the GOST reading in ``alternatives`` and no note.  If only one reader
        understands the text, its reading with a note naming what the other could not
        read (``parse("6205 C")`` is GOST type 6 with suffix С, noted "not an ISO
        designation: cannot read 'C' ...").

    Raises
    ------
    bearinglab.errors.InputError
        If ``system`` is not None, ``"gost"`` or ``"iso"``.
    bearinglab.errors.DesignationError
        If no reader understands the text; it names the part not understood by the reader
        that got further.

    Examples
    --------
    >>> parse("6205", system="gost").contact_angle_deg is None
    True
    >>> parse("1205").notes
    ()
    """
    if system not in _SYSTEMS:
        raise InputError("system", system, "'gost' or 'iso'")
    if not isinstance(text, str):
        raise DesignationError(repr(text), repr(text), "a designation must be a string")
    if not text.strip():
        raise DesignationError(text, text, "empty designation")
    if system == "gost":
        return parse_gost(text)
    if system == "iso":
        return parse_iso(text)
    iso = gost = None
    iso_error = gost_error = None
    try:
        iso = parse_iso(text)
    except ReadError as exc:
        iso_error = exc
    try:
        gost = parse_gost(text)
    except ReadError as exc:
        gost_error = exc
    if iso is not None and gost is not None:
        notes = iso.notes
        same = iso.bearing_type == gost.bearing_type and gost.iso_equivalent == iso.iso_equivalent
        if not same:
            notes += (
                f"also reads as GOST 3189-89: {gost.description}; the ISO reading is used "
                "(`system` gost forces the GOST one)",
            )
        return replace(iso, alternatives=(gost,), notes=notes)
    # The other reader's failure is noted only when it read part of the text: "NU205" is
    # no GOST number from its first letter, and saying so is noise.
    if iso is not None:
        assert gost_error is not None
        return replace(iso, notes=iso.notes + _not_read("a GOST 3189-89", gost_error))
    if gost is not None:
        assert iso_error is not None
        return replace(gost, notes=gost.notes + _not_read("an ISO", iso_error))
    assert iso_error is not None and gost_error is not None
    raise gost_error if gost_error.progress > iso_error.progress else iso_error


def _not_read(what: str, error: ReadError) -> tuple[str, ...]:
    """The note naming what the other reader could not read, e.g. "not an ISO designation:
    cannot read 'C' (unknown suffix for an ISO 62 bearing)", or none when that reader
    failed at the first character."""
    if error.progress <= 0:
        return ()
    return (f"not {what} designation: cannot read {error.part!r} ({error.reason})",)


def gost_equivalent(text: str, system: str | None = None) -> str | None:
    """Return the GOST 3189-89 designation of a bearing, or None if there is none.

    Parameters
    ----------
    text : str
        Designation in either system (read as :func:`parse` does) [-]
    system : str or None
        Force ``"gost"`` or ``"iso"`` reading [-]

    Examples
    --------
    >>> gost_equivalent("6006"), gost_equivalent("61904")
    ('106', '1000904')
    """
    return parse(text, system).gost_equivalent


def iso_equivalent(text: str, system: str | None = None) -> str | None:
    """Return the ISO designation of a bearing, or None if there is none; ``text`` and
    ``system`` as in :func:`gost_equivalent`.

    Parameters
    ----------
    text : str
        The designation in either system (read as :func:`parse` does).
    system : str or None
        ``"gost"`` or ``"iso"`` to force one reader; None tries both.

    Examples
    --------
    >>> iso_equivalent("310"), iso_equivalent("80205")
    ('6310', '6205-2Z')
    """
    return parse(text, system).iso_equivalent
