# doc/figures/earing_cylindrical_cup.png (doc/results.md "Cylindrical cup and
# earing"). Run in a directory holding earing_60mm.csv of prm/cylindrical_cup.prm
# and small_aluminium.csv, small_inverse.csv, small_von_mises.csv: the
# earing_24mm.csv of the three runs of tests/blanks/earing_test.py
# (build/tests/blanks/earing_test/<material>/):  gnuplot plot_earing_figure.gp
set terminal png size 900,340 font 'DejaVuSans,8' noenhanced
set output 'earing_cylindrical_cup.png'
set datafile separator ','
set datafile columnheaders
set grid
set xtics 15
set xlabel 'angle from the rolling direction (deg)'
set ylabel 'cup height (mm)'
set multiplot layout 1,2
set title 'prm/cylindrical_cup.prm (aluminium, 24 elements along the radius)'
set key bottom center
plot 'earing_60mm.csv' using 1:2 with linespoints pt 7 ps 0.5 title 'travel 60 mm (drawn through)'
set title 'small cup of blanks/earing_test, travel 24 mm'
set key top right
set yrange [17.9:19.35]
plot 'small_aluminium.csv' using 1:2 with linespoints pt 7 ps 0.5 title 'aluminium, Delta r = +0.125', \
     'small_inverse.csv' using 1:2 with linespoints pt 5 ps 0.5 title 'Delta r = -0.29', \
     'small_von_mises.csv' using 1:2 with linespoints pt 9 ps 0.6 title 'von Mises'
unset multiplot
