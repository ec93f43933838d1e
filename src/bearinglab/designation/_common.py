"""Helpers shared by the GOST and ISO readers: text normalisation and read errors.

>>> normalise_dashes("6\u221218030")
'6-18030'
"""

from __future__ import annotations

import unicodedata

from bearinglab.errors import DesignationError

#: The only digits a designation may use (after NFKC normalisation, which turns
#: full-width "６２０５" into "6205"); other scripts' digits ("٦٢٠٥") are refused.
ASCII_DIGITS: str = "0123456789"

#: Characters read as a plain hyphen: hyphen, non-breaking hyphen, figure dash, en dash,
#: em dash, minus sign (seed 003 writes "6−18030ПР20П" with U+2212, line 319).
DASHES: str = "-\u2010\u2011\u2012\u2013\u2014\u2212"


def normalise_dashes(text: str) -> str:
    """Replace every dash variant by ``"-"``.

    Parameters
    ----------
    text : str
        Designation text [-]
    """
    return "".join("-" if ch in DASHES else ch for ch in text)


def _foreign_digit(raw: str) -> bool:
    return any(
        ch not in ASCII_DIGITS and unicodedata.category(ch) == "Nd"
        for ch in unicodedata.normalize("NFKC", raw)
    )


def nfkc_chars(text: str) -> list[tuple[int, str]]:
    """Return (position in ``text``, character) of the NFKC normal form, character by
    character, so that every normalised character keeps its place in the original.

    Raises a :class:`ReadError` naming the run of characters if the text holds digits
    that are not ASCII 0-9 after normalisation.

    Parameters
    ----------
    text : str
        Designation as given [-]

    Examples
    --------
    >>> "".join(ch for _, ch in nfkc_chars("\uff16\uff12\uff10\uff15"))
    '6205'
    """
    out: list[tuple[int, str]] = []
    for i, raw in enumerate(text):
        for ch in unicodedata.normalize("NFKC", raw):
            if _foreign_digit(ch):
                j = i
                while j < len(text) and _foreign_digit(text[j]):
                    j += 1
                raise ReadError(
                    text,
                    text[i:j] or raw,
                    "digits must be the ASCII digits 0-9 (full-width digits are "
                    "accepted; other scripts' digits are not)",
                    progress=len(out),
                )
            out.append((i, ch))
    return out


class ReadError(DesignationError):
    """A :class:`DesignationError` that also records how far the reader got.

    ``progress`` is the number of normalised characters read before the failure; the
    top-level :func:`bearinglab.designation.parse` reports the error of the reader that
    got further.

    >>> e = ReadError("62A5", "A5", "unknown suffix", progress=2)
    >>> str(e), e.progress
    ("designation '62A5': cannot read 'A5': unknown suffix", 2)
    """

    def __init__(self, designation: str, part: str, reason: str, progress: int = 0) -> None:
        super().__init__(designation, part, reason)
        self.progress = progress


def original_slice(text: str, index: list[int], start: int, stop: int | None = None) -> str:
    """Return the original characters behind normalised positions ``start:stop``.

    Parameters
    ----------
    text : str
        Original designation [-]
    index : list of int
        For each normalised character, its position in ``text`` [-]
    start : int
        First normalised position [-]
    stop : int or None
        One past the last normalised position; None for the end [-]

    Examples
    --------
    >>> original_slice("4- 3003124P", [0, 1, 3, 4], 2, 4)
    '30'
    """
    if start >= len(index):
        return text[index[-1] + 1 :].strip() if index else text
    stop_n = len(index) if stop is None else stop
    if stop_n <= start:
        return ""
    lo = index[start]
    hi = index[stop_n - 1] + 1 if stop is not None else len(text)
    return text[lo:hi].strip()


def format_iso(basic: str, closure_codes: list[str], other_groups: list[str]) -> str:
    """Spell an ISO designation: closures joined after ``-``, other groups after spaces.

    Parameters
    ----------
    basic : str
        Basic designation, e.g. ``"6205"`` or ``"NU206"`` [-]
    closure_codes : list of str
        Closure (and snap-ring) codes, e.g. ``["2RS"]`` [-]
    other_groups : list of str
        Further suffix groups, e.g. ``["C3"]`` [-]

    Examples
    --------
    >>> format_iso("6205", ["2RS"], ["C3"])
    '6205-2RS C3'
    """
    text = basic
    if closure_codes:
        text += "-" + "".join(closure_codes)
    for group in other_groups:
        if group:
            text += " " + group
    return text
