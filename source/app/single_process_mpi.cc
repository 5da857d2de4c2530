#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <deepdraw/app/single_process_mpi.h>
#include <filesystem>
#include <string>
#include <sys/types.h>
#include <system_error>
#include <unistd.h>
#include <vector>

namespace deepdraw
{
  namespace app
  {
    namespace
    {
      constexpr const char *base_prefix = "deepdraw-mpi-";

      // Open MPI's variables (OMPI_, PMIX_, ORTE_, OPAL_) as they were
      // before this process set or MPI_Init added any.
      std::vector<std::string> mpi_environment_at_start;

      bool
      is_mpi_variable(const std::string &entry)
      {
        for (const char *prefix : {"OMPI_", "PMIX_", "ORTE_", "OPAL_"})
          if (entry.rfind(prefix, 0) == 0)
            return true;
        return false;
      }

      // A run killed with SIGKILL cannot remove its base: the next start
      // removes those whose process (the number in the name) has ended.
      void
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
    } // namespace


    SingleProcessMpi::SingleProcessMpi()
    {
      for (char **entry = environ; *entry != nullptr; ++entry)
        if (is_mpi_variable(*entry))
          mpi_environment_at_start.emplace_back(*entry);
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


    void
    restore_mpi_environment()
    {
      std::vector<std::string> added;
      for (char **entry = environ; *entry != nullptr; ++entry)
        if (is_mpi_variable(*entry)
            && std::find(mpi_environment_at_start.begin(),
                         mpi_environment_at_start.end(),
                         *entry)
                 == mpi_environment_at_start.end())
          added.emplace_back(*entry);
      for (const std::string &entry : added)
        unsetenv(entry.substr(0, entry.find('=')).c_str());
      for (const std::string &entry : mpi_environment_at_start)
      {
        const std::size_t equals = entry.find('=');
        setenv(entry.substr(0, equals).c_str(),
               entry.substr(equals + 1).c_str(),
               1);
      }
      unsetenv("DEEPDRAW_MPI_SESSION_BASE");
    }


    std::string
    working_directory_problem()
    {
      std::vector<char> buffer(4096);
      while (::getcwd(buffer.data(), buffer.size()) == nullptr)
      {
        if (errno != ERANGE)
          return std::string("the working directory cannot be read (")
                 + std::strerror(errno)
                 + (errno == ENOENT ? "; was it deleted?" : "")
                 + "); start deepdraw in an existing directory";
        buffer.resize(2 * buffer.size());
      }
      return "";
    }


    SingleProcessMpi::~SingleProcessMpi()
    {
      // After MPI_Finalize, which removes Open MPI's own session
      // directories.
      if (session_base.empty())
        return;
      std::error_code ignored;
      std::filesystem::remove_all(session_base, ignored);
    }
  } // namespace app
} // namespace deepdraw
