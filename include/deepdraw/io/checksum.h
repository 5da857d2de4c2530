// CRC-32 (IEEE 802.3, the polynomial of zlib and PNG) of blocks of bytes
// and of files: the checksum of a checkpoint and the digest of every input
// file a checkpoint records (doc/user_guide.md §6, doc/decisions.md D160).
#ifndef deepdraw_io_checksum_h
#define deepdraw_io_checksum_h

#include <cstddef>
#include <cstdint>
#include <string>

namespace deepdraw
{
  namespace io
  {
    // The CRC-32 of n bytes, continuing from crc (the CRC-32 of the bytes
    // before them; 0 for none): crc32(b, crc32(a)) is the CRC of a then b.
    std::uint32_t
    crc32(const void *data, std::size_t n, std::uint32_t crc = 0);

    // A file's size and CRC-32.
    struct FileDigest
    {
      std::uint64_t size = 0;
      std::uint32_t crc  = 0;

      bool
      operator==(const FileDigest &other) const
      {
        return size == other.size && crc == other.crc;
      }
    };

    // Reads the whole file; throws std::runtime_error naming it if it
    // cannot be read.
    FileDigest
    file_digest(const std::string &filename);
  } // namespace io
} // namespace deepdraw

#endif
