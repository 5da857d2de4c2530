#include <csignal>
#include <deepdraw/state/stop_request.h>

namespace deepdraw
{
  namespace state
  {
    namespace
    {
      volatile std::sig_atomic_t received_signal = 0;

      extern "C" void
      record_signal(const int signal_number)
      {
        received_signal = signal_number;
      }
    } // namespace


    void
    install_stop_handlers(const bool interrupt_waits)
    {
      // SIGHUP (the terminal closed) and SIGQUIT (Ctrl+backslash) end a run as
      // SIGTERM does, with a checkpoint (D163). SA_RESTART as std::signal
      // sets it, unless waits are to be interrupted.
      struct sigaction action = {};
      action.sa_handler       = record_signal;
      action.sa_flags         = interrupt_waits ? 0 : SA_RESTART;
      sigemptyset(&action.sa_mask);
      for (const int signal_number : {SIGINT, SIGTERM, SIGHUP, SIGQUIT})
        sigaction(signal_number, &action, nullptr);
    }


    int
    requested_stop_signal()
    {
      return received_signal;
    }


    std::string
    signal_name(const int signal_number)
    {
      if (signal_number == SIGINT)
        return "SIGINT";
      if (signal_number == SIGTERM)
        return "SIGTERM";
      if (signal_number == SIGHUP)
        return "SIGHUP";
      if (signal_number == SIGQUIT)
        return "SIGQUIT";
      return "signal " + std::to_string(signal_number);
    }
  } // namespace state
} // namespace deepdraw
