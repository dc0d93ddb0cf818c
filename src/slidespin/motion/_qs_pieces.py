"""The pieces of a quasi-static push, with their budget (MODEL §13): both quasi-static engines
(:mod:`slidespin.motion.quasi_static`, :mod:`slidespin.motion.quasi_static_line`) collect the
path's pieces (one contact mode between two switches or knots) in a :class:`Pieces` list that
refuses more than ``max_phases`` of them, as the dynamic engines end at ``max_phases``.
"""

from __future__ import annotations

from slidespin import _validate as v

__all__ = ["PhaseBudget", "Pieces", "check_max_phases"]


class PhaseBudget(RuntimeError):
    """More pieces than ``max_phases``: the push ends with status ``max_phases``."""


class Pieces(list):
    """A list of pieces ``(t_start, t_end, mode, ...)`` of at most ``cap`` entries."""

    def __init__(self, cap: int):
        super().__init__()
        self.cap = cap

    def append(self, item) -> None:
        if len(self) >= self.cap:
            raise PhaseBudget(
                f"more than max_phases = {self.cap} mode switches and path knots at "
                f"t = {item[0]!r} s"
            )
        super().append(item)


def check_max_phases(max_phases: object) -> int:
    """``max_phases`` as an int in [1, 1e9] (a one-line ``ValueError`` otherwise)."""
    if (
        isinstance(max_phases, bool)
        or not isinstance(max_phases, int)
        or not 1 <= max_phases <= v.MAX_STEPS
    ):
        raise ValueError(
            f"max_phases = {v._short(max_phases)} is invalid; valid range: integer in "
            f"[1, {v.MAX_STEPS}]"
        )
    return int(max_phases)
