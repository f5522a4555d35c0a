"""The single Gymnasium environment ``accsim/Crash-v0``."""
from __future__ import annotations

import os
from typing import Any, Sequence

import gymnasium
import numpy as np
from gymnasium import spaces

from accsim import _core
from accsim._paths import bundled_scenarios, config_args, scenario_paths

__all__ = ["CrashEnv", "bundled_scenarios", "spaces_from_spec"]


def spaces_from_spec(spec: _core.EnvSpec) -> tuple[spaces.Box, spaces.Box]:
    """Observation and action spaces from the C++ spec (the one source of truth)."""
    obs = spaces.Box(low=spec.obs_low, high=spec.obs_high, shape=(spec.obs_dim,), dtype=np.float32)
    act = spaces.Box(low=spec.action_low, high=spec.action_high, shape=(spec.action_dim,), dtype=np.float32)
    return obs, act


class CrashEnv(gymnasium.Env):
    """The ego drives through a reconstructed crash (Bullet physics in C++).

    Args:
        scenario: a scenario ``.json`` path or a list of them.
        suite: a ``.jsonl`` suite (one scenario per line).
        config: a YAML path or a dict of CrashEnvConfig fields.
        render_mode: ``None`` or ``"rgb_array"`` (top-down, following the ego).

    With neither scenario nor suite, the four bundled example scenarios are
    used. Observations are float32 in [-1, 1]; ``spec_names`` names each
    element. ``reset(options={"scenario_index": i})`` picks a scenario.
    """

    metadata = {"render_modes": ["rgb_array"], "render_fps": 10}

    def __init__(self, scenario: str | os.PathLike | Sequence[str] | None = None,
                 suite: str | os.PathLike | None = None,
                 config: str | os.PathLike | dict[str, Any] | None = None,
                 render_mode: str | None = None):
        if render_mode is not None and render_mode not in self.metadata["render_modes"]:
            raise ValueError(f"render_mode: expected None or 'rgb_array', got {render_mode!r}")
        yaml_path, json_text = config_args(config)
        self._env = _core.CrashEnv(scenario_paths(scenario, suite), yaml_path, json_text)
        spec = self._env.spec
        self.observation_space, self.action_space = spaces_from_spec(spec)
        self.obs_names = list(spec.obs_names)
        self.reward_terms = list(spec.reward_terms)
        self._action_names = list(spec.action_names)
        self.metadata = dict(self.metadata, render_fps=round(1.0 / spec.policy_dt))
        self.render_mode = render_mode
        self._renderer = _core.Renderer() if render_mode == "rgb_array" else None
        self._seeded = False

    @property
    def num_scenarios(self) -> int:
        return self._env.num_scenarios

    def reset(self, *, seed: int | None = None, options: dict[str, Any] | None = None):
        super().reset(seed=seed)
        options = dict(options or {})
        index = options.pop("scenario_index", -1)
        if options:
            raise ValueError(f"options: unknown keys {sorted(options)} (known: scenario_index)")
        if seed is None and not self._seeded:
            # Gymnasium seeds np_random from entropy when no seed is given;
            # draw the C++ seed from it so unseeded runs still differ.
            seed = int(self.np_random.integers(0, 2**63 - 1))
        if seed is not None:
            if not isinstance(seed, (int, np.integer)) or seed < 0:
                raise ValueError(f"seed: expected a non-negative integer, got {seed!r}")
            self._seeded = True
        obs, info = self._env.reset(None if seed is None else int(seed), int(index))
        return obs, info

    def step(self, action):
        a = np.asarray(action)
        if a.shape != self.action_space.shape:
            raise ValueError(f"action: expected shape {self.action_space.shape}, got {a.shape}")
        if a.dtype != np.float32:
            # float32 goes straight to the core, which rejects NaN/inf naming
            # the element; other numbers are checked here before the cast.
            if a.dtype.kind not in "fiu":
                raise ValueError(f"action: expected real numbers, got dtype {a.dtype}")
            with np.errstate(over="ignore"):  # overflow is handled just below
                f = a.astype(np.float32)
            if not np.isfinite(f).all():
                bad = np.flatnonzero(~np.isfinite(a))
                if bad.size:
                    k = int(bad[0])
                    raise ValueError(f"action[{k}] ({self._action_names[k]}): not a finite number ({a[k]!r})")
                # Finite but beyond float32's range: clip rather than let the
                # cast make inf (the core clips to [-1, 1] and counts it anyway).
                f = np.clip(a, -1e6, 1e6).astype(np.float32)
            a = f
        obs, reward, terminated, truncated, info = self._env.step(a)
        if terminated or truncated:
            info["episode"] = {"r": info["episode_return"], "l": info["episode_steps"], "t": info["time"]}
        return obs, float(reward), bool(terminated), bool(truncated), info

    def render(self):
        if self._renderer is None:
            return None
        return self._renderer.render(self._env)
