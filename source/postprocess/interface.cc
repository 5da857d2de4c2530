#include <deepdraw/postprocess/interface.h>

namespace deepdraw
{
  namespace postprocess
  {
    void
    Interface::parse_parameters(ParameterHandler &)
    {
    }


    void
    Interface::initialize(const SimulationAccess &)
    {
    }


    std::vector<double>
    Interface::requested_loads(const SimulationAccess &) const
    {
      return {};
    }


    void
    Interface::start(const SimulationAccess &, bool)
    {
    }


    void
    Interface::end_stage(const SimulationAccess &)
    {
    }


    void
    Interface::save(std::ostream &) const
    {
    }


    void
    Interface::load(std::istream &)
    {
    }


  } // namespace postprocess
} // namespace deepdraw
