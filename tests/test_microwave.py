"""The microwave category: parts, joints, clearances at every joint state, overrides, seeds."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import linprog
from scipy.spatial import ConvexHull

from infmob_usd.categories import microwave as mw
from infmob_usd.materials import appliance
from infmob_usd.model import build as build_model

from helpers import maker
from zoo import by_child, movable

SEEDS = range(10)
LABELS = {"body", "door", "plate", "button", "knob", "control_panel", "drawer", "rack", "filter"}


# a counter-top turntable model unless ``design`` says otherwise (the tests below check its door, plate and
# panel; the other designs have their own tests at the end)
make = maker("microwave", design="turntable")


# -- convex geometry helpers ---------------------------------------------------------


def rotation(axis, angle):
    a = np.asarray(axis, float) / np.linalg.norm(axis)
    k = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + math.sin(angle) * k + (1 - math.cos(angle)) * k @ k


def moved(points, dof, q):
    """Points of a child part after its one DoF moved by ``q`` (radians or metres)."""
    if dof.type == "prismatic":
        return points + np.asarray(dof.axis) * q
    o = np.asarray(dof.origin)
    return (points - o) @ rotation(dof.axis, q).T + o


def hulls(part, dof=None, q=0.0):
    out = []
    for piece in part.pieces:
        for c in piece.convex:
            out.append(moved(c, dof, q) if dof is not None else c)
    return out


def depth(a, b):
    """Radius of the largest ball inside both convex hulls (<= 0: they do not overlap).

    For disjoint hulls it is minus the amount every face must be pushed out for the
    two to meet, a lower bound of half their distance.
    """
    lo = np.maximum(a.min(0), b.min(0))
    hi = np.minimum(a.max(0), b.max(0))
    if (lo - hi > 0.01).any():
        return -0.005  # far apart along an axis
    eq = np.vstack([ConvexHull(a).equations, ConvexHull(b).equations])  # n.x + d <= 0, |n| = 1
    res = linprog([0, 0, 0, -1], A_ub=np.c_[eq[:, :3], np.ones(len(eq))], b_ub=-eq[:, 3],
                  bounds=[(None, None)] * 3 + [(None, 1.0)], method="highs")
    assert res.status == 0
    return -res.fun


def max_depth(hs_a, hs_b):
    return max((depth(a, b) for a in hs_a for b in hs_b), default=-1.0)


def carried(bp, name):
    """``name`` and the parts fixed to it (a rack on the turntable turns with it)."""
    out = {name}
    for j in bp.joints:
        if j.kind == "fixed" and j.parent in out:
            out.add(j.child)
    return out


def group_hulls(bp, name, dof=None, q=0.0):
    """Convex hulls of ``name`` and what it carries, moved by ``q`` along ``dof``."""
    return [h for n in carried(bp, name) for h in hulls(bp.parts[n], dof, q)]


def others(bp, name):
    """Convex hulls of every part except ``name`` and what it carries, at rest."""
    group = carried(bp, name)
    return [h for n, part in bp.parts.items() if n not in group for h in hulls(part)]


# -- parts and labels ------------------------------------------------------------------


@pytest.mark.parametrize("seed", SEEDS)
def test_required_parts_labels_and_materials(seed):
    p, bp = make(seed)
    assert bp.root == "body"
    want = {"body": "body", "door": "door", "plate": "plate", "control_panel": "control_panel"}
    for name, label in want.items():
        assert bp.parts[name].label == label
    assert {part.label for part in bp.parts.values()} <= LABELS
    door = bp.parts["door"]
    assert any(pc.material == "glass" for pc in door.pieces)
    # appliance finishes (materials/palettes.py): smoked or clear door glass, a clear turntable
    assert bp.materials["glass"] == appliance("glass") and bp.materials["plate"] == "glass:clear"
    assert bp.materials["body"] == appliance(p["body_finish"])
    assert p["body_finish"] in ("painted", "brushed_metal", "plastic")
    assert bp.materials["interior"] in (appliance("enamel"), appliance("painted"))
    assert bp.materials["button"] == bp.materials["knob"] == appliance("plastic")
    used = {pc.material for part in bp.parts.values() for pc in part.pieces}
    assert used <= set(bp.materials)
    for part in bp.parts.values():
        for pc in part.pieces:
            assert pc.convex, f"{part.name}: a piece without collision"
    # the model builds: every link has a positive mass
    links, _ = build_model(bp, {k: 1000.0 for k in bp.materials})
    assert all(link.mass > 0 for link in links)


@pytest.mark.parametrize("seed", SEEDS)
def test_size_is_a_countertop_microwave(seed):
    p, bp = make(seed)
    body = np.array([pc.bounds for pc in bp.parts["body"].pieces])
    size = body[:, 1].max(0) - body[:, 0].min(0)
    assert size[1] == pytest.approx(p["width"], abs=0.003)
    assert size[2] == pytest.approx(p["height"], abs=1e-6)
    assert 0.44 <= p["width"] <= 0.62 and 0.25 <= p["height"] <= 0.36
    assert bp.bounds()[0, 2] == pytest.approx(0.0, abs=1e-9)


# -- joints ------------------------------------------------------------------------------


@pytest.mark.parametrize("seed", SEEDS)
def test_joint_kinds_axes_and_limits(seed):
    p, bp = make(seed)
    door = by_child(bp, "door")
    assert door.kind == "revolute" and door.parent == "body"
    d = door.dofs[0]
    assert d.axis == pytest.approx((0, 0, -1))
    assert (d.lower, d.upper) == (0.0, pytest.approx(math.pi / 2))
    # pivot on the door's front face at its left (min Y) edge
    lo, hi = np.array([pc.bounds for pc in bp.parts["door"].pieces if pc.name != "handle"]).transpose(1, 0, 2)
    assert d.origin[0] == pytest.approx(hi[:, 0].max())
    assert d.origin[1] == pytest.approx(lo[:, 1].min())

    plate = by_child(bp, "plate")
    assert plate.kind == "continuous" and plate.parent == "body"
    assert abs(plate.dofs[0].axis[2]) == pytest.approx(1.0)

    assert by_child(bp, "control_panel").kind == "fixed"
    for name, part in bp.parts.items():
        j = next((j for j in bp.joints if j.child == name), None)
        if part.label == "button":
            assert j.kind == "prismatic" and j.parent == "control_panel"
            b = j.dofs[0]
            assert b.axis == pytest.approx((-1, 0, 0)) and b.lower == 0.0
            lo, hi = part.pieces[0].bounds
            assert b.upper == pytest.approx((hi[2] - lo[2]) / 8, rel=1e-6)
            # a pressed button still stands proud of the fascia
            face = bp.parts["control_panel"].pieces[0].bounds[1, 0]
            assert hi[0] - b.upper > face
        elif part.label == "knob":
            assert j.kind == "continuous" and j.parent == "control_panel"
            assert abs(j.dofs[0].axis[0]) == pytest.approx(1.0)
    # door, plate, up to six rows of three keys (a number pad with function keys), two dials, a release
    assert 2 <= len(movable(bp)) <= 2 + 3 * mw.KEYPAD_ROWS + 3


# -- clearances ----------------------------------------------------------------------------

TOUCH = 5e-4  # m: deepest overlap tolerated between two collision hulls


@pytest.mark.parametrize("seed", SEEDS)
def test_door_sweep_never_enters_the_rest(seed):
    _, bp = make(seed)
    dof = by_child(bp, "door").dofs[0]
    rest = others(bp, "door")
    for frac in (0.0, 0.25, 0.5, 0.75, 1.0):
        door = hulls(bp.parts["door"], dof, dof.lower + frac * (dof.upper - dof.lower))
        assert max_depth(door, rest) < TOUCH, f"door overlaps at {frac:.0%} open"


@pytest.mark.parametrize("seed", SEEDS)
def test_moving_parts_are_clear_at_rest(seed):
    """Every moving part keeps >= 2 mm from everything else at rest."""
    _, bp = make(seed)
    for j in movable(bp):
        d = max_depth(group_hulls(bp, j.child), others(bp, j.child))
        assert -2 * d >= 0.0019, f"{j.child} is within 2 mm of another part"


@pytest.mark.parametrize("seed", SEEDS)
def test_buttons_knobs_plate_move_freely(seed):
    _, bp = make(seed)
    for j in movable(bp):
        if j.child == "door":
            continue
        dof = j.dofs[0]
        qs = [dof.upper] if dof.type == "prismatic" else [0.7, math.pi / 2, 2.5, -1.3]
        rest = others(bp, j.child)
        for q in qs:
            assert max_depth(group_hulls(bp, j.child, dof, q), rest) < TOUCH, f"{j.child} at {q}"


@pytest.mark.parametrize("seed", SEEDS)
def test_nothing_below_ground_at_the_limits(seed):
    _, bp = make(seed)
    for j in movable(bp):
        dof = j.dofs[0]
        for q in (dof.lower, dof.upper):
            pts = np.vstack([pc.vertices for pc in bp.parts[j.child].pieces])
            assert moved(pts, dof, q)[:, 2].min() >= -1e-9


@pytest.mark.parametrize("seed", SEEDS)
def test_plate_lies_inside_the_cavity(seed):
    _, bp = make(seed)
    liner = [pc for pc in bp.parts["body"].pieces if pc.material == "interior"]
    inner = np.array([pc.bounds for pc in liner])
    floor = min(liner, key=lambda pc: pc.bounds[1, 2])  # the liner wall with the lowest top
    floor_top = floor.bounds[1, 2]
    cav_lo = np.array([inner[:, 0, 0].min(), inner[:, 0, 1].min(), floor_top])
    cav_hi = inner[:, 1].max(0)
    plate = np.array([pc.bounds for pc in bp.parts["plate"].pieces])
    lo, hi = plate[:, 0].min(0), plate[:, 1].max(0)
    assert (lo > cav_lo).all() and (hi < cav_hi).all()
    # it rests just above the floor, spins about its own centre, and the door closes in front
    assert 0.002 <= lo[2] - floor_top <= 0.006
    axis = by_child(bp, "plate").dofs[0].origin
    assert axis[:2] == pytest.approx(((lo + hi) / 2)[:2], abs=1e-3)
    assert hi[0] < min(pc.bounds[0, 0] for pc in bp.parts["door"].pieces)
    glass = [pc for pc in bp.parts["plate"].pieces if pc.material == "plate"]
    assert glass and max(pc.bounds[1, 2] for pc in glass) == pytest.approx(hi[2])


# -- overrides, growth, determinism ----------------------------------------------------


def test_forced_knobs_buttons_and_door_opener_build_those_parts():
    """Forced knobs, buttons and door openers build exactly those parts: a release button replaces the door
    handle (the generic contract: test_category_contract)."""
    _, bp = make(3, has_knob=False)
    assert not any(part.label == "knob" for part in bp.parts.values())
    _, bp = make(3, has_knob=True, knob_count=2, has_buttons=False)
    assert sorted(n for n, part in bp.parts.items() if part.label == "knob") == ["knob_0", "knob_1"]
    assert not any(n.startswith("button_") for n in bp.parts)
    _, bp = make(3, has_buttons=True, button_rows=2, bottom_keys=3, door_opener="bar")
    assert sum(n.startswith("button_") for n in bp.parts) == 6
    assert "door_release" not in bp.parts
    assert any(pc.name == "handle" for pc in bp.parts["door"].pieces)
    _, bp = make(3, door_opener="release_button")
    assert bp.parts["door_release"].label == "button"
    assert not any(pc.name == "handle" for pc in bp.parts["door"].pieces)
    p, _ = make(3, width=0.5, body_finish="brushed_metal")
    assert p["width"] == 0.5 and p["body_finish"] == "brushed_metal"


def test_smallest_and_busiest_panel_fit():
    """Three rows of buttons, two dials and a release on the smallest front still fit."""
    over = dict(width=0.44, height=0.25, panel_fraction=0.2, has_buttons=True, button_rows=3, bottom_keys=3,
                has_rack=False, has_knob=True, knob_count=2, door_opener="release_button", knob_radius=0.028)
    _, bp = make(0, **over)
    panel = bp.parts["control_panel"].pieces[0].bounds
    for part in bp.parts.values():
        if part.label in ("button", "knob"):
            lo, hi = np.array([pc.bounds for pc in part.pieces]).transpose(1, 0, 2)
            assert (lo[:, 1:].min(0) > panel[0, 1:]).all() and (hi[:, 1:].max(0) < panel[1, 1:]).all()
    assert len(movable(bp)) == 14
    for j in movable(bp):
        if j.child != "door":
            assert -2 * max_depth(hulls(bp.parts[j.child]), others(bp, j.child)) >= 0.0019


def test_seeds_differ_in_ways_a_person_sees():
    params = [make(s)[0] for s in range(20)]
    for name in ("body_finish", "door_opener", "has_knob", "has_buttons", "button_shape"):
        assert len({p[name] for p in params}) > 1, name
    counts = [len(movable(make(s)[1])) for s in range(20)]
    assert min(counts) < max(counts)


# -- designs -------------------------------------------------------------------------------------


@pytest.mark.parametrize("design", ["turntable", "flatbed", "over_the_range", "drawer_model"])
def test_each_design_is_forced_and_has_its_mechanism(design):
    """``--set design=...`` forces a design; each has its own moving parts and real product sizes."""
    p, bp = make(4, design=design, has_buttons=True)
    assert p["design"] == design
    lo, hi = bp.bounds()
    w, h = hi[1] - lo[1], hi[2] - lo[2]
    kinds = {bp.parts[j.child].label: j.kind for j in movable(bp)}
    assert ("plate" in bp.parts) == (design in ("turntable", "over_the_range"))
    if design == "drawer_model":  # a drawer slides out under a control strip, no hinged door
        assert "door" not in bp.parts and kinds["drawer"] == "prismatic"
        d = by_child(bp, "drawer").dofs[0]
        assert d.axis == pytest.approx((1, 0, 0)) and d.upper > 0.3
        assert h == pytest.approx(0.39, abs=0.01)
        assert w in (pytest.approx(0.606, abs=0.01), pytest.approx(0.759, abs=0.01))
    else:
        assert kinds["door"] == "revolute"
    if design == "over_the_range":  # 30 in wide, a bar handle on the door, a vent grille over it
        assert w == pytest.approx(0.759, abs=0.06) and 0.39 <= h <= 0.45
        assert any(pc.name == "handle" for pc in bp.parts["door"].pieces)
        filters = [j for j in movable(bp) if bp.parts[j.child].label == "filter"]  # two grease filters slide back
        assert len(filters) == 2 and all(j.kind == "prismatic" and j.dofs[0].axis == pytest.approx((-1, 0, 0))
                                         for j in filters)
    if design == "flatbed":  # a fixed ceramic floor instead of the turntable
        assert any(pc.material == "plate" for pc in bp.parts["body"].pieces)
    keys = sum(bp.parts[j.child].label == "button" and j.child != "door_release" for j in movable(bp))
    assert keys == mw.key_count(p)


@pytest.mark.parametrize("design", ["turntable", "over_the_range", "drawer_model"])
def test_a_number_pad_with_function_keys_is_forced(design):
    """--set button_rows=4..6 grows a keypad of three columns (a number pad and function keys) where the
    panel holds it: every key a button pressing in along -X inside the panel's outline; a drawer model's
    strip holds four rows, a tall counter-top panel six."""
    over = dict(design=design, has_buttons=True, button_rows=6, height=0.34, has_knob=True, knob_count=1)
    p, bp = make(2, **over)
    keys = [j for j in movable(bp) if bp.parts[j.child].label == "button" and j.child != "door_release"]
    assert len(keys) == mw.key_count(p)
    assert len(keys) == (12 if design == "drawer_model" else 18) - (3 - p["bottom_keys"])
    panel = bp.parts["control_panel"].pieces[0].bounds
    for j in keys:
        assert j.dofs[0].axis == pytest.approx((-1, 0, 0))
        lo, hi = np.array([pc.bounds for pc in bp.parts[j.child].pieces]).transpose(1, 0, 2)
        assert (lo[:, 1:].min(0) > panel[0, 1:]).all() and (hi[:, 1:].max(0) < panel[1, 1:]).all()
    p, bp = make(2, **{**over, "button_rows": 3, "bottom_keys": 3})
    assert sum(bp.parts[j.child].label == "button" and j.child != "door_release" for j in movable(bp)) == 9


@pytest.mark.parametrize("design", ["turntable", "flatbed", "over_the_range"])
def test_a_combination_rack_stands_on_what_carries_it(design):
    """--set has_rack=true: a low wire rack fixed to the turntable (it turns with it, clear of the cavity at
    every angle) or to a flatbed's body, its legs on the tray's top."""
    p, bp = make(5, design=design, has_rack=True)
    rack = [j for j in bp.joints if j.child == "rack"]
    assert len(rack) == 1 and rack[0].kind == "fixed"
    assert rack[0].parent == ("body" if design == "flatbed" else "plate")
    lo, hi = np.array([pc.bounds for pc in bp.parts["rack"].pieces]).transpose(1, 0, 2)
    if design != "flatbed":  # on the glass tray's top face
        assert lo[:, 2].min() == pytest.approx(bp.parts["plate"].pieces[0].bounds[1][2], abs=1e-6)
        dof = by_child(bp, "plate").dofs[0]
        rest = others(bp, "plate")
        for q in (0.4, 1.1, 2.6):
            assert max_depth(group_hulls(bp, "plate", dof, q), rest) < TOUCH
    else:
        assert -2 * max_depth(hulls(bp.parts["rack"]), [h for n, part in bp.parts.items()
                                                         if n not in ("rack", "body") for h in hulls(part)]) > 0.0019
    _, bp = make(5, design=design, has_rack=False)
    assert "rack" not in bp.parts


def test_two_wide_keys_under_the_number_pad():
    """bottom_keys=2: the keypad's last row holds two keys over the span three take above."""
    p, bp = make(1, has_buttons=True, button_rows=3, bottom_keys=2, design="turntable")
    keys = [n for n in bp.parts if n.startswith("button_")]
    assert len(keys) == 8 == mw.key_count(p)
    width = {n: np.ptp(np.array(bp.parts[n].pieces[0].bounds)[:, 1]) for n in keys}
    assert {n for n in keys if n.startswith("button_2_")} == {"button_2_0", "button_2_1"}
    if p["button_shape"] == "rect":
        assert width["button_2_0"] > width["button_0_0"]
