"""Many objects, safely: a process pool (or Ray), resume, error isolation, a manifest.

One object is a pure function of ``(category, seed, overrides)``: :func:`make_one`.
:func:`run_batch` maps it over a stream of jobs with ``workers`` processes (or on a Ray
cluster) and keeps ``DIR/manifest.jsonl``, one row per finished object. A run:

* holds an advisory lock on ``DIR/.infmob.lock`` (``fcntl.flock``) for its whole length:
  a second run into the same folder fails at once with a message naming the first (pid,
  start time, command), or waits for it with ``wait=True``;
* appends each finished object's row to the manifest and ``fsync``\\ s it, so a run killed
  at any moment (even ``SIGKILL``) resumes without redoing finished objects; the manifest
  is rewritten sorted, through a temporary file, when the run ends;
* on resume, skips an object only when every file its manifest row lists (size and
  SHA-256) is intact; a damaged or half-deleted folder is regenerated;
* writes each object under a temporary name carrying the run's id
  (``.NAME.infmob-PID-TOKEN-XXXX.tmp``) and, at start, removes only such names left by
  runs that are no longer alive: nothing else in ``DIR`` is ever deleted;
* never follows a symbolic link: ``DIR`` itself, category folders (checked at every object, so
  one swapped for a link mid-run is caught), the manifest, ``errors/`` and the lock are refused
  if they are links, so nothing outside ``DIR`` is written;
* records a failing object's traceback in ``DIR/errors/`` without stopping the batch;
* on ``KeyboardInterrupt`` or ``SystemExit`` (the CLI turns ``SIGTERM`` into one) terminates
  its pool's workers before returning; pool workers also die with a killed parent (Linux).
"""

from __future__ import annotations

import datetime
import errno
import fcntl
import hashlib
import itertools
import json
import os
import shutil
import socket
import stat
import sys
import time
import traceback
from collections.abc import Callable, Iterable
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from tqdm import tqdm

from ._version import __version__
from .errors import InfmobError, OutputError
from .runs import TEMP_NAME as _TEMP
from .runs import new_run_id, temp_prefix

MANIFEST = "manifest.jsonl"
ERRORS = "errors"
LOCK = ".infmob.lock"


@dataclass(frozen=True)
class Job:
    category: str
    seed: int
    overrides: tuple[tuple[str, Any], ...] = ()
    texture_size: int = 512
    formats: tuple[str, ...] = ("usd", "urdf", "mjcf")  # see infmob_usd.layers.FORMATS
    parts: str | None = None  # a part library folder (infmob_usd.partlib)
    parts_share: float = 0.5

    @property
    def name(self) -> str:
        return f"{self.category}_{self.seed:06d}"

    def folder(self, out: Path) -> Path:
        return Path(out) / self.category / self.name


def _is_link(path: Path) -> bool:
    try:
        return stat.S_ISLNK(os.lstat(path).st_mode)
    except FileNotFoundError:
        return False


def _real_dir(path: Path) -> bool:
    try:
        return stat.S_ISDIR(os.lstat(path).st_mode)
    except OSError:
        return False


def is_complete(folder: Path) -> bool:
    """An object folder is complete once renamed into place: a real folder with its metadata and every
    file the metadata names (whatever formats it holds)."""
    folder = Path(folder)
    if not _real_dir(folder) or not (folder / "metadata.json").is_file():
        return False
    try:
        files = json.loads((folder / "metadata.json").read_text())["files"].values()
    except (OSError, ValueError, KeyError, TypeError, AttributeError):
        return False
    return all((folder / f).is_file() for f in files)


def file_digests(folder: Path) -> dict[str, list]:
    """``{relative path: [size, sha256 hex]}`` of every regular file under ``folder`` (links skipped)."""
    out = {}
    for root, dirs, files in os.walk(folder):
        dirs.sort()
        for name in sorted(files):
            path = Path(root) / name
            st = os.lstat(path)
            if not stat.S_ISREG(st.st_mode):
                continue
            h = hashlib.sha256()
            with open(path, "rb") as f:
                for block in iter(lambda: f.read(1 << 20), b""):
                    h.update(block)
            out[path.relative_to(folder).as_posix()] = [st.st_size, h.hexdigest()[:32]]
    return out


def damage(folder: Path, row: dict) -> str | None:
    """Why ``folder`` no longer matches its manifest ``row`` (a missing or changed file), or ``None``.

    Files the row does not list (a preview added later) are ignored. Rows written before
    per-file digests existed fall back to :func:`is_complete`.
    """
    if not _real_dir(folder):
        return "missing" if not _is_link(folder) else "a symbolic link"
    files = row.get("files")
    if not isinstance(files, dict):
        return None if is_complete(folder) else "incomplete"
    for rel, want in sorted(files.items()):
        path = folder / rel
        try:
            st = os.lstat(path)
        except OSError:
            return f"{rel} is missing"
        if not stat.S_ISREG(st.st_mode) or st.st_size != want[0]:
            return f"{rel} changed"
        h = hashlib.sha256()
        with open(path, "rb") as f:
            for block in iter(lambda: f.read(1 << 20), b""):
                h.update(block)
        if h.hexdigest()[:32] != want[1][:32]:
            return f"{rel} changed"
    return None


def _pid_alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


def clean_partial(out: Path) -> list[Path]:
    """Remove temporary folders and files of dead runs (names ``.NAME.infmob-PID-TOKEN-X.tmp|.old``).

    Only entries directly in ``out`` or in its category folders are looked at; symbolic links
    are neither followed nor removed, names of any other form are left alone, and entries of a
    process still alive (an API ``save`` running beside us) are kept. Call with the lock held.
    """
    return _remove_temporaries(Path(out), lambda m: not _pid_alive(int(m["pid"])))


def _remove_temporaries(out: Path, ours) -> list[Path]:
    """Remove the temporary entries directly in ``out`` or its category folders whose name match ``ours``
    accepts (links neither followed nor removed)."""
    removed = []
    places = [out] + [d for d in sorted(out.iterdir()) if _real_dir(d) and not d.name.startswith(".")]
    for place in places:
        for entry in sorted(place.iterdir()):
            m = _TEMP.match(entry.name)
            if not m or not ours(m):
                continue
            st = os.lstat(entry)
            if stat.S_ISDIR(st.st_mode):
                shutil.rmtree(entry, ignore_errors=True)
            elif stat.S_ISREG(st.st_mode):
                entry.unlink(missing_ok=True)
            else:
                continue
            removed.append(entry)
    return removed


def _open_nofollow(path: Path, flags: int, what: str) -> int:
    try:
        return os.open(path, flags | os.O_NOFOLLOW | os.O_CLOEXEC, 0o644)
    except OSError as e:
        if e.errno == errno.ELOOP:
            raise OutputError(f"{path} is a symbolic link; infmob writes only inside --out and never through"
                              f" a link: remove it or choose another --out") from None
        raise OutputError(f"cannot write {what} {str(path)!r}: {e.strerror}; choose another --out") from None


def _write_error(out: Path, job: Job) -> str:
    err_dir = Path(out) / ERRORS
    if _is_link(err_dir):
        raise OutputError(f"{err_dir} is a symbolic link; remove it")
    err_dir.mkdir(parents=True, exist_ok=True)
    path = err_dir / f"{job.name}.txt"
    fd = _open_nofollow(path, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, "a traceback")
    with os.fdopen(fd, "w") as f:
        f.write(traceback.format_exc())
    return os.path.relpath(path, out)


FULL_BYTES = 1 << 20
"""Below this much free space an object that failed to write failed for want of it (OpenUSD's writers
report a full disk as a failed save, not as ``ENOSPC``)."""


def disk_full(exc: BaseException, out) -> bool:
    """Whether ``exc`` (raised writing into ``out``) means the disk or the user's quota is full."""
    if isinstance(exc, OSError) and exc.errno in (errno.ENOSPC, errno.EDQUOT):
        return True
    try:
        st = os.statvfs(out)
    except OSError:
        return False
    return st.f_bavail * st.f_frsize < FULL_BYTES


def _disk_full_error(out, what: str) -> OutputError:
    return OutputError(f"disk full writing {what} in {str(out)!r} (no space left on device): free some space and run"
                       f" the same command again (finished objects are kept, nothing half-written is left)")


def make_one(job: Job, out: str, run_id: str | None = None) -> dict:
    """Generate and save one object; return its manifest row (or an error row).

    The row lists every file written (``files``: size and SHA-256) so that a resumed run can
    tell an intact folder from a damaged one.
    """
    from .api import generate
    from .layers import write_object

    t0 = time.perf_counter()
    try:
        extra = {"parts": job.parts, "parts_share": job.parts_share} if job.parts else {}
        obj = generate(job.category, seed=job.seed, texture_size=job.texture_size, **extra, **dict(job.overrides))
        folder = write_object(obj, Path(out) / job.category, formats=job.formats, run_id=run_id)
        files = file_digests(folder)
    except Exception as exc:  # one bad object must not stop the batch
        if disk_full(exc, out):  # ... but a full disk stops it (every object after it would fail alike)
            return {"category": job.category, "seed": job.seed, "overrides": dict(job.overrides),
                    "error": f"{type(exc).__name__}: {' '.join(str(exc).split())}", "disk_full": True}
        try:
            tb = _write_error(Path(out), job)
        except OSError:
            tb = None
        return {"category": job.category, "seed": job.seed, "overrides": dict(job.overrides),
                "error": f"{type(exc).__name__}: {' '.join(str(exc).split())}", "traceback": tb}
    movable = [j for j in obj.joints if j.movable]
    kinds = obj.joint_kinds()
    return {
        "category": job.category,
        "seed": job.seed,
        "overrides": dict(job.overrides),
        "folder": os.path.relpath(folder, out),
        "links": sum(1 for link in obj.links if not link.dummy),
        "movable_joints": sum(kinds.values()),
        "simple_movable_joints": len(movable),
        "joint_kinds": kinds,
        "formats": list(job.formats),
        **({"parts": job.parts, "parts_share": job.parts_share, "retrieval": obj.retrieval} if job.parts else {}),
        **({"notes": list(obj.notes)} if obj.notes else {}),
        "seconds": {k: round(v, 4) for k, v in obj.timings.items()} | {"total": round(time.perf_counter() - t0, 4)},
        "version": __version__,
        "files": files,
    }


def _key(row: dict) -> tuple[str, int]:
    return (row["category"], row["seed"])


def read_manifest(out: Path) -> dict[tuple[str, int], dict]:
    """The rows of ``DIR/manifest.jsonl`` by ``(category, seed)``; a later row wins.

    A last line without its newline (a write cut by a kill) is ignored; any other line that
    is not a row raises :class:`OutputError`.
    """
    rows: dict[tuple[str, int], dict] = {}
    path = Path(out) / MANIFEST
    if _is_link(path):
        raise OutputError(f"{path} is a symbolic link; infmob never writes through a link: remove it")
    if not path.is_file():
        return rows
    text = path.read_bytes().decode("utf-8", "replace")
    lines = text.split("\n")
    for i, line in enumerate(lines, 1):
        if not line.strip():
            continue
        try:
            row = json.loads(line)
            _key(row)
            if not isinstance(row["seed"], int) or not isinstance(row["category"], str):
                raise TypeError
        except (ValueError, KeyError, TypeError):
            if i == len(lines):  # no newline after it: torn by a kill mid-write
                continue
            raise OutputError(f"{path} line {i} is not a manifest row; move the file away (finished objects"
                              f" are then regenerated) or choose another --out") from None
        rows[_key(row)] = row
    return rows


def _rewrite_manifest(out: Path, rows: dict[tuple[str, int], dict], run_id: str) -> None:
    path = Path(out) / MANIFEST
    tmp = Path(out) / f"{temp_prefix(MANIFEST, run_id)}x.tmp"
    fd = _open_nofollow(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, "the manifest")
    try:
        with os.fdopen(fd, "w") as f:
            f.write("".join(json.dumps(rows[k], sort_keys=True) + "\n" for k in sorted(rows)))
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, path)  # replaces a link itself, never its target
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise


class OutputLock:
    """An exclusive advisory lock (``fcntl.flock``) on ``DIR/.infmob.lock`` naming its holder."""

    def __init__(self, out: Path, wait: bool = False, log: Callable[[str], None] | None = None) -> None:
        self.path = Path(out) / LOCK
        self.wait = wait
        self.log = log
        self.fd: int | None = None

    def holder(self) -> str:
        try:
            info = json.loads(Path(self.path).read_text() or "{}")
            return (f"pid {info.get('pid')} on {info.get('host')}, started {info.get('started')},"
                    f" command: {info.get('command')}")
        except (OSError, ValueError):
            return "unknown process"

    def __enter__(self) -> OutputLock:
        fd = _open_nofollow(self.path, os.O_RDWR | os.O_CREAT, "the lock file")
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            if not self.wait:
                os.close(fd)
                raise OutputError(f"another infmob run is writing to {self.path.parent} ({self.holder()});"
                                  f" wait for it (--wait) or choose another --out") from None
            if self.log:
                self.log(f"waiting for another infmob run writing to {self.path.parent} ({self.holder()})")
            fcntl.flock(fd, fcntl.LOCK_EX)
        info = {"pid": os.getpid(), "host": socket.gethostname(),
                "started": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
                "command": " ".join(["infmob", *sys.argv[1:]]) if sys.argv else "?"}
        os.ftruncate(fd, 0)
        os.pwrite(fd, (json.dumps(info) + "\n").encode(), 0)
        self.fd = fd
        _PARENT_FDS.add(fd)
        return self

    def __exit__(self, *exc) -> None:
        if self.fd is not None:
            _PARENT_FDS.discard(self.fd)
            os.ftruncate(self.fd, 0)
            fcntl.flock(self.fd, fcntl.LOCK_UN)
            os.close(self.fd)
            self.fd = None


def progress_bar(total: int | None):
    """A bar with objects/s and ETA on a terminal (tqdm); silent when stderr is a file or a pipe."""
    return tqdm(total=total, unit="obj", file=sys.stderr, disable=None, leave=True)


_PARENT_FDS: set[int] = set()  # the lock and manifest descriptors of a run: closed in its forked workers


def _die_with_parent() -> None:
    """Pool initializer: the worker gets SIGKILL when its parent dies (Linux ``PR_SET_PDEATHSIG``), and
    drops its inherited copies of the run's lock and manifest descriptors (the lock lives with the run)."""
    for fd in list(_PARENT_FDS):
        try:
            os.close(fd)
        except OSError:
            pass
    _PARENT_FDS.clear()
    try:
        import ctypes
        import signal

        signal.signal(signal.SIGTERM, signal.SIG_DFL)  # terminate() must end a worker (not the CLI's handler)
        ctypes.CDLL(None, use_errno=True).prctl(1, int(signal.SIGKILL))  # PR_SET_PDEATHSIG
        if os.getppid() == 1:  # the parent died before the call
            os._exit(1)
    except (OSError, AttributeError):
        pass


def _stop_pool(pool: ProcessPoolExecutor) -> None:
    """Cancel queued jobs and terminate the workers now (no orphans after Ctrl-C or SIGTERM)."""
    procs = list((getattr(pool, "_processes", None) or {}).values())
    pool.shutdown(wait=False, cancel_futures=True)
    for p in procs:
        if p.is_alive():
            p.terminate()
    for p in procs:
        p.join(timeout=5)
        if p.is_alive():
            p.kill()
            p.join(timeout=5)


def run_batch(jobs: Iterable[Job], out: str | Path, workers: int = 1, overwrite: bool = False,
              backend: str = "process", address: str | None = None,
              on_row: Callable[[dict], None] | None = None,
              pool: ProcessPoolExecutor | None = None, total: int | None = None, wait_lock: bool = False,
              log: Callable[[str], None] | None = None) -> list[dict]:
    """Generate every job into ``out``; return the rows of this run (errors included).

    ``jobs`` is consumed lazily (a generator of millions of jobs is fine). Complete,
    intact objects are skipped unless ``overwrite``; a damaged one is regenerated (and
    ``log`` told why). ``pool``: an already running executor to use (with ``workers`` its
    size), e.g. one warmed up by a benchmark; by default a pool is started and shut down
    here. ``total``: the number of jobs, for the progress line. ``wait_lock``: wait for
    another run into ``out`` instead of raising :class:`OutputError` (``log`` is told who it waits for).
    Returned rows omit the per-file digests (they are in the manifest).
    """
    out = Path(out)
    if _is_link(out):
        raise OutputError(f"output folder {str(out)!r} is a symbolic link; infmob never writes through a link:"
                          f" give the real folder or another --out (nothing was written)")
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as e:
        raise OutputError(f"cannot create output folder {str(out)!r}: {e.strerror}; choose another --out") from None
    run_id = new_run_id()
    with OutputLock(out, wait=wait_lock, log=log):
        clean_partial(out)
        rows = read_manifest(out)
        manifest_fd = _open_nofollow(out / MANIFEST, os.O_WRONLY | os.O_APPEND | os.O_CREAT, "the manifest")
        _PARENT_FDS.add(manifest_fd)
        try:
            return _run_locked(jobs, out, workers, overwrite, backend, address, on_row, pool, total, log,
                               rows, manifest_fd, run_id)
        except BaseException:
            # the workers are stopped by now: the folders they were writing are this run's, half-written
            pid, token = run_id.split("-")
            _remove_temporaries(out, lambda m: m["pid"] == pid and m["token"] == token
                                and m.string.endswith(".tmp"))
            raise
        finally:
            _PARENT_FDS.discard(manifest_fd)
            os.close(manifest_fd)
            try:
                _rewrite_manifest(out, rows, run_id)
            except OSError as e:  # a full disk: the appended manifest stays valid; the next run sorts it
                if not disk_full(e, out):
                    raise
                if log:
                    log(f"the manifest of {out} was left unsorted (disk full); the next run sorts it")


def _run_locked(jobs, out, workers, overwrite, backend, address, on_row, pool, total, log, rows, manifest_fd,
                run_id) -> list[dict]:
    def todo():
        for job in jobs:
            cat = out / job.category
            if _is_link(cat) or _is_link(out):  # at every object: a folder swapped for a link mid-run too
                raise OutputError(f"{cat} is a symbolic link; infmob writes only inside --out and never"
                                  f" through a link: remove it or choose another --out")
            row = rows.get((job.category, job.seed))
            if not overwrite and row is not None:
                why = damage(job.folder(out), row)
                if why is None:
                    progress.update()
                    continue
                if log:
                    log(f"{job.folder(out)} is damaged ({why}): regenerating it")
            yield job

    progress = progress_bar(total)
    results: list[dict] = []

    def record(row: dict) -> None:
        if row.get("disk_full"):
            raise _disk_full_error(out, f"{row['category']} seed {row['seed']}")
        if "error" not in row:
            try:
                os.write(manifest_fd, (json.dumps(row, sort_keys=True) + "\n").encode())
                os.fsync(manifest_fd)
            except OSError as e:
                if disk_full(e, out):
                    raise _disk_full_error(out, "the manifest") from None
                raise OutputError(f"cannot append to {out / MANIFEST} ({e.strerror}); choose another --out") from None
            rows[_key(row)] = row
        results.append({k: v for k, v in row.items() if k != "files"})
        progress.update()
        if on_row:
            with tqdm.external_write_mode(file=sys.stdout):  # lines print above the bar, not through it
                on_row(row)

    try:
        if backend == "ray":
            _run_ray(todo(), str(out), address, record, run_id)
        elif workers <= 1 and pool is None:
            for job in todo():
                record(make_one(job, str(out), run_id))
        else:
            _run_pool(todo(), str(out), workers, pool, total, run_id, record, log)
    finally:
        progress.close()
    return results


def _lost_row(job: Job) -> dict:
    return {"category": job.category, "seed": job.seed, "overrides": dict(job.overrides), "traceback": None,
            "error": "lost: a worker process died while generating it (killed, e.g. by the out-of-memory killer);"
                     " run the same command again to redo it (finished objects are kept)"}


def _run_pool(it, out: str, workers: int, pool, total, run_id: str, record, log) -> None:
    """Map :func:`make_one` over the jobs of ``it`` on a process pool, at most 2 jobs per worker in flight
    (memory stays flat). A worker killed from outside (SIGKILL, the OOM killer) breaks the pool: the
    objects in flight are reported lost (error rows, so a rerun redoes them), and a fresh pool goes on."""
    own = pool is None
    if own and total:  # no more processes than jobs: each worker is forked up front
        workers = max(1, min(workers, total))
    carry: list[Job] = []
    while True:
        pool = pool or ProcessPoolExecutor(max_workers=workers, initializer=_die_with_parent)
        pending: dict = {}
        broken = False
        try:
            for job in itertools.chain(carry, it):
                pending[pool.submit(make_one, job, out, run_id)] = job
                if len(pending) >= 2 * workers:
                    break
            carry = []
            while pending:
                done, _ = wait(pending, return_when=FIRST_COMPLETED)
                if any(isinstance(f.exception(), BrokenProcessPool) for f in done):
                    done, _ = wait(pending)  # every job in flight fails with it, at once
                    broken = True
                for fut in done:
                    job = pending.pop(fut)
                    record(_lost_row(job) if isinstance(fut.exception(), BrokenProcessPool) else fut.result())
                    nxt = None if broken else next(it, None)
                    if nxt is not None:
                        try:
                            pending[pool.submit(make_one, nxt, out, run_id)] = nxt
                        except BrokenProcessPool:
                            carry.append(nxt)  # never started: the fresh pool runs it
                if broken:
                    break
        except BaseException:
            _stop_pool(pool)
            raise
        if not broken and not carry:
            if own:
                pool.shutdown(wait=True)
            return
        _stop_pool(pool)
        if log:
            log("a worker process died (killed from outside, e.g. by the out-of-memory killer): the objects it"
                " was making are reported lost; going on with a fresh pool of workers")
        pool, own = None, True


RAY_CONNECT_SECONDS = 5.0
_H2_PREFACE = b"PRI * HTTP/2.0\r\n\r\nSM\r\n\r\n" + b"\x00\x00\x00\x04\x00\x00\x00\x00\x00"  # + empty SETTINGS


def check_ray_address(address: str | None, timeout: float = RAY_CONNECT_SECONDS) -> None:
    """Fail within ``timeout`` seconds, with one line, when ``address`` (``HOST:PORT`` or
    ``ray://HOST:PORT``) does not answer: ``ray.init`` itself retries for minutes. ``None``, ``auto``
    and ``local`` (a cluster Ray finds or starts itself) are left to Ray."""
    if not address or address in ("auto", "local"):
        return
    hostport = address.split("://", 1)[-1].rstrip("/")
    host, _, port = hostport.rpartition(":")
    if not host or not port.isdigit() or not 0 < int(port) < 65536:
        raise InfmobError(f"--address {address!r} is not HOST:PORT (or ray://HOST:PORT); give the Ray head's"
                          f" address, e.g. 10.0.0.5:6379")
    try:
        with socket.create_connection((host.strip("[]"), int(port)), timeout=timeout) as conn:
            # Ray's GCS (and Ray Client) speak gRPC, i.e. HTTP/2: after the client preface the server
            # sends its SETTINGS frame (type 4) at once. Anything else would make ray.init hang.
            conn.sendall(_H2_PREFACE)
            head = b""
            while len(head) < 9:
                chunk = conn.recv(9 - len(head))
                if not chunk:
                    break
                head += chunk
    except OSError as e:
        why = "no answer" if isinstance(e, TimeoutError) else (e.strerror or str(e))
        raise InfmobError(f"cannot reach the Ray cluster at {address} ({why} within {timeout:.0f} s); start it"
                          f" (ray start --head) or fix --address") from None
    if len(head) < 9 or head[3] != 4:
        raise InfmobError(f"{address} answers, but not as a Ray cluster (no gRPC/HTTP2 handshake); give the"
                          f" Ray head's address (ray start --head prints it)")


def connect_ray(address: str | None, quiet: bool = False):
    """``ray``, connected to the cluster at ``address`` (started locally for ``None``): one line and
    seconds when it cannot be reached or does not speak Ray, not a 20-s retry loop and a traceback.
    ``quiet``: Ray's own log lines while connecting (a retry warning per second) are dropped."""
    check_ray_address(address)
    if address and address not in ("auto", "local"):  # read when ray is imported: 3 retries of 1 s
        os.environ.setdefault("RAY_NUM_REDIS_GET_RETRIES", "3")
    try:
        import ray
    except ImportError:
        raise InfmobError("the ray backend needs Ray: pip install -e '.[ray]'") from None
    if ray.is_initialized():
        return ray
    saved = os.dup(2) if quiet else None
    try:
        if quiet:
            null = os.open(os.devnull, os.O_WRONLY)
            os.dup2(null, 2)
            os.close(null)
        ray.init(address=address, ignore_reinit_error=True, log_to_driver=False)
    except Exception as e:  # noqa: BLE001 - ConnectionError, RuntimeError, RpcError ... all the same to us
        first = next((line for line in str(e).splitlines() if line.strip()), type(e).__name__)
        raise InfmobError(f"cannot connect to the Ray cluster at {address or 'a new local cluster'}"
                          f" ({first[:160]}); check --address (ray status on the head node)") from None
    finally:
        if saved is not None:
            os.dup2(saved, 2)
            os.close(saved)
    return ray


def _run_ray(todo: Iterable[Job], out: str, address: str | None, record: Callable[[dict], None],
             run_id: str) -> None:
    ray = connect_ray(address)
    remote = ray.remote(make_one)
    window = max(2 * int(ray.cluster_resources().get("CPU", 1)), 2)
    it = iter(todo)
    refs = [remote.remote(job, out, run_id) for job, _ in zip(it, range(window))]
    while refs:
        done, refs = ray.wait(refs, num_returns=1)
        for ref in done:
            record(ray.get(ref))
            nxt = next(it, None)
            if nxt is not None:
                refs.append(remote.remote(nxt, out, run_id))
