"""One object folder on the studio's stage, rendered at any joint configuration.

:class:`ObjectRenderer` loads the URDF's OBJ + MTL meshes (base colour, roughness, metallic and
normal maps; MTL tints, roughness gains and transparency SAPIEN's loader ignores are applied
here), poses the links from the URDF joints directly (no physics engine) and returns a
:class:`Frame`: the picture with a per-pixel link label and the ground's shading.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .posing import _forward_kinematics, _qpos_for, _read_object
from .studio import BACKGROUND, Camera, _ContactShade, _look_at_matrix, _stage, frame_points


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


def render_body(sapien, visuals, textures: dict):
    """A render body of one link's visual meshes (materials worn as :func:`_wear_material` does, ``textures``
    its cache) and its shapes, in ``visuals``' order."""
    body, shapes = sapien.render.RenderBodyComponent(), []
    for vis in visuals:
        shape = sapien.render.RenderShapeTriangleMesh(str(vis.mesh), list(vis.scale), None)
        _wear_material(sapien, shape, vis.mesh, textures)
        shape.local_pose = sapien.Pose(vis.origin)
        body.attach(shape)
        shapes.append(shape)
    return body, shapes


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
        self._triangles: dict[str, np.ndarray] = {}  # per link: its visual triangles, rows of _vertices[link]
        self._textures: dict[tuple, object] = {}  # worn textures made for this object (tint, alpha, gain)
        self._clear: list[int] = []  # render shapes one sees through (glass): their per-scene ids
        for name, visuals in self.files.links.items():
            if not visuals:
                continue
            body, shapes = render_body(sapien, visuals, self._textures)
            corners, verts_link, tris_link, count = [], [], [], 0
            for vis, shape in zip(visuals, shapes, strict=True):
                for part in shape.parts:
                    tris_link.append(np.asarray(part.get_triangles(), np.int64).reshape(-1, 3) + count)
                    count += len(part.get_vertices())
                verts = np.concatenate([p.get_vertices() for p in shape.parts]) * np.asarray(vis.scale)
                lo, hi = verts.min(0), verts.max(0)
                box = np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])
                corners.append(box @ vis.origin[:3, :3].T + vis.origin[:3, 3])
                verts_link.append(verts @ vis.origin[:3, :3].T + vis.origin[:3, 3])
            self._vertices[name] = np.concatenate(verts_link)
            self._triangles[name] = np.concatenate(tris_link)
            ent = sapien.Entity()
            ent.name = name
            ent.add_component(body)
            self.scene.add_entity(ent)
            self._clear += [shape.per_scene_id for shape in shapes  # ids are given on joining the scene
                            if any(part.material.base_color[3] < 1.0 for part in shape.parts)]
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
        offsets = np.cumsum([0] + [len(v) for v in self._vertices.values()])
        self._contact = _ContactShade(
            np.concatenate([v @ poses[n][:3, :3].T + poses[n][:3, 3] for n, v in self._vertices.items()]),
            self._ground_z, np.concatenate([self._triangles[n] + o for n, o in zip(self._vertices, offsets)]))
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
        segs = cam.get_picture("Segmentation")
        seg = segs[..., 1].astype(np.int64)
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
        color = self._ground_through_glass(cam, segs[..., 0], color)
        shade = np.where(ground, shade, 1.0).astype(np.float32)
        bg = np.asarray(BACKGROUND, np.float32) / 255.0
        rgb = np.where((labels >= 0)[..., None], color, bg * shade[..., None])
        rgb = np.clip(rgb * 255.0 + 0.5, 0, 255).astype(np.uint8)
        if supersample > 1:
            rgb = cv2.resize(rgb, (width, height), interpolation=cv2.INTER_AREA)
            labels = labels[supersample // 2::supersample, supersample // 2::supersample]
            shade = cv2.resize(shade, (width, height), interpolation=cv2.INTER_AREA)
        return Frame(rgb, labels.astype(np.int32), self.link_names, shade)

    def _ground_through_glass(self, cam, shape_ids: np.ndarray, color: np.ndarray) -> np.ndarray:
        """Glass lying on the ground (a lens, a dish) shows the ground through it as rendered, brighter than the
        shadow-caught ground round it (and without its contact shadow): such pixels wear the catcher's shading,
        or clear lenses read as milky white discs."""
        clear = np.isin(shape_ids, self._clear) if self._clear else np.zeros(shape_ids.shape, bool)
        if not clear.any():
            return color
        model = cam.get_model_matrix()
        world = cam.get_picture("Position")[..., :3][clear] @ model[:3, :3].T + model[:3, 3]
        low = world[:, 2] <= self._ground_z + 0.01
        ratio = float(np.asarray(BACKGROUND, np.float32).mean()) / 255.0 / max(self.stage.ground_lum, 1e-4)
        gain = np.ones(len(world), np.float32)
        gain[low] = ratio * self._contact(world[low, :2])
        color = color.copy()
        color[clear] *= gain[:, None]
        return color

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
