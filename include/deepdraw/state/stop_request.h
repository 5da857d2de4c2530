// A clean stop on SIGINT, SIGTERM, SIGHUP or SIGQUIT (doc/user_guide.md §6):
// the handler only records the signal; the increment loop looks at it between
// increments, writes a checkpoint and stops with exit code 3.
#ifndef deepdraw_state_stop_request_h
#define deepdraw_state_stop_request_h

#include <string>

namespace deepdraw
{
  namespace state
  {
    // Installs the handlers for SIGINT, SIGTERM, SIGHUP and SIGQUIT. With
    // interrupt_waits a signal ends a waitpid(2) with EINTR instead of
    // restarting it (a study passes the signal on to its run, D179).
    void
    install_stop_handlers(bool interrupt_waits = false);
    // The signal received, 0 if none.
    int
    requested_stop_signal();
    // "SIGINT", "SIGTERM", "SIGHUP", "SIGQUIT", or the number.
    std::string
    signal_name(int signal_number);
  } // namespace state
} // namespace deepdraw

#endif
