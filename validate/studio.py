"""The studio the pictures are taken in: one SAPIEN scene per process with a ground, a
shadow-casting key light and a soft environment map, cameras framed on an object from one
viewing direction, and a contact shadow around its footprint.
"""

from __future__ import annotations

import math
import shutil
import tempfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from . import render_backend
from .render_backend import _sapien

BACKGROUND = (224, 224, 224)  # neutral light grey, RGB uint8
FOVY_DEG = 32.0  # vertical field of view
VIEW_AZIMUTH_DEG = 38.0  # camera direction from +X towards +Y
VIEW_ELEVATION_DEG = 32.0  # above the horizon: high enough to look into open drawers
FILL = 0.86  # share of the half-frame the object may use


@dataclass
class Camera:
    eye: np.ndarray
    target: np.ndarray
    fovy: float  # radians
    near: float
    far: float


def _look_at_matrix(eye, target, up=(0, 0, 1)) -> np.ndarray:
    """SAPIEN camera pose: x forward, y left, z up."""
    eye = np.asarray(eye, float)
    f = np.asarray(target, float) - eye
    f /= np.linalg.norm(f)
    left = np.cross(up, f)
    left /= np.linalg.norm(left)
    m = np.eye(4)
    m[:3, 0], m[:3, 1], m[:3, 2], m[:3, 3] = f, left, np.cross(f, left), eye
    return m


def frame_points(points: np.ndarray, aspect: float = 1.0, fovy: float = math.radians(FOVY_DEG), fill: float = FILL,
                 azimuth: float = math.radians(VIEW_AZIMUTH_DEG),
                 elevation: float = math.radians(VIEW_ELEVATION_DEG)) -> Camera:
    """A camera looking from ``azimuth``/``elevation`` that fits every point in a frame of this aspect
    (width / height), centred, using ``fill`` of the half-frame."""
    pts = np.asarray(points, float).reshape(-1, 3)
    back = np.array([math.cos(elevation) * math.cos(azimuth), math.cos(elevation) * math.sin(azimuth),
                     math.sin(elevation)])
    fwd = -back
    right = np.cross(fwd, [0, 0, 1.0])
    right /= np.linalg.norm(right)
    up = np.cross(right, fwd)
    t = math.tan(fovy / 2) * fill
    tx = t * aspect
    target = (pts.min(0) + pts.max(0)) / 2
    for _ in range(4):
        rel = pts - target
        x, y, z = rel @ right, rel @ up, rel @ fwd
        dist = max(float(np.max(np.abs(x) / tx - z)), float(np.max(np.abs(y) / t - z)), 1e-3)
        depth = dist + z
        u, v = x / depth, y / depth  # tangent-plane coordinates
        du, dv = (u.max() + u.min()) / 2, (v.max() + v.min()) / 2
        if abs(du) < 1e-4 * tx and abs(dv) < 1e-4 * t:
            break
        target = target + (right * du + up * dv) * dist
    rel = pts - target
    dist = max(float(np.max(np.abs(rel @ right) / tx - rel @ fwd)), float(np.max(np.abs(rel @ up) / t - rel @ fwd)))
    radius = float(np.max(np.linalg.norm(rel, axis=1)))
    return Camera(target + back * dist, target, fovy, max(0.01, (dist - radius) * 0.5), dist + radius + 100.0)


def _softbox(az, el, a0, e0, wa, we):
    """1 inside a rectangle of the sky (azimuth a0 +- wa, elevation e0 +- we, degrees), soft edges."""
    da = (az - a0 + 180.0) % 360.0 - 180.0
    r = np.maximum(np.abs(da) / wa, np.abs(el - e0) / we)
    return np.clip((1.0 - r) / 0.35, 0, 1) * (el > 0)


_CARDS = ((-55.0, 14.0), (5.0, 8.0), (100.0, 12.0))
"""Black cards round the object: (azimuth, half-width) in degrees.  A vertical wall seen from the camera
(azimuth 38) mirrors azimuth 2 * normal - 38, so these land left of centre, near the centre and right
on a pot's wall, and the first one on the lower part of a screen facing +X."""
CARD_DEPTH = 0.45  # how far a card darkens the studio at its middle (0.75 drew black stripes on chrome)
BLUR_DEG = 7.0  # the studio as a polished metal mirrors it: every texel the mean over a cone this wide
BLUR_SAMPLES = 48


def _card(az, el, a0, wa):
    """1 in the middle of a dark card standing round the object (azimuth a0 +- wa degrees, from under the
    sweep's edge to 30 degrees up), falling smoothly to 0 at its edges."""
    da = (az - a0 + 180.0) % 360.0 - 180.0
    r = np.clip(1.0 - np.maximum(np.abs(da) / wa, np.abs(el + 20.0) / 50.0), 0, 1)
    return r * r * (3 - 2 * r)


def _studio(d: np.ndarray) -> np.ndarray:
    """The studio's radiance (grey, 0-1) seen along unit world directions ``d`` (..., 3), Z up.

    A product studio: a white sweep under the object, softboxes above, and dark cards standing round it, as
    photographers light metal: a polished or brushed surface then mirrors bright sweep beside dark card (a
    steel pot shows vertical light and dark bands, a screen a faint gradient) instead of one even grey that
    makes steel read as grey plastic.
    """
    up = np.clip(d[..., 2], -1, 1)
    az = np.degrees(np.arctan2(d[..., 1], d[..., 0]))
    el = np.degrees(np.arcsin(up))
    sky = 0.58 + 0.27 * np.clip(up, 0, 1) ** 0.6
    floor = 0.78 + 0.06 * np.clip(up + 1, 0, 1)
    v = np.where(up >= 0, sky, floor)
    v = v - 0.2 * np.exp(-((el - 2.0) / 9.0) ** 2)  # a darker band at the horizon: chrome reads as chrome
    for a0, wa in _CARDS:
        v = np.minimum(v, 1.0 - CARD_DEPTH * _card(az, el, a0, wa))
    v = np.maximum(v, _softbox(az, el, -25.0, 50.0, 28.0, 20.0))  # key softbox, where the key light is
    return np.maximum(v, 0.9 * _softbox(az, el, 130.0, 28.0, 18.0, 14.0))  # rim softbox behind the right


def _cone(n: int, half_angle: float) -> np.ndarray:
    """``n`` unit directions spread evenly over a cone of ``half_angle`` (radians) round +Z (a Fibonacci
    spiral: the same every run)."""
    k = np.arange(n) + 0.5
    cos_t = 1.0 - (k / n) * (1.0 - math.cos(half_angle))
    phi = k * math.pi * (3.0 - math.sqrt(5.0))
    sin_t = np.sqrt(1.0 - cos_t ** 2)
    return np.stack([sin_t * np.cos(phi), sin_t * np.sin(phi), cos_t], -1)


def _blurred(d: np.ndarray) -> np.ndarray:
    """:func:`_studio` averaged over a :data:`BLUR_DEG` cone round each direction of ``d`` (n, 3): the map a
    thin chrome tube mirrors, whose normal sweeps the whole studio across a few pixels, without aliasing."""
    cone = _cone(BLUR_SAMPLES, math.radians(BLUR_DEG))
    helper = np.where(np.abs(d[:, 2:3]) < 0.9, [[0.0, 0.0, 1.0]], [[1.0, 0.0, 0.0]])
    t1 = np.cross(helper, d)
    t1 /= np.linalg.norm(t1, axis=1, keepdims=True)
    t2 = np.cross(d, t1)
    dirs = cone[None, :, 0:1] * t1[:, None] + cone[None, :, 1:2] * t2[:, None] + cone[None, :, 2:3] * d[:, None]
    return _studio(dirs).mean(1)


def _environment_map(d: Path) -> list[str]:
    """Six cube faces of a soft studio (:func:`_studio`, prefiltered by :func:`_blurred`): bright sky fading
    to a grey horizon, a darker floor."""
    import cv2

    n = 64
    u = (np.arange(n) + 0.5) / n * 2 - 1
    s, t = np.meshgrid(u, u)  # t grows downwards in the image
    one = np.ones_like(s)
    # cube-map face directions (OpenGL convention) in the renderer's y-up cube space;
    # SAPIEN looks the cube up with world (x, z, y), so cube +y is world up.
    faces = {
        "px": (one, -t, -s), "nx": (-one, -t, s),
        "py": (s, one, t), "ny": (s, -one, -t),
        "pz": (s, -t, one), "nz": (-s, -t, -one),
    }
    paths = []
    for key in ("px", "nx", "py", "ny", "pz", "nz"):
        x, y, z = faces[key]
        world = np.stack([x, z, y], -1).reshape(-1, 3)  # cube z = world y, cube y = world z
        world /= np.linalg.norm(world, axis=1, keepdims=True)
        v = _blurred(world).reshape(n, n)
        img = np.clip(np.stack([v * 0.98, v, v * 1.03], -1) * 255, 0, 255).astype(np.uint8)
        path = d / f"{key}.png"
        cv2.imwrite(str(path), img[..., ::-1])
        paths.append(str(path))
    return paths


class _Stage:
    """The one SAPIEN scene of this process: ground, key light, studio environment, cameras.

    Objects come and go (one at a time); building the stage once saves the scene, shadow-map,
    environment and render-target set-up on every thumbnail.
    """

    def __init__(self):
        sapien = self.sapien = _sapien()
        self.scene = scene = sapien.Scene()
        self.owner = None
        scene.set_ambient_light([0.0, 0.0, 0.0])
        env_dir = Path(tempfile.mkdtemp(prefix="infmob_preview_env_"))
        ground_mat = sapien.render.RenderMaterial(base_color=[0.8, 0.8, 0.8, 1], specular=0.0, roughness=1.0,
                                                  metallic=0.0)
        body = sapien.render.RenderBodyComponent()
        plane = sapien.render.RenderShapePlane([1.0, 1000.0, 1000.0], ground_mat)
        plane.local_pose = sapien.Pose(q=[0.7071068, 0, -0.7071068, 0])  # plane normal +X -> +Z
        body.attach(plane)
        self.ground = sapien.Entity()
        self.ground.name = "ground"
        self.ground.add_component(body)
        scene.add_entity(self.ground)
        # key light from the front-left above (as seen from the camera): shadows fall back-right
        az, el = math.radians(-25.0), math.radians(58.0)
        self.light_dir = -np.array([math.cos(el) * math.cos(az), math.cos(el) * math.sin(az), math.sin(el)])
        self.light = scene.add_directional_light(self.light_dir.tolist(), [2.2, 2.15, 2.05], shadow=True,
                                                 shadow_map_size=2048)
        self.cameras: dict[tuple, object] = {}
        try:
            scene.set_environment_map_from_files(*_environment_map(env_dir))
            self.ground_lum = self._measure_ground()  # the first render also uploads the cube map
        finally:
            shutil.rmtree(env_dir, ignore_errors=True)

    def _measure_ground(self) -> float:
        """Luminance of lit, unshadowed ground (the same for every object: the lights never change)."""
        cam = self.camera(16, 16)
        cam.near, cam.far = 0.1, 10.0
        cam.entity.set_pose(self.sapien.Pose(_look_at_matrix([0.01, 0.0, 3.0], [0.0, 0.0, 0.0])))
        self.scene.update_render()
        cam.take_picture()
        color = cam.get_picture("Color")[..., :3]
        return float(np.median(color @ np.array([0.299, 0.587, 0.114], np.float32)))

    def configure(self, lo: np.ndarray, hi: np.ndarray):
        """Put the ground under an object with these bounds and fit the shadow map around it."""
        sapien = self.sapien
        size = float(np.max(hi - lo))
        centre = (lo + hi) / 2
        self.ground.set_pose(sapien.Pose([float(centre[0]), float(centre[1]), float(lo[2])]))
        light = self.light
        light.shadow_half_size = max(0.5, 1.3 * size)
        light.shadow_near = -4.0 * max(size, 1.0)
        light.shadow_far = 4.0 * max(size, 1.0)
        light.pose = sapien.Pose(centre.tolist(), sapien.math.shortest_rotation([1, 0, 0], self.light_dir.tolist()))

    def camera(self, width: int, height: int):
        key = (width, height)
        if key not in self.cameras:
            self.cameras[key] = self.scene.add_camera(f"cam{width}x{height}", width, height, math.radians(FOVY_DEG),
                                                      0.01, 100.0)
        return self.cameras[key]


def _stage() -> _Stage:
    if "stage" not in render_backend._STATE:
        render_backend._STATE["stage"] = _Stage()
    return render_backend._STATE["stage"]


class _ContactShade:
    """Soft darkening of the ground around an object's footprint (a cheap ambient occlusion).

    The footprint is what the visual mesh's triangles lying near the ground at rest cover, seen from above
    (a mouse's cable stays a thin line to its plug, not the hull of mouse and plug); an object with no such
    triangles (an open-bottomed mesh) falls back to the convex hull of its low vertices. The darkening fades
    with the distance from the footprint.
    """

    STRENGTH = 0.42

    def __init__(self, rest_points: np.ndarray, ground_z: float, triangles: np.ndarray | None = None):
        import cv2

        height = float(rest_points[:, 2].max() - ground_z)
        near = rest_points[:, 2] <= ground_z + 0.02 + 0.03 * height
        low = rest_points[near][:, :2]
        self.ok = len(low) >= 3
        if not self.ok:
            return
        lo, hi = low.min(0), low.max(0)
        extent = float(np.max(hi - lo))
        self.radius = 0.05 * float(np.min(hi - lo)) + 0.01 * extent + 0.01
        pad = 6 * self.radius
        self.origin = lo - pad
        n = 256
        self.cell = float(np.max(hi - lo) + 2 * pad) / n
        inside = np.zeros((n, n), np.uint8)
        flat = triangles[near[triangles].all(1)] if triangles is not None and len(triangles) else np.zeros((0, 3), int)
        if len(flat):
            px = ((rest_points[:, :2] - self.origin) / self.cell).round().astype(np.int32)
            for tri in px[flat]:
                cv2.fillConvexPoly(inside, tri, 1)
        else:
            hull = cv2.convexHull(((low - self.origin) / self.cell).astype(np.float32)).round().astype(np.int32)
            cv2.fillPoly(inside, [hull.reshape(-1, 2)], 1)
        self.dist = cv2.distanceTransform(1 - inside, cv2.DIST_L2, 5) * self.cell  # metres outside the footprint
        self.n = n

    def __call__(self, xy: np.ndarray) -> np.ndarray:
        if not self.ok:
            return np.ones(len(xy), np.float32)
        ij = np.floor((xy - self.origin) / self.cell).astype(np.int64)
        inside = (ij >= 0).all(1) & (ij < self.n).all(1)
        d = np.full(len(xy), np.inf, np.float32)
        d[inside] = self.dist[ij[inside, 1], ij[inside, 0]]
        return (1.0 - self.STRENGTH * np.exp(-d / self.radius)).astype(np.float32)
