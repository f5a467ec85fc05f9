"""Pockets that fall between grid speeds, solved again on a finer grid.

A pocket whose interval holds fewer than ``MIN_GRID_SPEEDS`` grid speeds is not recommended
(:mod:`~spindlesim.chatter.pockets`): its peak and flanks are only interpolated.  When such a pocket
is deeper than the recommended one, the lobes are solved at ``POINTS`` more speeds across it (its interval
widened by half its width on either side) and merged into the diagram, at most ``MAX_POCKETS`` pockets
per round and ``ROUNDS`` rounds.  The deeper pocket is then recommended on computed limits, or found to
be shallower than the interpolation promised.
"""

from __future__ import annotations

import logging
from typing import Callable

import numpy as np

from .pockets import MIN_GRID_SPEEDS, Pocket, best_pocket, stability_pockets
from .results import LobeDiagram

__all__ = ["refine_pockets", "unresolved_deeper", "POINTS", "MAX_POCKETS", "ROUNDS"]

log = logging.getLogger(__name__)

POINTS, MAX_POCKETS, ROUNDS = 9, 3, 2


def unresolved_deeper(pockets: tuple[Pocket, ...]) -> list[Pocket]:
    """The pockets with too few grid speeds that are deeper than the deepest resolved one (all
    unresolved ones when none is resolved), deepest first."""
    resolved = [p for p in pockets if p.grid_speeds >= MIN_GRID_SPEEDS]
    floor = resolved[0].depth_m if resolved else -np.inf
    return [p for p in pockets if p.grid_speeds < MIN_GRID_SPEEDS and p.depth_m > floor]


def _speeds_across(p: Pocket, grid: np.ndarray) -> np.ndarray:
    half = 0.5 * max(p.width_rpm, 1e-3 * p.peak_speed_rpm)
    lo, hi = max(p.speed_min_rpm - half, grid[0]), min(p.speed_max_rpm + half, grid[-1])
    new = np.linspace(lo, hi, POINTS)
    gap = 0.25 * (hi - lo) / (POINTS - 1)  # a new speed next to a grid speed adds nothing
    return new[np.min(np.abs(new[:, None] - grid[None, :]), axis=1) > gap]


def refine_pockets(diagram: LobeDiagram, solve: Callable[[np.ndarray], LobeDiagram]) -> LobeDiagram:
    """``diagram`` with the lobes at extra speeds in its unresolved, deeper pockets (module docstring);
    ``solve(speeds)`` gives the lobe diagram at those speeds.  The diagram itself when there is nothing
    to refine."""
    for _ in range(ROUNDS):
        todo = unresolved_deeper(stability_pockets(diagram))[:MAX_POCKETS]
        if not todo:
            break
        grid = np.asarray(diagram.speed_rpm, float)
        extra = np.unique(np.concatenate([_speeds_across(p, grid) for p in todo]))
        if not len(extra):
            break
        where = ", ".join(f"{p.peak_speed_rpm:,.0f} rpm ({p.grid_speeds} grid speed{'s' * (p.grid_speeds != 1)}, "
                          f"{p.peak_depth_m * 1e3:.3g} mm interpolated)" for p in todo)
        log.info("solving %d more speeds in pockets between grid speeds: %s", len(extra), where)
        diagram = diagram.merged(solve(extra), f"{len(extra)} speeds added in pockets the grid did not resolve: "
                                               f"{where}")
    best = best_pocket(stability_pockets(diagram))
    if best is not None and best.grid_speeds < MIN_GRID_SPEEDS:
        log.warning("the recommended pocket at %.0f rpm holds only %d grid speed(s) after refinement",
                    best.speed_rpm, best.grid_speeds)
    return diagram
