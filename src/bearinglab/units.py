"""Units at the edges: SI inside, engineering units on the command line and in JSON.

One table (:data:`UNITS`) says what each unit suffix means: the suffix that ends a JSON
key or a command-line flag (``speed_rpm``, ``--radial-load-n``), the symbol printed in
table headers (``rpm``, ``N``, ``µm``) and the SI value of one unit. The command line
converts option values with it, the error messages and table headers print its symbols,
and ``docs/json.md`` (checked by ``tests/unit/test_json_contract.py``) lists it as the
JSON contract: every key of every ``--json`` either ends in one of these suffixes or is
one of the dimensionless keys of :data:`bearinglab.json_keys.DIMENSIONLESS` (the keys
without a unit, and :data:`~bearinglab.json_keys.MAPS`, live there; this module writes the
contract's page, :func:`contract_markdown`).

>>> rpm_to_rad_s(30.0) == math.pi
True
>>> UNITS["n_per_um"].to_si(100.0)
100000000.0
>>> label("stiffness", "n_per_um")
'stiffness [N/µm]'
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .json_keys import DIMENSIONLESS

#: Angular speed of one revolution per minute [rad/s].
RPM = math.pi / 30.0


def rpm_to_rad_s(speed_rpm: float) -> float:
    """A speed in rpm as an angular speed [rad/s].

    Parameters
    ----------
    speed_rpm : float
        Speed [rpm].

    Returns
    -------
    float
        The same speed [rad/s].
    """
    return speed_rpm * RPM


def rad_s_to_rpm(speed: float) -> float:
    """An angular speed [rad/s] in rpm.

    Parameters
    ----------
    speed : float
        Angular speed [rad/s].

    Returns
    -------
    float
        The same speed [rpm].
    """
    return speed / RPM


def rad_s_to_hz(speed: float) -> float:
    """An angular speed [rad/s] as a frequency of revolution [Hz]."""
    return speed / (2.0 * math.pi)


@dataclass(frozen=True)
class Unit:
    """One engineering unit: key suffix, printed symbol, SI value of one unit, meaning."""

    suffix: str
    symbol: str
    factor: float
    quantity: str

    def to_si(self, value: float) -> float:
        """``value`` in this unit, in SI."""
        return value * self.factor

    def from_si(self, value: float) -> float:
        """An SI ``value`` in this unit."""
        return value / self.factor


def _units(*rows: tuple[str, str, float, str]) -> dict[str, Unit]:
    return {row[0]: Unit(*row) for row in rows}


#: suffix -> Unit. Suffixes are matched longest first, so ``n_per_um`` is not ``um``.
UNITS: dict[str, Unit] = _units(
    ("m", "m", 1.0, "length"),
    ("mm", "mm", 1e-3, "length"),
    ("um", "µm", 1e-6, "length"),
    ("nm", "nm", 1e-9, "length"),
    ("mm2", "mm²", 1e-6, "area"),
    ("mm4", "mm⁴", 1e-12, "second moment of area"),
    ("mrad", "mrad", 1e-3, "angle"),
    ("deg", "deg", math.pi / 180.0, "angle"),
    ("rad", "rad", 1.0, "angle"),
    ("n", "N", 1.0, "force"),
    ("kn", "kN", 1e3, "force"),
    ("n_m", "N·m", 1.0, "moment, torque"),
    ("n_mm", "N·mm", 1e-3, "moment, torque"),
    ("n_per_um", "N/µm", 1e6, "stiffness"),
    ("n_per_m", "N/m", 1.0, "stiffness"),
    ("n_m_per_rad", "N·m/rad", 1.0, "tilt stiffness"),
    ("n_per_m1_5", "N/m^1.5", 1.0, "Hertz load-deflection constant"),
    ("n_per_um1_5", "N/µm^1.5", 1e9, "Hertz load-deflection constant"),
    ("n_s_per_m", "N·s/m", 1.0, "damping"),
    ("pa", "Pa", 1.0, "pressure, stress"),
    ("upa", "µPa", 1e-6, "sound pressure"),
    ("mpa", "MPa", 1e6, "pressure, stress"),
    ("gpa", "GPa", 1e9, "pressure, stress, modulus"),
    ("kg", "kg", 1.0, "mass"),
    ("g", "g", 1e-3, "mass"),
    ("kg_m3", "kg/m³", 1.0, "density"),
    ("kg_m", "kg·m", 1.0, "unbalance"),
    ("g_mm", "g·mm", 1e-6, "unbalance"),
    ("s", "s", 1.0, "time"),
    ("ms", "ms", 1e-3, "time"),
    ("hours", "h", 3600.0, "time (life)"),
    ("million_rev", "10⁶ rev", 1e6, "life in revolutions"),
    ("hz", "Hz", 1.0, "frequency"),
    ("per_s", "1/s", 1.0, "rate (items per second)"),
    ("per_hour", "1/h", 1.0 / 3600.0, "rate (events per hour)"),
    ("khz", "kHz", 1e3, "frequency"),
    ("rpm", "rpm", RPM, "speed (to rad/s)"),
    ("rad_s", "rad/s", 1.0, "angular speed"),
    ("m_s", "m/s", 1.0, "velocity"),
    ("um_s", "µm/s", 1e-6, "velocity"),
    ("mm_s", "mm/s", 1e-3, "velocity"),
    ("m_s2", "m/s²", 1.0, "acceleration"),
    ("w", "W", 1.0, "power"),
    ("mm2_s", "mm²/s", 1e-6, "kinematic viscosity"),
    ("c", "°C", 1.0, "temperature (not converted: degrees Celsius)"),
    ("db", "dB", 1.0, "level (sound pressure re 20 µPa)"),
    ("pct", "%", 0.01, "percentage"),
    ("percent", "%", 0.01, "percentage"),
    ("si", "SI", 1.0, "a matrix in SI units, its rows' units under <key>_units"),
)

#: The units a ``--json`` key may end in (docs/json.md, "One unit per quantity"): suffix ->
#: what it is used for. The others of :data:`UNITS` (``m``, ``n_m``, ``n_per_m``, ``pa``,
#: ``kn``, ...) are for command-line options and SI matrices only; a JSON key in one of them
#: must be in :data:`JSON_EXCEPTIONS`.
JSON_SUFFIXES: dict[str, str] = {
    "hz": "frequencies",
    "rpm": "speeds of rotation",
    "n": "loads and forces",
    "mm": "dimensions",
    "um": "clearances, displacements, film thickness, form errors",
    "mm2": "cross-section areas",
    "mm4": "second moments of area",
    "deg": "angles",
    "mrad": "small tilts and misalignments",
    "n_per_um": "stiffness",
    "n_per_um1_5": "Hertz load-deflection constants (Q [N] = K delta[µm]^1.5)",
    "n_s_per_m": "damping",
    "n_mm": "moments and torques",
    "gpa": "contact pressures, stresses and moduli",
    "upa": "sound pressures (levels in dB re 20 µPa)",
    "db": "sound pressure levels re 20 µPa",
    "s": "times",
    "hours": "lives in hours",
    "million_rev": "lives in revolutions",
    "per_s": "rates",
    "per_hour": "rates of events per hour of monitoring (false alarms)",
    "g": "masses of balls and rings",
    "kg": "masses of the machine in a simulation (rotor, housing) and of a ring",
    "kg_m3": "densities",
    "g_mm": "unbalance (ISO 21940)",
    "m_s": "sliding and sound speeds",
    "mm_s": "vibration velocity of a machine (ISO 20816)",
    "um_s": "vibration velocity of a bearing (ISO 15242 bands)",
    "m_s2": "accelerations",
    "mm2_s": "kinematic viscosity",
    "c": "temperatures",
    "w": "power",
    "percent": "percentages",
    "si": "matrices in mixed SI units, with their rows' units beside them",
}
#: JSON keys allowed a unit outside :data:`JSON_SUFFIXES`: key -> the reason.
JSON_EXCEPTIONS: dict[str, str] = {}


def unit_of(key: str) -> Unit | None:
    """The unit a JSON key or flag ends in (longest suffix first), or None.

    >>> unit_of("stiffness_n_per_um").symbol
    'N/µm'
    >>> unit_of("ball_count") is None
    True
    """
    name = key.lstrip("-").replace("-", "_").lower()
    for suffix in sorted(UNITS, key=len, reverse=True):
        if name.endswith("_" + suffix):
            return UNITS[suffix]
    return None


def label(text: str, suffix: str) -> str:
    """A table header: ``text [symbol]`` of the unit with that suffix."""
    return f"{text} [{UNITS[suffix].symbol}]"


_CONTRACT_PROSE = """# The JSON contract

Every command takes `--json` and then prints one JSON object on stdout and nothing else
(warnings go into its `warnings` list; progress bars go to stderr and only on a terminal).
This page is the contract those objects keep; `tests/unit/test_json_contract.py` runs every
command and checks its output against it, and checks that this page lists every unit and
every dimensionless key that `bearinglab/units.py` knows. The page is generated from that
module: `python -m bearinglab.units > docs/json.md`.

## Rules

- **Every key carries its unit** as a suffix from the table below (`speed_rpm`,
  `radial_load_n`, `stiffness_n_per_um`), or is one of the dimensionless keys listed
  further down (names, counts, ratios, flags, labels). Suffixes are matched longest first:
  `_n_per_um` is a stiffness, `_n_m` a moment in newton metres and `_nm` nanometres.
- **One unit per quantity across commands.** Frequencies are in Hz (`_hz`), speeds in rpm,
  loads in N, lengths in mm (dimensions) or µm (clearances, displacements, film, form
  errors), stiffness in N/µm (Hertz constants in N/µm^1.5), moments and torques in N·mm,
  pressures and stresses in GPa, sound pressures in µPa and their levels in dB re 20 µPa,
  times in s. The units table says which suffixes a JSON key may end in (column "JSON");
  the others (`_m`, `_n_m`, `_n_per_m`, `_pa`, `_kn`, ...) are for command-line options
  only, and a JSON key in one of them is listed under "Exceptions" with its reason.
- **Members of a unit-suffixed container** carry that unit: `velocity_bands_um_s.low`.
  Members of a map (`geometry_sources`, `scores`, `sources`, `families`, `confusion`, ...)
  are named by data (a fault family, a channel, a label), but the keys inside a member keep
  the contract: `families.outer_race.tolerance_below`.
- A matrix in mixed SI units ends in `_si` and has a sibling `<key>_units` that gives the
  unit of each row (e.g. `stiffness_matrix_si`, `stiffness_matrix_units`).
- Numbers are finite: a command never prints NaN or infinity (it fails with one line instead);
  a value that does not apply is `null`.
- **Fault families** are spelled `outer_race`, `inner_race`, `ball` and `cage` everywhere
  (keys of `scores` and `families`, the members of `faults`, `primary_fault`); `likely_fault`
  is one of them, `"compound: a + b"` for several, or `null` for "no fault detected".
"""


def contract_markdown() -> str:
    """docs/json.md: the rules, the unit table and the dimensionless keys."""
    lines = [
        _CONTRACT_PROSE.rstrip(),
        "",
        "## Units",
        "",
        "| suffix | symbol | SI value of one unit | quantity | JSON |",
        "|---|---|---|---|---|",
    ]
    for u in sorted(UNITS.values(), key=lambda u: (u.quantity, u.suffix)):
        use = JSON_SUFFIXES.get(u.suffix, "no (options only)")
        lines.append(f"| `_{u.suffix}` | {u.symbol} | {u.factor:g} | {u.quantity} | {use} |")
    if JSON_EXCEPTIONS:
        lines += ["", "## Exceptions", "", "| key | why its unit is not the rule's |", "|---|---|"]
        lines += [f"| `{k}` | {JSON_EXCEPTIONS[k]} |" for k in sorted(JSON_EXCEPTIONS)]
    lines += ["", "## Dimensionless keys", "", "| key | what it holds |", "|---|---|"]
    lines += [f"| `{k}` | {DIMENSIONLESS[k]} |" for k in sorted(DIMENSIONLESS)]
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    print(contract_markdown(), end="")
