#include "accsim/env/vector_env.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace accsim {

VectorEnv::VectorEnv(int num_envs, const CrashEnvConfig& config,
                     std::vector<std::shared_ptr<const Scenario>> scenarios, int num_threads, AutoresetMode mode)
    : mode_(mode) {
  if (num_envs < 1 || num_envs > 65536) throw std::invalid_argument("num_envs: must be in [1, 65536]");
  if (num_threads < 0 || num_threads > 1024) throw std::invalid_argument("num_threads: must be in [0, 1024]");
  for (int i = 0; i < num_envs; ++i) envs_.push_back(std::make_unique<CrashEnv>(config, scenarios));
  const int dim = spec().obs_dim;
  obs_.assign(static_cast<size_t>(num_envs) * dim, 0.0f);
  final_obs_.assign(static_cast<size_t>(num_envs) * dim, 0.0f);
  rewards_.assign(static_cast<size_t>(num_envs), 0.0);
  terminated_.assign(static_cast<size_t>(num_envs), 0);
  truncated_.assign(static_cast<size_t>(num_envs), 0);
  const int hw = std::max(1u, std::thread::hardware_concurrency());
  num_threads_ = std::min(num_envs, num_threads == 0 ? hw : num_threads);
  for (int w = 1; w < num_threads_; ++w) workers_.emplace_back([this, w] { WorkerLoop(w); });
}

VectorEnv::~VectorEnv() {
  {
    std::lock_guard<std::mutex> lock(mu_);
    stop_ = true;
  }
  start_cv_.notify_all();
  for (auto& t : workers_) t.join();
}

void VectorEnv::WorkerLoop(int worker) {
  long seen = 0;
  for (;;) {
    const std::function<void(int)>* job = nullptr;
    {
      std::unique_lock<std::mutex> lock(mu_);
      start_cv_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      seen = generation_;
      job = job_;
    }
    for (int i = worker; i < num_envs(); i += num_threads_) (*job)(i);
    {
      std::lock_guard<std::mutex> lock(mu_);
      if (--pending_ == 0) done_cv_.notify_one();
    }
  }
}

void VectorEnv::ParallelFor(const std::function<void(int)>& fn) {
  if (num_threads_ == 1) {
    for (int i = 0; i < num_envs(); ++i) fn(i);
    return;
  }
  {
    std::lock_guard<std::mutex> lock(mu_);
    job_ = &fn;
    pending_ = num_threads_ - 1;
    ++generation_;
  }
  start_cv_.notify_all();
  for (int i = 0; i < num_envs(); i += num_threads_) fn(i);  // this thread is worker 0
  std::unique_lock<std::mutex> lock(mu_);
  done_cv_.wait(lock, [&] { return pending_ == 0; });
  job_ = nullptr;
}

void VectorEnv::Reset(std::optional<uint64_t> seed) {
  const int dim = spec().obs_dim;
  ParallelFor([&](int i) {
    CrashEnv& e = *envs_[static_cast<size_t>(i)];
    e.Reset(seed ? std::optional<uint64_t>(*seed + static_cast<uint64_t>(i)) : std::nullopt);
    e.CopyObservation(obs_.data() + static_cast<size_t>(i) * dim);
    rewards_[static_cast<size_t>(i)] = 0.0;
    terminated_[static_cast<size_t>(i)] = truncated_[static_cast<size_t>(i)] = 0;
  });
  was_reset_ = true;
}

void VectorEnv::StepOne(int i, const float* action) {
  const size_t u = static_cast<size_t>(i);
  const int dim = spec().obs_dim;
  CrashEnv& e = *envs_[u];
  float* out = obs_.data() + u * dim;
  if (e.needs_reset()) {  // kNextStep: the step after the end is the reset
    e.Reset();
    e.CopyObservation(out);
    rewards_[u] = 0.0;
    terminated_[u] = truncated_[u] = 0;
    return;
  }
  e.Step(action, static_cast<size_t>(spec().action_dim));
  rewards_[u] = e.reward();
  terminated_[u] = e.terminated();
  truncated_[u] = e.truncated();
  if (mode_ == AutoresetMode::kSameStep && e.needs_reset()) {
    e.CopyObservation(final_obs_.data() + u * dim);
    e.Reset();
  }
  e.CopyObservation(out);
}

void VectorEnv::Step(const float* actions, size_t size) {
  if (!was_reset_) throw std::logic_error("Step() before Reset(): call Reset() first");
  const int adim = spec().action_dim;
  if (size != static_cast<size_t>(num_envs()) * adim) {
    throw std::invalid_argument("actions: expected " + std::to_string(num_envs()) + " x " + std::to_string(adim) +
                                " values, got " + std::to_string(size));
  }
  for (size_t k = 0; k < size; ++k) {
    if (!std::isfinite(actions[k])) {
      throw std::invalid_argument("actions[" + std::to_string(k / adim) + "][" + std::to_string(k % adim) +
                                  "]: not a finite number");
    }
  }
  ParallelFor([&](int i) { StepOne(i, actions + static_cast<size_t>(i) * adim); });
}

}  // namespace accsim
