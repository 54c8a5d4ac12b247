"""The bottle category: profiles, cap (unscrew: turn + lift), label band, clearances."""

from __future__ import annotations

import math

import numpy as np
import pytest
from test_vase import check_cap_joint, check_common, check_hollow, check_sweep, gap, hulls, motion

from infmob_usd.categories import bottle
from infmob_usd.categories.parts.vessel_sizes import CAP_MATERIALS
from infmob_usd.errors import ParameterError

from helpers import maker
from zoo import by_child, make_bp

SEEDS = range(6)


# ``closure_draw=0`` unless a test asks: cap=auto then takes the profile's classic closure
make = maker("bottle", closure_draw=0.0)


@pytest.mark.parametrize("seed", SEEDS)
def test_parts_labels_and_size(seed):
    p, bp = make(seed)
    check_common(bp)
    assert bp.parts["body"].label == "body" and bp.parts["cap"].label == "cap"
    assert "label" not in bp.parts  # a label is glued on the body
    assert any(pc.material == "label" for pc in bp.parts["body"].pieces) == p["has_label"]
    body = np.array([pc.bounds for pc in bp.parts["body"].pieces])
    assert body[:, 1, 2].max() - body[:, 0, 2].min() == pytest.approx(p["height"], abs=1e-6)
    assert bp.materials["glass"].startswith("glass")
    check_hollow(bp, 0.5 * p["height"])


@pytest.mark.parametrize("profile", list(bottle.KINDS))
def test_each_profile_cap_turns_lifts_and_clears(profile):
    p, bp = make(2, profile=profile, has_label=True)
    check_cap_joint(bp, "cap", bottle.CAP_TRAVEL)
    check_sweep(bp, "cap")
    # the neck is much narrower than the body (a recognisable bottle)
    wall = bp.parts["body"].pieces[0].vertices
    r = np.hypot(wall[:, 0], wall[:, 1])
    top = wall[:, 2] > 0.9 * p["height"]
    assert r[top].max() < 0.7 * r.max()


@pytest.mark.parametrize("profile", list(bottle.KINDS))
def test_label_is_glued_on_the_body(profile):
    """A label is paper glued on the glass: pieces of the body hugging it, not a part that turns."""
    _, bp = make(4, profile=profile, has_label=True)
    assert "label" not in bp.parts and all(j.child != "label" for j in bp.joints)
    label = [pc for pc in bp.parts["body"].pieces if pc.material == "label"]
    assert len(label) == 1
    pts = label[0].vertices
    r = np.hypot(pts[:, 0], pts[:, 1])
    zs = (pts[:, 2].min(), pts[:, 2].max())
    glass = bp.parts["body"].pieces[0].vertices
    # the glass's rows from the one at or below the label to the one at or above it
    below, above = glass[glass[:, 2] <= zs[0], 2].max(), glass[glass[:, 2] >= zs[1], 2].min()
    band = (glass[:, 2] >= below) & (glass[:, 2] <= above)
    # its inside within 1.5 mm of the glass's widest radius along it: on the glass, not floating round it
    assert 0.0 < r.min() - np.hypot(glass[band, 0], glass[band, 1]).max() < 0.0015
    # label and cap never meet
    assert gap([np.asarray(pts)], hulls(bp.parts["cap"])) > 0.005


@pytest.mark.parametrize("cap", ["crown", "screw", "capsule", "stopper"])
def test_cap_override(cap):
    _, bp = make(1, cap=cap, profile="bordeaux")
    check_sweep(bp, "cap")
    if cap == "stopper":  # reaches into the neck
        rim = max(c[:, 2].max() for c in hulls(bp.parts["body"]))
        assert min(c[:, 2].min() for c in hulls(bp.parts["cap"])) < rim - 0.005


def test_overrides_and_bad_values():
    p, bp = make(3, has_label=False, profile="champagne", height=0.3)
    assert "label" not in bp.parts and p["height"] == 0.3
    assert len([j for j in bp.joints if j.movable]) == 1
    for bad in ({"profile": "magnum"}, {"cap": "cork"}, {"closure_draw": 1.5}):
        with pytest.raises(ParameterError):
            make(0, **bad)


@pytest.mark.parametrize("profile", list(bottle.KINDS))
def test_auto_cap_is_the_profiles_usual_closure(profile):
    p, bp = make(0, profile=profile)
    usual = bottle.KINDS[profile][2]
    assert p["cap"] == usual  # "auto" drawn, recorded as the closure that was built
    assert bp.materials["cap"] == {**CAP_MATERIALS, "pump": "plastic:white|black|light_grey"}[usual]
    assert bp.materials["glass"] == bottle.KINDS[profile][3]
    if usual == "stopper":  # a wooden stopper: the cork slot, reaching into the neck
        assert {pc.material for pc in bp.parts["cap"].pieces} == {"cork"}


def test_varied():
    params = [make(s)[0] for s in range(20)]
    for name in ("profile", "has_label"):
        assert len({p[name] for p in params}) > 1
    assert math.isclose(min(p["height"] for p in params), 0.15, abs_tol=0.08)


def test_swing_top_flips_back_clear_of_the_neck():
    p, bp = make(2, cap="swing_top", profile="beer", has_label=False)
    j = by_child(bp, "cap")
    assert j.kind == "flip_revolute" and j.parent == "body" and j.role == "lid"
    swing, tip = j.dofs
    assert swing.axis == pytest.approx((0, -1, 0)) and tip.axis == pytest.approx((0, -1, 0))
    assert swing.origin[2] < tip.origin[2]  # the bail's clasp on the neck ring, under the stopper's edge
    body = hulls(bp.parts["body"])
    assert gap(hulls(bp.parts["cap"]), body) >= 0.001
    for d in (swing, tip):  # each hinge alone opens the stopper upward and backward, clear of the glass
        for q in (0.2, 0.8, 1.5):
            m = motion(d, q)
            assert gap(hulls(bp.parts["cap"], m), body) >= 0.0005, (d, q)
    assert {"washer", "wire", "porcelain"} <= {pc.material for pc in bp.parts["cap"].pieces}


def test_pump_collar_unscrews_and_its_head_turns_and_rises():
    _, bp = make(1, profile="dispenser", has_label=False)
    assert bp.parts["head"].label == "head"
    check_cap_joint(bp, "cap", bottle.CAP_TRAVEL)
    h = by_child(bp, "head")
    assert h.kind == "continuous_prismatic" and h.parent == "cap"
    slide, _ = h.dofs
    assert slide.axis == pytest.approx((0, 0, 1)) and slide.upper == pytest.approx(0.012)
    assert gap(hulls(bp.parts["head"]), hulls(bp.parts["cap"])) > 0.0
    # the nozzle points toward +X
    pts = np.vstack([pc.vertices for pc in bp.parts["head"].pieces])
    assert pts[:, 0].max() > 0.02 > -pts[:, 0].min()


def test_sports_cap_spout_pulls_up():
    _, bp = make(1, cap="sports", profile="soda")
    s = by_child(bp, "spout")
    assert s.kind == "prismatic" and s.parent == "cap" and s.dofs[0].axis == pytest.approx((0, 0, 1))
    assert gap(hulls(bp.parts["spout"]), hulls(bp.parts["cap"])) > 0.0


def test_caps_fit_their_necks():
    # a cap wider than its finish plus skirt does not sit on its neck (a crown is 32 mm on a 26 mm finish)
    for cap in ("crown", "screw"):
        _, bp = make(4, cap=cap, profile="beer" if cap == "crown" else "soda")
        wall = bp.parts["body"].pieces[0].vertices
        top = wall[wall[:, 2] > wall[:, 2].max() - 0.005]
        neck = np.hypot(top[:, 0], top[:, 1]).max()
        cap_r = max(np.hypot(pc.vertices[:, 0], pc.vertices[:, 1]).max() for pc in bp.parts["cap"].pieces)
        assert cap_r < 1.3 * neck, (cap, cap_r, neck)


def test_closures_vary():
    caps = {make_bp(bottle, "bottle", s)[0]["cap"] for s in range(40)}
    assert {"swing_top", "pump", "sports", "crown", "screw"} <= caps
