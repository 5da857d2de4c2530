#include <deepdraw/io/input_error.h>
#include <deepdraw/io/output_directory.h>
#include <exception>
#include <filesystem>

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
        std::filesystem::create_directories(directory);
        open();
      }
      catch (const std::exception &error)
      {
        if (!existed)
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


    bool
    is_plain_file_name(const std::string &name)
    {
      return !name.empty() && name != "." && name != ".."
             && name.find_first_of(std::string("/\\\0", 3))
                  == std::string::npos;
    }
  } // namespace io
} // namespace deepdraw
