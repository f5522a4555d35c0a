"""Policy steps per second from Python: accsim's single env, its C++
VectorEnv for several sizes and thread counts, and highway-env's
intersection-v0 and highway-fast-v0, measured in the same run.

    bash scripts/bench-python.sh [--seconds 2] [--json]
"""
from __future__ import annotations

import argparse
import json
import os
import platform
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "python"))
import accsim  # noqa: E402


def measure(step, reset, seconds, batch=1):
    reset()
    steps, start = 0, time.perf_counter()
    while True:
        for _ in range(50):
            step()
        steps += 50 * batch
        elapsed = time.perf_counter() - start
        if elapsed >= seconds:
            return steps / elapsed


def single_accsim(seconds):
    env = accsim.CrashEnv(scenario=[p for p in accsim.bundled_scenarios() if "lane_changing" in p])
    rng = np.random.default_rng(0)
    acts = rng.uniform(-0.3, 0.3, (1000, 2)).astype(np.float32)
    state = {"t": 0}

    def step():
        _, _, term, trunc, _ = env.step(acts[state["t"] % 1000])
        state["t"] += 1
        if term or trunc:
            env.reset()

    return measure(step, lambda: env.reset(seed=0), seconds)


def vector_accsim(n, threads, seconds):
    vec = accsim.make_vec(n, scenario=[p for p in accsim.bundled_scenarios() if "lane_changing" in p],
                          num_threads=threads)
    # The same kind of actions as the single-env run: gentle and varying.
    acts = np.random.default_rng(0).uniform(-0.3, 0.3, (64, n, 2)).astype(np.float32)
    state = {"t": 0}

    def step():
        vec.step(acts[state["t"] % 64])
        state["t"] += 1

    return measure(step, lambda: vec.reset(seed=0), seconds, batch=n)


def highway(env_id, seconds):
    try:
        import gymnasium
        import highway_env  # noqa: F401
    except ImportError as e:
        return None, f"not installed ({e})"
    env = gymnasium.make(env_id)
    env.reset(seed=0)
    state = {}

    def step():
        _, _, term, trunc, _ = env.step(env.action_space.sample())
        if term or trunc:
            env.reset()

    # highway-env is slow; a shorter window is enough for its figure.
    return measure(step, lambda: env.reset(seed=0), min(seconds, 3.0)), None


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--seconds", type=float, default=2.0)
    p.add_argument("--json", action="store_true")
    args = p.parse_args()
    os.environ.setdefault("OMP_NUM_THREADS", "1")
    rows = {"single_env": single_accsim(args.seconds)}
    for n in (1, 8, 32, 128):
        for t in (1, 2):
            rows[f"vector_n{n}_t{t}"] = vector_accsim(n, t, args.seconds)
    hw = {}
    for env_id in ("intersection-v0", "highway-fast-v0"):
        sps, why = highway(env_id, args.seconds)
        hw[env_id] = sps if sps is not None else why
    result = {"machine": {"cpu": platform.processor() or platform.machine(), "cores": os.cpu_count()},
              "accsim_steps_per_second": rows, "highway_env_steps_per_second": hw}
    if args.json:
        print(json.dumps(result, indent=2))
        return
    best = max(rows.values())
    print(f"Python throughput, 4-vehicle lane-changing scenario, {os.cpu_count()} cores")
    print(f"  {'accsim single env (Python loop)':<40} {rows['single_env']:>10.0f} steps/s")
    for n in (1, 8, 32, 128):
        print(f"  {'accsim VectorEnv N=' + str(n):<26} 1 thread {rows[f'vector_n{n}_t1']:>10.0f}   "
              f"2 threads {rows[f'vector_n{n}_t2']:>10.0f} steps/s")
    for env_id, v in hw.items():
        if isinstance(v, float):
            print(f"  {'highway-env ' + env_id:<40} {v:>10.1f} steps/s   accsim best / this = {best / v:,.0f}x")
        else:
            print(f"  {'highway-env ' + env_id:<40} {v}")


if __name__ == "__main__":
    main()
