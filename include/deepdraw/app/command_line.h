// The program deepdraw as a function: the command line, reading and checking
// the input, the run, and the exit code of every outcome (doc/user_guide.md
// §1 and §5): 0 done, 1 bad command line, 2 bad input (nothing written), 3
// the run stopped (what was written stays valid).
#ifndef deepdraw_app_command_line_h
#define deepdraw_app_command_line_h

#include <string>
#include <vector>

namespace deepdraw
{
  namespace app
  {
    // arguments without the program name. Messages go to std::cout and
    // std::cerr, each one printable line. The caller initialises MPI (the
    // MUMPS and KLU solvers need it) and disables deal.II's abort on
    // exceptions.
    int
    run_command_line(const std::vector<std::string> &arguments);
  } // namespace app
} // namespace deepdraw

#endif
