"""tools.h5: the tool library on the spindle (``spindlesim tools``).

Group /tools: attributes ``speed_rpm``, ``nose_node``, ``method`` (receptance coupling); per tool a group
/tools/<name> with the layout of frf.h5's ``tool_point`` (``frequency_hz``, ``receptance_m_N`` [frequency, dof
(x, y), load (x, y)], its inverse ``dynamic_stiffness_N_m``) and ``mass_kg``, ``nose_to_tip_m``, ``nose_load``
(the static load the tool puts on the nose, on the nose's DOFs); /tools/spindle the spindle's receptance at the
nose [state, frequency, dof, load] for each static state solved.  With a ``chatter:`` section, /tools/lobes: one
row per tool (``tool``) with the minimum limit depth and its speed, the recommended speed and depth (NaN where no
pocket), and each tool's lobe diagram in /tools/<name>/lobes (``speed_rpm``, ``limit_depth_m``).  docs/output-format.md.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from .hdf5 import Data, RunInfo, labels, write_h5
from .rotor_writers import tool_point_frf

METHOD = ("receptance coupling of the spindle's receptances at the nose (every DOF of the node) with each tool's "
          "free-free receptances through its interface joint")


def _units(names) -> tuple[str, ...]:
    return tuple("rad" if n.startswith("theta") else "m" for n in names)


def write_tools(path: Path, run: RunInfo, study) -> Path:
    lib = study.library
    g = "/tools"
    data: dict = {}
    attrs: dict = {g: {"speed_rpm": lib.speed_rpm, "nose_node": lib.nose_node, "method": METHOD,
                       "tools": np.array([t.name for t in lib.tools], dtype=object)}}
    for t in lib.tools:
        tg = f"{g}/{t.name}"
        data.update(tool_point_frf(tg, lib.frequency_hz, t.receptance_m_N))
        data[f"{tg}/mass_kg"] = Data(t.mass_kg, "kg", (), "mass of holder and tool")
        data[f"{tg}/nose_to_tip_m"] = Data(t.nose_to_tip_m, "m", (), "from the spindle nose to the tool tip")
        data[f"{tg}/nose_load"] = Data(np.asarray(t.nose_load, float), "", ("nose_dof",),
                                       "static load the tool puts on the nose (its weight), on the nose's DOFs",
                                       component_units=np.array(["N m" if n.startswith("theta") else "N"
                                                                 for n in lib.dof_names], dtype=object))
        data.update(labels(tg, "nose_dof", lib.dof_names))
        attrs[tg] = {"spindle_state": lib.state_of[lib.tools.index(t)]}
    s = f"{g}/spindle"
    u = _units(lib.dof_names)
    data[f"{s}/frequency_hz"] = (lib.frequency_hz, "Hz", ("frequency_hz",))
    data[f"{s}/receptance"] = Data(lib.spindle_receptance, "", ("state", "frequency_hz", "dof", "load"),
                                   "the spindle's receptance at the nose (no tool) at each static state solved",
                                   component_units=np.array([[f"{a}/{'N m' if b == 'rad' else 'N'}" for b in u]
                                                             for a in u], dtype=object))
    data.update(labels(s, "dof", lib.dof_names))
    data.update(labels(s, "load", tuple("M" + n[-1] if n.startswith("theta") else "F" + n for n in lib.dof_names)))
    if study.lobes:
        lg = f"{g}/lobes"
        lb = study.lobes
        data.update(labels(lg, "tool", [x.name for x in lb]))
        for x in lb:  # each tool's diagram on its own speeds (the grid and the speeds added in its pockets)
            dg = f"{g}/{x.name}/lobes"
            data[f"{dg}/speed_rpm"] = (x.speed_rpm, "rpm", ("speed_rpm",))
            data[f"{dg}/limit_depth_m"] = Data(x.limit_depth_m, "m", ("speed_rpm",),
                                               "limit depth of cut (lower envelope)", fill_nan=True)
        for key, unit, what in (("min_depth_m", "m", "smallest limit depth over the speeds"),
                                ("min_speed_rpm", "rpm", "speed of that minimum"),
                                ("recommended_speed_rpm", "rpm", "middle of the best stability pocket (NaN: none)"),
                                ("recommended_depth_m", "m", "depth the pocket keeps over its speed interval")):
            data[f"{lg}/{key}"] = Data(np.array([getattr(x, key) for x in lb], float), unit, ("tool",), what,
                                       fill_nan=True)
        attrs[lg] = {"method": lb[0].method, "frf": study.lobes_frf}
    return write_h5(path, run, data, attrs)
