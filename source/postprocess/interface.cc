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


    std::string
    Interface::summary() const
    {
      return "";
    }


    void
    Interface::set_input_directory(const std::string &directory)
    {
      prm_directory = directory;
    }


    const std::string &
    Interface::input_directory() const
    {
      return prm_directory;
    }
  } // namespace postprocess
} // namespace deepdraw
