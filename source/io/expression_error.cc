#include <deal.II/base/exceptions.h>
#include <deepdraw/io/expression_error.h>
#include <deepdraw/io/printable_text.h>
#include <iostream>
#include <sstream>

namespace deepdraw
{
  namespace io
  {
    namespace
    {
      // Restores std::cerr also when the action throws something we let
      // pass.
      class CerrCapture
      {
      public:
        CerrCapture()
            : saved(std::cerr.rdbuf(captured.rdbuf()))
        {
        }
        ~CerrCapture()
        {
          std::cerr.rdbuf(saved);
        }
        std::string
        text() const
        {
          return captured.str();
        }

      private:
        std::ostringstream captured;
        std::streambuf    *saved;
      };

      // The text between '<' and '>' on muparser's "Message:" line.
      std::string
      muparser_message(const std::string &diagnostics)
      {
        const auto line = diagnostics.find("Message:");
        if (line == std::string::npos)
          return "";
        const auto open  = diagnostics.find('<', line);
        const auto close = diagnostics.find(">\n", open);
        if (open == std::string::npos || close == std::string::npos)
          return "";
        return diagnostics.substr(open + 1, close - open - 1);
      }
    } // namespace


    std::string
    expression_error(const std::function<void()> &action)
    {
      std::string reason;
      std::string diagnostics;
      {
        CerrCapture capture;
        try
        {
          action();
        }
        catch (const dealii::ExceptionBase &error)
        {
          reason = deal_ii_message(error);
        }
        catch (const std::exception &error)
        {
          reason = one_line(error.what());
        }
        catch (...)
        {
          reason = "cannot be evaluated";
        }
        diagnostics = capture.text();
      }
      if (reason.empty())
        return "";
      const std::string message = muparser_message(diagnostics);
      return message.empty() ? reason : one_line(message, 300);
    }
  } // namespace io
} // namespace deepdraw
