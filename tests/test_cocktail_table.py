"""The cocktail_table category: parts, joints, clearances at every joint state, overrides, seeds."""

from __future__ import annotations

import math

import numpy as np
import pytest
from test_office_chair import assert_clear, rest_overlaps

from infmob_usd.model import build as build_model

from collide import overlap
from helpers import joint_states, maker, states
from zoo import by_child

SEEDS = range(8)
TOL = 1e-7  # m^3 of overlap tolerated between two parts


make = maker("cocktail_table")


def rotation(axis, angle):
    a = np.asarray(axis, float) / np.linalg.norm(axis)
    k = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + math.sin(angle) * k + (1 - math.cos(angle)) * k @ k


def pose(joint, qs):
    """4x4 world pose of the child after each DoF of ``joint`` moved by ``qs`` (parent side first)."""
    m = np.eye(4)
    for dof, q in zip(joint.dofs, qs):
        step = np.eye(4)
        if dof.type == "prismatic":
            step[:3, 3] = np.asarray(dof.axis) * q
        else:
            o = np.asarray(dof.origin)
            r = rotation(dof.axis, q)
            step[:3, :3], step[:3, 3] = r, o - r @ o
        m = m @ step
    return m


@pytest.mark.parametrize("seed", SEEDS)
def test_parts_labels_and_model(seed):
    p, bp = make(seed)
    assert bp.root == "body" and {"body", "top"} <= set(bp.parts)
    if p["support"] == "pedestal" or (p["support"] == "legs" and not p["has_lift_top"]):
        assert set(bp.parts) == {"body", "top"}
    assert bp.parts["top"].label in ("top", "lid")
    assert bp.parts["body"].label in ("body", "stand")
    for part in bp.parts.values():  # a caster wheel's hub is decoration inside its tyre
        assert all(pc.convex for pc in part.pieces) or part.label == "wheel"
    assert {pc.material for part in bp.parts.values() for pc in part.pieces} <= set(bp.materials)
    links, _ = build_model(bp, {k: 800.0 for k in bp.materials})
    assert all(link.mass > 0 for link in links)
    lo, hi = bp.bounds()
    assert lo[2] == pytest.approx(0.0, abs=1e-9)
    assert hi[2] == pytest.approx(p["height"], abs=1e-6)
    assert p["width"] * (1 - 1e-3) <= hi[0] - lo[0] <= p["width"] + 0.03  # drawer handles may stand out


@pytest.mark.parametrize("seed", SEEDS)
def test_joint_matches_the_support(seed):
    p, bp = make(seed)
    j = by_child(bp, "top")
    lifting = p["support"] == "legs" and p["has_lift_top"]
    assert j.parent == ("lift_frame" if lifting else "body") and j.child == "top"
    if p["support"] in ("drawers", "nesting"):
        assert j.kind == "fixed"
        return
    if lifting:  # body -> lift frame -> top, the two stages along one axis
        first = by_child(bp, "lift_frame")
        assert first.kind == "prismatic" and first.dofs[0].axis == pytest.approx(j.dofs[0].axis)
        assert first.dofs[0].upper + j.dofs[0].upper >= 0.1
    if p["support"] == "pedestal":
        assert j.kind == "revolute_prismatic"
        lift, turn = j.dofs
        assert turn.axis == pytest.approx((0, 0, 1))
        assert (turn.lower, turn.upper) == (pytest.approx(-p["stand_turn"]), pytest.approx(p["stand_turn"]))
    else:
        assert j.kind == "prismatic"
        lift = j.dofs[0]
    # every lift rests at its bottom and moves up (gravity holds it at rest)
    assert lift.lower == 0.0 and 0.03 < lift.upper <= 0.25
    assert lift.axis[2] > 0.7
    forward = p["support"] == "legs" and p["has_lift_top"] and p["has_lift_forward"]
    assert (lift.axis[0] > 0.25) == forward and lift.axis[1] == 0.0


@pytest.mark.parametrize("seed", SEEDS)
def test_top_never_enters_the_body_nor_the_ground(seed):
    _, bp = make(seed, support="pedestal" if seed % 2 else "legs", has_lift_top=False)
    (j,) = bp.joints
    body, top = bp.parts["body"], bp.parts["top"]
    for qs in joint_states(j):
        m = pose(j, qs)
        assert overlap(top, m, body, np.eye(4)) < TOL, qs
        pts = np.vstack([pc.vertices for pc in top.pieces]) @ m[:3, :3].T + m[:3, 3]
        assert pts[:, 2].min() >= -1e-9


@pytest.mark.parametrize("seed", SEEDS)
def test_clear_at_rest(seed):
    """The moving top keeps a clearance from its stand at rest (1 mm in every direction)."""
    _, bp = make(seed, support="pedestal" if seed % 2 else "legs", has_lift_top=False)
    body, top = bp.parts["body"], bp.parts["top"]
    for d in np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]]) * 0.001:
        m = np.eye(4)
        m[:3, 3] = d
        assert overlap(top, m, body, np.eye(4)) < TOL


def test_forced_lifts_legs_and_pedestal_build_those_mechanisms():
    """Forced lift tops (straight and forward), legs with a shelf and a pedestal build those joints and parts;
    a nest of tables is sized down (the generic contract: test_category_contract)."""
    _, bp = make(1, support="legs", has_lift_top=True, has_lift_forward=False, top_shape="square")
    j = by_child(bp, "top")
    assert j.kind == "prismatic" and j.dofs[0].axis == pytest.approx((0, 0, 1))
    assert bp.parts["top"].label == "lid"
    _, bp = make(1, support="legs", has_lift_top=True, has_lift_forward=True, lift_forward_ratio=0.5)
    assert by_child(bp, "top").dofs[0].axis == pytest.approx(np.array([0.5, 0, 1]) / math.hypot(0.5, 1))
    _, bp = make(1, support="legs", has_lift_top=False, top_shape="round", leg_count=3, has_shelf=True)
    assert bp.joints[0].kind == "prismatic" and bp.parts["top"].label == "top"
    posts = [pc for pc in bp.parts["top"].pieces if pc.material == "metal"]
    assert len(posts) == 3
    _, bp = make(1, support="pedestal")
    assert bp.joints[0].kind == "revolute_prismatic" and bp.parts["body"].label == "stand"
    p, _ = make(1, width=0.8, height=0.5, support="legs")
    assert (p["width"], p["height"]) == (0.8, 0.5)
    p, _ = make(1, width=0.9, height=0.7, support="nesting")  # a nest of tables is side-table sized
    assert (p["width"], p["height"]) == (0.7, 0.6)


def test_seeds_vary():
    params = [make(s)[0] for s in range(20)]
    for name in ("support", "top_shape", "has_lift_top", "top_finish"):
        assert len({p[name] for p in params}) > 1, name


DESIGNS = [dict(support="legs", has_lift_top=True, has_lift_forward=True, has_shelf=True),
           dict(support="legs", has_lift_top=True, has_lift_forward=False, top_shape="round"),
           dict(support="drawers", drawer_sides="both", drawer_count=2, width=0.9, has_shelf=True),
           dict(support="drawers", drawer_sides="both", drawer_count=3, back_drawer_count=1, width=0.95),
           dict(support="drawers", drawer_sides="front", width=0.6, has_casters=False),
           dict(support="drawers", drawer_sides="front", has_casters=True, caster_style="twin", has_shelf=True),
           dict(support="drawers", drawer_sides="both", has_casters=True, caster_style="single"),
           dict(support="nesting", nested=None, has_inner=True),
           dict(support="nesting", has_inner=False)]


@pytest.mark.parametrize("over", DESIGNS, ids=lambda o: "-".join(f"{v}" for v in o.values()))
def test_designs_move_without_collisions(over):
    over = {k: v for k, v in over.items() if v is not None}
    p, bp = make(6, **over)
    moving = [j for j in bp.joints if j.kind != "fixed"]
    if p["support"] == "drawers":
        cap = 1 if p["width"] < 0.7 else 2 if p["width"] < 0.9 else 3
        n = min(cap, p["drawer_count"]) + (min(cap, p["back_drawer_count"]) if p["drawer_sides"] == "both" else 0)
        drawers = [j for j in moving if bp.parts[j.child].label == "drawer"]
        assert len(drawers) == n and all(abs(j.dofs[0].axis[0]) == pytest.approx(1.0) for j in drawers)
    if p["support"] == "drawers":
        casters = [j for j in moving if bp.parts[j.child].label == "caster"]
        wheels = [j for j in moving if bp.parts[j.child].label == "wheel"]
        assert len(casters) == (4 if p["has_casters"] else 0)
        assert len(wheels) == len(casters) * (2 if p["caster_style"] == "twin" else 1)
        assert all(j.kind == "continuous" for j in casters + wheels)
        if wheels:  # the wheels carry the table
            assert min(pc.bounds[0, 2] for j in wheels for pc in bp.parts[j.child].pieces) == pytest.approx(0, abs=1e-9)
    if p["support"] == "nesting":
        tables = [j for j in moving if bp.parts[j.child].label == "table"]
        assert 1 <= len(tables) <= 4 and all(j.kind == "prismatic" for j in tables)
        assert any(j.parent != "body" for j in tables) == p["has_inner"]
        feet = [pc.bounds[0, 2] for j in tables for pc in bp.parts[j.child].pieces]
        assert min(feet) > 0.0  # nested tables glide just above the floor
    if p["support"] == "legs":
        assert bp.parts["lift_frame"].label == "lift"
        assert any(pc.material == "strut" for pc in bp.parts["top"].pieces)  # the rods show under the top
    rest_pc = rest_overlaps(bp)
    for q in states(bp):
        assert_clear(bp, bp.poses(q), rest_pc, q)


def test_a_thick_painted_top_is_a_lightweight_board():
    """A painted top over 30 mm weighs as a honeycomb board (350 kg/m^3), not solid MDF: the same top
    in wood (650 kg/m^3) weighs 300 kg/m^3 more of its volume; a thin painted top stays MDF (750)."""
    import infmob_usd
    from infmob_usd.categories.parts.furniture_sizes import COCKTAIL

    def top(**kw):
        return infmob_usd.generate("cocktail_table", seed=8047, texture_size=16, support="drawers", **kw).link("top")

    for thickness, painted in ((0.04, COCKTAIL["hollow_top_density"]), (0.022, 750.0)):
        links = {f: top(top_finish=f, top_thickness=thickness) for f in ("painted", "wood")}
        volume = sum(pc.volume() for pc in links["painted"].pieces if pc.material == "top")
        assert volume > 0.01
        assert links["wood"].mass - links["painted"].mass == pytest.approx((650.0 - painted) * volume, rel=1e-6)


def test_ranges_and_parts_on_the_contract():
    """The schema's ranges are the sourced table's; a nest's table is an Assembly whose ``slide`` anchor sits at
    its outer end pointing out, the table nested in it is smaller in every way, and the sizes are frozen."""
    import dataclasses

    from infmob_usd.categories.cocktail_table import PARAMS
    from infmob_usd.categories.parts import table_mechanisms as TM
    from infmob_usd.categories.parts.furniture_sizes import COCKTAIL_RANGES, NEST

    bounds = {q.name: (q.low, q.high) for q in PARAMS if hasattr(q, "low")}
    assert {k: bounds[k] for k in COCKTAIL_RANGES} == COCKTAIL_RANGES
    size = TM.NestedSize.first(0.5, 0.6, 0.45, 2, 0.018, NEST)
    table, inner = TM.nested_table(size, -1, NEST)
    slide = table.anchor("slide")
    assert slide.z[0] == pytest.approx(-1) and slide.origin[0] == pytest.approx(table.bounds()[0, 0])
    assert inner.width < size.width and inner.depth < size.depth and inner.height < size.height
    with pytest.raises(dataclasses.FrozenInstanceError):
        size.width = 1.0  # type: ignore[misc]
