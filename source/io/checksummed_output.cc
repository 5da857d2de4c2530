#include <deepdraw/io/checksum.h>
#include <deepdraw/io/checksummed_output.h>

namespace deepdraw
{
  namespace io
  {
    ChecksummedOutput::Buffer::Buffer(std::streambuf *target)
        : target(target)
    {
    }


    std::streamsize
    ChecksummedOutput::Buffer::xsputn(const char           *bytes,
                                      const std::streamsize n)
    {
      const std::streamsize written = target->sputn(bytes, n);
      crc                           = crc32(bytes, written, crc);
      return written;
    }


    ChecksummedOutput::Buffer::int_type
    ChecksummedOutput::Buffer::overflow(const int_type byte)
    {
      if (traits_type::eq_int_type(byte, traits_type::eof()))
        return traits_type::not_eof(byte);
      const char value = traits_type::to_char_type(byte);
      return xsputn(&value, 1) == 1 ? byte : traits_type::eof();
    }


    ChecksummedOutput::ChecksummedOutput(std::ostream &target)
        : std::ostream(nullptr)
        , buffer(target.rdbuf())
    {
      rdbuf(&buffer);
    }


    std::uint32_t
    ChecksummedOutput::crc() const
    {
      return buffer.crc;
    }
  } // namespace io
} // namespace deepdraw
