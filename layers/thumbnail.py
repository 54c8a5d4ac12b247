"""The SimReady thumbnail: ``.thumbs/256x256/<name>.usda.png`` beside the USD root layer (SR.002).

The writer draws it without any GPU or Vulkan: a small numpy z-buffer rasteriser of the visual
meshes at rest, flat-shaded in each material's base colour, seen from the front-right and above
(fronts face +X, Z up), orthographic, 2x2 supersampled. ``infmob preview`` (SAPIEN's renderer,
where Vulkan runs) replaces it with a rendered picture of the same size.
"""

from __future__ import annotations

from collections import deque
from itertools import repeat
from pathlib import Path

import numpy as np

from infmob_usd.triangles import _norm, cross_rows

from .common import visual_meshes, write_file

SIZE = 256
THUMBS = Path(".thumbs") / f"{SIZE}x{SIZE}"
BACKGROUND = np.array([0.74, 0.74, 0.74])  # linear; (224, 224, 224) in sRGB, as validate.preview
VIEW = np.array([1.0, 0.78, 0.62])  # towards the camera: front (+X), right (+Y), above
LIGHT = np.array([0.55, 0.35, 0.76])
SUPERSAMPLE = 2
FILL = 0.88  # share of the frame the object's projected bounds may use


def thumbnail_path(folder: Path, name: str) -> Path:
    """Where SimReady looks for the thumbnail of ``folder/<name>.usda``."""
    return Path(folder) / THUMBS / f"{name}.usda.png"


def _srgb(linear: np.ndarray) -> np.ndarray:
    c = np.clip(linear, 0.0, 1.0)
    return np.where(c <= 0.0031308, c * 12.92, 1.055 * c ** (1 / 2.4) - 0.055)


_BACKGROUNDS: dict[int, np.ndarray] = {}


def _background(px: int) -> np.ndarray:
    """The empty ``(px, px, 3)`` canvas in the background colour (kept per size: never drawn on)."""
    img = _BACKGROUNDS.get(px)
    if img is None:
        bg = tuple(int(round(c * 255)) for c in _srgb(BACKGROUND))
        img = np.empty((px, px, 3), np.uint8)
        for channel, value in enumerate(bg):  # one channel at a time: ~10x a broadcast of the tuple
            img[..., channel] = value
        img.flags.writeable = False
        _BACKGROUNDS[px] = img
    return img


def rasterise(verts: np.ndarray, faces: np.ndarray, colours: np.ndarray, size: int = SIZE) -> np.ndarray:
    """Draw triangles, flat-shaded, into a ``(size, size, 3)`` uint8 sRGB image.

    Painter's algorithm: back faces culled, front faces sorted far to near by their mean depth, each
    filled by OpenCV at ``SUPERSAMPLE`` times the size with 1/16 px precision, then area-averaged down
    (~10 ms per thousand triangles). A sketch: where a large face and a small one overlap in depth the
    order can be wrong (a table's rails may show through its top); ``infmob preview`` renders properly.

    Parameters
    ----------
    verts : (n, 3) float
        World positions.
    faces : (m, 3) int
        Triangles (either winding: both sides are lit).
    colours : (m, 3) float
        Linear RGB base colour per triangle.
    """
    import cv2

    px = size * SUPERSAMPLE
    img = _background(px).copy()  # a copy of the filled canvas: ~5x filling it again
    if len(faces):
        d = VIEW / np.linalg.norm(VIEW)
        right = np.cross([0.0, 0.0, 1.0], d)
        right /= np.linalg.norm(right)
        up = np.cross(d, right)
        cam = verts @ np.stack([right, up, d], 1)  # (n, 3): screen x, y, depth (larger = nearer)
        sx, sy = cam[:, 0], cam[:, 1]
        lo, hi = np.array([sx.min(), sy.min()]), np.array([sx.max(), sy.max()])
        scale = FILL * px / max(float((hi - lo).max()), 1e-9)
        xy = (cam[:, :2] - (lo + hi) / 2) * scale + px / 2
        xy[:, 1] = px - xy[:, 1]  # image rows grow downwards
        t = xy[faces]
        # back faces (clockwise on screen: rows grow downwards) are hidden by the closed meshes' front faces
        front = ((t[:, 1, 0] - t[:, 0, 0]) * (t[:, 2, 1] - t[:, 0, 1])
                 - (t[:, 1, 1] - t[:, 0, 1]) * (t[:, 2, 0] - t[:, 0, 0])) < 0
        idx = np.flatnonzero(front)
        order = idx[np.argsort(cam[faces[idx], 2].mean(1), kind="stable")]  # far first (by mean depth)
        fo = faces[order]
        # shading of the faces drawn only
        n = cross_rows(verts[fo[:, 1]] - verts[fo[:, 0]], verts[fo[:, 2]] - verts[fo[:, 0]])
        n /= np.maximum(_norm(n), 1e-30)[:, None]
        shade = 0.3 + 0.7 * np.abs(n @ (LIGHT / np.linalg.norm(LIGHT)))
        rgb = np.round(_srgb(colours[order] * shade[:, None]) * 255).astype(np.uint8)
        pts = np.round(t[order] * 16).astype(np.int32)  # 4 fractional bits
        # one C call per triangle, driven by map (no Python loop body)
        deque(map(cv2.fillConvexPoly, repeat(img), pts, rgb.tolist(), repeat(cv2.LINE_8), repeat(4)), maxlen=0)
    return cv2.resize(img, (size, size), interpolation=cv2.INTER_AREA)


def sketch(obj, size: int = SIZE) -> np.ndarray:
    """The object at rest as :func:`rasterise` draws it; see-through materials (opacity < 0.5) are left out."""
    verts, faces, colours, off = [], [], [], 0
    for link in obj.links:
        for _vname, slot, _role, v, f, _n, _uv in visual_meshes(obj)[link.name]:
            look = obj.materials[slot]
            if float(look.opacity) < 0.5:
                continue
            verts.append(np.asarray(v, float) + link.origin)
            faces.append(np.asarray(f) + off)
            colours.append(np.broadcast_to(np.asarray(look.base_color, float), (len(f), 3)))
            off += len(v)
    if not faces:
        return rasterise(np.zeros((0, 3)), np.zeros((0, 3), int), np.zeros((0, 3)), size)
    return rasterise(np.vstack(verts), np.vstack(faces), np.vstack(colours), size)


def write_thumbnail(obj, folder: Path) -> Path:
    """Write the sketched thumbnail of ``obj`` into ``folder`` (see :func:`thumbnail_path`)."""
    from infmob_usd.materials import encode_png

    path = thumbnail_path(folder, obj.name)
    path.parent.mkdir(parents=True, exist_ok=True)
    write_file(path, encode_png(sketch(obj)))
    return path
