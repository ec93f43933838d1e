"""Labelled synthetic bearing-fault data sets in the bearing-datasets layout.

``make_dataset("data/synth", 200, faults=["none", "outer", "inner", "ball"])`` makes 200
records on a dask LocalCluster; ``bearing_datasets.open("synth", root="data")`` reads them
(package ``bearing-datasets``), with the ground truth (fault class and size, true speed,
defect frequencies) in the metadata. See :mod:`.record` (what a record is),
:mod:`.generate` (the set, made on the engine), :mod:`.sampling` (what is randomised),
:mod:`.path` (the transfer path) and :mod:`.layout` (the files).
"""

from .generate import DatasetResult, make_dataset
from .path import TransferPath
from .record import make_record
from .sampling import FAULTS, DatasetSpec, draw_record, parse_range

__all__ = [
    "FAULTS",
    "DatasetResult",
    "DatasetSpec",
    "TransferPath",
    "draw_record",
    "make_dataset",
    "make_record",
    "parse_range",
]
