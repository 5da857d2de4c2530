// VTU fields of the post-processor "forming limits" (doc/user_guide.md
// §8.2), per cell, every cell of a column with its column's value, for the
// bottom, mid and top surface: major_strain_*, minor_strain_* (logarithmic,
// since t = 0), flc_margin_* (eps1*(eps2) - eps1, in strain) and fld_zone_*
// (the value of formability::FldZone: safe 0, marginal 1, split 2,
// thinning 3, insufficient stretch 4, wrinkling tendency 5). They read the
// post-processor (SimulationAccess::find_postprocessor, D141), which must be
// listed.
#include <deepdraw/io/input_error.h>
#include <deepdraw/postprocess/forming_limits.h>
#include <deepdraw/postprocess/vtu_field.h>

namespace deepdraw
{
  namespace postprocess
  {
    namespace
    {
      const FormingLimits *
      forming_limits(const SimulationAccess &simulation)
      {
        return dynamic_cast<const FormingLimits *>(
          simulation.find_postprocessor(FormingLimits::name));
      }

      // What a field shows of a point: its name in Output/VTU fields, the
      // prefix of its arrays and the value.
      struct Quantity
      {
        const char *name, *prefix;
        double (*value)(const FormingLimits::FldPoint &);
      };

      constexpr Quantity quantities[]
        = {{"major strain",
            "major_strain",
            [](const FormingLimits::FldPoint &p) { return p.major_strain; }},
           {"minor strain",
            "minor_strain",
            [](const FormingLimits::FldPoint &p) { return p.minor_strain; }},
           {"flc margin",
            "flc_margin",
            [](const FormingLimits::FldPoint &p) { return p.margin.strain; }},
           {"fld zone", "fld_zone", [](const FormingLimits::FldPoint &p) {
              return double(unsigned(p.zone));
            }}};

      // prefix_bottom, prefix_mid, prefix_top of the value of quantities[k].
      template <unsigned int k>
      class FormabilityField : public VtuField
      {
      public:
        void
        check(const SimulationAccess &simulation) const override
        {
          if (forming_limits(simulation) == nullptr)
            throw InputError(
              "Output/VTU fields: '" + std::string(quantities[k].name)
              + "' is a result of the post-processor '" + FormingLimits::name
              + "'; add it to Postprocess/List of "
                "postprocessors");
        }

        void
        add(const SimulationAccess &simulation, VtuData &data) const override
        {
          const FormingLimits &results = *forming_limits(simulation);
          const std::vector<FormingLimits::ColumnFld> columns
            = results.evaluate(simulation);
          const std::vector<unsigned int> &column_of_cell
            = results.columns().column_of_cell();
          for (const SheetSurface surface : sheet_surfaces)
          {
            Vector<double> &values
              = data.add_cell_field(simulation,
                                    std::string(quantities[k].prefix) + "_"
                                      + surface_name(surface));
            for (unsigned int cell = 0; cell < values.size(); ++cell)
              values[cell] = quantities[k].value(
                columns[column_of_cell[cell]].surfaces[unsigned(surface)]);
          }
        }
      };
    } // namespace

    DEEPDRAW_REGISTER_VTU_FIELD(FormabilityField<0>,
                                quantities[0].name,
                                "major_strain_bottom/mid/top: the in-plane "
                                "major logarithmic strain of the cell's "
                                "column (post-processor 'forming limits').")
    DEEPDRAW_REGISTER_VTU_FIELD(FormabilityField<1>,
                                quantities[1].name,
                                "minor_strain_bottom/mid/top: the in-plane "
                                "minor logarithmic strain of the cell's "
                                "column (post-processor 'forming limits').")
    DEEPDRAW_REGISTER_VTU_FIELD(FormabilityField<2>,
                                quantities[2].name,
                                "flc_margin_bottom/mid/top: eps1*(eps2) - "
                                "eps1 of the cell's column, negative above "
                                "the FLC (post-processor 'forming limits').")
    DEEPDRAW_REGISTER_VTU_FIELD(FormabilityField<3>,
                                quantities[3].name,
                                "fld_zone_bottom/mid/top: the zone of the "
                                "cell's column, safe 0, marginal 1, split 2, "
                                "thinning 3, insufficient stretch 4, "
                                "wrinkling tendency 5 (post-processor "
                                "'forming limits').")
  } // namespace postprocess
} // namespace deepdraw
