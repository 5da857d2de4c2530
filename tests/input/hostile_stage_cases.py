"""Class "stages_and_outputs" of the hostile-input suite (tests/input/
hostile_cases.py): bad stages (D101), release stages (D150, D151) and
post-processor lists.
"""
from hostile_prm import cup, section, sub


def stage(number, *entries):
    """'subsection Process / subsection Stage N' with entries, each
    (entry, value) or (subsection, entry, value)."""
    return section("Process/Stage %d" % number, *entries)


def stage_and_output_cases(source):
    """Bad stages (D101) and post-processor lists: exit 2, nothing written."""
    two = stage(1, ("Name", "draw"), ("Final load", "0.25"))
    return [
        dict(name="stage_gap", files=cup(stage(2, ("Name", "draw"))), exit=2,
             messages=["Process/Stage 2/Name: stages run from Stage 1 on "
                       "without gaps, but Stage 1 has no name"]),
        dict(name="unnamed_stage_with_settings",
             files=cup(stage(1, ("Tools", "die"))), exit=2,
             messages=["Process/Stage 1/Tools is set, but the stage has no "
                       "Name"]),
        dict(name="last_stage_with_final_load",
             files=cup(stage(1, ("Name", "draw"), ("Final load", "0.5"))),
             exit=2, messages=["Process/Stage 1/Final load = '0.5': the last "
                               "stage ends at Process/Final load"]),
        dict(name="stage_without_final_load",
             files=cup(stage(1, ("Name", "draw")), stage(2, ("Name", "more"))),
             exit=2, messages=["Process/Stage 1/Final load = '': a stage "
                               "before the last needs the load"]),
        dict(name="stage_ends_before_it_begins",
             files=cup(stage(1, ("Name", "draw"), ("Final load", "0.75")),
                       stage(2, ("Name", "more"))),
             exit=2, messages=["Process/Final load = 0.5: Stage 2 begins "
                               "where the stage before it ends, at load "
                               "0.75, and must end after that"]),
        dict(name="stage_names_equal",
             files=cup(two, stage(2, ("Name", "draw"))), exit=2,
             messages=["Process/Stage 2/Name = 'draw': another stage has "
                       "this name"]),
        dict(name="stage_unknown_tool",
             files=cup(two, stage(2, ("Name", "release"),
                                  ("Tools", "die, punsh"))), exit=2,
             messages=["Process/Stage 2/Tools: no tool is named 'punsh'"]),
        dict(name="stage_unknown_kind",
             files=cup(two, stage(2, ("Name", "release"), ("Kind", "trim"))),
             exit=2, messages=["Kind", "trim"]),
        dict(name="stage_translation_not_zero_at_its_start",
             files=cup(two, stage(2, ("Name", "back"),
                                  ("Tool 1", "Translation", "0; 0; t"))),
             exit=2, messages=["Process/Stage 2/Tool 1/Translation = "
                               "'0; 0; t' gives uz = 0.25 mm at t = 0.25",
                               "must be 0 there"]),
        dict(name="stage_translation_not_an_expression",
             files=cup(two, stage(2, ("Name", "back"),
                                  ("Tool 1", "Translation", "0; 0"))),
             exit=2, messages=["Process/Stage 2/Tool 1/Translation = "
                               "'0; 0': expected 3 expression(s)"]),
        dict(name="stage_displacement_control_without_translation",
             files=cup(two, stage(2, ("Name", "lift"),
                                  ("Tool 3", "Control", "displacement"))),
             exit=2, messages=["Process/Stage 2/Tool 3/Translation: the tool "
                               "turns to displacement control in this stage "
                               "and needs its translation here"]),
        dict(name="stage_translation_of_a_force_controlled_tool",
             files=cup(two, stage(2, ("Name", "lift"),
                                  ("Tool 3", "Translation", "0; 0; 0"))),
             exit=2, messages=["Process/Stage 2/Tool 3/Translation: the tool "
                               "is force-controlled in this stage"]),
        dict(name="stage_holder_force_not_an_expression",
             files=cup(two, stage(2, ("Name", "more"),
                                  ("Blank holder force", "1e3*"))),
             exit=2, messages=["Process/Stage 2/Blank holder force = "
                               "'1e3*': expected 1 expression(s)"]),
        dict(name="stage_holder_force_too_large",
             files=cup(two, stage(2, ("Name", "more"),
                                  ("Blank holder force", "1e12*t"))),
             exit=2, messages=["Process/Stage 2/Blank holder force = "
                               "'1e12*t' gives"]),
        dict(name="stage_prescribed_displacement_unknown_face",
             files=cup(two, stage(2, ("Name", "more"),
                                  ("Prescribed displacements",
                                   "zmid: uz = 0"))),
             exit=2, messages=["Process/Stage 2/Prescribed displacements: "
                               "unknown face 'zmid'"]),
        dict(name="stage_load_stepping_not_a_number",
             files=cup(two, stage(2, ("Name", "more"),
                                  ("Load stepping", "Initial increment",
                                   "small"))),
             exit=2, messages=["Process/Stage 2/Load stepping/Initial "
                               "increment = 'small': allowed are"]),
        dict(name="stage_load_stepping_inconsistent",
             files=cup(two, stage(2, ("Name", "more"),
                                  ("Load stepping", "Minimum increment",
                                   "1"))),
             exit=2, messages=["Process/Stage 2/Load stepping/Minimum "
                               "increment must not exceed"]),
        dict(name="stage_minimum_newton_iterations_not_an_integer",
             files=cup(two, stage(2, ("Name", "more"),
                                  ("Newton", "Minimum iterations", "1.5"))),
             exit=2, messages=["Process/Stage 2/Newton/Minimum iterations = "
                               "'1.5': allowed are", "or empty"]),
        dict(name="stage_minimum_newton_iterations_above_maximum",
             files=cup(two, stage(2, ("Name", "more"),
                                  ("Newton", "Minimum iterations", "999"))),
             exit=2, messages=["Process/Stage 2/Newton/Minimum iterations = "
                               "999 exceeds Maximum iterations = 40"]),
        dict(name="stage_force_tolerance_zero",
             files=cup(two, stage(2, ("Name", "more"),
                                  ("Newton", "Force tolerance", "0"))),
             exit=2, messages=["Process/Stage 2/Newton/Force tolerance = "
                               "0.000000 is not allowed: 0 < value < 1"]),
        dict(name="stage_viscous_stabilization_negative",
             files=cup(two, stage(2, ("Name", "more"),
                                  ("Viscous stabilization", "0.4 - t"))),
             exit=2, messages=["Process/Stage 2/Viscous stabilization = "
                               "'0.4 - t' gives -0.025 at t = 0.425: allowed "
                               "are values >= 0"]),
        dict(name="stage_viscous_stabilization_not_zero_at_the_end",
             files=cup(two, stage(2, ("Name", "more"),
                                  ("Viscous stabilization", "1e-3"))),
             exit=2, messages=["Process/Stage 2/Viscous stabilization = "
                               "'1e-3' gives 0.001 at the stage's end, t = "
                               "0.5: it must be 0 there"]),
        dict(name="stage_viscous_stabilization_not_an_expression",
             files=cup(two, stage(2, ("Name", "more"),
                                  ("Viscous stabilization", "1e-3*(0.5-"))),
             exit=2, messages=["Process/Stage 2/Viscous stabilization = "
                               "'1e-3*(0.5-': expected 1 expression(s)"]),
        dict(name="unnamed_stage_with_minimum_newton_iterations",
             files=cup(stage(1, ("Newton", "Minimum iterations", "1"))),
             exit=2, messages=["Process/Stage 1/Newton/Minimum iterations is "
                               "set, but the stage has no Name"]),
        dict(name="release_with_a_free_rigid_body_mode",
             files=cup(two, stage(2, ("Name", "springback"),
                                  ("Kind", "release"))), exit=2,
             messages=["Process/Stage 2/Release supports = '': the released "
                       "sheet is free to move (translation along z): the "
                       "symmetry planes, the stage's Prescribed displacements "
                       "and its supports stop 5 of the 6 rigid-body modes"]),
        dict(name="release_support_unreadable",
             files=cup(two, stage(2, ("Name", "springback"),
                                  ("Kind", "release"),
                                  ("Release supports", "point(0, 0): uz"))),
             exit=2, messages=["Process/Stage 2/Release supports: cannot read "
                               "'point(0, 0): uz'; expected 'point(X, Y, Z): "
                               "COMPONENTS'"]),
        dict(name="release_support_unknown_component",
             files=cup(two, stage(2, ("Name", "springback"),
                                  ("Kind", "release"),
                                  ("Release supports", "point(0, 0, 0): uw"))),
             exit=2, messages=["Process/Stage 2/Release supports: 'uw' in "
                               "'point(0, 0, 0): uw': allowed are ux, uy, uz"]),
        dict(name="release_supports_in_a_forming_stage",
             files=cup(two, stage(2, ("Name", "more"),
                                  ("Release supports", "point(0, 0, 0): uz"))),
             exit=2, messages=["Process/Stage 2/Release supports is set, but "
                               "the stage is not a release (Kind = release)"]),
        dict(name="force_release_with_tools",
             files=cup(two, stage(2, ("Name", "springback"),
                                  ("Kind", "release"), ("Tools", "die"),
                                  ("Release supports", "point(0, 0, 0): uz"))),
             exit=2, messages=["Process/Stage 2/Tools = 'die': a force release "
                               "removes every tool; allowed are 'all' or "
                               "'none'"]),
        dict(name="release_as_first_stage",
             files=cup(stage(1, ("Name", "springback"), ("Kind", "release"))),
             exit=2, messages=["Process/Stage 1/Kind = release: the first "
                               "stage has nothing to release"]),
        dict(name="unknown_postprocessor",
             files=cup(sub("Postprocess", "List of postprocessors",
                           "statistics, wrinkles")), exit=2,
             messages=["Postprocess/List of postprocessors: unknown "
                       "post-processor 'wrinkles'; allowed: "]),
        dict(name="postprocessor_listed_twice",
             files=cup(sub("Postprocess", "List of postprocessors",
                           "statistics, tools, statistics")), exit=2,
             messages=["Postprocess/List of postprocessors: 'statistics' is "
                       "listed twice"]),
        dict(name="unknown_vtu_field",
             files=cup(sub("Output", "VTU fields", "stress, strain")), exit=2,
             messages=["Output/VTU fields: unknown field 'strain'; allowed: "]),
    ]
