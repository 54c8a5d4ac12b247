"""validate/files.py: the one URDF reader (paired with a writer) and forward kinematics."""

from __future__ import annotations

import math

import numpy as np
import pytest

import infmob_usd
from infmob_usd.validate.files import UrdfJoint, UrdfMesh, UrdfModel, parse_urdf, read_urdf, write_urdf

HAND = """<?xml version="1.0"?>
<robot name="arm">
  <link name="base">
    <collision name="c0"><origin xyz="0 0 0.05" rpy="0 0 0.5"/>
      <geometry><mesh filename="meshes/base.obj" scale="2 2 1"/></geometry></collision>
    <inertial><origin xyz="0 0 0.02" rpy="0 0 0"/><mass value="1.5"/>
      <inertia ixx="0.1" ixy="0" ixz="0" iyy="0.2" iyz="0" izz="0.3"/></inertial>
  </link>
  <link name="upper"><visual><geometry><mesh filename="meshes/upper.obj"/></geometry></visual></link>
  <link name="slider"/>
  <joint name="shoulder" type="revolute">
    <parent link="base"/><child link="upper"/>
    <origin xyz="0 0 0.1" rpy="0.1 -0.2 0.3"/><axis xyz="0 0 2"/>
    <limit lower="-1" upper="1.25" effort="5" velocity="2"/><dynamics damping="0.5"/>
  </joint>
  <joint name="slide" type="prismatic">
    <parent link="upper"/><child link="slider"/><axis xyz="1 0 0"/>
    <limit lower="0" upper="0.3"/>
  </joint>
</robot>
"""


def test_reads_every_field_of_a_hand_written_urdf():
    m = read_urdf(HAND)
    assert m.name == "arm" and list(m.links) == ["base", "upper", "slider"] and m.root == "base"
    base = m.links["base"]
    assert base.collisions == [UrdfMesh("meshes/base.obj", (0, 0, 0.05), (0, 0, 0.5), (2, 2, 1), "c0")]
    assert base.mass == 1.5 and base.com == (0, 0, 0.02) and base.inertia == (0.1, 0, 0, 0.2, 0, 0.3)
    assert m.links["upper"].visuals[0].filename == "meshes/upper.obj" and m.links["slider"].mass is None
    j = m.joints["shoulder"]
    assert (j.type, j.parent, j.child, j.xyz, j.rpy) == ("revolute", "base", "upper", (0, 0, 0.1), (0.1, -0.2, 0.3))
    assert (j.lower, j.upper, j.effort, j.velocity, j.damping, j.friction) == (-1, 1.25, 5, 2, 0.5, None)
    assert np.allclose(j.unit_axis, [0, 0, 1])
    s = m.joints["slide"]
    assert s.xyz == (0, 0, 0) and s.effort is None and s.damping is None


def test_write_then_read_gives_the_same_model():
    m = read_urdf(HAND)
    again = read_urdf(write_urdf(m))
    assert write_urdf(again) == write_urdf(m)
    assert again.links == m.links
    for a, b in zip(m.joints.values(), again.joints.values(), strict=True):
        assert np.array_equal(a.axis, b.axis)
        assert {k: v for k, v in vars(a).items() if k not in ("axis", "origin", "unit_axis")} == \
            {k: v for k, v in vars(b).items() if k not in ("axis", "origin", "unit_axis")}


def test_forward_kinematics_composes_origins_and_motions():
    m = read_urdf(HAND)
    poses = m.poses({"shoulder": 0.7, "slide": 0.2})
    j = m.joints["shoulder"]
    c, s = math.cos(0.7), math.sin(0.7)
    turn = np.array([[c, -s, 0, 0], [s, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])
    assert np.allclose(poses["upper"], j.origin @ turn)
    assert np.allclose(poses["slider"][:3, 3], poses["upper"][:3, 3] + poses["upper"][:3, 0] * 0.2)
    assert np.allclose(m.poses()["upper"], j.origin)  # joints missing from q at 0


def test_bad_urdf_raises_value_error_naming_the_problem():
    with pytest.raises(ValueError, match="well-formed"):
        read_urdf("<robot><link name='a'>")
    with pytest.raises(ValueError, match="type 'ball'"):
        read_urdf('<robot><link name="a"/><link name="b"/><joint name="j" type="ball">'
                  '<parent link="a"/><child link="b"/></joint></robot>')
    two_roots = UrdfModel("x", {}, {})
    two_roots.links.update(read_urdf('<robot><link name="a"/><link name="b"/></robot>').links)
    with pytest.raises(ValueError, match="2 root links"):
        two_roots.poses()


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    obj = infmob_usd.generate("lamp", seed=1, texture_size=16)  # compound joints, turned collision copies
    return obj, infmob_usd.save(obj, tmp_path_factory.mktemp("urdf"))


def test_a_written_object_round_trips_and_its_kinematics_match_the_model(written):
    obj, folder = written
    m = parse_urdf(folder / f"{obj.name}.urdf")
    assert write_urdf(read_urdf(write_urdf(m))) == write_urdf(m)
    assert list(m.links) == [link.name for link in obj.links]
    assert list(m.joints) == [j.name for j in obj.joints]
    assert sum(len(link.collisions) for link in m.links.values()) == sum(
        len(p.convex) for link in obj.links for p in link.pieces)
    rng = np.random.default_rng(0)
    for _ in range(5):  # the writer's model and the reader's kinematics agree at random states
        q = {j.name: float(rng.uniform(j.lower, j.upper)) if j.type != "continuous" else float(rng.uniform(-3, 3))
             for j in obj.joints if j.movable}
        want, got = obj.poses(q), m.poses(q)
        root = obj.links[0].name
        for name in want:  # the URDF root sits at the origin, the model's at its world position
            rel = np.linalg.inv(want[root]) @ want[name]
            assert np.allclose(got[name], rel, atol=1e-7), name


def test_joint_records_are_immutable():
    j = UrdfJoint("j", "revolute", "a", "b")
    with pytest.raises(AttributeError):
        j.lower = 1.0
