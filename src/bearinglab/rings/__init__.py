"""Natural frequencies of the outer ring of a loaded ball bearing (seed 000, Balmont &
Varlamov 1986): formulas in :mod:`.frequencies`, the analysis in :mod:`.modes`."""

from .frequencies import (
    free_ring_frequency,
    linear_stiffness_ratio,
    loaded_ring_frequencies,
    loaded_ring_frequency,
    radial_stiffness_under_axial_load,
    refined_equal_stiffness,
    refined_frequency,
    refined_ring_frequencies,
    rigid_body_frequency,
    split_mode,
)
from .modes import RingMode, RingModes, ring_modes

__all__ = [
    "RingMode",
    "RingModes",
    "free_ring_frequency",
    "linear_stiffness_ratio",
    "loaded_ring_frequencies",
    "loaded_ring_frequency",
    "radial_stiffness_under_axial_load",
    "refined_equal_stiffness",
    "refined_frequency",
    "refined_ring_frequencies",
    "rigid_body_frequency",
    "ring_modes",
    "split_mode",
]
