# A flat rigid plane z = 0, normal +z (towards a sheet above it), 30 x 30 mm.
tool flat die
patch
degrees 1 1
-10 -10 0 1
 20 -10 0 1
-10  20 0 1
 20  20 0 1
end
