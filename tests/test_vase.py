"""The vase category: parts, joints, clearances (and the check helpers the bottle and jar tests import).

Determinism and bad overrides are the shared category contract's; the vessel parts have
tests/test_parts_vessel.py."""

from __future__ import annotations

import math

import manifold3d
import numpy as np
import pytest

from infmob_usd import profiles
from infmob_usd.categories import vase
from infmob_usd.categories.parts import vessel as V
from infmob_usd.errors import ParameterError
from infmob_usd.lift_off import LIFT_OFF

from zoo import by_child, make_bp

SEEDS = range(8)


# -- helpers (bottle and jar tests import these) -------------------------------------


def hulls(part, matrix=None):
    out = [c for pc in part.pieces for c in pc.convex]
    if matrix is not None:
        out = [c @ matrix[:3, :3].T + matrix[:3, 3] for c in out]
    return out


def motion(dof, q):
    m = np.eye(4)
    a, o = np.asarray(dof.axis), np.asarray(dof.origin)
    if dof.type == "prismatic":
        m[:3, 3] = a * q
    else:
        k = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
        r = np.eye(3) + math.sin(q) * k + (1 - math.cos(q)) * k @ k
        m[:3, :3], m[:3, 3] = r, o - r @ o
    return m


def gap(hs_a, hs_b, search=0.02):
    """Smallest distance between two sets of convex hulls (0 when they touch or overlap)."""
    best = search
    mb = [(b, b.min(0), b.max(0)) for b in hs_b]
    for a in hs_a:
        lo, hi = a.min(0) - best, a.max(0) + best
        ma = None
        for b, blo, bhi in mb:
            if np.any(hi < blo) or np.any(bhi < lo):
                continue
            ma = ma or manifold3d.Manifold.hull_points(a)
            best = min(best, ma.min_gap(manifold3d.Manifold.hull_points(b), best))
    return best


def check_cap_joint(bp, child, lift):
    """A continuous_prismatic lid/cap on the body: lift along +Z 0..lift, turn about Z, on the axis."""
    j = by_child(bp, child)
    assert j.kind == "continuous_prismatic" and j.parent == "body"
    slide, turn = j.dofs
    assert slide.axis == pytest.approx((0, 0, 1)) and turn.axis == pytest.approx((0, 0, 1))
    # a hand's lift at most (the core's lift-off rule: lifted off the seat, not slid through the air)
    assert (slide.lower, slide.upper) == (0.0, pytest.approx(min(lift, LIFT_OFF))) and j.role == "lift_off"
    assert slide.origin[:2] == pytest.approx((0, 0)) and turn.origin[:2] == pytest.approx((0, 0))
    # the turn is neutral: the carried centre of mass (a solid of revolution) is on the axis
    pts = np.vstack([pc.vertices for pc in bp.parts[child].pieces])
    assert np.abs(pts[:, :2].mean(0)).max() < 2e-3
    # the pivot is on the axis at or just above the rim, inside the lid/cap
    top = max(c[:, 2].max() for c in hulls(bp.parts["body"]))
    assert top - 1e-6 <= slide.origin[2] <= top + 0.01


def check_sweep(bp, child, min_gap=0.001):
    """Clear of the body at rest, and at every sampled lift and turn never closer than that."""
    j = by_child(bp, child)
    slide, turn = j.dofs
    body = hulls(bp.parts["body"])
    assert gap(hulls(bp.parts[child]), body) >= min_gap - 1e-6
    for f in (0.0, 0.3, 1.0):
        for q in (0.4, math.pi / 2, 2.7, -1.9):
            m = motion(slide, f * slide.upper) @ motion(turn, q)
            assert gap(hulls(bp.parts[child], m), body) >= min_gap - 1e-6, (f, q)


def check_hollow(bp, z):
    """The point on the axis at height z is inside no collision hull of the body."""
    from scipy.spatial import Delaunay

    p = np.array([[0.0, 0.0, z]])
    for h in hulls(bp.parts["body"]):
        assert Delaunay(h).find_simplex(p)[0] < 0


def check_common(bp):
    assert bp.root == "body"
    used = {pc.material for part in bp.parts.values() for pc in part.pieces}
    assert used <= set(bp.materials)
    for part in bp.parts.values():
        for pc in part.pieces:
            assert pc.convex or part.label in ("cap", "lid"), f"{part.name}: a piece without collision"
            assert np.isfinite(pc.vertices).all()
    assert bp.bounds()[0, 2] == pytest.approx(0.0, abs=1e-9)


# -- vase --------------------------------------------------------------------------------


@pytest.mark.parametrize("seed", SEEDS)
def test_parts_labels_and_size(seed):
    p, bp = make_bp(vase, "vase", seed)
    check_common(bp)
    assert bp.parts["body"].label == "body"
    closure = p["closure"] if p["closure"] != "auto" else vase.usual_closure(p)
    assert closure in vase.CLOSURES and bp.parts[closure].label == closure
    assert [j for j in bp.joints if j.movable]  # every vase has a movable closure
    body = np.array([pc.bounds for pc in bp.parts["body"].pieces])
    lo, hi = body[:, 0].min(0), body[:, 1].max(0)
    assert hi[2] - lo[2] == pytest.approx(p["height"], abs=0.004)
    d = hi[0] - lo[0]
    assert 0.15 * p["height"] <= d <= 0.41 * p["height"]
    assert bp.materials["body"] == p["finish"] in ("ceramic", "glass", "enamel")
    check_hollow(bp, 0.5 * hi[2])


@pytest.mark.parametrize("seed", SEEDS)
def test_lid_turns_lifts_and_clears_the_body(seed):
    _, bp = make_bp(vase, "vase", seed, closure="lid")
    assert bp.parts["lid"].label == "lid"
    check_cap_joint(bp, "lid", vase.LID_LIFT)
    check_sweep(bp, "lid")
    # the plug reaches into the mouth, below the rim
    rim = max(c[:, 2].max() for c in hulls(bp.parts["body"]))
    assert min(c[:, 2].min() for c in hulls(bp.parts["lid"])) < rim - 0.01


@pytest.mark.parametrize("profile", list(vase.SHAPES))
def test_every_profile_builds_smooth_and_hollow(profile):
    p, bp = make_bp(vase, "vase", 3, profile=profile, closure="lid")
    wall = bp.parts["body"].pieces[0]
    # smooth: facets within the chord tolerance round the axis, and the profile turns at most 20
    # degrees from one band to the next (so its normals are smooth, not creased)
    r = np.hypot(wall.vertices[:, 0], wall.vertices[:, 1])
    rings = len(np.unique(np.round(np.arctan2(wall.vertices[:, 1], wall.vertices[:, 0]), 9)))
    assert r.max() * (1 - np.cos(np.pi / rings)) <= profiles.CHORD_TOL + 1e-9
    outer = wall.vertices[np.abs(wall.vertices[:, 1]) < 1e-12]
    outer = outer[outer[:, 0] > 0]
    zs = np.unique(outer[:, 2])
    prof = np.array([(outer[outer[:, 2] == z, 0].max(), z) for z in zs])  # the outside (inside shares heights)
    d = np.diff(prof, axis=0)
    heading = np.degrees(np.arctan2(d[:, 1], d[:, 0]))
    assert len(prof) >= 4 and np.abs(np.diff(heading)).max() <= 20.0 + 1e-6
    check_hollow(bp, 0.3 * p["height"])
    check_sweep(bp, "lid")


def test_spline_profile_is_smooth_and_the_coarse_one_envelopes_it():
    ctrl = [(0.05, 0.0), (0.08, 0.1), (0.03, 0.2), (0.035, 0.25)]
    fine, coarse = V.spline_profile(ctrl, n=80, coarse=8)
    assert np.all(np.diff(fine[:, 1]) > 0)
    # thinned within the profile tolerance of the curve sampled 10x finer
    dense, _ = V.spline_profile(ctrl, n=800, coarse=8)
    zs = np.linspace(0, 0.25, 2000)
    dev = np.abs(np.interp(zs, fine[:, 1], fine[:, 0]) - np.interp(zs, dense[:, 1], dense[:, 0]))
    assert dev.max() <= 2 * profiles.PROFILE_TOL and len(fine) < 80
    assert fine[:, 0].max() <= 0.08 + 1e-9  # no overshoot
    zs = np.linspace(0, 0.25, 500)
    assert np.all(np.interp(zs, coarse[:, 1], coarse[:, 0]) >= np.interp(zs, fine[:, 1], fine[:, 0]) - 1e-9)
    assert np.diff(coarse[:, 1]).min() > 0.005


def test_overrides_and_bad_values():
    p, bp = make_bp(vase, "vase", 1, closure="liner", profile="bowl", finish="enamel")
    assert "lid" not in bp.parts and [j.kind for j in bp.joints if j.movable] == ["prismatic"]
    assert p["profile"] == "bowl" and bp.materials["body"] == "enamel"
    with pytest.raises(ParameterError):
        make_bp(vase, "vase", 0, profile="urn")
    with pytest.raises(ParameterError):
        make_bp(vase, "vase", 0, closure="cork")


def test_grammar_drives_the_parts():
    # the grown tree is what gets built: one body node of the chosen shape, a foot, the closure
    _, bp = make_bp(vase, "vase", 2, profile="amphora", closure="stopper")
    assert {n: p.label for n, p in bp.parts.items()} == {"body": "body", "foot": "stand", "stopper": "stopper"}
    assert next(j for j in bp.joints if j.child == "foot").kind == "fixed"
    assert "amphora: builds body" in vase.CATEGORY.rules()


@pytest.mark.parametrize("closure", vase.CLOSURES)
def test_each_closure_forced_moves_and_clears(closure):
    for seed in (0, 5):
        _, bp = make_bp(vase, "vase", seed, closure=closure)
        j = by_child(bp, closure)
        assert j.parent == "body" and j.movable
        if closure == "liner":
            assert j.kind == "prismatic" and j.dofs[0].axis == pytest.approx((0, 0, 1))
            assert j.dofs[0].upper == pytest.approx(LIFT_OFF)  # a hand's lift
            # the liner hangs inside: clear of the wall at rest and lifted halfway
            body = hulls(bp.parts["body"])
            for f in (0.0, 0.5):
                assert gap(hulls(bp.parts["liner"], motion(j.dofs[0], f * j.dofs[0].upper)), body) >= 0.001
        else:
            check_sweep(bp, closure)


@pytest.mark.parametrize("seed", SEEDS)
def test_the_vase_stands_on_a_wide_foot(seed):
    # a vase tips over unless its foot is at least 40 % of its widest diameter
    _, bp = make_bp(vase, "vase", seed)
    foot = np.vstack([pc.vertices for pc in bp.parts["foot"].pieces])
    body = np.vstack([pc.vertices for pc in bp.parts["body"].pieces])
    assert np.ptp(foot[:, 0]) >= 0.4 * np.ptp(body[:, 0])


def test_varied():
    params = [make_bp(vase, "vase", s)[0] for s in range(20)]
    closures = {vase.usual_closure(p) for p in params}
    assert closures == set(vase.CLOSURES)
    for name in ("profile", "finish"):
        assert len({p[name] for p in params}) > 1
