"""One record of a synthetic data set: :func:`make_record`, and its errors in the data
set's terms.

A record is the acceleration of bearinglab's dynamic model (:func:`bearinglab.dynamics.
simulate`, rigid or slip) with the record's defects and raceway waviness / ball-size
errors, passed through the transfer path (:mod:`.path`) and given white measurement noise;
its inputs are drawn by :func:`.sampling.draw_record` from the data set's seed and the
record's index alone. A model's error about a record names the data set's input that drew
the value, in that input's unit.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError
from . import layout
from .sampling import DatasetSpec, draw_record

#: A model's parameter -> (the data set's input that sets it, the factor from SI to that
#: input's unit, the unit's symbol in the model's words).
_RECORD_INPUTS = {
    "width": ("defect_width_mm", 1e3, "[m]", "[mm]"),
    "depth": ("defect_depth_mm", 1e3, "[m]", "[mm]"),
    "amplitude": ("waviness_amplitude_um", 1e6, "[m]", "[um]"),
    "order": ("waviness_orders", 1.0, "", ""),
    "sample_rate": ("sample_rate_hz", 1.0, "", ""),
    "duration": ("duration_s", 1.0, "", ""),
    "shaft_speed": ("speed_rpm", 30.0 / math.pi, "[rad/s]", "[rpm]"),
    "radial_load": ("radial_load_n", 1.0, "", ""),
    "designation": ("bearings", None, "", ""),
}


def _record_error(exc: InputError, r: dict, bearing=None) -> InputError:
    """A model's error about a record in the data set's terms: the input that drew the
    value (``defect_width_mm``, not ``width``) and the value in that input's unit (mm, as
    typed, not m)."""
    if exc.parameter in ("errors", "band"):  # ball-size errors: the band drawn
        limit = (
            f"at most {0.1 * bearing.element_diameter * 1e6:.4g} um (each element within "
            f"+-5 % of its diameter, {bearing.element_diameter * 1e3:g} mm)"
            if bearing is not None
            else exc.allowed.replace("[m]", "[um]")
        )
        return InputError("ball_size_error_um", r["ball_size_error_um"], f"a band {limit}")
    name, factor, si, unit = _RECORD_INPUTS.get(exc.parameter, (None, None, "", ""))
    if name is None:
        return exc
    value = exc.value
    if factor is not None and isinstance(value, (int, float)) and not isinstance(value, bool):
        value = float(f"{value * factor:.10g}")
    allowed = exc.allowed.replace(si, unit) if si else exc.allowed
    return InputError(name, value, allowed, exc.hint)


def make_record(
    spec: DatasetSpec, seed: int, index: int, check: bool = True
) -> tuple[np.ndarray, dict, tuple]:
    """(samples float32, record inputs, kinematic frequencies object) of record ``index``
    of the data set ``spec`` seeded ``seed`` (inputs from :func:`.sampling.draw_record`).

    With ``check``, a record that cannot show what its label says is refused (an
    InputError, which the set records as a failed record): a fault whose defect frequency
    is above the Nyquist frequency, or less than one cage revolution (not every ball has
    passed the load zone). Its errors name the data set's inputs, in their units.

    Parameters
    ----------
    spec : DatasetSpec
        The data set's specification (its ranges and choices).
    seed : int
        The data set's seed (>= 0).
    index : int
        The record's index in the set (>= 0); with ``seed`` alone it fixes the record.
    check : bool
        Refuse a record that cannot show what its label says (default True).

    Returns
    -------
    samples : numpy.ndarray
        The sensor signal, float32.
    record : dict
        The record's inputs, as drawn (engineering units).
    model : tuple
        (bearing, kinematic frequencies) of the record.
    """
    from ..study.bearings import bearing_of

    r = draw_record(spec, seed, index)
    bearing = None
    try:
        bearing = bearing_of(r["bearing"])
        return _make_record(r, bearing, check)
    except InputError as exc:
        raise _record_error(exc, r, bearing) from None


def _make_record(r: dict, bearing, check: bool) -> tuple[np.ndarray, dict, tuple]:
    """:func:`make_record` of the drawn inputs ``r`` (errors in the model's terms)."""
    from ..dynamics import Defect, simulate
    from ..imperfections import BallSizeErrors, Imperfections, Waviness
    from ..kinematics import defect_frequencies
    from ..operating import OperatingCondition
    from ..plausibility import LOCATION_FAMILY, sampling_warnings
    from .path import TransferPath

    z = bearing.element_count
    defects = [
        Defect(
            d["location"],
            d["width_mm"] * 1e-3,
            d["depth_mm"] * 1e-3,
            angle=math.radians(d["angle_deg"]),
            ball=r["ball_index"] % z if d["location"] == "ball" else 0,
        )
        for d in r["defects"]
    ]
    for d, spec_d in zip(defects, r["defects"], strict=True):
        if d.location == "ball":
            spec_d["ball"] = d.ball
    waves = (
        [
            Waviness(
                w["race"],
                w["order"],
                r["waviness_amplitude_um"] * 1e-6,
                math.radians(w["phase_deg"]),
            )
            for w in r["waviness"]
        ]
        if r["waviness_amplitude_um"] > 0
        else []
    )
    errors = (
        BallSizeErrors.random(z, r["ball_size_error_um"] * 1e-6, seed=r["seed"])
        if r["ball_size_error_um"] > 0
        else None
    )
    imperfections = Imperfections(waves, ball_size_errors=errors) if (waves or errors) else None
    condition = OperatingCondition(
        radial_load=r["radial_load_n"], shaft_speed=r["speed_rpm"] * math.pi / 30.0
    )
    fs = r["sample_rate_hz"]
    if check and condition.shaft_speed > 0:
        kin = defect_frequencies(bearing, condition.shaft_speed)
        sampling_warnings(kin, fs, None, [LOCATION_FAMILY[d.location] for d in defects])
        revolution = 1.0 / kin.hz("ftf")
        if r["duration_s"] < revolution:
            raise InputError(
                "duration_s",
                r["duration_s"],
                f"at least one cage revolution, {revolution:.4g} s",
                "every ball passes the load zone once in it",
            )
    sim = simulate(
        bearing,
        condition,
        defects,
        model=r["model"],
        duration=r["duration_s"],
        sample_rate=fs,
        imperfections=imperfections,
    )
    x = TransferPath(tuple(r["resonances"])).apply(sim.signal.channels["acc_y"], fs)
    if r["noise_ms2"] > 0:
        x = x + np.random.default_rng(r["seed"]).normal(0.0, r["noise_ms2"], x.size)
    return x.astype(layout.DTYPE), r, (bearing, sim.kinematic)
