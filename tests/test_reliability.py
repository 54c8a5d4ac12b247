"""Reliability: validate never crashes, generate never touches what it did not make,
runs survive kills and each other, every bad input is a one-line error with exit status 2."""

import json
import math
import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

import infmob_usd
from infmob_usd.batch import LOCK, MANIFEST, Job, OutputLock, read_manifest, run_batch
from infmob_usd.cli import main
from infmob_usd.errors import OutputError, ParameterError

NAME = "kitchen_cabinet_000000"


def run(capsys, *argv):
    code = main([str(a) for a in argv])
    out = capsys.readouterr()
    return code, out.out, out.err


@pytest.fixture(scope="module")
def made(tmp_path_factory):
    """One finished run: kitchen_cabinet seeds 0, 1 at 16 px."""
    out = tmp_path_factory.mktemp("made")
    rows = run_batch([Job("kitchen_cabinet", s, (), 16) for s in range(2)], out)
    assert all("error" not in r for r in rows)
    return out


def _copy(made, tmp_path, name="out"):
    dst = tmp_path / name
    shutil.copytree(made, dst, symlinks=True)
    return dst


# --- validate: a corrupt object is a FAIL line, never a crash (H1, M2, L5) ---------------------

def _flip(path: Path, at: int = 60, n: int = 16) -> None:
    data = bytearray(path.read_bytes())
    data[at:at + n] = bytes(b ^ 0xFF for b in data[at:at + n])
    path.write_bytes(bytes(data))


CORRUPTIONS = {
    "truncated_usdc": lambda f: os.truncate(f / "payload/geometry.usdc", 25_000),
    "zero_usdc": lambda f: os.truncate(f / "payload/geometry.usdc", 0),
    "garbage_physics": lambda f: (f / "payload/physics.usda").write_text("garbage\n"),
    "garbage_usda": lambda f: (f / f"{NAME}.usda").write_text("garbage\n"),
    "garbage_urdf": lambda f: (f / f"{NAME}.urdf").write_text("<robot"),
    "deleted_urdf": lambda f: (f / f"{NAME}.urdf").unlink(),
    "garbage_metadata": lambda f: (f / "metadata.json").write_text("{"),
    "flipped_texture": lambda f: _flip(sorted((f / "textures").glob("*.png"))[0]),
}


@pytest.mark.parametrize("workers", [1, 2])
def test_validate_reports_every_corruption_as_a_fail_and_goes_on(made, tmp_path, capsys, workers):
    objs = tmp_path / "objs"
    good = made / "kitchen_cabinet" / NAME
    shutil.copytree(good, objs / "renamed_but_good")  # L5: found by its USD/URDF pair, not its folder name
    for name, corrupt in CORRUPTIONS.items():
        shutil.copytree(good, objs / name)
        corrupt(objs / name)
    report = tmp_path / "r.json"
    code, out, _ = run(capsys, "validate", "--usd-only", "--workers", workers, "--report", report, objs)
    assert code == 1
    lines = {Path(line.split()[1]).name: line for line in out.splitlines() if line.startswith(("ok ", "FAIL "))}
    assert lines["renamed_but_good"].startswith("ok ")
    for name in CORRUPTIONS:
        assert lines[name].startswith("FAIL "), lines[name]
        assert "\n" not in lines[name]
    assert "Traceback" not in out
    rep = json.loads(report.read_text())
    assert rep["objects"] == len(CORRUPTIONS) + 1 and rep["passed"] == 1
    bad_texture = {f["check"] for f in rep["failures"] if f["object"] == str(objs / "flipped_texture")}
    assert bad_texture == {"textures"}
    assert len({r["object"] for r in rep["results"]}) == rep["objects"]  # copies of one object told apart


def test_validate_with_sapien_fails_a_deleted_urdf_without_crashing(made, tmp_path, capsys):
    folder = tmp_path / NAME
    shutil.copytree(made / "kitchen_cabinet" / NAME, folder)
    (folder / f"{NAME}.urdf").unlink()
    code, out, _ = run(capsys, "validate", "--workers", 1, folder)
    assert code == 1 and out.startswith("FAIL ") and "sapien_load" in out


# --- generate: only its own names, nothing through a link (H2, H3, L4) -------------------------

def test_generate_removes_only_temp_names_of_dead_runs(made, tmp_path):
    out = _copy(made, tmp_path)
    cat = out / "kitchen_cabinet"
    foreign = [out / "myproject" / ".build.tmp", cat / ".mine.tmp", cat / f".{NAME}.abc.tmp"]
    for d in foreign:
        d.mkdir(parents=True)
    outside = tmp_path / "elsewhere" / ".x.infmob-1-00000000-ab.tmp"
    outside.mkdir(parents=True)
    (out / "link").symlink_to(outside.parent)
    dead = 2**22 + 1  # above any pid_max: a run that is surely not alive
    ours = cat / f".kitchen_cabinet_000005.infmob-{dead}-0123abcd-x1y2.tmp"
    ours.mkdir()
    alive = cat / f".kitchen_cabinet_000006.infmob-{os.getpid()}-0123abcd-x1y2.tmp"  # an API save running now
    alive.mkdir()
    run_batch([Job("kitchen_cabinet", 0, (), 16)], out)
    assert all(d.is_dir() for d in foreign) and outside.is_dir() and alive.is_dir()
    assert not ours.exists()


def test_nothing_is_written_through_a_symbolic_link(made, tmp_path):
    victim = tmp_path / "victim.txt"
    victim.write_text("victim")
    out = _copy(made, tmp_path)
    (out / "manifest.jsonl.tmp").symlink_to(victim)  # an old temp name: neither written nor removed
    run_batch([Job("kitchen_cabinet", 2, (), 16)], out)
    assert victim.read_text() == "victim" and (out / "manifest.jsonl.tmp").is_symlink()

    out2 = tmp_path / "o2"
    out2.mkdir()
    (out2 / MANIFEST).symlink_to(victim)
    with pytest.raises(OutputError, match="symbolic link"):
        run_batch([Job("tv", 0, (), 16)], out2)
    assert victim.read_text() == "victim"

    out3, elsewhere = tmp_path / "o3", tmp_path / "elsewhere3"
    out3.mkdir()
    elsewhere.mkdir()
    (out3 / "tv").symlink_to(elsewhere)
    with pytest.raises(OutputError, match="symbolic link"):
        run_batch([Job("tv", 0, (), 16)], out3)
    assert list(elsewhere.iterdir()) == []


# --- resume: damaged folders are regenerated, intact ones kept (L7) ----------------------------

def test_resume_regenerates_damaged_folders_only(made, tmp_path):
    out = _copy(made, tmp_path)
    cat = out / "kitchen_cabinet"
    sorted((cat / NAME / "textures").glob("*.png"))[0].unlink()
    usdc = cat / "kitchen_cabinet_000001" / "payload" / "geometry.usdc"
    usdc.write_bytes(b"\0" * usdc.stat().st_size)
    logged = []
    rows = run_batch([Job("kitchen_cabinet", s, (), 16) for s in range(3)], out, log=logged.append)
    assert sorted(r["seed"] for r in rows) == [0, 1, 2]
    assert any("is missing" in m for m in logged) and any("changed" in m for m in logged)
    before = {s: (cat / f"kitchen_cabinet_{s:06d}").stat().st_ino for s in range(3)}
    (cat / NAME / "preview.png").write_bytes(b"a file added later is not damage")
    assert run_batch([Job("kitchen_cabinet", s, (), 16) for s in range(3)], out) == []
    assert {s: (cat / f"kitchen_cabinet_{s:06d}").stat().st_ino for s in range(3)} == before


# --- concurrent runs: a lock per output folder (M1) ---------------------------------------------

HOLD = ("import sys, time; from infmob_usd.batch import OutputLock\n"
        "with OutputLock(sys.argv[1]):\n    print('locked', flush=True); time.sleep(float(sys.argv[2]))\n")


def test_a_second_run_fails_fast_naming_the_first_or_waits(tmp_path, capsys):
    out = tmp_path / "out"
    out.mkdir()
    holder = subprocess.Popen([sys.executable, "-c", HOLD, str(out), "6"], stdout=subprocess.PIPE, text=True)
    try:
        assert holder.stdout.readline().strip() == "locked"
        t_locked = t0 = time.perf_counter()
        code, _, err = run(capsys, "generate", "tv", "--out", out, "--texture-size", 16, "--workers", 1)
        assert code == 2 and f"pid {holder.pid}" in err and "--wait" in err and len(err.splitlines()) == 1
        assert time.perf_counter() - t0 < 5 and not (out / "tv").exists()
        code, _, err = run(capsys, "generate", "tv", "--out", out, "--texture-size", 16, "--workers", 1, "--wait")
        assert code == 0 and time.perf_counter() - t_locked > 5.5  # it waited for the holder to let go
        assert f"waiting for another infmob run writing to {out} (pid {holder.pid}" in err  # and said for whom
    finally:
        holder.kill()
        holder.wait()


def test_two_real_runs_into_one_folder_keep_every_object(tmp_path):
    out = tmp_path / "out"
    cmd = [sys.executable, "-m", "infmob_usd", "generate", "tv", "--out", str(out), "--texture-size", "16",
           "--workers", "1", "--wait", "--count", "3"]
    a = subprocess.Popen(cmd + ["--seed", "0"], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    b = subprocess.Popen(cmd + ["--seed", "10"], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    assert a.wait(timeout=300) == 0 and b.wait(timeout=300) == 0, a.stderr.read() + b.stderr.read()
    rows = read_manifest(out)
    assert sorted(s for _, s in rows) == [0, 1, 2, 10, 11, 12]
    assert sorted(p.name for p in (out / "tv").iterdir()) == [f"tv_{s:06d}" for s in (0, 1, 2, 10, 11, 12)]


# --- killed runs: resume without redoing work, no orphans (M5) ----------------------------------

def _children(pid: int) -> list[int]:
    try:
        return [int(x) for x in Path(f"/proc/{pid}/task/{pid}/children").read_text().split()]
    except OSError:
        return []


def _gone(pids, timeout=10.0) -> bool:
    t0 = time.time()
    while time.time() - t0 < timeout:
        if not any(Path(f"/proc/{p}").exists() and "Z" not in _state(p) for p in pids):
            return True
        time.sleep(0.1)
    return False


def _state(pid: int) -> str:
    try:
        return Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return "Z"


def _start(out: Path, count: int) -> subprocess.Popen:
    return subprocess.Popen([sys.executable, "-m", "infmob_usd", "generate", "tv", "--count", str(count),
                             "--out", str(out), "--texture-size", "16", "--workers", "2"],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def _wait_rows(out: Path, n: int, proc, timeout=240.0) -> None:
    t0 = time.time()
    while time.time() - t0 < timeout and proc.poll() is None:
        m = out / MANIFEST
        if m.is_file() and m.read_text().count("\n") >= n:
            return
        time.sleep(0.1)
    raise AssertionError(f"no {n} finished objects in time")


@pytest.mark.parametrize("sig", [signal.SIGKILL, signal.SIGTERM])
def test_a_killed_run_resumes_without_redoing_finished_objects(tmp_path, sig):
    from infmob_usd.validate import validate_object

    out = tmp_path / "out"
    proc = _start(out, 12)
    _wait_rows(out, 2, proc)
    workers = _children(proc.pid)
    proc.send_signal(sig)
    code = proc.wait(timeout=60)
    assert code == (-signal.SIGKILL if sig == signal.SIGKILL else 128 + signal.SIGTERM)
    assert workers and _gone(workers), "pool workers outlived their run"
    finished = read_manifest(out)
    assert 2 <= len(finished) < 12
    folder = lambda s: out / "tv" / f"tv_{s:06d}"  # noqa: E731
    inodes = {s: folder(s).stat().st_ino for _, s in finished}
    rows = run_batch([Job("tv", s, (), 16) for s in range(12)], out, workers=2)  # the lock was released
    assert not {r["seed"] for r in rows} & set(inodes), "finished objects were generated again"
    assert {s: folder(s).stat().st_ino for s in inodes} == inodes
    assert sorted(s for _, s in read_manifest(out)) == list(range(12))
    assert not [p for p in (out / "tv").iterdir() if p.name.startswith(".")]
    for s in range(12):
        assert validate_object(folder(s), sim=False).ok


# --- bad input: one line, exit status 2, nothing created (L1, L2, M3, L8) ---------------------

@pytest.mark.parametrize("argv, needle", [
    (["generate", "kitchen_cabinet", "--count", "99999999999999999999999"], "--count must be 1..1000000"),
    (["generate", "tv", "--seed", str(10**300)], "--seed must be 0.."),
    (["generate", ""], "no category"),
    (["generate", ","], "no category"),
    (["generate", "tv", "--address", "x"], "--backend ray"),
    (["generate", "all", "--set", "has_handles=true"], "not a parameter of bar_chair"),
    (["generate", "kitchen_cabinet", "--set", "column_count=2.0"], "column_count"),
    (["generate", "kitchen_cabinet", "--set", "has_handles=off"], "true or false"),
    (["generate", "tv", "--out", "a\nb"], "control characters"),
    (["validate", "--workers", "0", "."], "--workers must be 1..1024"),
    (["stats", ".", "--max-pairs", "0"], "--max-pairs must be at least 1"),
    (["bench", "--categories", ""], "no category"),
    (["textures", "--family", "wood:nope"], "no variant 'nope'"),
    (["fuzz", "0"], "N must be at least 1"),
])
def test_bad_input_is_one_line_and_exit_2(capsys, tmp_path, monkeypatch, argv, needle):
    monkeypatch.chdir(tmp_path)
    code, _, err = run(capsys, *argv)
    assert code == 2 and needle in err and len(err.strip().splitlines()) == 1, err
    assert list(tmp_path.iterdir()) == []  # nothing created


def test_unwritable_outputs_are_one_line_errors(made, capsys, tmp_path):
    (tmp_path / "FILE").write_text("")
    for argv, needle in [
        (["generate", "tv", "--out", "/proc/infmob"], "cannot create output folder"),
        (["validate", "--usd-only", "--report", "/proc/x.json", made], "--report"),
        (["validate", "--sweep", "1", "tv", "--out", tmp_path / "FILE"], "is a file"),
    ]:
        code, _, err = run(capsys, *argv)
        assert code == 2 and needle in err and len(err.strip().splitlines()) == 1, err


def test_a_garbage_manifest_is_a_one_line_error(made, tmp_path, capsys):
    out = _copy(made, tmp_path)
    with open(out / MANIFEST, "a") as f:
        f.write("garbage\n{}\n")
    code, _, err = run(capsys, "generate", "kitchen_cabinet", "--out", out, "--texture-size", 16)
    assert code == 2 and "manifest" in err and len(err.strip().splitlines()) == 1


def test_a_torn_last_manifest_line_is_ignored(made, tmp_path):
    out = _copy(made, tmp_path)
    with open(out / MANIFEST, "a") as f:
        f.write('{"category": "kitchen_cabinet", "se')  # a write cut by a kill
    assert len(read_manifest(out)) == 2


def test_lock_file_names_its_holder(tmp_path):
    with OutputLock(tmp_path) as lock:
        info = json.loads((tmp_path / LOCK).read_text())
        assert info["pid"] == os.getpid() and info["started"] and "command" in info
        assert f"pid {os.getpid()}" in lock.holder()


# --- typed, strict API (L6) and exact replay (L3) --------------------------------------------

def test_poses_reject_unknown_joints_and_non_finite_values():
    from zoo import zoo

    obj = zoo()
    name = obj.movable_joints[0].name
    assert obj.poses({name: 0.1})
    for q, needle in [({"nope": 0.1}, "not a movable joint"), ({name: math.nan}, "finite"),
                      ({name: math.inf}, "finite"), ({name: "0.1"}, "finite")]:
        with pytest.raises(ParameterError, match=needle):
            obj.poses(q)


def test_an_objects_own_metadata_replays_to_the_same_object(tmp_path):
    from infmob_usd import generate

    obj = generate("kitchen_cabinet", seed=3, texture_size=16, door_angle=0.65 * math.pi, width=1.23456789012345)
    folder = infmob_usd.save(obj, tmp_path)
    meta = json.loads((folder / "metadata.json").read_text())
    assert meta["overrides"] == {"door_angle": 0.65 * math.pi, "width": 1.23456789012345}
    again = generate("kitchen_cabinet", seed=3, texture_size=16, **meta["overrides"])
    assert again.params == obj.params
    generate("kitchen_cabinet", seed=3, texture_size=16, **meta["parameters"])  # rounded values are accepted
