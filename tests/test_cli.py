import subprocess
import sys

import pytest

from infmob_usd import list_categories
from infmob_usd.cli import main


def run(capsys, *argv):
    code = main(list(argv))
    out = capsys.readouterr()
    return code, out.out, out.err


def test_list_prints_one_category_per_line(capsys):
    code, out, _ = run(capsys, "list")
    assert code == 0 and out.split() == list_categories()


def test_params_prints_schema_and_growth(capsys):
    code, out, _ = run(capsys, "params", "kitchen_cabinet")
    assert code == 0
    assert "width" in out and "U(1.2, 4.8)" in out and "growth rules" in out and "drawers (0.32)" in out


def test_generate_writes_seeded_folders(capsys, tmp_path):
    code, out, _ = run(capsys, "generate", "kitchen_cabinet", "--count", "2", "--seed", "5",
                       "--out", str(tmp_path), "--texture-size", "32", "--set", "width=1.2")
    assert code == 0
    lines = out.split()
    assert sorted(p.rsplit("/", 1)[-1] for p in lines) == ["kitchen_cabinet_000005", "kitchen_cabinet_000006"]
    assert (tmp_path / "kitchen_cabinet" / "kitchen_cabinet_000006" / "kitchen_cabinet_000006.usda").is_file()
    code, out, _ = run(capsys, "validate", "--usd-only", str(tmp_path))
    assert code == 0 and "2/2 objects passed" in out


@pytest.mark.parametrize("argv,needle", [
    (["generate", "fridge"], "unknown category 'fridge'; valid categories: bar_chair, beverage_fridge"),
    (["generate", "kitchen_cabinet", "--set", "colour=red"], "unknown parameter 'colour'; valid parameters: width"),
    (["generate", "kitchen_cabinet", "--set", "width=7"], "expected a number in [1.2, 4.8] m"),
    (["generate", "kitchen_cabinet", "--set", "column_count=two"], "expected an integer in [1, 10]"),
    (["generate", "kitchen_cabinet", "--set", "width"], "NAME=VALUE"),
    (["generate", "kitchen_cabinet", "--texture-size", "300"], "power of two"),
    (["generate", "kitchen_cabinet", "--count", "0"], "--count must be 1..1000000"),
    (["params", "fridge"], "unknown category"),
])
def test_bad_input_is_one_line_exit_2_and_writes_nothing(capsys, tmp_path, argv, needle):
    out_dir = tmp_path / "out"
    argv = argv + (["--out", str(out_dir)] if argv[0] == "generate" else [])
    code, out, err = run(capsys, *argv)
    assert code == 2
    assert needle in err and len(err.strip().splitlines()) == 1
    assert not out_dir.exists()


def test_output_that_is_a_file_or_unwritable(capsys, tmp_path):
    f = tmp_path / "file"
    f.write_text("x")
    code, _, err = run(capsys, "generate", "kitchen_cabinet", "--out", str(f))
    assert code == 2 and "is a file" in err
    # /proc refuses new folders even for root: an unwritable place on every Linux machine
    code, _, err = run(capsys, "generate", "kitchen_cabinet", "--out", "/proc/infmob-test/out")
    assert code == 2 and "cannot create output folder" in err


def test_validate_fails_with_status_1_on_a_broken_object(capsys, tmp_path):
    assert run(capsys, "generate", "kitchen_cabinet", "--out", str(tmp_path), "--texture-size", "16")[0] == 0
    folder = tmp_path / "kitchen_cabinet" / "kitchen_cabinet_000000"
    next((folder / "meshes").glob("*collision_000.obj")).unlink()
    code, out, _ = run(capsys, "validate", "--usd-only", str(folder))
    assert code == 1 and "FAIL" in out and "0/1 objects passed" in out


def test_validate_without_objects_is_exit_2(capsys, tmp_path):
    code, _, err = run(capsys, "validate", str(tmp_path))
    assert code == 2 and "no object folders" in err


def test_console_script_runs_as_a_module():
    res = subprocess.run([sys.executable, "-m", "infmob_usd", "list"], capture_output=True, text=True)
    assert res.returncode == 0 and "kitchen_cabinet" in res.stdout
