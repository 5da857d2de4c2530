#include <cerrno>
#include <cstring>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/printable_text.h>
#include <deepdraw/io/regular_file.h>
#include <dirent.h>
#include <memory>
#include <sys/stat.h>

namespace deepdraw
{
  namespace io
  {
    namespace
    {
      // What a file that is not a regular file is, in a user's words.
      std::string
      file_type(const mode_t mode)
      {
        if (S_ISDIR(mode))
          return "a directory";
        if (S_ISFIFO(mode))
          return "a named pipe";
        if (S_ISSOCK(mode))
          return "a socket";
        if (S_ISCHR(mode))
          return "a character device";
        if (S_ISBLK(mode))
          return "a block device";
        return "a special file";
      }

      bool
      is_written_by_a_run(const std::string &name)
      {
        const auto ends_with = [&](const std::string &suffix)
        {
          return name.size() >= suffix.size()
                 && name.compare(name.size() - suffix.size(),
                                 suffix.size(),
                                 suffix)
                      == 0;
        };
        return ends_with(".csv") || ends_with(".vtu") || ends_with(".pvd")
               || ends_with(".tmp") || ends_with(".bin") || ends_with(".gp")
               || ends_with(".png");
      }
    } // namespace


    void
    check_regular_file(const std::string &path, const std::string &kind)
    {
      const std::string name = one_line(path, 500);
      struct stat       status;
      if (::stat(path.c_str(), &status) != 0)
        throw InputError(name + ": cannot open the " + kind + " ("
                         + std::strerror(errno) + ")");
      if (S_ISDIR(status.st_mode))
        throw InputError(name + ": is a directory, not a " + kind);
      if (!S_ISREG(status.st_mode))
        throw InputError(name + ": is " + file_type(status.st_mode)
                         + ", not a regular file (the " + kind + ")");
    }


    void
    check_output_path(const std::string &path)
    {
      // A directory in the way does not block: the write fails with its
      // own message (exit 3 for a checkpoint, tests/restart).
      struct stat status;
      if (::stat(path.c_str(), &status) != 0 || S_ISREG(status.st_mode)
          || S_ISDIR(status.st_mode))
        return;
      throw InputError(one_line(path, 500) + ": is " + file_type(status.st_mode)
                       + ", not a regular file; deepdraw would write its "
                         "results there");
    }


    void
    check_output_entries(const std::string &directory)
    {
      const std::unique_ptr<DIR, int (*)(DIR *)> listing(::opendir(
                                                           directory.c_str()),
                                                         &::closedir);
      if (!listing)
        return;
      while (const dirent *entry = ::readdir(listing.get()))
        if (is_written_by_a_run(entry->d_name))
          check_output_path(directory + "/" + entry->d_name);
    }
  } // namespace io
} // namespace deepdraw
