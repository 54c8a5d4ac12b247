"""ManiSkill 3 tasks on generated objects: ``OpenInfmob-v1`` and ``CloseInfmob-v1``.

Importing this module registers both gym ids with ManiSkill's ``register_env``::

    import gymnasium as gym
    import infmob_usd.maniskill  # noqa: F401  (registers the ids)

    env = gym.make("OpenInfmob-v1", folder="out/kitchen_cabinet_s1", sim_backend="cpu",
                   control_mode="pd_joint_pos", obs_mode="state")
    env = gym.make("OpenInfmob-v1", category="microwave", object_seed=3, sim_backend="cpu")

The object (an object folder, or ``category`` + ``object_seed`` generated once into ``cache_dir``) is loaded
as the task's articulation through ManiSkill's URDF loader, root fixed, standing on the ground. Every joint
is passive with the object's own dynamics (URDF damping and friction, return springs from
``metadata.json``, as ``infmob validate --sim`` sets them). Each episode picks one target joint from the
folder's ``annotations.json`` (schema ``infmob-annotations/1``; ``joint=`` fixes it); the joints it
``requires_open`` start open.

Success follows ManiSkill's ``OpenCabinetDrawer-v1``: the target joint at or past
``lower + open_frac * range`` (``open_frac``: the annotation's ``open_threshold``, 0.9, unless given;
ManiSkill 3.0.1's own cabinet task uses 0.75) with the moving link still (speed <= 0.1 m/s, <= 1 rad/s).
``CloseInfmob-v1`` starts the target open and succeeds at or below ``rest + closed_threshold * range``
(RoboCasa's ``is_closed`` convention, 0.05) with the link still. Range and "open" are the annotation's
``rest`` -> ``open`` (an ``open`` below ``rest`` opens downwards).

Robot: ``floating_panda_gripper`` (default: ManiSkill's floating Panda hand, its root placed each episode
where the hand is 0.1 m back from the first grasp along its approach; gravity off on the hand, as an arm
holds it) or ``panda`` (ManiSkill's Panda arm on a fixed base 0.75 m in front of the object). Observations
and the dense reward are ManiSkill's cabinet task's: ``tcp_pose``, and with state obs
``tcp_to_handle_pos``, ``target_link_qpos``, ``target_handle_pos``, ``target_fraction``; reward =
reach ``1 - tanh(5 d)`` (2 once the joint has moved) + 2 x progress towards the threshold, 3 at the
threshold, 5 on success (normalized: / 5). :class:`ScriptedGripper` is a scripted policy for the floating
gripper (approach the grasp frame, close, pull / push / turn along the annotated path).

Runs on ``sim_backend="cpu"`` with one environment.
"""

from __future__ import annotations

import math
import os
import shutil
import tempfile
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import sapien
import torch
from mani_skill.envs.sapien_env import BaseEnv
from mani_skill.sensors.camera import CameraConfig
from mani_skill.utils import sapien_utils
from mani_skill.utils.building.ground import build_ground
from mani_skill.utils.registration import register_env
from mani_skill.utils.structs import Pose
from mani_skill.utils.structs.types import SimConfig

from .validate.robot import (
    PREGRASP,
    TCP_OFFSET,
    Path3,
    euler_xyz,
    hand_rotation,
    read_annotations,
    rotation_between,
)
from .validate.sim import (
    _build_mimics,
    _drive_spring,
    _find_urdf,
    _read_meta,
    _urdf_dynamics,
    physx_friction_coefficient,
)

__all__ = ["CloseInfmobEnv", "OpenInfmobEnv", "ScriptedGripper", "object_folder"]

OBJECT = "infmob"  # the articulation's name in the ManiSkill scene
STILL_SPEED, STILL_SPIN = 0.1, 1.0  # m/s, rad/s: ManiSkill's "link is static" for success
CLOSED = -0.01  # m per finger: ManiSkill closes the fingers past touching (a thin part still gets force)
PANDA_STANDOFF = 0.6  # m back from the grasp where the Panda arm's base stands (outside a door's swing)
PANDA_BELOW = 0.3  # m the Panda arm's base stands below the grasp (the arm reaches about 0.85 m)


def object_folder(category: str, seed: int = 0, cache_dir: str | Path | None = None) -> Path:
    """The object folder of ``category`` / ``seed``, generated (URDF only, 64 px textures) into
    ``cache_dir/<category>_<seed>/`` on first use (default ``$XDG_CACHE_HOME/infmob_usd/maniskill``); the
    same folder afterwards (generation is deterministic)."""
    from .api import generate, save

    root = Path(cache_dir) if cache_dir is not None else Path(
        os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache") / "infmob_usd" / "maniskill"
    home = root / f"{category}_{int(seed)}"
    found = sorted(p for p in home.glob("*/metadata.json")) if home.is_dir() else []
    if found:
        return found[0].parent
    root.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(prefix=f".{category}_{int(seed)}-", dir=root))
    try:
        save(generate(category, int(seed), texture_size=64), tmp, formats="urdf")
        try:
            tmp.rename(home)  # atomic: a concurrent maker's folder wins, ours is dropped
        except OSError:
            shutil.rmtree(tmp)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    return object_folder(category, seed, root)


def _np(x) -> np.ndarray:
    return np.asarray(x.cpu().numpy() if isinstance(x, torch.Tensor) else x, float)


def _pose_matrix(pose: Pose) -> np.ndarray:
    return _np(pose.to_transformation_matrix())[0]


def _pose(rotation: np.ndarray, position) -> np.ndarray:
    m = np.eye(4)
    m[:3, :3], m[:3, 3] = rotation, position
    return m


def _unit(v) -> np.ndarray:
    v = np.asarray(v, float)
    return v / max(float(np.linalg.norm(v)), 1e-12)


def _sapien_pose(m: np.ndarray) -> sapien.Pose:
    return sapien.Pose(m.astype(np.float32))


class OpenInfmobEnv(BaseEnv):
    """Open one annotated joint of a generated object (see the module docstring for the arguments)."""

    SUPPORTED_ROBOTS = ["floating_panda_gripper", "panda"]
    closing = False  # CloseInfmob-v1: start open, succeed when closed

    def __init__(self, *args, folder: str | Path | None = None, category: str | None = None,
                 object_seed: int = 0, cache_dir: str | Path | None = None, joint: str | None = None,
                 open_frac: float | None = None, robot_uids: str = "floating_panda_gripper",
                 num_envs: int = 1, **kwargs):
        if (folder is None) == (category is None):
            raise ValueError("give folder=PATH (an object folder) or category=NAME (with object_seed=N),"
                             " not both or neither")
        if num_envs != 1:
            raise ValueError(f"num_envs={num_envs}: the infmob tasks run one environment (sim_backend='cpu')")
        self.folder = Path(folder) if folder is not None else object_folder(category, object_seed, cache_dir)
        if not (self.folder / "metadata.json").is_file():
            raise FileNotFoundError(f"{self.folder}: not an object folder (no metadata.json); give a folder"
                                    " written by infmob generate")
        self.meta = _read_meta(self.folder)
        self.urdf = _find_urdf(self.folder, self.meta)
        targets = read_annotations(self.folder)
        if targets is None:
            raise FileNotFoundError(f"{self.folder}: no annotations.json (write one, schema infmob-annotations/1)")
        targets = [t for t in targets if self._usable(t)]
        if joint is not None:
            targets = [t for t in targets if t["joint"] == joint]
        if not targets:
            raise ValueError(f"{self.folder.name}: no annotated target joint for this task"
                             + (f" named {joint!r}" if joint else ""))
        self.targets = targets
        self.open_frac = open_frac
        self.target = targets[0]
        super().__init__(*args, robot_uids=robot_uids, num_envs=1, **kwargs)

    def _usable(self, target: dict) -> bool:
        """Every target can be opened; closing needs a closed state to return to (not a continuous turn)
        and a part a hand returns (a pressed button comes back on its spring)."""
        if not self.closing:
            return True
        return target.get("joint_type") != "continuous" and target.get("action") not in ("press", "push")

    # ------------------------------------------------------------------ scene

    @property
    def _default_sim_config(self):
        return SimConfig(sim_freq=200, control_freq=20)

    @property
    def _default_sensor_configs(self):
        return []

    @property
    def _default_human_render_camera_configs(self):
        lo, hi = self._bounds
        centre, size = (lo + hi) / 2, float(np.max(hi - lo))
        eye = centre + np.array([1.6, -1.2, 0.9]) * max(size, 0.4) * 1.3
        return CameraConfig("render_camera", pose=sapien_utils.look_at(eye.tolist(), centre.tolist()),
                            width=512, height=512, fov=1.0, near=0.01, far=100)

    def _load_agent(self, options: dict):
        super()._load_agent(options, sapien.Pose(p=[3.0, 3.0, 3.0]))
        if self.robot_uids == "floating_panda_gripper":
            for link in self.agent.robot.get_links():
                for obj in link._objs:
                    obj.disable_gravity = True  # an arm holds the hand's weight

    def _load_scene(self, options: dict):
        self.ground = build_ground(self.scene)
        loader = self.scene.create_urdf_loader()
        loader.fix_root_link = True
        loader.name = OBJECT
        builder = loader.parse(str(self.urdf))["articulation_builders"][0]
        builder.initial_pose = sapien.Pose()
        self.obj = builder.build(name=OBJECT, fix_root_link=True, build_mimic_joints=False)
        physx_art = self.obj._objs[0]
        prefix = f"scene-0-{OBJECT}_"
        _build_mimics(physx_art, [SimpleNamespace(joint=prefix + r.joint, mimic=prefix + r.mimic,
                                                  multiplier=r.multiplier, offset=r.offset)
                                  for r in builder.mimic_joint_records])
        self._joints = list(physx_art.get_active_joints())
        self.joint_names = [j.name[len(prefix):] if j.name.startswith(prefix) else j.name for j in self._joints]
        limits = np.array([j.get_limit()[0] for j in self._joints], float).reshape(-1, 2)
        self.rest_qpos = np.clip(0.0, limits[:, 0], limits[:, 1]) if len(limits) else np.zeros(0)
        self._make_passive(physx_art)
        mesh = self.obj.get_first_collision_mesh(to_world_frame=False)
        self._bounds = (np.asarray(mesh.bounds[0], float), np.asarray(mesh.bounds[1], float))

    def _make_passive(self, physx_art) -> None:
        """The object's own joint dynamics, as ``infmob validate --sim`` sets them (drives off, URDF damping,
        URDF friction as PhysX coefficients at the rest pose, return springs from ``metadata.json``)."""
        physx_art.set_qpos(self.rest_qpos.astype(np.float32))
        dynamics = _urdf_dynamics(self.urdf)
        springs = {j["name"]: j["spring"] for j in self.meta.get("joints", []) if j.get("spring")}
        gravity = np.asarray(self.scene.sub_scenes[0].get_physx_system().config.gravity, float)
        for j, name in zip(self._joints, self.joint_names, strict=True):
            damping, friction = dynamics.get(name, (float(j.damping), 0.0))
            if name in springs:
                _drive_spring(j, springs[name], damping)
                continue
            c = physx_friction_coefficient(j, friction, gravity)
            j.set_drive_property(0.0, damping, mode="force")
            j.set_friction(c)

    def _after_reconfigure(self, options):
        self.base_z = -float(self._bounds[0][2])  # the object's lowest point on the ground

    # ------------------------------------------------------------------ episode

    def _initialize_episode(self, env_idx: torch.Tensor, options: dict):
        pick = int(self._batched_episode_rng.randint(0, len(self.targets))[0])
        self.target = t = self.targets[pick]
        self.qi = self.joint_names.index(t["joint"])
        self.target_link = self.obj.links_map[t["link"]]
        self.rest, self.open = float(t["rest"]), float(t["open"])
        frac = float(self.open_frac if self.open_frac is not None else t["open_threshold"])
        self.threshold = float(t.get("closed_threshold", 0.05)) if self.closing else frac
        g = t["grasps"][0]
        self.handle_local = np.asarray(g["position"], float) + float(g["depth"]) * _unit(g["approach"])
        self.obj.set_pose(Pose.create_from_pq(p=torch.tensor([[0.0, 0.0, self.base_z]])))
        q = self.rest_qpos.copy()
        for name in t.get("requires_open") or []:
            if name in self.joint_names:
                other = next((o for o in self.targets if o["joint"] == name), None)
                k = self.joint_names.index(name)
                q[k] = float(other["open"]) if other else float(self._joints[k].get_limit()[0][1])
        if self.closing:
            q[self.qi] = self.open
        self.obj.set_qpos(torch.tensor(q[None], dtype=torch.float32))
        self.obj.set_qvel(torch.zeros((1, len(q))))
        self._place_robot()

    def grasp_pose(self, index: int = 0) -> tuple[np.ndarray, float]:
        """The TCP pose (4x4, world, now) at annotated grasp ``index`` (the pads' centre: ``position`` +
        ``depth`` along the approach) and the finger opening to approach with (per finger)."""
        g = self.target["grasps"][index]
        link = _pose_matrix(self.target_link.pose)
        approach = _unit(link[:3, :3] @ np.asarray(g["approach"], float))
        position = (link @ np.array([*map(float, g["position"]), 1.0]))[:3]
        rot = hand_rotation(approach, link[:3, :3] @ np.asarray(g["closing"], float))
        if self.target.get("action") in ("press", "push"):  # the closed fingers' tips on the surface
            return _pose(rot, position - approach * 0.0095), 0.0
        position = position + approach * float(g["depth"])
        return _pose(rot, position), min(0.04, float(g.get("width") or 0.08) / 2 + 0.01)

    def panda_base(self) -> np.ndarray:
        """Where the Panda arm's base stands (4x4, world): :data:`PANDA_STANDOFF` back from the first grasp
        against its approach (level), facing it, :data:`PANDA_BELOW` below it (a base with a lift column;
        on the ground at the lowest)."""
        tcp, _opening = self.grasp_pose()
        back = -tcp[:3, 2].copy()
        back[2] = 0.0
        back = _unit(back) if np.linalg.norm(back) > 0.3 else np.array([1.0, 0.0, 0.0])  # approached from above
        xy = tcp[:2, 3] + back[:2] * PANDA_STANDOFF
        yaw = math.atan2(-back[1], -back[0])
        rot = np.array([[math.cos(yaw), -math.sin(yaw), 0], [math.sin(yaw), math.cos(yaw), 0], [0, 0, 1]])
        return _pose(rot, [xy[0], xy[1], max(0.0, float(tcp[2, 3]) - PANDA_BELOW)])

    def _place_robot(self) -> None:
        if self.robot_uids == "panda":
            self.agent.robot.set_pose(_sapien_pose(self.panda_base()))
            self.agent.reset(torch.tensor(self.agent.keyframes["rest"].qpos[None], dtype=torch.float32))
            return
        tcp, _opening = self.grasp_pose()
        hand = tcp.copy()
        hand[:3, 3] = tcp[:3, 3] - tcp[:3, 2] * (PREGRASP + TCP_OFFSET)
        self.agent.robot.set_pose(_sapien_pose(hand))
        q = torch.zeros((1, self.agent.robot.dof[0].item()))
        q[:, 6:] = 0.04
        self.agent.reset(q)

    # ------------------------------------------------------------------ evaluation

    def target_fraction(self) -> torch.Tensor:
        """How far the target joint is from rest to open (0 at rest, 1 fully open), shape (1,)."""
        q = self.obj.qpos[:, self.qi]
        span = self.open - self.rest
        return (q - self.rest) / span if span else q * 0

    def handle_position(self) -> torch.Tensor:
        """The first grasp's pads' centre (world), shape (1, 3)."""
        link = _pose_matrix(self.target_link.pose)
        return torch.tensor((link @ np.array([*self.handle_local, 1.0]))[None, :3], dtype=torch.float32)

    def evaluate(self):
        frac = self.target_fraction()
        done = frac <= self.threshold if self.closing else frac >= self.threshold
        still = ((torch.linalg.norm(self.target_link.linear_velocity, axis=1) <= STILL_SPEED)
                 & (torch.linalg.norm(self.target_link.angular_velocity, axis=1) <= STILL_SPIN))
        return {"success": done & still, "open_enough": done, "target_fraction": frac,
                "handle_link_pos": self.handle_position()}

    def _get_obs_extra(self, info: dict):
        obs = {"tcp_pose": self.agent.tcp.pose.raw_pose}
        if "state" in self.obs_mode:
            obs.update(tcp_to_handle_pos=info["handle_link_pos"] - self.agent.tcp.pose.p,
                       target_link_qpos=self.obj.qpos[:, self.qi:self.qi + 1],
                       target_handle_pos=info["handle_link_pos"],
                       target_fraction=info["target_fraction"][:, None])
        return obs

    def compute_dense_reward(self, obs, action: torch.Tensor, info: dict):
        d = torch.linalg.norm(self.agent.tcp.pose.p - info["handle_link_pos"], axis=1)
        reach = 1 - torch.tanh(5 * d)
        frac = info["target_fraction"]
        if self.closing:
            progress = (1 - frac) / max(1 - self.threshold, 1e-9)
            moved = frac < 0.999
        else:
            progress = frac / max(self.threshold, 1e-9)
            moved = frac > 0.001
        reach[moved] = 2.0  # once the joint moves the reach term is full, as in OpenCabinetDrawer-v1
        reward = reach + 2 * progress.clamp(0.0, 1.0)
        reward[info["open_enough"]] = reach[info["open_enough"]] + 3.0
        reward[info["success"]] = 5.0
        return reward

    def compute_normalized_dense_reward(self, obs, action: torch.Tensor, info: dict):
        return self.compute_dense_reward(obs=obs, action=action, info=info) / 5.0


class CloseInfmobEnv(OpenInfmobEnv):
    """Close one annotated joint that starts open (see the module docstring)."""

    closing = True


register_env("OpenInfmob-v1", max_episode_steps=200)(OpenInfmobEnv)
register_env("CloseInfmob-v1", max_episode_steps=200)(CloseInfmobEnv)


class ScriptedGripper:
    """A scripted policy for the floating gripper with ``control_mode="pd_joint_pos"``: from the pre-grasp
    pose move onto the first grasp, close the fingers, then move the grasp point along the annotated path
    (reversed for closing), never more than ``lead`` ahead of where the hand is, the hand turning as the
    path turns; a point path (a knob held on its axis) is turned in place about the joint's axis.

    ``policy = ScriptedGripper(env); obs, _ = env.reset(seed=s); policy.reset(); action = policy(obs)``.
    """

    approach_steps, close_steps = 12, 8
    speed, lead = 0.25, 0.05  # m/s along the path, m ahead of the hand
    turn_speed, turn_lead = 1.5, 0.35  # rad/s, rad

    def __init__(self, env):
        self.env = env.unwrapped

    def reset(self) -> None:
        e = self.env
        self.step_count = 0
        self.grasp, self.opening = e.grasp_pose()
        self.root = _pose_matrix(e.agent.robot.pose)
        self.pre = self.grasp.copy()
        self.pre[:3, 3] -= self.grasp[:3, 2] * PREGRASP
        obj = _pose_matrix(e.obj.pose)
        points = [(obj @ np.array([*map(float, p), 1.0]))[:3] for p in e.target["path"]]
        if e.closing:  # the path is annotated rest -> open; it starts where the grasp now is
            shift = self.grasp[:3, 3] - points[-1]
            points = [p + shift for p in reversed(points)]
        else:
            points = [p + self.grasp[:3, 3] - points[0] for p in points]
        self.path = Path3(points)
        self.goal = 0.0
        self.turn = None
        if self.path.length < 5e-4:
            frame = np.asarray(e._joints[e.qi].get_global_pose().to_transformation_matrix(), float)
            sign = -1.0 if (e.open - e.rest) * (-1 if e.closing else 1) < 0 else 1.0
            self.turn = (frame[:3, 3], frame[:3, 0] * sign, abs(e.open - e.rest))
            self.angle = 0.0

    def _action(self, tcp: np.ndarray, grip: float) -> np.ndarray:
        hand = tcp.copy()
        hand[:3, 3] = tcp[:3, 3] - tcp[:3, 2] * TCP_OFFSET
        rel = np.linalg.inv(self.root) @ hand
        values = np.concatenate([rel[:3, 3], euler_xyz(rel[:3, :3])])
        now = _np(self.env.agent.robot.get_qpos())[0]
        values[3:] = now[3:6] + (values[3:] - now[3:6] + math.pi) % (2 * math.pi) - math.pi
        low, high = -0.01, 0.04  # the floating gripper's finger controller: [-1, 1] maps to these (m)
        return np.concatenate([values, [2 * (grip - low) / (high - low) - 1]]).astype(np.float32)

    def __call__(self, obs=None) -> np.ndarray:
        self.step_count += 1
        n, k = self.approach_steps, self.close_steps
        dt = 1.0 / self.env.control_freq
        if self.step_count <= n:
            t = self.pre.copy()
            t[:3, 3] += (self.grasp[:3, 3] - self.pre[:3, 3]) * (self.step_count / n)
            return self._action(t, self.opening)
        if self.step_count <= n + k:
            return self._action(self.grasp, CLOSED)
        return self._action(self.follow(_pose_matrix(self.env.agent.tcp.pose), dt), CLOSED)

    def follow(self, tcp: np.ndarray, dt: float) -> np.ndarray:
        """The next TCP target (4x4, world) on the annotated path from the TCP now at ``tcp``, ``dt`` later."""
        if self.turn is not None:
            return self._turned(tcp, dt)
        here = self.path.nearest(tcp[:3, 3])
        self.goal = min(self.path.length + self.lead, self.goal + self.speed * dt, here + self.lead)
        return self.path_pose(here, self.goal)

    def path_pose(self, here: float, goal: float | None = None) -> np.ndarray:
        """The TCP pose (4x4, world) at arc length ``goal`` (default ``here``) of the path, the hand turned as
        the path's tangent has turned at ``here``."""
        turn = rotation_between(self.path.tangent(0.0), self.path.tangent(here))
        offset = self.grasp[:3, 3] - self.path.at(0.0)
        return _pose(turn @ self.grasp[:3, :3], self.path.at(here if goal is None else goal) + turn @ offset)

    def _turned(self, tcp: np.ndarray, dt: float) -> np.ndarray:
        pivot, axis, length = self.turn
        axis = _unit(axis)
        self.angle = min(length + self.turn_lead, self.angle + self.turn_speed * dt)
        k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
        r = np.eye(3) + math.sin(self.angle) * k + (1 - math.cos(self.angle)) * k @ k
        return _pose(r @ self.grasp[:3, :3], pivot + r @ (self.grasp[:3, 3] - pivot))

