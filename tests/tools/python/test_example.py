"""examples/python/seed001_table2.py runs and writes its plot; its simulated column is
the one `scallop validate` reports."""
import os
import subprocess
import sys

import scallop


def test_the_example_reproduces_seed001_table2_and_plots(tmp_path, source_dir, cli_json):
    png = tmp_path / "profile.png"
    script = os.path.join(source_dir, "examples", "python", "seed001_table2.py")
    done = subprocess.run([sys.executable, script, str(png)], capture_output=True, text=True,
                          cwd=tmp_path, timeout=300)
    assert done.returncode == 0, done.stderr
    rows = [line.split() for line in done.stdout.splitlines() if line.startswith("F")]
    assert [r[0] for r in rows] == ["F1a", "F1b", "F2a", "F2b", "F3a", "F3b", "F4a", "F4b"]
    # The printed simulated L/2 is the simulated exact L/2 of `scallop validate`'s
    # seed001_table2, and interval() gives it to the bit.
    validated = cli_json("validate", "-o", tmp_path / "validate")
    table = validated["tables"]["seed001_table2"]["rows"]
    assert [r["condition"] for r in table] == [r[0] for r in rows]
    for printed, row in zip(rows, table):
        exact = row["simulated_exact_half_interval_mm"]
        assert float(printed[5]) == round(exact, 6)
        got = scallop.interval(tool="bull", radius=row["radius_mm"],
                               corner_radius=row["corner_radius_mm"], lead=row["lead_deg"],
                               scallop=row["h_mm"])
        assert got["simulated_half_interval"] == exact
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and png.stat().st_size > 10000
    # The three passes at the simulated step-over leave the target scallop, to the grid.
    largest = float(done.stdout.split("largest scallop ")[1].split()[0])
    assert 0.099 < largest <= 0.1 + 1e-9
