"""Batched environments: a Gymnasium ``VectorEnv`` over the C++ thread pool,
and a Stable-Baselines3 ``VecEnv`` adapter."""
from __future__ import annotations

import os
from typing import Any, Sequence

import gymnasium
import numpy as np
from gymnasium.vector.utils import batch_space

from accsim import _core
from accsim._paths import config_args, scenario_paths
from accsim.env import spaces_from_spec

try:  # gymnasium >= 1.0
    from gymnasium.vector import AutoresetMode
    _NEXT_STEP = AutoresetMode.NEXT_STEP
except ImportError:  # pragma: no cover
    _NEXT_STEP = "NextStep"

__all__ = ["CrashVectorEnv", "make_vec"]


class CrashVectorEnv(gymnasium.vector.VectorEnv):
    """N crash environments stepped in C++ with the GIL released.

    Observations are a float32 ``(num_envs, obs_dim)`` numpy *view* of the
    C++ buffer (no copy): the array returned by ``reset``/``step`` is
    overwritten by the next call — copy it if you keep it. Autoreset mode:
    NEXT_STEP (the step after an episode ends returns the reset observation
    with reward 0). Environment i is seeded with ``seed + i``.
    """

    metadata = {"autoreset_mode": _NEXT_STEP, "render_modes": []}

    def __init__(self, num_envs: int, scenario: str | Sequence[str] | None = None,
                 suite: str | os.PathLike | None = None,
                 config: str | os.PathLike | dict[str, Any] | None = None,
                 num_threads: int = 0, _same_step: bool = False):
        if not isinstance(num_envs, (int, np.integer)) or num_envs < 1:
            raise ValueError(f"num_envs: expected a positive integer, got {num_envs!r}")
        yaml_path, json_text = config_args(config)
        paths = scenario_paths(scenario, suite)
        self._vec = _core.VectorEnv(int(num_envs), paths, yaml_path, json_text, int(num_threads), _same_step)
        probe = _core.CrashEnv(paths[:1], yaml_path, json_text)
        self.single_observation_space, self.single_action_space = spaces_from_spec(probe.spec)
        self.num_envs = int(num_envs)
        self.observation_space = batch_space(self.single_observation_space, self.num_envs)
        self.action_space = batch_space(self.single_action_space, self.num_envs)
        self._was_done = np.zeros(self.num_envs, dtype=bool)

    @property
    def num_threads(self) -> int:
        return self._vec.num_threads

    def reset(self, *, seed: int | None = None, options: dict[str, Any] | None = None):
        if options:
            raise ValueError(f"options: not supported by the vector env, got {sorted(options)}")
        if seed is not None and (not isinstance(seed, (int, np.integer)) or seed < 0):
            raise ValueError(f"seed: expected a non-negative integer, got {seed!r}")
        self._vec.reset(None if seed is None else int(seed))
        self._was_done[:] = False
        return self._vec.observations, {}

    def step(self, actions):
        a = np.asarray(actions)
        self._vec.step(a)
        terminated = self._vec.terminated.astype(bool)
        truncated = self._vec.truncated.astype(bool)
        info: dict[str, Any] = {}
        done = terminated | truncated
        if done.any():
            info["collision"] = np.array([self._vec.collided(i) if done[i] else False for i in range(self.num_envs)])
            info["_collision"] = done.copy()
        return self._vec.observations, self._vec.rewards.copy(), terminated, truncated, info

    def close_extras(self, **kwargs):
        self._vec = None


def make_vec(num_envs: int, **kwargs) -> CrashVectorEnv:
    """``CrashVectorEnv(num_envs, scenario=..., suite=..., config=..., num_threads=...)``."""
    return CrashVectorEnv(num_envs, **kwargs)
