"""The SimReady thumbnail: ``.thumbs/256x256/<name>.usda.png`` beside the USD root layer (SR.002).

The writer draws it without any GPU or Vulkan: a small numpy z-buffer rasteriser of the visual
meshes at rest, flat-shaded in each material's base colour, seen from the front-right and above
(fronts face +X, Z up), orthographic, 2x2 supersampled. ``infmob preview`` (SAPIEN's renderer,
where Vulkan runs) replaces it with a rendered picture of the same size.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from .common import visual_meshes

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


def rasterise(verts: np.ndarray, faces: np.ndarray, colours: np.ndarray, size: int = SIZE) -> np.ndarray:
    """Draw triangles, flat-shaded, into a ``(size, size, 3)`` uint8 sRGB image.

    Parameters
    ----------
    verts : (n, 3) float
        World positions.
    faces : (m, 3) int
        Triangles (either winding: both sides are lit).
    colours : (m, 3) float
        Linear RGB base colour per triangle.
    """
    px = size * SUPERSAMPLE
    img = np.empty((px * px, 3))
    img[:] = BACKGROUND
    if len(faces):
        d = VIEW / np.linalg.norm(VIEW)
        right = np.cross([0.0, 0.0, 1.0], d)
        right /= np.linalg.norm(right)
        up = np.cross(d, right)
        cam = verts @ np.stack([right, up, d], 1)  # (n, 3): screen x, y, depth (larger = nearer)
        lo, hi = cam[:, :2].min(0), cam[:, :2].max(0)
        scale = FILL * px / max(float((hi - lo).max()), 1e-9)
        xy = (cam[:, :2] - (lo + hi) / 2) * scale + px / 2
        xy[:, 1] = px - xy[:, 1]  # image rows grow downwards
        tri, z = xy[faces], cam[faces, 2]  # (m, 3, 2), (m, 3)
        n = np.cross(verts[faces[:, 1]] - verts[faces[:, 0]], verts[faces[:, 2]] - verts[faces[:, 0]])
        n /= np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-30)
        shade = 0.3 + 0.7 * np.abs(n @ (LIGHT / np.linalg.norm(LIGHT)))
        lit = colours * shade[:, None]
        x0 = np.clip(np.floor(tri[..., 0].min(1) - 0.5), 0, px - 1).astype(np.int64)
        x1 = np.clip(np.ceil(tri[..., 0].max(1) - 0.5), 0, px - 1).astype(np.int64)
        y0 = np.clip(np.floor(tri[..., 1].min(1) - 0.5), 0, px - 1).astype(np.int64)
        y1 = np.clip(np.ceil(tri[..., 1].max(1) - 0.5), 0, px - 1).astype(np.int64)
        w = x1 - x0 + 1
        counts = w * (y1 - y0 + 1)
        t = np.repeat(np.arange(len(faces)), counts)  # one sample per pixel of each triangle's box
        k = np.arange(len(t)) - np.repeat(np.cumsum(counts) - counts, counts)
        sx = x0[t] + k % w[t]
        sy = y0[t] + k // w[t]
        a, b, c = tri[t, 0], tri[t, 1], tri[t, 2]
        p = np.stack([sx + 0.5, sy + 0.5], 1)

        def edge(u, v, q):
            return (v[:, 0] - u[:, 0]) * (q[:, 1] - u[:, 1]) - (v[:, 1] - u[:, 1]) * (q[:, 0] - u[:, 0])

        area = edge(a, b, c)
        l0, l1, l2 = edge(b, c, p), edge(c, a, p), edge(a, b, p)
        sgn = np.sign(area)
        inside = (area != 0) & (l0 * sgn >= 0) & (l1 * sgn >= 0) & (l2 * sgn >= 0)
        t, sx, sy = t[inside], sx[inside], sy[inside]
        safe = area[inside]
        depth = (l0[inside] * z[t, 0] + l1[inside] * z[t, 1] + l2[inside] * z[t, 2]) / safe
        pix = sy * px + sx
        order = np.lexsort((-depth, pix))  # per pixel, nearest first
        first = np.unique(pix[order], return_index=True)[1]
        win = order[first]
        img[pix[win]] = lit[t[win]]
    rgb = _srgb(img).reshape(size, SUPERSAMPLE, size, SUPERSAMPLE, 3).mean((1, 3))
    return np.round(rgb * 255).astype(np.uint8)


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
    path.write_bytes(encode_png(sketch(obj)))
    return path
