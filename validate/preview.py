"""Pictures of finished object folders: thumbnails, rest/open previews, joint sweeps, contact sheets.

Reads what a user would read — the URDF, its OBJ + MTL meshes and the PBR texture PNGs, and
``metadata.json`` — and renders it with SAPIEN's Vulkan rasteriser (``sapien.render``): the base
colour, roughness, metallic and normal maps of the MTL files (``map_Kd``, ``map_Pr``, ``map_Pm``,
``norm``) are all used, lit by one shadow-casting key light plus a soft studio environment map.

Headless on CPU this needs a software Vulkan driver: Mesa's lavapipe **>= 25** (Debian 12:
``mesa-vulkan-drivers`` from bookworm-backports; the stock Mesa 22 of bookworm does not work).
Nothing here starts a physics engine: the link poses are computed from the URDF joints directly.

The pieces live beside this module: :mod:`.posing` (the object folder read, joint configurations),
:mod:`.studio` (the scene, lights, camera framing, contact shadow), :mod:`.renderer`
(:class:`ObjectRenderer`, :class:`Frame`) and :mod:`.render_backend` (SAPIEN made once, its
self-test, :data:`INSTALL_HINT`); this module composes them into pictures and the command.

Public API
----------
* :func:`render_object` — one picture (H, W, 3) ``uint8`` of an object at a joint fraction.
* :func:`preview` — ``preview.png`` (rest | opened, side by side) and ``sweep.gif`` (each movable
  joint swept from lower to upper limit, in turn).
* :func:`contact_sheet` — one labelled PNG grid of many objects.
* :func:`add_arguments` / :func:`main` — the ``infmob preview`` command.
* :class:`ObjectRenderer` — the object loaded once, for many pictures (tests, batch use).
* :func:`backend_status` — whether rendering works here, and if not, what to install.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np

from .posing import OPEN_FRACTION, _ObjectFiles, _open_gates, _qpos_for
from .render_backend import INSTALL_HINT, PreviewUnavailable, backend_status
from .renderer import Frame, ObjectRenderer

__all__ = [
    "PreviewUnavailable",
    "ObjectRenderer",
    "Frame",
    "render_object",
    "preview",
    "contact_sheet",
    "backend_status",
    "add_arguments",
    "main",
    "INSTALL_HINT",
]

SWEEP_SIZE = 256  # sweep.gif frame edge, pixels
SWEEP_MAX_FRAMES = 120
SWEEP_FRAMES_PER_JOINT = 10
THUMB_SIZE = 256


def simready_thumbnail(folder: Path, name: str) -> Path:
    """Where SimReady looks for the thumbnail of ``folder/<name>.usda`` (as ``infmob_usd.layers.thumbnail``
    writes it; ``tests/test_preview.py`` checks the two agree)."""
    return Path(folder) / ".thumbs" / f"{THUMB_SIZE}x{THUMB_SIZE}" / f"{name}.usda.png"


# ---------------------------------------------------------------------------------------------
# public API


def render_object(folder, size: int = 512, joint_fraction=0.0) -> np.ndarray:
    """Picture of one object folder, (size, size, 3) ``uint8`` RGB.

    ``joint_fraction`` (a number, or ``{joint name: number}``) poses every movable joint that far
    from rest towards its far limit (0 = rest, 1 = fully open; see :meth:`_Joint.at_fraction`);
    the camera is framed on that pose.
    """
    with ObjectRenderer(folder) as r:
        r.set_fraction(joint_fraction)
        return r.render(size, supersample=_supersample(size)).rgb


def _supersample(size: int) -> int:
    """2x2 supersampling (the camera has no MSAA) up to 512 px; above that the pixels are small."""
    return 2 if size <= 512 else 1


def _caption(width: int, text: str, scale: float) -> np.ndarray:
    """A light band ``width`` wide with ``text`` in dark grey, cut to fit."""
    import cv2

    font = cv2.FONT_HERSHEY_SIMPLEX
    (_, th), base = cv2.getTextSize("Ag", font, scale, 1)
    pad = max(3, int(round(th * 0.45)))
    band = np.full((th + base + 2 * pad, width, 3), 245, np.uint8)
    while len(text) > 4 and cv2.getTextSize(text, font, scale, 1)[0][0] > width - 2 * pad:
        text = text[:-4] + "..."
    cv2.putText(band, text, (pad, pad + th), font, scale, (50, 50, 50), 1, cv2.LINE_AA)
    return band


def _caption_scale(width: int) -> float:
    return float(np.clip(width / 640.0, 0.33, 0.8))


def _captioned(img: np.ndarray, text: str) -> np.ndarray:
    return np.concatenate([img, _caption(img.shape[1], text, _caption_scale(img.shape[1]))], axis=0)


def _caption_height(width: int) -> int:
    return _caption(width, "Ag", _caption_scale(width)).shape[0]


def _sweep_plan(files: _ObjectFiles) -> list[tuple[str, dict[str, float]]]:
    """(joint name, qpos) per frame: each movable joint in turn, lower -> upper, the others at rest (the
    doors a joint ``requires_open`` fully open)."""
    movable = files.movable
    if not movable:
        return []
    per = max(4, min(SWEEP_FRAMES_PER_JOINT, SWEEP_MAX_FRAMES // len(movable)))
    joints = movable[: SWEEP_MAX_FRAMES // per]  # past 30 joints the sweep shows the first 30
    rest = {j.name: j.rest() for j in movable}
    # a rack sweeps with its door fully open (``requires_open``)
    return [(j.name, _open_gates(files, {**rest, j.name: float(q)})) for j in joints for q in j.sweep(per)]


def preview(folder, out=None, size: int = 512) -> dict[str, Path]:
    """Write ``preview.png`` (rest | opened) and ``sweep.gif`` for one object folder.

    ``preview.png``: two ``size`` px square panels side by side, the object at rest and with every
    movable joint at 70 % of its range (continuous joints a quarter turn), one camera for both, a
    caption under each. ``sweep.gif``: 256 px frames, each movable joint in turn from its lower to
    its upper limit (10 frames a joint, at most 120 frames). ``out`` is a folder (default: the object
    folder itself). Returns ``{"preview": path, "sweep": path}`` (no sweep without movable joints); rendering
    into the object folder itself also replaces its SimReady thumbnail (``.thumbs/256x256/<name>.usda.png``,
    the writer's sketch) with a 256 px SAPIEN picture at rest (``"thumbnail"``).
    """
    import cv2

    folder = Path(folder)
    out = Path(out) if out is not None else folder
    out.mkdir(parents=True, exist_ok=True)
    written: dict[str, Path] = {}
    with ObjectRenderer(folder) as r:
        files = r.files
        rest_q, open_q = _qpos_for(files, 0.0), _qpos_for(files, OPEN_FRACTION)
        cam = r.camera_for(rest_q, open_q)
        ss = _supersample(size)
        r.set_qpos(rest_q)
        a = r.render(size, cam, ss).rgb
        r.set_qpos(open_q)
        b = r.render(size, cam, ss).rgb
        n = len(files.movable)
        a = _captioned(a, f"{files.name}  rest")
        b = _captioned(b, f"{n} movable joint{'s' * (n != 1)} at {int(OPEN_FRACTION * 100)}%" if n
                       else "no movable joints")
        if out == folder:  # SAPIEN's picture replaces the writer's sketch as the SimReady thumbnail
            r.set_qpos(rest_q)
            thumb = simready_thumbnail(folder, files.name)
            thumb.parent.mkdir(parents=True, exist_ok=True)
            cv2.imwrite(str(thumb), r.render(THUMB_SIZE, r.camera_for(rest_q), _supersample(THUMB_SIZE)).rgb[..., ::-1])
            written["thumbnail"] = thumb
        gap = np.full((a.shape[0], max(2, size // 128), 3), 255, np.uint8)
        path = out / "preview.png"
        cv2.imwrite(str(path), np.concatenate([a, gap, b], axis=1)[..., ::-1])
        written["preview"] = path
        plan = _sweep_plan(files)
        if plan:
            cam = r.camera_for(rest_q, *(q for _, q in plan))
            frames = []
            for jname, q in plan:
                r.set_qpos(q)
                frames.append(_captioned(r.render(SWEEP_SIZE, cam, 1).rgb, jname))
            written["sweep"] = _write_gif(out / "sweep.gif", frames)
    return written


def _write_gif(path: Path, frames: list[np.ndarray], fps: float = 10.0) -> Path:
    from PIL import Image

    imgs = [Image.fromarray(f) for f in frames]
    # one palette from a few frames: small file, steady colours from frame to frame
    probe = np.concatenate([frames[i] for i in np.linspace(0, len(frames) - 1, min(6, len(frames))).astype(int)])
    pal = Image.fromarray(probe).quantize(colors=255, method=Image.Quantize.MEDIANCUT)
    q = [im.quantize(palette=pal, dither=Image.Dither.NONE) for im in imgs]
    q[0].save(path, save_all=True, append_images=q[1:], duration=int(1000 / fps), loop=0)
    return path


def contact_sheet(folders, out_png, cell: int = 256, joint_fraction=0.0, columns: int | None = None,
                  open_fraction: float | None = None) -> Path:
    """One PNG grid of many object folders, each cell captioned ``category  seed N  J joints``.

    The sheet is ``columns * cell`` wide and ``rows * cell`` high (``columns`` defaults to
    ``ceil(sqrt(n))``, ``rows = ceil(n / columns)``); each cell is the picture with its caption
    under it. Objects are shown at rest unless ``joint_fraction`` says otherwise. With
    ``open_fraction`` every row is followed by a row of the same objects with their joints at that
    fraction of their range (dependent parts after their door), captioned ``... NN% open``:
    twice the rows.
    """
    import cv2

    folders = [Path(f) for f in folders]
    if not folders:
        raise ValueError("contact_sheet needs at least one object folder")
    cols = columns or math.ceil(math.sqrt(len(folders)))
    rows = math.ceil(len(folders) / cols)
    poses = [joint_fraction] if open_fraction is None else [joint_fraction, open_fraction]
    sheet = np.full((rows * len(poses) * cell, cols * cell, 3), 255, np.uint8)
    img_h = cell - _caption_height(cell)
    for i, f in enumerate(folders):
        y, x = divmod(i, cols)
        with ObjectRenderer(f) as r:
            meta = r.files.metadata
            n = len(r.files.movable)
            text = f"{meta.get('category', r.files.name)}  seed {meta.get('seed', '?')}  {n} joint{'s' * (n != 1)}"
            for k, fraction in enumerate(poses):
                r.set_fraction(fraction)
                img = r.render(cell, r.camera_for(aspect=cell / img_h), _supersample(cell), height=img_h).rgb
                img = _captioned(img, text + (f"  {fraction:.0%} open" if k else ""))
                cv2.rectangle(img, (0, 0), (cell - 1, cell - 1), (255, 255, 255), 1)
                row = y * len(poses) + k
                sheet[row * cell:(row + 1) * cell, x * cell:(x + 1) * cell] = img
    out_png = Path(out_png)
    out_png.parent.mkdir(parents=True, exist_ok=True)
    if not cv2.imwrite(str(out_png), sheet[..., ::-1]):
        raise OSError(f"cannot write the contact sheet {str(out_png)!r}")
    return out_png


# ---------------------------------------------------------------------------------------------
# command line: infmob preview PATH... [--out DIR] [--size PX] | infmob preview --sheet DIR [--out FILE]


def add_arguments(parser) -> None:
    parser.add_argument("paths", nargs="*", metavar="PATH",
                        help="an object or scene folder, or a folder of them (a scene gets preview.png at rest and"
                             " preview_open.png with every joint open)")
    parser.add_argument("--out", default=None,
                        help="previews: folder for DIR/<name>/preview.png + sweep.gif (default: beside each "
                             "object); with --sheet: the PNG file (default: DIR/contact_sheet.png)")
    parser.add_argument("--size", type=int, default=None, metavar="PX",
                        help="panel edge in pixels (default 512); with --sheet: the cell edge (default 256)")
    parser.add_argument("--sheet", metavar="DIR", default=None,
                        help="write one contact sheet of every object found under DIR instead")
    parser.add_argument("--open", type=float, default=None, metavar="F", dest="open_fraction",
                        help="with --sheet: under each row of objects at rest, a row of them with every joint at "
                             "fraction F (0-1] of its range")


def main(args) -> int:
    """Run ``infmob preview`` with the namespace of :func:`add_arguments`; returns the exit code."""
    from .files import find_objects, find_scenes, outside_scenes

    if args.size is not None and not 16 <= args.size <= 4096:
        print(f"infmob: error: --size must be 16..4096 pixels, got {args.size}", file=sys.stderr)
        return 2
    opened = getattr(args, "open_fraction", None)
    if opened is not None and (not args.sheet or not 0 < opened <= 1):
        print(f"infmob: error: --open takes a fraction in (0, 1] and needs --sheet, got {opened}", file=sys.stderr)
        return 2
    try:
        if args.sheet:
            found = find_objects([args.sheet])
            if not found:
                print(f"infmob: error: no object folders (with metadata.json) under {args.sheet}", file=sys.stderr)
                return 2
            cell = args.size or 256
            out = Path(args.out) if args.out else Path(args.sheet) / "contact_sheet.png"
            if out.suffix.lower() != ".png" or out.is_dir():
                print(f"infmob: error: with --sheet, --out is the PNG file to write (NAME.png), got {str(out)!r}",
                      file=sys.stderr)
                return 2
            if not out.parent.is_dir() and out.parent.exists():
                print(f"infmob: error: --out {str(out)!r}: {str(out.parent)!r} is not a folder", file=sys.stderr)
                return 2
            if out.parent.is_dir():  # fail before rendering, not after
                import tempfile

                try:
                    with tempfile.NamedTemporaryFile(dir=out.parent, prefix=".infmob-probe-"):
                        pass
                except OSError as exc:
                    print(f"infmob: error: --out {str(out)!r}: cannot write in {str(out.parent)!r} "
                          f"({exc.strerror or type(exc).__name__}); choose another --out", file=sys.stderr)
                    return 2
            path = contact_sheet(found, out, cell=cell, open_fraction=opened)
            print(f"{path}  ({len(found)} objects)")
            return 0
        if not args.paths:
            print("infmob: error: give object folders (PATH...) or --sheet DIR", file=sys.stderr)
            return 2
        scenes = find_scenes(args.paths)
        found = outside_scenes(find_objects(args.paths), scenes)
        if not found and not scenes:
            print(f"infmob: error: no object folders (with metadata.json) or scene folders (with scene.json) in"
                  f" {' '.join(args.paths)}", file=sys.stderr)
            return 2
        if args.out and Path(args.out).exists() and not Path(args.out).is_dir():
            print(f"infmob: error: --out {args.out!r} is a file; give a folder for the previews", file=sys.stderr)
            return 2
        for folder in found:
            out = Path(args.out) / folder.name if args.out else None
            written = preview(folder, out, size=args.size or 512)
            print("  ".join(str(p) for p in written.values()))
        for folder in scenes:
            from .scene_preview import scene_previews

            side = args.size or 1024
            try:
                written = scene_previews(folder, Path(args.out) / folder.name if args.out else None, side,
                                         side * 3 // 4)
            except (ValueError, KeyError, TypeError) as exc:  # a scene.json from elsewhere
                print(f"infmob: error: scene {folder}: {exc}; preview only scenes written by `infmob scene`",
                      file=sys.stderr)
                return 2
            print("  ".join(str(p) for p in written.values()))
        return 0
    except PreviewUnavailable as exc:
        print(f"infmob: error: {exc}", file=sys.stderr)
        return 2
    except OSError as exc:
        print(f"infmob: error: {exc}; choose another --out", file=sys.stderr)
        return 2
