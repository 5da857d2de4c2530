// The `subsection Contact` entries: defaults, parsing, the automatic
// augmentation parameter, and InputError for values out of range.
#include "test_utilities.h"

#include <deal.II/base/parameter_handler.h>
#include <deepdraw/contact/contact_parameters.h>
#include <deepdraw/io/input_error.h>
#include <iostream>
#include <string>

using namespace deepdraw::contact;
using deepdraw_test::check_close;
using deepdraw_test::check_true;

namespace
{
  ContactParameters
  parse(const std::string &entries)
  {
    dealii::ParameterHandler prm;
    prm.enter_subsection("Contact");
    ContactParameters::declare_parameters(prm);
    prm.leave_subsection();
    prm.parse_input_from_string("subsection Contact\n" + entries + "end\n");
    ContactParameters parameters;
    prm.enter_subsection("Contact");
    parameters.parse_parameters(prm);
    prm.leave_subsection();
    return parameters;
  }

  void
  expect_input_error(const std::string &entries, const std::string &expected)
  {
    try
    {
      parse(entries);
      check_true("InputError for '" + entries + "'", false);
    }
    catch (const deepdraw::InputError &e)
    {
      const std::string message = e.what();
      std::cout << "  message: " << message << std::endl;
      check_true("message names '" + expected + "'",
                 message.find(expected) != std::string::npos);
    }
  }
} // namespace

int
main()
{
  const ContactParameters defaults = parse("");
  check_close("default friction coefficient",
              defaults.friction_coefficient,
              0.162,
              0.);
  check_close("default augmentation parameter",
              defaults.augmentation_parameter,
              0.,
              0.);
  check_close("default augmentation scaling",
              defaults.augmentation_scaling,
              1.,
              0.);
  check_true("default linearisation full",
             defaults.linearisation == Linearisation::full);
  // Automatic r = E h: aluminium, 3 mm elements.
  check_close("automatic r = E h",
              defaults.augmentation(71000., 3.),
              213000.,
              1e-9);

  const ContactParameters set = parse("set Friction coefficient = 0\n"
                                      "set Augmentation scaling = 0.25\n"
                                      "set Linearisation = frozen normal\n");
  check_close("frictionless allowed", set.friction_coefficient, 0., 0.);
  check_close("scaled automatic r", set.augmentation(71000., 3.), 53250., 1e-9);
  check_true("frozen normal",
             set.linearisation == Linearisation::frozen_normal);

  const ContactParameters fixed = parse("set Augmentation parameter = 5000\n"
                                        "set Augmentation scaling = 3\n");
  check_close("fixed r wins", fixed.augmentation(71000., 3.), 5000., 0.);

  expect_input_error("set Friction coefficient = -0.1\n",
                     "Contact/Friction coefficient");
  expect_input_error("set Friction coefficient = -0.1\n", ">= 0");
  expect_input_error("set Augmentation parameter = -1\n",
                     "Contact/Augmentation parameter");
  expect_input_error("set Augmentation scaling = 0\n",
                     "Contact/Augmentation scaling");
  expect_input_error("set Augmentation scaling = -2\n", "> 0");
  return deepdraw_test::summary();
}
