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
                 num_threads: int = 0, render_mode: str | None = None, _same_step: bool = False):
        if render_mode is not None:
            raise ValueError(f"render_mode: the vector env does not render, got {render_mode!r}")
        if not isinstance(num_envs, (int, np.integer)) or num_envs < 1:
            raise ValueError(f"num_envs: expected a positive integer, got {num_envs!r}")
        yaml_path, json_text = config_args(config)
        paths = scenario_paths(scenario, suite)
        self._vec = _core.VectorEnv(int(num_envs), paths, yaml_path, json_text, int(num_threads), _same_step)
        self.single_observation_space, self.single_action_space = spaces_from_spec(self._vec.spec)
        self.num_envs = int(num_envs)
        self.observation_space = batch_space(self.single_observation_space, self.num_envs)
        self.action_space = batch_space(self.single_action_space, self.num_envs)
        self._term_names = list(self._vec.spec.reward_terms)
        self._seeded = False

    @property
    def num_threads(self) -> int:
        return self._vec.num_threads

    def reset(self, *, seed: int | Sequence[int] | None = None, options: dict[str, Any] | None = None):
        """``seed``: an int (environment i gets ``seed + i``), a list of one
        seed per environment, or None (each continues its own stream)."""
        if options:
            raise ValueError(f"options: not supported by the vector env, got {sorted(options)}")
        if seed is not None and not isinstance(seed, (int, np.integer)):
            seeds = list(seed)
            if len(seeds) != self.num_envs:
                raise ValueError(f"seed: expected {self.num_envs} seeds, got {len(seeds)}")
            if any(s is not None for s in seeds):
                self._vec.reset_each([_seed(s, f"seed[{i}]") for i, s in enumerate(seeds)])
                self._seeded = True
                return self._vec.observations, {}
            seed = None
        if seed is None and not self._seeded:
            # Never seeded: draw a base seed from OS entropy so that the
            # environments neither start alike nor repeat across runs.
            seed = int(np.random.SeedSequence().generate_state(1, np.uint64)[0] >> np.uint64(1))
        self._vec.reset(None if seed is None else _seed(seed, "seed"))
        self._seeded = True
        return self._vec.observations, {}

    def step(self, actions):
        a = np.asarray(actions)
        if a.dtype != np.float32 and a.dtype.kind in "fiu" and a.shape == self.action_space.shape:
            # The core checks float32 input itself; other numbers are checked
            # here first, because finite float64 values beyond float32's
            # range would become inf in the cast (the core clips to [-1, 1]).
            bad = np.argwhere(~np.isfinite(a))
            if bad.size:
                i, j = (int(x) for x in bad[0])
                raise ValueError(f"actions[{i}][{j}]: not a finite number ({a[i, j]!r})")
            a = np.clip(a, -1e6, 1e6)
        self._vec.step(a)
        terminated = self._vec.terminated.astype(bool)
        truncated = self._vec.truncated.astype(bool)
        terms = self._vec.reward_terms
        info: dict[str, Any] = {"reward_terms": {name: terms[:, k].copy() for k, name in enumerate(self._term_names)}}
        done = terminated | truncated
        if done.any():
            # Episode statistics at the step an episode ends, with Gymnasium's
            # "_key" masks saying which entries are valid.
            idx = np.flatnonzero(done)
            collision = np.zeros(self.num_envs, dtype=bool)
            ret = np.zeros(self.num_envs)
            length = np.zeros(self.num_envs, dtype=np.int64)
            for i in idx:
                final = self._vec.final_info(int(i))
                collision[i] = final["collision"]
                ret[i] = final["episode_return"]
                length[i] = final["episode_steps"]
            info["collision"], info["_collision"] = collision, done.copy()
            info["episode"] = {"r": ret, "l": length, "_r": done.copy(), "_l": done.copy()}
            info["_episode"] = done.copy()
        return self._vec.observations, self._vec.rewards.copy(), terminated, truncated, info

    def close_extras(self, **kwargs):
        self._vec = None


def _seed(value: Any, name: str) -> int:
    if not isinstance(value, (int, np.integer)) or isinstance(value, bool) or value < 0 or value >= 2**64:
        raise ValueError(f"{name}: expected an integer in [0, 2**64), got {value!r}")
    return int(value)


def make_vec(num_envs: int, **kwargs) -> CrashVectorEnv:
    """``CrashVectorEnv(num_envs, scenario=..., suite=..., config=..., num_threads=...)``."""
    return CrashVectorEnv(num_envs, **kwargs)
