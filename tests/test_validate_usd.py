import re
import shutil

import pytest

import infmob_usd
from infmob_usd.validate.usd_check import check_usd

from zoo import zoo


@pytest.fixture(scope="module")
def good(tmp_path_factory):
    return infmob_usd.save(zoo(), tmp_path_factory.mktemp("good"))


def _copy(good, tmp_path):
    dst = tmp_path / good.name
    shutil.copytree(good, dst)
    return dst


def _results(folder):
    return {c.name: c for c in check_usd(folder)}


def test_a_good_object_passes_every_usd_check(good):
    res = _results(good)
    assert all(c.ok for c in res.values()), res
    assert set(res) == {"usd_validators", "usd_physics", "joint_frames", "files", "textures", "usd_urdf_agree"}


def test_a_joint_frame_mismatch_is_caught(good, tmp_path):
    bad = _copy(good, tmp_path)
    phys = bad / "payload/physics.usda"
    text = phys.read_text()
    # move the pivot of one joint in body0's frame by 5 cm
    i = text.index('def PhysicsRevoluteJoint "joint_rev_part"')
    j = text.index("physics:localPos0", i)
    k = text.index("\n", j)
    text = text[:j] + "physics:localPos0 = (0.05, 0, 0.5)" + text[k:]
    phys.write_text(text)
    res = _results(bad)
    assert not res["joint_frames"].ok and "joint_rev_part" in res["joint_frames"].detail


def test_a_missing_texture_is_caught(good, tmp_path):
    bad = _copy(good, tmp_path)
    (bad / "textures/body_roughness.png").unlink()
    res = _results(bad)
    assert not res["files"].ok and "body_roughness" in res["files"].detail


def test_a_urdf_that_disagrees_is_caught(good, tmp_path):
    bad = _copy(good, tmp_path)
    urdf = bad / f"{bad.name}.urdf"
    text = urdf.read_text()
    text = re.sub(r'(<joint name="joint_rev_part".*?<axis xyz=")[^"]+', r"\g<1>1 0 0", text, flags=re.S)
    urdf.write_text(text)
    res = _results(bad)
    assert not res["usd_urdf_agree"].ok and "joint_rev_part" in res["usd_urdf_agree"].detail


def test_a_broken_mass_fails_the_validators(good, tmp_path):
    bad = _copy(good, tmp_path)
    phys = bad / "payload/physics.usda"
    text = re.sub(r"\n\s*quatf physics:principalAxes = [^\n]+", "", phys.read_text(), count=1)
    phys.write_text(text)
    res = _results(bad)
    assert not res["usd_validators"].ok


def test_a_misplaced_urdf_collision_hull_is_caught(good, tmp_path):
    folder = _copy(good, tmp_path)
    urdf = folder / f"{folder.name}.urdf"
    text = urdf.read_text()
    # move the first collision hull 5 mm along x
    text = re.sub(r'(<collision name="[^"]+"><origin xyz=")([-0-9.e]+)',
                  lambda m: m.group(1) + str(float(m.group(2)) + 0.005), text, count=1)
    urdf.write_text(text)
    res = _results(folder)
    assert not res["usd_urdf_agree"].ok and "collision hull" in res["usd_urdf_agree"].detail


def test_shell_wedges_share_one_collision_file_per_band(tmp_path):
    import xml.etree.ElementTree as ET

    import infmob_usd

    folder = infmob_usd.save(infmob_usd.generate("pot", seed=1, texture_size=16), tmp_path)
    links = ET.parse(folder / f"{folder.name}.urdf").getroot().findall("link")
    cols = [c for link in links for c in link.findall("collision")]
    files = {c.find("geometry/mesh").get("filename") for c in cols}
    assert len(files) < len(cols) / 3  # the wedges of each band reuse its first wedge's mesh
    assert any(c.find("origin").get("rpy") != "0 0 0" for c in cols)
    assert all((folder / f).is_file() for f in files)
    assert _results(folder)["usd_urdf_agree"].ok  # and they land where the USD hulls are
