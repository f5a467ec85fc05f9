"""The output contract of every HDF5 file (docs/output-format.md): xarray opens every group with
coordinates, units are UDUNITS strings, no NaN/Inf unless declared as fill, provenance, file modes."""

import logging
import os
import stat

import h5py
import numpy as np
import pytest

from spindlesim.output.hdf5 import Data, RunInfo, labels, write_h5

xr = pytest.importorskip("xarray")
pytest.importorskip("h5netcdf")

RUN = RunInfo("deck: text", "<test>", "0" * 64)
PROVENANCE = ("spindlesim_version", "created_utc", "platform", "python_version", "numpy_version", "scipy_version",
              "h5py_version", "numba_version", "deck_sha256", "deck_text", "deck_source", "command_line", "complete")
#: every unit the files use; each parses in UDUNITS-2 (cf-units) and in pint
UNITS = {"1", "m", "m/s", "s", "Hz", "rpm", "rad", "rad/m", "degree", "degC", "N", "N m", "N/m", "m/N", "N s/m",
         "N/rad", "N m/m", "N m/rad", "1/s", "Pa", "Pa s", "W", "m^3/s", "um", "megarevolution"}

CHATTER = """
chatter:
  operation: milling
  speeds_rpm: {start: 4000, stop: 12000, count: 12}
  Kt_N_mm2: 767.0
  Kn_N_mm2: 168.8
  teeth: 2
  tool_diameter_mm: 20.0
  radial_depth_mm: 20.0
  mode: down
  frf: rotor
"""

#: analysis -> (deck, options, text appended to the deck)
CASES = {
    "static": ("spindle_linear", {}, ""),
    "modal": ("spindle_linear", {"plots": False}, ""),
    "campbell": ("spindle_linear", {"speeds_rpm": [0.0, 6000.0, 12000.0], "plots": False}, ""),
    "frf": ("spindle_linear", {"plots": False}, ""),
    "unbalance": ("spindle_linear", {"plots": False}, ""),
    "thermal": ("spindle", {}, ""),
    "coefficients": ("spindle", {}, ""),
    "transient": ("transient", {"duration_s": 0.03, "plots": False}, ""),
    "bearing": ("bearing", {"plots": False}, ""),
    "dtrb": ("dtrb", {}, ""),
    "contact": ("contact", {"nx": 24, "ny": 48}, ""),
    "chatter": ("spindle_linear", {"simulate": [(8000.0, 0.5)]}, CHATTER),
}

#: analysis -> (group, data variable, {coordinate: label to select}) for the .sel check
SELECT = {
    "static": ("static", "displacement_m", {"node": 1, "dof": "x"}),
    "modal": ("modal", "mode_shape", {"mode": 1, "node": 1, "dof": "theta_x"}),
    "campbell": ("campbell", "frequency_hz", {"speed_rpm": 6000.0, "mode": 1}),
    "frf": ("frf", "receptance_m_N", {"frequency_hz": None}),
    "unbalance": ("unbalance", "response_m", {"speed_rpm": None, "node": 1, "dof": "y"}),
    "thermal": ("thermal/front", "journal_position_m", {"dof": "y"}),
    "coefficients": ("coefficients/front", "K_N_m", {"load": "Fx", "dof": "x"}),
    "transient": ("transient", "displacement_m", {"time_s": None, "dof": "x"}),
    "bearing": ("bearing/sweeps/load", "stiffness", {"fx_N": None, "load": "Fx", "dof": "x"}),
    "dtrb": ("dtrb/preload_sweep", "KXX_N_m", {"preload_m": None}),
    "contact": ("contact", "pressure_Pa", {"x_m": None, "y_m": None}),
    "chatter": ("chatter", "limit_depth_m", {"speed_rpm": None}),
}


@pytest.fixture
def umask022():
    old = os.umask(0o022)
    yield
    os.umask(old)


@pytest.fixture(scope="module")
def outputs(tmp_path_factory):
    """analysis -> (its .h5 file, every file it wrote), written once under umask 022."""
    from spindlesim.deck import default_deck, parse_deck
    from spindlesim.runs import run_analysis

    cache = {}

    def get(name):
        if name not in cache:
            deck, opts, extra = CASES[name]
            loaded = default_deck(deck)
            if extra:
                loaded = parse_deck(loaded.text + extra, f"{deck}.yaml")
            out = tmp_path_factory.mktemp(name)
            old = os.umask(0o022)
            try:
                paths = run_analysis(name, loaded, out, opts)
            finally:
                os.umask(old)
            cache[name] = (out / f"{name}.h5", paths)
        return cache[name]

    return get


def _groups(path):
    out = []
    with h5py.File(path, "r") as f:
        f.visititems(lambda n, o: out.append(n) if isinstance(o, h5py.Group) else None)
    return out


def _datasets(path):
    out = {}
    with h5py.File(path, "r") as f:
        f.visititems(lambda n, o: out.update({n: (o[()], dict(o.attrs))}) if isinstance(o, h5py.Dataset) else None)
    return out


@pytest.mark.parametrize("name", list(CASES))
def test_file_contract(outputs, name):
    path, paths = outputs(name)
    for p in paths:  # written under umask 022: readable by everyone, like any file the user creates
        assert stat.S_IMODE(os.stat(p).st_mode) == 0o644, p
    assert not list(path.parent.glob("*.tmp*"))
    with h5py.File(path, "r") as f:
        for key in PROVENANCE:
            assert key in f.attrs, key
        assert str(f.attrs["created_utc"]).endswith("+00:00")
    for ds_name, (value, attrs) in _datasets(path).items():
        units = attrs["units"]
        units = units.decode() if isinstance(units, bytes) else str(units)
        if units == "":
            comp = np.asarray(attrs["component_units"]).astype(str)
            assert set(comp.ravel()) <= UNITS, (ds_name, comp)
        else:
            assert units in UNITS, (ds_name, units)
        v = np.asarray(value)
        if v.dtype.kind in "fc":
            assert not np.isinf(v).any(), ds_name
            if np.isnan(v).any():
                assert "_FillValue" in attrs and np.isnan(attrs["_FillValue"]), ds_name
    for group in _groups(path):
        with xr.open_dataset(path, group=group, engine="h5netcdf") as ds:
            missing = [d for d in ds.sizes if d not in ds.coords]
            assert not missing, (group, missing)
            assert not [d for d in ds.sizes if str(d).startswith("phony_dim")]


@pytest.mark.parametrize("name", list(SELECT))
def test_select_by_coordinate(outputs, name):
    path, _ = outputs(name)
    group, var, where = SELECT[name]
    with xr.open_dataset(path, group=group, engine="h5netcdf") as ds:
        sel = {k: (ds[k].values[len(ds[k]) // 2] if v is None else v) for k, v in where.items()}
        picked = ds[var].sel(sel)
        assert picked.ndim == ds[var].ndim - len(sel)
        with h5py.File(path, "r") as f:
            raw = f[f"{group}/{var}"][()]
            index = tuple(int(np.flatnonzero(ds[d].values == sel[d])[0]) if d in sel else slice(None)
                          for d in ds[var].dims)
            np.testing.assert_array_equal(picked.values, raw[index])


def test_mixed_units_and_labels(outputs):
    path, _ = outputs("bearing")
    with xr.open_dataset(path, group="bearing", engine="h5netcdf") as ds:
        k = ds["stiffness"]
        assert k.attrs["units"] == "" and list(ds["load"].values) == ["Fx", "Fy", "Fz", "Mx", "My"]
        units = np.asarray(k.attrs["component_units"])
        assert units[0, 0] == "N/m" and units[0, 3] == "N/rad" and units[3, 0] == "N m/m" and units[3, 4] == "N m/rad"
        assert list(ds["displacement"].attrs["component_units"]) == ["m", "m", "m", "rad", "rad"]


def test_campbell_untracked_modes_are_fill(tmp_path, umask022):
    from spindlesim.analysis.results import CampbellResult
    from spindlesim.output.rotor_writers import write_campbell

    F = np.array([[100.0, 200.0], [101.0, np.nan]])
    r = CampbellResult(np.array([0.0, 1000.0]), F, F * 0, F * 0, np.array([["forward", "backward"], ["forward", ""]]),
                       np.zeros(0), np.zeros(0, int))
    path = write_campbell(tmp_path / "campbell.h5", RUN, r, frozen=r, frozen_rpm=0.0)
    with xr.open_dataset(path, group="campbell/frozen", engine="h5netcdf") as ds:
        assert np.isnan(ds.frequency_hz.sel(speed_rpm=1000.0, mode=2))
        assert ds.frequency_hz.encoding["_FillValue"] != ds.frequency_hz.encoding["_FillValue"]  # NaN
    assert stat.S_IMODE(os.stat(path).st_mode) == 0o644


# ----------------------------------------------------------------------------------------------
# write_h5 itself


def test_refuses_inf_and_undeclared_nan(tmp_path):
    path = tmp_path / "x.h5"
    with pytest.raises(ValueError, match=r"/g/a has 1 infinite"):
        write_h5(path, RUN, {"/g/a": (np.array([1.0, np.inf]), "m", ("i",))})
    with pytest.raises(ValueError, match=r"/g/a has 1 NaN .* does not declare NaN"):
        write_h5(path, RUN, {"/g/a": (np.array([1.0, np.nan]), "m", ("i",))})
    with pytest.raises(ValueError, match=r"/g/c has 1 infinite"):  # Inf even where NaN is a fill value
        write_h5(path, RUN, {"/g/c": Data(np.array([np.inf, np.nan]), "m", ("i",), fill_nan=True)})
    with pytest.raises(ValueError, match=r"attribute 'speed_rpm' of /g"):
        write_h5(path, RUN, {"/g/a": (np.ones(2), "m", ("i",))}, {"/g": {"speed_rpm": float("nan")}})
    with pytest.raises(ValueError, match=r"infinite"):
        write_h5(path, RUN, {"/g/z": (np.array([1 + 1j, complex(np.inf, 0)]), "m/N", ("i",))})
    assert not list(tmp_path.iterdir())  # nothing written, no temporary left


def test_declared_nan_fill_is_written(tmp_path):
    path = write_h5(tmp_path / "x.h5", RUN, {
        "/g/speed_rpm": (np.array([1.0, 2.0]), "rpm", ("speed_rpm",)),
        "/g/limit_m": Data(np.array([1e-3, np.nan]), "m", ("speed_rpm",), "NaN: none", fill_nan=True)})
    with h5py.File(path) as f:
        assert np.isnan(f["g/limit_m"].attrs["_FillValue"]) and np.isnan(f["g/limit_m"].fillvalue)
    with xr.open_dataset(path, group="g", engine="h5netcdf") as ds:
        assert float(ds.limit_m.sel(speed_rpm=1.0)) == 1e-3 and ds.limit_m.attrs["description"] == "NaN: none"


def test_incomplete_run_may_hold_nonfinite(tmp_path, caplog):
    run = RunInfo("d", "<test>", "0" * 64, complete=False, incomplete_reason="interrupted")
    with caplog.at_level(logging.WARNING, logger="spindlesim.output.hdf5"):
        path = write_h5(tmp_path / "x.h5", run, {"/g/a": (np.array([1.0, np.nan]), "m", ("i",))})
    assert "incomplete" in caplog.text and "/g/a" in caplog.text
    with h5py.File(path) as f:
        assert not f.attrs["complete"]


def test_dimensions_and_index_coordinates(tmp_path):
    path = write_h5(tmp_path / "x.h5", RUN, {
        "/g/frequency_hz": (np.array([1.0, 2.0, 3.0]), "Hz", ("frequency_hz",)),
        "/g/H": (np.ones((3, 2, 4), complex), "m/N", ("frequency_hz", "dof", "mode")),
        "/g/scalar": (2.5, "W", ()),
        "/g/legacy": (np.arange(2.0), "m"),  # no dimension names: written as before
        **labels("/g", "dof", ("x", "y")),
    })
    with h5py.File(path) as f:
        assert list(f["g/mode"][()]) == [1, 2, 3, 4] and f["g/mode"].attrs["units"] == "1"
        assert f["g/frequency_hz"].is_scale and f["g/dof"].is_scale
    with xr.open_dataset(path, group="g", engine="h5netcdf", phony_dims="sort") as ds:
        assert ds.H.dims == ("frequency_hz", "dof", "mode")
        assert ds.H.sel(frequency_hz=2.0, dof="y", mode=4).values == 1
        assert float(ds.scalar) == 2.5
    with pytest.raises(ValueError, match="dimension name"):
        write_h5(tmp_path / "y.h5", RUN, {"/g/a": (np.ones((2, 2)), "m", ("i",))})
    with pytest.raises(ValueError, match="dimension 'i'"):
        write_h5(tmp_path / "y.h5", RUN, {"/g/a": (np.ones(2), "m", ("i",)), "/g/b": (np.ones(3), "m", ("i",))})


@pytest.mark.parametrize("mask, mode", [(0o022, 0o644), (0o077, 0o600), (0o002, 0o664)])
def test_files_follow_the_umask(tmp_path, mask, mode):
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


def test_command_exits_1_naming_the_dataset(tmp_path, monkeypatch):
    """A solver result with NaN where none may be: exit 1, one line naming the dataset, no file."""
    import dataclasses

    from click.testing import CliRunner

    import spindlesim.analysis.static as static
    from spindlesim.cli import main

    solve = static.solve_static

    def broken(*args, **kwargs):
        r = solve(*args, **kwargs)
        return dataclasses.replace(r, bearing_force_N=np.full_like(r.bearing_force_N, np.nan))

    monkeypatch.setattr(static, "solve_static", broken)
    res = CliRunner().invoke(main, ["static", "-o", str(tmp_path)])
    assert res.exit_code == 1
    assert "/static/bearing_force_N" in res.output and "NaN" in res.output
    assert not list(tmp_path.glob("*.h5*"))
