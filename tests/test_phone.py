"""A flip phone's lid and a slider phone's screen half uncover the keypad they guard, a desk phone's handset lifts
out of its cradle: checked on the grounded blueprint."""

from __future__ import annotations

import numpy as np
import pytest

from helpers import maker

make = maker("phone")


def _points(bp, part):
    return np.vstack([pc.vertices for pc in bp.parts[part].pieces])


def _joint(bp, child):
    return next(s for s in bp.joints if s.child == child)


def _keys(bp, prefix):
    return [s for s in bp.joints if s.movable and s.child.startswith(prefix)]


def test_a_flip_phones_lid_opens_off_its_keypad_about_the_hinge_at_the_top():
    _, bp = make(0, design="flip")
    lid = _joint(bp, "lid").dofs[0]
    base = _points(bp, "body")
    assert lid.type == "revolute" and abs(lid.axis[1]) > 0.99 and lid.upper > np.radians(140)
    assert lid.origin[0] < base[:, 0].min() + 0.01  # the hinge at the far end: it opens away from the front
    keys = _keys(bp, "keypad_") + _keys(bp, "nav_keys_")
    assert len(_keys(bp, "keypad_")) == 12 and all(s.requires_open == "lid" for s in keys)
    closed = _points(bp, "lid")
    pose = bp.poses({("lid", 0): np.radians(90)})["lid"]
    opened = closed @ pose[:3, :3].T + pose[:3, 3]
    for s in keys:  # closed it lies over every key; at 90 degrees it stands clear of them
        k = _points(bp, s.child)
        assert closed[:, 2].max() > k[:, 2].max() and closed[:, 0].min() < k[:, 0].mean() < closed[:, 0].max()
        assert opened[:, 0].max() < k[:, 0].min()


def test_a_slider_phones_screen_half_slides_off_its_keypad():
    _, bp = make(0, design="slider")
    half = _joint(bp, "slider")
    d = half.dofs[0]
    assert d.type == "prismatic" and d.axis[0] < -0.99
    pad = [_points(bp, s.child) for s in _keys(bp, "keypad_")]
    assert len(pad) == 12 and all(s.requires_open == "slider" for s in _keys(bp, "keypad_"))
    front = _points(bp, "slider")[:, 0].max()
    assert front - d.upper < min(k[:, 0].min() for k in pad)  # slid up, it uncovers the whole pad
    assert all(s.parent == "slider" for s in _keys(bp, "nav_"))  # its navigation keys ride on it


def test_a_desk_phones_handset_lifts_out_of_its_cradle():
    _, bp = make(0, design="desk")
    hs = _joint(bp, "handset")
    assert hs.role == "lift_off" and np.allclose(hs.dofs[0].axis, (0, 0, 1)) and hs.dofs[0].upper >= 0.02
    assert _points(bp, "handset")[:, 1].mean() < 0  # on the left, seen from the front
    assert len(_keys(bp, "keypad_")) == 12 and 3 <= len(_keys(bp, "function_keys_")) <= 10


def test_seeds_draw_four_phone_families():
    from infmob_usd import api
    from infmob_usd.seeding import streams

    schema = api.get_category("phone").schema
    assert {schema.sample(streams("phone", s)["params"], {})["design"] for s in range(100)} == {
        "flip", "slider", "bar", "desk"}


def test_a_bar_phone_has_its_screen_over_its_keys_on_one_shell():
    _, bp = make(0, design="bar", has_battery_cover=True)
    assert {s.child for s in bp.joints if s.movable and not s.child.startswith(("keypad_", "nav_keys_"))} == {
        "battery_cover"}  # no lid, no slide: one shell
    keys = _keys(bp, "keypad_") + _keys(bp, "nav_keys_")
    assert len(_keys(bp, "keypad_")) == 12 and all(s.requires_open is None for s in keys)
    body = _points(bp, "body")
    assert 0.10 <= np.ptp(body[:, 0]) <= 0.115 and 0.043 <= np.ptp(body[:, 1]) <= 0.049  # Nokia 3310, 1100
    screen = next(pc.vertices for pc in bp.parts["body"].pieces if pc.name == "screen")
    # lying as picked up, its top end (the screen) away from the front: every key nearer the bottom end
    assert all(_points(bp, s.child)[:, 0].min() > screen[:, 0].max() for s in keys)
    assert np.ptp(screen[:, 0]) > 0.22 * np.ptp(body[:, 0])  # a real screen, not a strip


def test_a_desk_phones_handset_sits_in_pockets_over_its_hook_switch():
    """Lifted, the handset reads as taken out of its cradle, not floating: each cup sits in a pocket walled on its
    outer end and both sides, clear of the walls, and the hook switch's plunger stands under the grip."""
    for seed in range(3):
        _, bp = make(seed, design="desk")
        body = [pc.bounds for pc in bp.parts["body"].pieces]
        grip = next(pc.bounds for pc in bp.parts["handset"].pieces if not pc.name)
        for cup in (pc.bounds for pc in bp.parts["handset"].pieces if pc.name == "cup"):
            (x0, y0, z0), (x1, y1, _) = cup
            walls = [b for b in body if b[1][2] > z0 + 0.005 and b[0][0] < x1 + 0.01 and b[1][0] > x0 - 0.01
                     and b[0][1] < y1 + 0.01 and b[1][1] > y0 - 0.01]
            assert len(walls) >= 3, seed
            for (a0, b0, _), (a1, b1, _) in walls:  # clear of the cup all round: it lifts straight out
                assert a1 <= x0 - 0.001 or a0 >= x1 + 0.001 or b1 <= y0 - 0.001 or b0 >= y1 + 0.001
        under = [b for b in body if b[0][0] > grip[0][0] and b[1][0] < grip[1][0] and b[0][1] > grip[0][1] - 0.01
                 and b[1][1] < grip[1][1] + 0.01 and grip[0][2] - 0.005 < b[1][2] < grip[0][2]]
        assert under, seed


def _overlap(a, b) -> float:
    import manifold3d

    hull = manifold3d.Manifold.hull_points
    return (hull(np.asarray(a, float)) ^ hull(np.asarray(b, float))).volume()


def test_a_shells_rims_stand_on_its_floor_hull_not_through_it():
    """The shell collides as a floor under the keymat and the rims round the keys standing on it: rims reaching
    down through the floor put a second bottom face under a slider's half, and PhysX then pushes the half down
    onto a key it passes 2.5 mm over (seed 236's slider stopped at a third of its travel in SAPIEN's reach
    check)."""
    for design in ("flip", "slider", "bar", "desk"):
        _, bp = make(0, design=design)
        for part in ("body", "slider"):
            if part not in bp.parts:
                continue
            hulls = [h for pc in bp.parts[part].pieces if pc.name == "shell" for h in pc.convex]
            assert len(hulls) >= 5
            span = [np.ptp(np.asarray(h)[:, :2], axis=0).prod() for h in hulls]
            floor = hulls[int(np.argmax(span))]  # the slab under the keymat: the only hull across the whole plan
            worst = max(_overlap(floor, h) for h in hulls if h is not floor)
            assert worst < 1e-10, f"{design} {part}: hulls overlap the floor by {worst * 1e9:.0f} mm^3"


@pytest.mark.sim
def test_seed_236s_screen_half_slides_over_its_keypad_in_sapien(tmp_path):
    pytest.importorskip("sapien")
    import infmob_usd
    from infmob_usd.validate.sim import check_sapien

    folder = infmob_usd.save(infmob_usd.generate("phone", seed=236, texture_size=16), tmp_path)
    res = {c.name: c for c in check_sapien(folder, checks=["reach"])}
    assert res["reach"].ok, res["reach"].detail
