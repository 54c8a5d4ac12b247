"""A USB drive's plug is bare at each design's open limit (the cap off it, the sled's plug out of the mouth,
the swivel cover behind the body): checked on the grounded blueprint with the generated object's limits."""

from __future__ import annotations

import numpy as np
import pytest

from helpers import maker
from zoo import object_limits

make = maker("usb")


def _points(bp, part, names=None, q=None):
    pts = np.vstack([pc.vertices for pc in bp.parts[part].pieces if names is None or pc.name in names])
    pose = bp.poses(q or {})[part]
    return pts @ pose[:3, :3].T + pose[:3, 3]


def _opened(design, plug, seed=0):
    overrides = {"design": design, "plug": plug}
    _, bp = make(seed, **overrides)
    bp = object_limits("usb", seed, bp, **overrides)
    (joint,) = [j for j in bp.joints if j.movable]
    return bp, joint, {(joint.child, 0): joint.dofs[0].upper}


@pytest.mark.parametrize("plug", ["a", "c"])
def test_the_cap_comes_off_the_plug(plug):
    bp, joint, opened = _opened("capped", plug)
    tip = _points(bp, "body")[:, 0].max()
    assert joint.dofs[0].axis[0] > 0.99
    assert _points(bp, "cap", q=opened)[:, 0].min() > tip  # its skirt has passed the plug's tip


def test_the_sled_pushes_the_plug_out_of_the_mouth():
    bp, joint, opened = _opened("slider", "a")
    mouth = _points(bp, "body")[:, 0].max()
    shell = ("plug_top", "plug_bottom", "plug_side")
    assert _points(bp, "sled", shell)[:, 0].max() < mouth + 1e-4  # retracted at rest
    out = _points(bp, "sled", shell, q=opened)[:, 0].max() - mouth
    assert out > 0.0105  # nearly all of its 11.75 mm mating length


def test_the_swivel_cover_turns_behind_the_body():
    bp, joint, opened = _opened("swivel", "a")
    assert np.allclose(joint.dofs[0].axis, (0, 0, 1)) and joint.dofs[0].upper > 3.0
    plug_root = _points(bp, "body", ("body",))[:, 0].max()
    assert _points(bp, "cover", q=opened)[:, 0].max() < plug_root  # the plug is bare


@pytest.mark.parametrize("design", ["swivel", "capped", "slider"])
def test_the_plug_is_a_bright_plated_shell_round_a_moulded_insert(design):
    from infmob_usd.materials import FAMILIES, split_spec

    for seed in range(3):
        _, bp = make(seed, design=design, plug="a")
        part = "sled" if design == "slider" else "body"
        pieces = {pc.name: pc for pc in bp.parts[part].pieces}
        shell = FAMILIES[split_spec(bp.materials[pieces["plug_top"].material])[0]]
        # nickel-plated steel (USB 2.0 spec: 'nickel plate'): a metal that mirrors, not a satin grey
        assert shell.metallic == 1.0 and shell.roughness[1] <= 0.1
        assert split_spec(bp.materials[pieces["insert"].material])[0] == "plastic"


def test_a_two_tone_capped_drive_moulds_its_neck_in_the_caps_colour():
    _, bp = make(0, design="capped", accent="black", body_colour="white")
    neck = next(pc for pc in bp.parts["body"].pieces if pc.name == "neck")
    cap = bp.parts["cap"].pieces[0]
    assert neck.material == cap.material
