#include <cerrno>
#include <cstdio>
#include <cstring>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/printable_text.h>
#include <deepdraw/io/regular_file.h>
#include <deepdraw/io/text_file.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace deepdraw
{
  namespace io
  {
    std::string
    read_text_file(const std::string &filename, const std::string &kind)
    {
      const std::string name = one_line(filename, 500);
      check_regular_file(filename, kind);
      struct stat status;
      if (::stat(filename.c_str(), &status) != 0)
        throw InputError(name + ": cannot open the " + kind + " ("
                         + std::strerror(errno) + ")");
      if (static_cast<unsigned long long>(status.st_size) > max_text_file_size)
        throw InputError(name + ": " + std::to_string(status.st_size)
                         + " bytes, more than the "
                         + std::to_string(max_text_file_size >> 20) + " MB a "
                         + kind + " may have");

      const int descriptor = ::open(filename.c_str(), O_RDONLY | O_NONBLOCK);
      if (descriptor < 0)
        throw InputError(name + ": cannot open the " + kind + " ("
                         + std::strerror(errno) + ")");
      std::string text;
      char        buffer[65536];
      while (true)
      {
        const ssize_t n = ::read(descriptor, buffer, sizeof(buffer));
        if (n < 0 && errno == EINTR)
          continue;
        if (n < 0)
        {
          const int error_number = errno;
          ::close(descriptor);
          throw InputError(name + ": cannot read the " + kind + " ("
                           + std::strerror(error_number) + ")");
        }
        if (n == 0)
          break;
        text.append(buffer, static_cast<std::size_t>(n));
        // The file may grow while it is read (a file in /proc).
        if (text.size() > max_text_file_size)
        {
          ::close(descriptor);
          throw InputError(name + ": more than the "
                           + std::to_string(max_text_file_size >> 20) + " MB a "
                           + kind + " may have");
        }
      }
      ::close(descriptor);
      // Editors on Windows start UTF-8 files with a byte-order mark, which
      // would end up in the first value read (D175).
      if (text.compare(0, 3, "\xEF\xBB\xBF") == 0)
        text.erase(0, 3);

      const std::size_t bad = find_non_text_byte(text);
      if (bad != std::string::npos)
      {
        std::size_t line = 1, column = 1;
        for (std::size_t i = 0; i < bad; ++i)
          if (text[i] == '\n')
            ++line, column = 1;
          else
            ++column;
        char byte[8];
        std::snprintf(byte,
                      sizeof(byte),
                      "0x%02X",
                      unsigned(static_cast<unsigned char>(text[bad])));
        throw InputError(name + ":" + std::to_string(line)
                         + ": not a text file (byte " + byte + " at column "
                         + std::to_string(column) + "); a " + kind
                         + " must be UTF-8 text");
      }
      return text;
    }
  } // namespace io
} // namespace deepdraw
