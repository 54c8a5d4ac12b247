"""A Panda arm opens generated objects: inverse kinematics to the annotated grasp, then along the grasp's path.

Each object is the articulation of the ``OpenInfmob-v1`` ManiSkill task (:mod:`infmob_usd.maniskill`) with
``robot_uids="panda"``: ManiSkill's Panda arm on a base that stands 0.6 m in front of the grasp, 0.3 m below it
(a lift column; on the ground at the lowest). Per object:

1. the arm moves in joint space from its rest pose to 0.1 m back from the first annotated grasp (the joint
   values from SAPIEN's Pinocchio inverse kinematics, which ManiSkill's end-effector controllers use);
2. the hand moves straight onto the grasp and the fingers close;
3. the hand follows the annotated path (the grasp point over the joint's range, the hand turning with the
   path's tangent: :meth:`infmob_usd.maniskill.ScriptedGripper.follow`), a few centimetres ahead of where
   the hand is, with the arm's joint PD controller (ManiSkill's ``pd_joint_pos``) as the compliance.

No motion planner: mplib 0.1.1 (the version mani-skill 3.0.1 requires) crashes on loading any URDF with
numpy 2 (a segmentation fault in ``mplib.pymp.ArticulatedModel``), so the arm goes where the pre-grasp is
reached in a straight joint-space line; the base placement keeps the arm out of the object.

Not yet: a dishwasher door (it folds down to the floor in front; the arm loses it at 72-75 % of its range),
a refrigerator, beverage fridge or safe door (no place found from which one branch of the arm's solutions
follows the handle's arc to 90 %: a fridge's handle sweeps 1.4 m), a toaster oven door (35 %).

Success is the task's own: the joint past 90 % of its range with the part still. The grasps and paths are the
object's ``annotations.json``. Run from the repository root::

    .venv/bin/python docs/examples/arm_open.py                    # the four defaults, a GIF in docs/arm_open.gif
    .venv/bin/python docs/examples/arm_open.py --no-gif microwave:1:joint_door

The GIF is rendered on the CPU through SAPIEN's Vulkan renderer (Mesa lavapipe, see docs/cli.md 'preview').
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import gymnasium as gym
import numpy as np
import sapien
import torch

from infmob_usd import maniskill

ROOT = Path(__file__).resolve().parents[2]
# category:seed:joint - a base-cabinet drawer and door, a microwave door, an oven door
OBJECTS = ("kitchen_cabinet:1:joint_drawer_0_1", "kitchen_cabinet:1:joint_door_2_0", "microwave:0:joint_door",
           "oven:0:joint_door")
OPEN, CLOSED = 1.0, -1.0  # the Panda gripper controller's normalized finger targets
FOLLOW_STEPS = 120  # control steps (6 s) allowed along the path
CLEAR = 0.2  # m from the base's axis that the operated part's grasp point keeps below the shoulder
SHOULDER = 0.45  # m above the base: the Panda's link 0-2 (shoulder at 0.333 m) and a margin


class Arm:
    """The Panda of one episode: inverse kinematics, stepping (with frames kept for the GIF)."""

    def __init__(self, env, frames: list | None, every: int = 3):
        self.env, self.u = env, env.unwrapped
        self.frames, self.every, self.steps = frames, every, 0
        robot = self.u.agent.robot
        self.model = robot._objs[0].create_pinocchio_model()
        names = [link.name for link in robot.get_links()]
        self.tcp_index = names.index("panda_hand_tcp")
        self.mask = np.array([1] * 7 + [0] * (robot.dof[0].item() - 7), dtype=np.int32)
        self.base = maniskill._pose_matrix(robot.pose)
        self.limits = robot.get_qlimits().cpu().numpy()[0]
        self.rest = np.asarray(self.u.agent.keyframes["rest"].qpos, float)
        rng = np.random.default_rng(0)
        # starts over the arm's usual shapes (shoulder, elbow, wrist pitch; hand rolled either way)
        self.grid = [np.array([0.0, a, 0.0, b, 0.0, c, d, 0.04, 0.04]) for a in (-0.3, 0.3, 0.8)
                     for b in (-2.5, -2.0, -1.5) for c in (0.5, 1.0, 1.5, 2.0, 2.5) for d in (0.785, -2.356)]
        self.grid += [np.concatenate([rng.uniform(self.limits[:7, 0], self.limits[:7, 1]), [0.04, 0.04]])
                      for _ in range(40)]
        self.info = {}

    def qpos(self) -> np.ndarray:
        return self.u.agent.robot.get_qpos().cpu().numpy()[0]

    def step(self, arm_q: np.ndarray, grip: float) -> dict:
        _obs, _r, _term, _trunc, self.info = self.env.step(np.hstack([arm_q[:7], grip]).astype(np.float32))
        self.steps += 1
        if self.frames is not None and self.steps % self.every == 0:
            self.frames.append(np.asarray(self.env.render().cpu().numpy()[0], np.uint8))
        return self.info

    def ik(self, tcp: np.ndarray, q: np.ndarray, tries: int = 1000) -> np.ndarray | None:
        """Arm joint values within the joint limits putting the TCP at a world pose (4x4), the nearest to ``q``
        of the solutions from ``q``, the rest pose and ``tries`` starts of :attr:`grid`; None when none is found
        (SAPIEN's solver ignores limits: a solution outside them, after whole turns, is dropped)."""
        goal = sapien.Pose((np.linalg.inv(self.base) @ tcp).astype(np.float32))
        lo, hi = self.limits[:, 0], self.limits[:, 1]
        starts = [q, *([self.rest] if tries else []), *self.grid[:tries]]
        best = None
        for start in starts:
            result, ok, _err = self.model.compute_inverse_kinematics(
                self.tcp_index, goal, initial_qpos=np.asarray(start, float), active_qmask=self.mask,
                max_iterations=200)
            if not ok:
                continue
            r = np.asarray(result)[:7]
            r = r - 2 * np.pi * np.round((r - (lo[:7] + hi[:7]) / 2) / (2 * np.pi))  # whole turns
            if np.all(r >= lo[:7] - 1e-4) and np.all(r <= hi[:7] + 1e-4):
                if best is None or np.linalg.norm(r - q[:7]) < np.linalg.norm(best - q[:7]):
                    best = r
                if start is q:
                    break  # the solution next to where the arm is
        return best

    def chain(self, poses: list, step: float = 0.4, starts: int = 6) -> bool:
        """Whether one branch of solutions goes through ``poses`` (each within ``step`` rad of the last, from
        up to ``starts`` solutions at the first); keeps the last one as :attr:`start`."""
        tried = 0
        for seed in [self.rest, *self.grid]:
            first = self.ik(poses[0], np.asarray(seed, float), tries=0)
            if first is None:
                continue
            tried += 1
            q = np.concatenate([first, self.rest[7:]])
            for pose in poses[1:]:
                nxt = self.ik(pose, q, tries=0)
                if nxt is None or np.max(np.abs(nxt - q[:7])) > step:
                    break
                q = np.concatenate([nxt, self.rest[7:]])
            else:
                self.start = q
                return True
            if tried >= starts:
                return False
        return False

    def move(self, q_to: np.ndarray, steps: int, grip: float) -> None:
        q_from = self.qpos()[:7]
        for i in range(1, steps + 1):
            self.step(q_from + (q_to[:7] - q_from) * i / steps, grip)


def _clear(base: np.ndarray, points: np.ndarray) -> bool:
    """Whether the part's grasp point stays off the arm's base (a door folding down sweeps the floor in
    front): never within :data:`CLEAR` of the base's axis below the shoulder."""
    near = np.hypot(points[:, 0] - base[0], points[:, 1] - base[1]) < CLEAR
    return not np.any(near & (points[:, 2] < base[2] + SHOULDER))


def stand(env, policy, frames: list | None):
    """Put the arm's base where it reaches the pre-grasp, the grasp and the path up to the open threshold (a mobile base
    with a lift choosing where to stand): in front of the grasp against its approach, facing the object, the
    nearest first, then to either side (a door's handle swings aside); yields each such place in turn."""
    u = env.unwrapped
    grasp = policy.grasp
    back = -grasp[:3, 2].copy()
    back[2] = 0.0
    back = back / np.linalg.norm(back) if np.linalg.norm(back) > 0.3 else np.array([1.0, 0.0, 0.0])
    yaw = np.arctan2(-back[1], -back[0])
    rot = np.array([[np.cos(yaw), -np.sin(yaw), 0], [np.sin(yaw), np.cos(yaw), 0], [0, 0, 1]])
    # the path's points are at tenths of the range: the one at the open threshold is where success is
    done = policy.path.cum[min(10, int(np.ceil(10 * float(u.target["open_threshold"]) - 1e-9)))]
    # from the threshold back to the grasp, then the pre-grasp: one branch of the arm's solutions all along
    poses = [policy.path_pose(s) for s in np.linspace(done, 0.0, 25)] + [grasp, policy.pre]
    side = np.array([-back[1], back[0]])
    for standoff in (0.6, 0.8, 1.0, 1.2):
        for aside in (0.0, 0.3, -0.3):
            for lift in (0.3, 0.45, 0.15, 0.0, float(grasp[2, 3])):  # the last: on the ground
                base = np.eye(4)
                base[:3, :3] = rot
                base[:3, 3] = [*(grasp[:2, 3] + back[:2] * standoff + side * aside), max(0.0, grasp[2, 3] - lift)]
                if not _clear(base[:3, 3], policy.path.points):
                    continue
                u.agent.robot.set_pose(sapien.Pose(base.astype(np.float32)))
                arm = Arm(env, frames)
                if arm.chain(poses):
                    yield arm


def open_one(env, seed: int, frames: list | None, places: int = 3) -> tuple[bool, float, str]:
    """Reach, grasp, follow, from up to ``places`` places to stand (the next after a failure, the object
    reset); returns (success, joint fraction reached, what failed)."""
    env.reset(seed=seed)
    policy = maniskill.ScriptedGripper(env)
    policy.reset()
    result = (False, 0.0, "no place to stand from where the arm reaches the grasp and the path")
    for i, arm in enumerate(stand(env, policy, frames)):
        result = _attempt(env, arm, policy)
        if result[0] or i + 1 >= places:
            break
        env.reset(seed=seed)
        policy.reset()
    return result


def _aim_camera(u, arm: Arm, policy) -> None:
    """The GIF's camera on the hand's work: from the side of the line base -> grasp, a little above."""
    from mani_skill.utils import sapien_utils

    grasp, base = policy.grasp[:3, 3], arm.base[:3, 3]
    centre = (grasp + base) / 2
    along = np.array([base[0] - grasp[0], base[1] - grasp[1], 0.0])
    along /= max(float(np.linalg.norm(along)), 1e-9)
    eye = centre + np.array([along[1], -along[0], 0.0]) * 1.5 + along * 0.5 + np.array([0.0, 0.0, 0.6])
    camera = u.scene.human_render_cameras["render_camera"].camera
    camera.set_local_pose(sapien_utils.look_at(eye.tolist(), centre.tolist()).sp)


def _attempt(env, arm: Arm, policy) -> tuple[bool, float, str]:
    u = env.unwrapped
    if arm.frames is not None:
        _aim_camera(u, arm, policy)
    # the episode starts with the arm at the pre-grasp, on the branch that reaches along the path (from the
    # rest pose the arm may be inside the object: its base stands where it reaches, not where it rests)
    u.agent.reset(torch.tensor(np.concatenate([arm.start[:7], [0.04, 0.04]])[None], dtype=torch.float32))
    arm.move(arm.start, 5, OPEN)
    for i in range(1, 11):  # straight onto the grasp
        t = policy.pre.copy()
        t[:3, 3] += (policy.grasp[:3, 3] - policy.pre[:3, 3]) * i / 10
        q = arm.ik(t, arm.qpos())
        if q is None:
            return False, 0.0, "no arm pose reaches the grasp"
        arm.step(q, OPEN)
    for _ in range(10):
        arm.step(q, CLOSED)
    dt = 1.0 / u.control_freq
    for _ in range(FOLLOW_STEPS):
        target = policy.follow(maniskill._pose_matrix(u.agent.tcp.pose), dt)
        # only a solution next to the arm or to the last command: no jump to another branch
        found = arm.ik(target, arm.qpos(), tries=0)
        if found is None:
            found = arm.ik(target, np.concatenate([q[:7], arm.rest[7:]]), tries=0)
        q = found if found is not None else q
        info = arm.step(q, CLOSED)
        if bool(info["success"][0]):
            return True, float(info["target_fraction"][0]), ""
    return False, float(arm.info["target_fraction"][0]), "stopped short on the path"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("objects", nargs="*", default=list(OBJECTS), help="category:seed[:joint] (default: four objects)")
    ap.add_argument("--gif", default=str(ROOT / "docs" / "arm_open.gif"), help="the GIF to write")
    ap.add_argument("--no-gif", action="store_true", help="no rendering (physics and planning only)")
    ap.add_argument("--cache", default=None, help="where generated objects are kept (default: the task's cache)")
    args = ap.parse_args(argv)
    frames: list | None = None if args.no_gif else []
    opened = 0
    for spec in args.objects:
        category, seed, *joint = spec.split(":")
        folder = maniskill.object_folder(category, int(seed), Path(args.cache) if args.cache else None)
        env = gym.make("OpenInfmob-v1", folder=folder, joint=joint[0] if joint else None, robot_uids="panda",
                       sim_backend="cpu",
                       control_mode="pd_joint_pos", obs_mode="state", max_episode_steps=1000,
                       render_backend="none" if args.no_gif else "cpu",
                       render_mode=None if args.no_gif else "rgb_array")
        t0 = time.perf_counter()
        ok, frac, why = open_one(env, 0, frames)
        opened += ok
        print(f"{spec}: {'opened' if ok else 'FAILED: ' + why}, {frac:.0%} of its range"
              f" [{time.perf_counter() - t0:.1f} s]", flush=True)
        env.close()
    print(f"{opened}/{len(args.objects)} opened")
    if frames:
        from PIL import Image

        images = [Image.fromarray(f).resize((256, 256)) for f in frames]
        images[0].save(args.gif, save_all=True, append_images=images[1:], duration=100, loop=0, optimize=True)
        print(f"wrote {args.gif} ({len(images)} frames)")
    return 0 if opened == len(args.objects) else 1


if __name__ == "__main__":
    sys.exit(main())
