"""Map rotor-analysis results onto the HDF5 layout of docs/output-format.md."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..analysis.results import CampbellResult, FrfResult, ModalResult, StaticResult, UnbalanceResult
from .hdf5 import RunInfo, write_h5


def write_static(path: Path, run: RunInfo, r: StaticResult) -> Path:
    return write_h5(path, run, {
        "/static/node_z_m": (r.node_z_m, "m"),
        "/static/displacement_m": (r.displacement_m, "m"),
        "/static/slope_rad": (r.slope_rad, "rad"),
        "/static/bearing_name": (np.array(r.bearing_names, dtype=object), "1"),
        "/static/bearing_node": (r.bearing_nodes + 1, "1"),
        "/static/bearing_force_N": (r.bearing_force_N, "N"),
        "/static/applied_force_N": (r.applied_force_N, "N"),
        "/static/static_stiffness_N_m": (r.static_stiffness_N_m, "N/m"),
    }, {"/static": {"speed_rpm": r.speed_rpm, "stiffness_node": r.stiffness_node + 1,
                    "stiffness_dof": r.stiffness_dof,
                    "bearing_force_convention": "force exerted by the bearing on the shaft"}})


def write_modal(path: Path, run: RunInfo, r: ModalResult) -> Path:
    return write_h5(path, run, {
        "/modal/frequency_hz": (r.frequency_hz, "Hz"),
        "/modal/undamped_frequency_hz": (r.undamped_frequency_hz, "Hz"),
        "/modal/damping_ratio": (r.damping_ratio, "1"),
        "/modal/log_dec": (r.log_dec, "1"),
        "/modal/eigenvalue": (r.eigenvalues, "1/s"),
        "/modal/whirl": (np.array(r.whirl, dtype=object), "1"),
        "/modal/forward_fraction": (r.forward_fraction, "1"),
        "/modal/mode_shape": (r.mode_shape, "m, m, rad, rad (normalised: largest translation 1)"),
        "/modal/node_z_m": (r.node_z_m, "m"),
        "/modal/overdamped_roots": (r.overdamped_roots, "1/s (complex; zeta >= 0.999)"),
        "/modal/rigid_body_roots": (r.rigid_body_roots, "1/s"),
    }, {"/modal": {"speed_rpm": r.speed_rpm, "mode_shape_dofs": "x, y, theta_x, theta_y"}})


def write_campbell(path: Path, run: RunInfo, r: CampbellResult) -> Path:
    return write_h5(path, run, {
        "/campbell/speed_rpm": (r.speed_rpm, "rpm"),
        "/campbell/frequency_hz": (r.frequency_hz, "Hz"),
        "/campbell/log_dec": (r.log_dec, "1"),
        "/campbell/damping_ratio": (r.damping_ratio, "1"),
        "/campbell/whirl": (np.asarray(r.whirl, dtype=object), "1"),
        "/campbell/critical_speed_rpm": (r.critical_speeds_rpm, "rpm"),
        "/campbell/critical_mode": (r.critical_modes, "1"),
    }, {"/campbell": {"tracking": "MAC between consecutive speeds"}})


def write_frf(path: Path, run: RunInfo, r: FrfResult) -> Path:
    return write_h5(path, run, {
        "/frf/frequency_hz": (r.frequency_hz, "Hz"),
        "/frf/receptance_m_N": (r.receptance_m_N, "m/N"),
        "/frf/dynamic_stiffness_N_m": (r.dynamic_stiffness_N_m, "N/m"),
    }, {"/frf": {"input_node": r.input_node, "input_dof": r.input_dof, "output_node": r.output_node,
                 "output_dof": r.output_dof, "speed_rpm": r.speed_rpm}})


def write_unbalance(path: Path, run: RunInfo, r: UnbalanceResult) -> Path:
    return write_h5(path, run, {
        "/unbalance/speed_rpm": (r.speed_rpm, "rpm"),
        "/unbalance/response_m": (r.response_m, "m"),
        "/unbalance/node_z_m": (r.node_z_m, "m"),
    }, {"/unbalance": {"unbalance_kg_m": r.unbalance_kg_m, "unbalance_node": r.unbalance_node,
                       "output_node": r.output_node, "output_dof": r.output_dof,
                       "response_convention": "complex phasor: q(t) = Re(q e^{j W t})"}})
