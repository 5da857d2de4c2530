# Rigid cylinder of radius 50 mm for the Hertz line-contact test
# (tests/contact/hertz_cylinder.cc): axis along y through x = 0, z = 56, so
# its lowest line x = 0, z = 6 touches the top of a block 6 mm thick.
# One quadratic rational patch: u runs along the 90-degree arc from the
# lowest point (0, 6) to (50, 56), weights 1, sqrt(2)/2, 1; v runs along -y
# so that the normal x_u x x_v = (+x) x (-y) = -z at the lowest point, i.e.
# out of the cylinder, towards the sheet.
# The edge u = 0 lies on the symmetry plane x = 0 of the half model.
tool hertz cylinder
patch
degrees 2 1
0 2 6 1
50 2 6 0.70710678118654757
50 2 56 1
0 -1 6 1
50 -1 6 0.70710678118654757
50 -1 56 1
edges symmetry free free free
end
