"""Train Stable-Baselines3 SAC on a crash suite and save the model.

    python python/examples/train_sb3_sac.py --suite out/demo/suite/train.jsonl --steps 20000

Without --suite it trains on the four bundled example scenarios.
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np
import torch

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from stable_baselines3 import SAC  # noqa: E402
from stable_baselines3.common.logger import Logger  # noqa: E402

import accsim  # noqa: E402
from accsim.sb3 import CrashSB3VecEnv  # noqa: E402


def main() -> int:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--suite", help="JSONL suite to train on (default: the bundled examples)")
    p.add_argument("--steps", type=int, default=20000, help="environment steps (default 20000)")
    p.add_argument("--envs", type=int, default=4, help="parallel environments (default 4)")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--out", default="out/sac_crash.zip", help="where to save the model")
    args = p.parse_args()
    if args.steps < 1 or args.envs < 1:
        p.error("--steps and --envs must be positive")

    torch.set_num_threads(1)  # RL-sized networks: one intra-op thread is fastest here
    env = CrashSB3VecEnv(args.envs, suite=args.suite, seed=args.seed)
    model = SAC("MlpPolicy", env, seed=args.seed, learning_starts=min(1000, args.steps // 2),
                batch_size=256, train_freq=1, gradient_steps=1, verbose=0)
    # SB3's default logger makes a dated folder in /tmp on every run even when
    # it writes nothing there; this one records without writing anywhere.
    model.set_logger(Logger(folder=None, output_formats=[]))
    model.learn(total_timesteps=args.steps, progress_bar=False)
    Path(args.out).parent.mkdir(parents=True, exist_ok=True)
    model.save(args.out)

    reloaded = SAC.load(args.out)
    single = accsim.CrashEnv(suite=args.suite)
    obs, _ = single.reset(seed=args.seed)
    action, _ = reloaded.predict(obs, deterministic=True)
    assert action.shape == (2,) and np.isfinite(action).all()
    shown = ", ".join(f"{x:+.3f}" for x in action)
    print(f"saved {args.out}; reloaded model predicts [{shown}] for the first observation")
    return 0


if __name__ == "__main__":
    sys.exit(main())
