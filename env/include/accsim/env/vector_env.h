// VectorEnv: N CrashEnvs stepped together on a persistent thread pool, with
// contiguous, owner-held output buffers (observations [N, obs_dim] float32,
// rewards [N] float64, terminated/truncated [N] uint8) that bindings expose
// without copying.
//
// Autoreset (Gymnasium 1.x terms):
//  * kNextStep: the step after an episode ends resets that environment and
//    reports its first observation with reward 0 and both flags false.
//  * kSameStep: an ending environment is reset within the same step; its
//    final observation is kept in final_observations() (Stable-Baselines3's
//    convention).
// Determinism: each environment's results depend only on its own seed
// (Reset(seed) gives environment i the seed `seed + i`), never on the
// number of threads or on scheduling: threads claim environments one at a
// time (so an episode reset, ~50x a step, or a descheduled thread does not
// leave the other thread idle), and whichever thread runs environment i
// computes the same thing from i's own state into i's own rows.
// Errors: an exception thrown while stepping or resetting environment i is
// caught on its thread and rethrown from Step()/Reset() on the caller's
// thread (the lowest failing index, so the error does not depend on timing).
// Thread-safety: Reset() and Step() must not overlap; a second caller gets
// std::logic_error instead of a data race. The output buffers are owned by
// the VectorEnv, stay at the same address for its lifetime, and are
// overwritten by every Reset()/Step().
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "accsim/env/crash_env.h"

namespace accsim {

enum class AutoresetMode { kNextStep, kSameStep };

class VectorEnv {
 public:
  // `num_threads` 0 means one per hardware thread (at most num_envs).
  VectorEnv(int num_envs, const CrashEnvConfig& config, std::vector<std::shared_ptr<const Scenario>> scenarios,
            int num_threads = 0, AutoresetMode mode = AutoresetMode::kNextStep);
  ~VectorEnv();
  VectorEnv(const VectorEnv&) = delete;
  VectorEnv& operator=(const VectorEnv&) = delete;

  int num_envs() const { return static_cast<int>(envs_.size()); }
  int num_threads() const { return num_threads_; }
  AutoresetMode autoreset_mode() const { return mode_; }
  const EnvSpec& spec() const { return envs_.front()->spec(); }

  // Resets every environment; with a seed, environment i gets seed + i.
  void Reset(std::optional<uint64_t> seed = std::nullopt);
  // One seed per environment (`seeds.size() == num_envs`).
  void Reset(const std::vector<uint64_t>& seeds);
  // `actions` is [num_envs, action_dim] row-major. Validates every element
  // first (throws std::invalid_argument naming env and element, stepping
  // nothing), then steps all environments in parallel.
  void Step(const float* actions, size_t size);

  float* observations() { return obs_.data(); }
  const double* rewards() const { return rewards_.data(); }
  const uint8_t* terminated() const { return terminated_.data(); }
  const uint8_t* truncated() const { return truncated_.data(); }
  // [num_envs, kNumRewardTerms] weighted reward terms of the last step
  // (row sums equal rewards()); zeros after a reset.
  const double* reward_terms() const { return reward_terms_.data(); }
  // kSameStep: the last observation of environments that ended this step.
  const float* final_observations() const { return final_obs_.data(); }
  // The info of environment i's last step that ended an episode (either
  // mode; under kSameStep env(i).info() already belongs to the new episode).
  // Valid from that step until the environment's next episode ends.
  const StepInfo& final_info(int i) const { return final_infos_.at(static_cast<size_t>(i)); }
  const CrashEnv& env(int i) const { return *envs_.at(static_cast<size_t>(i)); }

 private:
  void ParallelFor(const std::function<void(int)>& fn);
  void RunClaims(uint32_t generation, const std::function<void(int)>* job);
  void WorkerLoop();
  void StepOne(int i, const float* action);
  void RecordReset(int i);

  std::vector<std::unique_ptr<CrashEnv>> envs_;
  AutoresetMode mode_;
  int num_threads_ = 1;
  std::vector<float> obs_, final_obs_;
  std::vector<double> rewards_;
  std::vector<double> reward_terms_;
  std::vector<uint8_t> terminated_, truncated_;
  std::vector<StepInfo> final_infos_;
  std::vector<std::exception_ptr> errors_;  // per environment, from the last ParallelFor
  bool was_reset_ = false;
  std::mutex call_mu_;  // held by Reset()/Step(); overlapping calls are refused

  // Thread pool: a new generation wakes the workers; the caller and the
  // workers then claim indices from next_ until all are taken, and the
  // caller waits until done_ counts all of them. next_ carries the
  // generation in its high 32 bits, so a worker that wakes late can never
  // claim an index (or touch the job) of a generation it did not read.
  std::vector<std::thread> workers_;
  std::mutex mu_;
  std::condition_variable start_cv_, done_cv_;
  const std::function<void(int)>* job_ = nullptr;  // guarded by mu_
  uint32_t generation_ = 0;                         // guarded by mu_
  bool stop_ = false;                               // guarded by mu_
  std::atomic<uint64_t> next_{0};  // generation << 32 | next unclaimed index
  std::atomic<int> done_{0};       // indices finished in this generation
};

}  // namespace accsim
