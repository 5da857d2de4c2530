// One output folder, one run (doc/user_guide.md §6, doc/decisions.md
// D162): a run holds the lock file .deepdraw.lock in its output directory
// from before it writes or cuts back anything until it ends. The lock is an
// flock() on that file, so it ends with the process however it ends
// (SIGKILL included); the holder's process id comes from the kernel's lock
// table, and the file stays empty (a lock costs no block of a nearly full
// disk). A lock file nobody holds is stale and taken over.
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
      // "parameter: 'DIR' is in use by deepdraw process PID ..." if a
      // living process holds it, and std::runtime_error if the lock file
      // cannot be made. A stale lock file is taken over, with a line on
      // stdout unless quiet; so is a file system without locks.
      void
      acquire(const std::string &directory,
              const std::string &parameter,
              bool               quiet);

      // For --check (D179): throws the InputError of acquire() if a living
      // process of this host holds the lock of `directory`; writes nothing.
      static void
      check_free(const std::string &directory, const std::string &parameter);

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
