#include <cerrno>
#include <cstdio>
#include <cstring>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/output_lock.h>
#include <deepdraw/io/printable_text.h>
#include <fcntl.h>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

namespace deepdraw
{
  namespace io
  {
    namespace
    {
      [[noreturn]] void
      throw_system_error(const std::string &what)
      {
        throw std::runtime_error(what + ": " + std::strerror(errno));
      }

      // The process holding the flock of the open file fd, from the
      // kernel's table of locks (/proc/locks: "1: FLOCK ADVISORY WRITE
      // PID MAJ:MIN:INODE 0 EOF", device numbers in hex); 0 if it is not
      // there (a holder on another host of a network file system).
      long
      holder_of(const int fd)
      {
        struct stat file;
        if (::fstat(fd, &file) != 0)
          return 0;
        std::ifstream locks("/proc/locks");
        std::string   line;
        while (std::getline(locks, line))
        {
          std::istringstream fields(line);
          std::string        number, kind, mode, access, device;
          long               pid = 0;
          if (!(fields >> number >> kind >> mode >> access >> pid >> device)
              || kind != "FLOCK")
            continue;
          unsigned int       major_number = 0, minor_number = 0;
          unsigned long long inode = 0;
          if (std::sscanf(device.c_str(),
                          "%x:%x:%llu",
                          &major_number,
                          &minor_number,
                          &inode)
                == 3
              && major_number == major(file.st_dev)
              && minor_number == minor(file.st_dev) && inode == file.st_ino)
            return pid;
        }
        return 0;
      }

      // What a lock file holds (nothing, since D162's lock files are
      // empty; an owner line if someone wrote one).
      std::string
      content_of(const int fd)
      {
        char          text[512] = {};
        const ssize_t n         = ::pread(fd, text, sizeof(text) - 1, 0);
        std::string   content(text, n > 0 ? std::size_t(n) : 0);
        return one_line(content.substr(0, content.find('\n')), 300);
      }

      // The lock file opened, made if missing (made = true then); it must
      // be a regular file.
      int
      open_lock_file(const std::string &lock_file, bool &made)
      {
        const int flags = O_RDWR | O_CLOEXEC | O_NOFOLLOW;
        int fd = ::open(lock_file.c_str(), flags | O_CREAT | O_EXCL, 0644);
        made   = fd >= 0;
        if (fd < 0 && errno == EEXIST)
          fd = ::open(lock_file.c_str(), flags);
        if (fd < 0)
          throw_system_error("cannot make the lock file " + lock_file);
        struct stat opened;
        if (::fstat(fd, &opened) != 0 || !S_ISREG(opened.st_mode))
        {
          ::close(fd);
          throw std::runtime_error(lock_file + " is not a regular file");
        }
        return fd;
      }

      // Whether the open file fd is still the one named lock_file (its
      // owner may have removed it between our open and our flock).
      bool
      is_at(const int fd, const std::string &lock_file)
      {
        struct stat opened, named;
        return ::fstat(fd, &opened) == 0
               && ::stat(lock_file.c_str(), &named) == 0
               && named.st_ino == opened.st_ino
               && named.st_dev == opened.st_dev;
      }

      [[noreturn]] void
      throw_in_use(const std::string &directory,
                   const std::string &parameter,
                   const long         pid)
      {
        throw InputError(
          parameter + ": '" + one_line(directory) + "' is in use by "
          + (pid > 0 ? "deepdraw process " + std::to_string(pid)
                     : std::string("a deepdraw process of another host"))
          + " (lock file " + one_line(OutputLock::file_name(directory))
          + "); one output directory takes one run at a time: wait for "
            "it to end, or use another output directory");
      }
    } // namespace


    void
    OutputLock::check_free(const std::string &directory,
                           const std::string &parameter)
    {
      // Read only, no flock of its own: --check writes nothing and must
      // not make a starting run see the directory in use.
      const std::string lock_file = file_name(directory);
      const int         fd        = ::open(lock_file.c_str(),
                            O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
      if (fd < 0)
        return;
      const long pid = holder_of(fd);
      ::close(fd);
      if (pid > 0 && pid != ::getpid())
        throw_in_use(directory, parameter, pid);
    }


    OutputLock::~OutputLock()
    {
      release();
    }


    std::string
    OutputLock::file_name(const std::string &directory)
    {
      return directory + "/.deepdraw.lock";
    }


    void
    OutputLock::acquire(const std::string &directory,
                        const std::string &parameter,
                        const bool         quiet)
    {
      release();
      const std::string lock_file = file_name(directory);
      for (unsigned int attempt = 0; attempt < 100; ++attempt)
      {
        bool      made    = false;
        const int fd      = open_lock_file(lock_file, made);
        const int failure = ::flock(fd, LOCK_EX | LOCK_NB) == 0 ? 0 : errno;
        if (failure == EWOULDBLOCK)
        {
          const long pid = holder_of(fd);
          ::close(fd);
          throw_in_use(directory, parameter, pid);
        }
        if (failure != 0 && !quiet)
          // A file system without locks: the run goes on unprotected.
          std::cout << "deepdraw: cannot lock " << lock_file << " ("
                    << std::strerror(failure)
                    << "); a second run in this output directory would not "
                       "be stopped"
                    << std::endl;
        if (!is_at(fd, lock_file))
        {
          ::close(fd);
          continue;
        }
        if (!made && !quiet)
        {
          const std::string content = content_of(fd);
          std::cout << "deepdraw: taking over the stale lock " << lock_file
                    << (content.empty() ? std::string()
                                        : " of process " + content)
                    << ": the run that took it has ended" << std::endl;
        }
        // Empty: a lock costs no block of a nearly full disk (D162).
        if (::ftruncate(fd, 0) != 0)
        {
          ::close(fd);
          throw_system_error("cannot empty the lock file " + lock_file);
        }
        path       = lock_file;
        descriptor = fd;
        return;
      }
      throw std::runtime_error("cannot take the lock " + lock_file);
    }


    void
    OutputLock::release()
    {
      if (descriptor < 0)
        return;
      // Removed while still held: a run waiting for it opens a new file.
      ::unlink(path.c_str());
      ::close(descriptor);
      descriptor = -1;
      path.clear();
    }
  } // namespace io
} // namespace deepdraw
