"""Remaining useful life (placeholder while the method is built)."""

from __future__ import annotations


def learn_life(learned, results):
    return learned


def remaining_life(result):
    return None
