"""Compiled bearing forces for the transient engine's explicit integrator (numba, cached on disk).

A bearing's ``compiled()`` (the contract, ``bearings/base.py``) returns its family's kernel number
and parameter vectors.  The engine concatenates every bearing's parameters into one float and
one int vector and describes each bearing by a handle (:func:`handle`): a small named tuple whose
TYPE names the family.  :func:`force` is resolved at compile time from that type, so a compiled
loop over the handles (``numba.literal_unroll``) calls each family's kernel directly, with no
branch at run time; a rotor with another mix of families gets its own compiled loop (cached).

    force(h, floats, ints, q, v, t, speed, angle, out): the force on the bearing's DOFs (node DOFs
    followed by internal DOFs, as ``force_and_tangent``) into ``out``; the bearing's parameters
    start at floats[h.f0] and ints[h.i0].
"""

from __future__ import annotations

from typing import NamedTuple

from numba import njit
from numba.extending import overload

from .linear.bearing import KIND as LINEAR
from .roller import flexible_race_kernel, rigid_race_kernel
from .roller.bearing import FLEXIBLE_RACE_KIND as FLEXIBLE_RACE
from .roller.bearing import RIGID_RACE_KIND as RIGID_RACE


class LinearForce(NamedTuple):
    f0: int


class RigidRaceForce(NamedTuple):
    f0: int
    i0: int


class FlexibleRaceForce(NamedTuple):
    f0: int
    i0: int


#: kernel number -> handle type (the table of compiled families)
HANDLES = {LINEAR: LinearForce, RIGID_RACE: RigidRaceForce, FLEXIBLE_RACE: FlexibleRaceForce}
#: the source files of every family's compiled force: a compiled loop over the handles inlines them
KERNEL_FILES = (__file__, rigid_race_kernel.__file__, flexible_race_kernel.__file__)


def handle(kind: int, f0: int, f1: int, i0: int) -> NamedTuple:
    """The handle of a bearing whose parameters are floats[f0:f1], ints[i0:]."""
    cls = HANDLES[kind]
    return cls(*(int(v) for v, name in ((f0, "f0"), (f1, "f1"), (i0, "i0")) if name in cls._fields))


@njit(cache=True, inline="always")
def _linear(fl, f0, q, v, speed, out):
    """f = -(K q + C v), K and C interpolated linearly in speed (held outside the table)."""
    n = int(fl[f0])
    s0 = f0 + 1
    k0 = s0 + n
    c0 = k0 + 4 * n
    if n == 1 or speed <= fl[s0]:
        i, w = 0, 0.0
    elif speed >= fl[s0 + n - 1]:
        i, w = n - 2, 1.0
    else:
        i = 0
        while fl[s0 + i + 1] < speed:
            i += 1
        w = (speed - fl[s0 + i]) / (fl[s0 + i + 1] - fl[s0 + i])
    j = i + 1 if n > 1 else 0
    for r in range(2):
        acc = 0.0
        for c in range(2):
            K = (1.0 - w) * fl[k0 + 4 * i + 2 * r + c] + w * fl[k0 + 4 * j + 2 * r + c]
            C = (1.0 - w) * fl[c0 + 4 * i + 2 * r + c] + w * fl[c0 + 4 * j + 2 * r + c]
            acc += K * q[c] + C * v[c]
        out[r] = -acc


def force(h, fl, it, q, v, t, speed, angle, out):  # pragma: no cover - resolved by numba (below)
    """Bearing force of the family named by the type of ``h`` (module note); compiled code only."""
    raise NotImplementedError("bearings.compiled.force runs inside compiled code only")


@overload(force, inline="always", jit_options={"cache": True})
def _force(h, fl, it, q, v, t, speed, angle, out):
    cls = getattr(h, "instance_class", None)
    if cls is LinearForce:
        def linear(h, fl, it, q, v, t, speed, angle, out):
            _linear(fl, h.f0, q, v, speed, out)
        return linear
    if cls is RigidRaceForce:
        def rigid(h, fl, it, q, v, t, speed, angle, out):
            rigid_race_kernel.force(fl, h.f0, it, h.i0, q, v, t, speed, angle, out)
        return rigid
    if cls is FlexibleRaceForce:
        def flexible(h, fl, it, q, v, t, speed, angle, out):
            flexible_race_kernel.force_at(fl, h.f0, it, h.i0, q, v, speed, angle, out)
        return flexible
    return None
