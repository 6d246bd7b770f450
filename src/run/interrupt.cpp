#include "interrupt.hpp"

#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstring>

namespace mssph {
namespace {

volatile std::sig_atomic_t g_signal = 0;
volatile std::sig_atomic_t g_end_at_once = 0;
char g_note[512] = "";

// The handler may call only async-signal-safe functions: write() and _exit(), no allocation.
void write_text(const char* text) {
  std::size_t left = std::strlen(text);
  while (left > 0) {
    const ssize_t n = ::write(STDERR_FILENO, text, left);
    if (n <= 0) return;
    text += n;
    left -= static_cast<std::size_t>(n);
  }
}

const char* fixed_signal_name(int signal) {
  switch (signal) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    case SIGHUP:
      return "SIGHUP";
    default:
      return "a signal";
  }
}

extern "C" void on_signal(int signal) {
  if (g_signal == 0) g_signal = signal;
  if (g_end_at_once) {
    write_text("error: ");
    write_text(fixed_signal_name(signal));
    write_text(" ");
    write_text(g_note);
    write_text("\n");
    ::_exit(128 + signal);
  }
}

}  // namespace

EndAtOnceOnSignal::EndAtOnceOnSignal(const std::string& note) {
  g_end_at_once = 0;  // the handler reads the note only while this is set
  const std::size_t n = std::min(note.size(), sizeof g_note - 1);
  std::memcpy(g_note, note.data(), n);
  g_note[n] = '\0';
  g_end_at_once = 1;
  // A signal noted before (during an earlier run of this process, or just now) ends it too.
  if (g_signal != 0) on_signal(g_signal);
}

EndAtOnceOnSignal::~EndAtOnceOnSignal() { g_end_at_once = 0; }

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // system calls under way (writes to the log) complete
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) sigaction(signal, &action, nullptr);
  std::signal(SIGPIPE, SIG_IGN);
  std::signal(SIGXFSZ, SIG_IGN);
}

int interrupt_signal() { return g_signal; }

bool interrupt_requested() { return g_signal != 0; }

std::string signal_name(int signal) {
  if (signal == SIGINT || signal == SIGTERM || signal == SIGHUP) return fixed_signal_name(signal);
  return "signal " + std::to_string(signal);
}

}  // namespace mssph
