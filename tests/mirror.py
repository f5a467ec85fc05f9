"""The mirror image of a rotor deck: the same machine numbered from the other end.

Shaft elements reversed, node k -> n + 2 - k on an n-element shaft (tool and holder nodes, which
follow the shaft's, keep their numbers; the holder moves to the other end), and the quantities that
change sign under the reflection z -> -z: axial forces, the moments about x and y, and directions
named along z (a single or tandem ball set's thrust, a spring preload's floating side).  A rotation
about z (the spin) is unchanged by the reflection, so speeds stay as they are.
"""

from __future__ import annotations

import copy

_FLIP_Z = {"+z": "-z", "-z": "+z"}


def mirror_deck(d: dict) -> dict:
    m = copy.deepcopy(d)
    n = len(d["shaft"]["elements"])

    def node(k: int) -> int:
        return n + 2 - k if k <= n + 1 else k

    m["shaft"]["elements"] = list(reversed(d["shaft"]["elements"]))
    if m.get("tool"):
        m["tool"]["holder_node"] = node(m["tool"].get("holder_node", 1))
    for item in m.get("disks", []) + m.get("bearings", []):
        item["node"] = node(item["node"])
    for load in m.get("loads", []):
        load["node"] = node(load["node"])
        for key in ("fz_N", "mx_Nm", "my_Nm"):
            if key in load:
                load[key] = -load[key]
    for b in m.get("bearings", []):
        if "axial_direction" in b:
            b["axial_direction"] = _FLIP_Z[b["axial_direction"]]
        pre = b.get("preload")
        if isinstance(pre, dict) and pre.get("floating") in _FLIP_Z:
            pre["floating"] = _FLIP_Z[pre["floating"]]
        if b.get("axial_load_N"):
            b["axial_load_N"] = -b["axial_load_N"]
    return m


def mirrored_node(d: dict, k: int) -> int:
    """1-based node k of deck ``d`` in its mirror image."""
    n = len(d["shaft"]["elements"])
    return n + 2 - k if k <= n + 1 else k
