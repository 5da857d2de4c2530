// libFuzzer target: the checkpoint reader (state::parse_checkpoint, what
// --resume and --check --resume read before anything is touched,
// doc/decisions.md D160) on arbitrary bytes. Each input is read twice: as
// it is (almost always refused by the checksum of format 4), and, when it
// begins with the tag of format 4, with its last 4 bytes replaced by the
// CRC-32 of the rest, so that the fields behind the checksum are fuzzed
// too. An input must either be refused with deepdraw::InputError or give a
// checkpoint whose every table name is a plain *.csv name and whose state
// is finite where the reader promises it; any other exception
// (std::bad_alloc of a count, std::length_error, ...), a sanitizer report
// or a broken promise is a bug (abort). Built and run by scripts/fuzz.sh,
// not by ctest.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <deepdraw/io/checksum.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/output_directory.h>
#include <deepdraw/state/checkpoint.h>
#include <iostream>
#include <string>

namespace
{
  constexpr char format_4[] = "deepdraw-checkpoint-4";

  [[noreturn]] void
  fail(const std::string &what)
  {
    std::cerr << "fuzz: accepted checkpoint with " << what << "\n";
    std::abort();
  }

  void
  read(const std::string &bytes)
  {
    deepdraw::state::Checkpoint checkpoint;
    try
    {
      checkpoint = deepdraw::state::parse_checkpoint(bytes, "fuzz.bin");
    }
    catch (const deepdraw::InputError &)
    {
      return;
    }
    for (const auto &[name, size] : checkpoint.table_sizes)
      if (!deepdraw::io::is_plain_file_name(name)
          || name.find(".csv") == std::string::npos)
        fail("the table name '" + name + "'");
    const auto &state = checkpoint.state;
    if (!std::isfinite(state.load) || !(state.next_increment > 0.)
        || !std::isfinite(state.next_increment))
      fail("a load or next increment out of range");
    for (const auto &vertex : state.vertices)
      for (unsigned int d = 0; d < 3; ++d)
        if (!std::isfinite(vertex[d]))
          fail("a vertex that is not finite");
    for (const unsigned int vertex : state.release_support_vertices)
      if (vertex >= state.vertices.size())
        fail("a support vertex beyond the vertices");
  }
} // namespace

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  const std::string bytes(reinterpret_cast<const char *>(data), size);
  read(bytes);
  if (size >= sizeof(format_4) + 4
      && std::memcmp(data, format_4, sizeof(format_4)) == 0)
  {
    std::string         sealed = bytes.substr(0, size - 4);
    const std::uint32_t crc = deepdraw::io::crc32(sealed.data(), sealed.size());
    sealed.append(reinterpret_cast<const char *>(&crc), sizeof(crc));
    read(sealed);
  }
  return 0;
}
