#include <deal.II/lac/vector.h>
#include <deepdraw/io/expression_error.h>
#include <deepdraw/io/function_of_load.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/printable_text.h>
#include <map>

namespace deepdraw
{
  namespace io
  {
    using namespace dealii;

    std::shared_ptr<FunctionParser<1>>
    parse_function_of_load(const std::string &text,
                           const unsigned int n_components,
                           const std::string &parameter)
    {
      auto function = std::make_shared<FunctionParser<1>>(n_components);
      // muparser's own diagnostic lines become the reason of the message
      // (io/expression_error.h).
      const std::string error = io::expression_error(
        [&]()
        {
          function->initialize("s,t",
                               text,
                               std::map<std::string, double>(),
                               /*time_dependent=*/true);
          function->set_time(0.);
          Vector<double> values(n_components);
          function->vector_value(Point<1>(), values);
        });
      if (!error.empty())
        throw InputError(parameter + " = '" + io::one_line(text)
                         + "': expected " + std::to_string(n_components)
                         + " expression(s) of the load t separated by "
                           "';' ("
                         + error + ")");
      return function;
    }
  } // namespace io
} // namespace deepdraw
