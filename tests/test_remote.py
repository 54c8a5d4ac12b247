"""A remote's keys are a keypad on its top face that press down against their springs, its flip cover guards the
keys under it, and its battery door slides out of the underside: checked on the grounded blueprint."""

from __future__ import annotations

import numpy as np

from helpers import maker

make = maker("remote")


def _points(bp, part):
    return np.vstack([pc.vertices for pc in bp.parts[part].pieces])


def _keys(bp):
    return [s for s in bp.joints if s.movable and bp.parts[s.child].label == "button"]


def test_a_tv_remote_has_a_numeric_keypad_of_keys_pressed_down():
    _, bp = make(0, design="tv", has_numpad=True, has_colour_keys=True)
    keys = _keys(bp)
    assert 10 <= len(keys) <= 50
    top = _points(bp, "body")[:, 2].max()
    for s in keys:
        d = s.dofs[0]
        assert d.type == "prismatic" and s.role == "button"
        assert np.allclose(d.axis, (0, 0, -1)) and 0.0008 <= d.upper <= 0.002  # a rubber dome's 1-1.5 mm
        assert _points(bp, s.child)[:, 2].min() < top  # let into the face, not floating on it
    # 1-9 and 0: three columns of keys in rows along the remote
    pad = np.array([_points(bp, s.child).mean(0) for s in keys if s.child.startswith("numpad_")])
    assert len(pad) >= 10
    assert len(np.unique(np.round(pad[:9, 1], 4))) == 3 and len(np.unique(np.round(pad[:9, 0], 4))) == 3
    assert {s.child.split("_")[0] for s in keys} >= {"top", "numpad", "volume", "navigation", "colour"}


def test_the_keys_under_an_ac_remotes_cover_wait_for_it_to_open():
    _, bp = make(0, design="ac")
    cover = next(s for s in bp.joints if s.child == "cover")
    assert cover.dofs[0].type == "revolute" and cover.dofs[0].upper > np.radians(150)
    under = [s for s in _keys(bp) if s.child.startswith("ac_covered_")]
    assert 6 <= len(under) <= 12 and all(s.requires_open == "cover" for s in under)
    # closed, the cover lies over every key it guards
    lid = bp.parts["cover"].pieces[0].vertices  # its plate
    for s in under:
        k = _points(bp, s.child)
        assert lid[:, 2].min() > k[:, 2].max() and lid[:, 0].min() < k[:, 0].min() < k[:, 0].max() < lid[:, 0].max()


def test_the_battery_door_slides_out_backwards_from_the_underside():
    for design in ("tv", "ac", "presenter", "streaming"):
        _, bp = make(1, design=design, **({"has_battery_door": True} if design == "streaming" else {}))
        door = next(s for s in bp.joints if s.child == "battery_door")
        d = door.dofs[0]
        assert d.type == "prismatic" and d.axis[0] < -0.99 and d.upper > 0.02
        assert _points(bp, "battery_door")[:, 2].max() < 0.005  # in the underside


def test_seeds_draw_four_remote_families():
    from infmob_usd import api
    from infmob_usd.seeding import streams

    schema = api.get_category("remote").schema
    assert {schema.sample(streams("remote", s)["params"], {})["design"] for s in range(100)} == {
        "tv", "streaming", "ac", "presenter"}


def test_a_streaming_remote_is_a_slim_bar_with_a_round_pad_and_few_keys():
    _, bp = make(0, design="streaming", has_battery_door=False, has_apps=False)
    keys = _keys(bp)
    assert 9 <= len(keys) <= 16 and all(s.requires_open is None for s in keys)
    assert not any(s.child == "battery_door" for s in bp.joints)  # rechargeable: no battery bay
    body = _points(bp, "body")
    width, length = np.ptp(body[:, 1]), np.ptp(body[:, 0])
    assert 0.034 <= width <= 0.040 and 0.12 <= length <= 0.16
    pad = np.array([_points(bp, s.child).mean(0) for s in keys if s.child.startswith("stream_pad_")])
    assert len(pad) == 5
    centre, ring = pad[0], pad[1:]
    reach = np.linalg.norm(ring[:, :2] - centre[:2], axis=1)
    assert np.ptp(reach) < 1e-4 and reach.min() > 0.35 * width / 2  # four arrows round the select key
    for s in keys:  # every key within the flat of the face
        k = _points(bp, s.child)
        assert np.abs(k[:, 1]).max() < width / 2 - 0.002
