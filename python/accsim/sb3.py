"""Stable-Baselines3 adapter: the C++ batched environment as an SB3 ``VecEnv``
(SB3's convention: same-step autoreset, final observation in
``info["terminal_observation"]``)."""
from __future__ import annotations

import time
from typing import Any, Sequence

import numpy as np
from stable_baselines3.common.vec_env.base_vec_env import VecEnv

from accsim import _core
from accsim._paths import config_args, scenario_paths
from accsim.env import spaces_from_spec

__all__ = ["CrashSB3VecEnv"]


class CrashSB3VecEnv(VecEnv):
    """``num_envs`` crash environments stepped by the C++ ``VectorEnv`` (GIL
    released), seen by SB3 as a ``VecEnv``.

    The core runs in SAME_STEP autoreset mode here, which is what SB3
    expects: an environment whose episode ended is reset within the step,
    the returned observation is the new episode's first, and the last one
    is in ``infos[i]["terminal_observation"]``; ``TimeLimit.truncated`` marks
    time-limit ends so SAC bootstraps through them. ``reset()`` seeds
    environment i with ``seed + i`` and moves ``seed`` on by ``num_envs``.
    Observations are copied out of the core's buffer (SB3 keeps them).
    """

    def __init__(self, num_envs: int, scenario: str | Sequence[str] | None = None, suite: str | None = None,
                 config: Any = None, num_threads: int = 0, seed: int = 0):
        yaml_path, json_text = config_args(config)
        paths = scenario_paths(scenario, suite)
        self._vec = _core.VectorEnv(int(num_envs), paths, yaml_path, json_text, int(num_threads), True)
        obs_space, act_space = spaces_from_spec(self._vec.spec)
        super().__init__(int(num_envs), obs_space, act_space)
        self._seed = seed
        self._t_start = time.time()
        self._actions: np.ndarray | None = None

    def reset(self):
        self._vec.reset(self._seed)
        self._seed += self.num_envs  # the next reset() gets fresh seeds
        return self._vec.observations.copy()

    def step_async(self, actions: np.ndarray) -> None:
        self._actions = np.asarray(actions, dtype=np.float32)

    def step_wait(self):
        self._vec.step(self._actions)
        done = (self._vec.terminated | self._vec.truncated).astype(bool)
        infos: list[dict[str, Any]] = [{} for _ in range(self.num_envs)]
        for i in np.flatnonzero(done):
            infos[i]["terminal_observation"] = self._vec.final_observations[i].copy()
            infos[i]["TimeLimit.truncated"] = bool(self._vec.truncated[i]) and not bool(self._vec.terminated[i])
            final = self._vec.final_info(int(i))
            infos[i]["collision"] = final["collision"]
            # What SB3's Monitor would add: the logger's ep_rew_mean/ep_len_mean.
            infos[i]["episode"] = {"r": final["episode_return"], "l": final["episode_steps"],
                                   "t": round(time.time() - self._t_start, 6)}
        return self._vec.observations.copy(), self._vec.rewards.astype(np.float32), done, infos

    def close(self) -> None:
        self._vec = None

    def seed(self, seed: int | None = None):
        self._seed = 0 if seed is None else int(seed)
        return [self._seed + i for i in range(self.num_envs)]

    def get_attr(self, attr_name, indices=None):
        return [getattr(self, attr_name, None) for _ in self._indices(indices)]

    def set_attr(self, attr_name, value, indices=None):
        setattr(self, attr_name, value)

    def env_method(self, method_name, *args, indices=None, **kwargs):
        raise NotImplementedError("env_method: the C++ environments have no Python methods to call")

    def env_is_wrapped(self, wrapper_class, indices=None):
        return [False for _ in self._indices(indices)]

    def _indices(self, indices):
        if indices is None:
            return range(self.num_envs)
        return [indices] if isinstance(indices, int) else indices
