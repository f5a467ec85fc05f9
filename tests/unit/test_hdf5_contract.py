"""The HDF5 writer itself (spindlesim/output/hdf5.py, docs/output-format.md "Every HDF5 file"):
refusal of non-finite numbers before anything is written, NaN only where declared as fill, atomic
writes, dimension scales that xarray (h5netcdf) reads as coordinates, complex storage, provenance,
and file modes that follow the umask."""

import datetime
import logging
import os
import platform
import stat

import h5py
import numpy as np
import pytest

from spindlesim.output import hdf5
from spindlesim.output.hdf5 import Data, RunInfo, labels, write_h5

xr = pytest.importorskip("xarray")
pytest.importorskip("h5netcdf")

RUN = RunInfo("deck: text", "<test>", "0" * 64)


def _files(folder):
    return sorted(p.name for p in folder.iterdir())


# ----------------------------------------------------------------------------------------------
# non-finite numbers


@pytest.mark.parametrize("datasets, attrs, message", [
    ({"/g/a": (np.array([1.0, np.inf]), "m", ("i",))}, None, r"/g/a has 1 infinite value\(s\) of 2"),
    ({"/g/a": (np.array([1.0, np.nan]), "m", ("i",))}, None, r"/g/a has 1 NaN value\(s\) of 2 and does not declare"),
    # Inf is refused even where NaN is the declared fill value
    ({"/g/c": Data(np.array([np.inf, np.nan]), "m", ("i",), fill_nan=True)}, None, r"/g/c has 1 infinite"),
    # complex: a non-finite real or imaginary part
    ({"/g/z": (np.array([1 + 1j, complex(np.inf, 0)]), "m/N", ("i",))}, None, r"/g/z has 1 infinite"),
    ({"/g/z": (np.array([1 + 1j, complex(0, np.nan)]), "m/N", ("i",))}, None, r"/g/z has 1 NaN"),
    ({"/g/s": (float("nan"), "W", ())}, None, r"/g/s has 1 NaN"),
    ({"/g/a": (np.ones(2), "m", ("i",))}, {"/g": {"speed_rpm": float("nan")}}, r"attribute 'speed_rpm' of /g"),
    ({"/g/a": (np.ones(2), "m", ("i",))}, {"/g": {"limits": [1.0, float("inf")]}}, r"attribute 'limits' of /g"),
], ids=["inf", "nan", "inf-in-fill", "complex-inf", "complex-nan", "scalar-nan", "attr-nan", "attr-list-inf"])
def test_complete_run_refuses_non_finite(tmp_path, datasets, attrs, message):
    """"refusing to write non-finite results: <dataset> has ..." and nothing on disk, no temporary."""
    with pytest.raises(ValueError, match=r"x\.h5: refusing to write non-finite results: " + message):
        write_h5(tmp_path / "x.h5", RUN, datasets, attrs)
    assert _files(tmp_path) == []


def test_refusal_counts_the_other_problems(tmp_path):
    with pytest.raises(ValueError, match=r"/g/a has 1 infinite .*\(and 1 more\)"):
        write_h5(tmp_path / "x.h5", RUN, {"/g/a": (np.array([np.inf]), "m", ("i",)),
                                          "/g/b": (np.array([np.nan]), "m", ("i",))})


def test_refusal_keeps_the_previous_file(tmp_path):
    """A refused write leaves an earlier complete file of the same name as it was."""
    path = write_h5(tmp_path / "x.h5", RUN, {"/g/a": (np.array([1.0, 2.0]), "m", ("i",))})
    before = path.read_bytes()
    with pytest.raises(ValueError):
        write_h5(path, RUN, {"/g/a": (np.array([1.0, np.nan]), "m", ("i",))})
    assert path.read_bytes() == before and _files(tmp_path) == ["x.h5"]


def test_failure_while_writing_leaves_no_file(tmp_path, monkeypatch):
    """An error after the temporary file is open (here: attaching the scales) removes it; the
    target name never appears."""
    def boom(*args):
        raise RuntimeError("disk full")

    monkeypatch.setattr(hdf5, "_attach_scales", boom)
    with pytest.raises(RuntimeError, match="disk full"):
        write_h5(tmp_path / "x.h5", RUN, {"/g/a": (np.ones(2), "m", ("i",))})
    assert _files(tmp_path) == []


def test_declared_nan_fill_is_written(tmp_path):
    path = write_h5(tmp_path / "x.h5", RUN, {
        "/g/speed_rpm": (np.array([1.0, 2.0]), "rpm", ("speed_rpm",)),
        "/g/limit_m": Data(np.array([1e-3, np.nan]), "m", ("speed_rpm",), "NaN: none", fill_nan=True)})
    with h5py.File(path) as f:
        assert np.isnan(f["g/limit_m"].attrs["_FillValue"]) and np.isnan(f["g/limit_m"].fillvalue)
        assert "_FillValue" not in f["g/speed_rpm"].attrs
    with xr.open_dataset(path, group="g", engine="h5netcdf") as ds:
        assert float(ds.limit_m.sel(speed_rpm=1.0)) == 1e-3 and np.isnan(ds.limit_m.sel(speed_rpm=2.0))
        assert ds.limit_m.attrs["description"] == "NaN: none"


def test_sweep_scalars_are_nan_fill_by_pattern(tmp_path):
    """/sweep/scalars/* and /sweep/elapsed_s (written by the sweep summary) may hold NaN: a case
    without that value."""
    path = write_h5(tmp_path / "sweep.h5", RUN, {
        "/sweep/scalars/modal.f1_hz": (np.array([100.0, np.nan]), "Hz", ("case",)),
        "/sweep/elapsed_s": (np.array([np.nan, 1.0]), "s", ("case",))})
    with h5py.File(path) as f:
        assert np.isnan(f["sweep/scalars/modal.f1_hz"].attrs["_FillValue"])
    with pytest.raises(ValueError, match="/sweep/status_code has 1 NaN"):
        write_h5(tmp_path / "sweep.h5", RUN, {"/sweep/status_code": (np.array([np.nan]), "1", ("case",))})


def test_incomplete_run_may_hold_non_finite(tmp_path, caplog):
    run = RunInfo("d", "<test>", "0" * 64, complete=False, incomplete_reason="interrupted")
    with caplog.at_level(logging.WARNING, logger="spindlesim.output.hdf5"):
        path = write_h5(tmp_path / "x.h5", run, {"/g/a": (np.array([1.0, np.nan]), "m", ("i",))})
    assert "incomplete" in caplog.text and "/g/a" in caplog.text
    with h5py.File(path) as f:
        assert not f.attrs["complete"] and f.attrs["incomplete_reason"] == "interrupted"


# ----------------------------------------------------------------------------------------------
# dimensions, units, complex


def test_dimensions_and_index_coordinates(tmp_path):
    path = write_h5(tmp_path / "x.h5", RUN, {
        "/g/frequency_hz": (np.array([1.0, 2.0, 3.0]), "Hz", ("frequency_hz",)),
        "/g/H": (np.arange(24).reshape(3, 2, 4) * (1 + 1j), "m/N", ("frequency_hz", "dof", "mode")),
        "/g/scalar": (2.5, "W", ()),
        **labels("/g", "dof", ("x", "y")),
    })
    with h5py.File(path) as f:
        # "mode" has no dataset of its own: an integer index 1..n with units "1"
        assert list(f["g/mode"][()]) == [1, 2, 3, 4] and f["g/mode"].attrs["units"] == "1"
        assert f["g/frequency_hz"].is_scale and f["g/dof"].is_scale and f["g/mode"].is_scale
        H = f["g/H"]
        assert [H.dims[i][0].name for i in range(3)] == ["/g/frequency_hz", "/g/dof", "/g/mode"]
    with xr.open_dataset(path, group="g", engine="h5netcdf") as ds:
        assert ds.H.dims == ("frequency_hz", "dof", "mode") and set(ds.coords) == {"frequency_hz", "dof", "mode"}
        assert ds.H.sel(frequency_hz=2.0, dof="y", mode=4).values == 15 * (1 + 1j)
        assert float(ds.scalar) == 2.5 and ds.scalar.attrs["units"] == "W"


def test_dimension_names_must_match(tmp_path):
    with pytest.raises(ValueError, match="1 dimension name"):
        write_h5(tmp_path / "y.h5", RUN, {"/g/a": (np.ones((2, 2)), "m", ("i",))})
    with pytest.raises(ValueError, match="dimension 'i'"):
        write_h5(tmp_path / "y.h5", RUN, {"/g/a": (np.ones(2), "m", ("i",)), "/g/b": (np.ones(3), "m", ("i",))})
    with pytest.raises(ValueError, match="not its 1-D coordinate"):
        write_h5(tmp_path / "y.h5", RUN, {"/g/a": (np.ones(2), "m", ("t",)), "/g/t": (np.ones((2, 1)), "s", ("t", "k"))})
    assert _files(tmp_path) == []


def test_units_description_and_component_units(tmp_path):
    path = write_h5(tmp_path / "x.h5", RUN, {
        "/g/k": Data(np.eye(2), "", ("load", "dof"), "K = -dF/dq", component_units=[["N/m", "N/rad"], ["N m/m", "N m/rad"]]),
        "/g/c": Data(np.ones(2), "N s/m", ("dof",), "damping"),
        **labels("/g", "dof", ("x", "theta")), **labels("/g", "load", ("Fx", "Mx")),
    })
    with xr.open_dataset(path, group="g", engine="h5netcdf") as ds:
        assert ds.c.attrs["units"] == "N s/m" and ds.c.attrs["description"] == "damping"
        assert ds.k.attrs["units"] == "" and ds.k.attrs["description"] == "K = -dF/dq"
        assert np.asarray(ds.k.attrs["component_units"]).tolist() == [["N/m", "N/rad"], ["N m/m", "N m/rad"]]
        assert list(ds.dof.values) == ["x", "theta"] and ds.dof.attrs["units"] == "1"


def test_complex_is_compound_r_i_and_reads_as_complex(tmp_path):
    """Complex data: an HDF5 compound of two float64 fields "r" and "i" (h5py's layout), read back
    as complex128 by h5py and by xarray through h5netcdf without invalid_netcdf."""
    z = np.array([1 + 2j, -3.5 - 0.25j, 1e-9j])
    path = write_h5(tmp_path / "x.h5", RUN, {"/g/f": (np.array([1.0, 2.0, 3.0]), "Hz", ("f",)),
                                             "/g/z": (z, "m/N", ("f",))})
    with h5py.File(path) as f:
        t = f["g/z"].id.get_type()
        assert isinstance(t, h5py.h5t.TypeCompoundID)
        assert [t.get_member_name(i) for i in range(t.get_nmembers())] == [b"r", b"i"]
        assert f["g/z"].dtype == np.complex128
    with xr.open_dataset(path, group="g", engine="h5netcdf") as ds:
        assert ds.z.dtype == np.complex128
        np.testing.assert_array_equal(ds.z.values, z)
        assert ds.z.sel(f=2.0).values == z[1]


# ----------------------------------------------------------------------------------------------
# provenance and file modes


def test_provenance(tmp_path):
    import numba
    import scipy

    import spindlesim

    before = datetime.datetime.now(datetime.timezone.utc).replace(microsecond=0)
    path = write_h5(tmp_path / "x.h5", RunInfo("deck: text", "deck.yaml", "ab" * 32, command_line="spindlesim x"),
                    {"/g/a": (np.ones(1), "m", ("i",))})
    after = datetime.datetime.now(datetime.timezone.utc)
    with h5py.File(path) as f:
        a = {k: (v.decode() if isinstance(v, bytes) else v) for k, v in f.attrs.items()}
    created = datetime.datetime.fromisoformat(a["created_utc"])
    assert created.utcoffset() == datetime.timedelta(0) and before <= created <= after
    assert a["platform"] == platform.platform() and a["python_version"] == platform.python_version()
    assert a["numpy_version"] == np.__version__ and a["scipy_version"] == scipy.__version__
    assert a["h5py_version"] == h5py.__version__ and a["numba_version"] == numba.__version__
    assert a["spindlesim_version"] == spindlesim.__version__
    assert (a["deck_text"], a["deck_source"], a["deck_sha256"], a["command_line"]) == (
        "deck: text", "deck.yaml", "ab" * 32, "spindlesim x")
    assert bool(a["complete"]) and "incomplete_reason" not in a


@pytest.mark.parametrize("mask, mode", [(0o022, 0o644), (0o077, 0o600), (0o002, 0o664)])
def test_files_follow_the_umask(tmp_path, mask, mode):
    """"0o666 less the umask", as open() would give, for HDF5 and PNG alike (mkstemp alone: 0600)."""
    from spindlesim.output.figures import new_figure, save_figure

    old = os.umask(mask)
    try:
        h5 = write_h5(tmp_path / "x.h5", RUN, {"/g/a": (np.ones(2), "m", ("i",))})
        fig = new_figure(2, 2)
        fig.subplots().plot([0, 1])
        png = save_figure(fig, tmp_path / "x.png", dpi=20)
    finally:
        os.umask(old)
    assert stat.S_IMODE(os.stat(h5).st_mode) == mode
    assert stat.S_IMODE(os.stat(png).st_mode) == mode
    assert _files(tmp_path) == ["x.h5", "x.png"]
