// The frame of a Gmsh mesh file, checked before deal.II's GridIn reads it
// (D178): GridIn trusts the counts a file announces and sizes its arrays by
// them, so a file announcing 4e9 nodes ends in std::bad_alloc, and a binary
// file's bytes reach its messages. Checked here: the file is text (ASCII
// .msh: Gmsh's binary format, file-type 1 in $MeshFormat, is refused with
// how to write ASCII), and the count of every $Nodes and $Elements section
// (format 2: the line after the section name; format 4: its second number)
// is at most the number of lines left in the file; the file is at most
// max_gmsh_file_size bytes.
#ifndef deepdraw_blank_gmsh_file_check_h
#define deepdraw_blank_gmsh_file_check_h

#include <cstddef>
#include <string>

namespace deepdraw
{
  namespace blank
  {
    // Some 5 million nodes: far beyond what fits the memory estimate of
    // the sheet's mesh (memory_estimate.h).
    constexpr std::size_t max_gmsh_file_size = std::size_t(256) << 20;

    // The text of the mesh file `filename` (a regular file); throws
    // InputError "<name>:<line>: ..." if its frame is broken.
    std::string
    read_gmsh_text(const std::string &filename);
  } // namespace blank
} // namespace deepdraw

#endif
