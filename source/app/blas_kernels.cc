#include <cstdlib>
#include <deepdraw/app/blas_kernels.h>
#include <dlfcn.h>
#include <unistd.h>

namespace deepdraw
{
  namespace app
  {
    std::string
    better_blas_kernels(const std::string &chosen)
    {
      // Only OpenBLAS's fallback for a CPU it does not know: a choice it
      // made from the CPU's model is kept.
      if (chosen != "Prescott")
        return "";
      __builtin_cpu_init();
      if (__builtin_cpu_supports("avx512f")
          && __builtin_cpu_supports("avx512bw")
          && __builtin_cpu_supports("avx512vl")
          && __builtin_cpu_supports("avx512dq"))
        return "SkylakeX";
      if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
        return "Haswell";
      return "";
    }


    void
    choose_blas_kernels(char *argv[])
    {
      if (std::getenv("OPENBLAS_CORETYPE") != nullptr)
        return;
      // Looked up, not linked: with another BLAS there is nothing to do.
      using CoreName  = char *(*)();
      const auto name = reinterpret_cast<CoreName>(
        dlsym(RTLD_DEFAULT, "openblas_get_corename"));
      if (name == nullptr || name() == nullptr)
        return;
      const std::string kernels = better_blas_kernels(name());
      if (kernels.empty())
        return;
      // Set either way: a second start does not try again.
      setenv("OPENBLAS_CORETYPE", kernels.c_str(), 1);
      execv("/proc/self/exe", argv);
    }
  } // namespace app
} // namespace deepdraw
