#include <deepdraw/io/memory_input.h>

namespace deepdraw
{
  namespace io
  {
    MemoryInput::Buffer::Buffer(const char *data, const std::size_t size)
    {
      // The get area only reads; streambuf's interface wants char *.
      char *begin = const_cast<char *>(data);
      setg(begin, begin, begin + size);
    }


    MemoryInput::Buffer::pos_type
    MemoryInput::Buffer::seekoff(const off_type                off,
                                 const std::ios_base::seekdir  direction,
                                 const std::ios_base::openmode which)
    {
      const pos_type failed(off_type(-1));
      if (!(which & std::ios_base::in))
        return failed;
      const off_type from   = direction == std::ios_base::beg ? 0
                              : direction == std::ios_base::cur
                                ? gptr() - eback()
                                : egptr() - eback();
      const off_type target = from + off;
      if (target < 0 || target > egptr() - eback())
        return failed;
      setg(eback(), eback() + target, egptr());
      return pos_type(target);
    }


    MemoryInput::Buffer::pos_type
    MemoryInput::Buffer::seekpos(const pos_type                position,
                                 const std::ios_base::openmode which)
    {
      return seekoff(off_type(position), std::ios_base::beg, which);
    }


    MemoryInput::MemoryInput(const char *data, const std::size_t size)
        : std::istream(nullptr)
        , buffer(data, size)
    {
      rdbuf(&buffer);
    }
  } // namespace io
} // namespace deepdraw
