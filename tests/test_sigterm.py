"""SIGTERM (a scheduler's stop, ``kill``, a container shutting down) stops every long command promptly
with one line on stderr and a non-zero status, and leaves nothing half-written: no partial object, site or
library, no temporary folder of ours (in ``TMPDIR`` or beside the output), no worker left running.

Each test starts the real command line in a subprocess, waits until it is visibly at work (its output or
its temporary folder has appeared), sends SIGTERM and checks the exit and what is left.
"""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

import infmob_usd

STOP_SECONDS = 10.0  # from SIGTERM to the exit (a sim step or a mesh decomposition in flight finishes first)
MESSAGE = "infmob: stopped by SIGTERM"


def _children(pid: int) -> list[int]:
    try:
        return [int(x) for x in Path(f"/proc/{pid}/task/{pid}/children").read_text().split()]
    except OSError:
        return []


def _alive(pid: int) -> bool:
    try:
        return Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0] != "Z"
    except OSError:
        return False


def _terminate_at_work(tmp_path: Path, argv: list, at_work, timeout: float = 240.0) -> tuple[int, str, Path]:
    """Run ``infmob argv`` with its own TMPDIR, SIGTERM it once ``at_work()``; returns (status, stderr, TMPDIR)
    after checking that it stopped within ``STOP_SECONDS`` with its workers."""
    tmpdir = tmp_path / "tmpdir"
    tmpdir.mkdir()
    err_path = tmp_path / "stderr.txt"
    with open(err_path, "w") as err, open(tmp_path / "stdout.txt", "w") as out:
        proc = subprocess.Popen([sys.executable, "-m", "infmob_usd", *map(str, argv)], stdout=out, stderr=err,
                                cwd=tmp_path, env=dict(os.environ, TMPDIR=str(tmpdir)))
    try:
        t0 = time.monotonic()
        while not at_work():
            assert proc.poll() is None, f"ended before it was at work: {err_path.read_text()[-2000:]}"
            assert time.monotonic() - t0 < timeout, "never got to work"
            time.sleep(0.05)
        workers = _children(proc.pid)
        t1 = time.monotonic()
        proc.send_signal(signal.SIGTERM)
        code = proc.wait(timeout=60)
        assert time.monotonic() - t1 < STOP_SECONDS, f"took {time.monotonic() - t1:.1f} s to stop"
        deadline = time.monotonic() + 10
        while any(_alive(p) for p in workers) and time.monotonic() < deadline:
            time.sleep(0.1)
        assert not any(_alive(p) for p in workers), "worker processes outlived the command"
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait(timeout=10)
    err = err_path.read_text()
    assert code == 128 + signal.SIGTERM, (code, err[-2000:])
    assert "Traceback" not in err, err[-3000:]
    lines = err.strip().splitlines()
    assert lines and lines[-1].startswith(MESSAGE), err[-2000:]
    assert err.count(MESSAGE) == 1, err[-2000:]
    return code, err, tmpdir


def _ours_left(tmpdir: Path) -> list[str]:
    return sorted(p.name for p in tmpdir.iterdir())


def test_generate_stops_on_sigterm_leaving_only_whole_objects(tmp_path):
    out = tmp_path / "out"
    manifest = out / "manifest.jsonl"
    _, _, tmpdir = _terminate_at_work(
        tmp_path, ["generate", "kitchen_cabinet", "--count", "30", "--workers", "2", "--texture-size", "16",
                   "--out", out], lambda: manifest.is_file() and manifest.read_text().count("\n") >= 1)
    assert _ours_left(tmpdir) == []
    folders = sorted((out / "kitchen_cabinet").iterdir())
    assert not [p.name for p in folders if p.name.startswith(".")], "a half-written object was left"
    from infmob_usd.validate import validate_object

    for f in folders:
        assert validate_object(f, sim=False, mass=False).ok, f


def test_validate_sweep_stops_on_sigterm_and_removes_its_temporary_folder(tmp_path):
    tmpdir = tmp_path / "tmpdir"
    _, _, tmpdir = _terminate_at_work(
        tmp_path, ["validate", "--sweep", "40", "--usd-only", "--workers", "1", "--texture-size", "16", "pot"],
        lambda: any(tmpdir.glob("infmob-sweep-*/pot/pot_*")))
    assert _ours_left(tmpdir) == []


@pytest.fixture(scope="module")
def many_objects(tmp_path_factory) -> Path:
    """Sixty object folders (copies of two), enough for a gallery build of several seconds."""
    root = tmp_path_factory.mktemp("ds")
    made = [infmob_usd.save(infmob_usd.generate(c, 0, texture_size=16), root / "src") for c in ("pot", "door")]
    for i in range(30):
        for f in made:
            shutil.copytree(f, root / "ds" / f"{f.name}_{i:02d}")
    return root / "ds"


def test_gallery_build_stops_on_sigterm_leaving_no_half_site(many_objects, tmp_path):
    site = tmp_path / "site"
    _, _, tmpdir = _terminate_at_work(
        tmp_path, ["gallery", many_objects, "--out", site, "--no-render"],
        lambda: (site / "data" / "obj").is_dir() and len(list((site / "data" / "obj").iterdir())) >= 2)
    assert not site.exists(), sorted(str(p.relative_to(site)) for p in site.rglob("*"))[:10]
    assert _ours_left(tmpdir) == []


def test_gallery_rebuild_stopped_by_sigterm_keeps_the_existing_site(many_objects, tmp_path):
    site = tmp_path / "site"
    site.mkdir()
    (site / "notes.txt").write_text("the user's own file")
    (site / "index.html").write_text("an older gallery")
    _terminate_at_work(tmp_path, ["gallery", many_objects, "--out", site, "--no-render"],
                       lambda: (site / "data" / "obj").is_dir() and len(list((site / "data" / "obj").iterdir())) >= 2)
    assert sorted(p.name for p in site.iterdir()) == ["index.html", "notes.txt"]
    assert (site / "index.html").read_text() == "an older gallery"


def test_parts_import_stops_on_sigterm_leaving_no_library(tmp_path):
    trimesh = pytest.importorskip("trimesh")
    src = tmp_path / "src"
    src.mkdir()
    knob = trimesh.creation.icosphere(subdivisions=5, radius=0.02)
    rows = ["file,label,units,up"]
    for i in range(40):
        knob.export(src / f"k{i:02d}.obj")
        rows.append(f"k{i:02d}.obj,knob,m,+z")
    (src / "labels.csv").write_text("\n".join(rows) + "\n")
    lib = tmp_path / "lib"
    _, _, tmpdir = _terminate_at_work(tmp_path, ["parts", "import", src, "--out", lib],
                                      lambda: any(tmp_path.glob(".lib.*")))
    assert not lib.exists() and not list(tmp_path.glob(".lib.*"))
    assert _ours_left(tmpdir) == []


def test_fuzz_with_workers_stops_on_sigterm_and_removes_its_temporary_folders(tmp_path):
    tmpdir = tmp_path / "tmpdir"
    _, _, tmpdir = _terminate_at_work(
        tmp_path, ["fuzz", "60", "--workers", "2", "--seed", "3", "--out", tmp_path / "kept"],
        lambda: len(list(tmpdir.glob("**/infmob-fuzz-*"))) >= 2)
    time.sleep(1.0)  # a worker still writing after its parent left would show here
    assert _ours_left(tmpdir) == []


def test_bench_stops_on_sigterm_and_removes_its_temporary_folder(tmp_path):
    tmpdir = tmp_path / "tmpdir"
    _, _, tmpdir = _terminate_at_work(
        tmp_path, ["bench", "--categories", "pot", "--count", "4", "--workers", "2", "--texture-size", "16"],
        lambda: any(tmpdir.glob("infmob-bench-*/*")))
    time.sleep(1.0)
    assert _ours_left(tmpdir) == []


def test_sigterm_inside_a_fork_callback_still_stops_the_command(tmp_path):
    """A SIGTERM that lands in an ``os.fork`` callback (logging releases its lock there whenever a worker
    pool forks) raises where Python only reports the exception; the command must still stop with 143."""
    script = tmp_path / "fork_signal.py"
    script.write_text(
        "import os, signal, sys, time\n"
        "from infmob_usd import cli\n"
        "signal.signal(signal.SIGTERM, cli._on_sigterm)\n"
        "sys.unraisablehook = cli._unraisable(sys.unraisablehook)\n"
        "os.register_at_fork(after_in_parent=lambda: [signal.raise_signal(signal.SIGTERM), sum(range(99))])\n"
        "try:\n"
        "    if os.fork() == 0:\n"
        "        os._exit(0)\n"
        "    time.sleep(5)\n"
        "    sys.exit(0)\n"
        "except cli.Terminated as e:\n"
        "    sys.exit(e.code)\n")
    done = subprocess.run([sys.executable, str(script)], capture_output=True, text=True, timeout=60)
    assert done.returncode == 128 + signal.SIGTERM, done.stderr[-2000:]
    assert "Traceback" not in done.stderr, done.stderr[-2000:]
