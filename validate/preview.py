"""Pictures of finished object folders: thumbnails, rest/open previews, joint sweeps, contact sheets.

Reads what a user would read — the URDF, its OBJ + MTL meshes and the PBR texture PNGs, and
``metadata.json`` — and renders it with SAPIEN's Vulkan rasteriser (``sapien.render``): the base
colour, roughness, metallic and normal maps of the MTL files (``map_Kd``, ``map_Pr``, ``map_Pm``,
``norm``) are all used, lit by one shadow-casting key light plus a soft studio environment map.

Headless on CPU this needs a software Vulkan driver: Mesa's lavapipe **>= 25** (Debian 12:
``mesa-vulkan-drivers`` from bookworm-backports; the stock Mesa 22 of bookworm does not work).
Nothing here starts a physics engine: the link poses are computed from the URDF joints directly.

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

import json
import math
import shutil
import subprocess
import sys
import tempfile
from dataclasses import dataclass, field, fields
from pathlib import Path

import numpy as np

from .files import UrdfJoint, forward_kinematics, parse_urdf

try:  # the package error type, so the CLI prints the message without a traceback
    from infmob_usd.errors import InfmobError as _BaseError
except Exception:  # pragma: no cover - module used standalone
    _BaseError = Exception

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

# ---------------------------------------------------------------------------------------------
# look of the pictures
BACKGROUND = (224, 224, 224)  # neutral light grey, RGB uint8
FOVY_DEG = 32.0  # vertical field of view
VIEW_AZIMUTH_DEG = 38.0  # camera direction from +X towards +Y
VIEW_ELEVATION_DEG = 32.0  # above the horizon: high enough to look into open drawers
FILL = 0.86  # share of the half-frame the object may use
OPEN_FRACTION = 0.7  # "opened" preview: each joint at 70 % of its range
CONTINUOUS_OPEN = math.pi / 2  # continuous joints: a quarter turn in the opened preview
SWEEP_SIZE = 256
SWEEP_MAX_FRAMES = 120
SWEEP_FRAMES_PER_JOINT = 10

INSTALL_HINT = (
    "infmob preview renders with SAPIEN (pip install 'sapien==3.0.3') on a Vulkan device. Headless on CPU "
    "that is Mesa's lavapipe >= 25; on Debian 12 (bookworm):\n"
    "  echo 'deb http://deb.debian.org/debian bookworm-backports main' > /etc/apt/sources.list.d/backports.list\n"
    "  apt-get update && apt-get install -y -t bookworm-backports mesa-vulkan-drivers libvulkan1\n"
    "(the stock bookworm Mesa 22 lavapipe is too old)."
)


class PreviewUnavailable(_BaseError, RuntimeError):
    """Rendering is impossible here: the message names what is missing and how to install it."""


# ---------------------------------------------------------------------------------------------
# small geometry helpers


# ---------------------------------------------------------------------------------------------
# reading an object folder


@dataclass
class _Visual:
    mesh: Path
    origin: np.ndarray  # 4x4 in the link frame
    scale: tuple


@dataclass(frozen=True)
class _Joint(UrdfJoint):
    """A URDF joint with the states the pictures show (limits always set: a revolute joint
    without any is +-pi)."""

    lower: float = 0.0
    upper: float = 0.0

    def rest(self) -> float:
        return float(np.clip(0.0, self.lower, self.upper)) if self.type != "continuous" else 0.0

    def at_fraction(self, f: float) -> float:
        """Joint value at fraction ``f`` of the way from rest to the far limit.

        For the usual joint with ``lower = 0`` this is ``lower + f * (upper - lower)``; a joint whose
        rest lies inside its range opens towards the farther limit; a continuous joint turns
        ``f / 0.7`` quarter turns (a quarter turn in the 70 % "opened" picture).
        """
        if self.type == "continuous":
            return f * CONTINUOUS_OPEN / OPEN_FRACTION
        q0 = self.rest()
        far = self.upper if abs(self.upper - q0) >= abs(self.lower - q0) else self.lower
        return q0 + f * (far - q0)

    def sweep(self, n: int) -> np.ndarray:
        if self.type == "continuous":
            return np.linspace(0.0, 2 * math.pi, n)
        return np.linspace(self.lower, self.upper, n)


@dataclass
class _ObjectFiles:
    folder: Path
    name: str
    metadata: dict
    links: dict[str, list[_Visual]]
    joints: list[_Joint]
    root: str

    @property
    def movable(self) -> list[_Joint]:
        return [j for j in self.joints if j.movable]



THUMB_SIZE = 256


def simready_thumbnail(folder: Path, name: str) -> Path:
    """Where SimReady looks for the thumbnail of ``folder/<name>.usda`` (as ``infmob_usd.layers.thumbnail``
    writes it; ``tests/test_preview.py`` checks the two agree)."""
    return Path(folder) / ".thumbs" / f"{THUMB_SIZE}x{THUMB_SIZE}" / f"{name}.usda.png"

def _read_object(folder: Path) -> _ObjectFiles:
    folder = Path(folder)
    meta_path = folder / "metadata.json"
    metadata = json.loads(meta_path.read_text()) if meta_path.is_file() else {}
    urdfs = sorted(folder.glob("*.urdf"))
    if not urdfs:
        raise FileNotFoundError(f"no .urdf file in {folder} (is it an object folder written by infmob?)")
    urdf = folder / f"{metadata.get('name', folder.name)}.urdf"
    urdf = urdf if urdf.is_file() else urdfs[0]
    model = parse_urdf(urdf)
    links: dict[str, list[_Visual]] = {}
    for name, link in model.links.items():
        visuals = []
        for vis in link.visuals:
            fname = vis.filename
            if fname.startswith("package://"):
                fname = fname[len("package://"):]
            path = (urdf.parent / fname).resolve()
            if not path.is_file():
                raise FileNotFoundError(f"visual mesh {fname!r} of link {name!r} is missing ({path})")
            visuals.append(_Visual(path, vis.origin, tuple(vis.scale)))
        links[name] = visuals
    joints = []
    for j in model.joints.values():
        lower = 0.0 if j.lower is None else j.lower
        upper = 0.0 if j.upper is None else j.upper
        if j.type == "revolute" and lower == upper == 0.0:
            lower, upper = -math.pi, math.pi
        values = {f.name: getattr(j, f.name) for f in fields(UrdfJoint)}
        joints.append(_Joint(**values | {"lower": min(lower, upper), "upper": max(lower, upper)}))
    children = {j.child for j in joints}
    roots = [n for n in links if n not in children]
    if not roots:
        raise ValueError(f"{urdf}: no root link (the joints form a cycle)")
    # order joints parent-before-child so forward kinematics is one pass
    ordered, known, pending = [], {roots[0]}, list(joints)
    while pending:
        ready = [j for j in pending if j.parent in known]
        if not ready:
            raise ValueError(f"{urdf}: joints {[j.name for j in pending]} do not hang from the root link")
        for j in ready:
            ordered.append(j)
            known.add(j.child)
            pending.remove(j)
    name = metadata.get("name") or urdf.stem
    return _ObjectFiles(folder, name, metadata, links, ordered, roots[0])


def _forward_kinematics(obj: _ObjectFiles, qpos: dict[str, float]) -> dict[str, np.ndarray]:
    poses = forward_kinematics(obj.root, obj.joints, qpos, lambda j: j.rest() if j.movable else 0.0)
    for name in obj.links:
        poses.setdefault(name, np.eye(4))  # a link no joint reaches stays at the origin
    return poses


def _gates(obj: _ObjectFiles) -> dict[str, list[str]]:
    """{joint name: the movable joints of the part it ``requires_open``} from ``metadata.json`` (a rack behind
    a door: the door's joints), as ``validate/sim.py`` reads them."""
    meta = [j for j in obj.metadata.get("joints", []) if j.get("type") not in (None, "fixed")]
    groups: dict[str, list[str]] = {}
    for j in meta:
        groups.setdefault(j.get("group"), []).append(j["name"])
    movable = {j.name for j in obj.movable}
    return {j["name"]: [n for n in groups.get(j["requires_open"], []) if n in movable]
            for j in meta if j.get("requires_open") and j["name"] in movable}


def _open_gates(obj: _ObjectFiles, qpos: dict[str, float]) -> dict[str, float]:
    """``qpos`` with every door whose dependent joint is off rest held fully open: a picture never drives a
    rack through a half-open door (the order a robot, and ``validate --sim``, opens them in)."""
    out = dict(qpos)
    by_name = {j.name: j for j in obj.movable}
    for name, gates in _gates(obj).items():
        j = by_name[name]
        if abs(out.get(name, j.rest()) - j.rest()) > 1e-9:
            for gate in gates:
                out[gate] = by_name[gate].at_fraction(1.0)
    return out


def _qpos_for(obj: _ObjectFiles, joint_fraction) -> dict[str, float]:
    """``joint_fraction``: one number for every movable joint, or ``{joint name: fraction}``. A joint that
    ``requires_open`` a part moves only with that part fully open (:func:`_open_gates`)."""
    if isinstance(joint_fraction, dict):
        unknown = set(joint_fraction) - {j.name for j in obj.movable}
        if unknown:
            raise KeyError(f"no movable joint named {sorted(unknown)} in {obj.name}")
        return _open_gates(obj, {j.name: j.at_fraction(float(joint_fraction.get(j.name, 0.0))) for j in obj.movable})
    return _open_gates(obj, {j.name: j.at_fraction(float(joint_fraction)) for j in obj.movable})


# ---------------------------------------------------------------------------------------------
# the renderer backend


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


def _softbox(az, el, a0, e0, wa, we):
    """1 inside a rectangle of the sky (azimuth a0 +- wa, elevation e0 +- we, degrees), soft edges."""
    da = (az - a0 + 180.0) % 360.0 - 180.0
    r = np.maximum(np.abs(da) / wa, np.abs(el - e0) / we)
    return np.clip((1.0 - r) / 0.35, 0, 1) * (el > 0)


def _environment_map(d: Path) -> list[str]:
    """Six cube faces of a soft studio: bright sky fading to a grey horizon, a darker floor."""
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
        norm = np.sqrt(x * x + y * y + z * z)
        up = y / norm  # sine of elevation in the world (cube y = world z)
        az = np.degrees(np.arctan2(z, x))  # world azimuth: cube z = world y
        el = np.degrees(np.arcsin(np.clip(up, -1, 1)))
        sky = 0.58 + 0.27 * np.clip(up, 0, 1) ** 0.6
        floor = 0.40 + 0.08 * np.clip(up + 1, 0, 1)
        v = np.where(up >= 0, sky, floor)
        v = v - 0.22 * np.exp(-((el - 2.0) / 4.0) ** 2)  # a darker band at the horizon: chrome reads as chrome

        v = np.maximum(v, _softbox(az, el, -25.0, 50.0, 28.0, 20.0))  # key softbox, where the key light is
        v = np.maximum(v, 0.9 * _softbox(az, el, 130.0, 28.0, 18.0, 14.0))  # rim softbox behind the right
        img = np.clip(np.stack([v * 0.98, v, v * 1.03], -1) * 255, 0, 255).astype(np.uint8)
        path = d / f"{key}.png"
        cv2.imwrite(str(path), img[..., ::-1])
        paths.append(str(path))
    return paths


# ---------------------------------------------------------------------------------------------
# rendering


@dataclass
class Frame:
    """One rendered picture and what each pixel shows."""

    rgb: np.ndarray  # (H, W, 3) uint8
    labels: np.ndarray  # (H, W) int32: link index into ``link_names``; -1 background / ground
    link_names: list[str]
    shadow: np.ndarray = field(repr=False, default=None)  # (H, W) float, 1 = lit ground

    @property
    def object_mask(self) -> np.ndarray:
        return self.labels >= 0

    def link_mask(self, name: str) -> np.ndarray:
        return self.labels == self.link_names.index(name)


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
    if "stage" not in _STATE:
        _STATE["stage"] = _Stage()
    return _STATE["stage"]


class _ContactShade:
    """Soft darkening of the ground around an object's footprint (a cheap ambient occlusion).

    The footprint is the convex hull, seen from above, of the visual mesh vertices that lie near
    the ground at rest; the darkening fades with the distance from it.
    """

    STRENGTH = 0.42

    def __init__(self, rest_points: np.ndarray, ground_z: float):
        import cv2

        height = float(rest_points[:, 2].max() - ground_z)
        low = rest_points[rest_points[:, 2] <= ground_z + 0.02 + 0.03 * height][:, :2]
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
        hull = cv2.convexHull(((low - self.origin) / self.cell).astype(np.float32)).round().astype(np.int32)
        inside = np.zeros((n, n), np.uint8)
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


def _mtl_entry(obj_path: Path) -> dict | None:
    """The MTL material an OBJ of ours uses: ``Kd``, ``d`` and the map lines with their options."""
    text = obj_path.read_text(errors="replace")
    lib = next((ln.split(None, 1)[1].strip() for ln in text.splitlines()[:8] if ln.startswith("mtllib ")), None)
    at = text.find("\nusemtl ")
    if lib is None or at < 0:
        return None
    name = text[at + 8:text.find("\n", at + 8)].strip()
    mtl = obj_path.parent / lib
    if not mtl.is_file():
        return None
    entry, current = {}, None
    for line in mtl.read_text(errors="replace").splitlines():
        key, _, rest = line.strip().partition(" ")
        if key == "newmtl":
            current = rest.strip()
        elif current == name and key:
            entry[key] = rest.strip()
    entry["_dir"] = mtl.parent
    return entry


def _map_file(entry: dict, key: str) -> tuple[Path | None, float]:
    """The file of map line ``key`` and its ``-mm`` gain (1 when absent)."""
    words = entry.get(key, "").split()
    if not words:
        return None, 1.0
    gain = float(words[words.index("-mm") + 2]) if "-mm" in words else 1.0
    return entry["_dir"] / words[-1], gain


def _wear_material(sapien, shape, obj_path: Path, made: dict) -> None:
    """Show a mesh's material as the MTL asks where SAPIEN's loader does not: ``Kd`` multiplies
    ``map_Kd`` (the object's tint of its look), ``map_Pr -mm 0 gain`` scales the roughness map,
    and ``d < 1`` makes the surface see-through (the map's alpha; SAPIEN's rasteriser blends it
    in its transparency pass, its ray tracer would use ``transmission``)."""
    import cv2

    entry = _mtl_entry(Path(obj_path))
    if entry is None:
        return
    kd = np.array([float(x) for x in entry.get("Kd", "1 1 1").split()[:3]], np.float32)
    d = float(entry.get("d", "1"))
    colour, _ = _map_file(entry, "map_Kd")
    rough, gain = _map_file(entry, "map_Pr")
    for part in shape.parts:
        mat = part.material
        if colour is not None and colour.is_file() and (d < 1.0 or np.abs(kd - 1.0).max() > 1e-3):
            key = ("colour", str(colour), tuple(kd.round(4)), round(d, 3))
            if key not in made:
                img = cv2.imread(str(colour), cv2.IMREAD_COLOR)[..., ::-1].astype(np.float32) / 255.0
                lin = np.where(img <= 0.04045, img / 12.92, ((img + 0.055) / 1.055) ** 2.4) * kd
                lin = np.clip(lin, 0.0, 1.0)
                srgb = np.where(lin <= 0.0031308, 12.92 * lin, 1.055 * lin ** (1 / 2.4) - 0.055)
                rgba = np.concatenate([srgb, np.full(srgb.shape[:2] + (1,), d, np.float32)], -1)
                made[key] = sapien.render.RenderTexture2D(
                    np.ascontiguousarray(np.rint(rgba * 255).astype(np.uint8)), "R8G8B8A8Unorm",
                    mipmap_levels=8, srgb=True)
            mat.base_color_texture = made[key]
        if d < 1.0:
            mat.base_color = [*mat.base_color[:3], d]
            mat.transmission = 1.0 - d
            mat.ior = float(entry.get("Ni", "1.5"))
        if rough is not None and rough.is_file() and abs(gain - 1.0) > 1e-3:
            key = ("rough", str(rough), round(gain, 4))
            if key not in made:
                img = cv2.imread(str(rough), cv2.IMREAD_GRAYSCALE).astype(np.float32) * gain
                grey = np.clip(np.rint(img), 0, 255).astype(np.uint8)
                made[key] = sapien.render.RenderTexture2D(
                    np.ascontiguousarray(np.repeat(grey[..., None], 4, -1)), "R8G8B8A8Unorm", mipmap_levels=8)
            mat.roughness_texture = made[key]


class ObjectRenderer:
    """One object folder placed on the (shared) stage; pictures at any joint configuration.

    Only one ObjectRenderer is on stage at a time: opening another one takes this one off.
    Use it as a context manager, or call :meth:`close` when done.
    """

    def __init__(self, folder: str | Path):
        self.files = _read_object(Path(folder))
        stage = self.stage = _stage()
        sapien = self._sapien = stage.sapien
        if stage.owner is not None:
            stage.owner.close()
        self.scene = stage.scene
        self.link_names = list(self.files.links)
        self._entities: dict[str, object] = {}
        self._corners: dict[str, np.ndarray] = {}  # per link: AABB corners of its visuals, link frame
        self._vertices: dict[str, np.ndarray] = {}  # per link: every visual vertex, link frame
        self._textures: dict[tuple, object] = {}  # worn textures made for this object (tint, alpha, gain)
        for name, visuals in self.files.links.items():
            if not visuals:
                continue
            body = sapien.render.RenderBodyComponent()
            corners, verts_link = [], []
            for vis in visuals:
                shape = sapien.render.RenderShapeTriangleMesh(str(vis.mesh), list(vis.scale), None)
                _wear_material(sapien, shape, vis.mesh, self._textures)
                shape.local_pose = sapien.Pose(vis.origin)
                body.attach(shape)
                verts = np.concatenate([p.get_vertices() for p in shape.parts]) * np.asarray(vis.scale)
                lo, hi = verts.min(0), verts.max(0)
                box = np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])
                corners.append(box @ vis.origin[:3, :3].T + vis.origin[:3, 3])
                verts_link.append(verts @ vis.origin[:3, :3].T + vis.origin[:3, 3])
            self._vertices[name] = np.concatenate(verts_link)
            ent = sapien.Entity()
            ent.name = name
            ent.add_component(body)
            self.scene.add_entity(ent)
            self._entities[name] = ent
            self._corners[name] = np.concatenate(corners)
        if not self._entities:
            raise ValueError(f"{self.files.folder}: the URDF has no visual meshes to render")
        stage.owner = self
        self._entity_link = {e.per_scene_id: self.link_names.index(n) for n, e in self._entities.items()}
        rest_q = _qpos_for(self.files, 0.0)
        rest = self.points(rest_q)
        self._ground_z = float(rest[:, 2].min())
        stage.configure(rest.min(0), rest.max(0))
        poses = _forward_kinematics(self.files, rest_q)
        self._contact = _ContactShade(
            np.concatenate([v @ poses[n][:3, :3].T + poses[n][:3, 3] for n, v in self._vertices.items()]),
            self._ground_z)
        self.qpos: dict[str, float] = {}
        self.set_fraction(0.0)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    # -- posing ----------------------------------------------------------------------------------
    @property
    def movable_joints(self) -> list[str]:
        return [j.name for j in self.files.movable]

    def set_qpos(self, qpos: dict[str, float]):
        self.qpos = dict(qpos)
        poses = _forward_kinematics(self.files, self.qpos)
        for name, ent in self._entities.items():
            ent.set_pose(self._sapien.Pose(poses[name]))
        self._poses = poses

    def set_fraction(self, joint_fraction=0.0):
        self.set_qpos(_qpos_for(self.files, joint_fraction))

    def points(self, qpos: dict[str, float] | None = None) -> np.ndarray:
        """World corners of every link's visual bounding box at ``qpos`` (default: the current pose)."""
        poses = self._poses if qpos is None else _forward_kinematics(self.files, qpos)
        return np.concatenate([c @ poses[n][:3, :3].T + poses[n][:3, 3] for n, c in self._corners.items()])

    def camera_for(self, *qposes: dict[str, float], aspect: float = 1.0) -> Camera:
        """A camera framed on the object at every one of ``qposes`` (default: the current pose)."""
        pts = np.concatenate([self.points(q) for q in qposes]) if qposes else self.points()
        pts = np.concatenate([pts, pts * [1, 1, 0] + [0, 0, self._ground_z]])  # keep the footprint in view
        return frame_points(pts, aspect)

    # -- pictures ----------------------------------------------------------------------------------
    def render(self, size: int = 512, camera: Camera | None = None, supersample: int = 1,
               height: int | None = None) -> Frame:
        """Render the current pose, ``size`` wide and ``height`` (default ``size``) high.

        ``camera`` defaults to one framed on the current pose; ``supersample`` renders that many
        times larger and shrinks (anti-aliasing).
        """
        import cv2

        width, height = size, height or size
        camera = camera or self.camera_for(aspect=width / height)
        if self.stage.owner is not self:
            raise RuntimeError("this ObjectRenderer was closed (another object took the stage)")
        cam = self.stage.camera(width * supersample, height * supersample)
        cam.set_fovy(camera.fovy, True)
        cam.near, cam.far = camera.near, camera.far
        cam.entity.set_pose(self._sapien.Pose(_look_at_matrix(camera.eye, camera.target)))
        self.scene.update_render()
        cam.take_picture()
        color = cam.get_picture("Color")[..., :3]
        seg = cam.get_picture("Segmentation")[..., 1].astype(np.int64)
        lut = np.full(int(seg.max()) + 1, -1, np.int32)
        for sid, idx in self._entity_link.items():
            if sid < lut.size:
                lut[sid] = idx
        labels = lut[seg]
        ground = seg == self.stage.ground.per_scene_id
        # shadow catcher: the ground is replaced by the background colour times its shading
        # (key-light shadow from the renderer, times a contact darkening around the footprint)
        lum = color @ np.array([0.299, 0.587, 0.114], np.float32)
        shade = np.clip(lum / max(self.stage.ground_lum, 1e-4), 0.0, 1.0)
        if ground.any():
            pos = cam.get_picture("Position")[..., :3][ground]  # camera space (OpenGL axes)
            model = cam.get_model_matrix()
            world = pos @ model[:3, :3].T + model[:3, 3]
            shade[ground] *= self._contact(world[:, :2])
        shade = np.where(ground, shade, 1.0).astype(np.float32)
        bg = np.asarray(BACKGROUND, np.float32) / 255.0
        rgb = np.where((labels >= 0)[..., None], color, bg * shade[..., None])
        rgb = np.clip(rgb * 255.0 + 0.5, 0, 255).astype(np.uint8)
        if supersample > 1:
            rgb = cv2.resize(rgb, (width, height), interpolation=cv2.INTER_AREA)
            labels = labels[supersample // 2::supersample, supersample // 2::supersample]
            shade = cv2.resize(shade, (width, height), interpolation=cv2.INTER_AREA)
        return Frame(rgb, labels.astype(np.int32), self.link_names, shade)

    def close(self):
        """Take the object off the stage and drop its meshes and textures from the cache."""
        if self.stage.owner is self:
            for ent in self._entities.values():
                self.scene.remove_entity(ent)
            self.stage.owner = None
            _release()
        self._entities.clear()
        self._textures.clear()


def _release():
    try:
        import sapien.render

        sapien.render.clear_cache(models=True, images=True, shaders=False)
    except Exception:
        pass


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
    parser.add_argument("paths", nargs="*", metavar="PATH", help="an object folder or a folder of them")
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
    from .files import find_objects

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
        found = find_objects(args.paths)
        if not found:
            print(f"infmob: error: no object folders (with metadata.json) in {' '.join(args.paths)}", file=sys.stderr)
            return 2
        if args.out and Path(args.out).exists() and not Path(args.out).is_dir():
            print(f"infmob: error: --out {args.out!r} is a file; give a folder for the previews", file=sys.stderr)
            return 2
        for folder in found:
            out = Path(args.out) / folder.name if args.out else None
            written = preview(folder, out, size=args.size or 512)
            print("  ".join(str(p) for p in written.values()))
        return 0
    except PreviewUnavailable as exc:
        print(f"infmob: error: {exc}", file=sys.stderr)
        return 2
    except OSError as exc:
        print(f"infmob: error: {exc}; choose another --out", file=sys.stderr)
        return 2
