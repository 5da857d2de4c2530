# NUMISHEET'93 2D draw bending, half model (x >= 0), profile extruded along y
# over [-5, 40] mm; doc/decisions.md D154.
# Blank holder: flat at z = 0.78 mm from x = 41 mm outwards.
# Written by scripts/write_u_channel_tools.py; do not edit.
tool holder
patch
degrees 1 1
41.0 40.0 0.78 1.0
200.0 40.0 0.78 1.0
41.0 -5.0 0.78 1.0
200.0 -5.0 0.78 1.0
edges free automatic automatic automatic
end
