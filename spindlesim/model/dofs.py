"""Degree-of-freedom numbering: node-major, a fixed tuple of DOF names per node.

Lateral analyses use ("x", "y", "theta_x", "theta_y"); a model that needs the axial DOF (seed
001's 5 DOF/node DTRB rotor) builds ``DofMap(n, DOFS_5)``; a rigid journal (seed 000's test rig)
has one node with ("x", "y").  Element matrices are written in the lateral order and scattered
by name, so adding "z" never renumbers them.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

DOFS_4 = ("x", "y", "theta_x", "theta_y")
DOFS_5 = ("x", "y", "z", "theta_x", "theta_y")
DOFS_JOURNAL = ("x", "y")


@dataclass(frozen=True)
class DofMap:
    n_nodes: int
    names: tuple[str, ...] = DOFS_4

    @property
    def per_node(self) -> int:
        return len(self.names)

    @property
    def size(self) -> int:
        return self.n_nodes * self.per_node

    def has(self, dof: str) -> bool:
        return dof in self.names

    def index(self, node: int, dof: str) -> int:
        """Global index of ``dof`` at 0-based ``node``."""
        if not 0 <= node < self.n_nodes:
            raise IndexError(f"node {node + 1} is not on the rotor (nodes 1..{self.n_nodes})")
        return node * self.per_node + self.names.index(dof)

    def at(self, node: int, dofs) -> np.ndarray:
        """Indices of ``dofs`` (names) at ``node``."""
        return np.array([self.index(node, d) for d in dofs], dtype=int)

    def lateral(self, node: int) -> np.ndarray:
        """Indices of (x, y, theta_x, theta_y) at ``node``."""
        return self.at(node, DOFS_4)

    def component(self, dof: str) -> np.ndarray:
        """Indices of one DOF at every node."""
        return np.array([self.index(n, dof) for n in range(self.n_nodes)], dtype=int)
