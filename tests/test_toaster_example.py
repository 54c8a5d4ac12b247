"""The newcomer's toaster (docs/examples/toaster.py): written on the part contract, it builds, has no
coordinate arithmetic to speak of, and passes validation."""

from __future__ import annotations

import importlib.util
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import infmob_usd
from infmob_usd.seeding import streams

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "docs" / "examples" / "toaster.py"


def load_example():
    spec = importlib.util.spec_from_file_location("toaster_example", EXAMPLE)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def build(seed: int, **over):
    cat = load_example().CATEGORY
    r = streams("toaster", seed)
    p = cat.schema.sample(r["params"], over)
    return cat, p, r, cat.build(p, r["structure"], r["geometry"])


def test_toaster_is_written_with_under_40_literals():
    out = subprocess.run([sys.executable, str(ROOT / "tools" / "literals.py"), str(EXAMPLE)], capture_output=True,
                         text=True, check=True).stdout
    assert int(out.split()[1]) < 40, out


def test_toaster_parts_sit_where_the_casing_anchors_put_them():
    for seed in range(4):
        _, p, _, bp = build(seed)
        joints = {j.child: j for j in bp.joints}
        lever, dial, tray = joints["lever"], joints["dial"], joints["tray"]
        assert lever.kind == "prismatic" and np.allclose(lever.dofs[0].axis, (0, 0, -1))  # slides down
        assert lever.dofs[0].lower == 0 and lever.dofs[0].upper > 0.05  # rests at the top
        assert dial.kind == "revolute" and np.allclose(dial.dofs[0].axis, (1, 0, 0))
        assert tray.kind == "prismatic" and np.allclose(tray.dofs[0].axis, (1, 0, 0))  # pulls out the front
        lo, hi = bp.bounds()
        assert np.allclose(hi - lo, (p["depth"], p["width"], p["height"]), atol=0.03)
        body = np.array([pc.bounds for pc in bp.parts["body"].pieces])
        tray_lo = np.array([pc.bounds for pc in bp.parts["tray"].pieces])[:, 0].min(0)
        assert tray_lo[2] > body[:, 0, 2].min()  # the tray stands on the floor plate, not under it


def test_same_slot_and_substrate_follow_the_finish():
    for finish in ("painted", "plastic"):
        _, _, _, bp = build(1, finish=finish)
        assert bp.materials["tray_front"] == bp.materials["body"]
        assert bp.densities.get("body") == (7850.0 if finish == "painted" else None)


@pytest.mark.sim
def test_toaster_validates_with_its_spring_held_lever(tmp_path):
    """Every check passes, rest included: the lever's return spring (role ``lever``) holds it at its top
    stop in SAPIEN and MuJoCo, where without one gravity pulls it 18-80 mm down its slot."""
    pytest.importorskip("sapien")
    from infmob_usd.api import assemble
    from infmob_usd.validate import validate_object

    cat, p, r, bp = build(3)
    obj = assemble(bp, 3, r["materials"], 16, p, {})
    result = validate_object(infmob_usd.save(obj, tmp_path), sim=True, physics=True)
    assert result.ok, {c.name: c.detail for c in result.checks if not c.ok}
