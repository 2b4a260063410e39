#pragma once

#include <atomic>

namespace lrsvo::cli {

// Ctrl-C (SIGINT) and SIGTERM during a long command: while one of these lives,
// the first such signal only sets requested(), so the command can stop after
// the current frame and write whole outputs; the handler then steps aside, and
// a second signal ends the program at once. The previous handlers come back
// when it is destroyed. One at a time.
class StopOnSignal {
 public:
  StopOnSignal();
  ~StopOnSignal();
  StopOnSignal(const StopOnSignal&) = delete;
  StopOnSignal& operator=(const StopOnSignal&) = delete;

  const std::atomic<bool>& requested() const;
  // Throws Interrupted when a signal asked the command to stop.
  void throwIfRequested() const;
};

// A command that stopped on a signal after writing its outputs: main() exits
// with 128 + signal, as a shell reports a process a signal ended.
struct Interrupted {
  int signal = 0;
};

}  // namespace lrsvo::cli
