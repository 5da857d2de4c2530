// flc.csv and flc.png: the forming-limit curve of subsection Formability as
// a table and a picture (doc/user_guide.md §8; deepdraw --flc); the picture
// of a forming-limit diagram with it (fld_<travel>mm.png of the
// post-processor "forming limits").
#ifndef deepdraw_formability_flc_files_h
#define deepdraw_formability_flc_files_h

#include <deepdraw/formability/formability_parameters.h>
#include <deepdraw/material/material_parameters.h>
#include <string>

namespace deepdraw
{
  namespace formability
  {
    // Writes directory/flc.csv (columns eps2, eps1, and for an M-K curve
    // strain_ratio and groove_angle_deg; true strains, the curve's points),
    // directory/flc.gp and, by gnuplot, directory/flc.png (the curve and its
    // safety band). directory must exist. Returns the console line about
    // the picture (io::plot_with_gnuplot); io::OutputError if a file cannot be
    // written.
    std::string
    write_flc_files(const FormingLimitCurve &curve,
                    const FldZoneParameters &zones,
                    const std::string       &directory);

    // The curve of parsed parameters (create_forming_limit_curve), then the
    // files. InputError, before anything is written, for curve type none
    // or a curve that cannot be made from the input.
    std::string
    write_flc_files(const FormabilityParameters        &parameters,
                    const material::MaterialParameters &material,
                    double                              sheet_thickness,
                    const std::string                  &directory);

    // Writes directory/<stem>.gp and, by gnuplot, <stem>.png: the points of
    // <stem>.csv (columns X, Y, surface, eps2, eps1, margin,
    // margin_percent, zone) coloured by zone over the curve of flc.csv in
    // the same directory and its safety band; `when` goes into the title
    // ("t = 20 mm"). Returns the console line about the picture.
    std::string
    write_fld_plot(const std::string       &directory,
                   const std::string       &stem,
                   const FormingLimitCurve &curve,
                   const FldZoneParameters &zones,
                   const std::string       &when);
  } // namespace formability
} // namespace deepdraw

#endif
