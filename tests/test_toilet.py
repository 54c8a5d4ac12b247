"""The toilet category: parts, one shared hinge line, clearances at every sampled joint state, overrides."""

from __future__ import annotations

import math

import numpy as np
import pytest

from infmob_usd.api import generate
from infmob_usd.blueprint import dof_motion
from infmob_usd.categories import toilet as mod
from infmob_usd.lift_off import LIFT_OFF
from infmob_usd.model import build as build_model
from infmob_usd.physical import gravity_torque

from collide import contacts, overlap
from helpers import labelled_states, maker
from zoo import by_child, movable, object_limits

SEEDS = range(8)
VOLUME_TOL = 1e-7  # m^3, as the physics checks


REAR = {"close_coupled": {"tank": "tank", "tank_lid": "lid"}, "one_piece": {"tank": "tank", "tank_lid": "lid"},
        "back_to_wall": {"unit": "cabinet"}, "wall_hung": {"prewall": "frame"}}
"""Each design's part behind the seat (fixed to the pan) and what it carries."""
DESIGNS = tuple(REAR)


def has_cistern(p):
    return p["design"] in ("close_coupled", "one_piece")


make = maker("toilet")


def welded(bp, a, b):
    """Parts joined only through fixed joints never move relative to each other."""
    def top(n):
        while True:
            j = next((j for j in bp.joints if j.child == n), None)
            if j is None or j.movable:
                return n
            n = j.parent
    return top(a) == top(b)


# -- parts and labels ----------------------------------------------------------------


@pytest.mark.parametrize("seed", SEEDS)
def test_parts_labels_and_materials(seed):
    p, bp = make(seed)
    assert bp.root == "base"
    want = {"base": "body", "seat": "seat", "cover": "lid", **REAR[p["design"]]}
    for name, label in want.items():
        assert bp.parts[name].label == label
    if has_cistern(p):
        flush = {"button": [("flush_button", "button")], "lever": [("flush_lever", "lever")],
                 "dual": [("flush_small", "button"), ("flush_large", "button")]}[p["flush"]]
    else:
        flush = [("flush_small", "button"), ("flush_large", "button")]
    for name, label in flush:
        assert bp.parts[name].label == label
    rear = next(iter(REAR[p["design"]]))
    assert by_child(bp, rear).kind == "fixed"
    assert bp.materials["ceramic"].startswith("ceramic")
    used = {pc.material for part in bp.parts.values() for pc in part.pieces}
    assert used <= set(bp.materials)
    for part in bp.parts.values():
        for pc in part.pieces:
            assert pc.convex, f"{part.name}: a piece without collision"
    links, _ = build_model(bp, {k: 1000.0 for k in bp.materials})
    assert all(link.mass > 0 for link in links)
    assert bp.bounds()[0, 2] == pytest.approx(0.0, abs=1e-9)


@pytest.mark.parametrize("seed", SEEDS)
def test_front_faces_plus_x_and_size(seed):
    p, bp = make(seed)
    bowl_x = np.mean([pc.bounds[:, 0].mean() for pc in bp.parts["seat"].pieces])
    rear = next(iter(REAR[p["design"]]))
    tank_x = np.mean([pc.bounds[:, 0].mean() for pc in bp.parts[rear].pieces])
    assert bowl_x > tank_x
    lo, hi = bp.bounds()
    assert abs(lo[0] + hi[0]) < 0.02 and abs(lo[1] + hi[1]) < 0.02  # centred
    seat_top = max(pc.bounds[1, 2] for pc in bp.parts["seat"].pieces)
    want = p["hung_seat_height"] if p["design"] == "wall_hung" else p["seat_height"]
    assert seat_top == pytest.approx(want, abs=1e-6)
    assert 0.4 <= seat_top <= 0.5
    if p["design"] == "wall_hung":  # off the floor: nothing of the pan below 0.1 m
        assert min(pc.bounds[0, 2] for pc in bp.parts["base"].pieces) > 0.1


def test_the_bowl_is_hollow():
    _, bp = make(0)
    seat = np.array([pc.bounds for pc in bp.parts["seat"].pieces])
    cx = (seat[:, 0, 0].min() + seat[:, 1, 0].max()) / 2 + 0.02
    rim = seat[:, 0, 2].min() - 0.05
    probe = np.array([cx, 0.0, rim])  # a point inside the bowl, below the rim
    from scipy.spatial import Delaunay
    for pc in bp.parts["base"].pieces:
        for c in pc.convex:
            assert Delaunay(c).find_simplex(probe) < 0, "the bowl cavity is filled by a collision hull"


# -- joints ------------------------------------------------------------------------------


@pytest.mark.parametrize("seed", SEEDS)
def test_seat_and_cover_share_one_hinge(seed):
    _, bp = make(seed)
    bp = object_limits("toilet", seed, bp)  # the core stops them where the cover leans on the cistern
    s, c = by_child(bp, "seat"), by_child(bp, "cover")
    assert s.kind == c.kind == "revolute"
    assert s.parent == "base" and c.parent == "seat"
    sd, cd = s.dofs[0], c.dofs[0]
    assert sd.axis == pytest.approx((0, -1, 0)) and cd.axis == pytest.approx((0, -1, 0))
    assert sd.origin == pytest.approx(cd.origin)
    lo, hi = np.array([pc.bounds for pc in bp.parts["seat"].pieces]).transpose(1, 0, 2)
    assert sd.origin[0] == pytest.approx(lo[:, 0].min()) and sd.origin[2] == pytest.approx(hi[:, 2].max())
    assert sd.lower == cd.lower == 0.0
    total = sd.upper + cd.upper
    assert math.pi / 2 < total < 2.0  # leaning back on the cistern
    assert sd.upper > 0.5 and cd.upper > 0.75
    # a positive angle lifts the front of the seat
    front = np.array([lo[:, 0].max() + 0.3, 0.0, sd.origin[2], 1.0])
    front[0] = hi[:, 0].max()
    assert (dof_motion(sd, 0.3) @ front)[2] > front[2] + 0.05


@pytest.mark.parametrize("seed", SEEDS)
def test_lid_and_flush_joints(seed):
    p, bp = make(seed)
    if not has_cistern(p):  # a dual-flush plate: two keys pressed into it
        for name in ("flush_small", "flush_large"):
            j = by_child(bp, name)
            assert j.kind == "prismatic" and j.parent == next(iter(REAR[p["design"]]))
            assert j.dofs[0].axis == pytest.approx((-1, 0, 0)) and 0 < j.dofs[0].upper <= 0.01
        assert len(movable(bp)) == 4
        return
    lid = by_child(bp, "tank_lid")
    assert lid.kind == "prismatic" and lid.parent == "tank"
    assert lid.dofs[0].axis == pytest.approx((0, 0, 1))
    # lifted a hand's lift (the core's lift-off rule): clear of its locating lip, not through the air
    assert (lid.dofs[0].lower, lid.dofs[0].upper) == (0.0, pytest.approx(LIFT_OFF))
    assert lid.dofs[0].upper > mod.S.LID["lip"] and lid.role == "lift_off"
    if p["flush"] == "button":
        j = by_child(bp, "flush_button")
        assert j.kind == "prismatic" and j.dofs[0].axis == pytest.approx((-1, 0, 0))
        assert 0 < j.dofs[0].upper <= 0.01
    elif p["flush"] == "dual":  # two buttons side by side on the cistern front
        for name in ("flush_small", "flush_large"):
            j = by_child(bp, name)
            assert j.kind == "prismatic" and j.parent == "tank" and j.dofs[0].axis == pytest.approx((-1, 0, 0))
        assert len(movable(bp)) == 5
        return
    else:
        j = by_child(bp, "flush_lever")
        d = j.dofs[0]
        assert j.kind == "revolute" and d.axis == pytest.approx((0, 1, 0))  # a side lever
        assert (d.lower, d.upper) == (0.0, pytest.approx(math.pi / 4))
    assert len(movable(bp)) == 4


def test_lever_centre_of_mass_is_on_its_axis():
    _, bp = make(0, flush="lever", design="close_coupled")
    d = by_child(bp, "flush_lever").dofs[0]
    # the core's counterweight heel puts it on the axis in the object
    obj = generate("toilet", 0, 16, flush="lever", design="close_coupled")
    j = next(j for j in obj.joints if j.child == "flush_lever")
    torque, m, com = gravity_torque(obj.links, obj.joints, j)
    assert abs(torque) < 1e-6 and any(p.name == "counterweight" for p in obj.link("flush_lever").pieces)
    # its grip is at +X of the axis, behind the cistern front, and turns down for a positive angle
    tip = np.array([*d.origin, 1.0]) + [0.05, 0, 0, 0]
    grip = max(pc.bounds[1, 0] for pc in bp.parts["flush_lever"].pieces)
    assert grip > d.origin[0] + 0.05 and grip < min(pc.bounds[1, 0] for pc in bp.parts["tank"].pieces[:2])
    assert (dof_motion(d, 0.3) @ tip)[2] < d.origin[2]


# -- clearances ----------------------------------------------------------------------------


@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_no_overlap_at_sampled_states(seed):
    _, bp = make(seed)
    bp = object_limits("toilet", seed, bp)
    for label, q in labelled_states(bp):
        bad = contacts(bp, q, VOLUME_TOL, skip=lambda a, b: welded(bp, a, b))
        assert not bad, f"(part, part, m^3) overlapping at {label}: {bad}"


@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_children_never_enter_their_parents(seed):
    _, bp = make(seed)
    bp = object_limits("toilet", seed, bp)
    for j in movable(bp):
        d = j.dofs[0]
        for f in (0.0, 0.25, 0.5, 0.75, 1.0):
            pose = bp.poses({(j.child, 0): d.lower + f * (d.upper - d.lower)})
            v = overlap(bp.parts[j.child], pose[j.child], bp.parts[j.parent], pose[j.parent])
            assert v < VOLUME_TOL, f"{j.child} enters {j.parent} at {f:.0%}"


class _Inflated:
    """A part whose collision hulls are grown by ``d`` on every axis (a cube Minkowski sum)."""

    def __init__(self, part, d):
        offs = np.array([[x, y, z] for x in (-d, d) for y in (-d, d) for z in (-d, d)])
        self.pieces = [_Hulls([(c[:, None, :] + offs[None]).reshape(-1, 3) for c in pc.convex])
                       for pc in part.pieces]


class _Hulls:
    def __init__(self, pts):
        self.pts = pts

    def hulls(self):
        return [(p, None) for p in self.pts]


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_moving_parts_keep_a_gap_at_rest(seed):
    """Every moving part stays >= 1 mm (per axis) from every other part at rest."""
    _, bp = make(seed)
    eye = np.eye(4)
    for j in movable(bp):
        grown = _Inflated(bp.parts[j.child], 0.001)
        for other in bp.parts:
            if other != j.child:
                v = overlap(grown, eye, bp.parts[other], eye)
                assert v < 1e-9, f"{j.child} is within 1 mm of {other}"


@pytest.mark.parametrize("seed", SEEDS)
def test_nothing_below_ground(seed):
    _, bp = make(seed)
    for label, q in labelled_states(bp):
        pose = bp.poses(q)
        for name, part in bp.parts.items():
            pts = np.vstack([pc.vertices for pc in part.pieces])
            z = (pts @ pose[name][:3, :3].T + pose[name][:3, 3])[:, 2]
            assert z.min() >= -1e-6, f"{name} below ground at {label}"


# -- overrides, determinism -----------------------------------------------------------------


@pytest.mark.parametrize("design", DESIGNS)
def test_each_design_is_forced_moves_and_stays_clear(design):
    seed = 5
    p, bp = make(seed, design=design, flush="dual")
    assert p["design"] == design and set(REAR[design]) <= set(bp.parts)
    assert len(movable(bp)) == 5 if has_cistern(p) else 4
    bp = object_limits("toilet", seed, bp, design=design, flush="dual")
    for label, q in labelled_states(bp):
        bad = contacts(bp, q, VOLUME_TOL, skip=lambda a, b: welded(bp, a, b))
        assert not bad, f"(part, part, m^3) overlapping at {label}: {bad}"
    for j in movable(bp):
        d = j.dofs[0]
        for f in (0.0, 0.5, 1.0):
            pose = bp.poses({(j.child, 0): d.lower + f * (d.upper - d.lower)})
            v = overlap(bp.parts[j.child], pose[j.child], bp.parts[j.parent], pose[j.parent])
            assert v < VOLUME_TOL, f"{j.child} enters {j.parent} at {f:.0%}"


def test_designs_look_apart():
    """One-piece cisterns are lower than close-coupled ones; a wall-hung pan's frame is the tallest part."""
    _, cc = make(4, design="close_coupled")
    _, op = make(4, design="one_piece")
    assert op.bounds()[1, 2] < cc.bounds()[1, 2] - 0.05
    _, wh = make(4, design="wall_hung")
    assert max(pc.bounds[1, 2] for pc in wh.parts["prewall"].pieces) > 0.95


def test_overrides():
    _, bp = make(3, flush="button", design="close_coupled")
    assert "flush_button" in bp.parts and "flush_lever" not in bp.parts
    _, bp = make(3, flush="lever", design="one_piece")
    assert "flush_lever" in bp.parts and "flush_button" not in bp.parts
    p, bp = make(3, seat_height=0.45, seat_finish="wood")
    assert p["seat_height"] == 0.45 and bp.materials["seat"] == "wood"


def test_seeds_differ():
    params = [make(s)[0] for s in range(12)]
    for name in ("design", "flush", "seat_finish", "ceramic_colour"):
        assert len({p[name] for p in params}) > 1, name
