"""scallop.simulate(): the CLI's heights to the bit, its report, a view not a copy, bad
jobs, threads, progress and Ctrl-C."""
import gc
import json
import math
import os
import subprocess
import sys
import signal
import threading
import time

import numpy as np
import pytest

import scallop
from conftest import ball_job, bull_job, write_job


def read_gsf_metres(path):
    """heights.gsf read here, independently of the module: (header dict, float32 rows)."""
    data = path.read_bytes()
    end = data.index(b"\0")
    header = dict(line.split(" = ", 1) for line in data[:end].decode().splitlines()[1:])
    start = (end + 4) // 4 * 4  # 1-4 NUL bytes pad the header to a multiple of 4
    nx, ny = int(header["XRes"]), int(header["YRes"])
    return header, np.frombuffer(data[start:], dtype="<f4").reshape(ny, nx)


# --- The CLI's heights, bit for bit ---------------------------------------------------

@pytest.mark.parametrize("make_job", [ball_job, bull_job], ids=["ball", "bull-lead-tilt"])
def test_heights_equal_the_cli_gsf_bit_for_bit(tmp_path, cli, make_job):
    job_file = write_job(tmp_path, make_job())
    cli("simulate", job_file, "-o", tmp_path / "out", "--json")
    header, gsf = read_gsf_metres(tmp_path / "out" / "heights.gsf")

    r = scallop.simulate(str(job_file))
    assert r.heights.dtype == np.float64
    assert r.heights.shape == (r.grid.ny, r.grid.nx) == gsf.shape
    assert (int(header["XRes"]), int(header["YRes"])) == (r.grid.nx, r.grid.ny)
    # The GSF holds float32(height_mm * 1e-3); row 0 of both is the largest y.
    assert np.array_equal((r.heights * 1e-3).astype(np.float32), gsf)
    # Not a trivially flat map: the raster cut something.
    assert r.heights.min() < r.heights.max()


def test_heights_equal_the_cli_exr(tmp_path, cli):
    job_file = write_job(tmp_path, bull_job())
    cli("simulate", job_file, "-o", tmp_path / "out", "--json")
    exr, grid = scallop.read_heights(str(tmp_path / "out" / "heights.exr"))
    r = scallop.simulate(job_file)  # a pathlib.Path works as well as a str
    assert np.array_equal(r.heights.astype(np.float32), exr.astype(np.float32))
    assert grid == r.grid


def test_report_equals_the_cli_report(tmp_path, cli):
    job_file = write_job(tmp_path, bull_job())
    cli("simulate", job_file, "-o", tmp_path / "out", "--json")
    written = json.loads((tmp_path / "out" / "report.json").read_text())
    r = scallop.simulate(str(job_file))
    got = r.report
    assert got["outputs"] == []  # nothing written
    for doc in (written, got):
        del doc["timings_s"], doc["measurements"]["mcells_per_s"], doc["outputs"]
    assert got == written
    assert got["grid"]["nx"] == r.grid.nx and tuple(got["grid"]["origin"]) == r.grid.origin


def test_a_dict_job_equals_its_file(tmp_path):
    job = ball_job()
    from_dict = scallop.simulate(job)
    from_file = scallop.simulate(str(write_job(tmp_path, job)))
    assert np.array_equal(from_dict.heights, from_file.heights)
    assert from_dict.report["job_source"] == "job"
    assert from_dict.report["inputs"] == from_file.report["inputs"]


def test_heights_do_not_depend_on_the_thread_count():
    one = scallop.simulate(bull_job(), threads=1)
    two = scallop.simulate(bull_job(), threads=2)
    assert one.report["threads"] == 1 and two.report["threads"] == 2
    assert np.array_equal(one.heights, two.heights)


def test_row_zero_is_the_largest_y():
    # One pass along x at y = 0 (the stock's lower edge): the cut is in the last rows.
    job = ball_job(step_over=100)
    r = scallop.simulate(job)
    top = job["stock"]["max"][2]
    assert r.grid.y[0] > r.grid.y[-1]
    assert np.all(r.heights[0] == top)                 # y = 4.5 mm: untouched
    assert r.heights[-1].max() < top - 0.3             # y near 0: the pass's floor
    assert r.grid.x[0] < r.grid.x[-1]


# --- A view of the map, not a copy ----------------------------------------------------

def test_heights_are_a_view_of_the_result_map():
    r = scallop.simulate(ball_job())
    h = r.heights
    ny, nx = h.shape
    assert not h.flags.owndata
    assert isinstance(h.base, scallop.HeightBuffer)
    assert h.base.nbytes == h.nbytes == nx * ny * 8
    # Row 0 (largest y) is the ZMap's last stored row: a negative row stride, no copy.
    assert h.strides == (-nx * 8, 8)
    assert h.ctypes.data == h.base.address + (ny - 1) * nx * 8
    assert r.heights is h                 # the attribute holds the one view
    assert h.base.grid == r.grid


def test_writing_through_the_view_is_seen_by_a_second_view():
    r = scallop.simulate(ball_job())
    h = r.heights
    stored_order = h[::-1]                # a second view: rows in the ZMap's order
    assert np.shares_memory(h, stored_order)
    h[2, 3] = 123.25
    assert stored_order[h.shape[0] - 1 - 2, 3] == 123.25
    assert r.heights[2, 3] == 123.25


def test_the_view_keeps_the_map_alive():
    r = scallop.simulate(ball_job())
    expected = np.array(r.heights)        # a copy, for comparison only
    h = r.heights
    del r
    gc.collect()
    scallop.simulate(ball_job(spacing=0.03))  # reuse freed memory, if any were freed
    assert np.array_equal(h, expected)


def test_the_process_holds_one_map_not_two():
    # In a fresh process, so that the peak resident memory is this run's: a 112 MB map
    # raises it by one map (plus the small scene), where a copy would add a second.
    code = """if True:
        import resource, sys
        import scallop
        from conftest import bull_job
        before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
        r = scallop.simulate(bull_job(spacing=0.002))
        after = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
        print(r.heights.nbytes, after - before)
    """
    here = os.path.dirname(os.path.abspath(__file__))
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          cwd=here, check=True)
    map_bytes, growth = map(int, done.stdout.split())
    assert map_bytes == 14_000_000 * 8
    assert 0.9 * map_bytes < growth < 1.5 * map_bytes


# --- Bad jobs: InputError naming the field, nothing written ---------------------------

BAD_JOBS = [
    (lambda j: j["grid"].update(spacing=-1), "grid.spacing"),
    (lambda j: j["tool"].update(type="drill"), "tool.type"),
    (lambda j: j["tool"].update(radius=0), "tool.radius"),
    (lambda j: j["stock"].update(max=[0, 0, 0]), "stock"),
    (lambda j: j["path"]["raster"].update(step_over="wide"), "path.raster.step_over"),
    (lambda j: j.update(colour="red"), "colour"),
    (lambda j: j.update(path={"file": "no_such_path.nc"}), "no_such_path.nc"),
]


@pytest.mark.parametrize("spoil,field", BAD_JOBS, ids=[f for _, f in BAD_JOBS])
def test_a_bad_job_raises_input_error_naming_the_field_as_the_cli(tmp_path, monkeypatch, cli,
                                                                 spoil, field):
    job = ball_job()
    spoil(job)
    job_file = write_job(tmp_path, job)
    monkeypatch.chdir(tmp_path)
    before = sorted(p.name for p in tmp_path.iterdir())

    with pytest.raises(scallop.InputError) as from_dict:
        scallop.simulate(job)
    with pytest.raises(scallop.InputError) as from_file:
        scallop.simulate(job_file.name)  # as the CLI below is given it
    assert field in str(from_dict.value) and field in str(from_file.value)
    assert str(from_dict.value).startswith("job: ")
    assert isinstance(from_dict.value, ValueError)
    assert sorted(p.name for p in tmp_path.iterdir()) == before  # nothing written

    done = cli("simulate", job_file.name, "-o", "out", check=False)
    assert done.returncode == 1
    assert done.stderr.strip() == f"scallop: error: {from_file.value}"


def test_a_value_json_cannot_hold_is_named():
    job = ball_job()
    job["tool"]["radius"] = float("nan")
    with pytest.raises(scallop.InputError, match=r"^job: tool\.radius: is nan"):
        scallop.simulate(job)
    job = ball_job()
    job["stock"]["min"][1] = object()
    with pytest.raises(scallop.InputError, match=r"job: stock\.min\[1\]: is a object"):
        scallop.simulate(job)


def test_bad_arguments_are_input_errors():
    with pytest.raises(scallop.InputError, match="^threads: "):
        scallop.simulate(ball_job(), threads=0)
    with pytest.raises(scallop.InputError, match="^progress: "):
        scallop.simulate(ball_job(), progress=3)
    with pytest.raises(scallop.InputError, match="^method: "):
        scallop.simulate(ball_job(), method="guess")
    with pytest.raises(scallop.InputError, match="^job: "):
        scallop.simulate(42)
    with pytest.raises(scallop.InputError, match="no_such_job.json: cannot open"):
        scallop.simulate("no_such_job.json")


def test_quiet_by_default(capfd):
    scallop.simulate(ball_job())
    out, err = capfd.readouterr()
    assert out == "" and err == ""
    scallop.simulate(ball_job(), verbose=True)
    assert "ball cutter R=2 mm" in capfd.readouterr().err


# --- Progress and Ctrl-C --------------------------------------------------------------

def test_progress_reports_cells_up_to_the_total():
    calls = []
    r = scallop.simulate(bull_job(spacing=0.01), progress=lambda d, t: calls.append((d, t)))
    total = r.grid.nx * r.grid.ny
    assert calls and all(t == total for _, t in calls)
    assert [d for d, _ in calls] == sorted(d for d, _ in calls)
    assert calls[-1] == (total, total)


@pytest.fixture
def long_job(tmp_path):
    """A 5-axis run of ~10 s on two cores (300 000 cells under 450 turning moves, ~6
    exact evaluations a cell): long enough that an interrupt clearly cuts it short."""
    lines = []
    for k in range(11):
        for n in range(41):
            a = math.radians(15 * math.sin(0.7 * n + k))
            lines.append(f"{-4 + 0.5 * n:.4f} {k:.4f} -0.3 0 {math.sin(a):.6f} {math.cos(a):.6f}")
    path = tmp_path / "turning.txt"
    path.write_text("\n".join(lines) + "\n")
    return {"tool": {"type": "bull", "radius": 3, "corner_radius": 1},
            "stock": {"min": [0, 0, -5], "max": [12, 10, 0]}, "grid": {"spacing": 0.02},
            "path": {"file": str(path)}}


def test_an_exception_from_progress_stops_the_run(long_job):
    calls = []

    def progress(done, total):
        calls.append(done)
        if len(calls) == 3:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        scallop.simulate(long_job, progress=progress)
    assert len(calls) == 3  # no call after the one that raised

    with pytest.raises(ZeroDivisionError):
        scallop.simulate(ball_job(), progress=lambda d, t: 1 / 0)


def test_ctrl_c_stops_a_long_run_promptly(long_job):
    seen = []
    timer = threading.Timer(0.5, signal.raise_signal, [signal.SIGINT])
    start = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            scallop.simulate(long_job, progress=lambda d, t: seen.append((d, t)))
    finally:
        timer.cancel()
    elapsed = time.monotonic() - start
    assert seen, "the run should have reported progress before the signal"
    done, total = seen[-1]
    assert done < total, "the run finished before Ctrl-C stopped it"
    # Stopped within a few tiles of the signal, far from the run's full length.
    assert elapsed < 5.0
    # The module still works after an interrupted run.
    assert scallop.simulate(ball_job()).heights.size > 0


# --- A job with a design surface ------------------------------------------------------

def test_a_design_job_reports_the_cli_comparison_without_its_picture(tmp_path, cli):
    # The design: a plane 0.35 mm below the stock top; the 0.4 mm deep raster gouges it.
    (tmp_path / "plane.stl").write_text(
        "solid plane\n"
        "facet normal 0 0 1\nouter loop\nvertex -1 -1 -0.35\nvertex 7 -1 -0.35\n"
        "vertex 7 6 -0.35\nendloop\nendfacet\n"
        "facet normal 0 0 1\nouter loop\nvertex -1 -1 -0.35\nvertex 7 6 -0.35\n"
        "vertex -1 6 -0.35\nendloop\nendfacet\nendsolid plane\n")
    job = ball_job()
    job["design"] = {"stl": "plane.stl", "gouge_tolerance": 0.01}
    job_file = write_job(tmp_path, job)
    cli("simulate", job_file, "-o", tmp_path / "out", "--json")
    written = json.loads((tmp_path / "out" / "report.json").read_text())["design"]

    before = sorted(p.name for p in tmp_path.iterdir())
    got = scallop.simulate(str(job_file)).report["design"]
    assert sorted(p.name for p in tmp_path.iterdir()) == before  # no deviation.png
    assert written.pop("image") == "deviation.png"
    del written["image_colour_range_mm"]
    assert got == written
    assert got["gouges"]["count"] > 0 and got["overcut"]["max_depth_mm"] > 0.04
