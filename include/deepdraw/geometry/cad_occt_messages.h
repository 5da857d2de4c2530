// While an object of this class lives, OpenCASCADE's default messenger
// prints nothing: its STEP and IGES readers and writers report statistics
// and warnings on standard output, which would bury deepdraw's own
// messages. Instead, the failure messages are kept (first_failure()), so
// that deepdraw can say why a file could not be read in its own InputError
// naming the file and face (doc/tool_files.md, CAD tools). Not
// thread-safe: reading and writing tools happens before the run, on one
// thread.
#ifndef deepdraw_geometry_cad_occt_messages_h
#define deepdraw_geometry_cad_occt_messages_h

// deal.II first: OpenCASCADE's macro Handle() breaks Trilinos' Sacado::Handle,
// which deal.II's headers declare.
#include <deal.II/base/config.h>
// OpenCASCADE:
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <TCollection_AsciiString.hxx>
#include <string>

namespace deepdraw::geometry
{
  class MutedOcctMessages
  {
  public:
    MutedOcctMessages()
        : printers(Message::DefaultMessenger()->Printers())
        , collector(new Collector())
    {
      Message::DefaultMessenger()->ChangePrinters().Clear();
      Message::DefaultMessenger()->AddPrinter(collector);
    }

    ~MutedOcctMessages()
    {
      Message::DefaultMessenger()->ChangePrinters() = printers;
    }

    MutedOcctMessages(const MutedOcctMessages &) = delete;
    MutedOcctMessages &
    operator=(const MutedOcctMessages &)
      = delete;

    // The first message of gravity Fail or worse since construction, with
    // OpenCASCADE's decoration ("**** ERR StepFile : ...") as it is; empty
    // if there was none.
    std::string
    first_failure() const
    {
      return collector->first_failure;
    }

  private:
    class Collector : public Message_Printer
    {
    public:
      mutable std::string first_failure;

    protected:
      void
      send(const TCollection_AsciiString &text,
           const Message_Gravity          gravity) const override
      {
        if (gravity >= Message_Fail && first_failure.empty())
          first_failure = text.ToCString();
      }
    };

    Message_SequenceOfPrinters printers;
    Handle(Collector) collector;
  };
} // namespace deepdraw::geometry

#endif
