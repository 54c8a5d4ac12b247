"""Every writer: USD layers, URDF + meshes, textures, semantics and metadata.

:func:`write_object` writes one object folder atomically: everything goes into a
hidden temporary folder beside the target, which is renamed into place only
when complete, so a crash never leaves a half-written asset under its real name.
"""

from __future__ import annotations

import os
import shutil
import tempfile
import time
from pathlib import Path

from infmob_usd.errors import OutputError

from .common import visual_meshes
from .meta import write_metadata, write_semantics
from .urdf import write_urdf
from .usd import write_usd

TEXTURES = "textures"


def check_output_dir(out: Path) -> Path:
    """Create ``out`` if needed; raise :class:`OutputError` if it cannot hold objects."""
    out = Path(out)
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
            (tex / f"{slot}_{name}.png").write_bytes(data)


def write_object(obj, out: Path, run_id: str | None = None) -> Path:
    """Write ``obj`` to ``out/<name>/`` and return that folder (replaced if it exists).

    The temporary folders are named ``.NAME.infmob-RUNID-XXXX.tmp`` / ``.old`` (``run_id``: the
    batch run's, by default this process's), the only names :func:`infmob_usd.batch.clean_partial`
    ever removes.
    """
    from infmob_usd.batch import new_run_id, temp_prefix

    out = check_output_dir(out)
    final = out / obj.name
    prefix = temp_prefix(obj.name, run_id or new_run_id())
    try:
        tmp = Path(tempfile.mkdtemp(prefix=prefix, suffix=".tmp", dir=out))
    except OSError as e:
        raise OutputError(f"cannot write in output folder {str(out)!r}: {e.strerror}; choose another") from None
    obj._visual_meshes = None
    try:
        t0 = time.perf_counter()
        obj._visual_meshes = visual_meshes(obj)  # normals and UVs once, for both writers
        obj.timings["geometry"] = obj.timings.get("geometry", 0.0) + time.perf_counter() - t0
        for stage, writer in (("textures_io", write_textures), ("usd", write_usd), ("urdf", write_urdf),
                              ("metadata", write_semantics), ("metadata", write_metadata)):
            t0 = time.perf_counter()
            writer(obj, tmp)
            obj.timings[stage] = obj.timings.get(stage, 0.0) + time.perf_counter() - t0
        os.chmod(tmp, 0o755)
        if final.exists():
            old = Path(tempfile.mkdtemp(prefix=prefix, suffix=".old", dir=out))
            os.replace(final, old / "x")
            os.replace(tmp, final)
            shutil.rmtree(old, ignore_errors=True)
        else:
            os.replace(tmp, final)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    finally:
        obj._visual_meshes = None
    return final
