"""The storage_rack category: frames, pinned levels, goods fixed to levels, totes, bins and drawers, clearances."""

from __future__ import annotations

import numpy as np
import pytest

from infmob_usd.categories import storage_rack as sr
from infmob_usd.seeding import streams

from collide import overlap
from helpers import maker
from zoo import by_child

SEEDS = range(4)
VOL = 1e-7  # m^3, the validator's contact volume


# the pallet-rack design unless another is asked for
make = maker("storage_rack", design="pallet_rack")


def levels(bp):
    return sorted(n for n, part in bp.parts.items() if part.label == "shelf")


def lift(bp, fractions):
    """World pose of every part: a level (and its goods) raised by its fraction of its travel."""
    out = {}
    for name in bp.parts:
        m = np.eye(4)
        n = name
        while True:
            j = next((j for j in bp.joints if j.child == n), None)
            if j is None:
                break
            if j.kind == "prismatic":
                d = j.dofs[0]
                m[:3, 3] += np.asarray(d.axis) * fractions.get(n, 0.0) * d.upper
            n = j.parent
        out[name] = m
    return out


def moving_with(bp, name):
    """The level a part rides on (itself for a level), or None for the frame."""
    while name != "frame":
        j = by_child(bp, name)
        if j.kind == "prismatic":
            return name
        name = j.parent
    return None


def contacts(bp, fractions):
    ps = lift(bp, fractions)
    names = list(bp.parts)
    hits = []
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            ma, mb = moving_with(bp, a), moving_with(bp, b)
            if ma == mb:
                continue  # welded
            if any({j.parent, j.child} == {a, b} for j in bp.joints):
                continue  # parent and child
            v = overlap(bp.parts[a], ps[a], bp.parts[b], ps[b])
            if v >= VOL:
                hits.append((a, b, v))
    return hits


@pytest.mark.parametrize("seed", SEEDS)
def test_parts_levels_and_uprights(seed):
    p, bp = make(seed)
    assert bp.root == "frame" and bp.parts["frame"].label == "frame"
    bays = p["bay_count"] or (1 if p["width"] <= 2.2 else 2)
    assert len(levels(bp)) == bays * p["level_count"]
    assert 3 <= p["level_count"] <= 5
    posts = [pc for pc in bp.parts["frame"].pieces if pc.sheet == 0.002]
    assert len(posts) == 2 * (bays + 1) >= 4
    assert any(pc.name == "perforation" and not pc.convex for pc in bp.parts["frame"].pieces)
    size = bp.bounds()[1] - bp.bounds()[0]
    assert size[1] == pytest.approx(p["width"], abs=0.03) and size[0] == pytest.approx(p["depth"], abs=0.03)
    assert bp.bounds()[0, 2] == pytest.approx(0.0, abs=1e-9)
    used = {pc.material for part in bp.parts.values() for pc in part.pieces}
    assert used <= set(bp.materials)
    for part in bp.parts.values():
        assert {pc.material for pc in part.pieces}


@pytest.mark.parametrize("seed", SEEDS)
def test_levels_are_pinned_not_jointed(seed):
    """A pallet-rack level is re-pinned in the uprights' holes by hand, unloaded: it is fixed to the frame, its
    beams resting on their brackets (no joint slides a level up the uprights); the rack's moving parts are the
    drawers of the drawer cabinets on its bottom levels."""
    p, bp = make(seed)
    for name in levels(bp):
        assert by_child(bp, name).kind == "fixed" and by_child(bp, name).parent == "frame"
    assert not [j for j in bp.joints if bp.parts[j.child].label == "shelf" and j.kind != "fixed"]
    # its moving parts are drawers: every bay's bottom level carries drawer cabinets
    bottoms = [n for n in levels(bp) if n.endswith("_0")]
    assert all(any(n.startswith(f"{lv}_cabinet_") for n in bp.parts) for lv in bottoms)
    assert any(j.kind == "prismatic" and bp.parts[j.child].label == "drawer" for j in bp.joints)


@pytest.mark.parametrize("seed", SEEDS)
def test_goods_are_fixed_to_their_level(seed):
    _, bp = make(seed, has_goods=True, goods_chance=1.0)
    goods = [n for n, part in bp.parts.items() if part.label in ("box", "pallet", "cabinet")]
    assert goods
    for n in goods:
        j = by_child(bp, n)
        assert j.kind == "fixed" and bp.parts[j.parent].label == "shelf"


@pytest.mark.parametrize("seed", SEEDS)
def test_every_state_is_free(seed):
    """Rest, every drawer out at 50 % and 100 %, and each drawer out alone."""
    _, bp = make(seed, has_goods=True, goods_chance=1.0)
    movers = [j.child for j in bp.joints if j.kind == "prismatic"]
    states = [{}, {m: 0.5 for m in movers}, {m: 1.0 for m in movers}] + [{m: 1.0} for m in movers]
    for s in states:
        assert contacts(bp, s) == [], s


def test_overrides():
    p, bp = make(0, bay_count=2, level_count=5, width=2.8)
    assert len(levels(bp)) == 10
    _, bp = make(0, has_goods=False)
    assert not any(part.label in ("box", "pallet") for part in bp.parts.values())
    _, bp = make(1, deck="wood", level_count=3, bay_count=1)
    assert len(levels(bp)) == 3
    assert any(pc.material == "deck_wood" for pc in bp.parts["level_0_0"].pieces)


def test_seeds_differ():
    params = [sr.CATEGORY.schema.sample(streams("storage_rack", s)["params"]) for s in range(12)]
    for name in ("deck", "level_count", "has_goods", "frame_finish"):
        assert len({p[name] for p in params}) > 1, name


@pytest.mark.parametrize("seed", range(3))
@pytest.mark.parametrize("design", ["shelving", "bin_rack"])
def test_totes_and_bins_slide_out_and_lids_open_once_out(design, seed):
    """Forced by ``design=``: every tote or bin slides out along +X from a fixed level, a lid hinges
    up about its tote's back edge and only once the tote is out; every state stays free."""
    p, bp = make(seed, design=design)
    assert p["design"] == design
    goods = [n for n, part in bp.parts.items() if part.label in ("box", "bin")]
    lids = [n for n, part in bp.parts.items() if part.label == "lid"]
    assert len(goods) >= 2 * (p["shelf_levels"] if design == "shelving" else p["bin_levels"])
    for name in levels(bp):
        assert by_child(bp, name).kind == "fixed"
    for n in goods:
        j = by_child(bp, n)
        d = j.dofs[0]
        assert j.kind == "prismatic" and bp.parts[j.parent].label == "shelf"
        assert d.axis == pytest.approx((1, 0, 0)) and 0 < d.upper < p["shelf_depth"]
    for n in lids:
        j = by_child(bp, n)
        assert j.kind == "revolute" and j.requires_open == j.parent and bp.parts[j.parent].label == "box"
        assert j.dofs[0].axis == pytest.approx((0, -1, 0))
    if design == "bin_rack":
        assert not lids
    ps = {n: np.eye(4) for n in bp.parts}
    names = list(bp.parts)
    for i, a in enumerate(names):  # at rest nothing meets anything but its parent or child
        for b in names[i + 1:]:
            if any({j.parent, j.child} == {a, b} for j in bp.joints):
                continue
            assert overlap(bp.parts[a], ps[a], bp.parts[b], ps[b]) < VOL, (a, b)


def test_shelving_has_lidded_and_open_totes():
    kinds = set()
    for seed in range(4):
        _, bp = make(seed, design="shelving")
        totes = [n for n, part in bp.parts.items() if part.label == "box"]
        kinds |= {any(j.parent == t for j in bp.joints) for t in totes}
    assert kinds == {True, False}


def test_drawer_cabinets_on_pallet_levels():
    """Forced by ``has_goods`` / ``goods_chance=1``: on some levels the goods are modular drawer cabinets
    (a level's goods kind is drawn per level, so several seeds are looked at). A cabinet is fixed on its level;
    its drawers stack inside it, each sliding out along +X on full-extension slides; every state is free:
    rest, all drawers out, all drawers out with every level raised, and each drawer out alone."""
    found = 0
    for seed in range(6):
        p, bp = make(seed, has_goods=True, goods_chance=1.0)
        cabinets = [n for n, part in bp.parts.items() if part.label == "cabinet"]
        if not cabinets:
            continue
        found += 1
        drawers = []
        for c in cabinets:
            j = by_child(bp, c)
            assert j.kind == "fixed" and bp.parts[j.parent].label == "shelf"
            box = np.vstack([pc.vertices for pc in bp.parts[c].pieces])
            kids = [j.child for j in bp.joints if j.parent == c]
            assert 1 <= len(kids) <= 10
            for k in kids:
                jk = by_child(bp, k)
                d = jk.dofs[0]
                assert jk.kind == "prismatic" and bp.parts[k].label == "drawer"
                assert d.axis == pytest.approx((1, 0, 0))
                v = np.vstack([pc.vertices for pc in bp.parts[k].pieces])
                assert d.upper >= 0.9 * np.ptp(v[:, 0]) - 0.03  # nearly all of the drawer comes out
                # inside its housing across and up; its front (and pull) at the housing's open front
                assert v[:, 1].min() > box[:, 1].min() and v[:, 1].max() < box[:, 1].max()
                assert v[:, 2].min() > box[:, 2].min() and v[:, 2].max() < box[:, 2].max()
                assert v[:, 0].max() > box[:, 0].max()
            drawers += kids
        levels_ = [j.child for j in bp.joints if j.kind == "prismatic" and bp.parts[j.child].label == "shelf"]
        every = {d: 1.0 for d in drawers}
        for s in ({}, every, {**every, **{m: 1.0 for m in levels_}}, *({d: 1.0} for d in drawers)):
            assert contacts(bp, s) == [], (seed, s)
    assert found >= 2


@pytest.mark.parametrize("design", ["shelving", "bin_rack"])
def test_totes_and_bins_stay_on_their_deck(design):
    """Slid fully out, a tote or bin still has its middle over its level's deck (further it would tip off: it is
    lifted off from there, not slid through the air)."""
    for seed in range(6):
        _, bp = make(seed, design=design)
        for n, part in bp.parts.items():
            if part.label not in ("box", "bin"):
                continue
            j = by_child(bp, n)
            x = np.vstack([pc.vertices for pc in part.pieces])[:, 0]
            deck_front = max(pc.bounds[1, 0] for pc in bp.parts[j.parent].pieces)
            assert (x.min() + x.max()) / 2 + j.dofs[0].upper <= deck_front + 1e-9, (seed, n)


@pytest.mark.parametrize("count", [1, 2, 3])
def test_cabinet_and_drawer_slots_tile_without_overlap(count):
    """Cabinets side by side stay inside the bay with a gap between them; a cabinet's drawers stack inside it,
    each above the last with a gap, and none reaches the cabinet's top panel."""
    from infmob_usd.categories.parts import racks as R

    span = (-1.2, 1.2)
    slots = R.cabinet_slots(span, count, 1.0)
    assert slots.xs[0] < slots.xs[1] <= 0.5
    assert span[0] <= slots.ys[0][0] and slots.ys[-1][1] <= span[1]
    for (_a0, a1), (b0, _b1) in zip(slots.ys, slots.ys[1:]):
        assert a1 + R.CAB_GAP <= b0 + 1e-12
    z, h = 0.1, 0.6
    xs, ys, zss = R.drawer_slots(slots.xs, slots.ys[0], z, h, 4)
    assert slots.xs[0] < xs[0] < xs[1] < slots.xs[1] and slots.ys[0][0] < ys[0] < ys[1] < slots.ys[0][1]
    assert len(zss) == 4 and zss[0][0] > z and zss[-1][1] < z + h - R.CAB_PANEL
    for (a0, a1), (b0, b1) in zip(zss, zss[1:]):
        assert a0 < a1 < b0 < b1


def test_grammar_shares_and_ranges_come_from_the_sourced_table():
    """The category draws what parts/rack_sizes.py lists: every numeric range of PARAMS is the table's."""
    from infmob_usd.categories.parts.rack_sizes import STORAGE_RACK_RANGES

    ranges = {p.name: (p.low, p.high) for p in sr.PARAMS if hasattr(p, "low")}
    assert ranges == STORAGE_RACK_RANGES
