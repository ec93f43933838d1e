"""The faces of a simulation (issue 12): Simulation and SimulatedRecord with to_dict,
to_pandas and plot, and simulate_record refusing a record that cannot show its defect."""

import json
import math

import pytest

from bearinglab.catalog import bearing_from_designation
from bearinglab.dynamics import Defect
from bearinglab.dynamics.record import simulate_record
from bearinglab.errors import InputError
from bearinglab.operating import OperatingCondition

B, _ = bearing_from_designation("6205")
C = OperatingCondition(radial_load=500.0, shaft_speed=1797 * math.pi / 30)
OUTER = [Defect("outer", width=1.0e-3, depth=0.2e-3)]
INNER = [Defect("inner", width=1.0e-3, depth=0.2e-3)]


@pytest.fixture(scope="module")
def record():
    return simulate_record(B, C, INNER, duration=0.5, sample_rate=12e3)


def test_record_dict_is_json_and_names_the_fault(record):
    d = json.loads(json.dumps(record.to_dict()))
    assert d["likely_fault"] == "inner_race" and d["diagnosis"]["likely_fault"] == "inner_race"
    assert d["speed_rpm"] == pytest.approx(1797) and d["sample_rate_hz"] == 12e3
    assert d["spectrum"]["channel"] == "disp_y" and d["spectrum"]["peaks"]
    assert d["parameters"] and d["defects"][0]["location"] == "inner"


def test_simulation_table_and_plots(record):
    table = record.to_pandas()
    sim = record.simulation
    assert list(table.columns)[:1] == ["time_s"] and len(table) == sim.signal.n_samples
    assert set(sim.signal.names) <= set(table.columns)
    assert table["time_s"].iloc[0] == pytest.approx(sim.stats["settle_s"])
    fig, axes = sim.plot()
    assert len(axes) == 2 and axes[0].get_ylabel().startswith("acc_y")
    fig, axes = record.plot()
    assert len(axes) == 2
    import matplotlib.pyplot as plt

    plt.close("all")


def test_a_record_that_cannot_show_its_defect_is_refused():
    with pytest.raises(InputError) as err:
        simulate_record(B, C, OUTER, duration=1.0, sample_rate=150.0)
    assert err.value.parameter == "sample_rate"
    with pytest.raises(InputError) as err:
        simulate_record(B, C, OUTER, duration=0.1, sample_rate=12e3, spectrum_channel="x")
    assert err.value.parameter == "spectrum_channel"
