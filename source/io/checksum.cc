#include <array>
#include <deepdraw/io/checksum.h>
#include <deepdraw/io/regular_file.h>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace deepdraw
{
  namespace io
  {
    namespace
    {
      // The table of the reflected polynomial 0xEDB88320, one entry per
      // byte value.
      std::array<std::uint32_t, 256>
      make_table()
      {
        std::array<std::uint32_t, 256> table{};
        for (std::uint32_t i = 0; i < 256; ++i)
        {
          std::uint32_t c = i;
          for (int k = 0; k < 8; ++k)
            c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
          table[i] = c;
        }
        return table;
      }
    } // namespace


    std::uint32_t
    crc32(const void *data, const std::size_t n, const std::uint32_t crc)
    {
      static const std::array<std::uint32_t, 256> table = make_table();
      const auto   *bytes = static_cast<const unsigned char *>(data);
      std::uint32_t c     = crc ^ 0xFFFFFFFFu;
      for (std::size_t i = 0; i < n; ++i)
        c = table[(c ^ bytes[i]) & 0xFFu] ^ (c >> 8);
      return c ^ 0xFFFFFFFFu;
    }


    FileDigest
    file_digest(const std::string &filename)
    {
      check_regular_file(filename, "input file");
      std::ifstream in(filename, std::ios::binary);
      if (!in)
        throw std::runtime_error("cannot read " + filename);
      FileDigest        digest;
      std::vector<char> buffer(1 << 16);
      while (in)
      {
        in.read(buffer.data(), buffer.size());
        const std::size_t n = static_cast<std::size_t>(in.gcount());
        digest.crc          = crc32(buffer.data(), n, digest.crc);
        digest.size += n;
      }
      if (in.bad())
        throw std::runtime_error("cannot read " + filename);
      return digest;
    }
  } // namespace io
} // namespace deepdraw
