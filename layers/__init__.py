"""Every writer: USD layers, URDF + meshes, MJCF, GLB, textures, semantics and metadata.

:func:`write_object` writes one object folder atomically: everything goes into a
hidden temporary folder beside the target, which is renamed into place only
when complete, so a crash never leaves a half-written asset under its real name.

Which formats are written is a list of names from :data:`FORMATS` (default
:data:`DEFAULT_FORMATS`); a new format is one entry there: its writer, the stage its
seconds are counted under, and the file it writes (recorded in ``metadata.json``).
Textures, ``semantics.txt``, ``metadata.json`` and ``annotations.json`` are always written.
"""

from __future__ import annotations

import os
import shutil
import tempfile
import time
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from pathlib import Path

from infmob_usd.errors import OutputError

from .common import visual_meshes, write_file
from .glb import write_glb
from .meta import write_annotations, write_metadata, write_semantics
from .mjcf import write_mjcf
from .thumbnail import write_thumbnail
from .urdf import write_urdf
from .usd import write_usd
from .usd_isaac import write_usd_isaac

TEXTURES = "textures"


@dataclass(frozen=True)
class Format:
    """One output format: ``writer(obj, folder)``, its timing stage and its file (``{name}`` = object name)."""

    writer: Callable
    stage: str
    file: str
    about: str
    key: str = ""  # the name metadata.json lists the file under, if not the format's own (two USD layouts)


FORMATS: dict[str, Format] = {
    "usd": Format(write_usd, "usd", "{name}.usda", "OpenUSD layers (payload/, Omniverse, Isaac)"),
    "urdf": Format(write_urdf, "urdf", "{name}.urdf", "URDF + OBJ meshes (SAPIEN, ManiSkill, PyBullet, MuJoCo)"),
    "mjcf": Format(write_mjcf, "mjcf", "{name}.xml", "MJCF for MuJoCo (materials, contact excludes)"),
    "glb": Format(write_glb, "glb", "{name}.glb", "binary glTF 2.0 with PBR materials, for web viewers"),
    "isaac": Format(write_usd_isaac, "usd", "{name}.usda", "OpenUSD in Isaac Sim's layout (payloads/, runnables/:"
                    " PhysX, Newton, MuJoCo variant sets), instead of usd", key="usd"),
}
DEFAULT_FORMATS = ("usd", "urdf", "mjcf")


def parse_formats(formats: str | Iterable[str] | None) -> tuple[str, ...]:
    """``"usd,urdf"`` or ``["usd", "urdf"]`` -> ``("usd", "urdf")`` in :data:`FORMATS` order;
    ``None`` -> :data:`DEFAULT_FORMATS`. Unknown or no names raise :class:`OutputError`."""
    if formats is None:
        return DEFAULT_FORMATS
    names = [f.strip().lower() for f in (formats.split(",") if isinstance(formats, str) else formats)]
    names = [n for n in names if n]
    unknown = [n for n in names if n not in FORMATS]
    if unknown or not names:
        what = f"unknown format(s) {', '.join(map(repr, unknown))}" if unknown else "no format given"
        raise OutputError(f"{what}; choose from {','.join(FORMATS)} (e.g. --formats usd,urdf,mjcf,glb)")
    if "usd" in names and "isaac" in names:
        raise OutputError("formats usd and isaac are two layouts of the same USD file; choose one")
    return tuple(n for n in FORMATS if n in names)


def check_output_dir(out: Path) -> Path:
    """Create ``out`` if needed; raise :class:`OutputError` if it cannot hold objects, or if it is a
    symbolic link (checked at every object written: a folder swapped for a link while a run goes on
    must not send the rest of the run elsewhere)."""
    out = Path(out)
    try:
        str(out).encode("utf-8")
    except UnicodeEncodeError:  # OpenUSD takes paths as UTF-8 and fails on every object
        raise OutputError(f"output folder {os.fsencode(out).decode('utf-8', 'backslashreplace')} is not valid"
                          f" UTF-8; OpenUSD cannot write there: give a folder whose name is UTF-8") from None
    if os.path.islink(out):
        raise OutputError(f"output folder {str(out)!r} is a symbolic link; infmob never writes through a link:"
                          f" give the real folder or another --out (nothing was written)")
    if out.exists() and not out.is_dir():
        raise OutputError(f"output path {str(out)!r} is a file; give a folder (--out DIR)")
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as e:
        raise OutputError(f"cannot create output folder {str(out)!r}: {e.strerror}; choose another --out") from None
    if not os.access(out, os.W_OK | os.X_OK):
        raise OutputError(f"output folder {str(out)!r} is not writable; choose another --out")
    return out


def write_textures(obj, folder: Path) -> None:
    """``textures/<slot>_<map>.png`` from the PNG bytes in ``obj.textures``."""
    tex = folder / TEXTURES
    tex.mkdir()
    for slot, maps in obj.textures.items():
        for name, data in maps.items():
            if not isinstance(data, bytes) or data[:8] != b"\x89PNG\r\n\x1a\n":
                raise ValueError(f"texture {slot}_{name} is not PNG bytes ({type(data).__name__})")
            write_file(tex / f"{slot}_{name}.png", data)


def publish(tmp: Path, final: Path, prefix: str) -> None:
    """Put the finished temporary folder ``tmp`` in place as ``final`` (replacing what is there, which is moved
    aside under ``prefix`` and removed), after checking that ``final``'s parent is still the real folder it was,
    not a link put in its place meanwhile."""
    os.chmod(tmp, 0o755)
    check_output_dir(final.parent)
    if final.exists():
        old = Path(tempfile.mkdtemp(prefix=prefix, suffix=".old", dir=final.parent))
        os.replace(final, old / "x")
        os.replace(tmp, final)
        shutil.rmtree(old, ignore_errors=True)
    else:
        os.replace(tmp, final)


def write_object(obj, out: Path, formats: str | Iterable[str] | None = None, run_id: str | None = None) -> Path:
    """Write ``obj`` to ``out/<name>/`` in ``formats`` (default :data:`DEFAULT_FORMATS`) and return
    that folder (replaced if it exists).

    The temporary folders are named ``.NAME.infmob-RUNID-XXXX.tmp`` / ``.old`` (``run_id``: the
    batch run's, by default this process's), the only names :func:`infmob_usd.batch.clean_partial`
    ever removes.
    """
    from infmob_usd.runs import new_run_id, temp_prefix

    formats = parse_formats(formats)
    out = check_output_dir(out)
    final = out / obj.name
    prefix = temp_prefix(obj.name, run_id or new_run_id())
    try:
        tmp = Path(tempfile.mkdtemp(prefix=prefix, suffix=".tmp", dir=out))
    except OSError as e:
        raise OutputError(f"cannot write in output folder {str(out)!r}: {e.strerror}; choose another") from None
    obj._visual_meshes = obj._mesh_files = None
    files = {FORMATS[name].key or name: "./" + FORMATS[name].file.format(name=obj.name) for name in formats}
    stages = [("textures_io", write_textures)]
    stages += [(FORMATS[name].stage, FORMATS[name].writer) for name in formats]
    stages += [("metadata", write_semantics), ("metadata", lambda o, f: write_metadata(o, f, files)),
               ("metadata", write_annotations)]
    if "usd" in files:  # the SimReady thumbnail beside the USD root layer
        stages.append(("thumbnail", write_thumbnail))
    try:
        t0 = time.perf_counter()
        obj._visual_meshes = visual_meshes(obj)  # normals and UVs once, for both writers
        obj.timings["geometry"] = obj.timings.get("geometry", 0.0) + time.perf_counter() - t0
        for stage, writer in stages:
            t0 = time.perf_counter()
            writer(obj, tmp)
            obj.timings[stage] = obj.timings.get(stage, 0.0) + time.perf_counter() - t0
        publish(tmp, final, prefix)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    finally:
        obj._visual_meshes = obj._mesh_files = None
    return final
