"""The ``report`` request: its inputs (the table's, with the report's defaults) and
:func:`report_from`, which builds the models from them and calls
:func:`~bearinglab.report.builder.build_report` once."""

from __future__ import annotations

from ..analyses.base import FILES, Analysis
from ..errors import InputError
from ..inputs import (
    BEARING,
    INPUTS,
    Input,
    bearing_from,
    check,
    check_defects,
    condition_from,
    restate,
    si,
)
from ..inputs.specs import parse_defect

#: The report's inputs, in the order the command line lists them.
REPORT_INPUTS: dict[str, Input] = {
    **{name: INPUTS[name] for name in BEARING},
    "speed_rpm": INPUTS["speed_rpm"].with_(default=..., help="Shaft (inner-ring) speed [rpm]."),
    "radial_load_n": INPUTS["radial_load_n"].with_(default=...),
    "axial_load_n": INPUTS["axial_load_n"],
    "lubricant": INPUTS["lubricant"].with_(
        default="iso-vg68",
        help="Built-in lubricant for the viscosity (friction, a_ISO), at its reference "
        "temperature: iso-vg68 or seed004-grease.",
    ),
    "viscosity_mm2_s": INPUTS["viscosity_mm2_s"].with_(
        help="Operating kinematic viscosity [mm^2/s] instead of lubricant."
    ),
    "defect": INPUTS["defect"].with_(
        help="A defect to simulate, repeatable, as for 'simulate': "
        "outer:width_mm=1.2,depth_mm=0.25[,angle_deg=270], inner:..., ball:width_mm=1.2[,ball=0]. "
        "Default: an example outer-race defect (said so in the report)."
    ),
    "duration_s": INPUTS["duration_s"].with_(
        default=1.0, help="Length of the simulated vibration record (rigid model) [s].", high=60.0
    ),
    "slip_duration_s": Input(
        "number",
        0.1,
        "Length of the slip-model run for the defect frequencies with slip [s] (about 5 s of "
        "computing per simulated second); 0 skips it.",
        low=0.0,
        high=10.0,
        what="a duration",
    ),
    "sample_rate_hz": INPUTS["sample_rate_hz"].with_(
        help="Sample rate of the simulated record [Hz] (default: 25.6 kHz, more at high speed "
        "so the ISO 15242 bands are resolved).",
        high=1e7,
    ),
}


def report_from(values: dict, progress=None):
    """The Report of a request (:func:`~bearinglab.report.builder.build_report`);
    ``progress(title, done, total)`` is called per section."""
    from .builder import build_report

    check(values, REPORT_INPUTS)
    condition = condition_from(
        {k: values.get(k) for k in ("speed_rpm", "radial_load_n", "axial_load_n")},
        positive_speed=True,
        unloaded="an unloaded bearing has no load distribution or life",
    )
    texts = list(values.get("defect") or [])
    defects = [parse_defect(text) for text in texts]
    bearing, decoded = bearing_from(values)
    check_defects(texts, defects, bearing)
    viscosity = values.get("viscosity_mm2_s")
    lubricant = values.get("lubricant") or "iso-vg68"
    try:
        return build_report(
            bearing,
            condition,
            designation=decoded,
            defects=defects,
            lubricant=None if viscosity is not None else lubricant,
            viscosity=si(values, "viscosity_mm2_s"),
            duration=values.get("duration_s") or 1.0,
            sample_rate=values.get("sample_rate_hz"),
            slip_duration=values.get("slip_duration_s", 0.1),
            progress=progress,
        )
    except InputError as exc:
        raise restate(exc, values, REPORT_INPUTS) from None


REPORT = Analysis(
    "report",
    "An engineer's report of a bearing at an operating point (build_report), one HTML page.",
    REPORT_INPUTS,
    run=report_from,
    files={"output": FILES["output"].with_(default=..., help="The HTML file to write.")},
)
