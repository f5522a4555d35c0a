import subprocess
import sys
from pathlib import Path

import numpy as np
from stable_baselines3.common.env_checker import check_env as sb3_check_env

import accsim
from accsim.sb3 import CrashSB3VecEnv

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "train_sb3_sac.py"


def test_single_env_works_with_sb3_as_is():
    sb3_check_env(accsim.CrashEnv(), warn=False)


def test_sb3_vec_env_follows_sb3_autoreset():
    vec = CrashSB3VecEnv(2, config={"time_limit": 0.5})
    obs = vec.reset()
    assert obs.shape == (2, 69)
    for _ in range(4):
        vec.step_async(np.zeros((2, 2), np.float32))
        _, _, dones, infos = vec.step_wait()
        assert not dones.any()
    vec.step_async(np.zeros((2, 2), np.float32))
    obs, rewards, dones, infos = vec.step_wait()
    assert dones.all()
    assert infos[0]["TimeLimit.truncated"]
    assert infos[0]["terminal_observation"].shape == (69,)
    assert not np.array_equal(infos[0]["terminal_observation"], obs[0])  # obs is already the reset one


def test_train_example_trains_saves_reloads_and_predicts(tmp_path):
    model = tmp_path / "sac.zip"
    result = subprocess.run(
        [sys.executable, str(EXAMPLE), "--steps", "300", "--envs", "2", "--out", str(model)],
        capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr[-2000:]
    assert model.exists()
    assert "reloaded model predicts" in result.stdout


def test_sb3_vec_env_matches_single_envs_with_sb3_semantics():
    """Same seeds: the batched env under SB3's same-step autoreset equals
    single envs reset by hand, terminal observations included."""
    config = {"time_limit": 0.8, "npc_time_jitter": 0.2}
    vec = CrashSB3VecEnv(2, config=config, seed=7, num_threads=2)
    singles = [accsim.CrashEnv(config=config) for _ in range(2)]
    obs = vec.reset()
    for i, e in enumerate(singles):
        assert np.array_equal(obs[i], e.reset(seed=7 + i)[0])
    rng = np.random.default_rng(1)
    ends = 0
    for _ in range(20):
        act = rng.uniform(-1, 1, (2, 2)).astype(np.float32)
        vec.step_async(act)
        obs, rewards, dones, infos = vec.step_wait()
        for i, e in enumerate(singles):
            o, r, term, trunc, info = e.step(act[i])
            assert rewards[i] == np.float32(r) and dones[i] == (term or trunc)
            if term or trunc:
                ends += 1
                assert np.array_equal(infos[i]["terminal_observation"], o)
                assert infos[i]["TimeLimit.truncated"] == (trunc and not term)
                assert infos[i]["episode"]["r"] == info["episode"]["r"]
                o, _ = e.reset()
            assert np.array_equal(obs[i], o)
    assert ends >= 4
