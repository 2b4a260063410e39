#include "apps/stop_on_signal.h"

#include <unistd.h>
#include <csignal>
#include <cstring>

#include "lrsvo/graph/error.h"

namespace lrsvo::cli {
namespace {

std::atomic<bool> stopRequested{false};
std::atomic<int> stopSignal{0};
std::atomic<bool> installed{false};
struct sigaction previousInterrupt, previousTerminate;

void onSignal(int number) {
  stopSignal.store(number);
  stopRequested.store(true);
  constexpr char kMessage[] = "\nlrsvo: stopping after this frame and writing the outputs (again to quit at once)\n";
  [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, kMessage, sizeof kMessage - 1);
  // The next signal takes the default action: the program ends.
  std::signal(number, SIG_DFL);
}

}  // namespace

static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free,
              "a signal handler may only touch lock-free atomics");

StopOnSignal::StopOnSignal() {
  if (installed.exchange(true)) throw Error("StopOnSignal: one at a time");
  stopRequested.store(false);
  stopSignal.store(0);
  struct sigaction action;
  std::memset(&action, 0, sizeof action);
  action.sa_handler = onSignal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &previousInterrupt);
  sigaction(SIGTERM, &action, &previousTerminate);
}

StopOnSignal::~StopOnSignal() {
  sigaction(SIGINT, &previousInterrupt, nullptr);
  sigaction(SIGTERM, &previousTerminate, nullptr);
  installed.store(false);
}

const std::atomic<bool>& StopOnSignal::requested() const { return stopRequested; }

void StopOnSignal::throwIfRequested() const {
  if (stopRequested.load()) throw Interrupted{stopSignal.load()};
}

}  // namespace lrsvo::cli
