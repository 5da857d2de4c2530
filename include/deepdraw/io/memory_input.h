// An input stream over bytes that it does not own (a checkpoint parsed
// where it was read, D221): no copy of them, and seekable, so that counts
// can be checked against the bytes left (io::remaining_bytes).
#ifndef deepdraw_io_memory_input_h
#define deepdraw_io_memory_input_h

#include <cstddef>
#include <istream>
#include <streambuf>

namespace deepdraw
{
  namespace io
  {
    class MemoryInput : public std::istream
    {
    public:
      // The bytes [data, data + size) must outlive the stream.
      MemoryInput(const char *data, std::size_t size);

    private:
      class Buffer : public std::streambuf
      {
      public:
        Buffer(const char *data, std::size_t size);

      protected:
        pos_type
        seekoff(off_type                off,
                std::ios_base::seekdir  direction,
                std::ios_base::openmode which) override;
        pos_type
        seekpos(pos_type position, std::ios_base::openmode which) override;
      };

      Buffer buffer;
    };
  } // namespace io
} // namespace deepdraw

#endif
