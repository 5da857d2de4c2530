// The strain path of a point of the sheet in the forming-limit diagram
// (doc/theory_formability.md §6, D142): a forming-limit curve holds for
// proportional paths, so a point whose ratio eps2/eps1 changed on the way
// must be read with care. Kept small (a checkpoint carries one per column
// and surface): the ratio d eps2 / d eps1 of the path's last segment and
// the least and the largest over its segments, a segment ending where the
// major strain has grown by segment_length since the segment began.
#ifndef deepdraw_formability_strain_path_h
#define deepdraw_formability_strain_path_h

#include <iosfwd>
#include <string>

namespace deepdraw
{
  namespace formability
  {
    class StrainPath
    {
    public:
      // The growth of the major strain over which a ratio is measured:
      // well above the noise of an increment's strain (1e-8 at the
      // residual tolerances of the shipped prms), well below the strains
      // of the diagram (tenths).
      static constexpr double segment_length = 0.005;

      // The principal strains after an increment (logarithmic, eps1 >=
      // eps2): completes a segment when eps1 has grown by segment_length
      // since its start.
      void
      add(double major_strain, double minor_strain);

      // Whether a segment was completed; the ratios are 0 until then.
      bool
      measured() const;
      // d eps2 / d eps1 of the last completed segment.
      double
      last_ratio() const;
      // The least and the largest ratio of the completed segments: equal
      // for a proportional path.
      double
      least_ratio() const;
      double
      largest_ratio() const;
      // The completed segments.
      unsigned int
      segments() const;

      void
      save(std::ostream &stream) const;
      void
      load(std::istream &stream, const std::string &source);

    private:
      // Where the current segment began.
      double       start_major = 0., start_minor = 0.;
      double       last = 0., least = 0., largest = 0.;
      unsigned int n_segments = 0;
    };
  } // namespace formability
} // namespace deepdraw

#endif
