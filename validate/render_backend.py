"""SAPIEN's Vulkan renderer for the pictures, made once per process, or a one-line reason and what
to install (:data:`INSTALL_HINT`).

:func:`backend_status` tries a tiny render in a child process that loads this file by path, so
this module imports nothing of the package (the package's error type only where it is there).
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

try:  # the package error type, so the CLI prints the message without a traceback
    from infmob_usd.errors import InfmobError as _BaseError
except Exception:  # pragma: no cover - module used standalone
    _BaseError = Exception


INSTALL_HINT = (
    "infmob preview renders with SAPIEN (pip install 'sapien==3.0.3') on a Vulkan device. Headless on CPU "
    "that is Mesa's lavapipe >= 25; on Debian 12 (bookworm):\n"
    "  echo 'deb http://deb.debian.org/debian bookworm-backports main' > /etc/apt/sources.list.d/backports.list\n"
    "  apt-get update && apt-get install -y -t bookworm-backports mesa-vulkan-drivers libvulkan1\n"
    "(the stock bookworm Mesa 22 lavapipe is too old)."
)


class PreviewUnavailable(_BaseError, RuntimeError):
    """Rendering is impossible here: the message names what is missing and how to install it."""


_STATE: dict = {}


def _sapien():
    """Import SAPIEN and create its renderer once, or raise :class:`PreviewUnavailable`."""
    if "sapien" in _STATE:
        return _STATE["sapien"]
    if "error" in _STATE:
        raise PreviewUnavailable(_STATE["error"])
    try:
        import sapien  # noqa: F401
        import sapien.render
    except Exception as exc:  # ImportError, or a broken wheel
        _STATE["error"] = f"cannot import sapien ({exc}).\n{INSTALL_HINT}"
        raise PreviewUnavailable(_STATE["error"]) from None
    try:
        # mipmapped textures: no sparkle where a 512 px wood texture covers a few pixels
        sapien.render.set_global_config(max_num_materials=4096, max_num_textures=8192, default_mipmap_levels=8)
        sapien.render.set_log_level("off")
        _STATE["renderer"] = sapien.render.SapienRenderer()
    except Exception as exc:
        _STATE["error"] = f"SAPIEN found no Vulkan device to render with ({exc}).\n{INSTALL_HINT}"
        raise PreviewUnavailable(_STATE["error"]) from None
    _STATE["sapien"] = sapien
    return sapien


def backend_status(timeout: float = 180.0) -> tuple[bool, str]:
    """Try a tiny render in a child process: ``(True, device)`` or ``(False, why + how to install)``.

    A child process, because a broken Vulkan driver can crash its process instead of raising.
    """
    if "status" in _STATE:
        return _STATE["status"]
    # load this file by path: the child needs neither the package nor its import machinery
    code = (
        "import importlib.util, sys\n"
        f"spec = importlib.util.spec_from_file_location('_infmob_preview_probe', {str(Path(__file__).resolve())!r})\n"
        "p = sys.modules[spec.name] = importlib.util.module_from_spec(spec); spec.loader.exec_module(p)\n"
        "try:\n"
        "    print(p._selftest(), flush=True)\n"
        "except p.PreviewUnavailable as e:\n"
        "    print('UNAVAILABLE:', e, flush=True); sys.exit(3)\n"
    )
    try:
        run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        status = (False, f"a test render took over {timeout:.0f} s.\n{INSTALL_HINT}")
    else:
        out = (run.stdout + run.stderr).strip()
        if run.returncode == 0 and "RENDER OK" in run.stdout:
            status = (True, run.stdout.strip().splitlines()[-1])
        elif run.returncode == 3:
            status = (False, out.split("UNAVAILABLE:", 1)[-1].strip())
        else:
            tail = "\n".join(out.splitlines()[-5:])
            status = (False, f"a test render failed (exit {run.returncode}): {tail}\n{INSTALL_HINT}")
    _STATE["status"] = status
    return status


def _selftest() -> str:
    sapien = _sapien()
    scene = sapien.Scene()
    scene.set_ambient_light([0.5, 0.5, 0.5])
    body = sapien.render.RenderBodyComponent()
    body.attach(sapien.render.RenderShapeBox([0.2, 0.2, 0.2], sapien.render.RenderMaterial(base_color=[1, 0, 0, 1])))
    ent = sapien.Entity()
    ent.add_component(body)
    scene.add_entity(ent)
    cam = scene.add_camera("probe", 32, 32, 1.0, 0.01, 10.0)
    cam.entity.set_pose(sapien.Pose([-1.0, 0, 0]))
    scene.update_render()
    cam.take_picture()
    rgb = cam.get_picture("Color")[..., :3]
    if not (rgb[16, 16, 0] > 0.2 and rgb[16, 16, 1] < 0.1):
        raise PreviewUnavailable(f"the test render came back wrong (centre pixel {rgb[16, 16]}).\n{INSTALL_HINT}")
    return "RENDER OK " + sapien.render.get_device_summary().splitlines()[0].strip()
