"""Seed 003 part 4 (Zhang, Yang & An, Front. Mech. Eng. 4:13, 2018): noise of a C&U 608
deep-groove ball bearing with raceway waviness and ball-size errors (DRAFT).

Published (seed file lines 839-881): at 720 rpm and a radial load of 0.05 kN, waviness
number 7, the mean SPL at point A (10 mm from the centre) is 29.832 dB (fig. 14; two
measurements of the same kind of bearing quoted from the literature: 27.8 and 29.4 dB);
the SPL rises with the waviness amplitude (fig. 17, "roughly linear"), the speed (fig.
18), the load (fig. 19) and the ball-size error band 1-3 um (fig. 20); it changes
irregularly, without a clear trend, with the waviness number 5-9 (figs. 15-16).

The published level itself is a case in bearinglab.validation.seed003_noise (a known
failure there, with the reason). The paper's Table 1 (bearing parameters) and its
waviness amplitude are not in the seed text; the values used here are chosen, not
fitted, in docs/capabilities/noise.md:
608 geometry from the catalogue estimate (Z = 7, D_w = 3.85 mm, d_m = 15 mm, P_d =
7.5 um), waviness of order 7 and amplitude 0.2 um on both raceways (phase 0), ball-size
errors uniform in a 2 um band (seed 1), point A straight above the centre (10 mm from
it, given explicitly: the library's default point lies outside the bearing). The "mean
SPL" is ``spl_time_mean_db``, the time average of the SPL-time curve
(:meth:`SoundPressure.spl_time`), as in the paper's figures 14-20.
"""

from __future__ import annotations

import itertools

import pytest

from bearinglab.validation.seed003_noise import PUBLISHED_MEAN_SPL_DB
from bearinglab.validation.seed003_noise import mean_spl as _mean_spl


def _rises(levels) -> bool:
    return all(b > a for a, b in itertools.pairwise(levels))


def test_608_mean_spl_is_finite_and_below_the_published_level():
    """Records what the chosen parameters give (about 11 dB), so a change shows."""
    assert 5.0 < _mean_spl() < PUBLISHED_MEAN_SPL_DB


def test_spl_grows_with_waviness_amplitude_and_pressure_roughly_linearly():
    """Fig. 17 (and seed 002: pressure roughly linear in the waviness): the level rises and
    the pressure nearly doubles when the amplitude doubles (ball-size errors add a part
    that does not scale)."""
    levels = [_mean_spl(amplitude=a) for a in (0.1e-6, 0.2e-6, 0.4e-6)]
    assert _rises(levels), levels
    for lo, hi in itertools.pairwise(levels):
        assert 1.6 < 10 ** ((hi - lo) / 20) < 2.2, levels


def test_spl_grows_with_speed():
    levels = [_mean_spl(rpm=r) for r in (360.0, 720.0, 1440.0)]  # fig. 18
    assert _rises(levels), levels


def test_spl_grows_with_load():
    levels = [_mean_spl(load=f) for f in (25.0, 50.0, 100.0, 200.0)]  # fig. 19
    assert _rises(levels), levels


def test_spl_grows_with_ball_size_error_band():
    levels = [_mean_spl(band=b) for b in (1e-6, 2e-6, 3e-6)]  # fig. 20
    assert _rises(levels), levels


def test_spl_changes_irregularly_with_waviness_number():
    """Figs. 15-16: no monotonic trend over waviness numbers 5-9."""
    levels = [_mean_spl(order=q) for q in range(5, 10)]
    assert not _rises(levels) and not _rises(levels[::-1]), levels


@pytest.mark.xfail(
    strict=True,
    reason=(
        "not reproduced: here the level climbs by about 12 dB from q = 5 to q = 8 (with Z = 7 "
        "the radial excitation is strongest for q near Z +- 1 and Z), the paper's fig. 16 "
        "shows no obvious change"
    ),
)
def test_spl_hardly_changes_with_waviness_number():
    levels = [_mean_spl(order=q) for q in range(5, 10)]
    assert max(levels) - min(levels) < 3.0, levels
