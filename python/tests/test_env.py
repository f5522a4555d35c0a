import warnings

import gymnasium
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

import accsim


def registered_ids():
    ids = [k for k in gymnasium.registry if k.startswith("accsim/")]
    assert ids, "accsim registered no environments"
    return ids


@pytest.mark.parametrize("render_mode", [None, "rgb_array"])
@pytest.mark.parametrize("env_id", registered_ids())
def test_check_env_passes_without_warnings(env_id, render_mode):
    env = gymnasium.make(env_id, render_mode=render_mode).unwrapped
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        check_env(env)


def test_spaces_come_from_the_cpp_spec():
    env = accsim.CrashEnv(config={"observed_vehicles": 2, "num_rays": 4})
    assert env.observation_space.shape == (15 + 2 * 9 + 4,)
    assert len(env.obs_names) == env.observation_space.shape[0]
    assert env.obs_names[0] == "ego.speed" and env.obs_names[-1] == "ray[3]"
    assert env.action_space.shape == (2,)


def rollout(env, seed, steps=80):
    obs, _ = env.reset(seed=seed)
    out = [obs]
    rng = np.random.default_rng(0)
    for _ in range(steps):
        obs, r, term, trunc, info = env.step(rng.uniform(-1, 1, 2).astype(np.float32))
        out.append(obs)
        out.append(np.array([r]))
        if term or trunc:
            obs, _ = env.reset()
            out.append(obs)
    return np.concatenate(out)


def test_same_seed_same_rollout_other_seed_other():
    config = {"npc_time_jitter": 0.3, "start_speed_jitter": 1.0}
    a = rollout(accsim.CrashEnv(config=config), 3)
    b = rollout(accsim.CrashEnv(config=config), 3)
    c = rollout(accsim.CrashEnv(config=config), 4)
    assert np.array_equal(a, b)
    assert not np.array_equal(a, c)


def test_info_reports_reward_terms_and_collision():
    straight = [p for p in accsim.bundled_scenarios() if p.endswith("straight_obstacle.json")]
    env = accsim.CrashEnv(scenario=straight)
    env.reset(seed=0)
    total = 0.0
    while True:
        _, r, term, trunc, info = env.step(np.zeros(2, dtype=np.float32))
        assert set(info["reward_terms"]) == set(env.reward_terms)
        assert sum(info["reward_terms"].values()) == pytest.approx(r)
        total += r
        if term or trunc:
            break
    assert term and info["collision"]
    assert info["collision_info"]["other"] == "stopped_car"
    assert info["collision_info"]["relative_speed"] > 5
    assert info["episode"]["r"] == pytest.approx(total)


@pytest.mark.parametrize("bad", [
    np.array([np.nan, 0.0], dtype=np.float32),
    np.array([0.0, np.inf]),
    np.zeros(3),
    np.zeros((1, 2)),
    np.array(["a", "b"]),
    [0.1],
])
def test_bad_actions_raise_value_error(bad):
    env = accsim.CrashEnv()
    env.reset(seed=0)
    with pytest.raises(ValueError, match="action"):
        env.step(bad)
    env.step(np.zeros(2, dtype=np.float32))  # still usable


def test_bad_constructor_arguments_name_the_field(tmp_path):
    with pytest.raises(ValueError, match="physics_hz"):
        accsim.CrashEnv(config={"physics_hz": 55})
    with pytest.raises(ValueError, match="unknown field"):
        accsim.CrashEnv(config={"policy_herz": 10})
    with pytest.raises(FileNotFoundError, match="scenario"):
        accsim.CrashEnv(scenario=str(tmp_path / "missing.json"))
    broken = tmp_path / "broken.json"
    broken.write_text('{"schema_version": 1}')
    with pytest.raises(ValueError, match="family: missing required field"):
        accsim.CrashEnv(scenario=str(broken))
    with pytest.raises(ValueError, match="render_mode"):
        accsim.CrashEnv(render_mode="human")


def test_rgb_array_render():
    env = accsim.CrashEnv(render_mode="rgb_array")
    env.reset(seed=0)
    frame = env.render()
    assert frame.shape == (480, 640, 3) and frame.dtype == np.uint8
    assert frame.std() > 5  # not a blank image


def test_step_after_episode_end_is_an_error():
    env = accsim.CrashEnv(config={"time_limit": 0.2})
    env.reset(seed=0)
    env.step(np.zeros(2, dtype=np.float32))
    _, _, _, trunc, _ = env.step(np.zeros(2, dtype=np.float32))
    assert trunc
    with pytest.raises(RuntimeError, match="Reset"):
        env.step(np.zeros(2, dtype=np.float32))


def test_bad_action_errors_name_the_element():
    env = accsim.CrashEnv()
    env.reset(seed=0)
    with pytest.raises(ValueError, match=r"action\[1\] \(steer"):
        env.step(np.array([0.0, np.nan]))
    with pytest.raises(ValueError, match="dtype"):
        env.step(np.array([True, False]))
    # Finite but beyond float32: clipped into [-1, 1] like any large value.
    _, _, _, _, info = env.step(np.array([1e300, -1e300]))
    assert info["clipped_actions"] == 2


def test_gymnasium_make_passes_scenario_suite_and_config(tmp_path):
    import json
    lines = [json.dumps(json.load(open(p))) for p in accsim.bundled_scenarios()]
    suite = tmp_path / "suite.jsonl"
    suite.write_text("\n".join(lines) + "\n")
    env = gymnasium.make("accsim/Crash-v0", suite=str(suite), config={"num_rays": 4})
    assert env.unwrapped.num_scenarios == 4
    assert env.observation_space.shape[0] == 69 + 4
    env.reset(seed=0, options={"scenario_index": 3})
    with pytest.raises(ValueError, match="options"):
        env.reset(options={"scenario": 1})


def test_config_from_a_yaml_file(tmp_path):
    from pathlib import Path
    env = accsim.CrashEnv(config=Path(__file__).resolve().parents[2] / "configs" / "env.yaml")
    env.reset(seed=0)
    bad = tmp_path / "bad.yaml"
    bad.write_text("physics_hz: 55\n")
    with pytest.raises(ValueError, match="physics_hz"):
        accsim.CrashEnv(config=str(bad))
    with pytest.raises(TypeError, match="config"):
        accsim.CrashEnv(config=3)
