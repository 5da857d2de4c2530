// Plain binary images in this machine's byte order (the SimulationState and
// checkpoint.bin, doc/decisions.md D55): values and blocks of bytes, with a
// read that says which stream ended early.
#ifndef deepdraw_io_binary_stream_h
#define deepdraw_io_binary_stream_h

#include <cstddef>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>

namespace deepdraw
{
  namespace io
  {
    // Reads n bytes; throws std::runtime_error("<source> ends early") if
    // the stream has fewer.
    inline void
    read_bytes(std::istream      &stream,
               void              *data,
               const std::size_t  n,
               const std::string &source)
    {
      stream.read(static_cast<char *>(data), n);
      if (!stream)
        throw std::runtime_error(source + " ends early");
    }

    template <typename T>
    void
    write_value(std::ostream &stream, const T &value)
    {
      stream.write(reinterpret_cast<const char *>(&value), sizeof(T));
    }

    template <typename T>
    void
    read_value(std::istream &stream, T &value, const std::string &source)
    {
      read_bytes(stream, &value, sizeof(T), source);
    }

    // A text as its size and its bytes.
    inline void
    write_string(std::ostream &stream, const std::string &text)
    {
      write_value(stream, text.size());
      stream.write(text.data(), text.size());
    }

    // Throws std::runtime_error if the stream ends early or the size is
    // beyond max_size.
    inline std::string
    read_string(std::istream      &stream,
                const std::string &source,
                const std::size_t  max_size = std::size_t(1) << 32)
    {
      std::size_t n = 0;
      read_value(stream, n, source);
      if (n > max_size)
        throw std::runtime_error("a text block of " + source + " is too long");
      std::string text(n, '\0');
      read_bytes(stream, text.data(), n, source);
      return text;
    }
  } // namespace io
} // namespace deepdraw

#endif
