#include "hinf/scenario/study.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <limits>
#include <memory>
#include <mutex>
#include <system_error>
#include <thread>
#include <unordered_map>

#include "hinf/core/errors.hpp"
#include "hinf/core/interrupt.hpp"
#include "scenario/scenario_run.hpp"

namespace hinf {

void StudyOptions::validate() const {
  require(threads >= 0, "StudyOptions threads must be >= 0 (0: the hardware's threads), got ", threads);
}

namespace {

// Calls work(i) for every i in [0, count) on up to `threads` worker threads; the calling
// thread waits and calls poll() about every 0.1 s and when the workers are done. work must not
// throw. When poll throws, the workers take no new index, are joined, and the exception is
// rethrown. When no thread can be created the calling thread does the work itself.
template <class Work, class Poll>
void parallel_for(std::size_t count, int threads, const Work& work, const Poll& poll) {
  if (count == 0) {
    poll();
    return;
  }
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::mutex mutex;
  std::condition_variable finished;
  std::size_t running = 0;  // workers not yet finished (under mutex)
  const auto loop = [&] {
    for (std::size_t i; !stop.load(std::memory_order_relaxed) && (i = next.fetch_add(1)) < count;) work(i);
  };
  const std::size_t wanted = std::min(count, static_cast<std::size_t>(std::max(1, threads)));
  std::vector<std::thread> workers;
  workers.reserve(wanted);
  for (std::size_t k = 0; k < wanted; ++k) {
    try {
      {
        std::lock_guard<std::mutex> lock(mutex);
        ++running;
      }
      workers.emplace_back([&] {
        loop();
        std::lock_guard<std::mutex> lock(mutex);
        --running;
        finished.notify_all();
      });
    } catch (const std::system_error&) {  // no more threads: go on with those made
      std::lock_guard<std::mutex> lock(mutex);
      --running;
      break;
    }
  }
  if (workers.empty()) {
    loop();
    poll();
    return;
  }
  std::exception_ptr stopped;
  try {
    std::unique_lock<std::mutex> lock(mutex);
    while (running > 0) {
      finished.wait_for(lock, std::chrono::milliseconds(100));
      lock.unlock();
      poll();  // without the lock: the workers may finish meanwhile
      lock.lock();
    }
  } catch (...) {
    stopped = std::current_exception();
    stop.store(true);
  }
  for (std::thread& worker : workers) worker.join();
  if (stopped) std::rethrow_exception(stopped);
  poll();
}

// A failed run's row: the outcome of its exception and its message.
void record_failure(StudyRun& row, const std::exception_ptr& error) {
  row.metrics = Metrics{};
  try {
    std::rethrow_exception(error);
  } catch (const ConjugatePointError& e) {
    row.status = RunOutcome::ConjugatePoint;
    row.reason = e.what();
  } catch (const CouplingConditionError& e) {
    row.status = RunOutcome::CouplingViolation;
    row.reason = e.what();
  } catch (const SolverError& e) {
    row.status = RunOutcome::SolverFailure;
    row.reason = e.what();
  } catch (const InputError& e) {
    row.status = RunOutcome::InvalidInput;
    row.reason = e.what();
  } catch (const std::exception& e) {
    row.status = RunOutcome::Failed;
    row.reason = e.what();
  } catch (...) {
    row.status = RunOutcome::Failed;
    row.reason = "an exception that is not a std::exception";
  }
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A design of the study and the runs that use it.
struct DesignSlot {
  std::size_t first_run = 0;  // the run whose scenario it is made from
  std::size_t users = 0;
  std::atomic<std::size_t> remaining{0};  // users not yet done (a shared design is freed at 0)
  std::shared_ptr<const detail::ScenarioDesign> design;  // shared designs only (users > 1)
};

}  // namespace

std::vector<StudyRun> run_scenarios(const std::vector<Scenario>& scenarios, const StudyOptions& options,
                                const std::function<void(std::size_t, std::size_t)>& progress) {
  options.validate();
  const std::size_t total = scenarios.size();
  const int threads =
      options.threads > 0 ? options.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::vector<StudyRun> rows(total);
  std::atomic<std::size_t> done{0};
  std::size_t reported = std::numeric_limits<std::size_t>::max();
  const auto poll = [&] {
    throw_if_interrupted();  // the runs in flight stop at their next step (their rows are dropped)
    const std::size_t now = done.load();
    if (now == reported || !progress) return;
    reported = now;
    progress(now, total);
  };

  // 1. Every scenario resolved and validated (an invalid one is a finished row), and the hash
  // of its design inputs.
  std::vector<Scenario> resolved(total);
  std::vector<char> valid(total, 0);
  std::vector<std::size_t> hashes(total, 0);
  parallel_for(
      total, threads,
      [&](std::size_t i) {
        StudyRun& row = rows[i];
        row.law = scenarios[i].law;
        row.output_feedback = scenarios[i].measurement.has_value();
        row.gamma = scenarios[i].law == Law::Lqr ? std::numeric_limits<double>::infinity() : scenarios[i].gamma;
        try {
          resolved[i] = scenarios[i].resolved();
          resolved[i].validate();
          hashes[i] = detail::design_hash(resolved[i]);
          valid[i] = 1;
        } catch (...) {
          record_failure(row, std::current_exception());
          done.fetch_add(1);
        }
      },
      poll);

  // 2. The designs: one per distinct set of design inputs (detail::same_design; in order of
  // first use), or one per run when designs are not shared.
  std::vector<int> design_of(total, -1);
  std::vector<std::unique_ptr<DesignSlot>> slots;
  {
    std::unordered_multimap<std::size_t, int> by_hash;  // the slots with each hash
    for (std::size_t i = 0; i < total; ++i) {
      if (!valid[i]) continue;
      int index = -1;
      if (options.share_designs) {
        const auto [first, last] = by_hash.equal_range(hashes[i]);
        for (auto it = first; it != last && index < 0; ++it)
          if (detail::same_design(resolved[slots[static_cast<std::size_t>(it->second)]->first_run], resolved[i]))
            index = it->second;
      }
      if (index < 0) {
        index = static_cast<int>(slots.size());
        slots.push_back(std::make_unique<DesignSlot>());
        slots.back()->first_run = i;
        if (options.share_designs) by_hash.emplace(hashes[i], index);
      }
      DesignSlot& slot = *slots[static_cast<std::size_t>(index)];
      ++slot.users;
      slot.remaining.store(slot.users);
      design_of[i] = index;
    }
  }
  std::vector<std::size_t> shared;  // the designs used by several runs, computed first
  for (std::size_t k = 0; k < slots.size(); ++k)
    if (slots[k]->users > 1) shared.push_back(k);
  parallel_for(
      shared.size(), threads,
      [&](std::size_t j) {
        DesignSlot& slot = *slots[shared[j]];
        slot.design = std::make_shared<const detail::ScenarioDesign>(detail::design_scenario(resolved[slot.first_run]));
      },
      poll);

  // 3. The runs, each with its design: a shared one, or its own made here.
  parallel_for(
      total, threads,
      [&](std::size_t i) {
        if (!valid[i]) return;
        StudyRun& row = rows[i];
        DesignSlot& slot = *slots[static_cast<std::size_t>(design_of[i])];
        row.design = design_of[i];
        std::shared_ptr<const detail::ScenarioDesign> design = slot.design;
        if (!design) design = std::make_shared<const detail::ScenarioDesign>(detail::design_scenario(resolved[i]));
        row.design_seconds = design->seconds;
        const auto start = std::chrono::steady_clock::now();
        try {
          const RunResult result = detail::simulate_scenario(resolved[i], *design, nullptr, /*sigma_eigenvalues=*/false);
          const RunStatus status = result.simulation.status;
          row.status = status == RunStatus::Diverged    ? RunOutcome::Diverged
                       : status == RunStatus::LostTrack ? RunOutcome::LostTrack
                                                        : RunOutcome::Completed;
          row.reason = status == RunStatus::Completed ? std::string() : result.simulation.status_message;
          row.metrics = result.metrics;
        } catch (...) {
          record_failure(row, std::current_exception());
        }
        row.simulate_seconds = seconds_since(start);
        design.reset();
        if (slot.remaining.fetch_sub(1) == 1) slot.design.reset();  // its last run: free it
        resolved[i] = Scenario{};
        done.fetch_add(1);
      },
      poll);
  if (progress && reported != total) progress(total, total);
  return rows;
}

}  // namespace hinf
