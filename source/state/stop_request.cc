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
      std::signal(SIGINT, record_signal);
      std::signal(SIGTERM, record_signal);
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
      return "signal " + std::to_string(signal_number);
    }
  } // namespace state
} // namespace deepdraw
