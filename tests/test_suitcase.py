"""The suitcase: its telescopic handle is a chain of stages that a pull on the grip draws out to hand height in
MuJoCo and a push on the grip slides back in; the lid opens flat beside the case."""

from __future__ import annotations

import json
import math

import pytest

import infmob_usd

pytestmark = pytest.mark.sim


@pytest.fixture(scope="module")
def spinner(tmp_path_factory):
    obj = infmob_usd.generate("suitcase", seed=0, texture_size=16, design="hard_spinner")
    return infmob_usd.save(obj, tmp_path_factory.mktemp("suitcase") / "spinner", formats="urdf,mjcf")


def _stages(meta):
    joints = {j["child"]: j for j in meta["joints"]}
    chain, part = [], "body"
    while True:
        nxt = [j for j in meta["joints"] if j["parent"] == part and j["child"].startswith("handle_stage_")]
        if not nxt:
            return chain, joints
        chain.append(nxt[0])
        part = nxt[0]["child"]


def test_the_handle_is_a_chain_of_upward_slides_and_the_lid_opens_flat(spinner):
    meta = json.loads((spinner / "metadata.json").read_text())
    chain, _ = _stages(meta)
    assert len(chain) >= 2, "a telescopic handle has at least two stages, each on the one below"
    for j in chain:
        assert j["type"] == "prismatic" and j["axis"] == pytest.approx([0, 0, 1])
    lid = next(j for j in meta["joints"] if j["child"] == "lid")
    assert lid["upper"] == pytest.approx(math.pi, abs=0.05), "a clamshell opens flat"


def _pull(m, d, body, force, seconds):
    """A hand's vertical force on ``body`` (a world force: the stages below carry it to their stops)."""
    import mujoco

    for _ in range(int(seconds / m.opt.timestep)):
        d.xfrc_applied[:] = 0.0
        d.xfrc_applied[body, 2] = force
        mujoco.mj_step(m, d)


def test_a_pull_on_the_grip_draws_every_stage_out_and_a_push_slides_it_back(spinner):
    """A hand's 40 N pull up on the grip: the stages below follow it to their stops and the grip's
    top rises to hand height (0.95-1.2 m); a 40 N push down slides them all back in."""
    import mujoco

    meta = json.loads((spinner / "metadata.json").read_text())
    chain, _ = _stages(meta)
    m = mujoco.MjModel.from_xml_path(str(next(spinner.glob("*.xml"))))
    d = mujoco.MjData(m)
    ids = [mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_JOINT, j["name"]) for j in chain]
    grip = m.jnt_bodyid[ids[-1]]
    _pull(m, d, grip, 40.0, 1.0)
    out = [float(d.qpos[m.jnt_qposadr[i]]) for i in ids]
    assert all(q > 0.9 * m.jnt_range[i][1] for q, i in zip(out, ids)), out
    top = float(d.xpos[grip][2]) + 0.03  # the grip stands 30 mm on its stage's slide frame
    assert 0.95 < top < 1.2, f"the extended grip's top is at {top:.3f} m"
    _pull(m, d, grip, -40.0, 1.0)
    back = [float(d.qpos[m.jnt_qposadr[i]]) for i in ids]
    assert all(q < 0.01 for q in back), f"the handle did not slide back in: {back}"
