"""scallop.gouge(): the report of `scallop gouge --json` and the same postures CSV."""
import pytest

import scallop


def without_timings(report):
    return {k: v for k, v in report.items() if k != "timings_s"}


@pytest.fixture(scope="module")
def dome(cli, tmp_path_factory):
    path = tmp_path_factory.mktemp("gouge") / "dome.stl"
    cli("surface", "--shape", "dome", "--size", "20", "20", "--facets", "300", "-o", path)
    return path


def test_gouge_equals_the_cli_report(cli_json, dome, tmp_path):
    expected = cli_json("gouge", dome, "--radius", 2, "--length", 5, "--both-ways",
                        "--grid-spacing", 0.2, "--postures", tmp_path / "cli.csv")
    got = scallop.gouge(dome, 2, 5, both_ways=True, grid_spacing=0.2,
                        postures=tmp_path / "py.csv")
    assert got["cc_points"] > 0
    assert got["gouge_map"]["grid"]["spacing"] == 0.2
    assert got["outputs"] == [str(tmp_path / "py.csv")]
    expected["outputs"] = got["outputs"]
    assert without_timings(got) == without_timings(expected)
    assert (tmp_path / "py.csv").read_bytes() == (tmp_path / "cli.csv").read_bytes()


def test_gouge_without_map_writes_its_folder(dome, tmp_path):
    report = scallop.gouge(str(dome), 2, 5, map=False, output=tmp_path / "out",
                           inclination_axis="feed")
    assert report["gouge_map"] is None
    assert report["strategy"]["inclination_axis"] == "feed"
    assert (tmp_path / "out" / "report.json").exists()
    assert not (tmp_path / "out" / "gouge_map.png").exists()


@pytest.mark.parametrize("kw,keyword", [
    (dict(radius=-2), "radius"),
    (dict(feed="z"), "feed"),
    (dict(grid_spacing=1e-7), "grid_spacing"),
    (dict(threads=0), "threads"),
])
def test_bad_keywords_are_named(dome, kw, keyword):
    args = dict(radius=2, length=5)
    args.update(kw)
    with pytest.raises(scallop.InputError, match=f"^{keyword}: "):
        scallop.gouge(dome, **args)
