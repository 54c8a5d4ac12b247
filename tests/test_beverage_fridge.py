"""The beverage_fridge category: parts, joints, clearances at joint states, overrides, seeds."""

from __future__ import annotations

import math

import numpy as np
import pytest

from infmob_usd.model import build as build_model

from collide import contacts, overlap
from helpers import maker
from zoo import by_child, movable

SEEDS = range(6)
VOL = 1e-7  # m^3: the validators' contact volume


# a glass-door cooler unless ``design`` says otherwise (the tests below check its glass door, racks or divider;
# the other designs have their own tests at the end)
make = maker("beverage_fridge", design="glass_cooler")


def at(j, f):
    """Value of a (one-DoF) joint at fraction ``f``; states are ``Blueprint.poses`` keys ``(child, 0)``."""
    return j.dofs[0].lower + f * (j.dofs[0].upper - j.dofs[0].lower)


def opened(bp, q):
    """``q`` with the door fully open when a rack behind it moves (as the validator does)."""
    out = dict(q)
    for j in bp.joints:
        if j.requires_open and q.get((j.child, 0), 0.0) != 0.0:
            out[(j.requires_open, 0)] = by_child(bp, j.requires_open).dofs[0].upper
    return out


# -- parts, labels, materials -------------------------------------------------------


@pytest.mark.parametrize("seed", SEEDS)
def test_parts_labels_and_materials(seed):
    p, bp = make(seed)
    assert bp.root == "body"
    assert bp.parts["body"].label == "body" and bp.parts["door"].label == "door"
    assert {part.label for part in bp.parts.values()} <= {"body", "door", "rack", "shelf", "button"}
    door = bp.parts["door"].pieces
    assert any(pc.material == "glass" for pc in door) and bp.materials["glass"].startswith("glass")
    assert sum(pc.name == "handle" for pc in door) >= 1
    used = {pc.material for part in bp.parts.values() for pc in part.pieces}
    assert used <= set(bp.materials)
    racks = [n for n, part in bp.parts.items() if part.label in ("rack", "shelf") and n.startswith("rack_")]
    if p["interior"] == "racks":
        assert len(racks) == p["rack_count"] and 3 <= len(racks) <= 5
    else:
        assert not racks and bp.parts["divider"].label == "shelf"
    links, _ = build_model(bp, {k: 1000.0 for k in bp.materials})
    assert all(link.mass > 0 for link in links)


@pytest.mark.parametrize("seed", SEEDS)
def test_size_and_hollow_cavity(seed):
    p, bp = make(seed)
    lo, hi = bp.bounds()
    assert lo[2] == pytest.approx(0.0, abs=1e-9)
    assert hi[2] == pytest.approx(p["height"], abs=1e-6)
    assert hi[1] - lo[1] == pytest.approx(p["width"], abs=1e-6)
    # the cavity is hollow: its centre is inside no collision hull of the body
    liner = np.array([pc.bounds for pc in bp.parts["body"].pieces if pc.material == "liner"])
    centre = (liner[:, 0].min(0) + liner[:, 1].max(0)) / 2
    for pc in bp.parts["body"].pieces:
        for c in pc.convex:
            assert not ((c.min(0) < centre) & (centre < c.max(0))).all()


# -- joints ------------------------------------------------------------------------


@pytest.mark.parametrize("seed", SEEDS)
def test_joint_kinds_axes_limits(seed):
    p, bp = make(seed)
    door = by_child(bp, "door")
    d = door.dofs[0]
    assert door.kind == "revolute" and door.parent == "body"
    assert (d.lower, d.upper) == (0.0, pytest.approx(math.pi / 2))
    frame = np.array([pc.bounds for pc in bp.parts["door"].pieces if pc.name != "handle"])
    assert d.origin[0] == pytest.approx(frame[:, 1, 0].max())
    if p["hinge_side"] == "left":
        assert d.axis == pytest.approx((0, 0, -1)) and d.origin[1] == pytest.approx(frame[:, 0, 1].min())
    else:
        assert d.axis == pytest.approx((0, 0, 1)) and d.origin[1] == pytest.approx(frame[:, 1, 1].max())
    for j in movable(bp):
        # racks are behind the door: they slide once it is open
        assert j.requires_open == ("door" if j.child.startswith("rack_") else None), j.child
        if j.child.startswith("rack_"):
            r = j.dofs[0]
            assert j.kind == "prismatic" and j.parent == "body"
            assert r.axis == pytest.approx((1, 0, 0)) and r.lower == 0.0
            b = np.array([pc.bounds for pc in bp.parts[j.child].pieces])
            assert r.upper == pytest.approx(p["rack_travel"] * (b[:, 1, 0].max() - b[:, 0, 0].min()), rel=1e-6)
    keys = sum(bp.parts[j.child].label == "button" for j in movable(bp))  # the control strip's push keys
    assert keys == (p["key_count"] if p["has_control_panel"] else 0)
    assert 1 <= len(movable(bp)) - keys <= 6


def test_door_opens_outward():
    for side in ("left", "right"):
        _, bp = make(0, hinge_side=side)
        j = by_child(bp, "door")
        pose = bp.poses({("door", 0): math.pi / 2})["door"]
        pts = np.vstack([pc.vertices for pc in bp.parts["door"].pieces])
        moved = pts @ pose[:3, :3].T + pose[:3, 3]
        assert moved[:, 0].max() > pts[:, 0].max() + 0.3  # swung out to the front
        assert j.dofs[0].origin[1] * (1 if side == "right" else -1) > 0


# -- clearances ----------------------------------------------------------------------


@pytest.mark.parametrize("seed", SEEDS)
def test_no_contacts_at_rest_and_sampled_states(seed):
    _, bp = make(seed, interior="racks")
    js = movable(bp)
    states = [{}]
    states += [{(j.child, 0): at(j, f) for j in js} for f in (0.5, 1.0)]
    states += [{(j.child, 0): at(j, f)} for j in js for f in (0.25, 0.5, 1.0)]
    for q in states:
        assert not contacts(bp, opened(bp, q)), q


@pytest.mark.parametrize("side", ["left", "right"])
@pytest.mark.parametrize("seed", [0, 3])
def test_the_door_is_solid(seed, side):
    """Frame, both glass panes and the gasket collide, covering the whole door face: a rack pulled
    out through the shut door meets it (open it first); with the door open it is free."""
    _, bp = make(seed, interior="racks", hinge_side=side)
    door = [pc for pc in bp.parts["door"].pieces if pc.name != "handle"]
    assert all(pc.convex for pc in door)
    assert sum(pc.material == "glass" for pc in door) == 2 and any(pc.material == "gasket" for pc in door)
    lo = np.min([pc.bounds[0] for pc in door], axis=0)
    hi = np.max([pc.bounds[1] for pc in door], axis=0)
    hulls = np.array([[c.min(0), c.max(0)] for pc in door for c in pc.convex])
    for y in np.linspace(lo[1] + 0.002, hi[1] - 0.002, 13):
        for z in np.linspace(lo[2] + 0.002, hi[2] - 0.002, 13):
            inside = (hulls[:, 0, 1] <= y) & (y <= hulls[:, 1, 1]) & (hulls[:, 0, 2] <= z) & (z <= hulls[:, 1, 2])
            assert inside.any(), (y, z)
    for j in movable(bp):
        if j.child.startswith("rack_"):
            hit = {frozenset((a, b)) for a, b, _ in contacts(bp, {(j.child, 0): at(j, 1.0)})}
            assert hit and all("door" in pair for pair in hit), hit
            # the open door stands at the hinge side, clear of the pulled-out rack
            assert not contacts(bp, opened(bp, {(j.child, 0): at(j, 1.0)}))
            assert not contacts(bp, {(j.child, 0): at(j, 1.0), ("door", 0): math.pi / 2})


@pytest.mark.parametrize("seed", SEEDS)
def test_moving_parts_do_not_enter_their_parent(seed):
    _, bp = make(seed)
    body = bp.parts["body"]
    for j in movable(bp):
        for f in (0.0, 0.5, 1.0):
            pose = bp.poses({(j.child, 0): at(j, f)})[j.child]
            assert overlap(bp.parts[j.child], pose, body, np.eye(4)) < VOL, (j.child, f)
        # and keep a gap at rest
        assert overlap(bp.parts[j.child], np.eye(4), body, np.eye(4), pad=0.001) < VOL


@pytest.mark.parametrize("seed", SEEDS)
def test_nothing_below_ground(seed):
    _, bp = make(seed)
    js = movable(bp)
    for q in [{(j.child, 0): at(j, 1.0) for j in js}, *({(j.child, 0): at(j, 1.0)} for j in js)]:
        pose = bp.poses(opened(bp, q))
        for name, part in bp.parts.items():
            pts = np.vstack([pc.vertices for pc in part.pieces])
            assert (pts @ pose[name][:3, :3].T + pose[name][:3, 3])[:, 2].min() >= -1e-6


# -- overrides, growth, determinism ------------------------------------------------------


def test_forced_racks_divider_and_panel_build_those_parts():
    """Forced rack counts and styles, the divider and the control panel build exactly those parts (the generic
    override contract is test_category_contract.test_overrides_drive_the_growth)."""
    _, bp = make(1, interior="racks", rack_count=5, rack_style="glass")
    assert sorted(n for n in bp.parts if n.startswith("rack_")) == [f"rack_{k}" for k in range(5)]
    assert all(bp.parts[f"rack_{k}"].label == "shelf" for k in range(5))
    _, bp = make(1, interior="racks", rack_count=3, rack_style="wire")
    assert all(bp.parts[f"rack_{k}"].label == "rack" for k in range(3))
    _, bp = make(1, interior="divider")
    assert len(movable(bp)) == 1 and "divider" in bp.parts
    _, a = make(2, has_control_panel=False)
    _, b = make(2, has_control_panel=True)
    assert a.bounds()[1, 2] == pytest.approx(b.bounds()[1, 2])
    assert len(b.parts["body"].pieces) > len(a.parts["body"].pieces)
    p, _ = make(2, width=0.6, handle_style="recessed")
    assert p["width"] == 0.6 and p["handle_style"] == "recessed"


def test_seeds_differ():
    params = [make(s)[0] for s in range(20)]
    for name in ("hinge_side", "handle_style", "interior", "rack_style", "has_control_panel", "body_finish"):
        assert len({p[name] for p in params}) > 1, name


# -- designs -------------------------------------------------------------------------------------


@pytest.mark.parametrize("design", ["glass_cooler", "undercounter", "wine", "dual_zone"])
def test_each_design_is_forced_and_has_its_mechanism(design):
    """``--set design=...`` forces a design; each has its own structure and moving parts, all free at rest
    and with every joint (doors first) open."""
    p, bp = make(7, design=design, interior="racks", rack_count=4, right_rack_count=4, bin_count=3, crisper_count=2,
                 has_freezer=False)
    assert p["design"] == design
    doors = sorted(n for n, part in bp.parts.items() if part.label == "door")
    assert doors == (["door", "right_door"] if design == "dual_zone" else ["door"])
    racks = [n for n, part in bp.parts.items() if part.label in ("rack", "shelf")]
    want = {"glass_cooler": 4, "undercounter": 2, "wine": 7, "dual_zone": 2 * 3}[design]
    assert len(racks) == want
    for n in racks:  # every rack slides out through its own door
        j = by_child(bp, n)
        assert j.kind == "prismatic" and j.requires_open == ("right_door" if n.startswith("right_") else "door")
    if design == "undercounter":  # bins ride on the door and lift off it; crispers slide out on the floor
        bins = [n for n, part in bp.parts.items() if part.label == "bin"]
        assert len(bins) == 3 and all(by_child(bp, n).parent == "door" for n in bins)
        assert all(by_child(bp, n).dofs[0].axis == pytest.approx((0, 0, 1)) for n in bins)
        crispers = [n for n, part in bp.parts.items() if part.label == "drawer"]
        assert len(crispers) == 2 and all(by_child(bp, n).requires_open == "door" for n in crispers)
        assert not any(pc.material == "glass" for pc in bp.parts["door"].pieces)  # a solid door
    if design == "wine":  # wooden shelf fronts, undercounter height
        assert all(any(pc.material == "wood" for pc in bp.parts[n].pieces) for n in racks)
        assert 0.82 <= bp.bounds()[1][2] <= 0.88
    if design == "dual_zone":  # two doors hinged on the outer sides, both swing out
        left, right = by_child(bp, "door").dofs[0], by_child(bp, "right_door").dofs[0]
        assert left.origin[1] < 0 < right.origin[1]
    assert contacts(bp, {}) == []


def test_control_keys_freezer_flap_and_zone_counts_are_forced():
    """--set forces the control strip's 2-5 push keys (pressing in along -X), an undercounter fridge's freezer
    flap (hinged at its top, swinging up only with the door open) and a dual-zone cooler's right zone count."""
    p, bp = make(3, design="undercounter", has_control_panel=True, key_count=5, has_freezer=True)
    keys = [j for j in movable(bp) if bp.parts[j.child].label == "button"]
    assert len(keys) == 5 and all(j.parent == "body" and j.dofs[0].axis == pytest.approx((-1, 0, 0)) for j in keys)
    flap = by_child(bp, "freezer_flap")
    assert flap.kind == "revolute" and flap.requires_open == "door" and bp.parts["freezer_flap"].label == "flap"
    assert flap.dofs[0].axis == pytest.approx((0, -1, 0)) and flap.dofs[0].upper == pytest.approx(math.pi / 2)
    flap_lo = min(pc.bounds[0, 2] for pc in bp.parts["freezer_flap"].pieces)
    shelves = [n for n, part in bp.parts.items() if part.label in ("rack", "shelf")]
    assert shelves and max(pc.bounds[1, 2] for n in shelves for pc in bp.parts[n].pieces) < flap_lo
    q = {("door", 0): by_child(bp, "door").dofs[0].upper, ("freezer_flap", 0): math.pi / 2}
    assert not contacts(bp, q)
    _, bp = make(3, design="undercounter", has_control_panel=False, has_freezer=False)
    assert "freezer_flap" not in bp.parts and not any(part.label == "button" for part in bp.parts.values())
    _, bp = make(3, design="dual_zone", rack_count=5, right_rack_count=3)
    assert sum(n.startswith("rack_") for n in bp.parts) == 4 and sum(n.startswith("right_rack_") for n in bp.parts) == 2
