"""Learn the trend's defaults from the six PRONOSTIA learning runs and write them as package
data (issues 27 and 29).

Reads ../shared/data/run-to-failure (the six learning runs of the PHM 2012 challenge, every
k-th snapshot: bearings.csv says which) with :func:`bearinglab.trend.learn_runs` and the
rule's default settings, and writes ``src/bearinglab/trend/data/learned_runs.json``: the
excursion rates of healthy operation that set the alarm's limits, the rule's false alarms
measured leave-one-run-out, and the lives and degradation the remaining-life estimate uses.
Prints what it learned.

    .venv/bin/python benchmarks/trend_learn.py [--out PATH]
"""

from __future__ import annotations

import argparse
import csv
import json
from pathlib import Path

from bearinglab.trend import learn_runs

ROOT = Path(__file__).resolve().parents[1]
RUNS = ROOT.parent / "shared" / "data" / "run-to-failure"
OUT = ROOT / "src" / "bearinglab" / "trend" / "data" / "learned_runs.json"


def conditions() -> dict:
    """Run -> its speed, load and the share of snapshots kept, from bearings.csv."""
    with open(RUNS / "bearings.csv", newline="", encoding="utf-8") as fh:
        return {
            row["bearing"]: {
                "speed_rpm": float(row["speed_rpm"]),
                "radial_load_n": float(row["radial_load_n"]),
                "every_kth_kept": int(row["every_kth_kept"]),
            }
            for row in csv.DictReader(fh)
        }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=OUT)
    args = parser.parse_args()
    runs = conditions()
    source = (
        f"the {len(runs)} learning runs of the PHM 2012 challenge (PRONOSTIA; every 10th "
        "snapshot, every 5th for Bearing3_1, as kept in ../shared/data/run-to-failure)"
    )
    learned = learn_runs(RUNS, source=source, conditions=runs)
    learned.write(args.out)
    d = learned.to_dict()
    print(json.dumps({k: v for k, v in d.items() if k != "runs"}, indent=1)[:4000])
    for run in d["runs"]:
        print(run)
    print(f"written to {args.out}")


if __name__ == "__main__":
    main()
