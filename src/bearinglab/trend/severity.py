"""Vibration severity zones A-D of the r.m.s. velocity (layer 1 data and a lookup).

ISO 20816-1:2016 ([ISO20816-1]) defines the four evaluation zones of broad-band r.m.s.
vibration velocity on non-rotating parts: A, newly commissioned machines; B, acceptable
for unrestricted long-term operation; C, not acceptable for long-term continuous
operation; D, severe enough to cause damage. The boundary values depend on the machine:

- ISO 20816-3:2022 ([ISO20816-3], Annex A, Tables A.1 and A.2; the same values as
  ISO 10816-3:2009): industrial machines above 15 kW running at 120-30 000 r/min,
  group 1 (300 kW to 50 MW; electrical machines of shaft height 315 mm and above) and
  group 2 (15 kW to 300 kW; shaft height 160-315 mm), each on rigid or flexible supports;
  band 10-1000 Hz above 600 r/min.
- ISO 10816-1:1995 ([ISO10816-1], Annex B, Table B.1, typical values, which ISO 20816-1
  replaced): machine classes I (small machines, up to about 15 kW) to IV (large machines
  on soft foundations).

The standards' texts were not available to the project; the values are those the
standards' tables are reprinted with throughout the condition-monitoring literature.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputError

ZONES = ("A", "B", "C", "D")


@dataclass(frozen=True)
class ZoneBoundaries:
    """The A/B, B/C and C/D boundaries [m/s] of a machine group, and their ``source``."""

    machine: str
    a_b: float
    b_c: float
    c_d: float
    source: str

    def to_dict(self) -> dict:
        return {
            "machine": self.machine,
            "boundaries_mm_s": {
                "a_b": self.a_b * 1e3,
                "b_c": self.b_c * 1e3,
                "c_d": self.c_d * 1e3,
            },
            "source": self.source,
        }


def _zones(machine: str, values_mm_s: tuple[float, float, float], source: str) -> ZoneBoundaries:
    return ZoneBoundaries(machine, *(v * 1e-3 for v in values_mm_s), source)


_ISO20816_3 = "ISO 20816-3:2022 Annex A Table A.{} ({}, {} support)"
_ISO10816_1 = "ISO 10816-1:1995 Annex B Table B.1 (class {})"
#: Machine group -> its zone boundaries.
MACHINES: dict[str, ZoneBoundaries] = {
    m.machine: m
    for m in (
        _zones("group1-rigid", (2.3, 4.5, 7.1), _ISO20816_3.format(1, "group 1", "rigid")),
        _zones("group1-flexible", (3.5, 7.1, 11.0), _ISO20816_3.format(1, "group 1", "flexible")),
        _zones("group2-rigid", (1.4, 2.8, 4.5), _ISO20816_3.format(2, "group 2", "rigid")),
        _zones("group2-flexible", (2.3, 4.5, 7.1), _ISO20816_3.format(2, "group 2", "flexible")),
        _zones("class1", (0.71, 1.8, 4.5), _ISO10816_1.format("I")),
        _zones("class2", (1.12, 2.8, 7.1), _ISO10816_1.format("II")),
        _zones("class3", (1.8, 4.5, 11.2), _ISO10816_1.format("III")),
        _zones("class4", (2.8, 7.1, 18.0), _ISO10816_1.format("IV")),
    )
}


def machine_zones(machine: str) -> ZoneBoundaries:
    """The zone boundaries of ``machine`` (InputError naming the groups there are)."""
    key = str(machine).strip().lower().replace("_", "-").replace(" ", "-")
    if key not in MACHINES:
        raise InputError("machine", machine, f"one of {', '.join(MACHINES)}")
    return MACHINES[key]


def zones_of(velocity, boundaries: ZoneBoundaries) -> np.ndarray:
    """The zone (A, B, C or D) of each r.m.s. velocity [m/s]; a value on a boundary is in
    the zone above it.

    >>> zones_of(np.array([1.0e-3, 1.4e-3, 3.0e-3, 9.0e-3]), MACHINES["group2-rigid"]).tolist()
    ['A', 'B', 'C', 'D']
    """
    v = np.asarray(velocity, dtype=float)
    edges = np.array([boundaries.a_b, boundaries.b_c, boundaries.c_d])
    return np.asarray(ZONES)[np.searchsorted(edges, v, side="right")]
