#include <cerrno>
#include <csignal>
#include <cstring>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/output_lock.h>
#include <deepdraw/io/printable_text.h>
#include <fcntl.h>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace deepdraw
{
  namespace io
  {
    namespace
    {
      std::string
      host_name()
      {
        char name[256] = {};
        if (::gethostname(name, sizeof(name) - 1) != 0)
          return "unknown host";
        return name;
      }

      // "PID HOST" of a lock file (empty if it has none).
      std::string
      read_owner(const int descriptor)
      {
        char          text[512] = {};
        const ssize_t n = ::pread(descriptor, text, sizeof(text) - 1, 0);
        std::string   owner(text, n > 0 ? std::size_t(n) : 0);
        const auto    end = owner.find('\n');
        return one_line(owner.substr(0, end), 300);
      }

      // Whether the process of "PID HOST" lives, as far as this host can
      // tell (kill(pid, 0); a process of another host counts as living).
      bool
      owner_lives(const std::string &owner)
      {
        std::istringstream fields(owner);
        long               pid = 0;
        std::string        host;
        if (!(fields >> pid) || pid <= 0)
          return false;
        fields >> host;
        if (!host.empty() && host != host_name())
          return true;
        return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM;
      }

      [[noreturn]] void
      throw_system_error(const std::string &what)
      {
        throw std::runtime_error(what + ": " + std::strerror(errno));
      }
    } // namespace


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
      // A lock file removed by its owner between our open and our flock is
      // not the lock any more: open again (at most a few times).
      for (unsigned int attempt = 0; attempt < 100; ++attempt)
      {
        const int fd = ::open(lock_file.c_str(),
                              O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW,
                              0644);
        if (fd < 0)
          throw_system_error("cannot make the lock file " + lock_file);
        struct stat opened, named;
        if (::fstat(fd, &opened) != 0 || !S_ISREG(opened.st_mode))
        {
          ::close(fd);
          throw std::runtime_error(lock_file + " is not a regular file");
        }
        if (::flock(fd, LOCK_EX | LOCK_NB) != 0)
        {
          const std::string owner = read_owner(fd);
          ::close(fd);
          throw InputError(
            parameter + ": '" + one_line(directory)
            + "' is in use by deepdraw process "
            + (owner.empty() ? std::string("(unknown)") : owner)
            + " (lock file " + one_line(lock_file)
            + "); one output directory takes one run at a time: wait for "
              "it to end, or use another output directory");
        }
        if (::stat(lock_file.c_str(), &named) != 0
            || named.st_ino != opened.st_ino || named.st_dev != opened.st_dev)
        {
          ::close(fd);
          continue;
        }
        const std::string owner = read_owner(fd);
        if (!owner.empty() && !quiet)
          std::cout << "deepdraw: taking over the stale lock " << lock_file
                    << " of process " << owner
                    << (owner_lives(owner) ? " (its lock has ended)"
                                           : ", which has ended")
                    << std::endl;
        const std::string me
          = std::to_string(::getpid()) + " " + host_name() + "\n";
        if (::ftruncate(fd, 0) != 0
            || ::pwrite(fd, me.data(), me.size(), 0) != ssize_t(me.size()))
        {
          const int saved = errno;
          ::unlink(lock_file.c_str());
          ::close(fd);
          errno = saved;
          throw_system_error("cannot write the lock file " + lock_file);
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
