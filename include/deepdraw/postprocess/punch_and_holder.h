// Which tool is the punch, along which direction it moves, and which tool
// is the blank holder (subsection Process tables: Punch tool, Blank holder
// tool): the punch force table and the earing profile read the sheet's
// response along the punch motion.
#ifndef deepdraw_postprocess_punch_and_holder_h
#define deepdraw_postprocess_punch_and_holder_h

#include <deal.II/base/numbers.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>
#include <deepdraw/contact/contact_coupling.h>
#include <string>

namespace deepdraw
{
  namespace postprocess
  {
    using namespace dealii;

    class PunchAndHolder
    {
    public:
      // Declared by the "punch force" post-processor.
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      // Finds the tools (InputError if a tool named in the prm does not
      // exist) and the punch direction over the run, to final_load (a
      // punch that does not move, or none, pushes along -z).
      void
      set_up(const contact::ContactCoupling &contact, double final_load);

      // Index of the punch / holder tool, numbers::invalid_unsigned_int if
      // there is none.
      unsigned int
      punch() const;
      unsigned int
      holder() const;
      // Unit direction of the punch motion.
      const Tensor<1, 3> &
      punch_direction() const;

    private:
      std::string  punch_name  = "punch";
      std::string  holder_name = "";
      unsigned int punch_tool  = numbers::invalid_unsigned_int;
      unsigned int holder_tool = numbers::invalid_unsigned_int;
      Tensor<1, 3> direction   = Tensor<1, 3>({0., 0., -1.});
    };
  } // namespace postprocess
} // namespace deepdraw

#endif
