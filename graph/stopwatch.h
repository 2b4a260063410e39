#pragma once

#include <chrono>
#include <ctime>

namespace lrsvo {

// Wall-clock time since construction or the last restart(), and the
// process's CPU time (all threads) over the same span, which helps read wall
// times taken on a busy machine. The one timer of the libraries and programs.
class Stopwatch {
 public:
  double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
  double milliseconds() const { return 1e3 * seconds(); }
  double cpuSeconds() const { return static_cast<double>(std::clock() - cpuStart_) / CLOCKS_PER_SEC; }
  void restart() { *this = Stopwatch(); }
  // The seconds since the start or the last lap, and a new lap from now: the
  // times of consecutive phases.
  double lap() {
    const double elapsed = seconds();
    restart();
    return elapsed;
  }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point start_ = Clock::now();
  std::clock_t cpuStart_ = std::clock();
};

}  // namespace lrsvo
