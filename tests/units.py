"""The units check of every dataset (issue 33, item 2): every dataset has a ``units`` attribute, and a name
ending in a unit (``_s``, ``_hz``, ``_rpm``, ``_m``, ``_N``, ``_C``, ``_W`` ...) carries exactly that unit, unless
its entries differ in unit (``component_units``, ``units`` "")."""

from __future__ import annotations

import h5py

#: a name's unit suffix -> the UDUNITS string the files write; the longest suffix that matches wins
SUFFIX_UNITS = {
    "_s": "s", "_hz": "Hz", "_rpm": "rpm", "_m": "m", "_N": "N", "_C": "degC", "_W": "W", "_Pa": "Pa",
    "_deg": "degree", "_rad": "rad", "_kg": "kg", "_mm": "mm", "_um": "um", "_Nm": "N m", "_m_N": "m/N",
    "_N_m": "N/m", "_Ns_m": "N s/m", "_Nm_rad": "N m/rad", "_Nms_rad": "N m s/rad", "_m_s": "m/s",
    "_m_s2": "m/s^2", "_m3_s": "m^3/s", "_Pa_s": "Pa s", "_kg_m2": "kg m^2", "_kg_m3": "kg/m^3", "_K": "K",
    "_J": "J", "_g_mm": "g mm", "_N_m2": "N/m^2", "_m_N_s": "m/(N s)", "_m_N_s2": "m/(N s^2)",
}
#: names whose last word only looks like a unit
NOT_A_UNIT = {"node_m"}


def expected_unit(name: str) -> str | None:
    best = None
    for suffix, unit in SUFFIX_UNITS.items():
        if name.endswith(suffix) and len(name) > len(suffix) and (best is None or len(suffix) > len(best[0])):
            best = (suffix, unit)
    return None if best is None or name in NOT_A_UNIT else best[1]


def unit_problems(path) -> list[str]:
    """Every dataset of the file at ``path`` without units, or whose unit is not the one its name states."""
    bad: list[str] = []

    def visit(name: str, obj) -> None:
        if not isinstance(obj, h5py.Dataset):
            return
        if "units" not in obj.attrs:
            bad.append(f"{name}: no units")
            return
        units = obj.attrs["units"]
        units = units.decode() if isinstance(units, bytes) else str(units)
        want = expected_unit(name.split("/")[-1].split(".")[-1])
        if want is None or "component_units" in obj.attrs:
            return
        if units != want:
            bad.append(f"{name}: units {units!r}, its name says {want!r}")

    with h5py.File(path, "r") as f:
        f.visititems(visit)
    return bad
