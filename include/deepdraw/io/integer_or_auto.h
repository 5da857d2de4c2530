// An entry that takes an integer in a range or the word "auto", for values
// the program can choose itself from the problem (Linear solver/Reuse
// iterations, D228). A Patterns::Integer underneath, so the messages of
// rejected values and the parameter documentation read as for an integer.
#ifndef deepdraw_io_integer_or_auto_h
#define deepdraw_io_integer_or_auto_h

#include <deal.II/base/patterns.h>
#include <memory>
#include <string>

namespace deepdraw
{
  namespace io
  {
    using namespace dealii;

    class IntegerOrAuto : public Patterns::PatternBase
    {
    public:
      IntegerOrAuto(int lower_bound, int upper_bound);

      bool
      match(const std::string &text) const override;

      // The integer's description with "or auto" added.
      std::string
      description(OutputStyle style = Machine) const override;

      std::unique_ptr<Patterns::PatternBase>
      clone() const override;

    private:
      Patterns::Integer integer;
    };
  } // namespace io
} // namespace deepdraw

#endif
