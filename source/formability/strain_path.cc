// The strain path of a point (doc/theory_formability.md §6).
#include <algorithm>
#include <deepdraw/formability/strain_path.h>
#include <deepdraw/io/binary_stream.h>

namespace deepdraw
{
  namespace formability
  {
    void
    StrainPath::add(const double major_strain, const double minor_strain)
    {
      const double growth = major_strain - start_major;
      if (!(growth >= segment_length))
        return;
      last    = (minor_strain - start_minor) / growth;
      least   = n_segments == 0 ? last : std::min(least, last);
      largest = n_segments == 0 ? last : std::max(largest, last);
      ++n_segments;
      start_major = major_strain;
      start_minor = minor_strain;
    }


    bool
    StrainPath::measured() const
    {
      return n_segments > 0;
    }


    double
    StrainPath::last_ratio() const
    {
      return last;
    }


    double
    StrainPath::least_ratio() const
    {
      return least;
    }


    double
    StrainPath::largest_ratio() const
    {
      return largest;
    }


    unsigned int
    StrainPath::segments() const
    {
      return n_segments;
    }


    void
    StrainPath::save(std::ostream &stream) const
    {
      for (const double value :
           {start_major, start_minor, last, least, largest})
        io::write_value(stream, value);
      io::write_value(stream, n_segments);
    }


    void
    StrainPath::load(std::istream &stream, const std::string &source)
    {
      for (double *value :
           {&start_major, &start_minor, &last, &least, &largest})
        io::read_value(stream, *value, source);
      io::read_value(stream, n_segments, source);
    }
  } // namespace formability
} // namespace deepdraw
