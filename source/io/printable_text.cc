#include <cctype>
#include <cstdio>
#include <deepdraw/io/printable_text.h>
#include <iomanip>
#include <sstream>

namespace deepdraw
{
  namespace io
  {
    namespace
    {
      // Length of the valid UTF-8 sequence starting at text[i] (1 for
      // ASCII), 0 if it is not valid (overlong forms and surrogates
      // included).
      std::size_t
      utf8_length(const std::string &text, const std::size_t i)
      {
        const auto byte = [&](const std::size_t k)
        { return static_cast<unsigned char>(text[k]); };
        const unsigned char c = byte(i);
        if (c < 0x80)
          return 1;
        std::size_t   n   = 0;
        unsigned long min = 0, code = 0;
        if ((c & 0xE0) == 0xC0)
          n = 2, min = 0x80, code = c & 0x1F;
        else if ((c & 0xF0) == 0xE0)
          n = 3, min = 0x800, code = c & 0x0F;
        else if ((c & 0xF8) == 0xF0)
          n = 4, min = 0x10000, code = c & 0x07;
        else
          return 0;
        if (i + n > text.size())
          return 0;
        for (std::size_t k = 1; k < n; ++k)
        {
          if ((byte(i + k) & 0xC0) != 0x80)
            return 0;
          code = (code << 6) | (byte(i + k) & 0x3F);
        }
        if (code < min || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF))
          return 0;
        return n;
      }

      bool
      is_control(const unsigned char c)
      {
        return c < 0x20 || c == 0x7F;
      }
    } // namespace


    std::string
    one_line(const std::string &text, const std::size_t max_length)
    {
      std::string result;
      bool        space = false;
      for (std::size_t i = 0; i < text.size();)
      {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'
            || c == '\v')
        {
          space = !result.empty();
          ++i;
          continue;
        }
        if (space)
          result += ' ';
        space                 = false;
        const std::size_t len = utf8_length(text, i);
        if (len == 0 || (len == 1 && is_control(c)))
        {
          char escaped[8];
          std::snprintf(escaped, sizeof(escaped), "\\x%02X", unsigned(c));
          result += escaped;
          ++i;
        }
        else
        {
          result.append(text, i, len);
          i += len;
        }
        if (result.size() > max_length)
        {
          // Cut at a character boundary.
          std::size_t cut = max_length;
          while (cut > 0
                 && (static_cast<unsigned char>(result[cut]) & 0xC0) == 0x80)
            --cut;
          result.resize(cut);
          result += "...";
          break;
        }
      }
      return result;
    }


    std::string
    to_string(const double value)
    {
      std::ostringstream text;
      text << std::setprecision(12) << value;
      return text.str();
    }


    std::string
    deal_ii_message(const dealii::ExceptionBase &exception)
    {
      std::ostringstream text;
      exception.print_info(text);
      return one_line(text.str());
    }


    std::size_t
    find_non_text_byte(const std::string &text)
    {
      for (std::size_t i = 0; i < text.size();)
      {
        const unsigned char c   = static_cast<unsigned char>(text[i]);
        const std::size_t   len = utf8_length(text, i);
        if (len == 0
            || (len == 1 && is_control(c) && c != '\t' && c != '\n' && c != '\r'
                && c != '\f'))
          return i;
        i += len;
      }
      return std::string::npos;
    }
  } // namespace io
} // namespace deepdraw
