import gc
import weakref

import gymnasium
import numpy as np
import pytest

import accsim


def actions(n, t):
    i = np.arange(n)
    return np.stack([0.4 * np.sin(0.1 * t + i), 0.2 * np.cos(0.05 * t + 2 * i)], axis=1).astype(np.float32)


def run(vec, steps=120):
    out = [vec.reset(seed=10)[0].copy()]
    for t in range(steps):
        obs, r, term, trunc, _ = vec.step(actions(vec.num_envs, t))
        out += [obs.copy(), r, term, trunc]
    return out


def test_thread_count_does_not_change_results():
    a = run(accsim.make_vec(8, num_threads=1))
    b = run(accsim.make_vec(8, num_threads=2))
    assert all(np.array_equal(x, y) for x, y in zip(a, b))


def test_vector_matches_single_envs_with_the_same_seeds():
    vec = accsim.make_vec(3, num_threads=2)
    singles = [accsim.CrashEnv() for _ in range(3)]
    obs, _ = vec.reset(seed=10)
    for i, e in enumerate(singles):
        o, _ = e.reset(seed=10 + i)
        assert np.array_equal(obs[i], o)
    done = [False] * 3
    for t in range(150):
        a = actions(3, t)
        obs, r, term, trunc, _ = vec.step(a)
        for i, e in enumerate(singles):
            if done[i]:  # NEXT_STEP autoreset: this step is the reset
                o, _ = e.reset()
                assert r[i] == 0.0 and not term[i] and not trunc[i]
                done[i] = False
            else:
                o, ri, ti, tr, _ = e.step(a[i])
                assert r[i] == ri and term[i] == ti and trunc[i] == tr
                done[i] = ti or tr
            assert np.array_equal(obs[i], o), (t, i)


def test_observations_are_a_zero_copy_view_that_keeps_its_owner_alive():
    vec = accsim.make_vec(4)
    obs, _ = vec.reset(seed=0)
    assert obs.dtype == np.float32 and obs.shape == (4, vec.single_observation_space.shape[0])
    assert obs.base is not None and not obs.flags.owndata
    before = obs.copy()
    obs2, *_ = vec.step(np.zeros((4, 2), np.float32))
    assert np.shares_memory(obs, obs2)  # the same buffer, updated in place
    assert not np.array_equal(before, obs)
    owner = obs.base
    while isinstance(owner, np.ndarray):
        owner = owner.base
    alive = weakref.ref(owner)
    del vec, obs2, owner
    gc.collect()
    assert alive() is not None and np.isfinite(obs).all()  # the view keeps the C++ owner alive
    del obs
    gc.collect()
    assert alive() is None  # ... and only the views did


@pytest.mark.parametrize("bad, match", [
    (np.zeros((3, 2), np.float32), "shape"),
    (np.zeros(8, np.float32), "shape"),
    (np.full((4, 2), np.nan, np.float32), r"actions\[0\]\[0\]"),
    (np.array([[0, 0], [0, 0], [0, np.inf], [0, 0]]), r"actions\[2\]\[1\]"),
    (np.array([["a", "b"]] * 4), "numeric"),
])
def test_bad_actions_raise_value_error(bad, match):
    vec = accsim.make_vec(4)
    vec.reset(seed=0)
    with pytest.raises(ValueError, match=match):
        vec.step(bad)
    vec.step(np.zeros((4, 2), np.float32))


def test_metadata_declares_the_autoreset_mode():
    # gymnasium 1.1 names it AutoresetMode.NEXT_STEP, whose value is "NextStep";
    # 1.0 (pinned here) has only that behaviour and no enum yet.
    mode = accsim.CrashVectorEnv.metadata["autoreset_mode"]
    assert getattr(mode, "value", mode) == "NextStep"


def test_gymnasium_make_vec_uses_the_cpp_vector_env_and_matches_sync():
    """The vector entry point and Gymnasium's own SyncVectorEnv over single
    envs (both NEXT_STEP) give identical arrays for the same seeds."""
    config = {"time_limit": 1.5, "npc_time_jitter": 0.2}
    native = gymnasium.make_vec("accsim/Crash-v0", num_envs=3, config=config)
    assert isinstance(native.unwrapped, accsim.CrashVectorEnv)
    sync = gymnasium.make_vec("accsim/Crash-v0", num_envs=3, vectorization_mode="sync", config=config)
    a, _ = native.reset(seed=5)
    b, _ = sync.reset(seed=5)
    assert np.array_equal(a, b)
    ends = 0
    for t in range(40):
        act = actions(3, t)
        a, ra, ta, tra, _ = native.step(act)
        b, rb, tb, trb, _ = sync.step(act)
        assert np.array_equal(a, b) and np.array_equal(ra, rb), t
        assert np.array_equal(ta, tb) and np.array_equal(tra, trb), t
        ends += int((ta | tra).sum())
    assert ends >= 3  # autoresets happened on the way


def test_reset_with_a_list_of_seeds():
    vec = accsim.make_vec(3, config={"npc_time_jitter": 0.3, "start_speed_jitter": 1.0})
    a = vec.reset(seed=20)[0].copy()
    b = vec.reset(seed=[20, 21, 22])[0].copy()
    assert np.array_equal(a, b)
    c = vec.reset(seed=[22, 21, 20])[0].copy()
    assert np.array_equal(c[0], a[2]) and np.array_equal(c[2], a[0])
    with pytest.raises(ValueError, match="seed"):
        vec.reset(seed=[1, 2])
    with pytest.raises(ValueError, match=r"seed\[1\]"):
        vec.reset(seed=[1, -2, 3])


def test_unseeded_environments_do_not_start_alike():
    vec = accsim.make_vec(6, config={"npc_time_jitter": 0.3, "start_speed_jitter": 1.0})
    obs, _ = vec.reset()
    assert len({row.tobytes() for row in obs}) == 6


def test_info_has_reward_terms_and_episode_statistics():
    vec = accsim.make_vec(4, config={"time_limit": 1.0})
    vec.reset(seed=0)
    names = vec.unwrapped._term_names
    returns = np.zeros(4)
    for t in range(10):
        _, r, term, trunc, info = vec.step(np.zeros((4, 2), np.float32))
        total = sum(info["reward_terms"][n] for n in names)
        assert np.allclose(total, r)
        returns += r
    done = term | trunc
    assert done.all()
    assert np.array_equal(info["_episode"], done)
    assert np.allclose(info["episode"]["r"], returns)
    assert (info["episode"]["l"] == 10).all()
    assert info["collision"].dtype == bool


def test_view_base_is_the_cpp_owner():
    vec = accsim.make_vec(2)
    obs, _ = vec.reset(seed=0)
    base = obs.base
    while isinstance(base, np.ndarray):
        base = base.base
    assert isinstance(base, accsim._core.VectorEnv)
    assert obs.ctypes.data == vec.unwrapped._vec.observations.ctypes.data
    # Buffers the caller has no business writing are read-only views.
    assert not vec.unwrapped._vec.rewards.flags.writeable
    assert not vec.unwrapped._vec.terminated.flags.writeable


def test_finite_float64_actions_beyond_float32_are_clipped_not_rejected():
    vec = accsim.make_vec(2)
    vec.reset(seed=0)
    vec.step(np.array([[1e300, -1e300], [0.0, 0.0]]))
    with pytest.raises(ValueError, match="dtype"):
        vec.step(np.zeros((2, 2), dtype=bool))
