import json
import shutil

import pytest

from infmob_usd.batch import Job, run_batch
from infmob_usd.validate import validate_object


def _jobs(n, category="kitchen_cabinet"):
    return [Job(category, s, (), 16) for s in range(n)]


def _manifest(out):
    return [json.loads(line) for line in (out / "manifest.jsonl").read_text().splitlines()]


def test_pool_writes_every_object_and_a_manifest(tmp_path):
    rows = run_batch(_jobs(3), tmp_path, workers=2)
    assert sorted(r["seed"] for r in rows) == [0, 1, 2]
    manifest = _manifest(tmp_path)
    assert [r["seed"] for r in manifest] == [0, 1, 2]
    for r in manifest:
        assert (tmp_path / r["folder"] / "metadata.json").is_file()
        assert r["movable_joints"] == sum(r["joint_kinds"].values()) > 0
        assert set(r["seconds"]) >= {"sampling", "geometry", "textures", "usd", "urdf", "total"}
        assert r["version"]


def test_pool_and_serial_give_identical_files(tmp_path):
    run_batch(_jobs(2), tmp_path / "a", workers=2)
    run_batch(_jobs(2), tmp_path / "b", workers=1)
    for s in range(2):
        name = f"kitchen_cabinet/kitchen_cabinet_{s:06d}"
        fa = sorted(p for p in (tmp_path / "a" / name).rglob("*") if p.is_file())
        fb = sorted(p for p in (tmp_path / "b" / name).rglob("*") if p.is_file())
        assert [p.read_bytes() for p in fa] == [p.read_bytes() for p in fb]


def test_an_interrupted_run_resumes_to_a_complete_valid_set(tmp_path):
    run_batch(_jobs(3), tmp_path, workers=1)
    # simulate a crash: one object half-written under its temporary name, one never started
    victim = tmp_path / "kitchen_cabinet" / "kitchen_cabinet_000001"
    dead = 2**22 + 12345  # above pid_max: a run that is surely not alive
    shutil.move(victim, tmp_path / "kitchen_cabinet" / f".kitchen_cabinet_000001.infmob-{dead}-0123abcd-xyz.tmp")
    shutil.rmtree(tmp_path / "kitchen_cabinet" / "kitchen_cabinet_000002")
    rows = run_batch(_jobs(4), tmp_path, workers=2)
    assert sorted(r["seed"] for r in rows) == [1, 2, 3]  # seed 0 was complete and skipped
    assert not list((tmp_path / "kitchen_cabinet").glob(".*"))
    assert [r["seed"] for r in _manifest(tmp_path)] == [0, 1, 2, 3]
    for s in range(4):
        assert validate_object(tmp_path / "kitchen_cabinet" / f"kitchen_cabinet_{s:06d}", sim=False).ok
    assert run_batch(_jobs(4), tmp_path) == []  # nothing left to do
    assert len(run_batch(_jobs(1), tmp_path, overwrite=True)) == 1


def test_a_failing_object_does_not_stop_the_batch(tmp_path, monkeypatch):
    from infmob_usd import api

    original = api.generate

    def flaky(category, seed=0, **kw):
        if seed == 1:
            raise RuntimeError("boom")
        return original(category, seed=seed, **kw)

    monkeypatch.setattr(api, "generate", flaky)
    rows = run_batch(_jobs(3), tmp_path, workers=1)
    errors = [r for r in rows if "error" in r]
    assert [r["seed"] for r in errors] == [1] and "boom" in errors[0]["error"]
    assert "RuntimeError: boom" in (tmp_path / errors[0]["traceback"]).read_text()
    assert [r["seed"] for r in _manifest(tmp_path)] == [0, 2]


def test_cli_exit_status_is_nonzero_when_an_object_fails(tmp_path, monkeypatch, capsys):
    from infmob_usd import api
    from infmob_usd.cli import main

    monkeypatch.setattr(api, "generate", lambda *a, **k: (_ for _ in ()).throw(ValueError("bad part")))
    code = main(["generate", "kitchen_cabinet", "--count", "2", "--workers", "1", "--out", str(tmp_path)])
    err = capsys.readouterr().err
    assert code == 1 and err.count("failed: ValueError: bad part") == 2


def test_ray_backend_gives_the_same_files_as_the_pool(tmp_path):
    ray = pytest.importorskip("ray")
    ray.init(num_cpus=2, include_dashboard=False, ignore_reinit_error=True, log_to_driver=False)
    try:
        run_batch(_jobs(2), tmp_path / "ray", backend="ray")
    finally:
        ray.shutdown()
    run_batch(_jobs(2), tmp_path / "pool", workers=2)
    for s in range(2):
        name = f"kitchen_cabinet/kitchen_cabinet_{s:06d}"
        fa = sorted(p.relative_to(tmp_path / "ray") for p in (tmp_path / "ray" / name).rglob("*") if p.is_file())
        fb = sorted(p.relative_to(tmp_path / "pool") for p in (tmp_path / "pool" / name).rglob("*") if p.is_file())
        assert fa == fb
        assert all((tmp_path / "ray" / f).read_bytes() == (tmp_path / "pool" / f).read_bytes() for f in fa)
