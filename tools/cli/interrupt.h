// Interrupt: Ctrl-C (SIGINT) stops a long run promptly and cleanly.
//
// The first SIGINT only sets a flag. Long loops poll it through the progress callback
// (ProgressBar::update, called after every cell tile), which throws Interrupted; the
// exception unwinds normally out of the TBB loop (TBB cancels the other tiles and
// rethrows it in the caller), so every AtomicFile destructor removes its temporary
// file and no partial output is left. tools/main.cpp maps it to the message
// "scallop: interrupted" and exit status 130 (128 + SIGINT, the shell's convention).
// A second SIGINT restores the default action and re-raises: the process dies at once,
// for a user who does not want to wait for the current tile (a killed process may
// leave a hidden ".NAME.tmp-PID-N" file, see tools/io/atomic_file.h).
#pragma once

#include <stdexcept>

namespace scallop {

class Interrupted : public std::runtime_error {
 public:
  Interrupted() : std::runtime_error("interrupted") {}
};

// Installs the SIGINT handler (main.cpp, once, before any work).
void installInterruptHandler();

// Code that polls brackets its long work with these (ProgressBar's constructor and
// destructor do). While no such scope is open, SIGINT keeps its default effect, so a
// command that never polls still stops at once instead of ignoring the first Ctrl-C.
void beginInterruptPolling();
void endInterruptPolling();

// True once SIGINT arrived (or setInterrupted(true) was called).
bool interruptRequested();

// Sets or clears the flag, as the handler sets it (tests; callers that cancel).
void setInterrupted(bool interrupted);

// Throws Interrupted when interruptRequested(); cheap enough to call per tile.
void throwIfInterrupted();

}  // namespace scallop
