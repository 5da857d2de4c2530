"""Class "formability" of the hostile-input suite (tests/input/
hostile_cases.py): bad input of the post-processor "forming limits"
(subsection Formability, its VTU fields) and of deepdraw --flc.
"""
from hostile_prm import cup, section, sub


def formability(*entries):
    """'subsection Formability' with entries (entry, value) and, as
    (subsection, entry, value), those of its subsection
    Marciniak-Kuczynski."""
    return section("Formability", *entries)


# The post-processor "forming limits" listed with the statistics.
FORMING_LIMITS = sub("Postprocess", "List of postprocessors",
                     "forming limits, statistics")
TABULATED = ("Forming limit curve", "tabulated")
MK = ("Forming limit curve", "Marciniak-Kuczynski")


def formability_cases(source):
    """Bad input of the post-processor "forming limits" (subsection
    Formability, its VTU fields) and of deepdraw --flc: exit 2 with one line
    naming the parameter, nothing written; a bad --flc command line is exit
    1."""
    def listed(*entries, name, messages):
        return dict(name=name, files=cup(FORMING_LIMITS, formability(*entries)),
                    exit=2, messages=messages)

    def flc(*entries, name, messages, exit=2):
        return dict(name=name, files=cup(formability(*entries)), exit=exit,
                    args=["--flc", "case.prm", "--output-directory", "output"],
                    messages=messages)

    return [
        listed(name="no_curve",
               messages=["Formability/Forming limit curve = none: the "
                         "post-processor 'forming limits' needs a "
                         "forming-limit curve; allowed values are tabulated"]),
        listed(TABULATED, ("Table", "-0.2, 0.4; 0, 0.3; 0, 0.32"),
               name="table_not_a_function",
               messages=["Formability/Table", "point 3", "increase strictly"]),
        listed(TABULATED, ("Table", "-0.2, 0.4; 0, nan"),
               name="table_not_finite",
               messages=["Formability/Table", "not finite"]),
        listed(TABULATED, ("Table", "-0.2, 0.4; 0.3"), name="table_not_pairs",
               messages=["Formability/Table: expected pairs 'eps2, eps1'"]),
        listed(TABULATED, name="table_empty",
               messages=["Formability/Table or Formability/Table file",
                         "the table is empty"]),
        listed(TABULATED, ("Table file", "flc_nothing.csv"),
               name="table_file_missing", messages=["flc_nothing.csv"]),
        listed(MK, ("Marciniak-Kuczynski", "Imperfection f0", "0"),
               name="f0_zero",
               messages=["Formability/Marciniak-Kuczynski/Imperfection f0",
                         "0 < f0 <= 1"]),
        listed(MK, ("Marciniak-Kuczynski", "Imperfection f0", "1.5"),
               name="f0_above_one", messages=["Imperfection f0"]),
        listed(MK, ("Marciniak-Kuczynski", "Imperfection f0", "nan"),
               name="f0_not_finite", messages=["Imperfection f0"]),
        listed(MK, ("Safety band", "inf"), name="safety_band_not_finite",
               messages=["Safety band"]),
        listed(MK, ("Thinning limit", "0"), name="thinning_limit_zero",
               messages=["Formability/Thinning limit"]),
        listed(("Forming limit curve", "Keeler-Brazier"),
               ("Keeler-Brazier n", "inf"), name="keeler_brazier_n_infinite",
               messages=["Formability/Keeler-Brazier n"]),
        listed(("Forming limit curve", "Keeler-Brazier"),
               name="keeler_brazier_outside_its_range",
               messages=["Material/Swift exponent"]),
        listed(MK, ("FLD travels", "-1"), name="fld_travel_negative",
               messages=["FLD travels"]),
        listed(MK, ("FLD travels", "0.25, abc"), name="fld_travel_not_a_number",
               messages=["FLD travels"]),
        listed(MK, ("FLD travels", "0.25, 0.2500000000001"),
               name="fld_travels_one_file_name",
               messages=["Formability/FLD travels: ", "both give the file "
                         "name fld_0.25mm.csv"]),
        dict(name="vtu_field_without_the_postprocessor",
             files=cup(sub("Output", "VTU fields", "stress, fld zone")),
             exit=2, messages=["Output/VTU fields: 'fld zone' is a result of "
                               "the post-processor 'forming limits'"]),
        flc(name="flc_no_curve",
            messages=["Formability/Forming limit curve is none"]),
        flc(MK, ("Marciniak-Kuczynski", "Imperfection f0", "0"),
            name="flc_f0_zero",
            messages=["Formability/Marciniak-Kuczynski/Imperfection f0"]),
        flc(MK, ("Marciniak-Kuczynski", "Strain ratio step", "2"),
            name="flc_strain_ratio_step", messages=["Strain ratio step"]),
        dict(name="flc_missing_file", args=["--flc", "nothing.prm"], exit=2,
             messages=["nothing.prm"]),
        dict(name="flc_no_parameter_file", args=["--flc"], exit=1,
             messages=["--flc needs a parameter file"]),
        dict(name="flc_two_parameter_files",
             files=cup(formability(MK)),
             args=["--flc", "case.prm", "case.prm"], exit=1,
             messages=["--flc: unknown, repeated or incomplete argument "
                       "'case.prm'"]),
    ]
