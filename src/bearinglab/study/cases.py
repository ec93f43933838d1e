"""The cases of a study: a grid of option values or a table read from CSV/Parquet.

A grid is the Cartesian product of its options' value lists (the last option varies
fastest, as in :func:`itertools.product`), repeated ``repeats`` times; options given as a
random range (``"uniform:LOW:HIGH"``) are drawn for each case from a generator seeded by
the study seed and the case index alone (:func:`case_rng`), so a case's inputs never
depend on the partitioning, the workers or the order in which cases run. The inputs of
cases ``start..stop`` are computed from their indices (:meth:`Grid.rows`): a study of
10^6 cases never holds its whole input table.

Value forms (Python values or the command line's text):

- a number, a text, or a list of them: those values;
- ``"A,B,C"``: a list;
- ``"START:STOP:COUNT"``: COUNT values evenly spaced from START to STOP (both included);
- ``"log:START:STOP:COUNT"``: COUNT values evenly spaced in log scale (START, STOP > 0);
- ``"uniform:LOW:HIGH"``: a random value in [LOW, HIGH) for each case.
"""

from __future__ import annotations

import difflib
import hashlib
import json
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..errors import InputError

#: Kinds of option value: what each holds.
KINDS = {
    "number": "a number",
    "integer": "a whole number",
    "text": "a text",
    "texts": "specifications, ';' between them (one value per case)",
    "path": "a file name",
    "bool": "true or false",
}
RANGE_FORMS = ("A,B,C", "START:STOP:COUNT", "log:START:STOP:COUNT", "uniform:LOW:HIGH")


@dataclass(frozen=True)
class Option:
    """One input of an analysis: its kind, default (None: not used unless given), help,
    choices, and ``seeded``: a value other than 0 is drawn afresh for each case from the
    case seed (ball-size errors, measurement noise: the analysis' own random inputs)."""

    kind: str
    default: object
    help: str
    choices: tuple = ()
    seeded: bool = False


@dataclass(frozen=True)
class Uniform:
    """A random value in [low, high) drawn for every case (:func:`case_rng`)."""

    low: float
    high: float

    def to_json(self) -> str:
        return f"uniform:{self.low!r}:{self.high!r}"


def case_rng(seed: int, case: int, stream: int = 0) -> np.random.Generator:
    """The random generator of one case: from the study ``seed``, the ``case`` index and
    the ``stream`` only (a data set passes its seed and the record index).

    ``stream`` 0 draws the random options, 1 seeds the analysis' own random inputs
    (ball-size errors, measurement noise), so adding a random option never changes them.

    Parameters
    ----------
    seed : int
        The study's (or data set's) seed, >= 0.
    case : int
        The case's (or record's) index, >= 0.
    stream : int
        0: the random options (the default); 1: the analysis' own random inputs.

    Returns
    -------
    numpy.random.Generator
        The same generator for the same three numbers.

    Examples
    --------
    >>> float(case_rng(1, 7).random()) == float(case_rng(1, 7).random())
    True
    """
    return np.random.default_rng(np.random.SeedSequence([int(seed), int(case), int(stream)]))


def case_seed(seed: int, case: int) -> int:
    """An integer seed for the analysis' random inputs of case index ``case`` of a study
    seeded ``seed`` (stream 1 of :func:`case_rng`).

    Parameters
    ----------
    seed : int
        The study's seed, >= 0.
    case : int
        The case's index, >= 0.

    Returns
    -------
    int
        A seed in [0, 2**32).
    """
    return int(np.random.SeedSequence([int(seed), int(case), 1]).generate_state(1)[0])


def _number(name: str, text: str, kind: str):
    try:
        value = float(text)
    except ValueError:
        raise InputError(name, text, KINDS[kind]) from None
    if not math.isfinite(value):
        raise InputError(name, text, "a finite number")
    if kind == "integer":
        if value != int(value):
            raise InputError(name, text, "a whole number")
        return int(value)
    return value


def _scalar(name: str, value, option: Option):
    """One value of ``option`` checked for its kind (text parsed)."""
    kind = option.kind
    if kind in ("text", "texts", "path"):
        if not isinstance(value, str) or not value.strip():
            raise InputError(name, value, "a non-empty text")
        value = value.strip()
    elif kind == "bool":
        if isinstance(value, str):
            low = value.strip().lower()
            if low not in ("true", "false", "yes", "no", "1", "0"):
                raise InputError(name, value, "true or false")
            value = low in ("true", "yes", "1")
        elif not isinstance(value, (bool, np.bool_)):
            raise InputError(name, value, "true or false")
        value = bool(value)
    else:
        if isinstance(value, str):
            value = _number(name, value.strip(), kind)
        elif isinstance(value, (bool, np.bool_)) or not isinstance(
            value, (int, float, np.integer, np.floating)
        ):
            raise InputError(name, value, KINDS[kind])
        elif not math.isfinite(value):
            raise InputError(name, value, "a finite number")
        elif kind == "integer":
            if value != int(value):
                raise InputError(name, value, "a whole number")
            value = int(value)
        else:
            value = float(value)
    if option.choices and value not in option.choices:
        raise InputError(name, value, "one of " + ", ".join(map(str, option.choices)))
    return value


def _count(name: str, text: str, whole: str) -> int:
    try:
        count = int(text)
    except ValueError:
        raise InputError(name, whole, "START:STOP:COUNT with a whole COUNT") from None
    if count < 1:
        raise InputError(name, whole, "a range with COUNT >= 1", "the range is empty")
    return count


def parse_values(name: str, value, option: Option) -> list | Uniform:
    """The value list (or random range) of one option from a Python value or its text.

    ``value`` is a value, a list of them, a :class:`Uniform` (returned as it is) or one of
    the text forms of this module; each value is checked against ``option`` (its kind and
    choices); ``name`` is the option's name, which the errors name.

    Parameters
    ----------
    name : str
        The option's name, for the errors (e.g. ``speed_rpm``).
    value : object
        A value, a list (tuple, array, range) of them, a :class:`Uniform`, or text: "A,B,C",
        "START:STOP:COUNT", "log:START:STOP:COUNT" (START, STOP > 0) or "uniform:LOW:HIGH"
        (LOW < HIGH; the ranges for numbers only), in the option's unit.
    option : Option
        The option: its kind (number, integer, text, texts, bool, path) and choices.

    Returns
    -------
    list or Uniform
        The values, each checked, or the random range.

    Examples
    --------
    >>> parse_values("speed_rpm", "1000:3000:3", Option("number", None, ""))
    [1000.0, 2000.0, 3000.0]
    >>> parse_values("designation", "6205,6206", Option("text", None, ""))
    ['6205', '6206']
    """
    if isinstance(value, Uniform):
        return value
    if isinstance(value, str):
        text = value.strip()
        if option.kind in ("number", "integer") and ":" in text:
            parts = [p.strip() for p in text.split(":")]
            head = parts[0].lower()
            if head == "uniform":
                if len(parts) != 3:
                    raise InputError(name, value, "uniform:LOW:HIGH")
                low, high = (_number(name, p, "number") for p in parts[1:])
                if not low < high:
                    raise InputError(
                        name, value, "uniform:LOW:HIGH with LOW < HIGH", "the range is empty"
                    )
                return Uniform(low, high)
            log = head == "log"
            parts = parts[1:] if log else parts
            if len(parts) != 3:
                raise InputError(name, value, "one of the forms " + ", ".join(RANGE_FORMS))
            start, stop = (_number(name, p, "number") for p in parts[:2])
            count = _count(name, parts[2], value)
            if log:
                if start <= 0 or stop <= 0:
                    raise InputError(name, value, "log:START:STOP:COUNT with START, STOP > 0")
                values = np.geomspace(start, stop, count)
            else:
                values = np.linspace(start, stop, count)
            return [
                _scalar(name, float(v), option)
                if option.kind == "number"
                else _scalar(name, round(float(v)), option)
                for v in values
            ]
        # a specification (outer:order=8,amplitude_um=0.5) is one value: its commas are
        # its own
        items = text.split(",") if "," in text and option.kind not in ("texts", "path") else [text]
        if any(not t.strip() for t in items):
            raise InputError(
                name,
                value,
                "a value or a list A,B,C without empty items",
                "the list is empty" if not text else "",
            )
        return [_scalar(name, t, option) for t in items]
    if isinstance(value, (list, tuple, np.ndarray, range)):
        values = list(value)
        if not values:
            raise InputError(name, value, "at least one value", "the list is empty")
        return [_scalar(name, v.item() if hasattr(v, "item") else v, option) for v in values]
    return [_scalar(name, value, option)]


def unknown_option(name: str, options: dict, analysis: str) -> InputError:
    """The error for an option ``analysis`` does not have, with the nearest names."""
    close = difflib.get_close_matches(name, list(options), n=3, cutoff=0.6)
    hint = f"did you mean {', '.join(close)}?" if close else ""
    return InputError("option", name, f"an option of '{analysis}': " + ", ".join(options), hint)


class Grid:
    """Cases of a Cartesian grid (module docstring); ``rows(start, stop)`` makes them.

    Parameters
    ----------
    values : dict
        Option name -> list of values or :class:`Uniform` (checked, see parse_values).
    repeats : int
        Times each grid point is repeated (with fresh random options).
    seed : int
        Study seed.
    """

    def __init__(self, values: dict, repeats: int, seed: int) -> None:
        self.values = values
        self.repeats = repeats
        self.seed = seed
        self.fixed = {k: v for k, v in values.items() if not isinstance(v, Uniform)}
        self.random = {k: v for k, v in values.items() if isinstance(v, Uniform)}
        self.shape = tuple(len(v) for v in self.fixed.values())
        self.count = int(np.prod(self.shape, dtype=np.int64)) * repeats
        self.columns = list(values)

    def rows(self, start: int, stop: int) -> list[dict]:
        """Inputs of cases start..stop-1 (``case`` first)."""
        index = np.arange(start, stop)
        point = index // self.repeats
        coords = np.unravel_index(point, self.shape) if self.shape else ()
        out = []
        for i, case in enumerate(index):
            row = {"case": int(case)}
            for (name, vals), c in zip(self.fixed.items(), coords, strict=True):
                row[name] = vals[int(c[i])]
            if self.random:
                rng = case_rng(self.seed, int(case))
                for name in sorted(self.random):
                    u = self.random[name]
                    row[name] = float(rng.uniform(u.low, u.high))
            out.append({"case": row["case"], **{k: row[k] for k in self.columns}})
        return out

    def random_inputs(self, options: dict) -> tuple[str, ...]:
        """The inputs that change with the seed: the random ranges, and the seeded options
        (:class:`Option`) wherever a value (or the default of one not given) is not 0."""
        return tuple(
            name
            for name, o in options.items()
            if name in self.random or (o.seeded and any(self.fixed.get(name, [o.default])))
        )

    def identity(self) -> dict:
        """JSON-ready description (what makes two studies the same)."""
        return {
            "grid": {
                k: (v.to_json() if isinstance(v, Uniform) else v) for k, v in self.values.items()
            },
            "repeats": self.repeats,
        }


class CaseTable:
    """Cases read from a CSV or Parquet file: one row per case, columns = option names.

    An empty cell leaves an optional input (one without a default: a clearance, a
    designation in a table that gives some bearings by their geometry) not given; an input
    with a default (a load, 0 N) needs a value in every row, or its column left out. A
    ``nan`` is refused as in ``--set``. The file's SHA-256 is part of the study's
    identity, so a changed file is a different study.
    """

    def __init__(self, path, options: dict, analysis: str) -> None:
        import pandas as pd

        path = Path(path)
        if not path.is_file():
            raise InputError("cases", str(path), "an existing .csv or .parquet file")
        suffix = path.suffix.lower()
        try:
            if suffix == ".csv":  # designations such as 6205 stay text
                frame = pd.read_csv(  # only an empty cell is missing: a typed nan is refused
                    path,
                    dtype={
                        k: str for k, o in options.items() if o.kind in ("text", "texts", "path")
                    },
                    keep_default_na=False,
                    na_values=[""],
                )
            elif suffix in (".parquet", ".pq"):
                frame = pd.read_parquet(path)
            else:
                raise InputError("cases", str(path), "a .csv or .parquet file")
        except InputError:
            raise
        except Exception as exc:  # noqa: BLE001 - any unreadable file: say why in one line
            raise InputError(
                "cases",
                str(path),
                "a readable .csv or .parquet table",
                " ".join(str(exc).split())[:200],
            ) from None
        if frame.empty:
            raise InputError(
                "cases", str(path), "a table with at least one case", "the table is empty"
            )
        for name in frame.columns:
            if name not in options:
                raise unknown_option(str(name), options, analysis)
        self.columns = [str(c) for c in frame.columns]
        records = []
        for i, row in enumerate(frame.to_dict(orient="records")):
            clean = {}
            for k, v in row.items():
                if v is None or (isinstance(v, float) and math.isnan(v)):
                    if options[k].default is not None and options[k].default is not ...:
                        raise InputError(
                            f"{k} (row {i + 1} of {path.name})",
                            "an empty cell",
                            f"a value: leave the column out for the default {options[k].default}",
                        )
                    clean[k] = None if options[k].default is ... else options[k].default
                else:
                    try:
                        clean[k] = _scalar(k, v.item() if hasattr(v, "item") else v, options[k])
                    except InputError as exc:
                        raise InputError(
                            f"{k} (row {i + 1} of {path.name})", exc.value, exc.allowed
                        ) from None
            records.append(clean)
        self.records = records
        self.count = len(records)
        self.digest = hashlib.sha256(path.read_bytes()).hexdigest()
        self.path = path

    def rows(self, start: int, stop: int) -> list[dict]:
        return [{"case": i, **self.records[i]} for i in range(start, stop)]

    def random_inputs(self, options: dict) -> tuple[str, ...]:
        """The seeded options (:class:`Option`) that are not 0 in some case."""
        return tuple(
            name
            for name, o in options.items()
            if o.seeded and any(r.get(name, o.default) for r in self.records)
        )

    def identity(self) -> dict:
        return {"cases_file": self.path.name, "cases_sha256": self.digest}


def partitions(count: int, size: int) -> list[tuple[int, int]]:
    """(start, stop) of each partition of ``count`` cases, ``size`` each (last shorter)."""
    return [(s, min(s + size, count)) for s in range(0, count, size)]


def default_partition_size(count: int, largest: int) -> int:
    """Cases per partition: at most ``largest`` (a few seconds of work), and small enough
    that a study has at least 32 partitions to spread; it depends on the case count only,
    so the partitioning (and so a resumed study) is the same on any cluster."""
    return max(1, min(largest, math.ceil(count / 32)))


def whole_number(name: str, value, minimum: int) -> int:
    """``value`` if it is an int (not a bool) >= ``minimum``, else InputError naming ``name``."""
    if isinstance(value, bool) or not isinstance(value, int) or value < minimum:
        raise InputError(name, value, f"a whole number >= {minimum}")
    return value


def partition_size_for(partition_size, count: int, largest: int) -> int:
    """``partition_size`` (a whole number >= 1), or :func:`default_partition_size` when None."""
    if partition_size is None:
        return default_partition_size(count, largest)
    return whole_number("partition_size", partition_size, 1)


def held_description(marker: Path) -> dict | None:
    """The description a study's or data set's marker file holds: None when there is no
    marker, {} when it cannot be read."""
    if not marker.exists():
        return None
    try:
        return json.loads(marker.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}


def canonical(obj) -> str:
    """Stable JSON text of a study's identity (sorted keys)."""
    return json.dumps(obj, sort_keys=True, default=str)


def check_writable(parameter: str, path, what: str = "a folder") -> Path:
    """Refuse a folder where no file can be written, before any work starts: a probe file
    is created (and removed) in ``path``, or, when ``path`` does not exist yet, in the
    nearest folder above it that does (where ``path`` would be made). The InputError
    names ``parameter``, ``path`` and the folder that refused. Returns that folder."""
    import os
    import tempfile

    path = Path(path)
    where = path.absolute()
    while not where.exists() and where != where.parent:
        where = where.parent
    if not where.is_dir():
        raise InputError(parameter, str(path), what, f"{where} is a file, not a folder")
    try:
        fd, probe = tempfile.mkstemp(dir=where, prefix=".bearinglab-probe-")
        os.close(fd)
        os.unlink(probe)
    except OSError as exc:
        raise InputError(
            parameter,
            str(path),
            f"{what} where files can be written",
            f"{where}: {exc.strerror or type(exc).__name__}",
        ) from None
    return where
