// The kernels of OpenBLAS, which does MUMPS' and UMFPACK's dense work
// (D28). OpenBLAS picks them for the CPU when it is loaded, before main;
// a CPU newer than its release (Debian 12 has 0.3.21; Intel's Emerald
// Rapids, family 6 model 207, is one) gets its generic SSE3 kernels,
// "Prescott", and the factorisations run at about half speed (D210).
#ifndef deepdraw_app_blas_kernels_h
#define deepdraw_app_blas_kernels_h

#include <string>

namespace deepdraw
{
  namespace app
  {
    // The kernels OpenBLAS should use instead of the ones it chose
    // (`chosen`, its openblas_get_corename()), or "" to keep them: for
    // OpenBLAS's fallback "Prescott" on a CPU with AVX-512 (F, BW, VL, DQ)
    // "SkylakeX", with AVX2 and FMA "Haswell".
    std::string
    better_blas_kernels(const std::string &chosen);

    // Called first in main: where better_blas_kernels names kernels and
    // OPENBLAS_CORETYPE is not set (a user's setting wins), sets it and
    // starts this program again with the same arguments, so that
    // OpenBLAS reads it when it is loaded. Returns (doing nothing) if
    // OpenBLAS is not the BLAS or the program cannot be started again.
    void
    choose_blas_kernels(char *argv[]);
  } // namespace app
} // namespace deepdraw

#endif
