// deepdraw: implicit simulation of sheet-metal deep drawing.
//   deepdraw FILE.prm [--output-directory DIR] [--resume] [--quiet]
//   deepdraw --check FILE.prm
//   deepdraw FILE.prm --study "Subsection/Parameter = v1, v2, ..." [...]
//   deepdraw --write-square-cup-tools DIR [FILE.prm]
//   deepdraw --help
//   deepdraw --print-parameters
// A run is app::run_command_line (command_line.h); a study is
// app::run_study (study.h), which runs this executable once per value; exit
// codes in doc/user_guide.md §1 and §5.
#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deepdraw/app/command_line.h>
#include <deepdraw/app/study.h>
#include <deepdraw/geometry/cad_tool_writer.h>
#include <deepdraw/geometry/square_cup_tools.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/parameter_file.h>
#include <deepdraw/io/printable_text.h>
#include <deepdraw/problem/forming_problem.h>
#include <filesystem>
#include <iostream>
#include <string>
#include <sys/types.h>
#include <system_error>
#include <unistd.h>
#include <vector>

namespace
{
  using namespace deepdraw;

  // --write-square-cup-tools DIR [FILE.prm]: the built-in tools as STEP and
  // IGES files (doc/tool_files.md, CAD tools), to check the CAD reader
  // against the exact builder or to start a CAD model from.
  int
  write_square_cup_tools(const std::vector<std::string> &arguments)
  {
    if (arguments.size() < 2 || arguments.size() > 3 || arguments[1].empty()
        || arguments[1][0] == '-')
    {
      std::cerr << "deepdraw: usage: deepdraw --write-square-cup-tools DIR "
                   "[FILE.prm]\n";
      return 1;
    }
    const std::string &directory = arguments[1];
    const std::string  prm_file  = arguments.size() == 3 ? arguments[2] : "";
    try
    {
      dealii::ParameterHandler prm;
      problem::FormingProblem::declare_parameters(prm);
      if (!prm_file.empty())
        io::read_parameter_file(prm, prm_file);
      geometry::SquareCupToolParameters tools;
      tools.parse_parameters(prm);
      prm.enter_subsection("Geometry");
      const double thickness = prm.get_double("Thickness");
      prm.leave_subsection();
      for (const std::string &file : geometry::write_cad_tool_files(
             geometry::build_square_cup_tools(tools, thickness),
             directory))
        std::cout << "deepdraw: wrote " << file << std::endl;
    }
    catch (const InputError &error)
    {
      std::cerr << "deepdraw: error in the input: "
                << io::one_line(error.what()) << std::endl;
      return 2;
    }
    catch (const dealii::ExceptionBase &error)
    {
      std::cerr << "deepdraw: error in " << prm_file << ": "
                << io::deal_ii_message(error) << std::endl;
      return 2;
    }
    catch (const std::exception &error)
    {
      std::cerr << "deepdraw: cannot write the tools to " << directory << ": "
                << io::one_line(error.what()) << std::endl;
      return 2;
    }
    return 0;
  }

  // FILE.prm [--output-directory DIR] --study "..." [--study "..."]
  int
  run_study(const std::vector<std::string> &arguments)
  {
    std::string              prm_file, output_directory;
    std::vector<std::string> study_options;
    for (std::size_t i = 0; i < arguments.size(); ++i)
    {
      const std::string &argument = arguments[i];
      if (argument == "--study" && i + 1 < arguments.size())
        study_options.push_back(arguments[++i]);
      else if (argument == "--output-directory" && i + 1 < arguments.size()
               && !arguments[i + 1].empty())
        output_directory = arguments[++i];
      else if (!argument.empty() && argument[0] != '-' && prm_file.empty())
        prm_file = argument;
      else
      {
        std::cerr << "deepdraw: --study: unknown or incomplete argument '"
                  << io::one_line(argument) << "'\n";
        return 1;
      }
    }
    if (prm_file.empty())
    {
      std::cerr << "deepdraw: --study needs a parameter file\n";
      return 1;
    }
    return app::run_study(prm_file, output_directory, study_options);
  }


  // deepdraw is one process: MPI serves MUMPS and Trilinos on one rank
  // only. Started without a launcher (mpirun sets OMPI_COMM_WORLD_SIZE),
  // Open MPI probes the network transports (UCX, OFI) for 0.2 s of every
  // run; the in-process ones chosen here start at once (D98). Nor does it
  // need the runtime daemon (0.1 s more): the daemon-less singleton runs
  // with a session directory under a base of this process's own, since
  // concurrent singletons under one base share a directory and fail (D98,
  // D99). A setting the user made wins; a study's parent deepdraw passes
  // its base on in the environment, which a child replaces by its own.
  class SingleProcessMpi
  {
  public:
    SingleProcessMpi()
    {
      if (std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr
          || std::getenv("PMIX_RANK") != nullptr)
        return;
      setenv("OMPI_MCA_pml", "ob1", 0);
      setenv("OMPI_MCA_btl", "self", 0);
      // Both Open MPI settings are a parent deepdraw's when its marker
      // names the base; otherwise either one is the user's.
      const char *base   = std::getenv("OMPI_MCA_orte_tmpdir_base");
      const char *parent = std::getenv("DEEPDRAW_MPI_SESSION_BASE");
      const bool  inherited
        = base != nullptr && parent != nullptr && std::string(base) == parent;
      if (!inherited
          && (base != nullptr
              || std::getenv("OMPI_MCA_ess_singleton_isolated") != nullptr))
        return;
      const char       *temporary = std::getenv("TMPDIR");
      const std::string directory
        = temporary != nullptr && *temporary ? temporary : "/tmp";
      remove_bases_of_ended_processes(directory);
      std::string pattern
        = directory + "/" + base_prefix + std::to_string(getpid()) + "-XXXXXX";
      if (mkdtemp(pattern.data()) == nullptr)
        return; // the daemon as before
      session_base = pattern;
      setenv("OMPI_MCA_orte_tmpdir_base", session_base.c_str(), 1);
      setenv("DEEPDRAW_MPI_SESSION_BASE", session_base.c_str(), 1);
      setenv("OMPI_MCA_ess_singleton_isolated", "1", 1);
    }

    // After MPI_Finalize (declared before MPI_InitFinalize in main), which
    // removes Open MPI's own session directories.
    ~SingleProcessMpi()
    {
      if (session_base.empty())
        return;
      std::error_code ignored;
      std::filesystem::remove_all(session_base, ignored);
    }

  private:
    static constexpr const char *base_prefix = "deepdraw-mpi-";

    // A run killed with SIGKILL cannot remove its base: the next start
    // removes those whose process (the number in the name) has ended.
    static void
    remove_bases_of_ended_processes(const std::string &directory)
    {
      std::error_code error;
      for (const auto &entry :
           std::filesystem::directory_iterator(directory, error))
      {
        const std::string name = entry.path().filename().string();
        if (name.rfind(base_prefix, 0) != 0)
          continue;
        const pid_t pid = std::atoi(name.c_str() + std::strlen(base_prefix));
        if (pid > 0 && kill(pid, 0) != 0 && errno == ESRCH)
          std::filesystem::remove_all(entry.path(), error);
      }
    }

    std::string session_base;
  };
} // namespace


int
main(int argc, char *argv[])
{
  const SingleProcessMpi single_process_mpi;
  // As many threads as cores (or DEAL_II_NUM_THREADS): the element
  // assembly runs in a WorkStream loop whose copier adds the cells in a
  // fixed order, so the results do not depend on the thread count (D61).
  dealii::Utilities::MPI::MPI_InitFinalize
    mpi(argc, argv, dealii::numbers::invalid_unsigned_int);
  dealii::deal_II_exceptions::disable_abort_on_exception();
  // With a file size limit (ulimit -f) a write beyond it raises SIGXFSZ,
  // which kills the process; ignored, the write fails with EFBIG and is
  // reported like a full disk (exit code 3, D51).
  std::signal(SIGXFSZ, SIG_IGN);
  const std::vector<std::string> arguments(argv + 1, argv + argc);
  if (!arguments.empty() && arguments[0] == "--write-square-cup-tools")
    return write_square_cup_tools(arguments);
  if (std::find(arguments.begin(), arguments.end(), "--study")
      != arguments.end())
    return run_study(arguments);
  return deepdraw::app::run_command_line(arguments);
}
