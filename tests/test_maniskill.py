"""The ManiSkill tasks (``OpenInfmob-v1``, ``CloseInfmob-v1``): real ManiSkill 3 / SAPIEN on the CPU.

The object is generated through the task's own cache (category + seed), with the annotations.json the build
writes.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("sapien")
pytest.importorskip("mani_skill")

import gymnasium as gym  # noqa: E402

from infmob_usd import maniskill  # noqa: E402

pytestmark = pytest.mark.sim
MAKE = dict(sim_backend="cpu", render_backend="none", control_mode="pd_joint_pos", obs_mode="state")


@pytest.fixture(scope="module")
def cache(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("maniskill")
    maniskill.object_folder("kitchen_cabinet", 1, root)
    return root


def _episode(env, policy, seed: int) -> tuple[bool, float, list[float]]:
    obs, _info = env.reset(seed=seed)
    policy.reset()
    rewards = []
    for _ in range(200):
        obs, reward, terminated, truncated, info = env.step(policy(obs))
        rewards.append(float(reward[0]))
        if terminated or truncated:
            break
    return bool(info["success"][0]), float(info["target_fraction"][0]), rewards


def _success_rate(task: str, cache: Path, seeds, **kwargs) -> tuple[float, list]:
    env = gym.make(task, category="kitchen_cabinet", object_seed=1, cache_dir=cache, **MAKE, **kwargs)
    policy = maniskill.ScriptedGripper(env)
    runs = []
    for s in seeds:
        ok, frac, _rewards = _episode(env, policy, s)
        runs.append((env.unwrapped.target["joint"], ok, round(frac, 2)))
    env.close()
    rate = sum(ok for _j, ok, _f in runs) / len(runs)
    print(f"{task} scripted gripper: {rate:.0%} success over seeds {list(seeds)}: {runs}")
    return rate, runs


def test_the_ids_are_registered_with_maniskill():
    from mani_skill.utils.registration import REGISTERED_ENVS

    assert {"OpenInfmob-v1", "CloseInfmob-v1"} <= set(REGISTERED_ENVS)
    assert gym.spec("OpenInfmob-v1").max_episode_steps == 200


def test_the_scripted_gripper_opens_drawers_and_doors(cache):
    rate, runs = _success_rate("OpenInfmob-v1", cache, range(4))
    assert len({j for j, _ok, _f in runs}) > 1  # the episode seed picks the target joint
    assert rate >= 0.75, runs
    rate, runs = _success_rate("OpenInfmob-v1", cache, [0], joint="joint_door_2_0")
    assert rate == 1.0 and runs[0][2] >= 0.9, runs


def test_the_scripted_gripper_closes_a_door(cache):
    rate, runs = _success_rate("CloseInfmob-v1", cache, [0], joint="joint_door_2_0")
    assert rate == 1.0 and runs[0][2] <= 0.05, runs


def test_obs_reward_and_no_success_without_a_grasp(cache):
    env = gym.make("OpenInfmob-v1", category="kitchen_cabinet", object_seed=1, cache_dir=cache,
                   joint="joint_drawer_0_0", **MAKE)
    obs, info = env.reset(seed=0)
    u = env.unwrapped
    assert obs.shape == (1, 31) and float(info["target_fraction"][0]) == pytest.approx(0.0, abs=1e-6)
    hold = np.concatenate([np.zeros(6), [1.0]]).astype(np.float32)  # stay at the pre-grasp, fingers open
    for _ in range(30):
        obs, reward, terminated, _truncated, info = env.step(hold)
    assert not bool(info["success"][0]) and not terminated
    assert abs(float(info["target_fraction"][0])) < 0.01
    # reach term only: 1 - tanh(5 * 0.1 m) back from the grasp, normalized by 5
    d = float(np.linalg.norm(u.agent.tcp.pose.p[0].numpy() - info["handle_link_pos"][0].numpy()))
    assert float(reward[0]) == pytest.approx((1 - np.tanh(5 * d)) / 5, abs=1e-4)
    # the drawer pulled open by hand is a success for the task (link still, past 0.9 of its range)
    q = u.obj.get_qpos().clone()
    q[0, u.qi] = u.open
    u.obj.set_qpos(q)
    assert bool(u.evaluate()["success"][0])
    env.close()


def test_bad_arguments_say_what_to_give(cache, tmp_path):
    with pytest.raises(ValueError, match="folder=PATH .* or category=NAME"):
        gym.make("OpenInfmob-v1", **MAKE)
    folder = maniskill.object_folder("kitchen_cabinet", 1, cache)
    with pytest.raises(FileNotFoundError, match="not an object folder"):
        gym.make("OpenInfmob-v1", folder=tmp_path, **MAKE)
    (tmp_path / "metadata.json").write_bytes((folder / "metadata.json").read_bytes())
    with pytest.raises(FileNotFoundError, match="no annotations.json"):
        gym.make("OpenInfmob-v1", folder=tmp_path, **MAKE)
    with pytest.raises(ValueError, match="no annotated target joint for this task named 'nope'"):
        gym.make("OpenInfmob-v1", folder=folder, joint="nope", **MAKE)
