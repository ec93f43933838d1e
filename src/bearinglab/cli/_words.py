"""The command line's words for the library's: an input's flag, and a text's input names
(in backquotes, or snake_case names of the running command's parameters) as flags. Imports
nothing of the cli, so that every part of it can use it."""

import re


def flag(name: str) -> str:
    """The command-line flag of input ``name``: ``radial_load_n`` -> ``--radial-load-n``."""
    return "--" + name.replace("_", "-")


#: The flags of the command running (parameter name -> flag), for its warnings.
_SHOWN: dict[str, str] = {}


def in_flags(text: str, shown: dict | None = None, *, bare: bool = True) -> str:
    """``text`` with the inputs it names as the command's flags: a name in backquotes
    (`balls`), or (with ``bare``) a snake_case name of one of the command's parameters."""
    shown = _SHOWN if shown is None else shown
    text = re.sub(r"`(\w+)`", lambda m: shown.get(m.group(1), flag(m.group(1))), text)
    names = [n for n in shown if "_" in n and n in text] if bare else []
    if not names:
        return text
    # not a key of a specification: width_mm=1.2, outer:width_mm
    pattern = r"(?<![\w:,=])(" + "|".join(sorted(names, key=len, reverse=True)) + r")(?![\w=])"
    return re.sub(pattern, lambda m: shown[m.group(1)], text)
