"""The dining_table category: parts, joints, clearances at every joint state, overrides, seeds."""

from __future__ import annotations

import numpy as np
import pytest

from infmob_usd.categories.parts.furniture_sizes import DINING
from infmob_usd.model import build as build_model

from collide import overlap
from helpers import maker
from zoo import by_child, movable

SEEDS = range(6)
TOL = 1e-7  # m^3 of overlap tolerated between two parts
EYE = np.eye(4)


make = maker("dining_table")


def at(moving, f):
    """``Blueprint.poses`` values with the joints in ``moving`` at fraction ``f`` (all simple prismatic)."""
    return {(j.child, 0): j.dofs[0].lower + f * (j.dofs[0].upper - j.dofs[0].lower) for j in moving}


def clash(bp, q):
    """Overlapping part pairs at ``q``; welded pairs skipped; parent and child are checked too."""
    welded = {"body"} | {j.child for j in bp.joints if not j.movable}
    pose = bp.poses(q)
    names = list(bp.parts)
    bad = []
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            if {a, b} <= welded:
                continue
            v = overlap(bp.parts[a], pose[a], bp.parts[b], pose[b])
            if v >= TOL:
                bad.append((a, b, v))
    return bad


@pytest.mark.parametrize("seed", SEEDS)
def test_parts_labels_and_model(seed):
    p, bp = make(seed)
    assert bp.root == "body"
    labels = {part.label for part in bp.parts.values()}
    assert labels <= {"body", "top", "leaf", "drawer", "leg", "bracket", "foot", "turntable", "caster", "wheel"}
    assert {pc.material for part in bp.parts.values() for pc in part.pieces} <= set(bp.materials)
    assert all(pc.convex for part in bp.parts.values() for pc in part.pieces)
    links, _ = build_model(bp, {k: 700.0 for k in bp.materials})
    assert all(link.mass > 0 for link in links)
    lo, hi = bp.bounds()
    # a lazy susan stands on the top
    susan = DINING["bearing"] + 0.001 + DINING["susan_t"] if "lazy_susan" in bp.parts else 0.0
    assert lo[2] == pytest.approx(0.0, abs=1e-9) and hi[2] == pytest.approx(p["height"] + susan, abs=1e-6)
    assert hi[0] - lo[0] == pytest.approx(p["length"], rel=1e-3)
    assert movable(bp), "every table has a moving part"


@pytest.mark.parametrize("seed", SEEDS)
def test_joint_kinds_axes_and_limits(seed):
    p, bp = make(seed)
    for j in bp.joints:
        part = bp.parts[j.child]
        if part.label == "wheel":  # a caster's wheel turns about its axle under the fork
            assert j.kind == "continuous" and bp.parts[j.parent].label == "caster"
            continue
        assert j.parent == "body"
        if j.child.startswith("leaf") and j.kind == "fixed":  # the stored extension leaves
            assert j.child in ("leaf", "leaf_2")
            continue
        if part.label in ("caster", "turntable"):  # casters swivel, the lazy susan turns, about z
            assert j.kind == "continuous" and j.dofs[0].axis == pytest.approx((0, 0, 1))
            continue
        if part.label == "foot":  # a levelling foot, fixed under its leg (it turns only with the table lifted)
            assert j.kind == "fixed"
            assert min(pc.bounds[0, 2] for pc in part.pieces) == pytest.approx(0.0, abs=1e-9)
            continue
        if part.label == "leaf" and j.kind == "prismatic":  # draw leaves pull out along the long axis
            d = j.dofs[0]
            assert abs(d.axis[0]) == pytest.approx(1.0) and d.lower == 0.0 and d.upper > 0.0
            continue
        if part.label in ("leaf", "bracket"):  # drop leaves rise level, lopers swing out under them
            d = j.dofs[0]
            assert j.kind == "revolute" and d.lower == 0.0 and d.upper == pytest.approx(np.pi / 2)
            assert abs(d.axis[0 if part.label == "leaf" else 2]) == pytest.approx(1.0)
            assert (j.requires_open is not None) == (part.label == "bracket")
            continue
        assert j.kind == "prismatic"
        d = j.dofs[0]
        assert d.lower == 0.0 and d.upper > 0.0
        if part.label == "top":  # halves slide apart along the long axis
            assert abs(d.axis[0]) == pytest.approx(1.0)
            assert d.axis[0] * np.mean([pc.bounds[:, 0].mean() for pc in part.pieces]) > 0
        elif part.label == "drawer":  # out along the short axis, or the long one from the ends
            k = 0 if p["drawer_sides"] == "ends" else 1
            assert abs(d.axis[k]) == pytest.approx(1.0)
            assert d.axis[k] * d.origin[k] > 0
            assert any(pc.name == "handle" for pc in part.pieces)
        else:  # an adjustable leg slides up from its resting bottom
            assert part.label == "leg" and d.axis == pytest.approx((0, 0, 1))


@pytest.mark.parametrize("seed", SEEDS)
def test_no_overlap_at_rest_and_with_joints_moved(seed):
    _, bp = make(seed)
    js = movable(bp)
    assert clash(bp, at([], 0.0)) == []
    assert clash(bp, at(js, 1.0)) == []
    assert clash(bp, at([j for j in js if not j.requires_open], 0.5)) == []  # a loper moves once its leaf is up
    by = {j.child: j for j in js}
    for j in js:  # each alone, with what it requires open
        assert clash(bp, at([j] + ([by[j.requires_open]] if j.requires_open else []), 1.0)) == [], j.child


@pytest.mark.parametrize("seed", SEEDS)
def test_moving_parts_clear_at_rest(seed):
    """Each moving part, nudged 1 mm in any direction, still touches nothing."""
    _, bp = make(seed)
    for j in movable(bp):
        for d in np.vstack([np.eye(3), -np.eye(3)]) * 0.001:
            m = np.eye(4)
            m[:3, 3] = d
            for other, part in bp.parts.items():
                if other != j.child:
                    assert overlap(bp.parts[j.child], m, part, EYE) < TOL, (j.child, other, d)


def test_busy_table_all_mechanisms():
    over = dict(support="legs", top_style="extension", has_drawers=True, drawer_count=2, back_drawer_count=2,
                drawer_sides="both",
                has_adjustable_legs=True, length=1.6, width=0.9, apron_height=0.08, leaf_count=1)
    _, bp = make(2, **over)
    labels = [part.label for part in bp.parts.values()]
    assert labels.count("drawer") == 4 and labels.count("leg") == 4 and labels.count("top") == 2
    assert labels.count("leaf") == 1
    js = movable(bp)
    assert len(js) == 10
    assert clash(bp, at(js, 1.0)) == []
    for j in js:
        assert clash(bp, at([j], 1.0)) == [], j.child


def test_forced_drawers_pedestal_and_top_build_those_parts():
    """Forced drawers, pedestal and top give those parts; a table asked for nothing movable still gets apron
    drawers (the generic contract: test_category_contract)."""
    _, bp = make(3, top_style="fixed", has_drawers=True, drawer_count=1, drawer_sides="one",
                 has_adjustable_legs=False, has_lazy_susan=False)
    assert [j.child for j in movable(bp)] == ["drawer_0"]
    assert "leaf" not in bp.parts
    # nothing movable asked for: the table still gets apron drawers
    p, bp = make(3, top_style="fixed", has_drawers=False, has_adjustable_legs=False, has_lazy_susan=False)
    assert p["has_drawers"] and movable(bp)
    assert all(bp.parts[j.child].label == "drawer" for j in movable(bp))
    _, bp = make(3, support="pedestal", has_adjustable_legs=True)
    assert not any(part.label == "leg" for part in bp.parts.values())
    p, _ = make(3, length=2.5, top_shape="oval")
    assert p["length"] == 2.5 and p["top_shape"] == "oval"


def test_seeds_vary():
    params = [make(s)[0] for s in range(20)]
    for name in ("support", "top_shape", "top_style", "has_drawers", "leg_style"):
        assert len({p[name] for p in params}) > 1, name
    counts = [len(movable(make(s)[1])) for s in range(12)]
    assert min(counts) < max(counts)


@pytest.mark.parametrize("over", [dict(support="legs", top_shape="rectangular", has_loper=True),
                                  dict(support="pedestal", top_shape="oval", has_loper=True),
                                  dict(support="legs", has_adjustable_legs=True, has_loper=False)])
def test_drop_leaf_table(over):
    """Two leaves hang from the narrow centre at rest and rise level on their hinges; a loper swings out
    under each raised leaf; nothing clashes with the leaves up or down; drawers in the ends."""
    p, bp = make(4, top_style="drop_leaf", has_drawers=True, drawer_sides="one", end_drawers=2, **over)
    assert p["drawer_sides"] == "ends"  # the lopers are in the long boards
    drawers = [j for j in movable(bp) if bp.parts[j.child].label == "drawer"]
    assert len(drawers) == 2 and all(abs(j.dofs[0].axis[0]) == 1.0 for j in drawers)  # one in each end
    js = {j.child: j for j in movable(bp)}
    for name in ("leaf_left", "leaf_right"):
        leaf = bp.parts[name]
        lo = min(pc.bounds[0, 2] for pc in leaf.pieces)
        assert lo < p["height"] - 0.2  # hanging down at rest
        raised = bp.poses(at([js[name]], 1.0))[name]
        top = max((pc.vertices @ raised[:3, :3].T + raised[:3, 3])[:, 2].max() for pc in leaf.pieces)
        assert top == pytest.approx(p["height"], abs=1e-6)  # level with the centre when raised
    assert ("loper_left" in bp.parts) == p["has_loper"]
    if p["has_loper"]:
        assert js["loper_left"].requires_open == "leaf_left"
    assert clash(bp, at([], 0.0)) == [] and clash(bp, at(list(js.values()), 1.0)) == []
    assert clash(bp, at([js["leaf_left"]], 0.5)) == []


def test_levelling_feet():
    p, bp = make(1, support="legs", has_adjustable_legs=False, has_levellers=True)
    feet = [j for j in bp.joints if bp.parts[j.child].label == "foot"]
    assert len(feet) == 4 and all(j.kind == "fixed" and j.parent == "body" for j in feet)
    legs = [pc for pc in bp.parts["body"].pieces if pc.bounds[0, 2] < 0.05]
    assert legs and min(pc.bounds[0, 2] for pc in legs) == pytest.approx(0.015, abs=1e-6)  # legs on the feet
    assert clash(bp, at([], 0.0)) == []
    _, bp = make(1, support="legs", has_adjustable_legs=True, has_levellers=True)
    assert not any(part.label == "foot" for part in bp.parts.values())  # inner legs have their own feet


@pytest.mark.parametrize("front,back,length", [(3, 1, 2.4), (1, 2, 1.8), (3, 3, 1.8), (3, 2, 1.95)])
def test_each_long_side_draws_its_own_drawer_count(front, back, length):
    """The +Y and -Y long sides carry their own drawer counts, spread
    evenly, each pulling out along its side's normal and clear of the others when all are out (three only on
    a table 1.9 m or longer)."""
    p, bp = make(2, support="legs", top_style="extension", has_drawers=True, drawer_sides="both",
                 drawer_count=front, back_drawer_count=back, length=length, width=1.0, apron_height=0.12,
                 has_adjustable_legs=False)
    cap = 3 if length >= 1.9 else 2
    js = [j for j in movable(bp) if bp.parts[j.child].label == "drawer"]
    sides = [np.sign(j.dofs[0].axis[1]) for j in js]
    assert sides.count(1) == min(front, cap) and sides.count(-1) == min(back, cap)
    assert clash(bp, at(js, 1.0)) == []


@pytest.mark.parametrize("length,per_leaf,count", [(1.4, 2, 1), (2.4, 2, 2), (2.4, 1, 1)])
def test_long_drop_leaves_rest_on_two_lopers(length, per_leaf, count):
    """A drop leaf over an apron 1.3 m or longer gets two lopers (a quarter of the apron from each end) when
    lopers_per_leaf is 2, else a single loper in the middle; each needs its leaf up and swings out clear of
    the rest."""
    p, bp = make(4, top_style="drop_leaf", has_loper=True, length=length, top_shape="rectangular",
                 end_overhang=0.1, support="legs", has_adjustable_legs=False, lopers_per_leaf=per_leaf)
    for side in ("left", "right"):
        names = [n for n in bp.parts if n.startswith(f"loper_{side}")]
        assert len(names) == count
        js = [by_child(bp, n) for n in names]
        assert all(j.requires_open == f"leaf_{side}" and j.kind == "revolute" for j in js)
    moving = [j for j in movable(bp)]
    assert clash(bp, at([], 0.0)) == [] and clash(bp, at(moving, 1.0)) == []  # as the single loper's test


def test_draw_leaf_table():
    """A draw-leaf table: a leaf under each end of the fixed top pulls out along +-X, stays under the top at
    rest, ends past the top's end when out, and clears everything."""
    p, bp = make(2, top_style="draw_leaf", top_shape="oval", support="legs", has_drawers=True,
                 drawer_sides="one", has_adjustable_legs=False, has_lazy_susan=False)
    assert p["top_shape"] == "rectangular"  # draw leaves are square-ended
    js = {j.child: j for j in movable(bp) if bp.parts[j.child].label == "leaf"}
    assert sorted(js) == ["leaf_back", "leaf_front"]
    for name, s in (("leaf_front", 1), ("leaf_back", -1)):
        j = js[name]
        assert j.kind == "prismatic" and j.parent == "body" and j.dofs[0].axis == pytest.approx((s, 0, 0))
        xs = np.array([pc.bounds[:, 0] for pc in bp.parts[name].pieces])
        assert s * xs.max() * s <= p["length"] / 2 + 1e-9 and abs(xs).max() <= p["length"] / 2
        assert j.dofs[0].upper > 0.2
        zs = np.array([pc.bounds[:, 2] for pc in bp.parts[name].pieces])
        assert zs.max() < p["height"] - p["top_thickness"]  # under the top
    moving = movable(bp)
    assert clash(bp, at([], 0.0)) == [] and clash(bp, at(moving, 1.0)) == []


@pytest.mark.parametrize("style", ["fixed", "draw_leaf"])
def test_lazy_susan(style):
    """A lazy susan turns about z on a bearing in the middle of a fixed or draw-leaf top, above it."""
    p, bp = make(1, top_style=style, has_lazy_susan=True, has_drawers=False, support="pedestal")
    j = by_child(bp, "lazy_susan")
    assert j.kind == "continuous" and j.parent == "body" and j.dofs[0].axis == pytest.approx((0, 0, 1))
    o = j.dofs[0].origin
    assert tuple(o) == pytest.approx((0, 0, o[2])) and o[2] > p["height"]
    lo = min(pc.bounds[0, 2] for pc in bp.parts["lazy_susan"].pieces)
    assert lo > p["height"]
    assert clash(bp, at([], 0.0)) == []
    _, bp = make(1, top_style="extension", has_lazy_susan=True)
    assert "lazy_susan" not in bp.parts  # a split top has no middle to turn on


def test_stacked_extension_leaves():
    """Two extension leaves lie stacked in the apron under the split, each half the opening wide."""
    _, bp = make(2, top_style="extension", leaf_count=2, has_drawers=True, drawer_sides="one", drawer_count=2,
                 support="legs", has_adjustable_legs=False)
    leaves = [n for n, part in bp.parts.items() if part.label == "leaf"]
    assert sorted(leaves) == ["leaf", "leaf_2"]
    assert all(by_child(bp, n).kind == "fixed" for n in leaves)
    z = [bp.parts[n].pieces[0].bounds[:, 2] for n in leaves]
    assert z[1][1] < z[0][0]  # the second under the first
    travel = by_child(bp, "top_front").dofs[0].upper
    w = [np.ptp(bp.parts[n].pieces[0].bounds[:, 0]) for n in leaves]
    assert w[0] == pytest.approx(w[1]) and w[0] <= travel + 1e-9
    assert clash(bp, at(movable(bp), 1.0)) == []


@pytest.mark.parametrize("style", ["twin", "single"])
def test_casters_under_the_legs(style):
    """Four swivelling casters carry the legs (no levelling feet); their wheels touch the floor."""
    p, bp = make(3, support="legs", has_casters=True, has_levellers=True, has_adjustable_legs=False,
                 caster_style=style)
    assert not any(part.label == "foot" for part in bp.parts.values())
    casters = [n for n, part in bp.parts.items() if part.label == "caster"]
    wheels = [n for n, part in bp.parts.items() if part.label == "wheel"]
    assert len(casters) == 4 and len(wheels) == 4 * (2 if style == "twin" else 1)
    assert all(by_child(bp, n).kind == "continuous" and by_child(bp, n).parent == "body" for n in casters)
    assert all(by_child(bp, n).kind == "continuous" for n in wheels)
    assert min(pc.bounds[0, 2] for n in wheels for pc in bp.parts[n].pieces) == pytest.approx(0.0, abs=1e-9)
    assert clash(bp, at([], 0.0)) == []


@pytest.mark.parametrize("length,count", [(1.6, 3), (2.4, 4)])
def test_pedestal_glides(length, count):
    """Levelling glides under a pedestal: three under a round foot, four under two trestle feet; the pedestal
    stands on them."""
    _, bp = make(1, support="pedestal", has_pedestal_levellers=True, length=length)
    feet = [n for n, part in bp.parts.items() if part.label == "foot"]
    assert len(feet) == count and all(by_child(bp, n).kind == "fixed" for n in feet)
    low = min(pc.bounds[0, 2] for pc in bp.parts["body"].pieces)
    assert low == pytest.approx(0.015, abs=1e-6)
    assert clash(bp, at([], 0.0)) == []


def test_ranges_and_parts_on_the_contract():
    """The schema's ranges are the sourced table's; the mechanisms are Assemblies joined by named anchors: a
    draw leaf's ``slide`` anchor sits at its outer end pointing out, a drawer's ``slide`` anchor on its
    opening's centre, and the apron frame is a frozen size dataclass."""
    import dataclasses

    from infmob_usd.categories.dining_table import PARAMS
    from infmob_usd.categories.parts import table_mechanisms as TM
    from infmob_usd.categories.parts import tables as TT
    from infmob_usd.categories.parts.furniture_sizes import DINING_RANGES

    bounds = {q.name: (q.low, q.high) for q in PARAMS if hasattr(q, "low")}
    assert {k: bounds[k] for k in DINING_RANGES} == DINING_RANGES
    leaf = TM.draw_leaf(2.0, 1.0, 0.45, -1, 0.7, DINING)
    slide = leaf.anchor("slide")
    assert slide.origin[0] == pytest.approx(-(1.0 - DINING["draw_leaf_in"][0])) and slide.z[0] == pytest.approx(-1)
    assert leaf.bounds()[0, 0] == pytest.approx(slide.origin[0]) and leaf.bounds()[1, 0] == pytest.approx(-0.55)
    drawer = TM.opening_drawer((-0.2, 0.6, 0.2, 0.7), 0.45, 1, False, 0.4, "knob", DINING)
    assert drawer.anchor("slide").origin == pytest.approx((0.0, 0.45, 0.65))
    p = {"length": 2.0, "width": 1.0, "height": 0.75, "top_thickness": 0.03, "top_shape": "rectangular",
         "end_overhang": 0.1, "side_overhang": 0.08, "leaf_fraction": 0.25, "leg_width": 0.07, "support": "legs",
         "apron_height": 0.1, "drawer_sides": "one"}
    fr = TT.DiningFrame.of(p, DINING, None, False, False, True)
    assert (fr.La, fr.Wa) == pytest.approx((1.8, 0.84)) and fr.za1 == pytest.approx(0.72)
    with pytest.raises(dataclasses.FrozenInstanceError):
        fr.La = 1.0  # type: ignore[misc]
