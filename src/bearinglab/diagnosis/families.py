"""Fault families: which lines each bearing fault puts in the envelope spectrum, and how far
from their kinematic values they may lie.

Signatures (Randall R. B., Antoni J., "Rolling element bearing diagnostics - A tutorial",
MSSP 25(2) (2011) 485-520, sec. 2 and fig. 4):

- outer race: harmonics of BPFO; under a fixed load no modulation, but a rotating load,
  unbalance or misalignment modulate it at the shaft rate, and the CWRU outer-race records
  at 3 and 12 o'clock carry shaft-rate sidebands (issue 11's measurements): sidebands
  +-1, 2 x shaft - the load on the defect then follows the same load-zone function of the
  shaft angle as an inner-race defect's under a fixed load, which is not a sinusoid (the
  load zone spans less than a turn), hence the same two orders as the inner race
  (Randall & Antoni 2011, sec. 2 and fig. 4). Record 144 (3 o'clock) shows 1 and 2 x BPFO
  with +-2 x shaft sidebands (z 10-17 with cpw) and no +-1. The sidebands are tested as
  nested templates (harmonics alone first: :mod:`.series`), so an unmodulated
  series loses nothing by them;
- inner race: harmonics of BPFI with sidebands at the shaft rate, the defect passing
  through the load zone once per revolution (+-1, 2 x shaft);
- ball: harmonics of the ball-defect rate 2 BSF (the defect strikes both races per spin
  revolution) with sidebands at the cage rate, which carries the ball through the load
  zone (+-1, 2 x FTF);
- every modulated family also shows the modulation's own lines, k x shaft or k x FTF
  (k = 1, 2: the sidebands of the 0th harmonic, :mod:`.series`); the shaft
  harmonics are masked as the machine's, so this adds FTF lines to the ball family only,
  and never to the test of its harmonics (FTF lines alone make no ball fault);
- cage: harmonics of FTF. FTF lines are also the cage-rate modulation of a ball fault and
  appear beside outer-race faults (a series of unequal balls repeats once per cage
  revolution), so they make a cage fault only when no ball or outer-race series is found.

Tolerances (fraction of the kinematic value, below and above), each overridable:

- races, +-2 %: the rolling elements slip, so the measured lines "differ by 1-2 % from the
  calculated values" (Randall & Antoni 2011, sec. 2.1), and the speed given is itself
  known to about 1 %; at 2 % the 10th, 15th and 20th shaft harmonics of a 6205 sit just
  outside 2, 3 and 4 x BPFI (at 8 % they fell inside, issue 11);
- ball, -7 % / +2 %: the ball's spin depends on the contact angle and the ball slides
  more than it rolls off the load zone, so its lines run further below the kinematic
  value: seed 004 (Hou X. et al., J. Mech. & Electr. Eng. 2024 no. 2) measured the
  ball-defect line at 93.6 % of the kinematic 2 BSF (6.4 % below), and Randall &
  Antoni (2011, sec. 2.1) note that the ball lines are the least certain;
- cage, +-2 %: FTF = BPFO / Z slips as BPFO does.

The ball window never reaches into a race's window (:func:`families` cuts it at the
race window's edge): a line within 2 % of BPFO or BPFI is read as that race's, however
wide the ball's slip. This matters where 2 BSF lies near a race rate - in roller
bearings, whose rollers fill more of the pitch circle (NU205: 2 x the roller spin
152.8 Hz against BPFO 145.9 Hz at 1800 rpm, 4.5 % apart, so that the -7 % ball window
held every BPFO harmonic and a simulated outer-race defect was called "ball"); a 6205's
2 BSF lies 31 % above its BPFO, 13 % below its BPFI, and keeps its whole window.

The search window is never narrower than the line's own three bins
(:data:`bearinglab.diagnosis.series.LINE_BINS`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import InputError

#: Fault families, in the order they are reported when equally significant.
FAMILIES = ("outer_race", "inner_race", "ball", "cage")
#: Family -> name of its kinematic frequency (bearinglab.kinematics names).
FREQUENCY = {"outer_race": "bpfo", "inner_race": "bpfi", "ball": "ball_defect", "cage": "ftf"}
#: Family -> (modulating frequency name, sideband orders either side).
SIDEBANDS = {
    "outer_race": ("shaft", 2),
    "inner_race": ("shaft", 2),
    "ball": ("ftf", 2),
    "cage": (None, 0),
}
#: Default tolerance windows (below, above), fractions of the kinematic value.
TOLERANCES = {
    "outer_race": (0.02, 0.02),
    "inner_race": (0.02, 0.02),
    "ball": (0.07, 0.02),
    "cage": (0.02, 0.02),
}
#: Family -> deepest sideband order counted with its harmonics when asking whether the
#: series stands without its sidebands: the first sidebands where the load zone may
#: modulate the defect deeply, once per revolution of what carries it (inner race: shaft;
#: ball: cage; Randall & Antoni 2011, sec. 2 and fig. 4), so that the carriers may be
#: weaker than their sidebands - or not (the harmonics alone are tried too:
#: :mod:`.series`); and the first shaft sidebands of the outer race, whose defect,
#: away from the load line or under a rotating load, is loaded through the shaft-rate
#: modulation too (CWRU 247 at 3 o'clock: 1 and 2 x BPFO with BPFO - shaft, 2 BPFO - shaft
#: and BPFO + shaft beside them, its harmonics alone 10^-1.82 against the gate's 10^-2).
GATE_ORDERS = {"outer_race": 1, "inner_race": 1, "ball": 1, "cage": 0}
#: Families whose sidebands count in that test only beside a carrier that shows
#: (:data:`bearinglab.diagnosis.series.LINE_ALPHA`): the outer race, whose fixed
#: defect sees one transfer path, so that its envelope is the impact train times a load
#: that is never negative, whose sidebands are then never stronger than their carrier
#: (|c_k| <= c_0). Without this condition a healthy record's stray lines at
#: BPFO - 1, 2 x shaft, with no BPFO line, passed (the raw envelope of 97 in 3 of its 40
#: healthy segments and speeds). The inner race and the ball keep sidebands without
#: carriers: their defect moves through the load zone and past the sensor, and the
#: held-out CWRU channels show inner-race series whose carriers stay under the level.
GATE_CARRIERS = {"outer_race": True, "inner_race": False, "ball": False, "cage": False}
#: Keys accepted for a family in ``tolerances`` (JSON and CLI spellings too).
ALIASES = {
    "outer_race": "outer_race",
    "outer": "outer_race",
    "bpfo": "outer_race",
    "inner_race": "inner_race",
    "inner": "inner_race",
    "bpfi": "inner_race",
    "ball": "ball",
    "bsf": "ball",
    "ball_defect": "ball",
    # a roller bearing's rolling element is the same family (reported as "roller")
    "roller": "ball",
    "roller_defect": "ball",
    "cage": "cage",
    "ftf": "cage",
}
#: Highest harmonic order read per family (the search stops at the upper frequency too).
HARMONICS = 8


@dataclass(frozen=True)
class Family:
    """One fault family at a speed: ``name``, kinematic ``frequency`` [Hz], tolerance
    ``below`` / ``above`` [-], modulating frequency ``modulation`` [Hz] (or None),
    sideband ``orders``, and what its harmonic test counts: sidebands up to
    ``gate_orders``, only beside carriers that show if ``gate_carriers``."""

    name: str
    frequency: float
    below: float
    above: float
    modulation: float | None
    orders: int
    gate_orders: int = 0
    gate_carriers: bool = False

    @property
    def lowest(self) -> float:
        """Lowest frequency at which the family reads a line [Hz]: the fundamental at the
        bottom of its window, its deepest lower sideband where that stays above 0, or the
        modulation's own first line."""
        low = self.frequency * (1.0 - self.below)
        if not (self.modulation and self.orders):
            return low
        side = low - self.orders * self.modulation
        return min(side if side > 0 else low, self.modulation)

    def to_dict(self) -> dict:
        """JSON form: ``kinematic_hz``, ``tolerance_below``, ``tolerance_above``,
        ``modulation_hz``, ``sideband_orders``."""
        return {
            "kinematic_hz": self.frequency,
            "tolerance_below": self.below,
            "tolerance_above": self.above,
            "modulation_hz": self.modulation,
            "sideband_orders": self.orders,
        }


def tolerances(overrides=None) -> dict[str, tuple[float, float]]:
    """The tolerance windows with the user's ``overrides`` applied.

    ``overrides`` maps a family (``outer``, ``inner race``, ``bpfi``, ``ball``, ``cage``...)
    to a fraction (the same below and above) or to (below, above); each in [0, 0.3).

    >>> tolerances({"ball": 0.05})["ball"], tolerances()["outer_race"]
    ((0.05, 0.05), (0.02, 0.02))
    """
    out = dict(TOLERANCES)
    if overrides is None:
        return out
    if not isinstance(overrides, dict):
        raise InputError("tolerances", overrides, "a dict family -> fraction or (below, above)")
    for key, value in overrides.items():
        family = ALIASES.get(str(key).strip().lower())
        if family is None:
            raise InputError("tolerances", key, f"a family among {sorted(ALIASES)}")
        pair = value if isinstance(value, (tuple, list)) else (value, value)
        try:
            below, above = (float(v) for v in pair)
        except (TypeError, ValueError):
            below = above = math.nan
        if not (0.0 <= below < 0.3 and 0.0 <= above < 0.3):
            raise InputError(
                f"tolerances[{key!r}]",
                value,
                "a fraction in [0, 0.3) or (below, above) fractions in [0, 0.3)",
            )
        out[family] = (below, above)
    return out


def separated(frequencies, windows: dict[str, tuple[float, float]]) -> dict:
    """``windows`` with the ball's cut where it reaches a race's window (the same
    fractions at every harmonic): the lower edge of the ball's raised to the upper edge
    of a race window below it, the upper edge lowered to the lower edge of one above.

    >>> w = separated({"bpfo": 145.9, "bpfi": 214.1, "ball_defect": 152.8}, TOLERANCES)
    >>> round(w["ball"][0], 4), w["ball"][1], w["outer_race"]
    (0.0261, 0.02, (0.02, 0.02))
    """
    ball = float(frequencies[FREQUENCY["ball"]])
    below, above = windows["ball"]
    if not ball > 0:
        return dict(windows)
    for race in ("outer_race", "inner_race"):
        f = float(frequencies[FREQUENCY[race]])
        race_below, race_above = windows[race]
        top, bottom = f * (1.0 + race_above), f * (1.0 - race_below)
        if f <= ball and top > ball * (1.0 - below):
            below = max(0.0, min(below, 1.0 - top / ball))
        elif f > ball and bottom < ball * (1.0 + above):
            above = max(0.0, min(above, bottom / ball - 1.0))
    out = dict(windows)
    out["ball"] = (below, above)
    return out


def families(
    frequencies, windows: dict[str, tuple[float, float]], modulations=None
) -> list[Family]:
    """The four families for ``frequencies`` (name -> Hz, with ``shaft``); their sidebands
    are spaced by ``modulations`` (``shaft``, ``ftf`` -> Hz: the rates the signal shows)
    where given, else by ``frequencies``."""
    rates = modulations or frequencies
    windows = separated(frequencies, windows)
    out = []
    for name in FAMILIES:
        modulation, orders = SIDEBANDS[name]
        below, above = windows[name]
        out.append(
            Family(
                name,
                float(frequencies[FREQUENCY[name]]),
                below,
                above,
                None if modulation is None else float(rates[modulation]),
                orders,
                GATE_ORDERS[name],
                GATE_CARRIERS[name],
            )
        )
    return out
