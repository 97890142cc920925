"""scallop.interval() and scallop.stats(): the CLI's JSON, number for number."""
import json

import numpy as np
import pytest

import scallop
from conftest import bull_job, write_job

INTERVALS = [
    dict(tool="bull", radius=3, corner_radius=1, lead=5, scallop=0.05),
    dict(tool="bull", radius=6, corner_radius=2, lead=10, tilt=4, scallop=0.1),
    dict(tool="ball", radius=5, scallop=0.01),
    dict(tool="flat", radius=4, lead=3, scallop=0.02),
]


def cli_args(kw):
    names = {"corner_radius": "--corner-radius"}
    args = []
    for key, value in kw.items():
        args += [names.get(key, "--" + key), value]
    return args


@pytest.mark.parametrize("kw", INTERVALS, ids=lambda kw: f"{kw['tool']}-R{kw['radius']}")
def test_interval_equals_the_cli_json(cli_json, kw):
    expected = cli_json("interval", *cli_args(kw))
    got = scallop.interval(**kw)
    assert got == expected
    assert got["simulated_half_interval"] > 0


@pytest.mark.parametrize("kw,field", [
    (dict(tool="bull", radius=3, scallop=0.05), "corner_radius"),
    (dict(tool="bull", radius=3, corner_radius=3, scallop=0.05), "corner_radius"),
    (dict(tool="ball", radius=3, corner_radius=1, scallop=0.05), "corner_radius"),
    (dict(tool="drill", radius=3, scallop=0.05), "tool"),
    (dict(tool="ball", radius=-1, scallop=0.05), "radius"),
    (dict(tool="ball", radius=3, lead=95, scallop=0.05), "lead"),
    (dict(tool="ball", radius=3, tilt=float("nan"), scallop=0.05), "tilt"),
    (dict(tool="ball", radius=3, scallop=0), "scallop"),
    (dict(tool="ball", radius=3, scallop=50), "scallop"),
])
def test_interval_errors_name_the_keyword(kw, field):
    with pytest.raises(scallop.InputError, match=f"^{field}: "):
        scallop.interval(**kw)


def test_interval_error_messages_match_the_cli_but_for_the_names(cli):
    done = cli("interval", "--tool", "ball", "--radius", 3, "--lead", 95, "--scallop", 0.05,
               check=False)
    assert done.returncode == 1
    with pytest.raises(scallop.InputError) as e:
        scallop.interval(tool="ball", radius=3, lead=95, scallop=0.05)
    assert done.stderr.strip() == "scallop: error: --" + str(e.value)


@pytest.fixture(scope="module")
def simulated_gsf(tmp_path_factory, cli):
    tmp = tmp_path_factory.mktemp("stats")
    job_file = write_job(tmp, bull_job())
    cli("simulate", job_file, "-o", tmp / "out", "--json")
    return tmp / "out" / "heights.gsf"


@pytest.mark.parametrize("region,level", [
    (None, "plane"), (None, "none"), ((1.0, 0.5, 6.5, 5.25), "plane"), ((2, 2, 3, 6), "none")])
def test_stats_equal_the_cli_json(cli_json, simulated_gsf, region, level):
    args = ["stats", simulated_gsf, "--level", level]
    if region:
        args += ["--region", *region]
    expected = cli_json(*args)["surface_stats"]
    heights, grid = scallop.read_heights(str(simulated_gsf))
    assert scallop.stats(heights, grid, region=region, level=level) == expected
    # The same with the spacing and origin given as numbers, and the grid as a dict.
    assert scallop.stats(heights, grid.spacing, region, level, origin=grid.origin) == expected
    as_dict = {"origin": list(grid.origin), "spacing": grid.spacing}
    assert scallop.stats(heights, as_dict, region=region, level=level) == expected


def test_stats_of_a_simulation_equal_its_report():
    r = scallop.simulate(bull_job())
    assert scallop.stats(r.heights, r.grid) == r.report["surface_stats"]


def test_stats_of_a_plane_are_zero():
    # An independent check of the levelling: a tilted plane levels to nothing.
    y, x = np.mgrid[0:20, 0:30]
    plane = 0.3 * x - 0.2 * y + 4.0
    s = scallop.stats(plane, 0.5)
    assert s["cells"] == 600 and s["area_mm2"] == pytest.approx(150.0)
    for key in ("Sa_mm", "Sq_mm", "Sp_mm", "Sv_mm", "Sz_mm"):
        assert abs(s[key]) < 1e-12
    # Row 0 is the largest y: z decreasing with row index means slope_y > 0 in mm.
    assert s["reference_plane"]["slope_x"] == pytest.approx(0.3 / 0.5)
    assert s["reference_plane"]["slope_y"] == pytest.approx(0.2 / 0.5)


def test_stats_errors_name_the_argument():
    h = np.zeros((4, 5))
    with pytest.raises(scallop.InputError, match="^level: "):
        scallop.stats(h, 1.0, level="cubic")
    with pytest.raises(scallop.InputError, match="^region: "):
        scallop.stats(h, 1.0, region=(3, 3, 1, 1))
    with pytest.raises(scallop.InputError, match="^region: "):
        scallop.stats(h, 1.0, region=(100, 100, 200, 200))
    with pytest.raises(scallop.InputError, match="^region: expected 4 numbers"):
        scallop.stats(h, 1.0, region=(0, 0, 1))
    with pytest.raises(scallop.InputError, match="^spacing: "):
        scallop.stats(h, -1.0)
    with pytest.raises(scallop.InputError, match="^heights: expected a 2-D array"):
        scallop.stats(np.zeros(5), 1.0)
    with pytest.raises(scallop.InputError, match="^heights: has the shape"):
        scallop.stats(h, scallop.Grid((0, 0), 1.0, 3, 3))
