"""scallop.validate(): the document of `scallop validate --json`, the same CSV files."""
import scallop


def test_validate_equals_the_cli(cli_json, tmp_path):
    expected = cli_json("validate", "-o", tmp_path / "cli")
    got = scallop.validate(tmp_path / "py")
    assert got["output_dir"] == str(tmp_path / "py")
    assert len(got["tables"]) == 9 and len(got["pictures"]) == 24
    expected["output_dir"] = got["output_dir"]
    assert got == expected
    for table in got["tables"].values():
        name = table["file"]
        assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes()


def test_validate_into_a_file_names_it(tmp_path):
    (tmp_path / "blocker").write_text("x")
    try:
        scallop.validate(tmp_path / "blocker" / "sub")
    except scallop.InputError as e:
        assert "blocker" in str(e)
    else:
        raise AssertionError("validate wrote into a file")
