// Plain binary images in this machine's byte order (the SimulationState and
// checkpoint.bin, doc/decisions.md D55): values and blocks of bytes, with a
// read that says which stream ended early, and counts that are checked
// against the bytes the stream still holds, so that a damaged count is
// reported instead of allocating gigabytes (D160).
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

    // The bytes left in a seekable stream (a checkpoint is read from
    // memory); the largest size_t if the stream cannot tell.
    inline std::size_t
    remaining_bytes(std::istream &stream)
    {
      const std::istream::pos_type position = stream.tellg();
      if (position == std::istream::pos_type(-1))
        return std::size_t(-1);
      stream.seekg(0, std::ios::end);
      const std::istream::pos_type end = stream.tellg();
      stream.seekg(position);
      return end >= position ? static_cast<std::size_t>(end - position) : 0;
    }

    // Reads a count of elements of element_size bytes each that are to
    // follow; throws std::runtime_error("<what>: a count of N ...") if the
    // stream does not hold that many.
    inline std::size_t
    read_count(std::istream      &stream,
               const std::size_t  element_size,
               const std::string &source,
               const std::string &what)
    {
      std::size_t n = 0;
      read_value(stream, n, source);
      const std::size_t left = remaining_bytes(stream);
      if (element_size > 0 && n > left / element_size)
        throw std::runtime_error(what + ": a count of " + std::to_string(n)
                                 + ", more than the " + std::to_string(left)
                                 + " bytes left can hold");
      return n;
    }

    // A text as its size and its bytes.
    inline void
    write_string(std::ostream &stream, const std::string &text)
    {
      write_value(stream, text.size());
      stream.write(text.data(), text.size());
    }

    // Throws std::runtime_error if the stream ends early or the size is
    // beyond max_size or what the stream holds.
    inline std::string
    read_string(std::istream      &stream,
                const std::string &source,
                const std::size_t  max_size = std::size_t(1) << 32)
    {
      std::size_t n = 0;
      read_value(stream, n, source);
      if (n > max_size || n > remaining_bytes(stream))
        throw std::runtime_error("a text block of " + source + " is too long");
      std::string text(n, '\0');
      read_bytes(stream, text.data(), n, source);
      return text;
    }
  } // namespace io
} // namespace deepdraw

#endif
