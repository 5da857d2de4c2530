// An output stream that passes its bytes on to another stream's buffer and
// keeps the CRC-32 of every byte passed (a checkpoint written to its file
// without an image of it in memory, D221).
#ifndef deepdraw_io_checksummed_output_h
#define deepdraw_io_checksummed_output_h

#include <cstdint>
#include <ostream>
#include <streambuf>

namespace deepdraw
{
  namespace io
  {
    class ChecksummedOutput : public std::ostream
    {
    public:
      explicit ChecksummedOutput(std::ostream &target);

      // The CRC-32 of the bytes written so far (io::crc32).
      std::uint32_t
      crc() const;

    private:
      class Buffer : public std::streambuf
      {
      public:
        explicit Buffer(std::streambuf *target);
        std::uint32_t crc = 0;

      protected:
        std::streamsize
        xsputn(const char *bytes, std::streamsize n) override;
        int_type
        overflow(int_type byte) override;

      private:
        std::streambuf *target;
      };

      Buffer buffer;
    };
  } // namespace io
} // namespace deepdraw

#endif
