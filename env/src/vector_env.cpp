#include "accsim/env/vector_env.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace accsim {
namespace {

// Refuses a second concurrent Reset()/Step() (for example from two Python
// threads once the GIL is released) rather than racing on the buffers.
std::unique_lock<std::mutex> ExclusiveCall(std::mutex& mu) {
  std::unique_lock<std::mutex> lock(mu, std::try_to_lock);
  if (!lock.owns_lock()) {
    throw std::logic_error("VectorEnv: Reset()/Step() called while another call is running on another thread");
  }
  return lock;
}

}  // namespace

VectorEnv::VectorEnv(int num_envs, const CrashEnvConfig& config,
                     std::vector<std::shared_ptr<const Scenario>> scenarios, int num_threads, AutoresetMode mode)
    : mode_(mode) {
  if (num_envs < 1 || num_envs > 65536) throw std::invalid_argument("num_envs: must be in [1, 65536]");
  if (num_threads < 0 || num_threads > 1024) throw std::invalid_argument("num_threads: must be in [0, 1024]");
  for (int i = 0; i < num_envs; ++i) envs_.push_back(std::make_unique<CrashEnv>(config, scenarios));
  const size_t n = static_cast<size_t>(num_envs);
  const size_t dim = static_cast<size_t>(spec().obs_dim);
  obs_.assign(n * dim, 0.0f);
  final_obs_.assign(n * dim, 0.0f);
  rewards_.assign(n, 0.0);
  reward_terms_.assign(n * kNumRewardTerms, 0.0);
  terminated_.assign(n, 0);
  truncated_.assign(n, 0);
  final_infos_.assign(n, StepInfo{});
  errors_.assign(n, nullptr);
  const int hw = std::max(1u, std::thread::hardware_concurrency());
  num_threads_ = std::min(num_envs, num_threads == 0 ? hw : num_threads);
  for (int w = 1; w < num_threads_; ++w) workers_.emplace_back([this] { WorkerLoop(); });
}

VectorEnv::~VectorEnv() {
  {
    std::lock_guard<std::mutex> lock(mu_);
    stop_ = true;
  }
  start_cv_.notify_all();
  for (auto& t : workers_) t.join();
}

// Claims indices of `generation` one at a time until none is left. A claim
// succeeds only while the caller is still waiting for that index, so `job`
// is alive whenever it is called. An exception stays with its index (one
// escaping a pool thread would terminate the process).
void VectorEnv::RunClaims(uint32_t generation, const std::function<void(int)>* job) {
  const uint64_t n = envs_.size();
  uint64_t v = next_.load(std::memory_order_acquire);
  for (;;) {
    if ((v >> 32) != generation || (v & 0xffffffffu) >= n) return;
    if (!next_.compare_exchange_weak(v, v + 1, std::memory_order_acq_rel, std::memory_order_acquire)) continue;
    const int i = static_cast<int>(v & 0xffffffffu);
    try {
      (*job)(i);
    } catch (...) {
      errors_[static_cast<size_t>(i)] = std::current_exception();
    }
    if (done_.fetch_add(1, std::memory_order_acq_rel) + 1 == static_cast<int>(n)) {
      std::lock_guard<std::mutex> lock(mu_);  // pairs with the caller's predicate check
      done_cv_.notify_one();
    }
    v = next_.load(std::memory_order_acquire);
  }
}

void VectorEnv::WorkerLoop() {
  uint32_t seen = 0;
  for (;;) {
    const std::function<void(int)>* job = nullptr;
    {
      std::unique_lock<std::mutex> lock(mu_);
      start_cv_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      seen = generation_;
      job = job_;
    }
    RunClaims(seen, job);
  }
}

void VectorEnv::ParallelFor(const std::function<void(int)>& fn) {
  std::fill(errors_.begin(), errors_.end(), nullptr);
  done_.store(0, std::memory_order_relaxed);
  uint32_t generation = 0;
  {
    std::lock_guard<std::mutex> lock(mu_);
    generation = ++generation_;
    job_ = &fn;
    next_.store(static_cast<uint64_t>(generation) << 32, std::memory_order_release);
  }
  if (num_threads_ > 1) start_cv_.notify_all();
  RunClaims(generation, &fn);  // the calling thread works too
  {
    std::unique_lock<std::mutex> lock(mu_);
    done_cv_.wait(lock, [&] { return done_.load(std::memory_order_acquire) == num_envs(); });
  }
  // Lowest index first, so which error is reported does not depend on timing.
  for (const auto& e : errors_) {
    if (e) std::rethrow_exception(e);
  }
}

void VectorEnv::RecordReset(int i) {
  const size_t u = static_cast<size_t>(i);
  envs_[u]->CopyObservation(obs_.data() + u * static_cast<size_t>(spec().obs_dim));
  rewards_[u] = 0.0;
  std::fill_n(reward_terms_.begin() + static_cast<std::ptrdiff_t>(u * kNumRewardTerms), kNumRewardTerms, 0.0);
  terminated_[u] = truncated_[u] = 0;
}

void VectorEnv::Reset(std::optional<uint64_t> seed) {
  auto lock = ExclusiveCall(call_mu_);
  was_reset_ = false;
  ParallelFor([&](int i) {
    envs_[static_cast<size_t>(i)]->Reset(seed ? std::optional<uint64_t>(*seed + static_cast<uint64_t>(i))
                                              : std::nullopt);
    RecordReset(i);
  });
  was_reset_ = true;
}

void VectorEnv::Reset(const std::vector<uint64_t>& seeds) {
  if (seeds.size() != envs_.size()) {
    throw std::invalid_argument("seeds: expected " + std::to_string(num_envs()) + " seeds, got " +
                                std::to_string(seeds.size()));
  }
  auto lock = ExclusiveCall(call_mu_);
  was_reset_ = false;
  ParallelFor([&](int i) {
    envs_[static_cast<size_t>(i)]->Reset(seeds[static_cast<size_t>(i)]);
    RecordReset(i);
  });
  was_reset_ = true;
}

void VectorEnv::StepOne(int i, const float* action) {
  const size_t u = static_cast<size_t>(i);
  CrashEnv& e = *envs_[u];
  if (e.needs_reset()) {  // kNextStep: the step after the end is the reset
    e.Reset();
    RecordReset(i);
    return;
  }
  e.Step(action, static_cast<size_t>(spec().action_dim));
  rewards_[u] = e.reward();
  std::copy(e.info().reward_terms.begin(), e.info().reward_terms.end(),
            reward_terms_.begin() + static_cast<std::ptrdiff_t>(u * kNumRewardTerms));
  terminated_[u] = e.terminated();
  truncated_[u] = e.truncated();
  const size_t dim = static_cast<size_t>(spec().obs_dim);
  if (e.needs_reset()) {
    final_infos_[u] = e.info();
    if (mode_ == AutoresetMode::kSameStep) {
      e.CopyObservation(final_obs_.data() + u * dim);
      e.Reset();
    }
  }
  e.CopyObservation(obs_.data() + u * dim);
}

void VectorEnv::Step(const float* actions, size_t size) {
  auto lock = ExclusiveCall(call_mu_);
  if (!was_reset_) throw std::logic_error("Step() needs Reset() first (never reset, or the last call failed)");
  const int adim = spec().action_dim;
  if (size != static_cast<size_t>(num_envs()) * adim) {
    throw std::invalid_argument("actions: expected " + std::to_string(num_envs()) + " x " + std::to_string(adim) +
                                " values, got " + std::to_string(size));
  }
  if (actions == nullptr) throw std::invalid_argument("actions: null pointer");
  for (size_t k = 0; k < size; ++k) {
    if (!std::isfinite(actions[k])) {
      throw std::invalid_argument("actions[" + std::to_string(k / adim) + "][" + std::to_string(k % adim) +
                                  "]: not a finite number (" + std::to_string(actions[k]) + ")");
    }
  }
  // A failure part-way leaves some environments stepped and others not;
  // Reset() is then the only way on.
  was_reset_ = false;
  ParallelFor([&](int i) { StepOne(i, actions + static_cast<size_t>(i) * adim); });
  was_reset_ = true;
}

}  // namespace accsim
