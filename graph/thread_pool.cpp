#include "lrsvo/graph/thread_pool.h"

#include <atomic>

namespace lrsvo {
namespace {

thread_local bool insideTask = false;

}  // namespace

struct ThreadPool::Job {
  Task task;
  int chunks = 0;
  std::atomic<int> next{0};
  std::atomic<int> seats{0};  // workers that may still join
  std::mutex mutex;           // guards finished and failure
  std::condition_variable allDone;
  int finished = 0;
  std::exception_ptr failure;
};

ThreadPool& ThreadPool::instance() {
  static ThreadPool pool;
  return pool;
}

ThreadPool::~ThreadPool() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  for (std::thread& worker : workers_) worker.join();
}

void ThreadPool::ensureWorkers(int count) {
  std::lock_guard lock(mutex_);
  while (static_cast<int>(workers_.size()) < count) workers_.emplace_back([this] { workerLoop(); });
}

void ThreadPool::runChunks(Job& job) {
  int done = 0;
  std::exception_ptr failure;
  for (int chunk = job.next++; chunk < job.chunks; chunk = job.next++) {
    try {
      job.task.run(job.task.object, chunk);
    } catch (...) {
      if (!failure) failure = std::current_exception();
    }
    ++done;
  }
  std::lock_guard lock(job.mutex);
  if (failure && !job.failure) job.failure = failure;
  job.finished += done;
  if (job.finished == job.chunks) job.allDone.notify_all();
}

void ThreadPool::workerLoop() {
  insideTask = true;  // a loop inside a task runs on its worker alone
  unsigned long long seen = 0;
  for (;;) {
    std::shared_ptr<Job> job;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      seen = generation_;
      job = job_;
    }
    if (job && job->seats-- > 0) runChunks(*job);
  }
}

void ThreadPool::run(int chunks, int threads, Task task) {
  if (chunks <= 0) return;
  std::unique_lock busy(busy_, std::defer_lock);
  const bool alone = threads <= 1 || chunks == 1 || insideTask || !busy.try_lock();
  if (alone) {
    for (int chunk = 0; chunk < chunks; ++chunk) task.run(task.object, chunk);
    return;
  }
  const int helpers = std::min(threads, chunks) - 1;
  ensureWorkers(helpers);
  auto job = std::make_shared<Job>();
  job->task = task;
  job->chunks = chunks;
  job->seats = helpers;
  {
    std::lock_guard lock(mutex_);
    job_ = job;
    ++generation_;
  }
  wake_.notify_all();
  insideTask = true;
  runChunks(*job);
  insideTask = false;
  std::unique_lock lock(job->mutex);
  job->allDone.wait(lock, [&] { return job->finished == job->chunks; });
  if (job->failure) std::rethrow_exception(job->failure);
}

}  // namespace lrsvo
