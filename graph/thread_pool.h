#pragma once

#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace lrsvo {

// The process's worker threads for parallelFor (graph/parallel_for.h).
//
// Idle workers sleep on a condition variable instead of spinning: the
// odometry calls OpenCV (KLT, stereo matching) between its parallel loops,
// and OpenCV runs on a pool of its own; on 2 cores, OpenMP's spinning idle
// threads made KLT take about 45 % longer beside it (docs/simulator.md).
// Workers are made on first use, as many as the largest request asks for.
class ThreadPool {
 public:
  // A chunk of a loop: task(object, chunk) runs chunk `chunk`.
  struct Task {
    const void* object;
    void (*run)(const void* object, int chunk);
  };

  static ThreadPool& instance();
  ThreadPool() = default;
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  // Runs task for chunks 0 .. chunks - 1 on the calling thread and up to
  // threads - 1 workers; returns when every chunk has run. The first exception
  // a chunk throws is rethrown here (the other chunks still run). Called from
  // inside a task, or while another thread's loop runs, it runs the chunks on
  // the calling thread alone.
  void run(int chunks, int threads, Task task);

 private:
  struct Job;
  void ensureWorkers(int count);
  void workerLoop();
  static void runChunks(Job& job);

  std::mutex mutex_;  // guards job_, generation_, stop_ and workers_
  std::condition_variable wake_;
  std::vector<std::thread> workers_;
  std::shared_ptr<Job> job_;
  unsigned long long generation_ = 0;
  bool stop_ = false;
  std::mutex busy_;  // held by the thread whose loop the workers serve
};

}  // namespace lrsvo
