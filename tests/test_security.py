"""Security and reliability: an untrusted dataset or hostile input never makes infmob read, copy, serve
or write anything outside what it was given; every failure is one line.

One test (or a few) per class of probe: the gallery serves and copies only what it should (1-3),
``validate`` fails files that point out of their folder (4), output paths are never followed (5),
worker counts are bounded (6), a killed worker does not abort a batch (7), sizes are bounded up
front and SIGTERM honoured (9), one-line errors everywhere else (10).
"""

from __future__ import annotations

import http.client
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

import infmob_usd
from infmob_usd.batch import Job, run_batch
from infmob_usd.cli import main
from infmob_usd.errors import InfmobError
from infmob_usd.validate.gallery import build_gallery

CAT = "tv"
NAME = f"{CAT}_000000"
QUIET = {"render": False, "log": lambda *a, **k: None}


def run(capsys, *argv):
    code = main([str(a) for a in argv])
    out = capsys.readouterr()
    return code, out.out, out.err


@pytest.fixture(scope="module")
def obj_dir(tmp_path_factory) -> Path:
    """One finished object at 16 px: DIR/tv/tv_000000."""
    root = tmp_path_factory.mktemp("sec_obj")
    infmob_usd.save(infmob_usd.generate(CAT, seed=0, texture_size=16), root / CAT)
    return root / CAT / NAME


def _dataset(obj_dir: Path, where: Path) -> Path:
    """A fresh DIR holding a copy of the object."""
    shutil.copytree(obj_dir, where / "ds" / CAT / NAME)
    return where / "ds"


def _secret(tmp_path: Path) -> Path:
    secret = tmp_path / "private" / "secret.txt"
    secret.parent.mkdir(parents=True, exist_ok=True)
    secret.write_text("TOP-SECRET-CONTENT\n")
    return secret


def _site_text(site: Path) -> str:
    return "".join(p.read_text(errors="replace") for p in site.rglob("*") if p.is_file())


# --- 1 + 3: the server serves the site and the shown object folders only ----------------------------

class _Served:
    """The gallery server in a thread, stopped (bounded) on exit."""

    def __init__(self, res):
        from infmob_usd.validate.gallery import make_server

        self.httpd, self.url = make_server(res["index"], res["site"], res["folders"], 0)
        self.port = self.httpd.server_address[1]
        self.thread = threading.Thread(target=self.httpd.serve_forever, daemon=True)

    def __enter__(self):
        self.thread.start()
        return self

    def __exit__(self, *exc):
        self.httpd.shutdown()
        self.httpd.server_close()
        self.thread.join(timeout=10)

    def get(self, path: str, host: str | None = None) -> tuple[int, bytes]:
        conn = http.client.HTTPConnection("127.0.0.1", self.port, timeout=10)
        try:
            conn.putrequest("GET", path, skip_host=True)
            conn.putheader("Host", host if host is not None else f"127.0.0.1:{self.port}")
            conn.endheaders()
            r = conn.getresponse()
            return r.status, r.read()
        finally:
            conn.close()


def _url_path(url: str) -> str:
    return "/" + url.split("/", 3)[3]


def test_server_serves_only_the_site_and_the_objects_shown(obj_dir, tmp_path):
    ds = _dataset(obj_dir, tmp_path / "a")
    secret = _secret(tmp_path)  # beside DIR and SITE, under their common parent
    (ds / CAT / NAME / "preview.png").write_bytes((obj_dir / "textures").glob("*.png").__next__().read_bytes())
    os.symlink(secret, ds / CAT / NAME / "leak.txt")  # a link inside DIR to a file outside it
    os.symlink(secret.parent, ds / CAT / NAME / "leakdir")
    res = build_gallery(ds, tmp_path / "b" / "site", **QUIET)
    with _Served(res) as s:
        index = _url_path(s.url)
        assert s.get(index)[0] == 200 and b"<html" in s.get(index)[1].lower()
        top = index[: index.index("/b/site/")]  # URLs are paths below the common parent of DIR and SITE
        thumb = f"{top}/a/ds/{CAT}/{NAME}/preview.png"
        assert s.get(thumb)[0] == 200  # a shown object's thumbnail
        assert s.get(f"{top}/b/site/data/index.js")[0] == 200
        for path in (f"{top}/private/secret.txt", f"{top}/", f"{top}/a/", f"{top}/a/ds/{CAT}/",
                     f"{top}/b/site/data/", f"{top}/a/ds/{CAT}/{NAME}/leak.txt",
                     f"{top}/a/ds/{CAT}/{NAME}/leakdir/secret.txt", f"{top}/../../../etc/passwd",
                     "/etc/passwd", "/"):
            status, body = s.get(path)
            assert status == 404, (path, status)
            assert b"TOP-SECRET" not in body and b"Directory listing" not in body, path
        for host in ("evil.example.com", "evil.example.com:80", f"attacker.test:{s.port}", "",
                     "127.0.0.1:1", "10.0.0.1"):
            assert s.get(index, host=host)[0] == 421, host  # DNS rebinding: a foreign Host is refused
        for host in (f"localhost:{s.port}", "127.0.0.1", "localhost"):
            assert s.get(index, host=host)[0] == 200, host


def test_serve_from_the_command_line_stops_on_sigterm(obj_dir, tmp_path):
    ds = _dataset(obj_dir, tmp_path)
    secret = _secret(tmp_path)
    proc = subprocess.Popen([sys.executable, "-m", "infmob_usd.cli", "gallery", str(ds), "--out",
                             str(tmp_path / "site"), "--no-render", "--serve", "--port", "0"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        line = proc.stdout.readline() + proc.stdout.readline()
        m = re.search(r"serving http://127\.0\.0\.1:(\d+)(/\S+)", line)
        assert m, line
        port, index = int(m.group(1)), m.group(2)
        top = index[: index.index("/site/")]
        conn = http.client.HTTPConnection("127.0.0.1", port, timeout=10)
        conn.request("GET", f"{top}/private/{secret.name}")
        assert conn.getresponse().status == 404
        conn.close()
        proc.send_signal(signal.SIGTERM)
        assert proc.wait(timeout=15) != 0
        assert "Traceback" not in proc.stderr.read()
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait(timeout=10)


def test_gallery_help_says_it_binds_loopback_only(capsys):
    with pytest.raises(SystemExit):
        main(["gallery", "--help"])
    assert "127.0.0.1 only" in " ".join(capsys.readouterr().out.split())


# --- 2: a gallery never copies a file from outside an object folder ----------------------------------

def _point_urdf_at(folder: Path, target: str) -> None:
    urdf = folder / f"{NAME}.urdf"
    text = urdf.read_text()
    first = re.search(r'filename="([^"]+)"', text).group(1)
    urdf.write_text(text.replace(f'filename="{first}"', f'filename="{target}"'))


@pytest.mark.parametrize("how", ["absolute", "dotdot", "package", "mtl_map", "mtllib", "link"])
def test_gallery_refuses_files_outside_the_object_folder(obj_dir, tmp_path, capsys, how):
    ds = _dataset(obj_dir, tmp_path)
    folder = ds / CAT / NAME
    secret = _secret(tmp_path)
    fake_obj = secret.with_name("mesh.obj")
    fake_obj.write_text("# TOP-SECRET-CONTENT\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    rel = os.path.relpath(fake_obj, folder)
    if how == "absolute":
        _point_urdf_at(folder, str(fake_obj))
    elif how in ("dotdot", "package"):
        _point_urdf_at(folder, ("package://" if how == "package" else "") + rel)
    elif how == "link":
        mesh = sorted((folder / "meshes").glob("*.obj"))[0]
        mesh.unlink()
        os.symlink(fake_obj, mesh)
    else:
        mtl = sorted((folder / "meshes").glob("*.mtl"))[0]
        text = mtl.read_text()
        if how == "mtl_map":
            secret.write_bytes(b"\x89PNG\r\n\x1a\nTOP-SECRET-CONTENT")
            mtl.write_text(re.sub(r"(map_Kd\s+)\S+", lambda m: m.group(1) + os.path.relpath(secret, mtl.parent),
                                  text))
            assert "map_Kd" in text
        else:
            fake_mtl = secret.with_name("evil.mtl")
            fake_mtl.write_text("newmtl TOP-SECRET-CONTENT\nKd 1 0 0\n")
            obj = sorted((folder / "meshes").glob("*.obj"))[0]
            obj.write_text(re.sub(r"(?m)^mtllib .*$", f"mtllib {os.path.relpath(fake_mtl, obj.parent)}",
                                  obj.read_text()))
    site = tmp_path / "site"
    (ds / "other").mkdir()
    shutil.copytree(obj_dir, ds / "other" / NAME)  # a clean object: the gallery is still made
    code, out, err = run(capsys, "gallery", ds, "--out", site, "--no-render")
    assert code == 1, err
    skipped = [line for line in err.splitlines() if line.startswith("gallery: skipped")]
    assert len(skipped) == 1 and str(folder) in skipped[0] and "refused" in skipped[0], err
    assert "TOP-SECRET" not in _site_text(site)
    assert "Traceback" not in err


def test_gallery_skips_object_folders_linked_from_outside(obj_dir, tmp_path, capsys):
    ds = _dataset(obj_dir, tmp_path)
    elsewhere = tmp_path / "elsewhere" / "private_obj"
    shutil.copytree(obj_dir, elsewhere)
    (elsewhere / "metadata.json").write_text(
        (elsewhere / "metadata.json").read_text().replace(f'"name": "{NAME}"', '"name": "TOP-SECRET-NAME"'))
    os.symlink(elsewhere, ds / "linked")
    res = build_gallery(ds, tmp_path / "site", **QUIET)
    assert res["objects"] == 1 and "TOP-SECRET" not in _site_text(res["site"])


# --- 4: validate's `files` check fails references out of the folder and non-finite vertices ---------

def _first_mesh(folder: Path) -> Path:
    return sorted((folder / "meshes").glob("*.obj"))[0]


def _etc_passwd(folder: Path, tmp_path: Path) -> None:
    _point_urdf_at(folder, "../../../../../../../../../../etc/passwd")


def _mesh_link(folder: Path, tmp_path: Path) -> None:
    mesh = _first_mesh(folder)
    outside = tmp_path / "outside.obj"
    shutil.copyfile(mesh, outside)  # the same mesh, so only the link itself is wrong
    mesh.unlink()
    os.symlink(outside, mesh)


def _nan_vertex(folder: Path, tmp_path: Path) -> None:
    mesh = _first_mesh(folder)
    mesh.write_text(re.sub(r"(?m)^v [^\n]*", "v nan 0 0", mesh.read_text(), count=1))


def _inf_vertex(folder: Path, tmp_path: Path) -> None:
    mesh = _first_mesh(folder)
    mesh.write_text(re.sub(r"(?m)^v [^\n]*", "v 0 1e999 0", mesh.read_text(), count=1))


@pytest.mark.parametrize("damage", [_etc_passwd, _mesh_link, _nan_vertex, _inf_vertex],
                         ids=lambda f: f.__name__.strip("_"))
def test_validate_files_check_fails_paths_out_of_the_folder(obj_dir, tmp_path, capsys, damage):
    folder = tmp_path / NAME
    shutil.copytree(obj_dir, folder)
    damage(folder, tmp_path)
    code, out, _ = run(capsys, "validate", "--usd-only", "--no-mass", folder)
    assert code == 1, out
    line = next(x for x in out.splitlines() if x.startswith(("ok ", "FAIL ")))
    assert line.startswith("FAIL") and re.search(r"files: [^\]]*(outside|absolute|NaN)", line), line


def test_validate_passes_the_clean_object(obj_dir, capsys):
    code, out, _ = run(capsys, "validate", "--usd-only", "--no-mass", obj_dir)
    assert code == 0, out


# --- 10: texture maps of another size than the object's texture_size ----------------------------------

def _png(px: int) -> bytes:
    import cv2
    import numpy as np

    return cv2.imencode(".png", np.full((px, px, 3), 128, np.uint8))[1].tobytes()


def test_validate_fails_maps_of_another_size_than_texture_size(obj_dir, tmp_path, capsys):
    folder = tmp_path / NAME
    shutil.copytree(obj_dir, folder)
    for p in sorted((folder / "textures").glob("*.png"))[:2]:
        p.write_bytes(_png(64))  # decodes, square: only its size against metadata's texture_size is wrong
    code, out, _ = run(capsys, "validate", "--usd-only", "--no-mass", folder)
    assert code == 1 and re.search(r"textures: [^\]]*64x64", out), out


def test_a_cache_entry_of_another_size_is_a_miss(tmp_path, monkeypatch):
    from infmob_usd.materials import cache

    monkeypatch.setenv("INFMOB_USD_CACHE", str(tmp_path / "cache"))
    cache.forget()
    obj = infmob_usd.generate(CAT, seed=0, texture_size=16)
    hashes = sorted((tmp_path / "cache").rglob("*.sha256.json"))
    assert hashes
    for h in hashes:  # every entry replaced by 64 px maps, together with its hash file
        digests = {}
        for png in sorted(h.parent.glob(h.name.replace(".sha256.json", "_*.png"))):
            png.write_bytes(_png(64))
            digests[png.stem.rsplit("_", 1)[1]] = cache.hashlib.sha256(png.read_bytes()).hexdigest()
        h.write_text(json.dumps(digests))
    cache.forget()
    again = infmob_usd.generate(CAT, seed=0, texture_size=16)
    cache.forget()
    assert again.textures == obj.textures


# --- 5: output paths are never followed --------------------------------------------------------------

def _linked_out(tmp_path: Path) -> tuple[Path, Path]:
    target = tmp_path / "target"
    target.mkdir()
    dead = target / f".{NAME}.infmob-999999999-0123abcd-x1y2.tmp"  # a dead run's temp folder in the target
    dead.mkdir()
    link = tmp_path / "link"
    os.symlink(target, link)
    return link, target


@pytest.mark.parametrize("argv", [
    ["generate", CAT, "--texture-size", "16", "--workers", "1", "--out", "{link}"],
    ["generate", CAT, "--texture-size", "16", "--workers", "1", "--out", "{link}/"],
    ["validate", CAT, "--sweep", "1", "--texture-size", "16", "--usd-only", "--out", "{link}"],
    ["fuzz", "1", "--categories", CAT, "--usd-only", "--workers", "1", "--out", "{link}"],
    ["gallery", "{obj}", "--no-render", "--out", "{link}"],
    ["parts", "export-builtin", "{link}"],
], ids=["generate", "generate_slash", "validate_sweep", "fuzz", "gallery", "parts_export"])
def test_out_that_is_a_link_is_a_one_line_error_and_writes_nothing(obj_dir, tmp_path, capsys, argv):
    link, target = _linked_out(tmp_path)
    before = sorted(target.rglob("*"))
    code, out, err = run(capsys, *[a.format(link=link, obj=obj_dir.parent) for a in argv])
    assert code == 2, (out, err)
    assert len(err.strip().splitlines()) == 1 and "symbolic link" in err, err
    assert sorted(target.rglob("*")) == before  # nothing written, the dead run's folder not removed


def test_a_category_folder_swapped_for_a_link_mid_run_sends_nothing_outside(tmp_path):
    out, elsewhere = tmp_path / "out", tmp_path / "elsewhere"
    elsewhere.mkdir()

    def swap(row):
        if not (out / CAT).is_symlink():
            os.rename(out / CAT, tmp_path / "moved")
            os.symlink(elsewhere, out / CAT)

    with pytest.raises(InfmobError, match="symbolic link"):
        run_batch([Job(CAT, s, (), 16) for s in range(3)], out, on_row=swap)
    assert list(elsewhere.iterdir()) == []
    assert [p.name for p in (tmp_path / "moved").iterdir()] == [NAME]


def test_api_save_refuses_a_link(tmp_path):
    obj = infmob_usd.generate(CAT, seed=0, texture_size=16)
    target = tmp_path / "target"
    target.mkdir()
    os.symlink(target, tmp_path / "link")
    with pytest.raises(InfmobError, match="symbolic link"):
        infmob_usd.save(obj, tmp_path / "link")
    assert list(target.iterdir()) == []


# --- 6: --workers bounded ----------------------------------------------------------------------------

@pytest.mark.parametrize("argv", [
    ["generate", CAT, "--workers", "100000", "--out", "{tmp}/o"],
    ["generate", CAT, "--workers", "0", "--out", "{tmp}/o"],
    ["validate", "{tmp}", "--workers", "100000"],
    ["fuzz", "3", "--workers", "100000"],
    ["textures", "--workers", "100000"],
    ["bench", "--workers", "100000"],
], ids=["generate", "generate_0", "validate", "fuzz", "textures", "bench"])
def test_absurd_worker_counts_are_one_line_errors(tmp_path, capsys, argv):
    t0 = time.monotonic()
    code, out, err = run(capsys, *[a.format(tmp=tmp_path) for a in argv])
    assert code == 2 and len(err.strip().splitlines()) == 1 and "--workers must be 1..1024" in err, err
    assert time.monotonic() - t0 < 10 and not (tmp_path / "o").exists()


def test_workers_are_capped_at_the_number_of_objects(tmp_path, capsys):
    code, out, err = run(capsys, "generate", CAT, "--texture-size", "16", "--workers", "64", "--out", tmp_path)
    assert code == 0, err
    assert "--workers 64 capped at 1, the number of objects" in err
    assert (tmp_path / CAT / NAME / "metadata.json").is_file()


# --- 7: a killed pool worker does not abort the batch ------------------------------------------------

def test_a_killed_worker_loses_its_objects_not_the_batch(tmp_path):
    from concurrent.futures import ProcessPoolExecutor

    from infmob_usd.batch import _die_with_parent

    jobs = [Job(CAT, s, (), 16) for s in range(6)]
    pool = ProcessPoolExecutor(max_workers=2, initializer=_die_with_parent)
    killed, notes = [], []

    def kill_one(row):  # as the out-of-memory killer does, after the first object
        if not killed:
            pid = next(iter(pool._processes))
            os.kill(pid, signal.SIGKILL)
            killed.append(pid)

    try:
        rows = run_batch(jobs, tmp_path, workers=2, pool=pool, on_row=kill_one, log=notes.append)
    finally:
        pool.shutdown(wait=False, cancel_futures=True)
    assert killed and len(rows) == 6 and sorted(r["seed"] for r in rows) == list(range(6))
    lost = [r for r in rows if "error" in r]
    assert lost and all(r["error"].startswith("lost: a worker process died") for r in lost), lost
    assert any("fresh pool" in n for n in notes), notes
    again = run_batch(jobs, tmp_path, workers=1)  # resume: only the lost objects are made
    assert sorted(r["seed"] for r in again) == sorted(r["seed"] for r in lost)
    assert all("error" not in r for r in again)


# --- 9: sizes bounded up front; 10: part-library paths stay inside the library ------------------------

def test_gallery_refuses_a_huge_urdf_at_once(obj_dir, tmp_path, capsys):
    ds = _dataset(obj_dir, tmp_path)
    urdf = ds / CAT / NAME / f"{NAME}.urdf"
    text = urdf.read_text()
    with open(urdf, "w") as f:  # a 20 MB comment: expat 2.5 re-scans a huge token per 64 kB chunk
        f.write(text.replace("<robot", "<!-- " + "x" * (20 << 20) + " -->\n<robot", 1))
    (ds / "other").mkdir()
    shutil.copytree(obj_dir, ds / "other" / NAME)
    t0 = time.monotonic()
    code, out, err = run(capsys, "gallery", ds, "--out", tmp_path / "site", "--no-render")
    assert time.monotonic() - t0 < 20
    assert code == 1 and re.search(r"gallery: skipped .*URDF \S+ is 20 MB, over the 16 MB", err), err


@pytest.fixture(scope="module")
def builtin_lib(tmp_path_factory) -> Path:
    from infmob_usd.parts_tools import export_builtin

    return export_builtin(tmp_path_factory.mktemp("lib") / "lib")


def _lib_copy(builtin_lib: Path, tmp_path: Path) -> Path:
    lib = tmp_path / "lib"
    shutil.copytree(builtin_lib, lib)
    return lib


def test_parts_import_refuses_a_huge_mesh_before_reading_it(tmp_path, capsys):
    src = tmp_path / "src"
    src.mkdir()
    with open(src / "big.obj", "wb") as f:  # 10 M faces are > 300 MB of OBJ: a sparse file of that size
        f.truncate(300 << 20)
    (src / "labels.csv").write_text("file,label\nbig.obj,knob\n")
    t0 = time.monotonic()
    code, out, err = run(capsys, "parts", "import", src, "--out", tmp_path / "lib")
    assert time.monotonic() - t0 < 10
    assert code == 2 and len(err.strip().splitlines()) == 1 and "300 MB, over the 100 MB" in err, err
    assert not (tmp_path / "lib").exists()


def test_a_library_with_a_flat_collision_piece_is_refused(builtin_lib, tmp_path, capsys):
    from infmob_usd.partlib import PartLibraryError, load_library

    lib = _lib_copy(builtin_lib, tmp_path)
    convex = sorted(lib.rglob("convex.json"))[0]
    d = json.loads(convex.read_text())
    d["pieces"][0] = [[x, y, 0.0] for x, y, _ in d["pieces"][0]]  # all on one plane: zero volume
    convex.write_text(json.dumps(d))
    with pytest.raises(PartLibraryError, match="encloses no volume"):
        load_library(lib)
    code, _, err = run(capsys, "generate", "cocktail_table", "--parts", lib, "--out", tmp_path / "o")
    assert code == 2 and "encloses no volume" in err and not (tmp_path / "o").exists()


@pytest.mark.parametrize("how", ["absolute", "dotdot", "link"])
def test_a_library_index_pointing_outside_is_refused(builtin_lib, tmp_path, how):
    from infmob_usd.partlib import PartLibraryError, load_library

    lib = _lib_copy(builtin_lib, tmp_path)
    other = _lib_copy(builtin_lib, tmp_path / "elsewhere")
    index = json.loads((lib / "index.json").read_text())
    entry = index["parts"][0]
    outside = other / entry["path"]
    if how == "absolute":
        entry["path"] = str(outside)
    elif how == "dotdot":
        entry["path"] = os.path.relpath(outside, lib)
    else:
        shutil.rmtree(lib / entry["path"])
        os.symlink(outside, lib / entry["path"])
    (lib / "index.json").write_text(json.dumps(index))
    with pytest.raises(PartLibraryError, match="outside the library"):
        load_library(lib)


# --- 10: one-line errors instead of tracebacks --------------------------------------------------------

class _FullDisk:
    """``os`` as layers/common.py sees it, with a disk that fills after ``room`` more writes."""

    def __init__(self, room: int):
        self.room = room

    def __getattr__(self, name):
        return getattr(os, name)

    def write(self, fd, data):
        self.room -= 1
        if self.room < 0:
            raise OSError(28, "No space left on device")
        return os.write(fd, data)


def test_a_full_disk_stops_generate_with_one_line(tmp_path, capsys, monkeypatch):
    from infmob_usd.layers import common

    run(capsys, "generate", CAT, "--texture-size", "16", "--workers", "1", "--out", tmp_path)  # seed 0 is done
    monkeypatch.setattr(common, "os", _FullDisk(room=40))  # the disk fills halfway through the next object
    code, out, err = run(capsys, "generate", CAT, "--texture-size", "16", "--count", "4", "--workers", "1",
                         "--out", tmp_path)
    assert code == 2 and len(err.strip().splitlines()) == 1 and "disk full" in err, err
    assert sorted(p.name for p in (tmp_path / CAT).iterdir()) == [NAME]  # no half-written folder left
    monkeypatch.undo()
    code, out, err = run(capsys, "generate", CAT, "--texture-size", "16", "--count", "2", "--workers", "1",
                         "--out", tmp_path)
    assert code == 0 and len(out.splitlines()) == 1, (out, err)  # resumes: only seed 1 made


@pytest.mark.skipif(os.geteuid() != 0 or not shutil.which("mount"), reason="mounting a small tmpfs needs root")
def test_a_really_full_disk_stops_generate_with_one_line(tmp_path):
    mnt = tmp_path / "small"
    mnt.mkdir()
    if subprocess.run(["mount", "-t", "tmpfs", "-o", "size=1m", "tmpfs", str(mnt)], capture_output=True).returncode:
        pytest.skip("mount not permitted here")
    try:
        p = subprocess.run([sys.executable, "-m", "infmob_usd.cli", "generate", CAT, "--texture-size", "16",
                            "--count", "4", "--workers", "2", "--out", str(mnt / "o")],
                           capture_output=True, text=True, timeout=300)
        assert p.returncode == 2 and "disk full" in p.stderr and "Traceback" not in p.stderr, p.stderr
        assert not [x for x in (mnt / "o").rglob("*") if ".tmp" in x.name or ".old" in x.name]
    finally:
        subprocess.run(["umount", str(mnt)], check=False)


def _cli(*argv, env=None, timeout=120) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "infmob_usd.cli", *map(os.fsdecode, argv)], capture_output=True,
                          timeout=timeout, env={**os.environ, **(env or {})})


def test_non_utf8_folders_and_an_ascii_terminal_are_one_line_or_escaped(obj_dir, tmp_path):
    bad = Path(os.fsdecode(os.fsencode(str(tmp_path)) + b"/\xff\xfe"))
    p = _cli("generate", CAT, "--texture-size", "16", "--workers", "1", "--out", bad)
    err = p.stderr.decode()
    assert p.returncode == 2 and len(err.strip().splitlines()) == 1 and "not valid UTF-8" in err, err
    assert not bad.exists()
    shutil.copytree(obj_dir, bad / CAT / NAME)  # a dataset someone else named
    for env in ({"PYTHONIOENCODING": "ascii"}, {"LC_ALL": "C", "LANG": "C"}):
        p = _cli("validate", "--usd-only", "--no-mass", bad, env=env)
        out, err = p.stdout.decode(), p.stderr.decode()
        assert p.returncode == 1 and "Traceback" not in err, (env, err)
        assert re.search(r"FAIL .*usd_open: the folder's path is not valid UTF-8", out), (env, out)
    p = _cli("gallery", "--no-render", "--out", tmp_path / "site", bad, env={"PYTHONIOENCODING": "ascii"})
    assert p.returncode == 0 and "Traceback" not in p.stderr.decode(), p.stderr
    with pytest.raises(InfmobError, match="not valid UTF-8"):
        infmob_usd.save(infmob_usd.generate(CAT, seed=0, texture_size=16), bad / "api")


def test_ascii_stdout_prints_non_ascii_text_escaped(tmp_path):
    folder = tmp_path / "café"  # a UTF-8 name on a terminal that cannot show it
    p = _cli("generate", CAT, "--texture-size", "16", "--workers", "1", "--out", folder,
             env={"PYTHONIOENCODING": "ascii"})
    assert p.returncode == 0 and b"caf\\xe9" in p.stdout and b"Traceback" not in p.stderr, p.stderr


API_MISUSE = [
    (lambda obj, d: infmob_usd.save("not an object", d), "needs an object made by generate"),
    (lambda obj, d: infmob_usd.save(None, d), "needs an object made by generate"),
    (lambda obj, d: infmob_usd.save(obj, 5), "folder must be a folder path"),
    (lambda obj, d: infmob_usd.save(obj, None), "folder must be a folder path"),
    (lambda obj, d: infmob_usd.save(obj, d, formats=5), "formats must be"),
    (lambda obj, d: infmob_usd.save(obj, d, formats=[1]), "formats must be"),
    (lambda obj, d: infmob_usd.generate(CAT, texture_size=16, parts=5), "parts must be a folder path"),
    (lambda obj, d: infmob_usd.generate(CAT, texture_size=16, parts_share="x"), "parts share must be a number"),
    (lambda obj, d: infmob_usd.generate(CAT, texture_size=16, parts_share=2), r"parts share must be .* got 2"),
    (lambda obj, d: infmob_usd.generate(CAT, texture_size=16, parts_share=-0.1), "parts share must be"),
    (lambda obj, d: infmob_usd.generate(CAT, seed="a", texture_size=16), "seed must be an integer"),
    (lambda obj, d: infmob_usd.generate(CAT, texture_size="16"), "texture size must be"),
    (lambda obj, d: infmob_usd.generate(123), "unknown category"),
]


@pytest.mark.parametrize("call, message", API_MISUSE, ids=[m for _, m in API_MISUSE])
def test_api_misuse_raises_typed_errors(obj_dir, tmp_path, call, message):
    obj = infmob_usd.generate(CAT, seed=0, texture_size=16)
    with pytest.raises(InfmobError, match=message) as info:
        call(obj, tmp_path / "o")
    assert isinstance(info.value, (TypeError, ValueError, KeyError)), type(info.value)
    assert not (tmp_path / "o").exists()


def test_parts_share_without_a_library_is_a_no_op(tmp_path):
    a = infmob_usd.save(infmob_usd.generate(CAT, seed=0, texture_size=16), tmp_path / "a", "urdf")
    b = infmob_usd.save(infmob_usd.generate(CAT, seed=0, texture_size=16, parts_share=1.0), tmp_path / "b", "urdf")
    assert (a / f"{NAME}.urdf").read_bytes() == (b / f"{NAME}.urdf").read_bytes()


def test_an_unreachable_ray_address_fails_in_seconds(tmp_path, capsys):
    t0 = time.monotonic()
    code, _, err = run(capsys, "generate", CAT, "--backend", "ray", "--address", "127.0.0.1:1", "--out", tmp_path / "o")
    assert time.monotonic() - t0 < 10
    assert code == 2 and len(err.strip().splitlines()) == 1 and "cannot reach the Ray cluster" in err, err
    assert not (tmp_path / "o").exists()
    code, _, err = run(capsys, "generate", CAT, "--backend", "ray", "--address", "nonsense", "--out", tmp_path / "o")
    assert code == 2 and "HOST:PORT" in err


def test_a_ray_address_that_is_not_ray_fails_in_seconds(tmp_path):
    pytest.importorskip("ray")
    import socket

    srv = socket.create_server(("127.0.0.1", 0))  # accepts, then says nothing Ray understands
    port = srv.getsockname()[1]
    stop = threading.Event()

    def serve():
        srv.settimeout(0.2)
        while not stop.is_set():
            try:
                srv.accept()[0].close()
            except OSError:
                pass

    threading.Thread(target=serve, daemon=True).start()
    try:
        t0 = time.monotonic()
        p = _cli("generate", CAT, "--backend", "ray", "--address", f"127.0.0.1:{port}", "--out", tmp_path / "o",
                 timeout=60)
        err = p.stderr.decode()
        assert time.monotonic() - t0 < 30
        assert p.returncode == 2 and len(err.strip().splitlines()) == 1 and "Ray cluster" in err, err
        assert not (tmp_path / "o").exists()
    finally:
        stop.set()
        srv.close()


@pytest.fixture(scope="module")
def scene_dir(tmp_path_factory):
    from infmob_usd.scenes import save_scene, scene

    return save_scene(scene("bathroom", 2, texture_size=16), tmp_path_factory.mktemp("scene"))


def _damage_json(scene: Path, tmp_path: Path):
    rec = json.loads((scene / "scene.json").read_text())
    rec["objects"][0]["folder"] = os.path.relpath(tmp_path / "secret", scene)
    (scene / "scene.json").write_text(json.dumps(rec))


def _damage_xml(scene: Path, tmp_path: Path):
    xml = (scene / "scene.xml").read_text()
    first = re.search(r'file="([^"]+)"', xml).group(1)
    (scene / "scene.xml").write_text(xml.replace(first, str(tmp_path / "secret" / "x.xml")))


def _damage_usd(scene: Path, tmp_path: Path):
    usda = (scene / "scene.usda").read_text()
    first = re.search(r"references = @([^@]+)@", usda).group(1)
    (scene / "scene.usda").write_text(usda.replace(first, str(tmp_path / "secret" / "x.usda")))


def _link_object(scene: Path, tmp_path: Path):
    rec = json.loads((scene / "scene.json").read_text())
    obj = scene / rec["objects"][0]["folder"]
    shutil.rmtree(obj)
    obj.symlink_to(tmp_path / "secret", target_is_directory=True)


@pytest.mark.parametrize("damage", [_damage_json, _damage_xml, _damage_usd, _link_object])
def test_a_scene_naming_files_outside_its_folder_is_refused_before_anything_is_loaded(scene_dir, tmp_path, capsys,
                                                                                        damage):
    """A scene folder from elsewhere whose scene.json, scene.xml or scene.usda (or a linked object folder)
    reaches out of it: validate fails it without loading, preview refuses it in one line."""
    (tmp_path / "secret").mkdir()
    scene = tmp_path / "scene"
    shutil.copytree(scene_dir, scene, symlinks=True)
    damage(scene, tmp_path)
    code, out, err = run(capsys, "validate", scene)
    assert code == 1 and "refused" in out and "outside the scene folder" in out, out
    code, out, err = run(capsys, "preview", scene, "--out", tmp_path / "previews")
    assert code == 2 and len(err.strip().splitlines()) == 1 and "outside the scene folder" in err, err
    assert not (tmp_path / "previews").exists() or not any((tmp_path / "previews").rglob("*.png"))
