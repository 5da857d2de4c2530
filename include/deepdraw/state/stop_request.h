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
    // Installs the handlers for SIGINT, SIGTERM, SIGHUP and SIGQUIT.
    void
    install_stop_handlers();
    // The signal received, 0 if none.
    int
    requested_stop_signal();
    // "SIGINT", "SIGTERM", "SIGHUP", "SIGQUIT", or the number.
    std::string
    signal_name(int signal_number);
  } // namespace state
} // namespace deepdraw

#endif
