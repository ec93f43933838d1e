"""Seed 003 part 4: noise of a C&U 608 bearing with raceway waviness and ball-size
errors (Zhang, Yang & An, Front. Mech. Eng. 4:13, 2018, as compiled in seed 003).

Published: at 720 rpm and 0.05 kN, waviness number 7, the mean SPL at point A is
29.832 dB (fig. 14; measurements quoted by the paper: 27.8 and 29.4 dB). The paper's
Table 1 (bearing parameters) and its waviness amplitude are not in the seed; the values
used are chosen, not fitted (docs/capabilities/noise.md): the catalogue's estimated 608
geometry, order-7 waviness of 0.2 um on both raceways, ball-size errors uniform in a
2 um band (seed 1), point A 10 mm above the centre (given explicitly: the library's
default point lies outside the bearing, and the 608's outer ring has a radius of 11 mm);
the "mean SPL" is ``spl_time_mean_db``, the time average of the SPL-time curve, as in the
paper's figs. 14-20 (not the L_eq of eq. 27 over the record, ``spl_leq_db``).
tests/literature/test_seed003_noise.py checks the trends with :func:`mean_spl`.
"""

from __future__ import annotations

import functools

from .case import Case

PUBLISHED_MEAN_SPL_DB = 29.832  # fig. 14
BASE = {"rpm": 720.0, "load": 50.0, "amplitude": 0.2e-6, "order": 7, "band": 2e-6}
POINTS = 1024  # one cage revolution (0.224 s): ~4.6 kHz


@functools.cache
def _noise(rpm, load, amplitude, order, band):
    from ..catalog import bearing_from_designation
    from ..imperfections import BallSizeErrors, Imperfections, Waviness
    from ..noise import SEED003_POINT_A, bearing_noise
    from ..operating import OperatingCondition
    from ..units import rpm_to_rad_s

    bearing, _ = bearing_from_designation("608")
    imperfections = Imperfections(
        [Waviness("inner", order, amplitude), Waviness("outer", order, amplitude)],
        ball_size_errors=BallSizeErrors.random(bearing.ball_count, band, seed=1),
    )
    condition = OperatingCondition(radial_load=load, shaft_speed=rpm_to_rad_s(rpm))
    return bearing_noise(bearing, condition, imperfections, points=POINTS, point=SEED003_POINT_A)


def mean_spl(**change) -> float:
    """Mean SPL at point A [dB] (the time mean of SPL(t)) for the base case with ``change``
    (keys of :data:`BASE`)."""
    return _noise(**(BASE | change)).to_dict()["spl_time_mean_db"]


CASES = [
    Case(
        "seed 003 (C&U 608, fig. 14)",
        "mean SPL at point A, 720 rpm, 0.05 kN, waviness 7",
        PUBLISHED_MEAN_SPL_DB,
        "dB",
        mean_spl,
        0.10,
        "3 dB: the paper's value and the two measurements it quotes span 2 dB",
        known_failure=(
            "not reproduced with the chosen, unfitted waviness amplitude: about 11 dB. The "
            "paper does not print its amplitude; the pressure is proportional to it (+6 dB "
            "per doubling), so about 2 um would be needed, ten times the 0.2 um chosen"
        ),
    ),
]
