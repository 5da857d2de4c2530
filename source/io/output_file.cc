// Checked writes: doc/user_guide.md §5.1 (a failed write stops the run with
// exit code 3), doc/decisions.md D51.
#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <deepdraw/io/output_error.h>
#include <deepdraw/io/output_file.h>
#include <deepdraw/io/writing_rank.h>
#include <fcntl.h>
#include <sstream>
#include <unistd.h>

namespace deepdraw
{
  namespace io
  {
    // A write that makes no progress without an error (not seen on regular
    // files) counts as a full disk.
    bool
    write_all(const int descriptor, const char *data, std::size_t size)
    {
      while (size > 0)
      {
        const ssize_t written = ::write(descriptor, data, size);
        if (written < 0)
        {
          if (errno == EINTR)
            continue;
          return false;
        }
        if (written == 0)
        {
          errno = ENOSPC;
          return false;
        }
        data += written;
        size -= static_cast<std::size_t>(written);
      }
      return true;
    }


    void
    write_file_atomically(const std::string &filename,
                          const std::string &content)
    {
      if (writes_files())
        write_own_file_atomically(filename, content);
    }


    void
    write_own_file_atomically(const std::string &filename,
                              const std::string &content)
    {
      const std::string temporary = filename + ".tmp";
      // O_NONBLOCK: a named pipe in place of the temporary file fails to
      // open instead of blocking (D164).
      const int descriptor = ::open(temporary.c_str(),
                                    O_WRONLY | O_CREAT | O_TRUNC | O_NONBLOCK,
                                    0644);
      if (descriptor < 0)
        throw OutputError(describe_system_error(errno, "creating", temporary));
      const auto fail = [&](const int error_number, const std::string &doing)
      {
        ::unlink(temporary.c_str());
        throw OutputError(describe_system_error(error_number, doing, filename));
      };
      if (!write_all(descriptor, content.data(), content.size()))
      {
        const int error_number = errno;
        ::close(descriptor);
        fail(error_number, "writing");
      }
      if (::close(descriptor) != 0)
        fail(errno, "writing");
      if (std::rename(temporary.c_str(), filename.c_str()) != 0)
        fail(errno, "renaming " + temporary + " to");
    }


    void
    check_finite_for_output(const double      *begin,
                            const double      *end,
                            const std::string &what)
    {
      for (const double *value = begin; value != end; ++value)
        if (!std::isfinite(*value) || std::abs(*value) > FLT_MAX)
        {
          std::ostringstream text;
          text << "a non-finite value (" << *value << ", entry "
               << value - begin << ") in " << what
               << "; deepdraw writes no NaN or inf";
          throw OutputError(text.str());
        }
    }


    void
    check_finite_for_output(const std::vector<double> &values,
                            const std::string         &what)
    {
      check_finite_for_output(values.data(),
                              values.data() + values.size(),
                              what);
    }
  } // namespace io
} // namespace deepdraw
