"""A DSLR's zoom ring drives its inner barrel out (coupled joints, the whole throw kept) and a compact's
telescoping lens stands out by both stages: checked on the grounded blueprint with the generated limits."""

from __future__ import annotations

import numpy as np

from categories.parts import cameras as K

from helpers import maker
from zoo import object_limits

make = maker("camera")


def _limited(**overrides):
    _, bp = make(0, **overrides)
    return object_limits("camera", 0, bp, **overrides)


def test_the_zoom_ring_drives_the_inner_barrel_its_whole_throw():
    bp = _limited(design="dslr", has_screen=False, has_door=False, reach=1.0)
    ring = next(j for j in bp.joints if j.child == "zoom_ring")
    barrel = next(j for j in bp.joints if j.child == "barrel")
    assert barrel.mimic is not None and barrel.mimic.leader == "zoom_ring"
    assert np.allclose(ring.dofs[0].axis, (1, 0, 0)) and np.allclose(barrel.dofs[0].axis, (1, 0, 0))
    assert ring.dofs[0].upper > 0.95 * K.ZOOM_TURN  # nothing cut the zoom short
    out = barrel.mimic.ratio * ring.dofs[0].upper
    assert abs(out - barrel.dofs[0].upper) < 1e-6 and out > 0.018  # an 18-55 zooms ~20 mm out


def test_a_two_stage_lens_stands_out_by_both_stages():
    bp = _limited(design="compact", has_inner_stage=True)
    stages = [j for j in bp.joints if j.child in ("barrel", "inner_barrel")]
    assert [j.parent for j in stages] == ["body", "barrel"]  # the inner stage rides in the outer
    q = {(j.child, 0): j.dofs[0].upper for j in stages}
    front = lambda q: max(bp.poses(q)["inner_barrel"][0, 3] + p.vertices[:, 0].max()  # noqa: E731
                          for p in bp.parts["inner_barrel"].pieces)
    assert front(q) - front({}) > 0.02  # two stages of 11-12 mm


def test_the_front_element_is_a_glossy_dome_behind_a_printed_rim():
    from infmob_usd.materials import FAMILIES, split_spec

    for design in ("dslr", "compact", "instant"):
        _, bp = make(1, design=design)
        part = next(n for n, p in bp.parts.items() if any(pc.name == "element" for pc in p.pieces))
        pieces = {pc.name: pc for pc in bp.parts[part].pieces}
        glass = pieces["element"]
        fam = FAMILIES[split_spec(bp.materials[glass.material])[0]]
        assert fam.roughness[1] <= 0.1  # a coated front element mirrors the room, it is not a matte disc
        x = glass.vertices[:, 0]
        assert np.ptp(x) >= 0.004  # domed: a meniscus 3-5 mm deep, not a flat plate
        rim = pieces["rim"].vertices[:, 0].max()
        assert x.max() < rim  # the dome stays behind the rim's face
        assert bp.materials[pieces["print"].material].endswith("white")  # the printed ring and inscription


def test_a_camera_carries_strap_lugs_on_its_sides():
    for design, count in (("dslr", 2), ("compact", 1), ("instant", 2)):
        _, bp = make(1, design=design)
        lugs = [pc.vertices for pc in bp.parts["body"].pieces if pc.name == "strap_lugs"]
        assert lugs, design
        pts = np.vstack(lugs)
        body = next(pc.vertices for pc in bp.parts["body"].pieces if pc.name == "body")
        sides = {int(np.sign(y)) for y in pts[:, 1] if abs(y) > body[:, 1].max() - 1e-6}
        assert len(sides) == count, (design, sides)


def _designs(category, seeds=range(100)):
    from infmob_usd import api
    from infmob_usd.seeding import streams

    schema = api.get_category(category).schema
    return {schema.sample(streams(category, s)["params"], {})["design"] for s in seeds}


def test_seeds_draw_five_camera_families():
    assert _designs("camera") == {"dslr", "mirrorless", "compact", "instant", "action"}


def _body(bp, name):
    return next(pc.vertices for pc in bp.parts["body"].pieces if pc.name == name)


def test_a_mirrorless_camera_zooms_on_a_slimmer_body_under_its_viewfinder():
    _, dslr = make(0, design="dslr", has_screen=False)
    for evf in ("hump", "corner"):
        _, bp = make(0, design="mirrorless", viewfinder=evf, has_screen=False)
        barrel = next(j for j in bp.joints if j.child == "barrel")
        assert barrel.mimic is not None and barrel.mimic.leader == "zoom_ring"  # the kit zoom's ring drives it
        body = _body(bp, "body")
        assert np.ptp(body[:, 0]) < np.ptp(_body(dslr, "body")[:, 0])  # no mirror box: a slimmer body
        assert np.ptp(body[:, 2]) < np.ptp(_body(dslr, "body")[:, 2])
        if evf == "hump":  # the EVF in a hump over the lens, its eyepiece on the hump's back
            hump = _body(bp, "evf")
            assert hump[:, 2].max() > body[:, 2].max() + 0.01
        else:  # a flat top plate, the eyecup standing out of the back's corner away from the grip (-y)
            cup = _body(bp, "eyecup")
            assert not any(pc.name == "evf" for pc in bp.parts["body"].pieces)
            assert cup[:, 0].min() < body[:, 0].min() - 0.004 and cup[:, 1].min() > 0


def test_an_action_camera_has_a_fixed_lens_a_shutter_on_top_and_a_side_door():
    _, bp = make(0, design="action")
    moving = {j.child: j.dofs[0].type for j in bp.joints if j.movable}
    assert moving == {"shutter": "prismatic", "door": "revolute"}
    body = _body(bp, "body")
    assert 0.070 <= np.ptp(body[:, 1]) <= 0.073 and np.ptp(body[:, 2]) <= 0.052  # GoPro HERO12, Osmo Action 4
    lens = _body(bp, "element")
    assert lens[:, 0].max() > body[:, 0].max()  # the lens stands out of the front
    assert lens[:, 1].mean() > 0 > _body(bp, "front_screen")[:, 1].mean()  # the status screen beside it
