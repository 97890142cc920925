#include "tools/cli/interrupt.h"

#include <signal.h>

#include <atomic>
#include <csignal>

namespace scallop {

namespace {

// Lock-free so that the handler only does async-signal-safe work (C++17 [support.signal]).
std::atomic<bool> gInterrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free, "the SIGINT flag must be lock-free");

std::atomic<int> gPollingScopes{0};
static_assert(std::atomic<int>::is_always_lock_free, "the polling count must be lock-free");

extern "C" void onSigint(int signo) {
  if (gPollingScopes.load() == 0 || gInterrupted.exchange(true)) {
    // Nobody polls, or a second Ctrl-C: die as SIGINT would have.
    std::signal(signo, SIG_DFL);
    std::raise(signo);
  }
}

}  // namespace

void installInterruptHandler() {
  struct sigaction action {};
  action.sa_handler = onSigint;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // blocking reads and writes carry on; loops poll the flag
  sigaction(SIGINT, &action, nullptr);
}

void beginInterruptPolling() {
  gPollingScopes.fetch_add(1);
}

void endInterruptPolling() {
  gPollingScopes.fetch_sub(1);
}

bool interruptRequested() {
  return gInterrupted.load(std::memory_order_relaxed);
}

void setInterrupted(bool interrupted) {
  gInterrupted.store(interrupted);
}

void throwIfInterrupted() {
  if (interruptRequested()) throw Interrupted();
}

}  // namespace scallop
