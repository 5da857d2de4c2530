# A flat rigid plane z = 0.5, normal -z (towards a sheet of thickness 0.5
# lying below it on flat_die.tool), 30 x 30 mm. The u direction runs along
# -x so that x_u x x_v = (-x) x (+y) = -z (doc/tool_files.md, Orientation).
tool flat holder
patch
degrees 1 1
 20 -10 0.5 1
-10 -10 0.5 1
 20  20 0.5 1
-10  20 0.5 1
end
