"""The door category: frame on the floor, leaf hinge side and swing, handles on both faces, clearances."""

from __future__ import annotations

import math

import numpy as np
import pytest

from infmob_usd.api import generate
from infmob_usd.blueprint import dof_motion
from infmob_usd.categories import door as mod
from infmob_usd.model import build as build_model
from infmob_usd.physical import gravity_torque

from collide import contacts, overlap
from helpers import labelled_states, maker
from zoo import by_child, make_bp, movable

SEEDS = range(8)
VOLUME_TOL = 1e-7  # m^3, as the physics checks


# a single unlatched leaf unless the test asks for another design (the tests below were written for it)
make = maker("door", design="single", has_latch=False, has_thumb_turn=False, has_letter_plate=False, has_viewer=False)


def leaf_body(bp):
    """Bounds of the leaf without handles and hinge knuckles."""
    pcs = [pc for pc in bp.parts["leaf"].pieces if pc.name != "handle" and pc.material not in ("handle", "hinge")]
    b = np.array([pc.bounds for pc in pcs])
    return b[:, 0].min(0), b[:, 1].max(0)


# -- parts, sizes ----------------------------------------------------------------------


@pytest.mark.parametrize("seed", SEEDS)
def test_parts_labels_and_size(seed):
    p, bp = make(seed)
    assert bp.root == "frame" and bp.parts["frame"].label == "frame"
    assert bp.parts["leaf"].label == "leaf"
    lo, hi = leaf_body(bp)
    size = hi - lo
    assert size[0] == pytest.approx(p["leaf_thickness"]) and 0.04 <= size[0] <= 0.06
    assert size[1] == pytest.approx(p["leaf_width"]) and 0.8 <= size[1] <= 1.0
    assert size[2] == pytest.approx(p["leaf_height"]) and 2.0 <= size[2] <= 2.1
    frame = np.array([pc.bounds for pc in bp.parts["frame"].pieces])
    assert frame[:, 0, 2].min() == pytest.approx(0.0, abs=1e-9)  # on the floor
    assert lo[2] > 0.005  # the leaf clears the floor / threshold
    f_lo, f_hi = frame[:, 0].min(0), frame[:, 1].max(0)
    assert abs(f_lo[0] + f_hi[0]) < 0.01 and abs(f_lo[1] + f_hi[1]) < 0.01  # at x = 0, centred
    used = {pc.material for part in bp.parts.values() for pc in part.pieces}
    assert used <= set(bp.materials)
    links, _ = build_model(bp, {k: 700.0 for k in bp.materials})
    assert all(link.mass > 0 for link in links)


@pytest.mark.parametrize("seed", SEEDS)
def test_leaf_hinge(seed):
    p, bp = make(seed)
    j = by_child(bp, "leaf")
    d = j.dofs[0]
    assert j.kind == "revolute" and j.parent == "frame"
    assert (d.lower, d.upper) == (0.0, pytest.approx(math.pi / 2))
    lo, hi = leaf_body(bp)
    left = p["hinge_side"] == "left"
    assert d.axis == pytest.approx((0, 0, -1) if left else (0, 0, 1))
    assert d.origin[0] == pytest.approx(hi[0])  # front face
    assert d.origin[1] == pytest.approx(lo[1] if left else hi[1])  # hinge edge
    # opening moves the free edge toward +X
    free = np.array([hi[0], hi[1] if left else lo[1], 1.0, 1.0])
    assert (dof_motion(d, 0.5) @ free)[0] > free[0] + 0.3


@pytest.mark.parametrize("seed", SEEDS)
def test_handles_on_both_faces(seed):
    p, bp = make(seed)
    lo, hi = leaf_body(bp)
    kind = p["handle"]
    if kind == "pull":
        xs = [pc.bounds[:, 0].mean() for pc in bp.parts["leaf"].pieces if pc.name == "handle"]
        assert max(xs) > hi[0] and min(xs) < lo[0]
        assert len(movable(bp)) == 1
        return
    names = [f"{kind}_front", f"{kind}_back"]
    for name in names:
        j = by_child(bp, name)
        d = j.dofs[0]
        assert j.parent == "leaf" and bp.parts[name].label == kind
        assert abs(d.axis[0]) == pytest.approx(1.0)
        if kind == "knob":
            assert j.kind == "continuous"
        else:
            assert j.kind == "revolute" and (d.lower, d.upper) == (0.0, pytest.approx(math.pi / 4))
    front, back = (by_child(bp, n).dofs[0].origin for n in names)
    assert front[0] > hi[0] and back[0] < lo[0]
    assert len(movable(bp)) == 3
    # in the object, the core's counterweight puts the centre of mass on the axis: gravity does
    # not turn the handle
    obj = generate("door", seed, 16, design="single", has_latch=False, has_thumb_turn=False)
    for name in names:
        torque, _, _ = gravity_torque(obj.links, obj.joints, next(j for j in obj.joints if j.child == name))
        assert abs(torque) < 1e-6


def test_lever_grip_turns_down():
    for side in ("left", "right"):
        _, bp = make(1, handle="lever", hinge_side=side)
        for name in ("lever_front", "lever_back"):
            d = by_child(bp, name).dofs[0]
            part = bp.parts[name]
            grip = max((pc for pc in part.pieces), key=lambda pc: np.ptp(pc.bounds[:, 1]))
            tip_y = grip.bounds[1, 1] if abs(grip.bounds[1, 1] - d.origin[1]) > abs(grip.bounds[0, 1] - d.origin[1]) \
                else grip.bounds[0, 1]
            tip = np.array([d.origin[0], tip_y, d.origin[2], 1.0])
            assert (dof_motion(d, 0.4) @ tip)[2] < d.origin[2] - 0.02
            # the grip points toward the hinge side
            hinge_y = by_child(bp, "leaf").dofs[0].origin[1]
            assert abs(tip_y - hinge_y) < abs(d.origin[1] - hinge_y)


# -- clearances ----------------------------------------------------------------------


@pytest.mark.parametrize("seed", [0, 1, 2, 3, 4, 5])
def test_no_overlap_at_sampled_states(seed):
    _, bp = make(seed)
    for label, q in labelled_states(bp):
        bad = contacts(bp, q, VOLUME_TOL)
        assert not bad, f"(part, part, m^3) overlapping at {label}: {bad}"


@pytest.mark.parametrize("seed", SEEDS)
def test_leaf_swing_never_enters_the_frame(seed):
    _, bp = make(seed)
    d = by_child(bp, "leaf").dofs[0]
    for f in np.linspace(0, 1, 9):
        m = dof_motion(d, f * d.upper)
        assert overlap(bp.parts["leaf"], m, bp.parts["frame"], np.eye(4)) < VOLUME_TOL, f"at {f:.0%}"


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_handles_clear_the_leaf(seed):
    _, bp = make(seed, handle=["knob", "lever", "knob"][seed])
    for j in movable(bp):
        if j.parent != "leaf":
            continue
        d = j.dofs[0]
        for q in (0.0, d.upper, -1.0 if j.kind == "continuous" else d.upper / 2):
            v = overlap(bp.parts[j.child], dof_motion(d, q), bp.parts["leaf"], np.eye(4))
            assert v < VOLUME_TOL


# -- growth, overrides, determinism ------------------------------------------------------


def test_overrides_drive_the_styles():
    _, bp = make(2, leaf_style="raised", panel_count=6, glazing="none", handle="knob")
    leaf = bp.parts["leaf"].pieces
    assert sum(1 for pc in leaf if pc.material == "leaf") == 1 + 2 * 6  # frame + board & field
    assert not any(pc.material == "glass" for pc in leaf)
    assert {"knob_front", "knob_back"} <= set(bp.parts)
    _, bp = make(2, leaf_style="recessed", panel_count=4, glazing="full")
    assert sum(1 for pc in bp.parts["leaf"].pieces if pc.material == "glass") == 4
    _, bp = make(2, leaf_style="flat", glazing="none", handle="pull", has_threshold=False, has_kick_plate=False)
    assert len(bp.parts) == 1 + 1 and not movable(bp)[1:]
    _, bp = make(2, has_threshold=True)
    assert min(pc.bounds[0, 2] for pc in bp.parts["leaf"].pieces) > 0.02
    p, _ = make(2, leaf_width=0.9, hinge_side="right")
    assert p["leaf_width"] == 0.9 and p["hinge_side"] == "right"


def test_latch_bolt_sits_in_the_strike_and_draws_back():
    for side in ("left", "right"):
        p, bp = make(4, has_latch=True, hinge_side=side)
        j, leaf = by_child(bp, "latch"), by_child(bp, "leaf")
        assert j.kind == "prismatic" and j.parent == "leaf" and leaf.requires_open == "latch"
        d = j.dofs[0]
        lo, hi = leaf_body(bp)
        bolt = np.array([pc.bounds for pc in bp.parts["latch"].pieces])
        out = 1.0 if side == "left" else -1.0
        edge = hi[1] if side == "left" else lo[1]
        tip = bolt[:, 1, 1].max() if out > 0 else bolt[:, 0, 1].min()
        assert out * (tip - edge) >= 0.012  # thrown into the jamb at rest
        assert d.axis == pytest.approx((0, -out, 0)) and d.upper > 0.013
        for q in (0.0, d.upper / 2, d.upper):  # in its mortise and the strike, touching nothing
            m = dof_motion(d, q)
            assert overlap(bp.parts["latch"], m, bp.parts["leaf"], np.eye(4)) < VOLUME_TOL
            assert overlap(bp.parts["latch"], m, bp.parts["frame"], np.eye(4)) < VOLUME_TOL
        back = bolt[:, 1, 1].max() - d.upper if out > 0 else bolt[:, 0, 1].min() + d.upper
        assert out * (back - edge) < 0  # drawn back inside the leaf


@pytest.mark.parametrize("design", ["single", "double", "sliding"])
def test_each_design_is_forced_and_moves(design):
    p, bp = make(6, design=design, has_latch=True, has_thumb_turn=True, handle="lever")
    assert p["design"] == design
    kinds = {j.child: j.kind for j in movable(bp)}
    if design == "double":
        assert kinds["leaf"] == kinds["leaf_2"] == "revolute"
        a, b = by_child(bp, "leaf").dofs[0], by_child(bp, "leaf_2").dofs[0]
        assert a.origin[1] < 0 < b.origin[1] and a.axis[2] == -b.axis[2]  # hung on both jambs
        assert {"lever_front_2", "thumb_turn_2"} <= set(kinds)
    elif design == "sliding":
        d = by_child(bp, "leaf").dofs[0]
        assert kinds["leaf"] == "prismatic" and abs(d.axis[1]) == pytest.approx(1.0) and d.upper > 0.5
        assert kinds["wheel_0"] == kinds["wheel_1"] == "continuous"
        assert all(by_child(bp, w).parent == "leaf" for w in ("wheel_0", "wheel_1"))
    else:
        assert kinds["latch"] == "prismatic" and kinds["thumb_turn"] == "revolute"
    for label, q in labelled_states(bp):
        if design == "single" and ("leaf", 0) in q:  # the leaf moves with its latch drawn back
            q = {**q, ("latch", 0): by_child(bp, "latch").dofs[0].upper}
        bad = contacts(bp, q, VOLUME_TOL)
        assert not bad, f"(part, part, m^3) overlapping at {label}: {bad}"


def test_seeds_differ():
    params = [make_bp(mod, "door", s)[0] for s in range(12)]
    for name in ("design", "handle", "leaf_style", "hinge_side", "glazing"):
        assert len({p[name] for p in params}) > 1, name


def test_thumb_turn_clears_a_bar_pull():
    """The thumb-turn sits above a long bar pull's top post (door seed 8 had it embedded in the pull)."""
    _, bp = make(8, design="single", handle="pull", has_thumb_turn=True, pull_length=0.45)
    d = by_child(bp, "thumb_turn").dofs[0]
    for q in (0.0, d.upper):
        assert overlap(bp.parts["thumb_turn"], dof_motion(d, q), bp.parts["leaf"], np.eye(4)) < VOLUME_TOL


@pytest.mark.parametrize("seed", [0, 3, 6])
def test_letter_plate_flap_swings_in_through_the_leaf(seed):
    """The letter plate's flap hangs in its opening, turns in about +y through the cut in the leaf without
    touching it, and gravity holds it closed (its centre of mass inward of the pin)."""
    p, bp = make(seed, has_letter_plate=True, glazing="none")
    j = by_child(bp, "letter_flap")
    d = j.dofs[0]
    assert j.parent == "leaf" and j.kind == "revolute" and bp.parts["letter_flap"].label == "flap"
    assert d.axis[1] == pytest.approx(1.0) and d.upper > 1.3
    lo, hi = leaf_body(bp)
    assert 0.7 < d.origin[2] < p["handle_height"] - 0.2 and d.origin[0] > hi[0]
    for q in (0.0, 0.5 * d.upper, d.upper):
        assert overlap(bp.parts["letter_flap"], dof_motion(d, q), bp.parts["leaf"], np.eye(4)) < VOLUME_TOL
    # pushed in, the flap's bottom edge goes into the leaf (toward -x)
    tip = np.array([d.origin[0], d.origin[1], d.origin[2] - 0.03, 1.0])
    assert (dof_motion(d, 1.0) @ tip)[0] < d.origin[0] - 0.02
    links, joints = build_model(bp, {k: 700.0 for k in bp.materials})
    jm = next(jj for jj in joints if jj.child == "letter_flap")
    assert gravity_torque(links, joints, jm)[0] < 0  # pressed onto its closed stop


@pytest.mark.parametrize("seed", [1, 4])
def test_viewer_cover_swings_aside(seed):
    """A door viewer at eye height; its privacy cover hangs over the eyepiece on the back face and swings
    aside about the leaf normal without entering the leaf."""
    _, bp = make(seed, has_viewer=True, glazing="none")
    j = by_child(bp, "viewer_cover")
    d = j.dofs[0]
    assert j.parent == "leaf" and j.kind == "revolute" and abs(d.axis[0]) == pytest.approx(1.0)
    lo, hi = leaf_body(bp)
    assert 1.4 <= d.origin[2] <= 1.6 and d.origin[0] < lo[0]
    for q in (0.0, d.upper):
        assert overlap(bp.parts["viewer_cover"], dof_motion(d, q), bp.parts["leaf"], np.eye(4)) < VOLUME_TOL


def test_entrance_options_forced_and_glazing_rules():
    """Letter plate and viewer are forced by their flags on a single leaf; a fully glazed leaf takes no
    letter plate and a glazed one no viewer; a kick plate and a threshold are their own fixed parts."""
    _, bp = make(2, has_letter_plate=True, has_viewer=True, glazing="none", has_kick_plate=True,
                 has_threshold=True)
    names = {j.child for j in movable(bp)}
    assert {"letter_flap", "viewer_cover"} <= names
    assert by_child(bp, "kick_plate").kind == "fixed" and by_child(bp, "threshold").kind == "fixed"
    _, bp = make(2, has_letter_plate=True, has_viewer=True, glazing="full")
    assert "letter_flap" not in bp.parts and "viewer_cover" not in bp.parts


def test_barn_door_floor_guide_straddles_the_leaf():
    """A sliding leaf's floor guide stands on the floor with the leaf's bottom edge between its fins, at rest
    and slid open."""
    _, bp = make(5, design="sliding", has_guide=True, guide_style="floor_guide", has_kick_plate=True)
    d = by_child(bp, "leaf").dofs[0]
    for q in (0.0, d.upper):
        assert overlap(bp.parts["floor_guide"], np.eye(4), bp.parts["leaf"], dof_motion(d, q)) < VOLUME_TOL
        assert overlap(bp.parts["floor_guide"], np.eye(4), bp.parts["kick_plate"], dof_motion(d, q)) < VOLUME_TOL
    g_lo = np.array([pc.bounds for pc in bp.parts["floor_guide"].pieces])[:, 0].min(0)
    assert g_lo[2] == pytest.approx(0.0, abs=1e-6)


def test_barn_door_stay_roller_runs_on_the_leaf_face():
    """A stay roller (a continuous wheel on the frame, about the vertical) sits in front of the leaf's bottom
    edge, over the floor, and stays clear of the leaf and its kick plate through the whole slide."""
    for side in ("left", "right"):
        _, bp = make(5, design="sliding", has_guide=True, guide_style="stay_roller", has_kick_plate=True,
                     hinge_side=side)
        j = by_child(bp, "stay_roller")
        assert j.kind == "continuous" and j.parent == "frame" and j.dofs[0].axis == pytest.approx((0, 0, 1))
        assert bp.parts["stay_roller"].label == "wheel"
        lo, hi = leaf_body(bp)
        r_lo = np.array([pc.bounds for pc in bp.parts["stay_roller"].pieces])[:, 0].min(0)
        assert hi[0] < r_lo[0] < hi[0] + 0.01 and 0.0 < r_lo[2] < lo[2] + 0.03  # at the leaf's face, low
        d = by_child(bp, "leaf").dofs[0]
        for q in np.linspace(0.0, d.upper, 5):
            for other in ("leaf", "kick_plate"):
                assert overlap(bp.parts["stay_roller"], np.eye(4), bp.parts[other], dof_motion(d, q)) < VOLUME_TOL
                assert overlap(bp.parts["frame"], np.eye(4), bp.parts[other], dof_motion(d, q)) < VOLUME_TOL
            # the roller is behind the leaf wherever it slides (its y within the leaf's span)
            shift = dof_motion(d, q)[1, 3]
            assert lo[1] + shift < j.dofs[0].origin[1] < hi[1] + shift


@pytest.mark.parametrize("seed", (3, 6))
def test_dutch_door_halves_open_alone(seed):
    """A Dutch door: two halves on one hinge line, cut above the bottom half's handles; each opens on its own
    without touching the other; the bottom half has the handles, the top half its deadbolt's thumb-turn."""
    p, bp = make(seed, design="dutch", has_deadbolt=True, handle="lever")
    lo, hi = (np.array([pc.bounds for pc in bp.parts[n].pieces if pc.material == "leaf"]) for n in ("leaf", "leaf_2"))
    bottom_top, top_bottom = lo[:, 1, 2].max(), hi[:, 0, 2].min()
    assert 0.002 < top_bottom - bottom_top < 0.01  # a cut a few mm wide
    assert bottom_top > p["handle_height"] + 0.05 and bottom_top >= 1.0
    a, b = by_child(bp, "leaf").dofs[0], by_child(bp, "leaf_2").dofs[0]
    assert a.origin[:2] == pytest.approx(b.origin[:2]) and a.axis == pytest.approx(b.axis)
    assert by_child(bp, "lever_front").parent == "leaf" and by_child(bp, "deadbolt").parent == "leaf_2"
    assert "thumb_turn" not in bp.parts
    for qa, qb in ((a.upper, 0.0), (0.0, b.upper), (a.upper / 2, b.upper)):
        assert overlap(bp.parts["leaf"], dof_motion(a, qa), bp.parts["leaf_2"], dof_motion(b, qb)) < VOLUME_TOL
