"""The CWRU drive-end bearing (6205-2RS JEM SKF) at the data set's 1797 rpm.

Decodes the designation, shows where each geometry value comes from, prints the defect
frequencies next to CWRU's published multipliers, and draws the Hertz contact of a ball
loaded to 1000 N.

Run: .venv/bin/python examples/cwru_6205.py [output-directory]
"""

import math
import sys
from pathlib import Path

from bearinglab.catalog import bearing_from_designation
from bearinglab.contact.ball_race import ball_contacts
from bearinglab.kinematics import defect_frequencies
from bearinglab.plotting import save_figure

CWRU_PUBLISHED = {"bpfi": 5.4152, "bpfo": 3.5848, "ftf": 0.39828, "ball_defect": 4.7135}


def main(out: Path) -> None:
    bearing, designation = bearing_from_designation("6205-2RS")
    print(designation.description)
    for field in ("ball_count", "ball_diameter", "pitch_diameter", "diametral_clearance"):
        src = bearing.sources[field]
        print(f"  {field:20s} {getattr(bearing, field):.6g}  ({src.kind})")
    f = defect_frequencies(bearing, 1797 * math.pi / 30)
    print("frequency  order (ours)  order (CWRU)  Hz at 1797 rpm")
    for name, published in CWRU_PUBLISHED.items():
        print(f"  {name:10s} {f.orders[name]:10.5f} {published:12.5f} {f.hz(name):12.2f}")
    contacts = ball_contacts(bearing, 1000.0)
    print(
        f"p_max inner/outer at 1000 N: {float(contacts.inner.max_pressure) / 1e9:.3f} / "
        f"{float(contacts.outer.max_pressure) / 1e9:.3f} GPa"
    )
    out.mkdir(parents=True, exist_ok=True)
    print("wrote", save_figure(contacts.plot()[0], out / "cwru_6205_contact.png"))
    print("wrote", save_figure(f.plot()[0], out / "cwru_6205_frequencies.png"))


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else Path("out"))
