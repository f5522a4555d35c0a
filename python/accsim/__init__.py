"""accsim: crash reports reconstructed as physically simulated RL scenarios.

The environments are C++ (Bullet physics); this package builds Gymnasium
spaces from the C++ spec and registers ``accsim/Crash-v0``.
"""
from __future__ import annotations

import gymnasium

from accsim._core import EnvSpec  # noqa: F401  (re-exported)
from accsim.env import CrashEnv, bundled_scenarios
from accsim.vector import CrashVectorEnv, make_vec

__all__ = ["CrashEnv", "CrashVectorEnv", "make_vec", "bundled_scenarios"]

if "accsim/Crash-v0" not in gymnasium.registry:
    # gymnasium.make_vec uses the C++ VectorEnv unless vectorization_mode says otherwise.
    gymnasium.register(id="accsim/Crash-v0", entry_point="accsim.env:CrashEnv",
                       vector_entry_point="accsim.vector:CrashVectorEnv")
