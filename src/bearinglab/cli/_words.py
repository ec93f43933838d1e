"""The command line's words for the library's: an input's flag, and the inputs a text
names (in backquotes, the library's markup) as flags. Imports nothing of the cli, so that
every part of it can use it."""

from ..errors import markup


def flag(name: str) -> str:
    """The command-line flag of input ``name``: ``radial_load_n`` -> ``--radial-load-n``."""
    return "--" + name.replace("_", "-")


#: The flags of the command running (parameter name -> flag), for its warnings.
_SHOWN: dict[str, str] = {}


def in_flags(text: str, shown: dict | None = None) -> str:
    """``text`` with the inputs it names in backquotes (`balls`) as the command's flags.

    >>> in_flags("give `balls` and `ball_diameter_mm`", {})
    'give --balls and --ball-diameter-mm'
    """
    shown = _SHOWN if shown is None else shown
    return markup(text, lambda name: shown.get(name, flag(name)))
