"""A knife lies on its side: folding tools turn out of the handle's open side to straight about their pivot pin,
each in its own layer; a utility knife's blade slides out of the nose: checked on the grounded blueprint."""

from __future__ import annotations

import math

import numpy as np

from helpers import maker
from helpers import part_points as _points

make = maker("knife")


def _tools(bp):
    return [s for s in bp.joints if s.movable and s.parent == "body"]


def test_multi_tool_folds_each_tool_into_the_handle_and_out_straight():
    _, bp = make(1, design="multi_tool")
    tools = _tools(bp)
    assert 2 <= len(tools) <= 5
    body = _points(bp, "body")
    x0, x1 = body[:, 0].min(), body[:, 0].max()
    layers = []
    for s in tools:
        d = s.dofs[0]
        assert np.allclose(np.abs(d.axis), (0, 0, 1)) and math.isclose(d.upper, math.pi)  # in the table's plane
        pts = _points(bp, s.child)
        # folded: inside the handle's length and height, between its scales
        assert pts[:, 0].min() >= x0 - 1e-6 and pts[:, 0].max() <= x1 + 1e-6
        assert body[:, 2].min() < pts[:, 2].min() and pts[:, 2].max() < body[:, 2].max()
        layers.append((round(pts[:, 2].min(), 5), round(pts[:, 2].max(), 5)))
        # opened straight, it stands out of the handle's front (blades) or back (openers) end
        out = _points(bp, s.child, bp.poses({(s.child, 0): d.upper})[s.child])
        assert out[:, 0].max() > x1 + 0.02 or out[:, 0].min() < x0 - 0.02
    assert len(set(layers)) == len(layers)  # one tool per layer: they turn past each other


def test_utility_blade_slides_out_of_the_nose():
    _, bp = make(0, design="utility")
    (s,) = _tools(bp)
    d = s.dofs[0]
    assert d.type == "prismatic" and np.allclose(d.axis, (1, 0, 0)) and d.upper > 0.015
    body, blade = _points(bp, "body"), _points(bp, "blade")
    assert blade[:, 0].max() < body[:, 0].max()  # retracted: the point inside the nose
    out = _points(bp, "blade", bp.poses({("blade", 0): d.upper})["blade"])
    assert out[:, 0].max() > body[:, 0].max() + 0.015


def _piece_points(bp, part, name, pose=None):
    pts = np.vstack([pc.vertices for pc in bp.parts[part].pieces if pc.name == name])
    pose = np.eye(4) if pose is None else pose
    return pts @ pose[:3, :3].T + pose[:3, 3]


def test_a_blade_is_satin_flat_with_a_bright_ground_bevel_along_its_edge():
    for design in ("pocket", "multi_tool", "utility"):
        _, bp = make(2, design=design)
        blades = [s.child for s in _tools(bp) if bp.parts[s.child].pieces[0].name.endswith("blade")
                  or s.child == "blade"]
        assert blades, design
        for blade in blades:
            pieces = {pc.name: pc for pc in bp.parts[blade].pieces}
            grind = pieces.get("grind")
            assert grind is not None, f"{design}: no ground bevel on {blade}"
            assert bp.materials[grind.material].startswith("chrome")  # polished, unlike the satin flats
            flat = bp.parts[blade].pieces[0]
            assert bp.materials[flat.material].startswith(("brushed_metal", "chrome"))
            assert np.ptp(grind.vertices[:, 2]) <= np.ptp(flat.vertices[:, 2]) + 1e-9


def test_the_utility_blade_leaves_only_through_the_nose_front():
    from scipy.spatial import ConvexHull

    for seed in range(4):
        _, bp = make(seed, design="utility", cutter="retractable")
        (s,) = _tools(bp)
        body = _piece_points(bp, "body", "half")
        plan = ConvexHull(body[:, :2])
        out = _piece_points(bp, "blade", "blade", bp.poses({("blade", 0): s.dofs[0].upper})["blade"])[:, :2]
        ring = out[ConvexHull(out).vertices]
        t = np.linspace(0.0, 1.0, 50)[:, None, None]
        edge = (ring[None] + t * (np.roll(ring, -1, 0) - ring)[None]).reshape(-1, 2)  # along the blade's outline
        inside = edge[edge[:, 0] < body[:, 0].max() - 1e-4]
        # every blade point still over the handle lies in the handle's plan (none through its top edge)
        assert (inside[:, :2] @ plan.equations[:, :2].T + plan.equations[:, 2]).max() <= 1e-6, seed
