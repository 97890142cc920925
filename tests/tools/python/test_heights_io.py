"""scallop.read_heights() and write_heights(): GSF, EXR and X3P round trips, and the
files the CLI writes."""
import hashlib
import xml.etree.ElementTree as ET
import zipfile

import numpy as np
import pytest

import scallop
from conftest import ball_job, bull_job, write_job


@pytest.fixture(scope="module")
def result():
    return scallop.simulate(bull_job())


def test_write_heights_gsf_equals_the_cli_file_byte_for_byte(tmp_path, cli, result):
    job_file = write_job(tmp_path, bull_job())
    cli("simulate", job_file, "-o", tmp_path / "out", "--json")
    mine = tmp_path / "mine.gsf"
    scallop.write_heights(str(mine), result.heights, result.grid, title="scallop bull R=3 MM")
    assert mine.read_bytes() == (tmp_path / "out" / "heights.gsf").read_bytes()


@pytest.mark.parametrize("ext", [".gsf", ".exr"])
def test_round_trip(tmp_path, result, ext):
    path = str(tmp_path / ("h" + ext))
    scallop.write_heights(path, result.heights, result.grid)
    back, grid = scallop.read_heights(path)
    assert grid.nx == result.grid.nx and grid.ny == result.grid.ny
    assert not back.flags.owndata and isinstance(back.base, scallop.HeightBuffer)
    if ext == ".exr":
        # float32 mm, and the grid in double attributes: exact.
        assert grid == result.grid
        assert np.array_equal(back, result.heights.astype(np.float32))
    else:
        # float32 metres: to float precision; a second round trip changes nothing.
        assert grid.spacing == pytest.approx(result.grid.spacing, rel=1e-15)
        assert np.allclose(back, result.heights, rtol=1e-7, atol=0)
        again = str(tmp_path / "again.gsf")
        scallop.write_heights(again, back, grid)
        assert np.array_equal(scallop.read_heights(again)[0], back)


def test_write_x3p_holds_the_heights_in_metres(tmp_path, result):
    path = tmp_path / "h.x3p"
    scallop.write_heights(str(path), result.heights, result.grid, title="a test")
    with zipfile.ZipFile(path) as z:
        xml = z.read("main.xml")
        data = np.frombuffer(z.read("bindata/data.bin"), dtype="<f8")
        assert z.read("md5checksum.hex").decode().startswith(hashlib.md5(xml).hexdigest())
    root = ET.fromstring(xml)
    size = {e.tag.split("}")[-1]: int(e.text) for e in root.iter()
            if e.tag.split("}")[-1] in ("SizeX", "SizeY")}
    assert size == {"SizeX": result.grid.nx, "SizeY": result.grid.ny}
    # X3P's first row is the smallest y (ZMap order): the array's rows reversed.
    stored = data.reshape(result.grid.ny, result.grid.nx)
    assert np.array_equal(stored, result.heights[::-1] * 1e-3)


def test_x3p_round_trip(tmp_path, result):
    path = str(tmp_path / "h.x3p")
    scallop.write_heights(path, result.heights, result.grid)
    back, grid = scallop.read_heights(path)
    # float64 metres: back in mm is exactly (h * 1e-3) * 1e3.
    assert np.array_equal(back, (result.heights * 1e-3) * 1e3)
    assert (grid.nx, grid.ny) == (result.grid.nx, result.grid.ny)
    assert grid.spacing == pytest.approx(result.grid.spacing, rel=1e-15)
    assert grid.origin == pytest.approx(result.grid.origin, abs=1e-12)


def rewrite_x3p(src, dst, change):
    """Copies the X3P archive `src` to `dst`, members passed through change(name, bytes)."""
    with zipfile.ZipFile(src) as z, zipfile.ZipFile(dst, "w") as out:
        for name in z.namelist():
            data = change(name, z.read(name))
            if data is not None:
                out.writestr(name, data)


@pytest.mark.parametrize("change,message", [
    (lambda n, d: None if n == "main.xml" else d, "no main.xml in the X3P archive"),
    (lambda n, d: d[:-8] if n == "bindata/data.bin" else d, "bindata/data.bin is"),
    (lambda n, d: d[:-8] + d[-8:][::-1] if n == "bindata/data.bin" else d,
     "does not match main.xml's MD5ChecksumPointData"),
    (lambda n, d: d.replace(b"<SizeX>", b"<SizeX>x") if n == "main.xml" else d, "SizeX is"),
    (lambda n, d: d.replace(b"<FeatureType>SUR", b"<FeatureType>PRF") if n == "main.xml" else d,
     "FeatureType is not SUR"),
    (lambda n, d: d.replace(b"</SizeX>", b"") if n == "main.xml" else d,
     "main.xml is not well-formed XML"),
    (lambda n, d: d.replace(b"PointDataLink", b"PointLink") if n == "main.xml" else d,
     "main.xml has no PointDataLink element"),
])
def test_a_damaged_x3p_is_refused_naming_what_is_wrong(tmp_path, result, change, message):
    good = tmp_path / "good.x3p"
    scallop.write_heights(str(good), result.heights, result.grid)
    bad = tmp_path / "bad.x3p"
    rewrite_x3p(good, bad, change)
    with pytest.raises(scallop.InputError, match="bad.x3p: .*" + message.replace(".", r"\.")):
        scallop.read_heights(str(bad))
    (tmp_path / "not_zip.x3p").write_bytes(b"PK but not really")
    with pytest.raises(scallop.InputError, match="not_zip.x3p: cannot open the X3P"):
        scallop.read_heights(str(tmp_path / "not_zip.x3p"))


def test_write_heights_accepts_any_real_array_and_a_grid_dict(tmp_path):
    h = np.arange(12, dtype=np.int32).reshape(3, 4)
    path = str(tmp_path / "i.exr")
    scallop.write_heights(path, h, {"origin": [1.5, -2.0], "spacing": 0.25})
    back, grid = scallop.read_heights(path)
    assert np.array_equal(back, h)
    assert grid == scallop.Grid((1.5, -2.0), 0.25, 4, 3)
    assert grid.extent == (1.5, 2.5, -2.0, -1.25)
    assert np.array_equal(grid.x, [1.625, 1.875, 2.125, 2.375])
    assert np.array_equal(grid.y, [-1.375, -1.625, -1.875])


def test_io_errors_name_the_file_or_argument(tmp_path, result):
    h, g = result.heights, result.grid
    with pytest.raises(scallop.InputError, match="no_such.gsf: no such file"):
        scallop.read_heights(str(tmp_path / "no_such.gsf"))
    bad = tmp_path / "bad.gsf"
    bad.write_bytes(b"not a gsf file at all")
    with pytest.raises(scallop.InputError, match="bad.gsf"):
        scallop.read_heights(str(bad))
    with pytest.raises(scallop.InputError, match=r"h\.bmp: expected a file name ending in \.x3p"):
        scallop.write_heights(str(tmp_path / "h.bmp"), h, g)
    with pytest.raises(scallop.InputError, match="^heights: has the shape"):
        scallop.write_heights(str(tmp_path / "h.gsf"), h[:, 1:], g)
    with pytest.raises(scallop.InputError, match="^grid: expected a scallop.Grid"):
        scallop.write_heights(str(tmp_path / "h.gsf"), h, 0.5)
    with pytest.raises(scallop.InputError, match=r"^grid\.spacing: "):
        scallop.write_heights(str(tmp_path / "h.gsf"), h, {"origin": [0, 0], "spacing": 0})
    with pytest.raises(scallop.InputError, match=r"no_dir/h\.gsf"):
        scallop.write_heights(str(tmp_path / "no_dir" / "h.gsf"), h, g)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.gsf"]


def test_help_documents_every_function():
    for name in ("simulate", "interval", "stats", "read_heights", "write_heights"):
        doc = getattr(scallop, name).__doc__
        assert doc and len(doc) > 200, name
    assert "InputError" in scallop.__doc__ and scallop.InputError.__doc__
    assert issubclass(scallop.InputError, ValueError)
    for cls in (scallop.Result, scallop.Grid, scallop.HeightBuffer):
        assert cls.__doc__
    assert scallop.__version__


@pytest.mark.parametrize("ext,kept", [(".gsf", True), (".exr", True), (".x3p", False)])
def test_write_heights_keeps_the_frame_where_the_format_can(tmp_path, result, ext, kept):
    frame = "origin (1, 2, 3) mm, u (1, 0, 0), normal (0, 0, 1)"
    path = str(tmp_path / ("h" + ext))
    scallop.write_heights(path, result.heights, result.grid, frame=frame)
    heights, grid, back = scallop.read_heights(path, with_frame=True)
    assert back == (frame if kept else "")
    assert grid.nx == result.grid.nx and grid.ny == result.grid.ny
    scallop.write_heights(str(tmp_path / ("plain" + ext)), result.heights, result.grid)
    assert scallop.read_heights(str(tmp_path / ("plain" + ext)), with_frame=True)[2] == ""
