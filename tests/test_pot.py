"""The pot category, checked on its blueprint (world space, grounded): parts, joints, clearances."""

from __future__ import annotations

import math

import numpy as np
import pytest

from infmob_usd.categories import pot
from infmob_usd.lift_off import LIFT_OFF
from infmob_usd.model import build as build_model

from collide import overlap
from helpers import maker
from zoo import make_bp

SEEDS = range(8)


# the plain design (a dome lid on the rim, no pasta insert, no steam vent) unless a test asks for another
make = maker("pot", pot_design="plain", has_pasta=False, has_vent=False)


def handle_pieces(bp):
    """The pot's handles: side loops are pieces of the body, a long handle and a helper are fixed parts."""
    out = [pc for pc in bp.parts["body"].pieces if pc.name == "handle"]
    for n in ("handle", "helper"):
        if n in bp.parts:
            out += bp.parts[n].pieces
    return out


def lift(dz, turn=0.0):
    c, s = math.cos(turn), math.sin(turn)
    m = np.eye(4)
    m[:2, :2] = [[c, -s], [s, c]]
    m[2, 3] = dz
    return m


def lowest(part, pose=None):
    pose = np.eye(4) if pose is None else pose
    pts = np.vstack([pc.vertices for pc in part.pieces])
    return float((pts @ pose[:3, :3].T + pose[:3, 3])[:, 2].min())


@pytest.mark.parametrize("seed", SEEDS)
def test_parts_labels_materials(seed):
    p, bp = make(seed)
    assert bp.root == "body"
    labels = {n: part.label for n, part in bp.parts.items()}
    want = {"body": "body", "lid": "lid"}
    want.update({"lid_knob": "knob"} if p["lid_handle"] == "knob" else {"lid_handle": "handle"})
    if p["handle_layout"] == "long_handle":
        want["handle"] = "handle"
        if p["has_helper"]:
            want["helper"] = "handle"
    assert labels == want
    assert handle_pieces(bp), "the pot has its handles"
    assert (p["handle_layout"] == "side_handles") == any(pc.name == "handle" for pc in bp.parts["body"].pieces)
    lid_top = "lid_knob" if p["lid_handle"] == "knob" else "lid_handle"
    j = next(j for j in bp.joints if j.child == lid_top)
    assert (j.parent, j.kind) == ("lid", "fixed")
    assert bp.materials["body"] == p["body_finish"]
    if p["lid_finish"] == "glass":
        assert any(pc.material == "glass" for pc in bp.parts["lid"].pieces)
    used = {pc.material for part in bp.parts.values() for pc in part.pieces}
    assert used <= set(bp.materials)
    for part in bp.parts.values():
        for pc in part.pieces:
            assert pc.convex and all(len(c) <= 255 for c in pc.convex)
    links, _ = build_model(bp, {k: 1000.0 for k in bp.materials})
    assert all(link.mass > 0 for link in links)


@pytest.mark.parametrize("seed", SEEDS)
def test_size_and_hollow(seed):
    p, bp = make(seed)
    lo, hi = np.array([pc.bounds for pc in bp.parts["body"].pieces if pc.name != "handle"]).transpose(1, 0, 2)
    size = hi.max(0) - lo.min(0)
    R = p["radius"]
    assert size[2] == pytest.approx(p["depth_ratio"] * R, abs=1e-6)
    assert R < size[0] / 2 < R + 0.01
    assert bp.bounds()[0, 2] == pytest.approx(0.0, abs=1e-9)
    # hollow: no collision hull of the body reaches the axis above the bottom
    for pc in bp.parts["body"].pieces:
        for c in pc.convex:
            if c[:, 2].min() > 0.02:
                assert np.linalg.norm(c[:, :2], axis=1).max() > 0.5 * R


@pytest.mark.parametrize("seed", SEEDS)
def test_lid_joint(seed):
    _, bp = make(seed)
    (j,) = [j for j in bp.joints if j.movable]
    assert j.kind == "continuous_prismatic" and (j.parent, j.child) == ("body", "lid") and j.role == "lift_off"
    slide, turn = j.dofs
    assert slide.axis == pytest.approx((0, 0, 1)) and turn.axis == pytest.approx((0, 0, 1))
    assert (slide.lower, slide.upper) == (0.0, pytest.approx(0.03))
    assert turn.origin[:2] == pytest.approx((0, 0)) and turn.type == "continuous"
    # the lid rests just above the rim (gravity holds it on its lower stop)
    rim = max(pc.bounds[1, 2] for pc in bp.parts["body"].pieces if pc.name != "handle")
    assert 0.001 <= lowest(bp.parts["lid"]) - rim <= 0.004
    assert slide.origin[2] == pytest.approx(lowest(bp.parts["lid"]), abs=1e-6)


@pytest.mark.parametrize("seed", SEEDS)
def test_lid_is_clear_along_its_motion(seed):
    _, bp = make(seed)
    body, lid = bp.parts["body"], bp.parts["lid"]
    # clear at rest with the 2 mm gap, and at every lift and turn
    assert overlap(lid, np.eye(4), body, np.eye(4), pad=0.0015) == 0.0
    for dz in (0.0, 0.01, 0.02, 0.03):
        for turn in (0.0, 1.3, -2.6):
            assert overlap(lid, lift(dz, turn), body, np.eye(4)) < 1e-9
            assert lowest(lid, lift(dz, turn)) > 0


def test_forced_handle_layouts_and_lid_handle_build_those_parts():
    """Forced handle layouts put the handles where they belong; a forced lid handle and finish give those parts
    (the generic contract: test_category_contract)."""
    _, bp = make(2, handle_layout="long_handle", has_helper=False)
    xs = np.vstack([pc.vertices for pc in bp.parts["handle"].pieces])
    assert xs[:, 0].min() > 0 and xs[:, 0].max() > 0.2  # one long handle toward +X
    assert "helper" not in bp.parts
    _, bp = make(2, handle_layout="long_handle", has_helper=True)
    assert np.vstack([pc.vertices for pc in bp.parts["helper"].pieces])[:, 0].max() < 0  # the helper at -X
    _, bp = make(2, handle_layout="side_handles")
    ys = np.vstack([pc.vertices for pc in bp.parts["body"].pieces if pc.name == "handle"])
    assert ys[:, 1].min() < 0 < ys[:, 1].max()
    assert "handle" not in bp.parts
    _, bp = make(2, lid_handle="loop", lid_finish="glass")
    assert sum(pc.name == "handle" for pc in bp.parts["lid_handle"].pieces) == 3
    assert bp.materials["glass"].startswith("glass")
    p, bp = make(2, radius=0.1, depth_ratio=2.0)
    assert bp.bounds()[1, 2] > 0.2


def test_handles_stay_below_the_rim_and_above_the_ground():
    for layout in ("side_handles", "long_handle"):
        for seed in range(6):
            _, bp = make(seed, handle_layout=layout, radius=0.08, depth_ratio=0.6)
            rim_bottom = max(pc.bounds[1, 2] for pc in bp.parts["body"].pieces if pc.name != "handle") - 0.006
            hs = handle_pieces(bp)
            lid_r = max(np.linalg.norm(np.vstack([pc.vertices for pc in bp.parts["lid"].pieces])[:, :2], axis=1))
            for pc in hs:
                near = np.linalg.norm(pc.vertices[:, :2], axis=1) <= lid_r + 0.005
                assert (pc.vertices[near, 2] < rim_bottom + 0.0001).all()
                assert pc.vertices[:, 2].min() > 0


def test_variety():
    params = [make(s)[0] for s in range(20)]
    for name in ("handle_layout", "lid_handle", "body_finish", "lid_finish"):
        assert len({q[name] for q in params}) > 1, name


@pytest.mark.parametrize("seed", range(4))
def test_steamer_tiers_stack_and_lift_with_the_lid_on_top(seed):
    _, bp = make(seed, pot_design="steamer")
    tiers = sorted(n for n in bp.parts if n.startswith("tier"))
    assert 1 <= len(tiers) <= 2 and all(bp.parts[t].label == "insert" for t in tiers)
    parent = "body"
    for t in tiers:
        j = next(j for j in bp.joints if j.child == t)
        assert j.kind == "prismatic" and j.parent == parent and j.dofs[0].axis == pytest.approx((0, 0, 1))
        assert overlap(bp.parts[t], np.eye(4), bp.parts[parent], np.eye(4), pad=0.001) == 0.0
        parent = t
    lid = next(j for j in bp.joints if j.child == "lid")
    assert lid.parent == tiers[-1] and lid.kind == "continuous_prismatic"


@pytest.mark.parametrize("seed", range(4))
def test_pressure_lid_turns_to_unlock_and_lifts_with_valve_and_lock(seed):
    _, bp = make(seed, pot_design="pressure")
    j = next(j for j in bp.joints if j.child == "lid")
    assert j.kind == "revolute_prismatic" and j.parent == "body"
    slide, turn = j.dofs
    assert slide.axis == pytest.approx((0, 0, 1)) and turn.axis == pytest.approx((0, 0, 1))
    assert 0.4 < turn.upper < 0.8
    kinds = {j.child: (j.parent, j.kind) for j in bp.joints}
    assert kinds["valve"] == ("lid", "continuous") and kinds["lock"] == ("lid", "prismatic")
    assert bp.parts["lock"].label == "button" and bp.parts["valve"].label == "valve"


def test_designs_vary():
    designs = {make_bp(pot, "pot", s)[0]["pot_design"] for s in range(20)}
    assert designs == {"plain", "steamer", "pressure"}


def test_steamer_tiers_one_or_two_and_light():
    """Tiers vary 1..2 over seeds; a tier is pressed 0.8 mm sheet: 0.15-2 kg of steel at any size
    (at the pot's clad wall they would weigh 2-4 kg)."""
    from infmob_usd.mass import inertial

    counts = set()
    for seed in range(30):
        _, bp = make(seed, pot_design="steamer")
        tiers = [n for n in bp.parts if n.startswith("tier")]
        counts.add(len(tiers))
        for t in tiers:
            kg = inertial((pc, 7900.0, 0.0) for pc in bp.parts[t].pieces)[0]
            assert 0.15 < kg < 2.0, (seed, t, kg)  # the insert row of mass_ranges.csv: 0.1-2.0
    assert counts == {1, 2}


@pytest.mark.parametrize("seed", range(3))
def test_steam_vent_turns_on_the_lid(seed):
    _, bp = make(seed, has_vent=True)
    j = next(j for j in bp.joints if j.child == "vent")
    assert (j.parent, j.kind, j.role) == ("lid", "revolute", "knob")
    assert j.dofs[0].axis == pytest.approx((0, 0, 1), abs=0.3) and j.dofs[0].upper == pytest.approx(math.pi / 2)
    assert bp.parts["vent"].label == "vent"
    vent = bp.parts["vent"]
    # on the dome, clear of the lid at rest and turned
    assert overlap(vent, np.eye(4), bp.parts["lid"], np.eye(4)) < 1e-9
    assert lowest(vent) > lowest(bp.parts["lid"])


@pytest.mark.parametrize("seed", range(3))
def test_pasta_insert_hangs_in_the_pot_and_lifts_with_the_lid_on_it(seed):
    p, bp = make(seed, has_pasta=True)
    j = next(j for j in bp.joints if j.child == "pasta")
    assert (j.parent, j.kind) == ("body", "prismatic") and bp.parts["pasta"].label == "basket"
    assert j.dofs[0].axis == pytest.approx((0, 0, 1))
    basket, body = bp.parts["pasta"], bp.parts["body"]
    depth = lowest(basket)
    rim = max(pc.bounds[1, 2] for pc in body.pieces if pc.name != "handle")
    assert rim - depth > 0.5 * min(p["pasta_reach"] * p["depth_ratio"] * p["radius"], 0.2)  # it reaches down
    assert j.dofs[0].upper == pytest.approx(LIFT_OFF) and j.role == "lift_off"  # and lifts a hand's lift
    assert overlap(basket, np.eye(4), body, np.eye(4), pad=0.001) == 0.0
    assert next(j for j in bp.joints if j.child == "lid").parent == "pasta"
