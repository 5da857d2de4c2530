// Minimal assertion helpers for the unit-test programs: every check prints
// what it compared, and a failed check makes the program exit non-zero.
#ifndef deepdraw_tests_test_utilities_h
#define deepdraw_tests_test_utilities_h

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

namespace deepdraw_test
{
  inline int &
  failure_count()
  {
    static int count = 0;
    return count;
  }

  // |actual - expected| <= tolerance, printed either way.
  inline void
  check_close(const std::string &what,
              const double       actual,
              const double       expected,
              const double       tolerance)
  {
    const double error = std::abs(actual - expected);
    const bool   ok    = error <= tolerance && std::isfinite(actual);
    std::cout << (ok ? "  ok   " : "  FAIL ") << what << ": " << actual
              << " vs " << expected << " (|error| " << error << ", tolerance "
              << tolerance << ")" << std::endl;
    if (!ok)
      ++failure_count();
  }

  // |actual - expected| <= tolerance * max(|expected|, floor).
  inline void
  check_relative(const std::string &what,
                 const double       actual,
                 const double       expected,
                 const double       tolerance,
                 const double       floor = 1e-300)
  {
    check_close(what,
                actual,
                expected,
                tolerance * std::max(std::abs(expected), floor));
  }

  inline void
  check_true(const std::string &what, const bool condition)
  {
    std::cout << (condition ? "  ok   " : "  FAIL ") << what << std::endl;
    if (!condition)
      ++failure_count();
  }

  // Return value of main(): 0 only if no check failed.
  inline int
  summary()
  {
    if (failure_count() == 0)
    {
      std::cout << "all checks passed" << std::endl;
      return EXIT_SUCCESS;
    }
    std::cout << failure_count() << " check(s) FAILED" << std::endl;
    return EXIT_FAILURE;
  }
} // namespace deepdraw_test

#endif
