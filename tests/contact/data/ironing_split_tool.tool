# Ironing tool (tests/contact/ironing_split_tool.prm): the plane z = 1,
# normal -z, x in [-5, 5], y in [-3, 4], split along x at -1.63, -0.91,
# -0.37, 0.29, 1.13 and 1.61 into seven patches that parametrise the same
# plane differently (bilinear; quadratic with non-uniform speed; rational
# with weights 1, 2, 1; cubic x linear; u along y instead of x). The
# junctions are exact (C0, same normal), so a node sliding across them must
# see a continuous gap and normal (doc/tool_files.md): any jump of the tool force
# is an artefact of the projection or of the edge handling.
# Orientation: with u along -x and v along +y, or u along +y and v along
# +x, x_u x x_v = -z.
tool ironing tool
patch
degrees 1 1
-1.6299999999999999 -3 1 1
-5 -3 1 1
-1.6299999999999999 4 1 1
-5 4 1 1
end
patch
degrees 2 1
-0.91000000000000003 -3 1 1
-1.054 -3 1 1
-1.6299999999999999 -3 1 1
-0.91000000000000003 4 1 1
-1.054 4 1 1
-1.6299999999999999 4 1 1
end
patch
degrees 2 1
-0.37 -3 1 1
-0.64000000000000001 -3 1 2
-0.91000000000000003 -3 1 1
-0.37 4 1 1
-0.64000000000000001 4 1 2
-0.91000000000000003 4 1 1
end
patch
degrees 3 1
-0.37 -3 1 1
-0.37 -2.2999999999999998 1 1
-0.37 1.2000000000000002 1 1
-0.37 4 1 1
0.28999999999999998 -3 1 1
0.28999999999999998 -2.2999999999999998 1 1
0.28999999999999998 1.2000000000000002 1 1
0.28999999999999998 4 1 1
end
patch
degrees 1 1
1.1299999999999999 -3 1 1
0.28999999999999998 -3 1 1
1.1299999999999999 4 1 1
0.28999999999999998 4 1 1
end
patch
degrees 2 1
1.6100000000000001 -3 1 1
1.514 -3 1 1
1.1299999999999999 -3 1 1
1.6100000000000001 4 1 1
1.514 4 1 1
1.1299999999999999 4 1 1
end
patch
degrees 2 1
5 -3 1 1
3.3050000000000002 -3 1 2
1.6100000000000001 -3 1 1
5 4 1 1
3.3050000000000002 4 1 2
1.6100000000000001 4 1 1
end
