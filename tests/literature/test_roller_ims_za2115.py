"""IMS/NASA prognostics data, Rexnord ZA-2115 (Qiu H., Lee J., Lin J., Yu G., J. Sound
Vib. 289 (2006) 1066-1090): 16 rollers of 0.331 in per row on a 2.815 in pitch circle,
contact angle 15.17 deg, at 2000 rpm: BPFO 236.4, BPFI 296.9, BSF 139.9, FTF 14.8 Hz as
printed. Through the roller-bearing model (catalogue row ``ZA-2115 (IMS)``).

Tolerances: issue 28 asks the unrounded values (the same formula, computed by hand:
gamma = 0.331 cos(15.17 deg)/2.815 = 0.113488) within 0.1 %; the printed ones within half
a unit of their last digit (0.05 Hz)."""

import math

import pytest

from bearinglab.catalog import bearing_from_designation
from bearinglab.kinematics import defect_frequencies

FR = 2000.0 / 60.0
GAMMA = 0.331 * math.cos(math.radians(15.17)) / 2.815
BY_HAND = {
    "bpfo": 8 * (1 - GAMMA) * FR,  # 236.40
    "bpfi": 8 * (1 + GAMMA) * FR,  # 296.93
    "bsf": 2.815 / (2 * 0.331) * (1 - GAMMA**2) * FR,  # 139.92
    "ftf": 0.5 * (1 - GAMMA) * FR,  # 14.775
}
PRINTED = {"bpfo": 236.4, "bpfi": 296.9, "bsf": 139.9, "ftf": 14.8}


@pytest.fixture(scope="module")
def freqs():
    bearing, _ = bearing_from_designation("ZA-2115 (IMS)", rollers=True)
    assert bearing.rolling_element == "roller" and bearing.rows == 2
    return defect_frequencies(bearing, speed_rpm=2000.0)


@pytest.mark.parametrize("name", sorted(BY_HAND))
def test_unrounded_frequencies_within_a_tenth_of_a_percent(freqs, name):
    assert freqs.hz(name) == pytest.approx(BY_HAND[name], rel=1e-3)


@pytest.mark.parametrize("name", sorted(PRINTED))
def test_printed_frequencies_within_their_rounding(freqs, name):
    assert freqs.hz(name) == pytest.approx(PRINTED[name], abs=0.05)


def test_the_hand_values_are_the_issues(freqs):
    assert [round(BY_HAND[k], 2) for k in ("bpfo", "bpfi", "bsf")] == [236.40, 296.93, 139.92]
    assert round(BY_HAND["ftf"], 3) == 14.775


def test_roller_names_in_the_json(freqs):
    d = freqs.to_dict()
    assert d["roller_count"] == 16 and d["roller_defect_hz"] == pytest.approx(2 * d["bsf_hz"])
    assert d["bpfo_order"] + d["bpfi_order"] == pytest.approx(16)
