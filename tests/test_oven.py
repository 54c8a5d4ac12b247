"""The oven category: parts, joints, balance of the door and knobs, clearances at joint states."""

from __future__ import annotations

import math

import numpy as np
import pytest

from infmob_usd.categories import oven
from infmob_usd.categories.parts.appliance import OVEN_RACK_R
from infmob_usd.lift_off import LIFT_OFF
from infmob_usd.mass import inertial
from infmob_usd.materials import FAMILIES, split_spec
from infmob_usd.seeding import streams

import collide
from helpers import maker
from zoo import by_child, movable

SEEDS = range(4)
LABELS = {"body", "door", "drawer", "rack", "knob", "button", "grate", "control_panel"}
VOL = 1e-7  # m^3, the validator's contact volume


make = maker("oven")


def q_at(bp, fractions):
    """``Blueprint.poses`` values for ``fractions`` ({child: f}): every DoF of that child's joint
    at fraction ``f`` of its range (continuous: ``f`` pi); joints not named stay at rest."""
    q = {}
    for j in bp.joints:
        if j.child in fractions:
            f = fractions[j.child]
            for i, d in enumerate(j.dofs):
                q[(j.child, i)] = f * math.pi if d.type == "continuous" else d.lower + f * (d.upper - d.lower)
    return q


def jointed(bp, a, b):
    """Parent and child, or welded (only fixed joints between): pairs the validator skips."""
    if any({j.parent, j.child} == {a, b} for j in bp.joints):
        return True
    parent = {j.child: j for j in bp.joints}

    def up(n):
        seq = [n]
        while seq[-1] in parent:
            seq.append(parent[seq[-1]].parent)
        return seq

    ua, ub = up(a), up(b)
    common = next(x for x in ua if x in ub)
    path = [parent[x] for x in ua[:ua.index(common)]] + [parent[x] for x in ub[:ub.index(common)]]
    return not any(j.movable for j in path)


def contacts(bp, state):
    return collide.contacts(bp, q_at(bp, state), VOL, skip=lambda a, b: jointed(bp, a, b))


def opened(bp, state):
    """``state`` with the door fully open when a rack behind it moves (as the validator does)."""
    out = dict(state)
    for j in bp.joints:
        if j.requires_open and state.get(j.child, 0.0) != 0.0:
            out[j.requires_open] = 1.0
    return out


def com(part, bp):
    dens = {slot: FAMILIES[split_spec(fam)[0]].density for slot, fam in bp.materials.items()}
    return inertial((pc, dens[pc.material]) for pc in part.pieces)[1]


# -- parts and joints ------------------------------------------------------------------------


@pytest.mark.parametrize("seed", SEEDS)
def test_parts_labels_and_materials(seed):
    p, bp = make(seed)
    assert bp.root == "body"
    assert {part.label for part in bp.parts.values()} <= LABELS
    for name in ("door", "control_panel"):
        assert bp.parts[name].label == name
    racks = [n for n, part in bp.parts.items() if part.label == "rack"]
    knobs = [n for n, part in bp.parts.items() if part.label == "knob"]
    ovens = 2 if p["style"] == "double_wall" else 1  # a double wall oven has racks in each oven
    assert len(racks) == ovens * p["rack_count"] and 2 <= p["rack_count"] <= 4
    assert 2 <= len(knobs) <= 8
    assert any(pc.material == "glass" for pc in bp.parts["door"].pieces)
    assert any(pc.name == "handle" for pc in bp.parts["door"].pieces)
    used = {pc.material for part in bp.parts.values() for pc in part.pieces}
    assert used <= set(bp.materials)
    assert bp.bounds()[0, 2] == pytest.approx(0.0, abs=1e-9)


@pytest.mark.parametrize("seed", SEEDS)
def test_joint_kinds_axes_and_limits(seed):
    p, bp = make(seed)
    doors = {n for n, part in bp.parts.items() if part.label == "door"}
    door = by_child(bp, "door")
    d = door.dofs[0]
    assert door.kind == "revolute" and door.parent == "body"
    assert d.axis == pytest.approx((0, 1, 0)) and (d.lower, d.upper) == (0.0, pytest.approx(math.pi / 2))
    slab = np.array([pc.bounds for pc in bp.parts["door"].pieces if pc.name != "handle"])
    assert d.origin[0] == pytest.approx(slab[:, 1, 0].max())  # front face
    assert d.origin[2] == pytest.approx(slab[:, 0, 2].min())  # bottom edge
    for name, part in bp.parts.items():
        if name == "body":
            continue
        j = by_child(bp, name)
        # only the racks are behind the door; the drawer, grates, knobs and buttons move freely
        assert (j.requires_open in doors) if part.label == "rack" else j.requires_open is None, name
        if part.label == "rack":
            assert j.requires_open == ("lower_door" if name.startswith("lower_") else "door")
        if part.label == "rack":
            assert j.kind == "prismatic" and j.dofs[0].axis == pytest.approx((1, 0, 0))
            b = np.array([pc.bounds for pc in part.pieces])
            depth = b[:, 1, 0].max() - b[:, 0, 0].min()  # the wire frame's depth (+ its wire)
            assert j.dofs[0].lower == 0.0
            assert j.dofs[0].upper == pytest.approx(p["rack_travel"] * depth, abs=2 * OVEN_RACK_R)
            assert j.dofs[0].upper > 0.15  # the real pull-out, not a stop at the closed door
        elif part.label == "knob":
            assert j.parent == "control_panel" and j.dofs[0].axis == pytest.approx((1, 0, 0))
            if p["knob_motion"] == "revolute":
                assert (j.dofs[0].lower, j.dofs[0].upper) == (pytest.approx(-math.pi / 4), pytest.approx(math.pi / 4))
            else:
                assert j.kind == "continuous"
        elif part.label == "button":
            assert j.kind == "prismatic" and j.dofs[0].axis == pytest.approx((-1, 0, 0))
            assert 0.0 == j.dofs[0].lower < j.dofs[0].upper <= 0.006
        elif part.label == "grate":
            assert j.kind == "limited_floating"
            # lifts off first, then only a little play: no slide across the cooktop; a lift-off part stops at
            # a hand's lift (its bars stand clear of the burner caps on their feet)
            assert [dd.axis for dd in j.dofs] == [(0, 0, 1), (1, 0, 0), (0, 1, 0)] and j.role == "lift_off"
            assert (j.dofs[0].lower, j.dofs[0].upper) == (0.0, pytest.approx(min(p["grate_lift"], LIFT_OFF)))
            assert j.dofs[0].upper <= LIFT_OFF and 0.04 >= j.dofs[1].upper
            assert max(abs(j.dofs[2].lower), j.dofs[2].upper) <= 0.006
        elif part.label == "drawer":
            assert j.kind == "prismatic" and j.dofs[0].axis == pytest.approx((1, 0, 0))
        elif name == "control_panel":
            assert j.kind == "fixed"


@pytest.mark.parametrize("seed", SEEDS)
def test_gravity_keeps_the_door_shut_and_knobs_balanced(seed):
    _, bp = make(seed)
    hinge = by_child(bp, "door").dofs[0].origin
    c = com(bp.parts["door"], bp)
    assert c[0] < hinge[0] - 0.005  # behind the hinge line: gravity presses it closed (q -> 0)
    for name, part in bp.parts.items():
        if part.label == "knob":
            o = by_child(bp, name).dofs[0].origin
            assert com(part, bp)[1:] == pytest.approx(o[1:], abs=2e-4)


# -- clearances --------------------------------------------------------------------------------


@pytest.mark.parametrize("seed", [0, 1])
def test_rest_and_combined_states_are_free(seed):
    _, bp = make(seed, has_drawer=True)
    for f in (0.0, 0.5, 1.0):
        state = opened(bp, {j.child: f for j in movable(bp)})
        assert contacts(bp, state) == [], f"contact with every joint at {f:.0%}"


@pytest.mark.parametrize("seed", [2, 3])
def test_each_joint_alone_at_its_limits(seed):
    """Every single-joint state is free; a rack is pulled out with the door open first."""
    _, bp = make(seed, has_drawer=True, has_grates=True, style="range")
    for j in movable(bp):
        for f in (1.0,) if j.dofs[0].lower == 0 else (0.0, 1.0):
            assert contacts(bp, opened(bp, {j.child: f})) == [], f"{j.child} at {f:.0%}"


def test_the_door_is_solid():
    """The whole door collides (skins, frame, both glass panes): a rack pulled out through the
    shut door meets it and nothing else; with the door open it is free."""
    _, bp = make(1)
    door = bp.parts["door"]
    assert all(pc.convex for pc in door.pieces)
    glass = [pc for pc in door.pieces if pc.material == "glass"]
    assert len(glass) == 2
    slab = np.array([pc.bounds for pc in door.pieces if pc.name != "handle"])
    lo, hi = slab[:, 0].min(0), slab[:, 1].max(0)
    # the door's collision covers its whole face: sample points across it, through its depth
    hulls = np.array([[c.min(0), c.max(0)] for pc in door.pieces if pc.name != "handle" for c in pc.convex])
    ys = np.linspace(lo[1] + 0.03, hi[1] - 0.03, 9)
    zs = np.linspace(lo[2] + 0.03, hi[2] - 0.03, 9)
    for y in ys:
        for z in zs:
            inside = (hulls[:, 0, 1] <= y) & (y <= hulls[:, 1, 1]) & (hulls[:, 0, 2] <= z) & (z <= hulls[:, 1, 2])
            assert inside.any(), (y, z)
    racks = [j for j in movable(bp) if bp.parts[j.child].label == "rack"]
    assert racks
    for j in racks:
        assert {(a, b) for a, b, _ in contacts(bp, {j.child: 1.0})} == {("door", j.child)}
        assert contacts(bp, {j.child: 1.0, "door": 1.0}) == []


@pytest.mark.parametrize("seed", SEEDS)
def test_nothing_below_ground(seed):
    _, bp = make(seed, has_drawer=True)
    for f in (0.0, 0.5, 1.0):
        ps = bp.poses(q_at(bp, opened(bp, {j.child: f for j in movable(bp)})))
        for name, part in bp.parts.items():
            pts = np.vstack([pc.vertices for pc in part.pieces])
            assert (pts @ ps[name][:3, :3].T + ps[name][:3, 3])[:, 2].min() >= -1e-6, (name, f)


# -- overrides, growth, determinism ------------------------------------------------------------


def test_forced_grates_knobs_buttons_drawer_and_racks_build_those_parts():
    """Forced grates, knob and button counts, drawer and racks build exactly those parts (the generic contract:
    test_category_contract)."""
    _, bp = make(0, style="wall")
    assert not any(part.label == "grate" for part in bp.parts.values())
    _, bp = make(0, style="range", has_grates=True, grate_count=3)
    assert sorted(n for n, part in bp.parts.items() if part.label == "grate") == ["grate_0", "grate_1", "grate_2"]
    _, bp = make(0, knob_count=8, has_buttons=True, button_count=6, width=0.5)
    assert sum(part.label == "knob" for part in bp.parts.values()) == 8
    assert sum(part.label == "button" for part in bp.parts.values()) == 6
    _, bp = make(0, style="range", has_drawer=False)
    assert "drawer" not in bp.parts
    _, bp = make(0, style="range", has_drawer=True, rack_count=4)
    assert bp.parts["drawer"].label == "drawer"
    assert sum(part.label == "rack" for part in bp.parts.values()) == 4


def test_seeds_differ():
    params = [oven.CATEGORY.schema.sample(streams("oven", s)["params"]) for s in range(12)]
    for name in ("style", "knob_motion", "has_drawer", "has_buttons", "rack_count"):
        assert len({p[name] for p in params}) > 1, name


@pytest.mark.parametrize("style", ["range", "warming", "wall", "double_wall"])
def test_each_design_is_forced_and_has_its_parts(style):
    """``--set style=...`` forces a design; each has its own structure and its movable joints."""
    p, bp = make(5, style=style, has_grates=True, has_drawer=True)
    labels = [part.label for part in bp.parts.values()]
    doors = sorted(n for n, part in bp.parts.items() if part.label == "door")
    assert doors == (["door", "lower_door"] if style == "double_wall" else ["door"])
    assert ("grate" in labels) == (style in ("range", "warming"))
    assert ("drawer" in labels) == (style in ("range", "warming"))
    racks = [n for n, part in bp.parts.items() if part.label == "rack"]
    assert len(racks) == p["rack_count"] * (2 if style == "double_wall" else 1)
    assert all(by_child(bp, n).requires_open in doors for n in racks)
    top = max(pc.bounds[1][2] for part in bp.parts.values() for pc in part.pieces)
    if style == "double_wall":  # two ovens stacked: 1.2-1.4 m like real double wall ovens
        assert 1.15 < top < 1.4
        lo, up = by_child(bp, "lower_door").dofs[0].origin[2], by_child(bp, "door").dofs[0].origin[2]
        assert up > lo + 0.35
    if style == "warming":  # the warming drawer has a bar handle, like the door's
        assert any(pc.name == "handle" and pc.material == "handle" for pc in bp.parts["drawer"].pieces)
    assert len(movable(bp)) >= 4
