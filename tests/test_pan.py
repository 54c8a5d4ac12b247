"""The pan category, checked on its blueprint (world space, grounded): parts, joints, clearances."""

from __future__ import annotations

import numpy as np
import pytest

from infmob_usd.categories import pan
from infmob_usd.lift_off import LIFT_OFF
from infmob_usd.model import build as build_model

from collide import overlap
from helpers import maker
from zoo import make_bp

SEEDS = range(8)


# the riveted design (a fixed handle) unless a test asks for another; no helper handle
make = maker("pan", handle_style="riveted", has_helper=False)


def up(dz):
    m = np.eye(4)
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
    want = {"body": "body", "handle": "handle", "lid": "lid"}  # a riveted pan always has its lid
    assert {n: part.label for n, part in bp.parts.items()} == want
    assert all(pc.name == "handle" for pc in bp.parts["handle"].pieces)
    j = next(j for j in bp.joints if j.child == "handle")
    assert j.kind == "fixed" and j.parent == "body"
    coating = [pc for pc in bp.parts["body"].pieces if pc.material == "coating"]
    assert bool(coating) == (p["finish"] == "nonstick")
    used = {pc.material for part in bp.parts.values() for pc in part.pieces}
    assert used <= set(bp.materials)
    for part in bp.parts.values():
        for pc in part.pieces:
            assert pc.convex and all(len(c) <= 255 for c in pc.convex)
    links, _ = build_model(bp, {k: 1000.0 for k in bp.materials})
    assert all(link.mass > 0 for link in links)


@pytest.mark.parametrize("seed", SEEDS)
def test_shallow_wide_body(seed):
    p, bp = make(seed)
    lo, hi = np.array([pc.bounds for pc in bp.parts["body"].pieces]).transpose(1, 0, 2)
    R = p["radius"]
    assert (hi.max(0) - lo.min(0))[2] == pytest.approx(p["depth_ratio"] * R, abs=1e-6)
    assert bp.bounds()[0, 2] == pytest.approx(0.0, abs=1e-9)
    floor = bp.parts["body"].pieces[0].bounds  # the bottom
    assert floor[1, 0] >= 0.58 * R  # a wide flat floor, not a wok
    hs = np.vstack([pc.vertices for pc in bp.parts["handle"].pieces])
    assert hs[:, 0].max() - R > 0.14 and hs[:, 2].min() > 0


@pytest.mark.parametrize("seed", SEEDS)
def test_lid_joint_and_clearance(seed):
    _, bp = make(seed, has_lid=True)
    j = next(j for j in bp.joints if j.child == "lid")
    assert j.kind == "prismatic" and j.parent == "body" and j.role == "lift_off"
    (d,) = j.dofs
    assert d.axis == pytest.approx((0, 0, 1)) and (d.lower, d.upper) == (0.0, pytest.approx(0.02))
    rim = max(pc.bounds[1, 2] for pc in bp.parts["body"].pieces)
    assert 0.001 <= lowest(bp.parts["lid"]) - rim <= 0.004
    lid = bp.parts["lid"]
    assert overlap(lid, np.eye(4), bp.parts["body"], np.eye(4), pad=0.0015) == 0.0
    for dz in (0.0, 0.01, 0.02):
        for other in ("body", "handle"):
            assert overlap(lid, up(dz), bp.parts[other], np.eye(4)) < 1e-9
    assert overlap(lid, np.eye(4), bp.parts["handle"], np.eye(4), pad=0.0015) == 0.0


def test_forced_lid_helper_hole_and_finishes_build_those_parts():
    """A riveted pan grows its lid anyway; forced helper handle, hanging hole and finishes give those parts and
    material slots (the generic contract: test_category_contract)."""
    _, bp = make(1, has_lid=False)  # the riveted design grows its lid anyway: every pan moves
    assert set(bp.parts) == {"body", "handle", "lid"} and any(j.movable for j in bp.joints)
    _, bp = make(1, has_helper=True)
    assert bp.parts["helper"].label == "handle"
    assert next(j for j in bp.joints if j.child == "helper").kind == "fixed"
    _, a = make(1, has_hole=True)
    _, b = make(1, has_hole=False)
    assert len(a.parts["handle"].pieces) > 10 > len(b.parts["handle"].pieces)
    p, bp = make(1, finish="cast_iron", handle_finish="wood")
    assert all(pc.material == "body" for pc in bp.parts["handle"].pieces)
    _, bp = make(1, finish="steel", handle_finish="wood")
    assert bp.materials["handle"] == "wood"
    assert all(pc.material == "handle" for pc in bp.parts["handle"].pieces)


def test_shallowest_pan_with_thick_handle():
    _, bp = make(0, radius=0.1, depth_ratio=0.3, handle_thickness=0.017, bead=0.0028, has_lid=True)
    hs = np.vstack([pc.vertices for pc in bp.parts["handle"].pieces])
    assert hs[:, 2].min() > 0
    assert overlap(bp.parts["lid"], np.eye(4), bp.parts["handle"], np.eye(4), pad=0.0015) == 0.0


def test_variety():
    params = [make_bp(pan, "pan", s)[0] for s in range(20)]
    for name in ("finish", "has_lid", "has_hole", "lid_finish", "handle_style"):
        assert len({q[name] for q in params}) > 1, name


@pytest.mark.parametrize("seed", range(4))
def test_folding_handle_hinges_on_its_lug_and_lifts(seed):
    _, bp = make(seed, handle_style="folding")
    j = next(j for j in bp.joints if j.child == "handle")
    assert j.kind == "revolute" and j.parent == "body"
    d = j.dofs[0]
    assert d.axis == pytest.approx((0, -1, 0)) and d.lower == 0.0 and d.upper > 1.0
    # clear of the body (its lug) at rest, and a positive turn lifts the grip end
    assert overlap(bp.parts["handle"], np.eye(4), bp.parts["body"], np.eye(4), pad=0.001) == 0.0
    grip = np.vstack([pc.vertices for pc in bp.parts["handle"].pieces])
    tip = grip[grip[:, 0].argmax()]
    c, s_ = np.cos(0.5), np.sin(0.5)
    rel = tip - d.origin
    assert d.origin[2] + rel[0] * s_ + rel[2] * c > tip[2] + 0.02
    assert any(pc.convex for pc in bp.parts["body"].pieces if pc.material in ("body", "handle"))


@pytest.mark.parametrize("seed", range(4))
def test_detachable_handle_slides_off_with_a_release_slider(seed):
    _, bp = make(seed, handle_style="detachable")
    j = next(j for j in bp.joints if j.child == "handle")
    assert j.kind == "prismatic" and j.parent == "body" and j.dofs[0].axis == pytest.approx((1, 0, 0))
    # pulled off its lug by a hand's pull (the core's lift-off rule), not slid through the air
    assert j.dofs[0].upper == pytest.approx(LIFT_OFF) and j.role == "lift_off"
    r = next(j for j in bp.joints if j.child == "release")
    assert r.kind == "prismatic" and r.parent == "handle" and bp.parts["release"].label == "button"
    assert overlap(bp.parts["handle"], np.eye(4), bp.parts["body"], np.eye(4), pad=0.001) == 0.0
    assert overlap(bp.parts["release"], np.eye(4), bp.parts["handle"], np.eye(4), pad=0.0003) == 0.0


def test_every_pan_has_a_movable_joint():
    for s in range(30):
        _, bp = make_bp(pan, "pan", s)
        assert any(j.movable for j in bp.joints), s
