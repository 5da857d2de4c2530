# NUMISHEET'93 2D draw bending, half model (x >= 0), profile extruded along y
# over [-5, 40] mm; doc/decisions.md D154.
# Punch: half width 35 mm, corner radius 5 mm, bottom at z = 0.78 mm (on the sheet).
# Written by scripts/write_u_channel_tools.py; do not edit.
tool punch
patch
degrees 1 1
0.0 40.0 0.78 1.0
30.0 40.0 0.78 1.0
0.0 -5.0 0.78 1.0
30.0 -5.0 0.78 1.0
edges symmetry automatic automatic automatic
end
patch
degrees 2 1
30.0 40.0 0.78 1.0
35.0 40.0 0.78 0.7071067811865476
35.0 40.0 5.78 1.0
30.0 -5.0 0.78 1.0
35.0 -5.0 0.78 0.7071067811865476
35.0 -5.0 5.78 1.0
end
patch
degrees 1 1
35.0 40.0 5.78 1.0
35.0 40.0 100.78 1.0
35.0 -5.0 5.78 1.0
35.0 -5.0 100.78 1.0
end
