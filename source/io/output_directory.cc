#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/output_directory.h>
#include <deepdraw/io/writing_rank.h>
#include <exception>
#include <filesystem>
#include <unistd.h>

namespace deepdraw
{
  namespace io
  {
    void
    open_output_directory(const std::string           &directory,
                          const std::string           &parameter,
                          const std::function<void()> &open,
                          const bool                   made_for_run)
    {
      const bool existed = !made_for_run && std::filesystem::exists(directory);
      try
      {
        if (writes_files())
          std::filesystem::create_directories(directory);
        open();
      }
      catch (const std::exception &error)
      {
        if (!existed && writes_files())
        {
          std::error_code ignored;
          std::filesystem::remove_all(directory, ignored);
        }
        if (dynamic_cast<const InputError *>(&error) != nullptr)
          throw;
        throw InputError(parameter + ": cannot write results to '" + directory
                         + "': " + error.what());
      }
    }


    void
    check_output_directory(const std::string &directory,
                           const std::string &parameter)
    {
      // The directory, or the nearest ancestor that exists: the run makes
      // the rest (create_directories), so that one must be a directory it
      // can make a directory in.
      namespace fs = std::filesystem;
      std::error_code ec;
      fs::path existing = fs::absolute(directory.empty() ? "." : directory);
      while (!fs::exists(existing, ec) && existing.has_parent_path()
             && existing != existing.parent_path())
        existing = existing.parent_path();
      std::string reason;
      if (!fs::is_directory(existing, ec))
        reason = "'" + existing.string() + "' is not a directory";
      else
      {
        // A probe made and removed at once: access() says yes to root on
        // a file system that refuses directories (/proc).
        std::string probe = (existing / ".deepdraw-check-XXXXXX").string();
        if (::mkdtemp(probe.data()) == nullptr)
          reason = "no directory can be made in '" + existing.string() + "' ("
                   + std::strerror(errno) + ")";
        else
          ::rmdir(probe.c_str());
      }
      if (!reason.empty())
        throw InputError(parameter + ": cannot write results to '" + directory
                         + "': " + reason);
    }


    bool
    is_plain_file_name(const std::string &name)
    {
      return !name.empty() && name != "." && name != ".."
             && name.find_first_of(std::string("/\\\0", 3))
                  == std::string::npos;
    }
  } // namespace io
} // namespace deepdraw
