"""The error the catalogue raises when it cannot give some values (:class:`GeometryNeeded`),
in a module of its own so that both builders (ball and roller) raise it."""

from __future__ import annotations

from ..errors import CatalogError


class GeometryNeeded(CatalogError):
    """The catalogue cannot give some values; the caller must give them as overrides.

    ``needed`` lists the BallBearing keywords to give (the command line maps them to its
    options), ``reason`` says why, without the "give ..." clause.
    """

    def __init__(self, reason: str, needed: tuple[str, ...]) -> None:
        self.reason = reason
        self.needed = tuple(needed)
        super().__init__(f"{reason}; give {', '.join(self.needed)} as overrides")
