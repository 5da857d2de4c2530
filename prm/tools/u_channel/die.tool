# NUMISHEET'93 2D draw bending, half model (x >= 0), profile extruded along y
# over [-5, 40] mm; doc/decisions.md D154.
# Die: opening half width 36 mm, shoulder radius 5 mm, top at z = 0.
# Written by scripts/write_u_channel_tools.py; do not edit.
tool die
patch
degrees 1 1
36.0 -5.0 -100.0 1.0
36.0 -5.0 -5.0 1.0
36.0 40.0 -100.0 1.0
36.0 40.0 -5.0 1.0
end
patch
degrees 2 1
36.0 -5.0 -5.0 1.0
36.0 -5.0 0.0 0.7071067811865476
41.0 -5.0 0.0 1.0
36.0 40.0 -5.0 1.0
36.0 40.0 0.0 0.7071067811865476
41.0 40.0 0.0 1.0
end
patch
degrees 1 1
41.0 -5.0 0.0 1.0
200.0 -5.0 0.0 1.0
41.0 40.0 0.0 1.0
200.0 40.0 0.0 1.0
end
