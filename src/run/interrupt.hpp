#pragma once
// SIGINT, SIGTERM and SIGHUP during a run: the step loop stops at the end of the current step,
// the log is marked "interrupted: <signal> ..." and the process exits with 128 + the signal's
// number (130, 143, 129), as a shell reports a process the signal killed. The loop checks after
// every step, and the scene's validated limits bound the work of one step (haptic ticks per step,
// particle count), so a signal is always answered. Before the log exists (loading the scene,
// building millions of particles, constructing the backend) there is nothing to mark, and that
// work looks at no flag: there a signal ends the process at once (end_at_once_on_signal).
#include <stdexcept>
#include <string>

namespace mssph {

class RunInterrupted : public std::runtime_error {
 public:
  RunInterrupted(const std::string& reason, int signal) : std::runtime_error(reason), signal_(signal) {}
  int signal() const { return signal_; }
  // 128 + the signal number.
  int exit_code() const { return 128 + signal_; }

 private:
  int signal_;
};

// Installs the handlers for SIGINT, SIGTERM and SIGHUP, and ignores SIGPIPE (a closed stdout
// then shows as a failed write, which a finished run ignores, instead of killing the process) and
// SIGXFSZ (a file size limit then fails a write with EFBIG, reported like a full disk).
void install_interrupt_handlers();
// While one lives, SIGINT, SIGTERM and SIGHUP end the process at once, from the handler, with
// exit code 128 + the signal's number and "error: <signal> <note>" on stderr, e.g. note "before
// the run started; nothing was written". For work that has written nothing yet: a blocked open or
// read, or a long loop, ends within milliseconds. `note` is copied (at most 511 bytes are kept).
// Its end (the log is about to be written, or the set-up threw) goes back to what
// install_interrupt_handlers() set: a signal is noted for the step loop to act on.
class EndAtOnceOnSignal {
 public:
  explicit EndAtOnceOnSignal(const std::string& note);
  ~EndAtOnceOnSignal();
  EndAtOnceOnSignal(const EndAtOnceOnSignal&) = delete;
  EndAtOnceOnSignal& operator=(const EndAtOnceOnSignal&) = delete;
};
// The first interrupting signal received, 0 when none.
int interrupt_signal();
bool interrupt_requested();
// "SIGINT", "SIGTERM", "SIGHUP", or "signal N".
std::string signal_name(int signal);

}  // namespace mssph
