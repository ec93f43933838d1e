"""The pressure along a roller on the elastic half-space (contact/line_pressure.py) and one
roller's contacts (contact/roller_race.py): checked against Hertz's point contact (a fully
crowned roller makes one), the slice model, and the edge stress it exists to show."""

import numpy as np
import pytest

from bearinglab.contact.hertz import point_contact
from bearinglab.contact.line import crowned_profile, logarithmic_profile
from bearinglab.contact.line_pressure import line_contact_pressure, rectangle_influence
from bearinglab.contact.roller_race import roller_contacts
from bearinglab.errors import InputError
from bearinglab.roller_geometry import RollerBearing, RollerProfile

E_PRIME = 2.286e11
R, L = 4.2e-3, 9.6e-3


def test_influence_of_a_square_at_its_centre_and_far_away():
    assert float(rectangle_influence(0.0, 0.0, -1.0, 1.0, -1.0, 1.0)) == pytest.approx(
        8 * np.arcsinh(1.0)
    )
    # far from a small cell, 1/r times its area
    far = float(rectangle_influence(100.0, 0.0, -0.5, 0.5, -0.5, 0.5))
    assert far == pytest.approx(1.0 / 100.0, rel=1e-4)


def test_a_crowned_roller_is_a_hertz_point_contact():
    """A full crown of radius R_c turns the line contact into an elliptical one with radii
    (R, R_c): the half-space solution on its coarse default mesh reaches Hertz's p_max and
    approach within 3.5 % (2048 against 2109 MPa; 0.6 % on a 80 x 25 mesh)."""
    hertz = point_contact(500.0, R, 0.05, E_PRIME)
    r = line_contact_pressure(500.0, L, R, E_PRIME, drop=lambda x: crowned_profile(x, 0.05))
    assert r.max_pressure == pytest.approx(float(hertz.max_pressure), rel=0.035)
    assert r.approach == pytest.approx(float(hertz.approach), rel=0.02)
    # the loaded cells' centres lie within the ellipse's semi-major axis
    assert np.max(np.abs(r.x[r.along > 0])) < float(hertz.semi_major)


def test_the_load_is_carried():
    r = line_contact_pressure(3000.0, L, R, E_PRIME)
    areas = np.outer(np.diff(-0.5 * L * np.cos(np.linspace(0, np.pi, 41))), np.diff(r.y)[:1])
    assert float(np.sum(r.pressure * areas)) == pytest.approx(3000.0, rel=1e-9)


def test_an_unprofiled_roller_has_an_edge_stress_a_logarithmic_one_none():
    flat = line_contact_pressure(5000.0, L, R, E_PRIME)
    assert flat.edge_ratio > 2 and np.argmax(flat.along) in (0, len(flat.along) - 1)
    # its middle stays near Hertz's 2-D value (the ends carry the rest)
    assert flat.middle_pressure == pytest.approx(flat.hertz_pressure, rel=0.1)
    log = line_contact_pressure(
        5000.0, L, R, E_PRIME, drop=lambda x: logarithmic_profile(x, 10e-3, L), tilt=1e-3
    )
    assert log.edge_ratio == 0.0 and log.max_pressure < 1.3 * log.hertz_pressure


def test_the_edge_stress_grows_with_the_mesh_at_a_sharp_edge():
    coarse = line_contact_pressure(5000.0, L, R, E_PRIME, axial_cells=20)
    fine = line_contact_pressure(5000.0, L, R, E_PRIME, axial_cells=40)
    assert fine.edge_ratio > 1.5 * coarse.edge_ratio  # singular: a mesh's value


def test_roller_contacts_report_both_races_and_the_slice_model():
    b = RollerBearing(roller_count=14, roller_diameter=10e-3, roller_length=L, pitch_diameter=65e-3)
    r = roller_contacts(b, 5000.0, tilt=1e-3)
    d = r.to_dict()
    assert d["roller_load_n"] == 5000.0 and d["rolling_element"] == "roller"
    # the inner contact (smaller radius) presses harder
    assert d["inner"]["max_pressure_gpa"] > d["outer"]["max_pressure_gpa"]
    # the half-space and the slices agree on the peak within 10 % for a profiled roller
    assert d["inner"]["max_pressure_gpa"] == pytest.approx(
        d["inner"]["slice_max_pressure_gpa"], rel=0.1
    )
    assert sum(d["slice_loads_n"]) == pytest.approx(5000.0)
    assert d["roller_approach_um"] == pytest.approx(d["palmgren_approach_um"], rel=0.2)
    flat = roller_contacts(
        RollerBearing(
            roller_count=14,
            roller_diameter=10e-3,
            roller_length=L,
            pitch_diameter=65e-3,
            profile=RollerProfile("flat"),
        ),
        40e3,
    )
    words = " ".join(flat.warnings)
    assert "4000 MPa" in words and "edge stress" in words
    with pytest.raises(InputError):
        roller_contacts(b, -1.0)
