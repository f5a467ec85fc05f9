"""Key numbers of the embedded default deck (seed 003 spindle, linear bearings), for golden files."""

import numpy as np

from spindlesim.analysis.campbell import solve_campbell
from spindlesim.analysis.frf import solve_frf, solve_unbalance
from spindlesim.analysis.modal import solve_modal
from spindlesim.analysis.static import solve_static
from spindlesim.deck import default_deck
from spindlesim.model.build import build_rotor


def compute() -> dict:
    rotor = build_rotor(default_deck("spindle_linear").deck)
    st = solve_static(rotor)
    md = solve_modal(rotor, n_modes=8)
    cb = solve_campbell(rotor, np.linspace(0, 12000, 7), n_modes=6)
    fr = solve_frf(rotor, np.array([10.0, 500.0, 1000.0, 1117.0, 2000.0, 3150.0, 5000.0]), 1, "x", 1, "x")
    ub = solve_unbalance(rotor, np.array([1000.0, 6000.0, 12000.0]), 1, 1e-5, 0.0, 1, "x")
    return {
        "static_nose_displacement_m": st.displacement_m[0].tolist(),
        "static_bearing_force_N": st.bearing_force_N.ravel().tolist(),
        "static_stiffness_N_m": st.static_stiffness_N_m,
        "modal_frequency_hz": md.frequency_hz.tolist(),
        "modal_damping_ratio": md.damping_ratio.tolist(),
        "modal_whirl": list(md.whirl),
        "campbell_frequency_hz": cb.frequency_hz.ravel().tolist(),
        "frf_abs_m_N": np.abs(fr.receptance_m_N).tolist(),
        "frf_phase_rad": np.angle(fr.receptance_m_N).tolist(),
        "unbalance_abs_m": np.abs(ub.response_m[:, 0, 0]).tolist(),
    }


def compute_three_lobe() -> dict:
    """The embedded default deck: seed 003 spindle on two 3-lobe bearings at thermal equilibrium."""
    rotor = build_rotor(default_deck("spindle").deck)
    md = solve_modal(rotor, n_modes=6)
    k_front, c_front = rotor.bearings[0].linearized(rotor.speed_rad_s)
    return {
        "three_lobe_modal_frequency_hz": md.frequency_hz.tolist(),
        "three_lobe_modal_damping_ratio": md.damping_ratio.tolist(),
        "three_lobe_front_K_N_m": k_front.ravel().tolist(),
        "three_lobe_front_C_Ns_m": c_front.ravel().tolist(),
    }
