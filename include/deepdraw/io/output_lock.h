// One output folder, one run (doc/user_guide.md §6, doc/decisions.md
// D162): a run holds the lock file .deepdraw.lock in its output directory,
// with its process id and host, from before it writes or cuts back
// anything until it ends. The lock is an flock() on that file, so it ends
// with the process however it ends (SIGKILL included); a lock file left
// behind by a process that is gone is stale and taken over.
#ifndef deepdraw_io_output_lock_h
#define deepdraw_io_output_lock_h

#include <string>

namespace deepdraw
{
  namespace io
  {
    class OutputLock
    {
    public:
      OutputLock()                   = default;
      OutputLock(const OutputLock &) = delete;
      OutputLock &
      operator=(const OutputLock &)
        = delete;
      // Releases the lock (release()).
      ~OutputLock();

      // Takes the lock of `directory` (which must exist). Throws InputError
      // "parameter: DIR is in use by deepdraw process PID on HOST ..." if
      // a living process holds it, and std::runtime_error if the lock file
      // cannot be made. A stale lock file is taken over, with a line on
      // stdout unless quiet.
      void
      acquire(const std::string &directory,
              const std::string &parameter,
              bool               quiet);

      // Removes the lock file and ends the lock; nothing if none is held.
      void
      release();

      // The lock file of a directory.
      static std::string
      file_name(const std::string &directory);

    private:
      std::string path;
      int         descriptor = -1;
    };
  } // namespace io
} // namespace deepdraw

#endif
