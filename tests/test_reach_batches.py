"""SAPIEN ``reach`` drives parts that cannot touch each other together, and that never changes a verdict.

A shelf with three drawers: two 1.2 m apart (one run is enough for both) and one stacked 1 cm above
the first (never in the same run as it). A stop on the shelf in front of one far drawer blocks it:
the batched check must report exactly what driving every joint alone reports.
"""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("sapien")

import infmob_usd  # noqa: E402
from infmob_usd import geometry as g  # noqa: E402
from infmob_usd import joints as J  # noqa: E402
from infmob_usd.api import assemble  # noqa: E402
from infmob_usd.blueprint import Blueprint  # noqa: E402
from infmob_usd.validate import sim  # noqa: E402

pytestmark = pytest.mark.sim


def shelf(blocked: bool) -> Blueprint:
    bp = Blueprint("shelf", materials={"m": "painted", "t": "plastic"})
    body = [g.box_between([-0.3, -1.0, 0.0], [0.3, 1.0, 0.02], "m")]
    if blocked:  # a post 10 cm in front of drawer b's face: it stops b after ~10 of its 30 cm
        body.append(g.box_between([0.3, 0.65, 0.04], [0.34, 0.85, 0.3], "m"))
    bp.add("body", "body", body)
    # b rides on a carriage that lifts 1 cm: PhysX ignores contacts between a link and its parent,
    # so the post (on the body) must not be b's parent to stop it
    bp.add("carriage", "drawer", [g.box_between([-0.2, 0.6, 0.021], [0.2, 0.9, 0.029], "t")])
    bp.join(J.prismatic("body", "carriage", (0.0, 0.75, 0.021), (0, 0, 1), 0.0, 0.01))
    for name, parent, y0, z0 in (("a", "body", -0.9, 0.03), ("b", "carriage", 0.6, 0.04),
                                 ("c", "body", -0.9, 0.12)):
        bp.add(name, "drawer", [g.box_between([-0.2, y0, z0], [0.2, y0 + 0.3, z0 + 0.08], "t")])
        bp.join(J.prismatic(parent, name, (0.2, y0 + 0.15, z0), (1, 0, 0), 0.0, 0.3))
    return bp


def _context(folder):
    meta = sim._read_meta(folder)
    urdf = sim._find_urdf(folder, meta)
    scene, art = sim.load_sapien(urdf)
    ctx = sim._context(folder, meta, urdf, scene, art)
    ctx.reset()
    return ctx


def _reach(folder, batch: bool, monkeypatch):
    monkeypatch.setattr(sim, "REACH_BATCH", batch)
    return {c.name: c for c in sim.check_sapien(folder, checks=["reach"])}["reach"]


def test_parts_apart_share_a_run_and_stacked_parts_do_not(tmp_path, monkeypatch):
    folder = infmob_usd.save(assemble(shelf(False), 0, np.random.default_rng(0), 16), tmp_path / "ok")
    ctx = _context(folder)
    names = [j.name for j in ctx.joints]
    batches = [sorted(names[i].removeprefix("joint_") for i in b) for b in sim._reach_batches(ctx, {})]
    assert ["a", "b"] not in batches and ["b", "carriage"] not in batches  # b's carriage carries b
    assert any("a" in b and len(b) > 1 for b in batches) and not any({"a", "c"} <= set(b) for b in batches), \
        batches
    opened = sim._reach_plans(ctx.meta)[1].start_q(ctx, [])  # every part out: the second start state
    from_open = sim._reach_batches(ctx, {}, opened)
    batched, alone = _reach(folder, True, monkeypatch), _reach(folder, False, monkeypatch)
    assert batched.ok and alone.ok, (batched.detail, alone.detail)
    assert f"in {len(batches) + len(from_open)} runs" in batched.detail and "runs" not in alone.detail.split(";")[0]


def test_a_blocked_part_in_a_run_fails_as_it_does_alone(tmp_path, monkeypatch):
    from infmob_usd import physical

    monkeypatch.setattr(physical, "limit_to_clearance", lambda obj: obj)  # the core would shorten b
    folder = infmob_usd.save(assemble(shelf(True), 0, np.random.default_rng(0), 16), tmp_path / "bad")
    ctx = _context(folder)
    names = [j.name for j in ctx.joints]
    assert any("joint_b" in {names[i] for i in b} and len(b) > 1 for b in sim._reach_batches(ctx, {}))
    batched, alone = _reach(folder, True, monkeypatch), _reach(folder, False, monkeypatch)
    assert not batched.ok and not alone.ok
    assert batched.detail.split("; held")[0] == alone.detail.split("; held")[0], (batched.detail, alone.detail)
    # from rest b stops at the post; from the all-open state it starts through it (more misses there)
    assert "joint_b -> upper 0.3: stopped at 0.1 " in batched.detail, batched.detail
