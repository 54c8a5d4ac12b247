"""The dispenser: a pump, pressed to the bottom of its stroke and let go, is back at rest on its return spring
with the dispenser standing free on the ground in SAPIEN (the springs set from ``metadata.json`` as a user's
loader sets them: a friction-held pump head would stay down or drift)."""

from __future__ import annotations

import json

import numpy as np
import pytest

import infmob_usd

pytestmark = pytest.mark.sim


def _free_standing(folder):
    """The object's URDF in a SAPIEN scene on the ground, its root free, its return springs set."""
    from sapien.wrapper.urdf_loader import URDFLoader

    from infmob_usd.validate.sim import _import_sapien, apply_springs

    sapien = _import_sapien()
    scene = sapien.Scene([sapien.physx.PhysxCpuSystem()])
    scene.set_timestep(1 / 240)
    scene.add_ground(0.0, render=False)
    loader = URDFLoader()
    loader.set_scene(scene)
    loader.fix_root_link = False
    builders, _, _ = loader.parse(str(next(folder.glob("*.urdf"))))
    for b in builders:
        for link in b.link_builders:
            link.visual_records = []
    art = builders[0].build(fix_root_link=False)
    return scene, art, apply_springs(art, json.loads((folder / "metadata.json").read_text()))


@pytest.mark.parametrize("design", ["pump_bottle", "sauce_pump"])
def test_a_pressed_pump_springs_back_when_let_go(design, tmp_path):
    obj = infmob_usd.generate("dispenser", seed=1, texture_size=16, design=design)
    folder = infmob_usd.save(obj, tmp_path / design, formats="urdf")
    meta = json.loads((folder / "metadata.json").read_text())
    pump = next(j for j in meta["joints"] if j["role"] == "plunger")
    scene, art, springs = _free_standing(folder)
    i = [j.name for j in art.get_active_joints()].index(pump["name"])
    q = np.zeros(art.dof, dtype=np.float32)
    q[i] = pump["upper"]  # pressed to the bottom of its stroke
    art.set_qpos(q)
    for _ in range(240):  # 1 s
        scene.step()
    assert abs(float(art.get_qpos()[i])) < 0.05 * pump["upper"], f"{design}: the pump stayed down"
    assert springs >= 1


def test_a_pump_bottle_is_labelled():
    """A soap or lotion pump bottle carries a printed label round its straight part, on the body (glued)."""
    from helpers import maker

    _, bp = maker("dispenser")(2, design="pump_bottle")
    band = [pc for pc in bp.parts["body"].pieces if pc.material == "label"]
    wall = [pc for pc in bp.parts["body"].pieces if pc.material == "glass"]
    assert len(band) == 1
    lo, hi = band[0].vertices.min(0), band[0].vertices.max(0)
    top = max(pc.vertices[:, 2].max() for pc in wall)
    assert 0.2 * top < (lo[2] + hi[2]) / 2 < 0.6 * top  # round the body, under the shoulder
    assert hi[0] - lo[0] > 0.9 * (max(pc.vertices[:, 0].max() for pc in wall) - min(pc.vertices[:, 0].min()
                                                                                   for pc in wall))
