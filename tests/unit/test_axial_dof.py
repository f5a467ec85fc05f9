"""5 DOF per node (seed 001): the axial bar and the lateral model are independent of the DOF layout."""

import numpy as np
import pytest

from spindlesim.analysis.modal import solve_modal
from spindlesim.analysis.static import solve_static
from tests.rotor_helpers import isotropic_bearing, rotor_from, uniform_rows


def _rotor(fz):
    body = uniform_rows(10, 1000.0, 50.0) + "bearings:\n" + isotropic_bearing("a", 1, 1e8) + isotropic_bearing("b", 11, 1e8)
    body += f"loads:\n  - {{node: 6, fy_N: -100.0, fz_N: {fz!r}}}\n"
    return rotor_from(body)


def test_axial_dof_added_and_lateral_results_unchanged():
    r4, r5 = _rotor(0.0), _rotor(1e-300)  # a (negligible) axial load switches the axial DOF on
    assert r4.dofs.per_node == 4 and r5.dofs.per_node == 5
    m4 = solve_modal(r4, n_modes=4)
    m5 = solve_modal(r5, n_modes=6)
    lateral5 = m5.frequency_hz[m5.frequency_hz < m4.frequency_hz[-1] * 1.01]
    np.testing.assert_allclose(lateral5[:4], m4.frequency_hz, rtol=1e-9)
    s4, s5 = solve_static(r4), solve_static(_rotor(0.0))
    np.testing.assert_allclose(s5.displacement_m, s4.displacement_m)


def test_axial_bar_free_free_frequencies():
    """Free-free bar: w_n = n pi c / L, c = sqrt(E / rho). For N equal linear elements with consistent
    mass the discrete modes are known exactly (e.g. Hughes, The Finite Element Method, 1987, sec. 9.2):
    w_h = (c / h) sqrt(6 (1 - cos(k h)) / (2 + cos(k h))), k = n pi / L, h = L / N."""
    from spindlesim.fe.assembly import assemble_shaft

    r = _rotor(1.0)
    sh = assemble_shaft(r)
    iz = r.dofs.component("z")
    K, M = sh.K_B[np.ix_(iz, iz)], sh.M[np.ix_(iz, iz)]
    import scipy.linalg as sla

    w = np.sqrt(np.abs(sla.eigh(K, M, eigvals_only=True)))
    c = np.sqrt(211e9 / 7810)
    exact = np.arange(1, 3) * np.pi * c / 1.0
    kh = np.arange(1, 3) * np.pi / 10
    discrete = c / 0.1 * np.sqrt(6 * (1 - np.cos(kh)) / (2 + np.cos(kh)))
    assert w[0] < 1e-3 * exact[0]  # rigid axial motion
    np.testing.assert_allclose(w[1:3], discrete, rtol=1e-9)
    np.testing.assert_allclose(w[1:3], exact, rtol=0.02)  # and close to the continuum


def test_axial_load_compresses_bar_between_no_axial_support():
    r = _rotor(1.0)
    with pytest.raises(ValueError, match="singular"):
        solve_static(r)  # nothing holds the shaft axially: reported, not a garbage answer


def test_axial_mode_shape_is_stored_and_drawn(tmp_path):
    """Issue 21 item 7: the axial mode keeps its axial component.  Free-free bar (the lateral bearings
    hold nothing axially): the first elastic axial mode of N equal linear elements is cos(pi z / L) at
    the nodes, exactly (it satisfies the element recurrence and both free ends), at the discrete
    frequency of test_axial_bar_free_free_frequencies; modal.h5 holds it under dof "z" and
    modal_shapes.png draws it."""
    import h5py

    from spindlesim.output.hdf5 import RunInfo
    from spindlesim.output.rotor_plots import modes_figure
    from spindlesim.output.rotor_writers import write_modal

    r = _rotor(1e-300)
    m = solve_modal(r, n_modes=30)
    k = list(m.whirl).index("axial")
    c = np.sqrt(211e9 / 7810)
    kh = np.pi / 10
    assert m.undamped_frequency_hz[k] * 2 * np.pi == pytest.approx(c / 0.1 * np.sqrt(6 * (1 - np.cos(kh)) / (2 + np.cos(kh))),
                                                                  rel=1e-9)
    z = m.mode_shape[k, :, 4]
    exact = np.cos(np.pi * r.node_z_m / 1.0)
    np.testing.assert_allclose(z, exact * np.sign(z[0].real), atol=1e-9)
    assert np.max(np.abs(m.mode_shape[k, :, :2])) < 1e-6  # no lateral part
    path = write_modal(tmp_path / "modal.h5", RunInfo("deck", "test", "0"), m)
    with h5py.File(path) as f:
        dofs = list(f["modal/dof"][:].astype(str))
        assert dofs == ["x", "y", "theta_x", "theta_y", "z"]
        np.testing.assert_allclose(f["modal/mode_shape"][k, :, dofs.index("z")], z)
    fig = modes_figure(m, max_modes=k + 1)
    drawn = [ln for ln in fig.axes[k].lines if ln.get_label().startswith("z")]
    assert len(drawn) == 1
    np.testing.assert_allclose(drawn[0].get_ydata(), z.real[np.argsort(r.node_z_m, kind="stable")])
