// An integer in a range or "auto" (D228).
#include <deepdraw/io/integer_or_auto.h>

namespace deepdraw
{
  namespace io
  {
    IntegerOrAuto::IntegerOrAuto(const int lower_bound, const int upper_bound)
        : integer(lower_bound, upper_bound)
    {
    }


    bool
    IntegerOrAuto::match(const std::string &text) const
    {
      return text == "auto" || integer.match(text);
    }


    std::string
    IntegerOrAuto::description(const OutputStyle style) const
    {
      std::string text = integer.description(style);
      // Machine style is "[Integer range a...b (inclusive)]".
      const std::size_t end = style == Machine ? text.rfind(']') : text.size();
      return text.insert(end == std::string::npos ? text.size() : end,
                         " or auto");
    }


    std::unique_ptr<Patterns::PatternBase>
    IntegerOrAuto::clone() const
    {
      return std::make_unique<IntegerOrAuto>(*this);
    }
  } // namespace io
} // namespace deepdraw
