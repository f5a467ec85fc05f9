"""Measured FRF files: CSV and UFF 58 round trips, merging, and errors naming file, line and problem."""

import numpy as np
import pytest

from spindlesim.chatter import FrfFileError, Mode, ToolPointFrf, ToolPointModel, combine_frfs, read_frf, write_frf_csv
from spindlesim.chatter.readers import read_frf_csv, read_frf_uff


@pytest.fixture
def pyuff():
    return pytest.importorskip("pyuff")


def _frf(coupled: bool = True) -> ToolPointFrf:
    model = ToolPointModel.from_modes([Mode("x", 650.0, 0.035, 2.2e7), Mode("y", 720.0, 0.03, 2.6e7)])
    f = np.linspace(50.0, 2000.0, 391)
    H = model.receptance(2 * np.pi * f)
    if coupled:
        H[:, 0, 1] = 0.1 * H[:, 0, 0]
        H[:, 1, 0] = -0.2j * H[:, 1, 1]
    return ToolPointFrf(f, H, "synthetic")


def test_csv_round_trip_all_terms(tmp_path):
    frf = _frf()
    p = tmp_path / "tool.csv"
    write_frf_csv(p, frf)
    back = read_frf(p, "csv")
    assert np.array_equal(back.frequency_hz, frf.frequency_hz)
    assert np.array_equal(back.H, frf.H)  # repr() of floats: exact
    assert "tool.csv" in back.source


def test_csv_single_direction_files_and_merge(tmp_path):
    frf = _frf(coupled=False)
    write_frf_csv(tmp_path / "x.csv", frf, direction="x")
    write_frf_csv(tmp_path / "y.csv", frf, direction="y")
    fx = read_frf(tmp_path / "x.csv", "csv", direction="x")
    assert np.all(fx.H[:, 1, 1] == 0) and np.array_equal(fx.H[:, 0, 0], frf.H[:, 0, 0])
    both = combine_frfs([fx, read_frf(tmp_path / "y.csv", "csv", direction="y")])
    assert np.array_equal(both.H, frf.H)
    # a y file on another grid is interpolated onto the x frequencies within the common band
    fine = ToolPointFrf(np.linspace(40.0, 2100.0, 4121), _frf(False).H[:1].repeat(4121, 0) * 0 + 1e-7)
    merged = combine_frfs([fx, fine])
    assert np.allclose(merged.H[:, 1, 1], 1e-7) and len(merged.frequency_hz) == len(fx.frequency_hz)


def test_csv_header_case_comments_and_column_order(tmp_path):
    p = tmp_path / "t.csv"
    p.write_text("# tap test, x\n\nImag_m_N, Frequency_Hz ,real_m_N\n-1e-6,100,2e-7\n-2e-6,110,1e-7\n")
    frf = read_frf_csv(p, "y")
    assert frf.frequency_hz.tolist() == [100.0, 110.0]
    assert frf.H[1, 1, 1] == pytest.approx(1e-7 - 2e-6j)


@pytest.mark.parametrize("text, direction, line, fragment", [
    ("frequency_hz,real_m_N,imag_m_N\n100,1e-7,-1e-6\n110,abc,-1e-6\n", "x", 3, "real_m_n: 'abc' is not a number"),
    ("frequency_hz,real_m_N,imag_m_N\n100,1e-7,-1e-6\n110,1e-7\n", "x", 3, "2 fields, the header has 3"),
    ("frequency_hz,real_m_N,imag_m_N\n100,1e-7,-1e-6\n# c\n90,1e-7,-1e-6\n", "x", 4, "does not increase"),
    ("freq,real_m_N,imag_m_N\n100,1e-7,-1e-6\n", "x", 1, "no 'frequency_hz' column"),
    ("frequency_hz,real_m_N,imag_m_N\n100,1e-7,-1e-6\n110,1e-7,-1e-6\n", None, 1, "needs its direction"),
    ("frequency_hz,xx_real_m_N,xx_imag,yy_real_m_N\n", None, 1, "unknown column(s) xx_imag"),
    ("frequency_hz,xx_real_m_N,yy_real_m_N,yy_imag_m_N\n", None, 1, "xx_imag_m_N is missing"),
    ("frequency_hz,real_m_N,imag_m_N\n100,1e-7,nan\n110,1e-7,-1e-6\n", "x", 2, "not finite"),
    ("frequency_hz,real_m_N,imag_m_N\n100,1e-7,-1e-6\n", "x", 2, "at least two are needed"),
    ("# tap\nfrequency_hz,real_m_N,imag_m_N\n", "x", 2, "0 data row(s); at least two are needed (a header but no rows)"),
    ("# nothing\n", "x", None, "empty file"),
])
def test_csv_errors_name_file_line_and_problem(tmp_path, text, direction, line, fragment):
    p = tmp_path / "bad.csv"
    p.write_text(text)
    with pytest.raises(FrfFileError) as err:
        read_frf_csv(p, direction)
    assert err.value.line == line
    assert fragment in str(err.value)
    assert str(err.value).startswith(str(p) + (f":{line}:" if line else ":"))


def _uff58(pyuff, path, f, H, kind=8, units="m/N", binary=0):
    sets = []
    w = 2 * np.pi * f
    factor = {8: 1.0, 11: 1j * w, 12: -(w**2)}[kind]
    for (i, j) in ((0, 0), (1, 1), (0, 1), (1, 0)):
        sets.append(pyuff.prepare_58(
            binary=binary, func_type=4, rsp_node=1, rsp_dir=i + 1, ref_node=1, ref_dir=j + 1,
            data=H[:, i, j] * factor, x=f, id1=f"H{i}{j}", rsp_ent_name="tool", ref_ent_name="tool",
            abscissa_spacing=0, abscissa_spec_data_type=18, ordinate_spec_data_type=kind,
            orddenom_spec_data_type=13, ordinate_axis_units_lab=units))
    pyuff.UFF(str(path)).write_sets(sets, mode="overwrite")


@pytest.mark.parametrize("kind", [8, 12])
def test_uff58_round_trip_receptance_and_accelerance(tmp_path, kind, pyuff):
    frf = _frf()
    p = tmp_path / "tool.uff"
    _uff58(pyuff, p, frf.frequency_hz, frf.H, kind)
    back = read_frf(p, "uff")
    assert np.allclose(back.frequency_hz, frf.frequency_hz, rtol=1e-12)
    assert np.allclose(back.H, frf.H, rtol=1e-9, atol=1e-9 * np.abs(frf.H).max())
    only_x = read_frf(p, "uff", direction="x")
    assert np.all(only_x.H[:, 1, 1] == 0) and np.allclose(only_x.H[:, 0, 0], frf.H[:, 0, 0], rtol=1e-9)


def test_uff58_units_label_mm_per_newton(tmp_path, pyuff):
    frf = _frf()
    p = tmp_path / "mm.uff"
    _uff58(pyuff, p, frf.frequency_hz, frf.H * 1e3, 8, units="mm/N")
    assert np.allclose(read_frf_uff(p).H, frf.H, rtol=1e-9)


def test_uff_errors(tmp_path, pyuff):
    with pytest.raises(FrfFileError, match="no such file"):
        read_frf_uff(tmp_path / "missing.uff")
    p = tmp_path / "time.uff"
    x = np.linspace(0, 1, 11)
    ds = pyuff.prepare_58(func_type=1, rsp_node=1, rsp_dir=1, ref_node=1, ref_dir=1, data=np.sin(x), x=x,
                          id1="time", rsp_ent_name="a", ref_ent_name="a", abscissa_spacing=1,
                          abscissa_spec_data_type=17, ordinate_spec_data_type=8, orddenom_spec_data_type=13,
                          )
    pyuff.UFF(str(p)).write_sets([ds], mode="overwrite")
    with pytest.raises(FrfFileError, match="no dataset 58 FRF"):
        read_frf_uff(p)
    q = tmp_path / "vel.uff"
    frf = _frf()
    _uff58(pyuff, q, frf.frequency_hz, frf.H, 8)
    text = q.read_text().splitlines()
    # make the second dataset's abscissa a time axis (record 8, first field 18 -> 17)
    starts = [i for i, s in enumerate(text) if s.strip() == "-1"][::2]
    rec8 = starts[1] + 9
    text[rec8] = text[rec8].replace("18", "17", 1)
    q.write_text("\n".join(text) + "\n")
    with pytest.raises(FrfFileError) as err:
        read_frf_uff(q)
    assert err.value.line == starts[1] + 1 and "abscissa type 17" in str(err.value)


def test_csv_coherence_column_and_window_decay(tmp_path):
    """An optional coherence column (single-direction layout: `coherence`; all directions: `xx_coherence` ...) and
    the `# exponential_window_decay_1_s: D` comment are read, carried through band, interpolation, the single
    direction writer and combine_frfs; files without them read as before (coherence None, decay 0)."""
    p = tmp_path / "tap.csv"
    p.write_text("# a tap test\n# exponential_window_decay_1_s: 4.5\nfrequency_hz,real_m_N,imag_m_N,coherence\n"
                 "100,1e-7,-1e-6,0.5\n110,2e-7,-2e-6,0.9\n120,3e-7,-3e-6,1.0\n")
    fy = read_frf_csv(p, "y")
    assert fy.coherence.shape == (3, 2, 2) and fy.coherence[:, 1, 1].tolist() == [0.5, 0.9, 1.0]
    assert np.isnan(fy.coherence[:, 0, 0]).all() and fy.window_decay_1_s == (0.0, 4.5)
    assert fy.band(105.0, 125.0).coherence[:, 1, 1].tolist() == [0.9, 1.0]
    assert fy.interpolated(np.array([105.0])).coherence[0, 1, 1] == \
        pytest.approx(0.7)
    q = tmp_path / "back.csv"
    write_frf_csv(q, fy, direction="y")
    back = read_frf_csv(q, "y")
    assert np.array_equal(back.coherence[:, 1, 1], fy.coherence[:, 1, 1]) and back.window_decay_1_s == (0.0, 4.5)
    x = tmp_path / "x.csv"
    x.write_text("frequency_hz,real_m_N,imag_m_N\n100,1e-7,-1e-6\n110,2e-7,-2e-6\n120,3e-7,-3e-6\n")
    fx = read_frf_csv(x, "x")
    assert fx.coherence is None and fx.window_decay_1_s == (0.0, 0.0)
    both = combine_frfs([fx, fy])
    assert both.window_decay_1_s == (0.0, 4.5) and np.isnan(both.coherence[:, 0, 0]).all()
    assert both.coherence[:, 1, 1].tolist() == [0.5, 0.9, 1.0]
    a = tmp_path / "all.csv"
    a.write_text("frequency_hz,xx_real_m_N,xx_imag_m_N,xx_coherence\n100,1e-7,-1e-6,0.25\n110,2e-7,-2e-6,0.75\n")
    assert read_frf_csv(a).coherence[:, 0, 0].tolist() == [0.25, 0.75]


@pytest.mark.parametrize("text, line, fragment", [
    ("frequency_hz,real_m_N,imag_m_N,coherence\n100,1e-7,-1e-6,1.5\n110,1e-7,-1e-6,1\n", 2, "coherence: 1.5 is outside"),
    ("frequency_hz,xx_real_m_N,xx_imag_m_N,yy_coherence\n100,1e-7,-1e-6,1\n", 1, "yy_coherence without yy_real_m_N"),
    ("# exponential_window_decay_1_s: -2\nfrequency_hz,real_m_N,imag_m_N\n100,1,1\n110,1,1\n", 1, "must be finite and >= 0"),
    ("# exponential_window_decay_1_s: fast\nfrequency_hz,real_m_N,imag_m_N\n100,1,1\n110,1,1\n", 1, "is not a number"),
])
def test_csv_coherence_and_decay_errors(tmp_path, text, line, fragment):
    p = tmp_path / "bad.csv"
    p.write_text(text)
    with pytest.raises(FrfFileError) as err:
        read_frf_csv(p, "x")
    assert err.value.line == line and fragment in str(err.value)
