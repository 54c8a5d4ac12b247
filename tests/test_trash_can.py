"""The trash can: a pedal bin's foot pedal lifts its lid in MuJoCo (one DoF for the foot, the lid coupled to it),
and a pedal bin with an inner bucket passes the SAPIEN checks (reach from rest and from all open: the lid is
not held against its pedal's tendon, and the pedal closes the bail first, as its lid must)."""

from __future__ import annotations

import json

import pytest

import infmob_usd
from infmob_usd.categories.parts import bins as B

pytestmark = pytest.mark.sim

PEDAL_BIN = dict(design="pedal_bin", has_bucket=True, has_bail=True)


@pytest.fixture(scope="module")
def pedal_bin(tmp_path_factory):
    obj = infmob_usd.generate("trash_can", seed=3, texture_size=16, **PEDAL_BIN)
    return infmob_usd.save(obj, tmp_path_factory.mktemp("trash_can") / "pedal_bin", formats="usd,urdf,mjcf")


def test_the_lid_follows_its_pedal(pedal_bin):
    meta = json.loads((pedal_bin / "metadata.json").read_text())
    lid = next(j for j in meta["joints"] if j["name"] == "joint_lid")
    assert lid["mimic"]["joint"] == "joint_pedal"
    assert lid["mimic"]["multiplier"] == pytest.approx(B.LID_OPENS / B.PEDAL_TURN)


def test_pressing_the_pedal_lifts_the_lid_in_mujoco(pedal_bin):
    """A foot's torque on the pedal alone: the lid rises with it, at the coupling's ratio."""
    import mujoco

    m = mujoco.MjModel.from_xml_path(str(next(pedal_bin.glob("*.xml"))))
    d = mujoco.MjData(m)
    ip, il = (mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_JOINT, n) for n in ("joint_pedal", "joint_lid"))
    dp, dl = m.jnt_dofadr[ip], m.jnt_dofadr[il]
    for _ in range(int(1.5 / m.opt.timestep)):
        d.qfrc_applied[:] = 0.0
        d.qfrc_applied[dp] = 15.0  # N m: a foot on a 6 cm tread presses with ~250 N
        mujoco.mj_step(m, d)
    qp, ql = float(d.qpos[m.jnt_qposadr[ip]]), float(d.qpos[m.jnt_qposadr[il]])
    assert qp > 0.8 * m.jnt_range[ip][1], f"the pedal did not go down ({qp:.3f})"
    assert ql > 0.8 * m.jnt_range[il][1], f"the lid did not rise with the pedal ({ql:.3f})"
    assert ql == pytest.approx(B.LID_OPENS / B.PEDAL_TURN * qp, abs=0.05 * m.jnt_range[il][1])
    assert abs(d.qvel[dl]) < 1.0


def test_a_pedal_bin_with_a_bucket_passes_the_sapien_checks(pedal_bin):
    from infmob_usd.validate import validate_object

    meta = json.loads((pedal_bin / "metadata.json").read_text())
    pedal = next(j for j in meta["joints"] if j["name"] == "joint_pedal")
    assert "bail" in pedal.get("requires_closed", []), "the pedal must close the bail its lid would meet"
    report = validate_object(pedal_bin, sim=True)
    failed = [c for c in report.checks if not c.ok]
    assert not failed, [f"{c.name}: {c.detail}" for c in failed]



@pytest.mark.parametrize("seed", [0, 1])
def test_an_open_bins_bucket_lifts_right_out(seed):
    """A lidless bin's one joint is its bucket: the body's walls guide it until its bottom clears the rim, so at
    its limit the bucket stands clear of the body (not a hand's 3 cm lift hidden inside it)."""
    obj = infmob_usd.generate("trash_can", seed=seed, texture_size=16, design="open_bin")
    bucket = next(j for j in obj.movable_joints if j.child == "bucket")
    links = {link.name: link for link in obj.links}

    def lowest_top(name):
        b = [pc.bounds + links[name].origin for pc in links[name].pieces]
        return min(x[0][2] for x in b), max(x[1][2] for x in b)

    bottom, _ = lowest_top("bucket")
    _, rim = lowest_top("body")
    assert bottom + bucket.upper > rim
