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
    install_stop_handlers()
    {
      // SIGHUP (the terminal closed) and SIGQUIT (Ctrl+backslash) end a run as
      // SIGTERM does, with a checkpoint (D163).
      for (const int signal_number : {SIGINT, SIGTERM, SIGHUP, SIGQUIT})
        std::signal(signal_number, record_signal);
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
