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


def measure(step, reset, seconds, batch=1, windows=5, calls_per_check=None):
    """Best rate over `windows` consecutive windows of seconds / windows:
    other work on a shared machine only ever slows a window down, so the
    best one is the closest to what the code itself costs."""
    reset()
    calls_per_check = calls_per_check or max(1, 400 // batch)
    best = 0.0
    for _ in range(windows):
        steps, start = 0, time.perf_counter()
        while True:
            for _ in range(calls_per_check):
                step()
            steps += calls_per_check * batch
            elapsed = time.perf_counter() - start
            if elapsed >= seconds / windows:
                break
        best = max(best, steps / elapsed)
    return best


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
    # The single-env run's action stream (for N = 1 exactly the same actions,
    # so the same episodes and resets): gentle and varying.
    acts = np.random.default_rng(0).uniform(-0.3, 0.3, (1000, n, 2)).astype(np.float32)
    state = {"t": 0}

    def step():
        vec.step(acts[state["t"] % 1000])
        state["t"] += 1

    return measure(step, lambda: vec.reset(seed=0), seconds, batch=n)


def breakdown(n=128):
    """Where a batched policy step's time goes (one thread, microseconds per
    environment step): physics and the rest of CrashEnv.Step, episode
    resets spread over the steps of an episode, and Python/binding overhead."""
    lc = [p for p in accsim.bundled_scenarios() if "lane_changing" in p]
    acts = np.random.default_rng(0).uniform(-0.3, 0.3, (64, n, 2)).astype(np.float32)
    vec = accsim.make_vec(n, scenario=lc, num_threads=1)
    core = vec.unwrapped._vec
    core.reset(0)
    t0 = time.perf_counter()
    resets = 20
    for k in range(resets):
        core.reset(k * n)
    reset_us = (time.perf_counter() - t0) / (resets * n) * 1e6
    # Steps without episode ends: an episode long enough not to end in the window.
    long = accsim.make_vec(n, scenario=lc, num_threads=1,
                           config={"terminate_on_collision": False, "time_limit": 60.0}).unwrapped._vec
    long.reset(0)
    steps = 30
    t0 = time.perf_counter()
    for k in range(steps):
        long.step(acts[k % 64])
    step_us = (time.perf_counter() - t0) / (steps * n) * 1e6
    # The benchmark's own mix (episodes end and reset), through the raw core
    # binding and through the Gymnasium wrapper, from the same seeds.
    steps = 200
    core.reset(0)
    episodes, t0 = 0, time.perf_counter()
    for k in range(steps):
        core.step(acts[k % 64])
        episodes += int((core.terminated | core.truncated).sum())
    core_us = (time.perf_counter() - t0) / (steps * n) * 1e6
    vec.reset(seed=0)
    t0 = time.perf_counter()
    for k in range(steps):
        vec.step(acts[k % 64])
    wrapped_us = (time.perf_counter() - t0) / (steps * n) * 1e6
    return {"reset_us": reset_us, "step_no_end_us": step_us, "core_mixed_us": core_us,
            "python_overhead_us": max(0.0, wrapped_us - core_us), "mean_episode_steps": steps * n / max(1, episodes)}


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

    # highway-env is slow (tens of steps/s): fewer, longer windows.
    return measure(step, lambda: env.reset(seed=0), 3.0, windows=3, calls_per_check=2), None


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--seconds", type=float, default=2.0)
    p.add_argument("--json", action="store_true")
    args = p.parse_args()
    os.environ.setdefault("OMP_NUM_THREADS", "1")
    load_at_start = os.getloadavg()[0]
    rows = {"single_env": single_accsim(args.seconds)}
    for n in (1, 8, 32, 128):
        for t in (1, 2):
            rows[f"vector_n{n}_t{t}"] = vector_accsim(n, t, args.seconds)
    parts = breakdown()
    hw = {}
    for env_id in ("intersection-v0", "highway-fast-v0"):
        sps, why = highway(env_id, args.seconds)
        hw[env_id] = sps if sps is not None else why
    result = {"machine": {"cpu": platform.processor() or platform.machine(), "cores": os.cpu_count(),
                          "load_average_at_start": load_at_start},
              "accsim_steps_per_second": rows, "highway_env_steps_per_second": hw,
              "breakdown_us_per_env_step": parts}
    if args.json:
        print(json.dumps(result, indent=2))
        return
    best = max(rows.values())
    load = load_at_start
    print(f"Python throughput, 4-vehicle lane-changing scenario, {os.cpu_count()} cores "
          f"(load average {load:.1f} at the start: other work on the machine lowers the 2-thread figures)")
    print(f"  {'accsim single env (Python loop)':<40} {rows['single_env']:>10.0f} steps/s")
    for n in (1, 8, 32, 128):
        print(f"  {'accsim VectorEnv N=' + str(n):<26} 1 thread {rows[f'vector_n{n}_t1']:>10.0f}   "
              f"2 threads {rows[f'vector_n{n}_t2']:>10.0f} steps/s")
    print("  where a batched step's time goes (N=128, 1 thread, per environment step):")
    print(f"    CrashEnv.Step (physics, NPCs, reward, observation)  {parts['step_no_end_us']:6.1f} us")
    print(f"    episode reset {parts['reset_us']:.0f} us / {parts['mean_episode_steps']:.0f} steps per episode"
          f"            {parts['reset_us'] / parts['mean_episode_steps']:6.1f} us")
    print(f"    core total as benchmarked                          {parts['core_mixed_us']:6.1f} us")
    overhead = parts["python_overhead_us"]
    print(f"    Python wrapper and bindings                        "
          f"{'  <0.1' if overhead < 0.1 else f'{overhead:6.1f}'} us")
    for env_id, v in hw.items():
        if isinstance(v, float):
            print(f"  {'highway-env ' + env_id:<40} {v:>10.1f} steps/s   accsim best / this = {best / v:,.0f}x")
        else:
            print(f"  {'highway-env ' + env_id:<40} {v}")


if __name__ == "__main__":
    main()
