"""scallop.bench(): the document of `scallop bench --json`, with progress and errors."""
import pytest

import scallop


def test_bench_gives_the_cli_heights(cli_json):
    expected = cli_json("bench", "--quick", "--case", "B1", "--area", 1, "--no-stamp",
                        "--threads", 1)
    calls = []
    got = scallop.bench(["B1"], quick=True, area=1, stamp=False, threads=1,
                        progress=lambda done, total: calls.append((done, total)))
    assert [c["name"] for c in got["cases"]] == ["B1"]
    for key in ("heights_hash", "cells", "moves", "segments", "evals_per_cell"):
        assert got["cases"][0][key] == expected["cases"][0][key], key
    assert got["threads"] == 1 and got["quick"] is True and got["area_mm"] == 1
    assert got["stamp"] == {}
    assert calls and calls[-1] == (100 * 100, 100 * 100)


def test_an_exception_in_progress_stops_the_bench():
    def stop(done, total):
        raise RuntimeError("enough")

    with pytest.raises(RuntimeError, match="enough"):
        scallop.bench(["B1"], quick=True, area=1, stamp=False, progress=stop)


@pytest.mark.parametrize("kw,keyword", [
    (dict(cases=["B10"]), "cases"),
    (dict(cases=["B1"], area=0.01), "area"),
    (dict(cases=["B1"], area=-1), "area"),
    (dict(cases=["B1"], progress=3), "progress"),
])
def test_bad_keywords_are_named(kw, keyword):
    with pytest.raises(scallop.InputError, match=f"^{keyword}: "):
        scallop.bench(quick=True, stamp=False, **kw)
