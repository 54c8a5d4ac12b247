"""A part behind a door moves only once the door is open: declared, written, and honoured by checks."""

import json
import math

import numpy as np
import pytest

import infmob_usd
from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.api import assemble
from infmob_usd.blueprint import Blueprint
from infmob_usd.errors import ModelError
from infmob_usd.validate.physics import check_physics


def cupboard(gated: bool) -> Blueprint:
    """A hollow box with a door on its front (+X) and a tray inside that slides out through it."""
    bp = Blueprint("cupboard", materials={"m": "painted", "t": "plastic"})
    t = 0.02
    bp.add("body", "body", [
        g.box_between([-0.3, -0.3, 0.0], [0.3, 0.3, t], "m"),
        g.box_between([-0.3, -0.3, 0.5 - t], [0.3, 0.3, 0.5], "m"),
        g.box_between([-0.3, -0.3, t], [0.3, -0.3 + t, 0.5 - t], "m"),
        g.box_between([-0.3, 0.3 - t, t], [0.3, 0.3, 0.5 - t], "m"),
        g.box_between([-0.3, -0.3 + t, t], [-0.3 + t, 0.3 - t, 0.5 - t], "m"),
    ])
    bp.add("door", "door", [g.box_between([0.303, -0.3, 0.003], [0.323, 0.3, 0.497], "m")])
    bp.join(J.revolute("body", "door", (0.323, -0.3, 0.0), (0, 0, -1), 0.0, math.pi / 2))
    bp.add("tray", "drawer", [g.box_between([-0.25, -0.2, 0.03], [0.25, 0.2, 0.08], "t")])
    bp.join(J.prismatic("body", "tray", (0.25, 0, 0.03), (1, 0, 0), 0.0, 0.35,
                        requires_open="door" if gated else None))
    return bp


def cupboard_with_rider() -> Blueprint:
    """The gated cupboard with a small box on its tray that slides further out only with the tray pulled
    out: it requires the tray open, which requires the door open."""
    bp = cupboard(True)
    bp.add("rider", "drawer", [g.box_between([-0.1, -0.05, 0.081], [0.0, 0.05, 0.12], "t")])
    bp.join(J.prismatic("tray", "rider", (0.0, 0, 0.081), (1, 0, 0), 0.0, 0.05, requires_open="tray"))
    return bp


def _checks(folder):
    return {c.name: c for c in check_physics(folder)}


def _unlimited(bp):
    """The object without the core's clearance limits (what the checks must catch by themselves)."""
    from infmob_usd import physical

    original = physical.limit_to_clearance
    physical.limit_to_clearance = lambda obj: obj
    try:
        return assemble(bp, 0, np.random.default_rng(0), 16)
    finally:
        physical.limit_to_clearance = original


def test_requires_open_is_written_and_honoured(tmp_path):
    obj = assemble(cupboard(True), 0, np.random.default_rng(0), 16)
    assert next(j for j in obj.joints if j.child == "tray").upper == pytest.approx(0.35)
    folder = infmob_usd.save(obj, tmp_path / "gated")
    meta = json.loads((folder / "metadata.json").read_text())
    tray = next(j for j in meta["joints"] if j["child"] == "tray")
    assert tray["requires_open"] == "door"
    res = _checks(folder)
    assert res["self_collision"].ok, res["self_collision"].detail

    ungated = infmob_usd.save(_unlimited(cupboard(False)), tmp_path / "free")
    res = _checks(ungated)
    assert not res["self_collision"].ok and "door" in res["self_collision"].detail
    # the core's clearance pass stops an ungated tray before the closed door instead
    limited = assemble(cupboard(False), 0, np.random.default_rng(0), 16)
    assert next(j for j in limited.joints if j.child == "tray").upper < 0.303 - 0.25
    assert _checks(infmob_usd.save(limited, tmp_path / "limited"))["self_collision"].ok


@pytest.mark.sim
def test_reach_opens_the_door_first(tmp_path):
    pytest.importorskip("sapien")
    from infmob_usd.validate.sim import check_sapien

    folder = infmob_usd.save(assemble(cupboard(True), 0, np.random.default_rng(0), 16), tmp_path / "gated")
    res = {c.name: c for c in check_sapien(folder, checks=["reach"])}
    assert res["reach"].ok, res["reach"].detail
    ungated = infmob_usd.save(_unlimited(cupboard(False)), tmp_path / "free")
    res = {c.name: c for c in check_sapien(ungated, checks=["reach"])}
    assert not res["reach"].ok and "joint_tray" in res["reach"].detail


def _joint(meta, child):
    return next(j["name"] for j in meta["joints"] if j["child"] == child)


def test_requires_open_is_transitive_in_every_check(tmp_path):
    """A part that requires a part open that requires another open (tines on a rack behind a dishwasher's
    door) moves with both open: every reader of metadata.json follows the chain, nearest gate first, so no
    check pulls the tray through the closed door when it moves the rider."""
    folder = infmob_usd.save(assemble(cupboard_with_rider(), 0, np.random.default_rng(0), 16), tmp_path / "o")
    res = _checks(folder)
    assert res["self_collision"].ok, res["self_collision"].detail
    from infmob_usd.validate.files import gate_joints
    from infmob_usd.validate.mujoco_sim import opened_by
    from infmob_usd.validate.posing import _qpos_for, _read_object

    meta = json.loads((folder / "metadata.json").read_text())
    door, tray, rider = (_joint(meta, c) for c in ("door", "tray", "rider"))
    assert next(j for j in meta["joints"] if j["name"] == rider)["requires_open"] == "tray"
    assert gate_joints(meta) == {tray: [door], rider: [tray, door]}
    assert opened_by(meta)[rider] == [tray, door]
    files = _read_object(folder)
    q = _qpos_for(files, {rider: 1.0})
    assert q[door] == pytest.approx(math.pi / 2) and q[tray] == pytest.approx(0.35)


@pytest.mark.sim
def test_reach_opens_every_gate_of_the_chain(tmp_path):
    pytest.importorskip("sapien")
    from infmob_usd.validate.sim import check_sapien

    folder = infmob_usd.save(assemble(cupboard_with_rider(), 0, np.random.default_rng(0), 16), tmp_path / "o")
    res = {c.name: c for c in check_sapien(folder, checks=["reach"])}
    assert res["reach"].ok, res["reach"].detail


def test_the_gate_must_be_a_movable_part_declared_first():
    bp = cupboard(False)
    bp.add("late", "drawer", [g.box_between([-0.1, -0.1, 0.2], [0.1, 0.1, 0.25], "t")])
    with pytest.raises(ModelError, match="requires 'ghost' open"):
        bp.join(J.prismatic("body", "late", (0.1, 0, 0.2), (1, 0, 0), 0.0, 0.1, requires_open="ghost"))


def test_a_part_never_requires_its_own_gate_closed():
    """Closed both ways, a door that requires its tray closed would have the tray require the door closed as
    well as open: refused, naming the two parts."""
    from dataclasses import replace

    for gated, closed in (("tray", "door"), ("door", "tray")):
        bp = cupboard(True)
        bp.joints[:] = [replace(s, requires_closed=(closed,)) if s.child == gated else s for s in bp.joints]
        with pytest.raises(ModelError, match="'tray' moves only with 'door' open but requires it closed"):
            assemble(bp, 0, np.random.default_rng(0), 16)


def oven_with_flap() -> Blueprint:
    """A hollow box on a 10 cm plinth with a door hinged along its bottom front edge that falls open to level,
    and a 19 cm flap hinged near the door's top on its outer face, which swings outwards only with the door
    open: then it swings down towards the floor, and hangs off its hinge."""
    bp = cupboard(False)
    del bp.parts["tray"], bp.parts["door"]
    bp.joints[:] = []
    bp.add("door", "door", [g.box_between([0.303, -0.3, 0.1], [0.323, 0.3, 0.497], "m")])
    bp.join(J.revolute("body", "door", (0.323, 0.0, 0.1), (0, 1, 0), 0.0, math.pi / 2))
    bp.add("flap", "flap", [g.box_between([0.325, -0.05, 0.3], [0.335, 0.05, 0.49], "m")])
    bp.join(J.revolute("door", "flap", (0.325, 0.0, 0.49), (0, -1, 0), 0.0, math.pi / 2, requires_open="door"))
    return bp


def test_ground_and_rest_are_judged_with_the_gates_that_carry_a_joint_open(tmp_path):
    """A part that moves only with the part carrying it open (a flap on a fall-down door) keeps clear of the
    floor in that state, the one every check moves it in, and rests there: its centre of mass is brought onto
    its hinge line (a counterweight heel), since with the door down gravity pulls it off its rest stop."""
    from infmob_usd.physical import gravity_torque

    obj = assemble(oven_with_flap(), 0, np.random.default_rng(0), 16)
    flap = next(j for j in obj.joints if j.child == "flap")
    assert 0.3 < flap.upper < math.radians(80), flap.upper
    res = _checks(infmob_usd.save(obj, tmp_path / "o"))
    assert res["ground"].ok, res["ground"].detail
    link = next(k for k in obj.links if k.name == "flap")
    assert any(p.name == "counterweight" for p in link.pieces)
    torque, mass, _ = gravity_torque(obj.links, obj.joints, flap)
    assert abs(torque) < 1e-3 * 9.81 * mass
