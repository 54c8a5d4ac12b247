"""Pictures of a scene folder: the room seen from above one corner, at rest or with every joint open.

Each object is put on the preview stage from its own URDF meshes (as :mod:`.renderer` does for one object),
posed by its joints (no physics) and placed by ``scene.json``; the floor and the two walls away from the
camera are drawn (a cut-away: the near walls would hide the room); what is hung on or set into the near
walls is left out (it would float), what stands on the floor against them stays.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

from .files import scene_refusals
from .posing import _forward_kinematics, _qpos_for, _read_object
from .renderer import render_body
from .studio import _look_at_matrix, _stage

CORNERS = {("south", "east"): (1, 1), ("south", "west"): (1, 0), ("north", "east"): (0, 1), ("north", "west"): (0, 0)}


def _corner(rec: dict) -> tuple[tuple[str, str], tuple[int, int]]:
    """The corner to look from: the one whose two walls (cut away in the picture) hold the fewest objects."""
    count = {w: sum(1 for o in rec["objects"] if o.get("wall") == w) for w in ("north", "east", "south", "west")}
    walls = min(CORNERS, key=lambda ws: (count[ws[0]] + count[ws[1]], list(CORNERS).index(ws)))
    return walls, CORNERS[walls]


def _pose(o: dict) -> np.ndarray:
    m = np.eye(4)
    c, s = math.cos(math.radians(o["yaw"])), math.sin(math.radians(o["yaw"]))
    m[:3, :3] = [[c, -s, 0], [s, c, 0], [0, 0, 1]]
    m[:3, 3] = o["position"]
    return m


class _SceneOnStage:
    def __init__(self, folder: Path, rec: dict, fraction: float, hidden: tuple[str, str]):
        stage = self.stage = _stage()
        self.sapien = stage.sapien
        if stage.owner is not None:
            stage.owner.close()
        self.entities, textures, files = [], {}, {}
        gone: set[str] = set()
        for o in rec["objects"]:  # hosts come before what stands on them
            if (o.get("wall") in hidden and o["on"] != "floor") or o["on"].split(":")[0] in gone:
                gone.add(o["id"])
                continue  # hung on or set into a cut-away wall, or on something that is: it would float
            if o["folder"] not in files:
                files[o["folder"]] = _read_object(folder / o["folder"])
            f = files[o["folder"]]
            poses = _forward_kinematics(f, _qpos_for(f, fraction))
            place = _pose(o)
            for name, visuals in f.links.items():
                if visuals:
                    self._add(visuals, place @ poses[name], textures)
        self._room(rec["room"], hidden, folder, {o["id"]: o for o in rec["objects"]})
        stage.owner = self

    def _add(self, visuals, pose, textures):
        sapien = self.sapien
        body, _ = render_body(sapien, visuals, textures)
        ent = sapien.Entity()
        ent.add_component(body)
        ent.set_pose(sapien.Pose(pose))
        self.stage.scene.add_entity(ent)
        self.entities.append(ent)

    def _worn(self, box: dict, folder: Path, placed: dict):
        """The look a fixture wears: its object's texture of the slot, tinted as that object's MTL asks
        (``Kd``); its flat colour where the texture is not there."""
        import cv2

        sapien, o = self.sapien, placed.get(box["wears"]["object"])
        slot = box["wears"]["slot"]
        look = sapien.render.RenderMaterial(base_color=[*box["color"], 1], roughness=0.5)
        texture = None if o is None else folder / o["folder"] / "textures" / f"{slot}_basecolor.png"
        if texture is None or not texture.is_file():
            return look
        kd = np.ones(3, np.float32)
        for mtl in sorted((folder / o["folder"] / "meshes").glob("*.mtl")):
            lines = [ln.strip() for ln in mtl.read_text(errors="replace").splitlines()]
            if f"newmtl {slot}" in lines:
                after = lines[lines.index(f"newmtl {slot}") + 1:]
                kd_line = next((ln for ln in after if ln.startswith(("Kd ", "newmtl "))), "")
                if kd_line.startswith("Kd "):
                    kd = np.array([float(x) for x in kd_line.split()[1:4]], np.float32)
                break
        img = cv2.imread(str(texture), cv2.IMREAD_COLOR)[..., ::-1].astype(np.float32) / 255.0
        lin = np.clip(np.where(img <= 0.04045, img / 12.92, ((img + 0.055) / 1.055) ** 2.4) * kd, 0.0, 1.0)
        srgb = np.where(lin <= 0.0031308, 12.92 * lin, 1.055 * lin ** (1 / 2.4) - 0.055)
        rgba = np.concatenate([srgb, np.ones(srgb.shape[:2] + (1,), np.float32)], -1)
        look.base_color = [1.0, 1.0, 1.0, 1.0]
        look.base_color_texture = sapien.render.RenderTexture2D(
            np.ascontiguousarray(np.rint(rgba * 255).astype(np.uint8)), "R8G8B8A8Unorm", mipmap_levels=8, srgb=True)
        return look

    def _room(self, room: dict, hidden: tuple[str, str], folder: Path, placed: dict):
        sapien = self.sapien
        wall = sapien.render.RenderMaterial(base_color=[0.86, 0.85, 0.82, 1], roughness=0.9)
        floor = sapien.render.RenderMaterial(base_color=[0.55, 0.45, 0.35, 1], roughness=0.7)
        for box in room["boxes"]:
            if box["name"].startswith((*(f"wall_{w}" for w in hidden), "ceiling")):
                continue  # the walls between the camera and the room
            lo, hi = np.array(box["min"]), np.array(box["max"])
            body = sapien.render.RenderBodyComponent()
            look = floor if box["name"] == "floor" else wall
            if "wears" in box:  # a fixture (a worktop) in the material of the object it joins
                look = self._worn(box, folder, placed)
            elif "color" in box:  # a fixture in its own colour
                look = sapien.render.RenderMaterial(base_color=[*box["color"], 1], roughness=0.5)
            shape = sapien.render.RenderShapeBox(((hi - lo) / 2).tolist(), look)
            body.attach(shape)
            ent = sapien.Entity()
            ent.add_component(body)
            ent.set_pose(sapien.Pose(((lo + hi) / 2).tolist()))
            self.stage.scene.add_entity(ent)
            self.entities.append(ent)

    def close(self):
        if self.stage.owner is self:
            for ent in self.entities:
                self.stage.scene.remove_entity(ent)
            self.stage.owner = None
        self.entities.clear()


def render_scene(folder, width: int = 1024, height: int = 768, fraction: float = 0.0, view: str = "corner"
                 ) -> np.ndarray:
    """An RGB picture (``height`` x ``width`` x 3, uint8) of the scene folder with each joint at
    ``fraction`` of its range (0 rest, 1 open); ``view`` ``corner`` (from above the corner whose two walls
    hold the fewest objects: those walls and what hangs on them are left out) or ``top``."""
    folder = Path(folder)
    rec = json.loads((folder / "scene.json").read_text())
    refused = scene_refusals(folder, rec)
    if refused:
        raise ValueError(f"{folder}: {refused[0]}")
    hidden, (cx, cy) = _corner(rec)
    on = _SceneOnStage(folder, rec, fraction, hidden)
    try:
        r = rec["room"]
        d, w, h = r["depth"], r["width"], r["height"]
        stage = on.stage
        # the studio's ground under the room's floor slab, not in its top face (they would z-fight)
        stage.configure(np.array([0.0, 0.0, -r["wall_thickness"] - 0.01]), np.array([d, w, h]))
        target = np.array([d * 0.45, w * 0.45, 0.5])
        if view == "top":
            eye = np.array([d / 2 + 0.01, w / 2, max(d, w) * 1.6])
            target = np.array([d / 2, w / 2, 0.0])
        else:
            ex = d * 1.25 + 1.0 if cx else -d * 0.25 - 1.0
            ey = w * 1.15 + 1.0 if cy else -w * 0.15 - 1.0
            eye = np.array([ex, ey, h * 1.5 + 0.6])
            target = np.array([d * (0.45 if cx else 0.55), w * (0.45 if cy else 0.55), 0.5])
        cam = stage.camera(width, height)
        cam.set_fovy(math.radians(50), True)
        cam.near, cam.far = 0.05, 100.0
        cam.entity.set_pose(on.sapien.Pose(_look_at_matrix(eye, target)))
        stage.scene.update_render()
        cam.take_picture()
        rgb = cam.get_picture("Color")[..., :3]
        return np.clip(rgb * 255 + 0.5, 0, 255).astype(np.uint8)
    finally:
        on.close()


def scene_previews(folder, out=None, width: int = 1024, height: int = 768) -> dict[str, Path]:
    """Write ``preview.png`` (at rest) and ``preview_open.png`` (every joint fully open) of the scene folder
    into ``out`` (default: the scene folder); returns ``{name: path}``."""
    import cv2

    folder = Path(folder)
    out = Path(out) if out is not None else folder
    out.mkdir(parents=True, exist_ok=True)
    written = {}
    for fraction, name in ((0.0, "preview.png"), (1.0, "preview_open.png")):
        path = out / name
        if not cv2.imwrite(str(path), render_scene(folder, width, height, fraction=fraction)[..., ::-1]):
            raise OSError(f"cannot write {path}")
        written[name] = path
    return written
