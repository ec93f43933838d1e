"""The input table: every input a user gives, declared once.

An :class:`Input` is one value of a request in engineering units: its public name (the
command-line flag with dashes, the JSON key and the study column with underscores), its
kind, default, range in its unit (the unit is the name's suffix, :mod:`bearinglab.units`),
help and the model field it sets. The command line generates its options from it, the
studies their columns, and :meth:`Input.check` is the one range check for both; errors
name the input by its public name (the command line words them as flags). A request read
against the table (:func:`~.values.check`, :func:`~.values.closed`, :func:`~.values.si`,
:func:`~.values.restate`) is in :mod:`.values`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from ..errors import InputError

#: What a value of each kind must be (the "expected ..." of an error).
KINDS = {
    "number": "a number",
    "integer": "a whole number",
    "text": "a text",
    "texts": "texts",
    "bool": "true or false",
    "path": "a file name",
}


@dataclass(frozen=True)
class Input:
    """One input: ``kind`` (number, integer, text, texts - repeatable -, bool or path),
    ``default`` (None: not used unless given), ``help``, allowed ``choices``, the range
    [``low``, ``high``] in the input's unit (open at an end with ``low_open`` /
    ``high_open``), ``sets`` (the model field it sets, for the docs) and ``seeded``: a
    value other than 0 is drawn afresh for each study case from the case seed (random
    ball-size errors, measurement noise)."""

    kind: str
    default: object
    help: str
    choices: tuple = ()
    seeded: bool = False
    low: float | None = None
    high: float | None = None
    low_open: bool = False
    high_open: bool = False
    sets: str | tuple = ""
    what: str = ""
    aliases: tuple = ()

    def with_(self, **changes) -> Input:
        """This input with another default or help (one analysis' reading of it)."""
        return replace(self, **changes)

    @property
    def fields(self) -> tuple[str, ...]:
        """The model parameters this input sets (``sets``: "Model.field" or "field", one or
        several), by their names: a model error about one of them is about this input."""
        sets = (self.sets,) if isinstance(self.sets, str) else self.sets
        return tuple(s.rpartition(".")[2] for s in sets if s)

    def allowed(self, unit: str = "") -> str:
        """The allowed range (or choices) in words, in the input's ``unit`` (its symbol).

        Parameters
        ----------
        unit : str
            The unit symbol to write after the bounds (e.g. "mm"); empty: none.
        """
        if self.choices:
            return "one of " + ", ".join(map(str, self.choices))
        if self.low is None and self.high is None:
            return KINDS[self.kind]
        what = self.what or ("an integer" if self.kind == "integer" else "a value")
        unit = f" {unit}" if unit else ""
        if self.high is None:
            return f"{what} {'>' if self.low_open else '>='} {self.low:g}{unit}"
        if self.low is None:
            return f"{what} {'<' if self.high_open else '<='} {self.high:g}{unit}"
        return (
            f"{what} in {'(' if self.low_open else '['}{self.low:g}, {self.high:g}"
            f"{')' if self.high_open else ']'}{unit}"
        )

    def check(self, name: str, value):
        """``value`` if it is allowed (None passes: not given); otherwise an InputError
        naming ``name``, the value as given and the range in the input's unit.

        Parameters
        ----------
        name : str
            The input's public name, for the error and to find its unit (its suffix).
        value : object
            The value as given, in the input's unit; None passes (not given).

        Returns
        -------
        object
            ``value``, unchanged.
        """
        if value is None:
            return None
        if self.choices:
            if value not in self.choices:
                raise InputError(name, value, self.allowed())
            return value
        if self.kind not in ("number", "integer"):
            return value
        from ..units import unit_of

        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise InputError(name, value, KINDS[self.kind])
        unit = unit_of(name)
        symbol = unit.symbol if unit is not None else ""
        if not math.isfinite(value):
            ranged = self.low is not None or self.high is not None
            allowed = self.allowed(symbol) if ranged else "a finite number"
            raise InputError(name, value, allowed, unit=symbol)
        bad = False
        if self.low is not None:
            bad = value <= self.low if self.low_open else value < self.low
        if not bad and self.high is not None:
            bad = value >= self.high if self.high_open else value > self.high
        if bad:
            raise InputError(name, value, self.allowed(symbol), unit=symbol)
        return value


def _n(default, help_, low=None, high=None, **kw) -> Input:
    return Input("number", default, help_, low=low, high=high, **kw)


_LENGTH = {"low": 0.0, "high": 1e5, "low_open": True, "what": "a length"}

#: name -> Input, in the order the command line lists them.
INPUTS: dict[str, Input] = {
    # ---------------------------------------------------------------- the bearing
    "designation": Input(
        "text",
        None,
        "Bearing designation (GOST 3189-89 or ISO, e.g. 6205-2RS, 180205) or catalogue name "
        "(e.g. ER-16K); optional with explicit geometry.",
    ),
    "system": Input(
        "text", None, "Read the designation as GOST 3189-89 or ISO.", choices=("gost", "iso")
    ),
    "balls": Input("integer", None, "Number of balls Z.", low=3, sets="BallBearing.ball_count"),
    "ball_diameter_mm": _n(None, "Ball diameter D_w [mm].", **_LENGTH, sets="ball_diameter"),
    "pitch_diameter_mm": _n(None, "Pitch diameter d_m [mm].", **_LENGTH, sets="pitch_diameter"),
    "contact_angle_deg": _n(None, "Nominal contact angle [deg].", sets="contact_angle"),
    "inner_groove_factor": _n(
        None, "Inner groove curvature factor f_i (> 0.5).", sets="inner_groove_factor"
    ),
    "outer_groove_factor": _n(
        None, "Outer groove curvature factor f_o (> 0.5).", sets="outer_groove_factor"
    ),
    "clearance_um": _n(None, "Diametral clearance P_d [um].", sets="diametral_clearance"),
    "inner_arch_angle_deg": _n(
        None, "Gothic-arch angle of the inner groove [deg] (0 = circular).", sets="inner_arch_angle"
    ),
    "outer_arch_angle_deg": _n(
        None, "Gothic-arch angle of the outer groove [deg] (0 = circular).", sets="outer_arch_angle"
    ),
    "rollers": Input(
        "integer", None, "Number of rollers per row Z.", low=3, sets="RollerBearing.roller_count"
    ),
    "roller_diameter_mm": _n(
        None,
        "Roller diameter D_we (mean diameter of a tapered roller) [mm].",
        **_LENGTH,
        sets="roller_diameter",
    ),
    "roller_length_mm": _n(
        None,
        "Effective roller length L_we (the line contact's length) [mm].",
        **_LENGTH,
        sets="roller_length",
    ),
    "roller_profile": Input(
        "text",
        None,
        "Roller profile: flat (unprofiled), logarithmic (ISO/TS 16281, the default), "
        "crowned:crown_radius_mm=R[,flat_length_mm=F] or user:positions_mm=A/B/C,"
        "drops_um=A/B/C (the drop below the straight line at each position from the "
        "roller's middle).",
        sets="profile",
    ),
    "cone_angle_deg": _n(
        None,
        "Cone (inner raceway) angle of a tapered bearing [deg] (default: on apex).",
        0.0,
        45.0,
        what="an angle",
        sets="cone_angle",
    ),
    "rows": Input(
        "integer", None, "Rows of rollers (1 or 2).", low=1, high=2, sets="RollerBearing.rows"
    ),
    "arrangement": Input(
        "text",
        None,
        "Two rows of a roller bearing: back_to_back or face_to_face (mirrored tapered rows), "
        "tandem (two rows alike, e.g. NN); single for one row.",
        choices=("single", "back_to_back", "face_to_face", "tandem"),
        sets="arrangement",
    ),
    "axial_clearance_um": _n(
        None,
        "Axial play of a mirrored pair or double-row tapered bearing [um]; negative: a preload.",
        -1e4,
        1e4,
        sets="axial_clearance",
    ),
    "bore_mm": _n(None, "Bore d [mm].", **_LENGTH, sets="bore"),
    "outside_diameter_mm": _n(None, "Outside diameter D [mm].", **_LENGTH, sets="outside_diameter"),
    "width_mm": _n(None, "Width B [mm].", **_LENGTH, sets="width"),
    "elastic_modulus_gpa": _n(
        None,
        "Young's modulus of rings and balls [GPa].",
        0.0,
        1e4,
        low_open=True,
        sets="Material.elastic_modulus",
    ),
    "poisson_ratio": _n(
        None,
        "Poisson's ratio of rings and balls.",
        0.0,
        0.5,
        high_open=True,
        sets="Material.poisson_ratio",
    ),
    "density_kg_m3": _n(
        None,
        "Density of rings and balls [kg/m^3].",
        0.0,
        1e5,
        low_open=True,
        sets="Material.density",
    ),
    "geometry": Input(
        "path",
        None,
        "TOML file with any of the geometry values (keys as the input names, e.g. "
        "ball_diameter_mm = 7.94, balls = 9; also system and name).",
    ),
    # ---------------------------------------------------------------- operating condition
    "speed_rpm": _n(
        None,
        "Speed of the rotating ring [rpm].",
        0.0,
        1e6,
        what="a speed",
        sets="OperatingCondition.shaft_speed",
    ),
    "radial_load_n": _n(
        0.0,
        "Radial load F_r on the shaft, downwards [N].",
        0.0,
        1e7,
        what="a load",
        sets="OperatingCondition.radial_load",
    ),
    "axial_load_n": _n(
        0.0,
        "Axial load F_a on the inner ring [N].",
        -1e7,
        1e7,
        what="a load",
        sets="OperatingCondition.axial_load",
    ),
    "radial_load_angle_deg": _n(
        -90.0,
        "Direction of the radial load from +x towards +y [deg]; -90 = downwards.",
        -1e6,
        1e6,
        sets="OperatingCondition.radial_load_angle",
    ),
    "misalignment_mrad": _n(
        0.0,
        "Imposed tilt of the inner ring about the axis across the radial load [mrad].",
        -20.0,
        20.0,
        what="a tilt",
        sets="OperatingCondition.misalignment",
    ),
    "outer_rotating": Input("bool", False, "The outer ring turns, the inner ring is fixed."),
    "slices": Input(
        "integer",
        30,
        "Slices of each roller's line contact (ISO/TS 16281); roller bearings only.",
        low=3,
        high=500,
        what="a number of slices",
    ),
    # ---------------------------------------------------------------- lubricant
    "film": Input("bool", False, "Subtract the Hamrock-Dowson EHL film from the approaches."),
    "lubricant": Input(
        "text",
        None,
        "Built-in lubricant: iso-vg68 or seed004-grease.",
        choices=("iso-vg68", "seed004-grease"),
    ),
    "temperature_c": _n(
        None,
        "Lubricant temperature [degC] (default: its reference).",
        -60.0,
        300.0,
        what="a temperature",
    ),
    "viscosity_mm2_s": _n(
        None,
        "Operating kinematic viscosity of the lubricant (a grease's base oil) [mm^2/s].",
        0.0,
        1e6,
        low_open=True,
        what="a viscosity",
    ),
    # ---------------------------------------------------------------- load distribution
    "gyroscopic": Input(
        "bool",
        False,
        "Include the balls' gyroscopic moments, held by friction at the controlling raceway "
        "(`race_control`).",
    ),
    "race_control": Input(
        "text",
        "outer",
        "Raceway control that sets each ball's orbital speed and spin: outer or inner (the "
        "ball rolls without spinning on that race, Jones), or hybrid (per ball by Jones's "
        "criterion, friction shared as Harris does).",
        choices=("outer", "inner", "hybrid"),
    ),
    "ring_expansion": Input(
        "bool", False, "Reduce the clearance by the inner ring's centrifugal expansion."
    ),
    # ---------------------------------------------------------------- records
    "folder": Input(
        "path",
        ...,
        "Folder of recordings: files analyze reads (.npz, .csv, .wav, .mat), PRONOSTIA "
        "snapshots acc_NNNNN.csv as published.",
    ),
    "signal_file": Input(
        "path",
        ...,
        "Vibration record: .npz, .csv (with a time column), .wav or .mat (CWRU variables, "
        "MATLAB structs such as MFPT's bearing.gs, v7.3).",
    ),
    "channel": Input(
        "text",
        None,
        "Channel or struct field path (e.g. DE, acc_y, bearing.gs or gs); default acc_y, DE "
        "or gs if present, else the first.",
    ),
    "sample_rate_hz": _n(
        None,
        "Sample rate of the record [Hz]: of a recording, where its file does not store it "
        "(a rate given that differs from the file's is used, with a warning); of a simulated "
        "record, the rate it is made at.",
        0.0,
        1e9,
        low_open=True,
        what="a sample rate",
    ),
    "duration_s": _n(
        None,
        "Length of the simulated record [s].",
        0.0,
        3600.0,
        low_open=True,
        what="a duration",
    ),
    "dynamic_model": Input(
        "text",
        "rigid",
        "rigid: seed 003's 4-DOF rigid-ring model (no slip); slip: seed 004's model with ball "
        "slip and a cage.",
        choices=("rigid", "slip"),
        aliases=("model",),
        sets="model",
    ),
    "defect_width_mm": _n(None, "Width of a defect along the rolling direction [mm].", **_LENGTH),
    "defect_depth_mm": _n(None, "Depth of a defect [mm].", **_LENGTH),
    "defect_angle_deg": _n(
        None,
        "Position of an outer-race defect, from +x towards +y [deg] (270 or -90: the bottom, "
        "the middle of the load zone).",
        -360.0,
        360.0,
        what="an angle",
    ),
    "noise_ms2": _n(
        0.0,
        "RMS white noise added to the accelerations [m/s^2].",
        0.0,
        1e6,
        what="an RMS acceleration",
        seeded=True,
        sets="noise",
    ),
    # ---------------------------------------------------------------- where long work runs
    "jobs": Input(
        "integer",
        1,
        "Worker processes (a pool of processes forked from the command); 1: this process.",
        low=1,
        what="a number of processes",
    ),
    "scheduler": Input(
        "text",
        None,
        "tcp://HOST:PORT of a running dask scheduler (default: $DASK_SCHEDULER_ADDRESS, else "
        "a LocalCluster of this machine's cores); 'serial' runs in this process.",
    ),
    "workers": Input(
        "integer",
        None,
        "Worker processes of the LocalCluster (default: the cores).",
        low=1,
        what="a number of workers",
    ),
    "partition_size": Input(
        "integer",
        None,
        "Cases (records) per partition (default: from the analysis and the count).",
        low=1,
        what="a number of cases",
    ),
    "yes": Input("bool", False, "Run more than the confirmation limit."),
    # ---------------------------------------------------------------- form errors, defects
    "waviness": Input(
        "texts",
        None,
        "Sinusoidal waviness, repeatable: RACE:order=7,amplitude_um=0.5[,phase_deg=0][,ball=N] "
        "with RACE inner, outer or ball; r = A cos(order theta + phase) in the ring's (or "
        "ball's) own frame.",
    ),
    "ball_size_error_um": Input(
        "text",
        None,
        "Random ball diameter errors: BAND (uniform in [-BAND/2, +BAND/2] um about the nominal "
        "diameter: BAND is the lot's largest minus smallest ball) or LOW,HIGH [um]; drawn "
        "with the seed.",
        seeded=True,
    ),
    "surface3d": Input(
        "texts",
        None,
        "Random 3-D raceway surface (seed 002 eq. 6), repeatable: "
        "RACE:amplitude_um=..,length_circ_mm=..,length_axial_mm=.. with RACE inner or outer "
        "(RMS height, circumferential and axial correlation lengths).",
    ),
    "seed": Input(
        "integer",
        None,
        "Seed of the random ball-size errors and surfaces (default 0: the same request gives "
        "the same bearing; surface i in the order given uses SEED + 1 + i).",
        low=0,
        high=2**32 - 1,
    ),
    "defect": Input(
        "texts",
        None,
        "A localised defect, repeatable: outer:width_mm=1.2,depth_mm=0.25[,angle_deg=270] "
        "(angle from +x towards +y, 270 = bottom, the default), "
        "inner:width_mm=...,depth_mm=...[,angle_deg=...], ball:width_mm=1.2[,ball=0].",
    ),
}

#: The inputs that describe the bearing (a designation and/or its geometry).
BEARING = tuple(INPUTS)[: tuple(INPUTS).index("geometry") + 1]
#: The explicit geometry a bearing needs without a designation.
GEOMETRY_NEEDED = ("balls", "ball_diameter_mm", "pitch_diameter_mm")
#: The explicit geometry a roller bearing needs without a designation.
ROLLER_NEEDED = ("rollers", "roller_diameter_mm", "roller_length_mm", "pitch_diameter_mm")
#: The inputs that belong to one kind of rolling element only.
BALL_ONLY = (
    "balls",
    "ball_diameter_mm",
    "inner_groove_factor",
    "outer_groove_factor",
    "inner_arch_angle_deg",
    "outer_arch_angle_deg",
)
ROLLER_ONLY = (
    "rollers",
    "roller_diameter_mm",
    "roller_length_mm",
    "roller_profile",
    "cone_angle_deg",
    "rows",
    "arrangement",
    "axial_clearance_um",
)
#: The form errors.
FORMS = ("waviness", "ball_size_error_um", "surface3d", "seed")
